"""The meshes a URDF names by a path of its own (not package://), and where they are in the project.

A vendor's URDF names its meshes three ways: ``package://<description>/meshes/...`` (they resolve
where the vendor's description package is installed: left alone), a path relative to the URDF
(``meshes/pelvis.STL``, ``./meshes/pelvis.stl``, ``../meshes/...``), or ``file://`` / an absolute path.
The installed URDF lies in ``share/robot_hardware_interface/urdf/``, where a relative path points at
nothing; so each relative (or file:// inside the project) mesh that exists in the project becomes a
copy in the package, ``meshes/<robot>/<its path beside the URDF>``, and the installed URDF names it
``package://robot_hardware_interface/meshes/<robot>/...`` (RViz, robot_state_publisher and the fake
robot's MuJoCo all resolve package://). Only referenced files are copied, never a whole folder.

Only files inside the project count: a clone of the project (CI's `rhi-gen check`) must see the same
files. A relative mesh not found is reported (``MissingMesh``) and left as written; an absolute path
or file:// outside the project is left as written without a word (it names one machine's file).
"""
from __future__ import annotations

import os
import posixpath
import re
from pathlib import Path
from urllib.parse import unquote

from lxml import etree

from ..model import MeshCopy, MissingMesh

_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*://")
FILE_SCHEME = "file://"


def mesh_references(xml: bytes) -> tuple[str, ...]:
    """Every distinct ``<mesh filename>`` of the URDF, in document order."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    try:
        root = etree.fromstring(xml, parser)
    except etree.XMLSyntaxError:
        return ()  # the URDF loader has already accepted it; nothing to copy from what it cannot parse
    seen: dict[str, None] = {}
    for mesh in root.iter("mesh"):
        name = mesh.get("filename")
        if name:
            seen.setdefault(name.strip(), None)
    return tuple(seen)


def _local_path(reference: str, urdf_dir: str) -> tuple[str, bool] | None:
    """(absolute normalised path, written as relative) of a reference naming a file; None for package://,
    other schemes and unexpanded substitutions."""
    if "$(" in reference or "${" in reference:
        return None
    if reference.startswith(FILE_SCHEME):
        path = unquote(reference[len(FILE_SCHEME):])
        return (os.path.normpath(path), False) if path.startswith("/") else None
    if _SCHEME.match(reference):
        return None
    if reference.startswith("/"):
        return os.path.normpath(reference), False
    return os.path.normpath(os.path.join(urdf_dir, reference)), True


def _inside(path: str, root: str) -> bool:
    return path == root or path.startswith(root.rstrip("/") + "/")


def find_meshes(xml: bytes, urdf_file: str | Path, project_root: Path,
                robot: str) -> tuple[tuple[MeshCopy, ...], tuple[MissingMesh, ...]]:
    """(copies by package path, missing in URDF order) for the URDF ``urdf_file`` (its folder is where
    relative paths start) of ``robot``, whose expansion is ``xml``."""
    root = os.path.normpath(os.path.abspath(project_root))
    urdf_dir = os.path.dirname(os.path.normpath(os.path.abspath(urdf_file)))
    found: list[tuple[str, str]] = []
    missing: list[MissingMesh] = []
    for reference in mesh_references(xml):
        local = _local_path(reference, urdf_dir)
        if local is None:
            continue
        path, relative = local
        if _inside(path, root) and os.path.isfile(path):
            found.append((reference, path))
        elif relative:
            missing.append(MissingMesh(reference, Path(os.path.relpath(path, root)).as_posix()))
    if not found:
        return (), tuple(missing)
    # Paths as they lie beside the URDF; a mesh above its folder (../meshes/x.stl) moves the base up,
    # so two different files never share a package path.
    base = os.path.commonpath([urdf_dir, *(os.path.dirname(p) for _, p in found)])
    copies = (MeshCopy(reference, Path(os.path.relpath(path, root)).as_posix(),
                       f"meshes/{robot}/{Path(os.path.relpath(path, base)).as_posix()}")
              for reference, path in found)
    return tuple(sorted(copies, key=lambda c: (c.path, c.reference))), tuple(missing)


def missing_line(key: str, urdf_shown: str, missing: tuple[MissingMesh, ...]) -> str | None:
    """The one line `new` and `generate` print for a robot whose relative meshes are not in the project:
    how many, the first and where it was looked for, and how to provide them. None when none is missing."""
    if not missing:
        return None
    first = missing[0]
    written = posixpath.normpath(first.reference)
    if "/" not in written:
        how = f"put the mesh files beside {urdf_shown}"
    elif not written.startswith("../"):
        how = f"put the vendor's {written.split('/', 1)[0]}/ folder beside {urdf_shown}"
    else:
        how = f"put the vendor's mesh files in {posixpath.dirname(first.looked)}/"
    count = f"{len(missing)} mesh{'es' if len(missing) > 1 else ''}"
    return (f"meshes: {key} names {count} that {'are' if len(missing) > 1 else 'is'} not in the project (first: "
            f"{first.reference}, looked for {first.looked}); optional, the package and the fake robot work "
            f"without them: to install them, {how} (only the files the URDF names are copied) and run "
            "`rhi-gen generate`")
