"""The C++ stand-ins (tests/cpp/standins), for every ROS 2 distro of tests.support.cpp_build.DISTROS: they
compile warning-free, behave as documented, and reject what that distro's real APIs reject.
Messages are the real ROS 2 headers (tests/support/ros_msgs.py, tests/support/vendor_msgs.py); with the
rosidl-generated vendor messages the self-test also checks them (skipped, with the reason, when
../shared is missing).

Per distro (humble, jazzy, kilted, rolling):
* the self-test program compiles with g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror and passes,
  plain and under -fsanitize=address,undefined and -fsanitize=thread;
* every stand-in header visible on that distro's include path compiles on its own;
* every compile_fail/ snippet meant for the distro (its "// distros:" line; all when absent)
  compiles without RHI_EXPECT_FAIL and fails, with the expected diagnostic, with it;
  (code that reaches only the distro-independent include/ folder is checked on one distro per
  rclcpp class, REPRESENTATIVES: humble, jazzy and rolling; see _distros_for)
* the self-test includes every public stand-in header of the distro (so new headers get exercised).

A missing g++ fails these tests (tests.support.cpp_build.require_compiler); they are never skipped.
"""
from __future__ import annotations

import os
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tests.support import selected, vendor_msgs
from tests.support.cpp_build import (
    DISTROS,
    STANDINS,
    STANDINS_INCLUDE,
    WARNING_FLAGS,
    message_include_flags,
    require_compiler,
    standin_flags,
)

SELFTEST_DIR = STANDINS / "selftest"
SELFTEST = SELFTEST_DIR / "selftest.cpp"
VENDOR_SELFTEST = SELFTEST_DIR / "selftest_vendor_msgs.cpp"
COMPILE_FAIL = sorted((SELFTEST_DIR / "compile_fail").glob("*.cpp"))

VENDOR_CHECKS = "selftest: vendor messages checked"
FLAVOURS = {
    "plain": ["-O2"],
    # -O0 -g1: sanitizer builds compile about twice as fast and still catch everything here
    "asan_ubsan": ["-O0", "-g1", "-fno-omit-frame-pointer", "-fsanitize=address,undefined",
                   "-fno-sanitize-recover=all"],
    "tsan": ["-O0", "-g1", "-fsanitize=thread"],
}
# ASCII quotes in diagnostics, whatever the machine's locale.
ENV_C = {**os.environ, "LC_ALL": "C", "LANG": "C"}
WORKERS = os.cpu_count() or 2
# For compiles of a second or less (-fsyntax-only): one more than the cores, so that a core does not wait while
# a thread collects one compiler's result and starts the next
SHORT_WORKERS = WORKERS + 1


def _cxxflags(distro: str, vendor_messages: bool = False) -> list[str]:
    """``vendor_messages``: the generated vendor packages on the include path too (the self-test's vendor
    part); without, the ROS 2 wheels' messages only, which is all the stand-ins' own headers include."""
    return [*WARNING_FLAGS, "-pthread", *standin_flags(distro),
            *message_include_flags(None if vendor_messages else "")]


def _public_headers(distro: str) -> list[str]:
    """Headers reachable as <x> on ``distro``'s include path (the first folder providing one wins)."""
    seen: dict[str, Path] = {}
    for folder in DISTROS[distro].include_dirs:
        for p in sorted(folder.rglob("*")):
            if p.suffix in (".hpp", ".h") and p.is_file():
                seen.setdefault(p.relative_to(folder).as_posix(), p)
    return sorted(seen)


# ---------------------------------------------------------------- which distros a file needs
# Code that reaches only the distro-independent stand-ins (include/) behaves the same on every distro
# with the same rclcpp settings (rhi_fake/detail/distro.hpp): it is checked on one distro of each
# such class, a file that reaches a distro folder's header on every distro. That keeps this module
# within a few minutes on two cores (test_rclcpp_classes_hold checks the premise).
_INCLUDE_RE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def _distro_macros(distro: str) -> dict[str, int]:
    text = (STANDINS / "distros" / distro / "include" / "rhi_fake" / "detail" / "distro.hpp").read_text()
    return {k: int(v) for k, v in re.findall(r"#define (RHI_FAKE_\w+) (\d+)", text)}


