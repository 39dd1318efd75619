"""Fixtures shared by every tier (tests/README.md); the helpers they use live in tests/support/."""
from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.support import fresh_clone, fresh_clone_selection, load, shared_use, vendor_msgs
from tests.support.cli import cli
from tests.support.repo import copy_project

REPORTS = pytest.StashKey[list[str]]()
FIXTURE_READS = pytest.StashKey[dict[object, set[str]]]()

shared_use.install()
shared_use.watch(vendor_msgs.UPSTREAM)
shared_use.watch(vendor_msgs.UPSTREAM_MSGS)


def pytest_configure(config: pytest.Config) -> None:
    """The load mode (RHI_TEST_LOAD=N: N busy processes per core beside the session, tests/support/load.py),
    and a cache of the session's own for `rhi-gen check`'s memos (rhi_gen/pipeline/verified.py): the tests'
    checks leave nothing in the user's ~/.cache, and a memo of theirs can never answer a user's check."""
    config.pluginmanager.register(load, "rhi-load")
    cache = Path(tempfile.mkdtemp(prefix="rhi-gen-test-cache-"))
    config.add_cleanup(lambda: shutil.rmtree(cache, ignore_errors=True))
    os.environ["RHI_GEN_CACHE"] = str(cache)


@pytest.fixture
def report(request: pytest.FixtureRequest) -> Callable[[str], None]:
    """``report(text)``: text for the reader, shown in the "reports" section at the end of the run
    (without -s), for figures a test measures but does not assert (the corpus summary, load times)."""
    return request.config.stash.setdefault(REPORTS, []).append


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    texts: list[str] = [*terminalreporter.config.stash.get(REPORTS, [])]
    if fresh_clone_selection.recorded():
        texts.append(f"tests that read ../shared: {fresh_clone_selection.recorded()} (a fresh clone re-runs them; "
                     f"{fresh_clone_selection.LIST_ENV}=<file> lists them)")
        fresh_clone_selection.write_list()
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


@pytest.hookimpl(trylast=True)  # after tests/cpp/conftest.py has marked the C++ tier
def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list[pytest.Item]) -> None:
    """tests/cli/test_fresh_clone.py runs last, so it knows which tests read ../shared, and its clone reuses
    every object the session compiled (its RHI_CPP_CACHE). A whole-suite session starts that clone now, running
    the quick tier and the benchmark in the background (tests/support/fresh_clone.py). The modules with C++ tests
    run first: after the last of them the clone runs the C++ tests that read ../shared, while the session runs
    the modules without a compiler. In the clone, the selection the outer session passes on
    (tests/support/fresh_clone_selection.py) deselects the rest."""
    last = [item for item in items if item.nodeid.split("::")[0].endswith("test_fresh_clone.py")]
    rest = [item for item in items if item not in last]
    with_cpp = {item.nodeid.split("::")[0] for item in rest if item.get_closest_marker("cpp") is not None}
    rest.sort(key=lambda item: item.nodeid.split("::")[0] not in with_cpp)  # stable: each group in its order
    items[:] = rest + last
    dropped = fresh_clone_selection.apply(items)
    if dropped:
        config.hook.pytest_deselected(items=dropped)
    fresh_clone.start_early(session, items)


# ------------------------------------------------------------------------ reads of ../shared (shared_use.py)
@pytest.hookimpl(wrapper=True)
def pytest_make_collect_report(collector: pytest.Collector):
    """A module whose collection read ../shared (parameters from it): each of its tests counts as reading it."""
    with shared_use.recording(main=True) as used:
        report = yield
    if used and isinstance(collector, pytest.Module):
        fresh_clone_selection.note_module(collector.nodeid)
    return report


@pytest.hookimpl(wrapper=True)
def pytest_fixture_setup(fixturedef: pytest.FixtureDef[object], request: pytest.FixtureRequest):
    """A fixture's reads count for every test that uses it (its value may carry what it read)."""
    with shared_use.recording(main=True) as used:
        result = yield
    if used:
        request.config.stash.setdefault(FIXTURE_READS, {})[fixturedef] = set(used)
    return result


@pytest.hookimpl(wrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None):
    with shared_use.recording(main=True) as used:
        result = yield
    reads = item.config.stash.get(FIXTURE_READS, {})
    info = getattr(item, "_fixtureinfo", None)  # a test function's; other items have no fixtures
    by_name = info.name2fixturedefs if info else {}
    defs = [d for name in getattr(item, "fixturenames", ()) for d in by_name.get(name, ())]
    if used or any(d in reads for d in defs):
        fresh_clone_selection.note_test(item.nodeid)
    fresh_clone.after_test(item)
    return result
