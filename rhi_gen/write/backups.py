"""--force backups: the file a forced write replaces is kept as generated/.rhi-gen-backup/<path>.N."""
from __future__ import annotations

from collections.abc import Set
from pathlib import Path

from .changes import CREATED, FileChange

BACKUP_DIR = ".rhi-gen-backup"
# The backup folder lives in generated/, beside (never inside) the package: colcon must not find a
# second package.xml or CMakeLists.txt, and git should not pick backups up by accident.
BACKUP_MARKERS = {
    f"{BACKUP_DIR}/COLCON_IGNORE": b"",
    f"{BACKUP_DIR}/.gitignore": b"# rhi-gen --force backups: kept for you, not for version control\n*\n",
}


def backup_name(out_root: Path, rel: str, taken: Set[str] = frozenset()) -> str:
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