def _rclcpp_class(distro: str) -> tuple[int, bool, bool]:
    """What the distro-independent stand-ins branch on: Humble's deprecated shared_ptr callbacks, rclcpp 21
    (Iron: NodeOptions::enable_logger_service, the QoS overloads of create_client/create_service) and rclcpp
    29 (Kilted: the rmw_qos_profile_t service overloads and the implicit future conversions removed)."""
    m = _distro_macros(distro)
    major = m["RHI_FAKE_RCLCPP_MAJOR"]
    return m["RHI_FAKE_RCLCPP_SHARED_PTR_CALLBACK_DEPRECATED"], major >= 21, major >= 29


REPRESENTATIVES = sorted({_rclcpp_class(d): d for d in DISTROS}.values())


def _reaches_distro_folder(path: Path, distro: str, seen: set[Path] | None = None) -> bool:
    """Does ``path`` include (transitively) a header of a distro folder (other than distro.hpp)?"""
    seen = set() if seen is None else seen
    for name in _INCLUDE_RE.findall(path.read_text()):
        for folder in DISTROS[distro].include_dirs:
            found = folder / name
            if found.is_file():
                if found in seen:
                    break
                seen.add(found)
                if folder != STANDINS_INCLUDE and name != "rhi_fake/detail/distro.hpp":
                    return True
                if _reaches_distro_folder(found, distro, seen):
                    return True
                break
    return False


def _distros_for(path: Path, declared: list[str] | None = None) -> list[str]:
    candidates = declared if declared is not None else list(DISTROS)
    if any(_reaches_distro_folder(path, d) for d in candidates):
        return candidates
    return [d for d in candidates if d in REPRESENTATIVES] or candidates[:1]


def _snippet_meta(snippet: Path) -> tuple[str | None, list[str]]:
    """(expected diagnostic regex, distros) from the snippet's first two comment lines."""
    lines = snippet.read_text().splitlines()
    expected = lines[0][len("// expect: "):] if lines and lines[0].startswith("// expect: ") else None
    declared = None
    if len(lines) > 1 and lines[1].startswith("// distros: "):
        declared = lines[1][len("// distros: "):].split()
    if declared is not None and set(declared) - set(DISTROS):
        return expected, declared
    return expected, _distros_for(snippet, declared)


SNIPPET_CASES = [(s, d) for s in COMPILE_FAIL for d in _snippet_meta(s)[1]]


def _build_selftests(out_dir: Path, source: Path, jobs: list[tuple[str, str]], vendor_messages: bool):
    """``source`` built for every (distro, flavour) of ``jobs``, in parallel: {(distro, flavour): (binary, result)}."""
    cxx = require_compiler()

    def build(job: tuple[str, str]):
        distro, flavour = job
        binary = out_dir / f"{source.stem}_{distro}_{flavour}"
        cmd = [cxx, *_cxxflags(distro, vendor_messages=vendor_messages), *FLAVOURS[flavour], str(source),
               "-o", str(binary)]
        return job, binary, subprocess.run(cmd, capture_output=True, text=True, env=ENV_C)

    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        results = list(pool.map(build, jobs))
    return {job: (binary, proc) for job, binary, proc in results}


def _run_selftest(binary: Path) -> subprocess.CompletedProcess:
    env = {**ENV_C, "ASAN_OPTIONS": "abort_on_error=0:halt_on_error=1",
           "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1",
           "TSAN_OPTIONS": "halt_on_error=1:second_deadlock_stack=1"}
    return subprocess.run([str(binary)], capture_output=True, text=True, env=env, timeout=300)


SELFTEST_JOBS = [(d, f) for d in DISTROS for f in FLAVOURS]


@pytest.fixture(scope="session")
def selftest_binaries(tmp_path_factory, request) -> dict[tuple[str, str], tuple[Path, subprocess.CompletedProcess]]:
    """The self-test of every distro in every flavour the session's selected tests name: the ROS 2 wheels'
    messages only, so it builds and runs the same with or without ../shared."""
    jobs = selected.keep(SELFTEST_JOBS, selected.values(request, ("distro", "flavour")))
    return _build_selftests(tmp_path_factory.mktemp("standins"), SELFTEST, jobs, vendor_messages=False)


@pytest.fixture(scope="session")
def vendor_selftest_binaries(tmp_path_factory, request
                             ) -> dict[tuple[str, str], tuple[Path, subprocess.CompletedProcess]]:
    """The vendor messages' self-test of every distro and flavour the session's selected tests name (none
    without ../shared: the tests skip)."""
    if vendor_msgs.missing_reason():
        return {}
    jobs = selected.keep(SELFTEST_JOBS, selected.values(request, ("distro", "flavour")))
    return _build_selftests(tmp_path_factory.mktemp("standins_vendor"), VENDOR_SELFTEST, jobs, vendor_messages=True)


