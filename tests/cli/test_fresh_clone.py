"""Issue 24: a fresh clone passes its own tests and runs its own benchmark.

`git clone` of the repository's HEAD into an empty temporary folder (nothing beside it: no ../shared), then
the commands the user documentation gives, parsed from it so the test runs them word for word:

* README.md's "Run the tests": the whole command (install-test-deps, venv, pip, pytest) must pass, and the
  number of skipped tests must be the one docs/testing.md states ("without the AimDK message definitions N
  tests skip"),
  plus this file's own two tests, whose inner copies skip (RHI_FRESH_CLONE_INNER is set) so the clone
  does not clone itself again;
* docs/benchmarks.md's "Hot paths": the command with `--robot g1 --robot pm01` measures both; with
  `--robot x2` it says in one line that it skipped X2 and why (no raw compiler error).

What the clone runs: when this session runs the whole suite, it records which tests read ../shared
(tests/support/shared_use.py records every open, listing, stat and compiler argument under it, through
fixtures and cached values too), and the clone runs exactly those, the whole quick tier (no compiler: the
CLI, the install it runs from, the gates) and any test this session did not run
(tests/support/fresh_clone_selection.py, passed in RHI_FRESH_CLONE_SELECT). The rest of the C++ tier would
compile the clone's files, the session's byte for byte, into the same objects and run them again. The skip
count above checks the record: a test that skips in the clone but did not read ../shared here would be
missing from the clone's run, and the count would fall short. Run alone (or with -k, -m, paths), this file
runs the whole suite in the clone.

Cost: in a whole-suite session the clone is made when collection ends, and runs the README's test command
with the quick tier, then the benchmark, in the background while the session runs (tests/support/
fresh_clone.py); after the session's last C++ test, the C++ tests that read ../shared run in the same clone
(`.venv/bin/python -m pytest`, the command's last step, again) with the session's compiled-object cache
(RHI_CPP_CACHE: object keys hold contents, never paths, so they are cache hits), while the session runs the
rest of its quick tier; these tests wait for both. The clone tests HEAD as it
was when the session started: commit first when running this on a working tree with changes.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from tests.support import cpp_build, vendor_msgs
from tests.support.fresh_clone import (
    BENCHMARK,
    BENCHMARK_ARGS,
    BENCHMARK_X2,
    EARLY,
    INNER,
    SHARED_CPP,
    TESTS,
    FreshClone,
    benchmark_command,
    can_clone,
    documented_skip_count,
    readme_test_command,
)

pytestmark = pytest.mark.cpp  # it runs the whole suite, compiles included, in the clone

INNER_SELF_SKIPS = 2


@pytest.fixture(scope="module")
def clone(request, tmp_path_factory) -> FreshClone:
    """The clone this session started when collection ended, running the quick tier and the benchmark
    (tests/support/fresh_clone.py); run without the whole suite, a new one running the whole suite."""
    reason = can_clone()
    if reason:
        pytest.skip(reason)
    early = request.config.stash.get(EARLY, None)
    if early is not None:
        return early
    made = FreshClone(tmp_path_factory.mktemp("fresh"))
    made.env["RHI_CPP_CACHE"] = str(session_cache(tmp_path_factory))
    made.start([(TESTS, readme_test_command(), {}), (BENCHMARK, f"{benchmark_command()} {BENCHMARK_ARGS}", {}),
                (BENCHMARK_X2, f"{benchmark_command()} --robot x2", {})])
    return made


def session_cache(tmp_path_factory) -> Path:
    """The session's object cache (the same content gives the same key in any folder)."""
    return cpp_build.session_builder(tmp_path_factory).cache_dir


def slowest(stdout: str, count: int) -> list[str]:
    """The first ``count`` lines of pytest's durations table in ``stdout`` (what the clone spent its time on)."""
    lines = stdout.splitlines()
    start = next((i for i, line in enumerate(lines) if "slowest" in line and "durations" in line), None)
    return [] if start is None else [line for line in lines[start + 1:start + 1 + count] if line.strip()]


# What the record must have found in a whole-suite session (with ../shared beside it), and what not.
READS_SHARED = ("tests/gates/test_vendor_data.py::test_the_copies_are_byte_identical_to_the_shared_vendor_data",
                "tests/cpp/test_cpp_drivers.py::test_driver_against_simulated_robot[agibot/x2-jazzy-plain]",
                "tests/cpp/test_cpp_mutations.py::test_mutation_is_caught[take_control_refusal_ignored]",
                "tests/cpp/test_cpp_gtest_compiles.py::test_gtest_runs_against_the_standin[agibot/x2-rolling]")
