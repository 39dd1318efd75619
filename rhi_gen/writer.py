"""Writing: compare a rendered plan with the disk, show it, apply it all-or-nothing.

Only files whose bytes change are touched. Apply first writes every new file next to its target,
then swaps them in with os.replace; if anything fails, what was already swapped is restored, so a
failure at any point leaves every file as it was.
"""
from __future__ import annotations

import difflib
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

from .errors import RhiGenError

CREATED, CHANGED, UNCHANGED, REMOVED = "created", "changed", "unchanged", "removed"


class WriteError(RhiGenError):
    """The disk refused a write; every file was restored."""


@dataclass(frozen=True)
class FileChange:
    path: str               # relative to the output root, POSIX
    status: str             # created | changed | unchanged | removed
    old: bytes | None
    new: bytes | None


def compare(out_root: Path, plan: dict[str, bytes], removable: Iterable[str] = ()) -> list[FileChange]:
    """What applying ``plan`` under ``out_root`` would do; ``removable`` are owned files no longer planned."""
    changes = []
    for rel, data in plan.items():
        target = out_root / rel
        old = target.read_bytes() if target.is_file() else None
        status = CREATED if old is None else (UNCHANGED if old == data else CHANGED)
        changes.append(FileChange(rel, status, old, data))
    for rel in sorted(set(removable) - set(plan)):
        target = out_root / rel
        if target.is_file():
            changes.append(FileChange(rel, REMOVED, target.read_bytes(), None))
    return changes


def unified_diff(change: FileChange, prefix: str = "") -> str:
    def lines(data: bytes | None) -> list[str]:
        return [] if data is None else data.decode("utf-8", "replace").splitlines(keepends=True)

    old_name = "/dev/null" if change.old is None else f"a/{prefix}{change.path}"
    new_name = "/dev/null" if change.new is None else f"b/{prefix}{change.path}"
    text = "".join(difflib.unified_diff(lines(change.old), lines(change.new), old_name, new_name))
    if text and not text.endswith("\n"):
        text += "\n"
    return text


BACKUP_DIR = ".rhi-gen-backup"
# The backup folder lives in generated/, beside (never inside) the package: colcon must not find a
# second package.xml or CMakeLists.txt, and git should not pick backups up by accident.
BACKUP_MARKERS = {
    f"{BACKUP_DIR}/COLCON_IGNORE": b"",
    f"{BACKUP_DIR}/.gitignore": b"# rhi-gen --force backups: kept for you, not for version control\n*\n",
}


def backup_name(out_root: Path, rel: str, taken: set[str] = frozenset()) -> str:
    """``.rhi-gen-backup/<rel>.N`` with N one more than the highest backup of ``rel`` (1 for the first).

    Deterministic (no timestamps): the same disk state always gives the same name.
    """
    target = out_root / BACKUP_DIR / rel
    highest = 0
    if target.parent.is_dir():
        for sibling in target.parent.iterdir():
            suffix = sibling.name[len(target.name) + 1:]
            if sibling.name.startswith(target.name + ".") and suffix.isdigit():
                highest = max(highest, int(suffix))
    n = highest + 1
    while f"{BACKUP_DIR}/{rel}.{n}" in taken:
        n += 1
    return f"{BACKUP_DIR}/{rel}.{n}"


def backup_changes(out_root: Path, originals: dict[str, bytes]) -> list[FileChange]:
    """CREATED changes that keep ``originals`` (rel path -> current bytes) under .rhi-gen-backup/."""
    if not originals:
        return []
    out: list[FileChange] = []
    for rel, data in sorted(BACKUP_MARKERS.items()):
        if not (out_root / rel).exists():
            out.append(FileChange(rel, CREATED, None, data))
    taken: set[str] = set()
    for rel, data in sorted(originals.items()):
        name = backup_name(out_root, rel, taken)
        taken.add(name)
        out.append(FileChange(name, CREATED, None, data))
    return out


_ANSI = {"bold": "\x1b[1m", "red": "\x1b[31m", "green": "\x1b[32m", "cyan": "\x1b[36m", "reset": "\x1b[0m"}


