"""Apply a list of FileChanges all-or-nothing.

Only files whose bytes change are touched. Apply first writes every new file next to its target,
then swaps them in with os.replace; if anything fails, what was already swapped is restored, so a
failure at any point leaves every file as it was.
"""
from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

from ..errors import WriteError
from .changes import CHANGED, CREATED, REMOVED, FileChange


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
            fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".rhi-tmp", dir=target.parent)
            tmp = Path(tmp_name)
            staged.append((change, tmp))
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
        for change, staged_tmp in staged:
            target = out_root / change.path
            aside: Path | None = None
            if target.exists():
                fd, aside_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".rhi-bak", dir=target.parent)
                os.close(fd)
                aside = Path(aside_name)
                reserved.append(aside)
                os.replace(target, aside)
            swapped.append((target, aside))
            if staged_tmp is not None:
                os.replace(staged_tmp, target)
    except BaseException as exc:
        _restore(swapped)
        for aside_path in reserved:
            _quiet_unlink(aside_path)
        _discard(staged, made_dirs)
        if isinstance(exc, OSError):
            raise WriteError(f"cannot replace file: {exc.strerror}", file=getattr(exc, "filename", None),
                             fix="every file was restored; fix the disk problem and retry") from exc
        raise
    for aside_path in reserved:
        _quiet_unlink(aside_path)
    _remove_empty_dirs(out_root, [out_root / c.path for c in pending if c.status == REMOVED])


def _restore(swapped: list[tuple[Path, Path | None]]) -> None:
    """Undo the swaps, newest first: old files back in place, new files gone."""
    for target, aside in reversed(swapped):
        with contextlib.suppress(OSError):  # best effort: restore every other file too
            if aside is not None:
                os.replace(aside, target)
            elif target.exists():
                target.unlink()


def _quiet_unlink(path: Path) -> None:
    with contextlib.suppress(OSError):
        path.unlink(missing_ok=True)


def _discard(staged: list[tuple[FileChange, Path | None]], made_dirs: list[Path]) -> None:
    for _change, tmp in staged:
        if tmp is not None:
            _quiet_unlink(tmp)
    for folder in reversed(made_dirs):
        with contextlib.suppress(OSError):
            folder.rmdir()


def _remove_empty_dirs(root: Path, removed: list[Path]) -> None:
    for path in removed:
        for parent in path.parents:
            if parent == root or root not in parent.parents:
                break
            try:
                parent.rmdir()
            except OSError:
                break