def _check_selftest_run(binary: Path, build: subprocess.CompletedProcess, what: str) -> str:
    assert build.returncode == 0, f"{what} does not compile:\n{build.stderr[-8000:]}"
    run = _run_selftest(binary)
    assert run.returncode == 0, f"{what} failed:\n{run.stdout}\n{run.stderr[-8000:]}"
    assert re.search(r"selftest: all \d+ checks passed", run.stdout), run.stdout
    assert "WARNING: ThreadSanitizer" not in run.stderr, run.stderr[-8000:]
    return run.stdout


@pytest.mark.parametrize("flavour", list(FLAVOURS))
@pytest.mark.parametrize("distro", list(DISTROS))
def test_selftest_compiles_and_passes(selftest_binaries, distro, flavour):
    binary, build = selftest_binaries[(distro, flavour)]
    _check_selftest_run(binary, build, f"selftest ({distro}, {flavour})")


@pytest.mark.parametrize("flavour", list(FLAVOURS))
@pytest.mark.parametrize("distro", list(DISTROS))
def test_selftest_checks_the_vendor_messages(vendor_selftest_binaries, distro, flavour):
    """The rosidl-generated aimdk_msgs / interface_protocol and the ROS hooks with them (needs ../shared)."""
    reason = vendor_msgs.missing_reason()
    if reason:
        pytest.skip(reason)
    binary, build = vendor_selftest_binaries[(distro, flavour)]
    stdout = _check_selftest_run(binary, build, f"vendor message selftest ({distro}, {flavour})")
    assert VENDOR_CHECKS in stdout, stdout[-3000:]


def _headers_to_check(distro: str) -> list[str]:
    """Headers of ``distro``'s include path that are checked alone on it (see _distros_for)."""
    out = []
    for header in _public_headers(distro):
        path = next(f / header for f in DISTROS[distro].include_dirs if (f / header).is_file())
        if path.parent.parts[:len(STANDINS_INCLUDE.parts)] != STANDINS_INCLUDE.parts:
            out.append(header)  # a distro folder's own header
        elif distro in _distros_for(path):
            out.append(header)
    return out


def test_rclcpp_classes_hold():
    """The premise of checking distro-independent code on REPRESENTATIVES only."""
    assert REPRESENTATIVES == ["humble", "jazzy", "rolling"], REPRESENTATIVES
    for path in STANDINS_INCLUDE.rglob("*.h*"):
        text = path.read_text()
        used = set(re.findall(r"\bRHI_FAKE_\w+", text)) - {"RHI_FAKE_RCLCPP_SHARED_PTR_CALLBACK_DEPRECATED",
                                                            "RHI_FAKE_RCLCPP_MAJOR", "RHI_FAKE_PLUGIN_XML",
                                                            "RHI_FAKE_LOG_ECHO"}  # the last two: env variables
        if used:
            assert _reaches_distro_folder(path, "rolling"), (
                f"{path.name} uses {sorted(used)} but reaches no distro folder: check it on every distro")
    assert "RHI_FAKE_RCLCPP_MAJOR >= 21" in (STANDINS_INCLUDE / "rclcpp" / "node_options.hpp").read_text()
    node = (STANDINS_INCLUDE / "rclcpp" / "node.hpp").read_text()
    assert "RHI_FAKE_RCLCPP_MAJOR < 21" in node and "RHI_FAKE_RCLCPP_MAJOR < 29" in node
    assert "RHI_FAKE_RCLCPP_MAJOR < 29" in (STANDINS_INCLUDE / "rclcpp" / "client.hpp").read_text()
    # every rclcpp major the stand-ins compare with splits the distros along _rclcpp_class
    thresholds = {int(t) for path in STANDINS_INCLUDE.rglob("*.h*")
                  for t in re.findall(r"RHI_FAKE_RCLCPP_MAJOR\s*(?:<|>=)\s*(\d+)", path.read_text())}
    assert {21, 29} <= thresholds, thresholds
    for threshold in thresholds:
        for a in DISTROS:
            for b in DISTROS:
                if _rclcpp_class(a) == _rclcpp_class(b):
                    major_a = _distro_macros(a)["RHI_FAKE_RCLCPP_MAJOR"]
                    major_b = _distro_macros(b)["RHI_FAKE_RCLCPP_MAJOR"]
                    assert (major_a >= threshold) == (major_b >= threshold), (threshold, a, b)