READS_NOTHING_SHARED = ("tests/cpp/test_cpp_drivers.py::test_driver_against_simulated_robot[unitree/g1-jazzy-plain]",
                        "tests/cpp/test_cpp_mutations.py::test_mutation_is_caught[crc_polynomial]",
                        "tests/cpp/test_cpp_gtest_compiles.py::test_gtest_runs_against_the_standin[engineai/pm01-humble]")


def check_phase(clone: FreshClone, name: str, report) -> str:
    """The pytest summary line of ``name``, a run of the README's test command (or its last step) that passed."""
    result = clone.result(name)
    assert result is not None, f"the fresh clone did not run {name}"
    proc, seconds = result
    tail = proc.stdout[-6000:] + proc.stderr[-3000:]
    report(f"fresh clone, {name}: `{proc.args[-1]}` took {seconds:.0f} s")
    assert proc.returncode == 0, f"{name}: exit {proc.returncode} after {seconds:.0f} s:\n{tail}"
    summary = proc.stdout.strip().splitlines()[-1]
    report(f"fresh clone, {name}: {summary}")
    for line in slowest(proc.stdout, 8):
        report(f"fresh clone, {name}, slowest: {line}")
    reasons = [line for line in proc.stdout.splitlines() if line.startswith("SKIPPED")]
    allowed = ("aimdk_msgs", "upstream URDF", "upstream is missing", INNER)
    assert all(any(a in line for a in allowed) for line in reasons), "\n".join(reasons)
    return summary


def test_readme_test_command_passes_in_a_fresh_clone(clone, request, tmp_path_factory, report):
    summaries = [check_phase(clone, TESTS, report)]  # the README's command word for word
    if clone.quick_selection is not None:
        # The session ran the rest: the C++ tests that read ../shared run in the clone now, by the command's last
        # step (its install is done), with the session's objects.
        if clone.shared_cpp is None:  # not started after the session's last C++ test (tests/conftest.py)
            clone.start_shared_cpp(request.session.items, session_cache(tmp_path_factory))
        chosen = clone.shared_cpp
        assert chosen is not None
        quick = json.loads(clone.quick_selection.read_text(encoding="utf-8"))
        if vendor_msgs.UPSTREAM.is_dir():  # both halves: a test of the quick tier may read ../shared too
            run_ids = set(quick["run"]) | set(chosen["run"])
            assert set(READS_SHARED) <= run_ids, f"not recorded as reading ../shared: {set(READS_SHARED) - run_ids}"
            assert not set(READS_NOTHING_SHARED) & run_ids, \
                f"recorded as reading ../shared: {set(READS_NOTHING_SHARED) & run_ids}"
        report(f"fresh clone: ran {len(quick['run']) + len(chosen['run'])} of this session's {len(chosen['outer'])} "
               f"tests (the quick tier, {len(quick['run'])}, while the session ran; then every C++ test that read "
               f"../shared, {len(chosen['run'])}) and, in each run, this file's own two")
        summaries.append(check_phase(clone, SHARED_CPP, report))
    skipped = sum(int(m[1]) if (m := re.search(r"(\d+) skipped", summary)) else 0 for summary in summaries)
    expected = documented_skip_count() + INNER_SELF_SKIPS * len(summaries)
    assert skipped == expected, (
        f"docs/testing.md says {documented_skip_count()} tests skip without the AimDK message definitions "
        f"(+{INNER_SELF_SKIPS} in each of the clone's {len(summaries)} pytest runs: the inner copies of this "
        f"file's tests); the clone skipped {skipped}")


def test_readme_benchmark_runs_in_a_fresh_clone(clone, report):
    if not (clone.dest / ".venv" / "bin" / "python").is_file():
        pytest.fail("the README's test command did not create .venv (see the test above)")
    result = clone.result(BENCHMARK)
    assert result is not None
    proc, seconds = result
    report(f"fresh clone: benchmark (g1, pm01 on jazzy) took {seconds:.0f} s")
    assert proc.returncode == 0, f"exit {proc.returncode}:\n{proc.stdout[-4000:]}\n{proc.stderr[-4000:]}"
    assert "== unitree/g1 on jazzy" in proc.stdout and "== engineai/pm01 on jazzy" in proc.stdout, proc.stdout[-4000:]
    assert "readwrite_pos" in proc.stdout and "locks_pos" in proc.stdout, proc.stdout[-4000:]
    assert "skipped" not in proc.stdout, proc.stdout[-4000:]
    # X2's messages are not in the repository: one line says so, no compiler runs.
    result = clone.result(BENCHMARK_X2)
    assert result is not None
    proc, _ = result
    lines = (proc.stdout + proc.stderr).strip().splitlines()
    assert proc.returncode != 0 and lines[0].startswith("skipped agibot/x2: agibot_topics needs vendor messages"), lines
    assert "RHI_UPSTREAM" in lines[0] and "error:" not in proc.stderr, lines
