"""The repository as the tests see it: its folders, and copies of its project to work on."""
from __future__ import annotations

import shutil
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TESTS = REPO / "tests"
FIXTURES = TESTS / "fixtures"
URDF_FIXTURES = FIXTURES / "urdf"
HOSTILE = FIXTURES / "hostile"
# The optional upstream vendor data (../shared/upstream or $RHI_UPSTREAM): tests/support/vendor_msgs.py and
# tests/support/upstream_urdf.py, which also know the copies the repository carries (tests/data/).
PACKAGE = "robot_hardware_interface"


def copy_project(root: Path, *, generated: bool = False) -> Path:
    """The repository's robots/ (and with ``generated``, its checked-in generated/) copied into ``root``."""
    shutil.copytree(REPO / "robots", root / "robots")
    if generated:
        shutil.copytree(REPO / "generated", root / "generated")
    return root