@pytest.mark.parametrize("distro", list(DISTROS))
def test_every_header_compiles_on_its_own(distro, tmp_path):
    cxx = require_compiler()
    headers = _headers_to_check(distro)
    assert len(headers) > (50 if distro in REPRESENTATIVES else 15), headers

    def check(header: str):
        src = tmp_path / (re.sub(r"[^A-Za-z0-9]", "_", header) + ".cpp")
        src.write_text(f'#include "{header}"\n#include "{header}"\n')
        proc = subprocess.run([cxx, *_cxxflags(distro), "-fsyntax-only", str(src)],
                              capture_output=True, text=True, env=ENV_C)
        return header, proc

    with ThreadPoolExecutor(max_workers=SHORT_WORKERS) as pool:
        failures = [(h, p.stderr) for h, p in pool.map(check, headers) if p.returncode != 0]
    assert not failures, "\n\n".join(f"{h}:\n{err[-3000:]}" for h, err in failures)


# The standard headers the stand-ins and the generated code include, precompiled once per distro for the
# snippets: a -fsyntax-only compile is mostly parsing them (a third to a half of each compile saved).
# Never for the headers-alone checks, whose point is what each header includes itself.
STD_HEADERS = ("algorithm", "array", "atomic", "cctype", "chrono", "cinttypes", "cmath", "condition_variable",
               "cstddef", "cstdint", "cstdio", "cstdlib", "cstring", "exception", "functional", "future",
               "limits", "map", "memory", "mutex", "optional", "set", "shared_mutex", "sstream", "stdexcept",
               "string", "string_view", "thread", "tuple", "type_traits", "typeindex", "unordered_map", "utility",
               "variant", "vector")


def _precompiled_std(cxx: str, distro: str, folder: Path) -> list[str]:
    """-include flags for ``distro``'s precompiled standard headers (built with exactly the snippets' flags;
    -Winvalid-pch: a precompiled header g++ cannot use is an error, not a silent slow-down)."""
    header = folder / distro / "rhi_std.hpp"
    header.parent.mkdir(parents=True, exist_ok=True)
    header.write_text("".join(f"#include <{h}>\n" for h in STD_HEADERS), encoding="utf-8")
    proc = subprocess.run([cxx, *_cxxflags(distro), "-x", "c++-header", str(header), "-o", f"{header}.gch"],
                          capture_output=True, text=True, env=ENV_C)
    assert proc.returncode == 0, f"precompiling the standard headers ({distro}):\n{proc.stderr[-3000:]}"
    return ["-Winvalid-pch", "-include", str(header)]


@pytest.fixture(scope="session")
def compile_fail_results(tmp_path_factory):
    """Both compiles of every (snippet, distro), in parallel: {(name, distro): (regex, ok, bad)}."""
    cxx = require_compiler()
    folder = tmp_path_factory.mktemp("snippet_pch")
    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        distros = sorted({d for _, d in SNIPPET_CASES})
        pch = dict(zip(distros, pool.map(lambda d: _precompiled_std(cxx, d, folder), distros), strict=True))

    def run(case: tuple[Path, str]):
        snippet, distro = case
        expected, _ = _snippet_meta(snippet)
        base = [cxx, *_cxxflags(distro), *pch[distro], "-fsyntax-only", str(snippet)]
        ok = subprocess.run(base, capture_output=True, text=True, env=ENV_C)
        bad = subprocess.run([*base, "-DRHI_EXPECT_FAIL"], capture_output=True, text=True, env=ENV_C)
        return (snippet.name, distro), (expected, ok, bad)

    with ThreadPoolExecutor(max_workers=SHORT_WORKERS) as pool:
        return dict(pool.map(run, SNIPPET_CASES))


