"""Session order only: tests/test_fresh_clone.py runs last, so the clone it tests reuses every object the
session compiled (its RHI_CPP_CACHE)."""
from __future__ import annotations


def pytest_collection_modifyitems(session, config, items):
    last = [item for item in items if item.nodeid.split("::")[0].endswith("test_fresh_clone.py")]
    items[:] = [item for item in items if item not in last] + last
