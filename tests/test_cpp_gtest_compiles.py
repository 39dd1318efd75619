"""The generated gtest/gmock test of every robot (test/test_<robot>_hardware_interface.cpp, from
rhi_gen/templates/robot/test.cpp.j2) compiles against the Humble stand-ins and the system gmock.

On a ROS 2 Humble machine that file is built by ament_add_gmock() and run by `colcon test`; here
nothing else compiles it. Every robot of robots/ is rendered into a temporary project and its test
is compiled with g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror -fsyntax-only against the Humble
stand-ins (tests/cpp/standins/distros/humble/include + include: hardware_interface/resource_manager.hpp,
ros2_control_test_assets/descriptions.hpp, rclcpp, ...) and the generated include folder. (The
4.x+ ResourceManager stand-ins exist and are self-tested; the generated test skips itself there
until its template supports them.)
The same file is then linked with gmock_main and run: the stand-in ResourceManager "exports"
exactly what the test's <ros2_control> block lists, so this checks the test's own bookkeeping
(expected keys and counts), not the driver.

A missing g++ or missing gmock/gtest headers fail these tests (never skip): install g++,
libgmock-dev and libgtest-dev (.ci/run does).
"""
from __future__ import annotations

import functools
import os
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest
import yaml

from rhi_gen.cli import main
from tests import vendor_msgs
from tests.cpp_build import ENV_C, REPO, WARNING_FLAGS, message_include_flags, project_robot_labels, \
    require_compiler, run_compiler, standin_flags

PACKAGE = "robot_hardware_interface"
LABELS = project_robot_labels(extra_robots=False)  # vendor/robot of robots/*/*.yaml
GMOCK_LIBS = ("-lgmock_main", "-lgmock", "-lgtest")


def _compiler() -> str:
    return os.environ.get("CXX", "g++")


@functools.lru_cache(maxsize=None)
def _gmock_problem(cxx: str) -> str | None:
    """Why <gmock/gmock.h> / <gtest/gtest.h> cannot be compiled with ``cxx`` (None when they can)."""
    probe = subprocess.run([cxx, "-std=c++17", "-fsyntax-only", "-x", "c++", "-"],
                           input="#include <gmock/gmock.h>\n#include <gtest/gtest.h>\n",
                           capture_output=True, text=True, env=ENV_C)
    if probe.returncode == 0:
        return None
    return ("gmock/gtest headers not found (<gmock/gmock.h>): install the Debian packages "
            "libgmock-dev and libgtest-dev (apt-get install -y libgmock-dev libgtest-dev; "
            ".ci/run installs them); the generated gtest is never skipped\n" + probe.stderr[-2000:])


def require_toolchain() -> None:
    """Called by every compiling test: a missing g++ or gmock fails it (pytest.fail), never skips."""
    problem = _gmock_problem(require_compiler())
    if problem:
        pytest.fail(problem)


def _toolchain_ok() -> bool:
    path = shutil.which(_compiler())
    return path is not None and _gmock_problem(path) is None


@pytest.fixture(scope="module")
def package_dir(tmp_path_factory) -> Path:
    """robots/ rendered into a temporary project (generated/ of the repository is not touched)."""
    project = tmp_path_factory.mktemp("gtest_project")
    shutil.copytree(REPO / "robots", project / "robots")
    assert main(["generate", "--project", str(project)]) == 0
    return project / "generated" / PACKAGE


def _flags(package: Path) -> list[str]:
    # WARNING_FLAGS has -Wpedantic: the generated CMakeLists.txt adds -Wall -Wextra -Wpedantic.
    return [*WARNING_FLAGS, *standin_flags("humble"), f"-I{package / 'include'}", *message_include_flags()]


def _skip_reason(label: str) -> str | None:
    """Set when the robot's transport needs vendor messages that cannot be generated (no ../shared)."""
    transport = yaml.safe_load((REPO / "robots" / f"{label}.yaml").read_text(encoding="utf-8"))["transport"]
    return vendor_msgs.skip_reason(transport)


def _source(package: Path, label: str) -> Path:
    return package / "test" / f"test_{label.split('/')[1]}_hardware_interface.cpp"


@dataclass
class GtestResult:
    syntax_error: str | None = None
    build_error: str | None = None
    run: subprocess.CompletedProcess | None = None


@pytest.fixture(scope="module")
def results(package_dir, tmp_path_factory) -> dict[str, GtestResult]:
    """Per robot, 2 in parallel: -fsyntax-only, then link with gmock_main and run."""
    if not _toolchain_ok():
        return {}  # every test then fails in require_toolchain()
    out_dir = tmp_path_factory.mktemp("gtest_bin")

    def one(label: str) -> tuple[str, GtestResult]:
        result = GtestResult()
        if _skip_reason(label):
            return label, result
        source = _source(package_dir, label)
        if not source.is_file():
            result.syntax_error = f"{label}: {source.name} was not generated"
            return label, result
        try:
            run_compiler([*_flags(package_dir), "-fsyntax-only", str(source)],
                         what=f"{label} gtest ({source.name})")
        except AssertionError as exc:
            result.syntax_error = str(exc)
            return label, result
        binary = out_dir / f"gtest_{label.replace('/', '_')}"
        try:
            run_compiler([*_flags(package_dir), "-O0", "-pthread", str(source), *GMOCK_LIBS,
                          "-o", str(binary)], what=f"{label} gtest (linked with gmock_main)")
        except AssertionError as exc:
            result.build_error = str(exc)
            return label, result
        result.run = subprocess.run([str(binary)], capture_output=True, text=True, env=ENV_C,
                                    timeout=120)
        return label, result

    with ThreadPoolExecutor(max_workers=2) as pool:
        return dict(pool.map(one, LABELS))


def test_every_robot_has_a_gtest(package_dir):
    assert LABELS, "no robots under robots/"
    made = sorted(p.name for p in (package_dir / "test").glob("test_*_hardware_interface.cpp"))
    assert made == sorted(_source(package_dir, label).name for label in LABELS)


@pytest.mark.parametrize("label", LABELS)
def test_gtest_compiles(results, label):
    require_toolchain()
    if _skip_reason(label):
        pytest.skip(_skip_reason(label))
    assert results[label].syntax_error is None, results[label].syntax_error


@pytest.mark.parametrize("label", LABELS)
def test_gtest_runs_against_the_standin(results, label):
    require_toolchain()
    if _skip_reason(label):
        pytest.skip(_skip_reason(label))
    result = results[label]
    if result.syntax_error is not None:
        pytest.fail(f"{label}: does not compile (see test_gtest_compiles)")
    assert result.build_error is None, result.build_error
    run = result.run
    assert run is not None and run.returncode == 0, (
        f"{label} gtest failed:\n{run.stdout[-6000:]}\n{run.stderr[-3000:]}")
    assert re.search(r"^\[  PASSED  \] \d+ tests?\.$", run.stdout, re.M), run.stdout[-3000:]
    assert "[  SKIPPED ]" not in run.stdout and "[  FAILED  ]" not in run.stdout, run.stdout[-3000:]
