"""The C++ stand-ins (tests/cpp/standins): they compile warning-free, behave as documented, and reject
what the real ROS 2 Humble / unitree_sdk2 APIs reject. Messages are the real ROS 2 headers
(tests/ros_msgs.py, tests/vendor_msgs.py).

* the self-test program compiles with g++ -std=c++17 -Wall -Wextra -Werror and passes, plain and under
  -fsanitize=address,undefined and -fsanitize=thread; with the rosidl-generated vendor messages it also
  checks them (skipped, with the reason, when ../shared is missing);
* every stand-in header compiles on its own;
* every compile_fail/ snippet compiles without RHI_EXPECT_FAIL and fails, with the expected
  diagnostic, with it;
* the self-test includes every public stand-in header (so new headers get exercised).

A missing g++ fails these tests (tests.cpp_build.require_compiler); they are never skipped.
"""
from __future__ import annotations

import os
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tests import vendor_msgs
from tests.cpp_build import message_include_flags, require_compiler

STANDINS = Path(__file__).resolve().parent / "cpp" / "standins"
INCLUDE = STANDINS / "include"
SELFTEST = STANDINS / "selftest" / "selftest.cpp"
COMPILE_FAIL = sorted((STANDINS / "selftest" / "compile_fail").glob("*.cpp"))

CXXFLAGS = ["-std=c++17", "-Wall", "-Wextra", "-Werror", "-pthread", f"-I{INCLUDE}"]
VENDOR_CHECKS = "selftest: vendor messages checked"
FLAVOURS = {
    # the generated CMakeLists adds -Wpedantic: keep the stand-ins clean under it too
    "plain": ["-O2", "-Wpedantic"],
    # -O0 -g1: sanitizer builds compile about twice as fast and still catch everything here
    "asan_ubsan": ["-O0", "-g1", "-fno-omit-frame-pointer", "-fsanitize=address,undefined",
                   "-fno-sanitize-recover=all"],
    "tsan": ["-O0", "-g1", "-fsanitize=thread"],
}
# ASCII quotes in diagnostics, whatever the machine's locale.
ENV_C = {**os.environ, "LC_ALL": "C", "LANG": "C"}


def _public_headers() -> list[str]:
    out = []
    for p in sorted(INCLUDE.rglob("*")):
        if p.suffix in (".hpp", ".h") and p.is_file():
            out.append(p.relative_to(INCLUDE).as_posix())
    return out


@pytest.fixture(scope="session")
def selftest_binaries(tmp_path_factory) -> dict[str, tuple[Path, subprocess.CompletedProcess]]:
    """Compile the self-test in every flavour, in parallel; {flavour: (binary, compile result)}."""
    cxx = require_compiler()
    out_dir = tmp_path_factory.mktemp("standins")
    vendor = [] if vendor_msgs.missing_reason() else ["-DRHI_SELFTEST_VENDOR_MSGS"]
    messages = message_include_flags()

    def build(flavour: str):
        binary = out_dir / f"selftest_{flavour}"
        cmd = [cxx, *CXXFLAGS, *messages, *vendor, *FLAVOURS[flavour], str(SELFTEST), "-o", str(binary)]
        return flavour, binary, subprocess.run(cmd, capture_output=True, text=True, env=ENV_C)

    with ThreadPoolExecutor(max_workers=len(FLAVOURS)) as pool:
        results = list(pool.map(build, FLAVOURS))
    return {flavour: (binary, proc) for flavour, binary, proc in results}


@pytest.mark.parametrize("flavour", list(FLAVOURS))
def test_selftest_compiles_and_passes(selftest_binaries, flavour):
    binary, build = selftest_binaries[flavour]
    assert build.returncode == 0, f"selftest ({flavour}) does not compile:\n{build.stderr[-8000:]}"
    env = {**ENV_C, "ASAN_OPTIONS": "abort_on_error=0:halt_on_error=1",
           "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1",
           "TSAN_OPTIONS": "halt_on_error=1:second_deadlock_stack=1"}
    run = subprocess.run([str(binary)], capture_output=True, text=True, env=env, timeout=300)
    assert run.returncode == 0, f"selftest ({flavour}) failed:\n{run.stdout}\n{run.stderr[-8000:]}"
    assert re.search(r"selftest: all \d+ checks passed", run.stdout), run.stdout
    assert "WARNING: ThreadSanitizer" not in run.stderr, run.stderr[-8000:]


