"""Issue 24: a fresh clone passes its own tests and runs its own benchmark.

`git clone` of the repository's HEAD into an empty temporary folder (nothing beside it: no ../shared), then
the README's own commands, parsed from README.md so the test runs them word for word:

* "Run the tests": the whole command (install-test-deps, venv, pip, pytest) must pass, and the number of
  skipped tests must be the one README states ("without the AimDK message definitions N tests skip"),
  plus this file's own two tests, whose inner copies skip (RHI_FRESH_CLONE_INNER is set) so the clone
  does not clone itself again;
* "Benchmarks": the command with `--robot g1 --robot pm01` measures both; with `--robot x2` it says in
  one line that it skipped X2 and why (no raw compiler error).

What the clone runs: when this session ran the whole suite, it knows which tests read ../shared
(tests/support/shared_use.py records every open, listing, stat and compiler argument under it, through
fixtures and cached values too), and the clone runs exactly those, the whole quick tier (no compiler: the
CLI, the install it runs from, the gates) and any test this session did not run
(tests/support/fresh_clone_selection.py, passed in RHI_FRESH_CLONE_SELECT; the README command is still run
word for word). The rest of the C++ tier would compile the clone's files, the session's byte for byte, into
the same objects and run them again. Run alone (or with -k, -m, paths), this file runs the whole suite in
the clone. The skip count above checks the record: a test that skips in the clone but did not read
../shared here would be missing from the clone's run, and the count would fall short.

Cost: this runs last in the session (tests/conftest.py) and passes the session's compiled-object cache
to the clone (RHI_CPP_CACHE: object keys hold contents, never paths, so the clone's compiles are cache
hits); pip installs from its own cache. The clone tests HEAD: commit first when running this on a
working tree with changes.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from tests.support import cpp_build, fresh_clone_selection, vendor_msgs
from tests.support.repo import REPO

pytestmark = pytest.mark.cpp  # it runs the whole suite, compiles included, in the clone

INNER = "RHI_FRESH_CLONE_INNER"
# What a user's machine does not have: the project's shared vendor data and this session's own settings.
DROPPED_ENV = ("RHI_UPSTREAM", "RHI_UPSTREAM_MSGS", "VIRTUAL_ENV", "PYTEST_ADDOPTS", "PYTEST_CURRENT_TEST",
               "PYTHONPATH")
TIMEOUT = 3600


def readme_block(heading: str) -> str:
    """The first ```sh block of README.md's section ``heading``."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    section = text.split(f"\n## {heading}\n", 1)[1].split("\n## ", 1)[0]
    match = re.search(r"```sh\n(.*?)```", section, re.S)
    assert match, f"README.md, {heading!r}: no ```sh block"
    return match[1].strip()


# In the inner run both tests of this file skip (the clone must not clone itself again).
INNER_SELF_SKIPS = 2


def readme_skip_count() -> int:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    match = re.search(r"without the AimDK message definitions (\d+) tests skip", text)
    assert match, "README.md does not say how many tests skip without the AimDK message definitions"
    return int(match[1])


@pytest.fixture(scope="module")
def clone(tmp_path_factory, request):
    if os.environ.get(INNER):
        pytest.skip(f"inner run of tests/cli/test_fresh_clone.py ({INNER} is set): a fresh clone does not clone "
                    "itself again")
    if not (REPO / ".git").exists() or shutil.which("git") is None:
        pytest.skip("not a git checkout (or no git): nothing to clone")
    root = tmp_path_factory.mktemp("fresh")
    dest = root / "clone"                      # root holds nothing else: no ../shared beside the clone
    subprocess.run(["git", "clone", "--quiet", str(REPO), str(dest)], check=True, capture_output=True)
    assert not (dest.parent / "shared").exists()
    env = {k: v for k, v in os.environ.items() if k not in DROPPED_ENV}
    env[INNER] = "1"
    env["TMPDIR"] = str(root / "tmp")          # the inner pytest's basetemp, away from this session's
    (root / "tmp").mkdir()
    # The session's object cache (the same content gives the same key in any folder).
    env["RHI_CPP_CACHE"] = str(os.environ.get("RHI_CPP_CACHE") or
                               cpp_build.session_builder(tmp_path_factory).cache_dir)
    if fresh_clone_selection.whole_suite(request.config):
        # this session ran every test and knows which read ../shared: the clone runs those and the quick tier
        chosen = fresh_clone_selection.selection(request.session.items, request.node.nodeid.split("::")[0])
        fresh_clone_selection.write(root / "selection.json", chosen)
        env[fresh_clone_selection.ENV] = str(root / "selection.json")
    return dest, env


def slowest(stdout: str, count: int) -> list[str]:
    """The first ``count`` lines of pytest's durations table in ``stdout`` (what the clone spent its time on)."""
    lines = stdout.splitlines()
    start = next((i for i, line in enumerate(lines) if "slowest" in line and "durations" in line), None)
    return [] if start is None else [line for line in lines[start + 1:start + 1 + count] if line.strip()]


