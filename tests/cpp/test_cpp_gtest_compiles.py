"""The generated gtest/gmock test of every robot (test/test_<robot>_hardware_interface.cpp, from
rhi_gen/templates/robot/test.cpp.j2) compiles against the Humble and Rolling stand-ins and the system gmock.

On a ROS 2 machine that file is built by ament_add_gmock() and run by `colcon test`; here
nothing else compiles it. Every robot of robots/ is rendered into a temporary project and its test
is compiled (-O0) and linked with the robot's driver object (-O2, the driver harness's plain object:
the session's object cache keys it by the package files it reads, so it is compiled once), both with
g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror, against the stand-ins of each distro of GTEST_DISTROS
(tests/cpp/standins/distros/<distro>: hardware_interface/resource_manager.hpp,
ros2_control_test_assets/descriptions.hpp, rclcpp, ...) and the generated include folder: Humble for
the 2.x API (raw-pointer export, no RM clock), Rolling for the newest (framework-owned handles, the
RM's clock constructor). A custom-transport robot's driver is as generated (the harness's has its user
regions filled), so it is compiled here, at -O0.
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
from tests.support import selected, shared_use, vendor_msgs
from tests.support.cpp_build import (
    DISTROS,
    ENV_C,
    HARNESS_ROBOTS,
    OVERLAP_WORKERS,
    compile_driver,
    label_transport,
    project_robot_labels,
    require_compiler,
    session_builder,
)
from tests.support.repo import copy_project

PACKAGE = "robot_hardware_interface"
LABELS = project_robot_labels(extra_robots=False)  # vendor/robot of robots/*/*.yaml
# The harness's custom-transport robots, as generated (user regions not filled in): their gtest must
# run without hardware and without an SDK on every supported distro.
CUSTOM_LABELS = sorted(f"{y.parent.name}/{y.stem}" for y in HARNESS_ROBOTS.glob("*/*.yaml")
                       if yaml.safe_load(y.read_text(encoding="utf-8"))["transport"] == "custom")
GMOCK_LIBS = ("-lgmock_main", "-lgmock", "-lgtest")


def _compiler() -> str:
    return os.environ.get("CXX", "g++")


@functools.cache
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
    copy_project(project)
    for label in CUSTOM_LABELS:
        vendor, robot = label.split("/")
        (project / "robots" / vendor).mkdir(exist_ok=True)
        for path in (HARNESS_ROBOTS / vendor).glob(f"{robot}.*"):
            shutil.copy2(path, project / "robots" / vendor / path.name)
    assert main(["generate", "--project", str(project)]) == 0
    return project / "generated" / PACKAGE


# Humble (interfaces over driver-owned doubles, the ResourceManager validates the exports) and
# Rolling/Lyrical (framework-owned handles, a ResourceManager with a clock and a logger that creates
# the plugin through pluginlib and rejects joints missing from the URDF); Jazzy and Kilted share
# Rolling's path and are covered by the driver harness (tests/cpp/test_cpp_drivers.py).
GTEST_DISTROS = ("humble", "jazzy", "rolling")  # 2.x, 4.x, 6.x; the custom robot on every distro
JOBS = [(label, distro) for label in LABELS for distro in GTEST_DISTROS] + \
    [(label, distro) for label in CUSTOM_LABELS for distro in DISTROS]


def _skip_reason(label: str) -> str | None:
    """Set when the robot's transport needs vendor messages that cannot be generated (no ../shared)."""
    return vendor_msgs.skip_reason(label_transport(label))


def _source(package: Path, label: str) -> Path:
    return package / "test" / f"test_{label.split('/')[1]}_hardware_interface.cpp"


@dataclass
class GtestResult:
    syntax_error: str | None = None
    build_error: str | None = None
    run: subprocess.CompletedProcess | None = None


