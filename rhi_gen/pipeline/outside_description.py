"""`rhi-gen new` with a description that lies (or reads files) outside the project.

The vendor YAML must name a description a clone of the project can read: a path that climbs out of
the repository (``urdf: ../../../home/x/robot.urdf``) or a ``package_paths`` entry in someone's
workspace breaks `rhi-gen check` in CI. So when the description, or any file xacro reads for it
(includes, ``load_yaml`` files), is outside the project, `new` writes the expanded URDF (a plain
URDF: its bytes; a xacro: the expansion with the given args) to ``robots/<vendor>/<robot>.urdf``, names
that in ``urdf:``, and records in a YAML comment where it came from and how to refresh it. Copying
only a xacro's top file would break on its first include from another package; the expansion is the
one self-contained form. A description entirely inside the project keeps its relative path.
"""
from __future__ import annotations

import shlex
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import ProjectError
from ..inputs import wording
from ..inputs.urdf_loader import is_xacro
from ..inputs.xacro_expand import xacro_files
from ..model import UrdfRobot
from ..project import Project


@dataclass(frozen=True)
class DescriptionCopy:
    """The self-contained copy `new` writes into the project, and where it came from."""
    source: Path                 # the description given to `new` (absolute)
    reason: Path                 # the first file read that lies outside the project
    rel: str                     # project-relative path of the copy (robots/<vendor>/<robot>.urdf)
    data: bytes                  # the (expanded) URDF
    expanded: bool               # True: xacro expanded; False: a plain URDF copied
    xacro_args: Mapping[str, str] = field(default_factory=dict)
    package_paths: Mapping[str, str] = field(default_factory=dict)

    @property
    def file_name(self) -> str:
        """How the YAML next to the copy names it (``urdf:``)."""
        return Path(self.rel).name

    def _why(self) -> str:
        if self.reason == self.source:
            return "it lies outside the project"
        return f"it reads {_printable(str(self.reason))}, outside the project"

    def refresh_command(self) -> str:
        src = shlex.quote(str(self.source))
        if not self.expanded:
            return f"cp {src} {self.rel}"
        args = " ".join(shlex.quote(f"{k}:={v}") for k, v in self.xacro_args.items())
        return f"xacro {src}{' ' + args if args else ''} > {self.rel}"

    def note(self, yaml_rel: str) -> str:
        """The line `new` prints on stdout."""
        verb = f"expanded {_printable(str(self.source))} into" if self.expanded else \
            f"copied {_printable(str(self.source))} to"
        return (f"{verb} {self.rel}: {self._why()}, and a clone of the project must be able to run "
                f"`rhi-gen check` ({yaml_rel} says where it came from)")

    def yaml_comment(self) -> list[str]:
        """Comment lines for the YAML, just above ``urdf:``."""
        src = _printable(str(self.source))
        if self.expanded:
            given = [f"{k}:={v}" for k, v in self.xacro_args.items()]
            given += [f"$(find {k}) = {v}" for k, v in self.package_paths.items()]
            first = f"# urdf: {src} expanded by `rhi-gen new`" + (f" ({'; '.join(given)})" if given else "")
        else:
            first = f"# urdf: a copy of {src}, made by `rhi-gen new`"
        return [_printable(first),
                _printable(f"#   because {self._why()}: the copy lets a clone of the project run `rhi-gen check`."),
                _printable(f"#   To take a newer version: {self.refresh_command()}")]


def _printable(text: str) -> str:
    """A path inside a YAML comment: a newline (or any control character) would end the comment."""
    return "".join(c if c.isprintable() else f"\\x{ord(c):02x}" for c in text)


def _inside(project: Project, path: Path) -> bool:
    return path.resolve().is_relative_to(project.root.resolve())


def files_read(urdf_path: Path, xacro_args: Mapping[str, str], package_paths: Mapping[str, str]) -> list[Path]:
    """The description and, for a xacro, every file its expansion reads (absolute)."""
    files = [urdf_path.resolve()]
    if is_xacro(urdf_path):
        files += xacro_files(urdf_path, xacro_args, package_paths, display_path=str(urdf_path),
                             wording=wording.CLI)
    return files


def plan_copy(project: Project, *, vendor: str, robot: str, urdf_path: Path, urdf: UrdfRobot,
              xacro_args: Mapping[str, str], package_paths: Mapping[str, str], force: bool) -> DescriptionCopy | None:
    """The copy `new` must write, or None when the description and everything it reads are in the project.

    Refuses (ProjectError) to replace a different file already at the copy's place without ``force``.
    """
    outside = [f for f in files_read(urdf_path, xacro_args, package_paths) if not _inside(project, f)]
    if not outside:
        return None
    target = project.yaml_path(vendor, robot).with_suffix(".urdf")
    if target.resolve() == urdf_path.resolve():  # never overwrite the description itself with its expansion
        target = target.with_suffix(".expanded.urdf")
    rel = target.relative_to(project.root).as_posix()
    data = urdf.canonical_xml
    if target.exists() and not target.is_file():
        raise ProjectError("is in the way of the description's copy (not a file)", file=rel,
                           fix="move it away, then rerun `rhi-gen new`")
    if target.exists() and not force and target.read_bytes() != data:
        raise ProjectError(f"already exists and is not {urdf_path}", file=rel,
                           fix=f"pass --urdf {rel} to use that file, or add --force to replace it with "
                               f"{'the expansion' if is_xacro(urdf_path) else 'a copy'} of {urdf_path}")
    return DescriptionCopy(
        source=urdf_path.resolve(), reason=outside[0], rel=rel, data=data, expanded=is_xacro(urdf_path),
        xacro_args=dict(xacro_args),
        package_paths={k: str(Path(v).resolve()) for k, v in package_paths.items()})
