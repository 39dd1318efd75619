"""How a fix names the input the user has to change: a command-line option or a vendor YAML key.

The same xacro or URDF problem is fixed differently depending on where the description came from:
`rhi-gen new` and `rhi-gen inspect` take ``--xacro-arg NAME=VALUE``, ``--package-path PKG=DIR`` and
``--urdf FILE``; `generate`, `check` and `diff` read ``xacro_args``, ``package_paths`` and ``urdf`` from
the vendor YAML. The loaders take one of the two :class:`Wording` values below and never guess.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Wording:
    """The words a fix uses for each input a description depends on."""
    in_yaml: bool

    def xacro_arg(self, name: str) -> str:
        """How to set xacro arg ``name``."""
        if self.in_yaml:
            return f"add xacro_args: {{{name}: <value>}} to the vendor YAML"
        return f"add --xacro-arg {name}=<value>"

    def package_path(self, package: str) -> str:
        """How to tell rhi-gen where ``$(find package)`` is."""
        if self.in_yaml:
            return f"add package_paths: {{{package}: <dir>}} to the vendor YAML"
        return f"add --package-path {package}=<dir> (the package's folder, the one holding its package.xml)"

    def package_path_given(self, package: str) -> str:
        """Where the current directory of ``package`` was given."""
        return f"package_paths: {{{package}: ...}} in the vendor YAML" if self.in_yaml else \
            f"--package-path {package}=..."

    def fix_package_path(self, package: str) -> str:
        if self.in_yaml:
            return f"fix package_paths: {{{package}: <dir>}} in the vendor YAML"
        return f"fix --package-path {package}=<dir> (the package's folder, the one holding its package.xml)"

    @property
    def packages_option(self) -> str:
        """The name of the package mapping, in a sentence."""
        return "package_paths in the vendor YAML" if self.in_yaml else "--package-path PKG=DIR"

    @property
    def urdf_path(self) -> str:
        """Where the description's path was given, for a fix such as "check <this>"."""
        return "the urdf: path in the vendor YAML (relative paths are relative to the YAML)" if self.in_yaml \
            else "the --urdf path"

    @property
    def urdf_key(self) -> str:
        return "urdf:" if self.in_yaml else "--urdf"


YAML = Wording(in_yaml=True)   # generate, check, diff: the inputs come from robots/<vendor>/<robot>.yaml
CLI = Wording(in_yaml=False)   # new, inspect: the inputs come from the command line