@pytest.fixture(scope="module")
def results(package_dir, tmp_path_factory, request) -> shared_use.Recorded:
    """Per robot and distro the session's selected tests name (all in a whole run), 2 in parallel: build
    with the driver (the stand-in ResourceManager creates the plugin from the registry PLUGINLIB_EXPORT_CLASS
    fills, as pluginlib loads it), link with gmock_main and run."""
    if not _toolchain_ok():
        return shared_use.Recorded({})  # every test then fails in require_toolchain()
    builder = session_builder(tmp_path_factory)

    def one(job: tuple[str, str]) -> tuple[tuple[str, str], tuple[GtestResult, set[str]]]:
        with shared_use.recording() as used:  # per job: the X2's reads of ../shared are the X2 tests' alone
            result = build_and_run(job)
        return job, (result, set(used))

    def build_and_run(job: tuple[str, str]) -> GtestResult:
        label, distro = job
        result = GtestResult()
        if _skip_reason(label):
            return result
        source = _source(package_dir, label)
        if not source.is_file():
            result.syntax_error = f"{label}: {source.name} was not generated"
            return result
        tag = f"{label.replace('/', '_')}_{distro}"
        # The gtest (-O0: test code) and the driver (-Werror, the harness's plain object: the same package content
        # gives the same object, compiled once per session) are each compiled, then linked with gmock_main. A custom
        # robot's driver is as generated here (the harness's has the toy bus filled in): -O0, compiled fastest.
        driver = compile_driver(builder, package_dir, label, label_transport(label), "plain", distro,
                                flags=("-O0",) if label in CUSTOM_LABELS else None)
        gtest = builder.compile(source, ("-O0",), [package_dir / "include", *DISTROS[distro].include_dirs],
                                package=package_dir, name=f"gtest_{tag}", distro=distro,
                                transport=label_transport(label))
        failed = [step for step in (gtest, driver) if not step.ok]
        if failed:
            result.syntax_error = (f"{label} gtest with its driver ({distro}) does not compile:\n"
                                   + "\n".join(step.stderr[:4000] for step in failed))
            return result
        link = builder.link([gtest, driver], (), f"gtest_{tag}", libs=GMOCK_LIBS)
        if not link.ok:
            result.build_error = f"{label} gtest ({distro}) does not link with gmock_main:\n{link.stderr[:4000]}"
            return result
        binary = link.path
        # What pluginlib reads through the ament index: the package's plugin description (4.x+
        # stand-in ResourceManagers resolve the <plugin> lookup name through it, as upstream does).
        env = {**ENV_C, "RHI_FAKE_PLUGIN_XML": str(package_dir / f"{PACKAGE}.xml"), "RHI_FAKE_LOG_ECHO": "1"}
        result.run = subprocess.run([str(binary)], capture_output=True, text=True, env=env, timeout=600)
        return result

    with ThreadPoolExecutor(max_workers=OVERLAP_WORKERS) as pool:  # the builder runs one compiler per core
        wanted = selected.values(request, "label")
        return shared_use.Recorded(dict(pool.map(one, selected.keep(JOBS, wanted, key=lambda job: job[0]))))


def test_every_robot_has_a_gtest(package_dir):
    assert LABELS, "no robots under robots/"
    made = sorted(p.name for p in (package_dir / "test").glob("test_*_hardware_interface.cpp"))
    assert made == sorted(_source(package_dir, label).name for label in LABELS + CUSTOM_LABELS)


@pytest.mark.parametrize(("label", "distro"), JOBS, ids=[f"{label}-{distro}" for label, distro in JOBS])
def test_gtest_compiles(results, label, distro):
    require_toolchain()
    reason = _skip_reason(label)
    if reason:
        pytest.skip(reason)
    assert results[(label, distro)].syntax_error is None, results[(label, distro)].syntax_error


@pytest.mark.parametrize(("label", "distro"), JOBS, ids=[f"{label}-{distro}" for label, distro in JOBS])
def test_gtest_runs_against_the_standin(results, label, distro):
    """No GTEST_SKIP on any supported distro: every test of the suite runs and passes."""
    require_toolchain()
    reason = _skip_reason(label)
    if reason:
        pytest.skip(reason)
    result = results[(label, distro)]
    if result.syntax_error is not None:
        pytest.fail(f"{label}: does not compile (see test_gtest_compiles)")
    assert result.build_error is None, result.build_error
    run = result.run
    assert run is not None and run.returncode == 0, (
        f"{label} gtest failed:\n{run.stdout[-6000:]}\n{run.stderr[-3000:]}")
    assert re.search(r"^\[  PASSED  \] \d+ tests?\.$", run.stdout, re.M), run.stdout[-3000:]
    assert "[  SKIPPED ]" not in run.stdout and "[  FAILED  ]" not in run.stdout, run.stdout[-3000:]
