"""The compile-and-run tier: every test collected below this folder is marked ``cpp`` (g++ and the
binaries it builds), so ``pytest -m "not cpp"`` leaves it out. The C++ sources the tests build sit next
to them (harness/, standins/, toy_bus/); the build logic is tests/support/cpp_build.py."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cpp_build import CppBuilder, RenderedPackage, session_builder, session_reference_package

HERE = Path(__file__).resolve().parent


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if HERE in item.path.parents:
            item.add_marker(pytest.mark.cpp)


@pytest.fixture(scope="session")
def cpp_builder(tmp_path_factory: pytest.TempPathFactory) -> CppBuilder:
    """The session's compiler front end; objects cached by content (RHI_CPP_CACHE=<dir> keeps them)."""
    return session_builder(tmp_path_factory)


@pytest.fixture(scope="session")
def reference(tmp_path_factory: pytest.TempPathFactory) -> RenderedPackage:
    """The package of every robot of robots/ (and the harness's test robots), rendered once a session."""
    return session_reference_package(tmp_path_factory)
