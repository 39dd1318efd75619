"""The upstream URDFs the tests use as independent oracles.

The repository carries those whose licence allows it (tests/data/upstream_urdf, BSD-3-Clause: the Unitree
G1 ones and EngineAI PM01; provenance and licences beside them); the others (AgiBot X2, PM01 EDU) are read
from the project's shared vendor data, ../shared/upstream/urdf beside the clone or $RHI_UPSTREAM/urdf
(tests/support/vendor_msgs.py). A test that needs one of those skips with one line saying how to provide it.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.support import vendor_msgs
from tests.support.repo import REPO

IN_REPO = REPO / "tests" / "data" / "upstream_urdf"
SHARED = vendor_msgs.UPSTREAM / "urdf"
HOW_TO_PROVIDE = ("put the project's shared folder beside the clone (../shared/upstream/urdf) "
                  "or set RHI_UPSTREAM=<folder holding urdf/>")


def find(name: str) -> Path | None:
    """The repository's copy of upstream/urdf/<name>, else the shared one, else None."""
    for folder in (IN_REPO, SHARED):
        if (folder / name).is_file():
            return folder / name
    return None


def missing_reason(name: str) -> str:
    return f"upstream URDF {name}: not carried in the repository (licence), and {SHARED} is missing: {HOW_TO_PROVIDE}"


def require(name: str) -> Path:
    """upstream/urdf/<name>, or a one-line skip when neither the repository nor ../shared has it."""
    path = find(name)
    if path is None:
        pytest.skip(missing_reason(name))
    return path


def in_repo() -> list[Path]:
    return sorted(IN_REPO.glob("*.urdf"))


def shared_only() -> list[Path]:
    """The shared URDFs the repository does not carry ([] without ../shared)."""
    carried = {p.name for p in in_repo()}
    return [p for p in sorted(SHARED.glob("*.urdf")) if p.name not in carried] if SHARED.is_dir() else []
