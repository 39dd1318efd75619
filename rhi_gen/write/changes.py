"""What applying a plan would do to the disk, file by file: created, changed, unchanged or removed."""
from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

CREATED, CHANGED, UNCHANGED, REMOVED = "created", "changed", "unchanged", "removed"


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
