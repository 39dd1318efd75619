"""The load mode (tests/support/load.py): spinners started, counted and stopped, by a session and by itself."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from tests.support import load
from tests.support.repo import REPO


def spinning(pids: list[int]) -> list[int]:
    """The pids of ``pids`` that still run (not zombies)."""
    alive = []
    for pid in pids:
        try:
            state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except FileNotFoundError:
            continue
        if state != "Z":
            alive.append(pid)
    return alive


def wait_gone(pids: list[int], deadline_s: float = 30.0) -> list[int]:
    """Waits (bounding a hang only) until none of ``pids`` runs; the ones still running."""
    end = time.monotonic() + deadline_s
    while spinning(pids) and time.monotonic() < end:
        time.sleep(0.05)
    return spinning(pids)


def test_per_core_reads_the_variable() -> None:
    assert [load.per_core(v) for v in (None, "", " 0 ", "1", "3")] == [0, 0, 0, 1, 3]
    for bad in ("yes", "-1", "1.5"):
        with pytest.raises(pytest.UsageError, match=load.ENV):
            load.per_core(bad)


def test_spinners_start_count_and_stop() -> None:
    spinners = load.Load(3)
    spinners.start()
    try:
        pids = [p.pid for p in spinners.processes]
        assert spinners.running() == 3
        time.sleep(0.3)
        cpu = [sum(int(x) for x in Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[11:13])
               for pid in pids]
        assert all(ticks > 0 for ticks in cpu), f"the spinners use the CPU (clock ticks: {cpu})"
    finally:
        spinners.stop()
    assert spinners.running() == 0
    assert spinning(pids) == []
    spinners.stop()  # again: nothing left to stop


def test_a_spinner_ends_with_its_parent() -> None:
    """A session killed with SIGKILL (no pytest_unconfigure) leaves no spinner behind."""
    parent = subprocess.run(
        [sys.executable, "-c", textwrap.dedent("""
            import sys
            from tests.support import load
            spinners = load.Load(2)
            spinners.start()
            print(" ".join(str(p.pid) for p in spinners.processes), flush=True)
            import os, signal
            os.kill(os.getpid(), signal.SIGKILL)
        """)], cwd=REPO, capture_output=True, text=True, timeout=60)
    pids = [int(pid) for pid in parent.stdout.split()]
    assert len(pids) == 2
    assert wait_gone(pids) == []


# A conftest that registers the load mode as tests/conftest.py does (once, also where a parent conftest did).
CONFTEST = ("from tests.support import load\n\n"
            "def pytest_configure(config):\n"
            "    if not config.pluginmanager.has_plugin('rhi-load'):\n"
            "        config.pluginmanager.register(load, 'rhi-load')\n")


def run_session(folder: Path, test: str, per_core: int) -> tuple[subprocess.CompletedProcess, list[int]]:
    """pytest on ``folder``/test_session.py (``test``, which writes its spinners' pids to ``folder``/pids) with
    RHI_TEST_LOAD=``per_core``: the run, and the pids."""
    (folder / "conftest.py").write_text(CONFTEST)
    (folder / "test_session.py").write_text(textwrap.dedent(test))
    env = {**os.environ, load.ENV: str(per_core), "PYTHONPATH": str(REPO)}
    env.pop(load.OWNER, None)
    run = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "--rootdir", str(folder),
                          str(folder / "test_session.py")], cwd=folder, env=env, capture_output=True, text=True,
                         timeout=300)
    return run, [int(pid) for pid in (folder / "pids").read_text().split()]


def test_a_session_loads_the_machine_and_a_nested_one_does_not(tmp_path: Path) -> None:
    """A pytest session with RHI_TEST_LOAD=1 runs one spinner per core while its tests run, a pytest started
    inside it (the fresh clone's inner run) starts none, and none is left once the session ended."""
    inner = tmp_path / "inner"
    inner.mkdir()
    (inner / "conftest.py").write_text(CONFTEST)
    (inner / "test_inner.py").write_text("from tests.support import load\n\n"
                                         "def test_inner(request):\n"
                                         "    assert load.STATE not in request.config.stash\n")
    run, pids = run_session(tmp_path, f"""
        import os, subprocess, sys
        from tests.support import load

        def test_seen(request):
            spinners = request.config.stash[load.STATE]
            with open({str(tmp_path / "pids")!r}, "w") as f:
                f.write(" ".join(str(p.pid) for p in spinners.processes))
            assert spinners.running() == spinners.count == load.cores()
            assert os.environ[load.OWNER] == str(os.getpid())
            inner = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider",
                                    {str(inner)!r}], capture_output=True, text=True)
            assert "none started here" in inner.stdout, inner.stdout
            assert "1 passed" in inner.stdout, inner.stdout
    """, 1)
    assert run.returncode == 0, run.stdout + run.stderr
    assert f"load mode ({load.ENV}): {load.cores()} busy processes" in run.stdout
    assert len(pids) == load.cores()
    assert spinning(pids) == [], "the session stopped its spinners when it ended"


@pytest.mark.parametrize(("ending", "exit_code"), [("raise KeyboardInterrupt", 2), ("assert False", 1)],
                         ids=["ctrl-c", "failure"])
def test_an_interrupted_or_failed_session_stops_its_spinners(tmp_path: Path, ending: str, exit_code: int) -> None:
    run, pids = run_session(tmp_path, f"""
        from tests.support import load

        def test_ends(request):
            with open({str(tmp_path / "pids")!r}, "w") as f:
                f.write(" ".join(str(p.pid) for p in request.config.stash[load.STATE].processes))
            {ending}  # a Ctrl-C while the test runs, or a failure
    """, 2)
    assert run.returncode == exit_code, run.stdout + run.stderr
    assert len(pids) == 2 * load.cores()
    assert spinning(pids) == []
