"""What ``$(arg name)`` and ``$(find pkg)`` mean in an expansion: only what the user named.

- xacro args are checked to be strings (the vendor YAML could give a number);
- package folders are made absolute, and kept as the user wrote them for messages;
- while xacro runs, a stand-in ``ament_index_python.packages`` module in ``sys.modules`` knows
  exactly those packages, so ``$(find pkg)`` and ``${find('pkg')}`` never depend on a sourced ROS
  workspace; an unknown package or a folder that is not one raises :class:`UnknownPackage` or
  :class:`BadPackageDir` for the error mapping (:mod:`.xacro_errors`);
- :func:`resolve_spec` resolves the same substitutions in an include's ``filename``, to find the
  ``<xacro:include>`` a failure came from (:mod:`.xacro_includes`).
"""
from __future__ import annotations

import contextlib
import os
import re
import sys
import types
from collections.abc import Iterator, Mapping
from pathlib import Path

from ..errors import UrdfError
from .xacro_run import XacroRun

__all__ = ["BadPackageDir", "UnknownPackage", "ament_index_stand_in", "checked_args", "package_folders",
           "resolve_spec"]

_MISSING = object()
_AMENT_MODULES = ("ament_index_python", "ament_index_python.packages")


def checked_args(args: Mapping[str, str] | None, shown: str) -> dict[str, str]:
    """``args`` as xacro's ``mappings``; a value that is not a string is an error in ``shown``."""
    mappings: dict[str, str] = {}
    for key, value in (args or {}).items():
        if not isinstance(key, str) or not isinstance(value, str):
            raise UrdfError(
                f"xacro arg {key!r} must be a string, got {type(value).__name__} {value!r}",
                file=shown, key="xacro_args",
                fix="quote the value in the vendor YAML (xacro args are strings)")
        mappings[key] = value
    return mappings


def package_folders(package_paths: Mapping[str, str | Path] | None) -> tuple[dict[str, str], dict[str, str]]:
    """package -> absolute folder, and package -> folder as the user wrote it (for messages)."""
    packages: dict[str, str] = {}
    given: dict[str, str] = {}  # as the user wrote them, for messages
    for pkg, directory in (package_paths or {}).items():
        packages[str(pkg)] = os.path.normpath(os.path.abspath(os.fspath(directory)))
        given[str(pkg)] = os.fspath(directory)
    return packages, given


class UnknownPackage(KeyError):
    """Raised by the stand-in ``get_package_share_directory`` (the real one raises a KeyError too)."""

    def __init__(self, package: str) -> None:
        super().__init__(package)
        self.package = package

    def __str__(self) -> str:
        return f"package '{self.package}' not found"


class BadPackageDir(Exception):
    def __init__(self, package: str, directory: str) -> None:
        super().__init__(f"package '{package}' -> {directory} is not a directory")
        self.package = package
        self.directory = directory


@contextlib.contextmanager
def ament_index_stand_in(packages: Mapping[str, str],
                          given: Mapping[str, str] | None = None) -> Iterator[None]:
    """Make ``from ament_index_python.packages import get_package_share_directory`` resolve
    exactly ``packages`` while the block runs; the previous ``sys.modules`` entries (a real
    ament_index_python, or none) are put back afterwards."""

    def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
        try:
            directory = packages[package_name]
        except KeyError:
            raise UnknownPackage(package_name) from None
        if not os.path.isdir(directory):
            raise BadPackageDir(package_name, (given or packages).get(package_name, directory))
        return directory

    top = types.ModuleType("ament_index_python")
    top.__path__ = []  # a package, so the dotted import is well-formed
    sub = types.ModuleType("ament_index_python.packages")
    sub.PackageNotFoundError = UnknownPackage  # type: ignore[attr-defined]
    sub.get_package_share_directory = get_package_share_directory  # type: ignore[attr-defined]
    sub.get_package_prefix = get_package_share_directory  # type: ignore[attr-defined]
    top.packages = sub  # type: ignore[attr-defined]

    saved = {name: sys.modules.get(name, _MISSING) for name in _AMENT_MODULES}
    sys.modules["ament_index_python"] = top
    sys.modules["ament_index_python.packages"] = sub
    try:
        yield
    finally:
        for name, module in saved.items():
            if module is _MISSING:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = module  # type: ignore[assignment]


_SUBSTITUTION = re.compile(r"\$\((\w+)(?:\s+([^)\s]*))?\s*\)")


def resolve_spec(spec: str, including_dir: str, run: XacroRun) -> str | None:
    """The path an include's ``filename`` names, for the substitutions rhi-gen can resolve
    (``$(find pkg)``, ``$(arg name)``, ``$(dirname)``); None when it holds anything else."""
    unresolved = False

    def substitute(m: re.Match[str]) -> str:
        nonlocal unresolved
        command, value = m.group(1), m.group(2) or ""
        if command == "find" and value in run.packages:
            return run.packages[value]
        if command == "arg" and value in run.args:
            return run.args[value]
        if command == "dirname":
            return including_dir
        unresolved = True
        return ""

    text = _SUBSTITUTION.sub(substitute, spec.strip())
    if unresolved or "$" in text:
        return None
    return os.path.normpath(text if os.path.isabs(text) else os.path.join(including_dir, text))
