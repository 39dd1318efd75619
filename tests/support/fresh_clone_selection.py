"""What the fresh clone of tests/cli/test_fresh_clone.py runs: the tests whose outcome can differ there.

The outer session (the whole suite, ../shared beside it) records which tests read ../shared
(tests/support/shared_use.py, hooks in tests/conftest.py). The clone runs the README's test command word
for word; this selection, passed in RHI_FRESH_CLONE_SELECT, deselects there the tests of the C++ tier that
read nothing of ../shared. It comes in two halves (tests/support/fresh_clone.py): the quick tier, known before
anything ran, which the clone runs while the session's C++ tier does; then the C++ tests that read ../shared,
known once the session ran them. Together they keep:
* every test that read ../shared, directly, through a fixture or a cached value (the X2 cases, which skip
  there; the stand-ins' AimDK self-test; the upstream URDF comparisons; the copy check);
* the whole quick tier (no compiler): the CLI and the install it runs from, the gates, in a couple of minutes;
* any test the outer session did not run (a new one).
What it drops builds objects from the clone's files, byte for byte the session's, with the same keys:
it would repeat the session's compiles (cache hits) and runs.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

ENV = "RHI_FRESH_CLONE_SELECT"
LIST_ENV = "RHI_SHARED_READS_LIST"

_tests: set[str] = set()
_modules: set[str] = set()


def note_test(nodeid: str) -> None:
    _tests.add(nodeid)


def note_module(nodeid: str) -> None:
    _modules.add(nodeid)


def recorded() -> int:
    return len(_tests)


def write_list() -> None:
    """The node ids that read ../shared, one per line, into the file $RHI_SHARED_READS_LIST names (if set)."""
    where = os.environ.get(LIST_ENV)
    if where:
        Path(where).write_text("".join(f"{n}\n" for n in sorted(_tests)), encoding="utf-8")


def reads_shared(nodeid: str) -> bool:
    return nodeid in _tests or nodeid.split("::")[0] in _modules


def whole_suite(config: pytest.Config) -> bool:
    """The session ran every test (no paths, -k, -m or --deselect): only then is the record complete."""
    return (config.args_source is pytest.Config.ArgsSource.TESTPATHS and not config.option.keyword
            and not config.option.markexpr and not config.option.deselect and not getattr(config.option, "lf", False))


def quick_tier(items: list[pytest.Item], own_file: str) -> dict[str, list[str]]:
    """``selection`` split, first half: the tests without a compiler (known before anything ran)."""
    outer = [i.nodeid for i in items if not i.nodeid.startswith(own_file)]
    run = [i.nodeid for i in items if not i.nodeid.startswith(own_file) and i.get_closest_marker("cpp") is None]
    return {"run": run, "outer": outer}


def shared_cpp(items: list[pytest.Item], own_file: str) -> dict[str, list[str]]:
    """``selection`` split, second half: the C++ tests that read ../shared (known once they ran)."""
    outer = [i.nodeid for i in items if not i.nodeid.startswith(own_file)]
    run = [i.nodeid for i in items if not i.nodeid.startswith(own_file)
           and i.get_closest_marker("cpp") is not None and reads_shared(i.nodeid)]
    return {"run": run, "outer": outer}


def write(path: Path, chosen: dict[str, list[str]]) -> None:
    path.write_text(json.dumps(chosen, indent=0), encoding="utf-8")


def apply(items: list[pytest.Item]) -> list[pytest.Item]:
    """In a clone given a selection: keep what it runs and what the outer session did not know; return the rest."""
    where = os.environ.get(ENV)
    if not where:
        return []
    chosen = json.loads(Path(where).read_text(encoding="utf-8"))
    run, outer = set(chosen["run"]), set(chosen["outer"])
    dropped = [i for i in items if i.nodeid in outer and i.nodeid not in run]
    items[:] = [i for i in items if i not in dropped]
    return dropped
