"""Read a URDF (or xacro) file strictly into a :class:`~rhi_gen.model.UrdfRobot`: the entry point.

- The file is read with one clear error for each way it can be unreadable.
- ``*.xacro`` files (and any file whose root declares the xacro namespace) are expanded first by
  :func:`rhi_gen.inputs.xacro_expand.expand_xacro`.
- The XML is parsed strictly (:mod:`.urdf_parse`) and checked the way ROS' urdfdom does
  (:mod:`.urdf_robot`, :mod:`.urdf_joints`, :mod:`.urdf_tree`); the fingerprint bytes come from
  :mod:`.urdf_canonical`.
- Every problem is a :class:`UrdfError` with the file as the user knows it (``display_path``), the
  line of the offending element and a fix.

yourdfpy is deliberately not used here: it recovers from malformed XML and is slow to import.
``JOINT_TYPES``, ``canonical_urdf_bytes`` and ``portable_xml`` are re-exported from their modules.
"""
from __future__ import annotations

import stat
from collections.abc import Mapping
from pathlib import Path

from lxml import etree

from ..errors import UrdfError
from ..model import UrdfRobot
from .urdf_canonical import canonical_urdf_bytes, portable_xml
from .urdf_joints import JOINT_TYPES
from .urdf_parse import UrdfContext, declares_xacro, parse_strict, strict_parser
from .urdf_robot import robot_from_root
from .wording import YAML, Wording

__all__ = ["JOINT_TYPES", "canonical_urdf_bytes", "is_xacro", "load_urdf", "parse_urdf_bytes", "portable_xml"]


def parse_urdf_bytes(xml: bytes, *, source: str) -> UrdfRobot:
    """Parse an already-expanded URDF. ``source`` is how the document is named in errors."""
    ctx = UrdfContext(source, expanded=False)
    return robot_from_root(parse_strict(xml, ctx), xml, ctx)


def _read(path: Path, shown: str, wording: Wording) -> bytes:
    where = f"check {wording.urdf_path}"
    inside = f"point {wording.urdf_key} at the .urdf or .xacro file inside it"
    try:
        st = path.stat()
        if stat.S_ISDIR(st.st_mode):
            raise UrdfError("is a directory, not a URDF or xacro file", file=shown,
                            fix=inside)
        if not stat.S_ISREG(st.st_mode):
            raise UrdfError("is not a regular file", file=shown, fix=where)
        return path.read_bytes()
    except UrdfError:
        raise
    except (FileNotFoundError, NotADirectoryError):
        raise UrdfError("file not found", file=shown, fix=where) from None
    except IsADirectoryError:
        raise UrdfError("is a directory, not a URDF or xacro file", file=shown,
                        fix=inside) from None
    except PermissionError:
        raise UrdfError("cannot read the file (permission denied)", file=shown,
                        fix="make the file readable (chmod a+r)") from None
    except OSError as e:
        raise UrdfError(f"cannot read the file ({e.strerror or e})", file=shown, fix=where) from None
    except ValueError as e:  # e.g. a NUL character in the path
        raise UrdfError(f"invalid path ({e})", file=shown, fix=where) from None


def is_xacro(path: str | Path) -> bool:
    """Whether ``load_urdf`` runs xacro on ``path``: its name ends in ``.xacro`` or its root declares the
    xacro namespace. False for a file that cannot be read or parsed (load_urdf reports those)."""
    p = Path(path)
    if p.name.lower().endswith(".xacro"):
        return True
    try:
        data = p.read_bytes()
        return b"xacro" in data and declares_xacro(etree.fromstring(data, strict_parser()))
    except (OSError, ValueError, etree.LxmlError):
        return False


def load_urdf(path: str | Path, *, xacro_args: Mapping[str, str] | None = None,
              package_paths: Mapping[str, str | Path] | None = None,
              display_path: str | None = None, wording: Wording = YAML) -> UrdfRobot:
    """Load a URDF or xacro file.

    ``xacro_args`` and ``package_paths`` (ROS package name -> directory for ``$(find pkg)``) are
    used only when the file is a xacro: its name ends in ``.xacro`` or its root declares the xacro
    namespace. ``display_path`` is how the file is named in error messages and in
    ``UrdfRobot.source`` (default: ``path`` as given). ``wording`` says how a fix names the inputs:
    vendor YAML keys (``wording.YAML``, the default) or command-line options (``wording.CLI``).
    """
    p = Path(path)
    shown = display_path if display_path is not None else str(path)
    data = _read(p, shown, wording)
    ctx = UrdfContext(shown, expanded=False, wording=wording)
    is_xacro = p.name.lower().endswith(".xacro")
    root = None
    if is_xacro or b"xacro" in data:
        root = parse_strict(data, ctx)  # lxml's messages for malformed XML beat expat's
        is_xacro = is_xacro or declares_xacro(root)
    if is_xacro:
        from .xacro_expand import expand_xacro

        expanded = expand_xacro(p, xacro_args or {}, package_paths or {}, display_path=shown, wording=wording)
        xctx = UrdfContext(shown, expanded=True, wording=wording)
        canonical = portable_xml(canonical_urdf_bytes(expanded), p, package_paths or {})
        return robot_from_root(parse_strict(expanded, xctx), expanded, xctx, canonical)
    if root is None:
        root = parse_strict(data, ctx)
    return robot_from_root(root, data, ctx)
