"""Fixtures shared by every tier (tests/README.md); the helpers they use live in tests/support/."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from tests.support.cli import cli
from tests.support.repo import copy_project

REPORTS = pytest.StashKey[list[str]]()


@pytest.fixture
def report(request: pytest.FixtureRequest) -> Callable[[str], None]:
    """``report(text)``: text for the reader, shown in the "reports" section at the end of the run
    (without -s), for figures a test measures but does not assert (the corpus summary, load times)."""
    return request.config.stash.setdefault(REPORTS, []).append


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    texts = terminalreporter.config.stash.get(REPORTS, [])
    if texts:
        terminalreporter.section("reports")
        for text in texts:
            terminalreporter.write_line(text.rstrip("\n"))


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


def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list[pytest.Item]) -> None:
    """tests/cli/test_fresh_clone.py runs last, so the clone it tests reuses every object the session
    compiled (its RHI_CPP_CACHE)."""
    last = [item for item in items if item.nodeid.split("::")[0].endswith("test_fresh_clone.py")]
    items[:] = [item for item in items if item not in last] + last