def run(cmd: str, cwd: Path, env: dict[str, str]) -> tuple[subprocess.CompletedProcess, float]:
    start = time.monotonic()
    proc = subprocess.run(["bash", "-c", cmd], cwd=cwd, env=env, capture_output=True, text=True, timeout=TIMEOUT)
    return proc, time.monotonic() - start


# What the record must have found in a whole-suite session (with ../shared beside it), and what not.
READS_SHARED = ("tests/gates/test_vendor_data.py::test_the_copies_are_byte_identical_to_the_shared_vendor_data",
                "tests/cpp/test_cpp_drivers.py::test_driver_against_simulated_robot[agibot/x2-jazzy-plain]",
                "tests/cpp/test_cpp_mutations.py::test_mutation_is_caught[take_control_refusal_ignored]",
                "tests/cpp/test_cpp_gtest_compiles.py::test_gtest_runs_against_the_standin[agibot/x2-rolling]")
READS_NOTHING_SHARED = ("tests/cpp/test_cpp_drivers.py::test_driver_against_simulated_robot[unitree/g1-jazzy-plain]",
                        "tests/cpp/test_cpp_mutations.py::test_mutation_is_caught[crc_polynomial]",
                        "tests/cpp/test_cpp_gtest_compiles.py::test_gtest_runs_against_the_standin[engineai/pm01-humble]")


def test_readme_test_command_passes_in_a_fresh_clone(clone, report):
    dest, env = clone
    if fresh_clone_selection.ENV in env and vendor_msgs.UPSTREAM.is_dir():
        chosen = json.loads(Path(env[fresh_clone_selection.ENV]).read_text(encoding="utf-8"))
        run_ids = set(chosen["run"])
        assert set(READS_SHARED) <= run_ids, f"not recorded as reading ../shared: {set(READS_SHARED) - run_ids}"
        assert not set(READS_NOTHING_SHARED) & run_ids, \
            f"recorded as reading ../shared: {set(READS_NOTHING_SHARED) & run_ids}"
    command = readme_block("Run the tests")
    proc, seconds = run(command, dest, env)
    tail = proc.stdout[-6000:] + proc.stderr[-3000:]
    report(f"fresh clone: `{command}` took {seconds:.0f} s")
    assert proc.returncode == 0, f"exit {proc.returncode} after {seconds:.0f} s:\n{tail}"
    summary = proc.stdout.strip().splitlines()[-1]
    report(f"fresh clone: {summary}")
    for line in slowest(proc.stdout, 8):
        report(f"fresh clone, slowest: {line}")
    if fresh_clone_selection.ENV in env:
        chosen = json.loads(Path(env[fresh_clone_selection.ENV]).read_text(encoding="utf-8"))
        report(f"fresh clone: ran {len(chosen['run'])} of this session's {len(chosen['outer'])} tests (every test "
               "that read ../shared, and the quick tier) and this file's own two")
    skipped = int(m[1]) if (m := re.search(r"(\d+) skipped", summary)) else 0
    assert skipped == readme_skip_count() + INNER_SELF_SKIPS, (
        f"README says {readme_skip_count()} tests skip without the AimDK message definitions "
        f"(+{INNER_SELF_SKIPS}: the inner copies of this file's tests); the clone skipped {skipped}:\n"
        + "\n".join(line for line in proc.stdout.splitlines() if line.startswith("SKIPPED")))
    reasons = [line for line in proc.stdout.splitlines() if line.startswith("SKIPPED")]
    allowed = ("aimdk_msgs", "upstream URDF", "upstream is missing", INNER)
    assert all(any(a in line for a in allowed) for line in reasons), "\n".join(reasons)


def test_readme_benchmark_runs_in_a_fresh_clone(clone, report):
    dest, env = clone
    if not (dest / ".venv" / "bin" / "python").is_file():
        pytest.fail("the README's test command did not create .venv (see the test above)")
    command = readme_block("Benchmarks").split("#", 1)[0].strip()
    # One distro keeps this test's cost where it was; jazzy runs every path (framework-owned handles).
    proc, seconds = run(f"{command} --robot g1 --robot pm01 --distro jazzy", dest, env)
    report(f"fresh clone: benchmark (g1, pm01 on jazzy) took {seconds:.0f} s")
    assert proc.returncode == 0, f"exit {proc.returncode}:\n{proc.stdout[-4000:]}\n{proc.stderr[-4000:]}"
    assert "== unitree/g1 on jazzy" in proc.stdout and "== engineai/pm01 on jazzy" in proc.stdout, proc.stdout[-4000:]
    assert "readwrite_pos" in proc.stdout and "locks_pos" in proc.stdout, proc.stdout[-4000:]
    assert "skipped" not in proc.stdout, proc.stdout[-4000:]
    # X2's messages are not in the repository: one line says so, no compiler runs.
    proc, _ = run(f"{command} --robot x2", dest, env)
    lines = (proc.stdout + proc.stderr).strip().splitlines()
    assert proc.returncode != 0 and lines[0].startswith("skipped agibot/x2: agibot_topics needs vendor messages"), lines
    assert "RHI_UPSTREAM" in lines[0] and "error:" not in proc.stderr, lines
