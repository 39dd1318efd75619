"""Fixtures shared by every tier (tests/README.md); the helpers they use live in tests/support/."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cli import cli
from tests.support.repo import copy_project


@pytest.fixture
def robots_project(tmp_path: Path) -> Path:
    """A project at tmp_path/proj holding a copy of the repository's robots/, nothing generated yet."""
    return copy_project(tmp_path / "proj")


@pytest.fixture
def project(robots_project: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    """``robots_project`` after ``rhi-gen generate``: the repository's robots as a user's generated project.

    tests/cli/test_hostile_inputs.py overrides it with its own one-robot project (the hostile arm)."""
    assert cli(capsys, robots_project, "generate")[0] == 0
    return robots_project
