"""What the session's selected tests need of a module fixture that builds many things at once.

A fixture that compiles every robot, cell or mutation up front (so the compiles overlap) would, in a run
that selected a few of its tests (`-k`, the fresh clone's selection of tests/support/fresh_clone_selection.py),
still build everything. It asks here which parameter values the selected tests that use it carry, and
builds only those.
"""
from __future__ import annotations

from typing import Any

import pytest

EVERYTHING = None


def values(request: pytest.FixtureRequest, param: str | tuple[str, ...], *,
           unparametrized: Any = EVERYTHING) -> set[Any] | None:
    """The values of ``param`` (a tuple of them for several names) among the session's selected tests that use
    the requesting fixture, directly or through another fixture. A test that uses it without that parameter
    contributes ``unparametrized``; by default that means it needs everything, and the answer is None."""
    names = param if isinstance(param, tuple) else (param,)
    wanted: set[Any] = set()
    for item in request.session.items:
        if request.fixturename not in getattr(item, "fixturenames", ()):
            continue
        callspec = getattr(item, "callspec", None)
        if callspec is None or any(name not in callspec.params for name in names):
            if unparametrized is EVERYTHING:
                return None
            wanted.add(unparametrized)
        else:
            found = tuple(callspec.params[name] for name in names)
            wanted.add(found if isinstance(param, tuple) else found[0])
    return wanted


def keep(jobs: list[Any], wanted: set[Any] | None, key=lambda job: job) -> list[Any]:
    """The jobs whose key is wanted (every job when ``wanted`` is None)."""
    return list(jobs) if wanted is None else [job for job in jobs if key(job) in wanted]
