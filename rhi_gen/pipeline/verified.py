"""The memo of the last `rhi-gen check` that passed, so checking the same bytes again loads and renders nothing.

A full check's verdict is a function of what it reads: the robot YAMLs (which robots/ lists), the
URDFs they name, robots/package.yaml, generated/.rhi-gen-manifest and every file that manifest
records, and rhi-gen itself (its code and templates, its version, the Python and libraries that
render). After a full check that passed, ``record`` keeps a sha256 of each of those files and one
stamp of rhi-gen; ``still_verified`` answers "up to date" while every one still matches, reading
the files but parsing none. Anything else misses and the full check runs and says why: an input
edited, a generated file edited, missing or no longer recorded, a robot YAML added or removed,
another rhi-gen (another version, or its code or templates edited).

The manifest's own fingerprints cannot serve: they are of the parsed YAML and the expanded URDF
(checking them means parsing and expanding), robots/package.yaml has none, and the generator version
does not change when rhi-gen's templates are edited between releases.

What the memo trusts, and what it leaves to the full check:
- A robot described by a xacro is always checked in full (no memo is kept): xacro reads files and
  environment variables (includes, $(find), $(env)) that only running it names.
- File times, to tell a file was not written while the full check read it: a file changed less than
  ``SETTLE_S`` before the check began (the same rule git uses for its index) is not memoised; the next
  check memoises it. A file replaced during a check by a copy that keeps an old time (cp -p) fools this.
- The installed libraries are told apart by their files' paths, sizes and times, not by their contents.
- The memo lives in the user's cache (rhi_gen/cache.py), never in the project: a fresh clone, CI, or
  an unwritable cache runs the full check every time. An unreadable memo is ignored.
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import json
import os
import sys
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import rhi_gen

from ..cache import cache_root
from ..project import Project, robot_yamls

if TYPE_CHECKING:
    from .load import LoadedRobot

FORMAT = 2
SETTLE_S = 2.0   # a file this recent when the check began may have changed while it was read
KEEP = 64        # memos kept (one per project folder); the oldest go first
LIBRARIES = ("jinja2", "markupsafe", "yaml", "lxml")  # what rendering runs besides rhi-gen and Python
PACKAGE_ROOT = Path(rhi_gen.__file__).parent


def memo_path(project: Project) -> Path:
    """One memo per project folder."""
    return cache_root() / "checked" / (hashlib.sha256(str(project.root).encode()).hexdigest()[:24] + ".json")


def code_stamp(root: Path = PACKAGE_ROOT) -> str:
    """sha256 of every file of the rhi_gen package (code, templates, C++ sources) with its path, of
    rhi-gen's version, of the Python running it and of the libraries rendering runs."""
    digest = hashlib.sha256(f"{rhi_gen.__version__}\0{sys.version}\0".encode())
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for name in sorted(files):
            if not name.endswith((".pyc", ".pyo")):
                path = Path(folder, name)
                digest.update(f"{path.relative_to(root).as_posix()}\0".encode())
                digest.update(hashlib.sha256(path.read_bytes()).digest())
    for library in LIBRARIES:
        spec = importlib.util.find_spec(library)
        origin = spec.origin if spec is not None else None
        stat = os.stat(origin) if origin else None
        digest.update(f"{library}\0{origin}\0{stat and (stat.st_size, stat.st_mtime_ns)}\0".encode())
    return digest.hexdigest()


def _sha256(path: Path) -> str | None:
    """sha256 of the file's bytes; None when it is not a readable file."""
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


def _package_meshes(project: Project) -> list[str]:
    """The files in the package's meshes/ (rhi-gen owns the folder: one added there makes the check fail)."""
    folder = project.package_dir / "meshes"
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file()) \
        if folder.is_dir() else []


def still_verified(project: Project) -> int | None:
    """The number of robots when the last passing check read exactly these bytes with this rhi-gen; else None."""
    try:
        memo = json.loads(memo_path(project).read_text(encoding="utf-8"))
        if memo.get("format") != FORMAT or memo["root"] != str(project.root):
            return None
        if memo["yamls"] != [str(p) for p in robot_yamls(project)]:
            return None
        if any(_sha256(Path(path)) != sha for path, sha in memo["files"].items()):
            return None
        if memo["meshes"] != _package_meshes(project):
            return None
        if memo["stamp"] != code_stamp():
            return None
        return int(memo["robots"])
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def record(project: Project, loaded: Sequence[LoadedRobot], outputs: Iterable[str], began: float) -> bool:
    """Memoise a full check that passed: ``loaded`` its robots, ``outputs`` the files the manifest records
    (relative to generated/), ``began`` when it started (time.time()). False when nothing was kept: a
    xacro description, a file too recent, or the cache not writable."""
    from ..inputs.package_info import FILE_NAME as PACKAGE_YAML
    from ..inputs.urdf_loader import is_xacro
    from ..write.manifest import path as manifest_path

    urdfs = [Path(r.config.urdf) for r in loaded]
    if any(is_xacro(urdf) for urdf in urdfs):
        return False
    yamls = [r.yaml_path for r in loaded]
    # the meshes copied, and where the missing ones were looked for: one appearing there changes the verdict
    meshes = [project.root / path for r in loaded for path in (*(m.source for m in r.model.meshes),
                                                                *(m.looked for m in r.model.missing_meshes))]
    files = [*yamls, *urdfs, project.robots_dir / PACKAGE_YAML, manifest_path(project.generated_dir),
             *(project.generated_dir / rel for rel in outputs), *meshes]
    hashes: dict[str, str | None] = {}
    for path in files:
        try:
            if os.stat(path).st_mtime > began - SETTLE_S:
                return False
        except FileNotFoundError:
            pass
        except OSError:
            return False
        hashes[str(path)] = _sha256(path)
    try:
        stamp = code_stamp()
    except OSError:  # a file of rhi-gen that cannot be read: no memo could ever match
        return False
    memo = {"format": FORMAT, "root": str(project.root), "robots": len(yamls), "stamp": stamp,
            "yamls": [str(p) for p in yamls], "files": hashes, "meshes": _package_meshes(project)}
    return _write(memo_path(project), json.dumps(memo, sort_keys=True))


def _write(target: Path, text: str) -> bool:
    """``text`` to ``target`` whole or not at all (a concurrent check reads the old memo or the new one)."""
    import tempfile  # only when writing: the answer from a memo never needs it

    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(suffix=".tmp", dir=target.parent)
    except OSError:
        return False
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.replace(tmp, target)
    except OSError:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        return False
    _prune(target.parent)
    return True


def _prune(folder: Path) -> None:
    """Keep the ``KEEP`` most recent memos (a memo per project folder ever checked would pile up)."""
    with contextlib.suppress(OSError):
        memos = sorted(folder.glob("*.json"), key=lambda p: p.stat().st_mtime, reverse=True)
        for old in memos[KEEP:]:
            old.unlink()