@pytest.mark.parametrize("snippet,distro", SNIPPET_CASES, ids=[f"{s.stem}-{d}" for s, d in SNIPPET_CASES])
def test_compile_fail_snippet(compile_fail_results, snippet, distro):
    expected, ok, bad = compile_fail_results[(snippet.name, distro)]
    assert expected, f"{snippet.name}: first line must be '// expect: <regex>'"
    assert ok.returncode == 0, f"{snippet.name} ({distro}) must compile without RHI_EXPECT_FAIL:\n{ok.stderr}"
    assert bad.returncode != 0, f"{snippet.name} compiled with RHI_EXPECT_FAIL on {distro}; the stand-ins accept it"
    assert re.search(expected, bad.stderr), (
        f"{snippet.name} ({distro}): expected a diagnostic matching {expected!r}, got:\n{bad.stderr[-4000:]}")


def test_snippets_name_only_known_distros():
    for snippet in COMPILE_FAIL:
        unknown = set(_snippet_meta(snippet)[1]) - set(DISTROS)
        assert not unknown, f"{snippet.name}: unknown distros {sorted(unknown)}"


# The rejections the issue names, per distro: each must be among the cases above.
REQUIRED_REJECTIONS = {
    "command_interface_copy": ["humble"],
    "command_interface_copy_4x": ["jazzy", "kilted", "rolling"],
    "on_init_info_override_removed": ["rolling"],
    "on_init_info_call_deprecated": ["jazzy", "kilted"],
    "handle_raw_pointer_ctor": ["jazzy", "kilted", "rolling"],
    "export_state_interfaces_call": ["jazzy", "kilted", "rolling"],
    "handle_get_value_removed": ["kilted", "rolling"],
    "handle_get_value_deprecated": ["jazzy"],
    # services: the QoS overloads per distro, the deprecated/removed future conversion, callback forms
    # (include/ only: kilted is checked through rolling, the representative of its rclcpp class)
    "create_client_qos_humble": ["humble"],
    "create_client_rmw_qos_deprecated": ["jazzy"],
    "create_client_rmw_qos_removed": ["rolling"],
    "client_future_conversion_deprecated": ["humble", "jazzy"],
    "client_future_conversion_removed": ["rolling"],
    "service_callback_signature": ["humble", "jazzy", "rolling"],
    "client_callback_signature": ["humble", "jazzy", "rolling"],
    "set_value_nodiscard": ["jazzy", "kilted", "rolling"],
    "resource_manager_urdf_only": ["jazzy", "kilted", "rolling"],
}


@pytest.mark.parametrize("name", sorted(REQUIRED_REJECTIONS))
def test_required_rejections_are_covered(name):
    cases = {(s.stem, d) for s, d in SNIPPET_CASES}
    missing = [d for d in REQUIRED_REJECTIONS[name] if (name, d) not in cases]
    assert not missing, f"compile_fail/{name}.cpp does not cover {missing}"


@pytest.mark.parametrize("distro", list(DISTROS))
def test_selftest_includes_every_public_header(distro):
    sources = [SELFTEST, SELFTEST_DIR / ("hi_humble.inc" if DISTROS[distro].hi_major < 3 else "hi_since_jazzy.inc")]
    included = set()
    for source in sources:
        included |= set(re.findall(r'#include [<"]([^>"]+)[>"]', source.read_text()))
    missing = [h for h in _public_headers(distro)
               if not h.startswith("rhi_fake/") and h not in included
               and h not in INDIRECT_ONLY and h not in GTEST_ONLY.get(DISTROS[distro].hi_major >= 3, set())]
    assert not missing, f"the {distro} self-test does not include: {missing}"


# Headers a driver does not include directly; the self-test reaches them through others.
INDIRECT_ONLY = {
    "rcl/time.h",
    "rmw/types.h",
    "rmw/qos_profiles.h",
    "hardware_interface/macros.hpp",
    "rclcpp/any_service_callback.hpp",
    "rclcpp/callback_group.hpp",
    "rclcpp/context.hpp",
    "rclcpp/exceptions.hpp",
    "rclcpp/executor.hpp",
    "rclcpp/logger.hpp",
    "rclcpp/node_interfaces/node_base_interface.hpp",
    "rclcpp/node_interfaces/node_clock_interface.hpp",
    "rclcpp/node_interfaces/node_logging_interface.hpp",
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

# Headers only the generated gtest (templates/robot/test.cpp.j2) includes, never a driver. On
# Humble tests/cpp/test_cpp_gtest_compiles.py compiles and runs them; the 4.x+ self-test runs its own.
GTEST_ONLY = {
    False: {
        "hardware_interface/resource_manager.hpp",
        "hardware_interface/hardware_component_info.hpp",
        "ros2_control_test_assets/descriptions.hpp",
    },
    True: set(),
}
