"""The repository as the tests see it: its folders, and copies of its project to work on."""
from __future__ import annotations

import shutil
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TESTS = REPO / "tests"
FIXTURES = TESTS / "fixtures"
URDF_FIXTURES = FIXTURES / "urdf"
HOSTILE = FIXTURES / "hostile"
# The upstream material next to the repository (SDK facts, vendor URDFs and messages); absent in a fresh clone.
SHARED = REPO.parent / "shared"
UPSTREAM_URDF = SHARED / "upstream" / "urdf"
PACKAGE = "robot_hardware_interface"


def copy_project(root: Path, *, generated: bool = False) -> Path:
    """The repository's robots/ (and with ``generated``, its checked-in generated/) copied into ``root``."""
    shutil.copytree(REPO / "robots", root / "robots")
    if generated:
        shutil.copytree(REPO / "generated", root / "generated")
    return root