def test_selftest_checks_the_vendor_messages(selftest_binaries):
    """The rosidl-generated aimdk_msgs / interface_protocol and the ROS hooks with them (needs ../shared)."""
    reason = vendor_msgs.missing_reason()
    if reason:
        pytest.skip(reason)
    binary, build = selftest_binaries["plain"]
    assert build.returncode == 0, build.stderr[-8000:]
    run = subprocess.run([str(binary)], capture_output=True, text=True, env=ENV_C, timeout=300)
    assert run.returncode == 0 and VENDOR_CHECKS in run.stdout, run.stdout[-3000:] + run.stderr[-3000:]


def test_every_header_compiles_on_its_own(tmp_path):
    cxx = require_compiler()
    headers = _public_headers()
    assert len(headers) > 50

    def check(header: str):
        src = tmp_path / (re.sub(r"[^A-Za-z0-9]", "_", header) + ".cpp")
        src.write_text(f'#include "{header}"\n#include "{header}"\n')
        proc = subprocess.run([cxx, *CXXFLAGS, *message_include_flags(), "-Wpedantic", "-fsyntax-only", str(src)],
                              capture_output=True, text=True, env=ENV_C)
        return header, proc

    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        failures = [(h, p.stderr) for h, p in pool.map(check, headers) if p.returncode != 0]
    assert not failures, "\n\n".join(f"{h}:\n{err[-3000:]}" for h, err in failures)


@pytest.fixture(scope="session")
def compile_fail_results():
    """Both compiles of every snippet, in parallel: {name: (expected regex, ok proc, bad proc)}."""
    cxx = require_compiler()

    def run(snippet: Path):
        first = snippet.read_text().splitlines()[0]
        expected = first[len("// expect: "):] if first.startswith("// expect: ") else None
        base = [cxx, *CXXFLAGS, *message_include_flags(), "-fsyntax-only", str(snippet)]
        ok = subprocess.run(base, capture_output=True, text=True, env=ENV_C)
        bad = subprocess.run([*base, "-DRHI_EXPECT_FAIL"], capture_output=True, text=True, env=ENV_C)
        return snippet.name, (expected, ok, bad)

    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        return dict(pool.map(run, COMPILE_FAIL))


@pytest.mark.parametrize("snippet", COMPILE_FAIL, ids=[p.stem for p in COMPILE_FAIL])
def test_compile_fail_snippet(compile_fail_results, snippet):
    expected, ok, bad = compile_fail_results[snippet.name]
    assert expected, f"{snippet.name}: first line must be '// expect: <regex>'"
    assert ok.returncode == 0, f"{snippet.name} must compile without RHI_EXPECT_FAIL:\n{ok.stderr}"
    assert bad.returncode != 0, f"{snippet.name} compiled with RHI_EXPECT_FAIL; the stand-ins accept it"
    assert re.search(expected, bad.stderr), (
        f"{snippet.name}: expected a diagnostic matching {expected!r}, got:\n{bad.stderr[-4000:]}")


def test_command_interface_copy_is_among_the_compile_fail_cases():
    assert "command_interface_copy" in {p.stem for p in COMPILE_FAIL}


def test_selftest_includes_every_public_header():
    text = SELFTEST.read_text()
    included = set(re.findall(r'#include [<"]([^>"]+)[>"]', text))
    missing = [h for h in _public_headers()
               if not h.startswith("rhi_fake/") and h not in included
               and h not in INDIRECT_ONLY and h not in GTEST_ONLY]
    assert not missing, f"selftest.cpp does not include: {missing}"


# Headers a driver does not include directly; the self-test reaches them through others.
INDIRECT_ONLY = {
    "rcl/time.h",
    "rmw/types.h",
    "rmw/qos_profiles.h",
    "hardware_interface/macros.hpp",
    "rclcpp/callback_group.hpp",
    "rclcpp/context.hpp",
    "rclcpp/exceptions.hpp",
    "rclcpp/executor.hpp",
    "rclcpp/logger.hpp",
    "rclcpp/node_interfaces/node_base_interface.hpp",
    "rclcpp/node_options.hpp",
    "rclcpp/publisher.hpp",
    "rclcpp/publisher_options.hpp",
    "rclcpp/subscription.hpp",
    "rclcpp/subscription_options.hpp",
    "rclcpp/timer.hpp",
    "rclcpp/utilities.hpp",
    "rclcpp/visibility_control.hpp",
    "unitree/common/thread/thread_decl.hpp",
    "unitree/robot/client/client.hpp",
    "unitree/robot/client/client_base.hpp",
}

# Headers only the generated gtest (templates/robot/test.cpp.j2) includes, never a driver; that
# test compiles and runs them (tests/test_cpp_gtest_compiles.py).
GTEST_ONLY = {
    "hardware_interface/resource_manager.hpp",
    "hardware_interface/hardware_component_info.hpp",
    "ros2_control_test_assets/descriptions.hpp",
}