def colour_diff(text: str) -> str:
    """ANSI colours for a unified diff (headers bold, hunks cyan, removals red, additions green)."""
    out = []
    for line in text.splitlines(keepends=True):
        body, nl = (line[:-1], "\n") if line.endswith("\n") else (line, "")
        if line.startswith(("+++ ", "--- ")):
            colour = "bold"
        elif line.startswith("@@"):
            colour = "cyan"
        elif line.startswith("+"):
            colour = "green"
        elif line.startswith("-"):
            colour = "red"
        else:
            out.append(line)
            continue
        out.append(f"{_ANSI[colour]}{body}{_ANSI['reset']}{nl}")
    return "".join(out)


def apply(out_root: Path, changes: list[FileChange]) -> None:
    """Make the disk match ``changes``; all or nothing.

    Phase 1 writes every new content to a temp file beside its target (a failure removes them and
    any folder made). Phase 2 moves each old file aside and the new one in with os.replace; a
    failure (or Ctrl-C) moves every old file back and removes every new one. Only then are the
    old files deleted. Callers put the manifest and --force backups in the same ``changes``, so
    they land in the same transaction as the files.
    """
    pending = [c for c in changes if c.status in (CREATED, CHANGED, REMOVED)]
    staged: list[tuple[FileChange, Path | None]] = []
    made_dirs: list[Path] = []
    try:
        for change in pending:
            target = out_root / change.path
            if change.new is None:
                staged.append((change, None))
                continue
            for parent in reversed(target.parents):
                if not parent.exists():
                    parent.mkdir()
                    made_dirs.append(parent)
            fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".rhi-tmp", dir=target.parent)
            staged.append((change, Path(tmp)))
            with os.fdopen(fd, "wb") as handle:
                handle.write(change.new)
            if target.exists():
                os.chmod(tmp, target.stat().st_mode & 0o777)
            else:
                os.chmod(tmp, 0o644)
    except BaseException as exc:
        _discard(staged, made_dirs)
        if isinstance(exc, OSError):
            raise WriteError(f"cannot write: {exc.strerror}", file=getattr(exc, "filename", None),
                             fix="nothing was changed; free disk space or fix permissions and retry") from exc
        raise

    swapped: list[tuple[Path, Path | None]] = []  # (target, old file moved aside, or None)
    reserved: list[Path] = []                      # every name reserved for an old file
    try:
        for change, tmp in staged:
            target = out_root / change.path
            aside = None
            if target.exists():
                fd, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".rhi-bak", dir=target.parent)
                os.close(fd)
                aside = Path(name)
                reserved.append(aside)
                os.replace(target, aside)
            swapped.append((target, aside))
            if tmp is not None:
                os.replace(tmp, target)
    except BaseException as exc:
        _restore(swapped)
        for name in reserved:
            _quiet_unlink(name)
        _discard(staged, made_dirs)
        if isinstance(exc, OSError):
            raise WriteError(f"cannot replace file: {exc.strerror}", file=getattr(exc, "filename", None),
                             fix="every file was restored; fix the disk problem and retry") from exc
        raise
    for name in reserved:
        _quiet_unlink(name)
    _remove_empty_dirs(out_root, [out_root / c.path for c in pending if c.status == REMOVED])


def _restore(swapped: list[tuple[Path, Path | None]]) -> None:
    """Undo the swaps, newest first: old files back in place, new files gone."""
    for target, aside in reversed(swapped):
        try:
            if aside is not None:
                os.replace(aside, target)
            elif target.exists():
                target.unlink()
        except OSError:
            pass


def _quiet_unlink(path: Path) -> None:
    try:
        path.unlink(missing_ok=True)
    except OSError:
        pass


def _discard(staged: list[tuple[FileChange, Path | None]], made_dirs: list[Path]) -> None:
    for _change, tmp in staged:
        if tmp is not None:
            _quiet_unlink(tmp)
    for folder in reversed(made_dirs):
        try:
            folder.rmdir()
        except OSError:
            pass


def _remove_empty_dirs(root: Path, removed: list[Path]) -> None:
    for path in removed:
        for parent in path.parents:
            if parent == root or root not in parent.parents:
                break
            try:
                parent.rmdir()
            except OSError:
                break
