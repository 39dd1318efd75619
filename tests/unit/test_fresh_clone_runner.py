"""tests/support/fresh_clone.py: the clone is HEAD with nothing beside it, its commands run in the background
and end with the session (what tests/cli/test_fresh_clone.py relies on, checked here in seconds)."""
from __future__ import annotations

import os
import shutil
import signal
import subprocess
import time

import pytest

from tests.support import load
from tests.support.fresh_clone import INNER, FreshClone
from tests.support.repo import REPO


@pytest.fixture
def clone(tmp_path):
    if not (REPO / ".git").exists() or shutil.which("git") is None:  # not INNER: a fresh clone runs this too
        pytest.skip("not a git checkout (or no git): nothing to clone")
    made = FreshClone(tmp_path)
    yield made
    made.stop()


def test_the_clone_is_head_and_runs_steps_in_order_in_the_background(clone, tmp_path):
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True, text=True).stdout.strip()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["clone", "tmp"]  # nothing beside the clone
    clone.start([("head", "git rev-parse HEAD", {}), ("env", 'echo "$' + INNER + ' $TMPDIR $EXTRA"', {"EXTRA": "x"})])
    head_run, env_run = clone.result("head"), clone.result("env")
    assert head_run is not None and head_run[0].stdout.strip() == head
    assert env_run is not None and env_run[0].stdout.split() == ["1", str(tmp_path / "tmp"), "x"]


def test_stop_ends_the_running_command_and_the_steps_after_it(clone):
    clone.start([("long", "sleep 60 & wait", {}), ("after", "echo never", {})])
    deadline = time.monotonic() + 60  # bounds a hang only: the command is running once _running is set
    while clone._running is None and time.monotonic() < deadline:
        time.sleep(0.01)
    assert clone._running is not None, "the long command never started"
    clone.stop()
    long_run = clone.result("long")
    # killed (SIGKILL to its process group), not left to finish its minute, however slow the machine
    assert long_run is not None and long_run[0].returncode == -signal.SIGKILL
    assert clone.result("after") is None


def test_steps_started_later_run_after_the_earlier_ones(clone):
    """The C++ phase, started after the session's last C++ test, waits for the quick tier and the benchmark."""
    clone.start([("first", "sleep 0.5 && echo first > ../tmp/order", {})])
    clone.start([("second", "cat ../tmp/order", {})])
    second = clone.result("second")
    assert second is not None and second[0].stdout.strip() == "first"


def test_the_inner_run_inherits_the_load_mode_and_starts_no_load(tmp_path, monkeypatch):
    """RHI_TEST_LOAD carries into the clone's commands with the loading session's pid: the inner pytest sees the
    outer session's spinners and starts none (tests/support/load.py)."""
    if not (REPO / ".git").exists() or shutil.which("git") is None:
        pytest.skip("not a git checkout (or no git): nothing to clone")
    monkeypatch.setenv(load.ENV, "3")
    monkeypatch.setenv(load.OWNER, str(os.getpid()))
    made = FreshClone(tmp_path)
    try:
        made.start([("env", f'echo "${load.ENV} ${load.OWNER}"', {})])
        run = made.result("env")
        assert run is not None and run[0].stdout.split() == ["3", str(os.getpid())]
        assert load.owner_alive({load.OWNER: str(os.getpid())}) is False  # this process: its own spinners
        assert load.owner_alive({load.OWNER: str(os.getppid())}) is True  # an ancestor's: none started
    finally:
        made.stop()
