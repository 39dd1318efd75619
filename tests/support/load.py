"""The suite's load mode: ``RHI_TEST_LOAD=N`` runs N busy processes per core beside the test session.

A check whose verdict depends on how fast the machine is fails on a busy one (issue 48: a user's run beside
three runnable processes per core). The load mode makes that machine on demand, so that such a check is found
here rather than by a user: the session starts ``N x cores`` CPU-spinning processes (plain Python loops, at the
session's own niceness, so they compete with it as other users' work would) when it starts, and stops them when
it ends, passed, failed or interrupted (pytest_unconfigure runs on Ctrl-C too). A spinner also ends by itself
once the session's process is gone (killed with SIGKILL, say): it looks at its parent every few milliseconds,
so no spinner outlives the session that started it.

One session loads the machine, never two: the session that starts the spinners sets ``OWNER`` in its
environment, and a pytest started below it (the fresh clone's inner run, tests/support/fresh_clone.py, which
inherits ``RHI_TEST_LOAD``) starts none: the outer session's spinners already load the machine it runs on.
"""
from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field

import pytest

ENV = "RHI_TEST_LOAD"
OWNER = "RHI_TEST_LOAD_OWNER"   # the pid of the session whose spinners run
STATE = pytest.StashKey["Load"]()

# A busy loop that ends once its parent (the pid it is given: it may already be gone when the loop starts)
# is no longer its parent: the parent is looked at every 100 000 iterations, a few milliseconds.
SPINNER = ("import os, sys\n"
           "parent = int(sys.argv[1])\n"
           "while os.getppid() == parent:\n"
           "    for _ in range(100000):\n"
           "        pass\n")


def per_core(value: str | None) -> int:
    """Busy processes per core that ``RHI_TEST_LOAD`` asks for: unset, empty or 0 is none; a bad value is an
    error that names the variable."""
    text = (value or "").strip()
    if not text:
        return 0
    if not text.isdigit():
        raise pytest.UsageError(f"{ENV}={value!r}: expected a whole number of busy processes per core (1, 3), "
                                f"or 0 for none")
    return int(text)


@dataclass
class Load:
    """The spinners of one session: started by ``start``, ended by ``stop`` (idempotent)."""
    count: int
    processes: list[subprocess.Popen] = field(default_factory=list)

    def start(self) -> None:
        for _ in range(self.count):
            self.processes.append(subprocess.Popen(
                [sys.executable, "-c", SPINNER, str(os.getpid())], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL, start_new_session=True))  # a Ctrl-C at the terminal is the session's

    def running(self) -> int:
        return sum(1 for p in self.processes if p.poll() is None)

    def stop(self) -> None:
        for p in self.processes:
            if p.poll() is None:
                p.kill()
        for p in self.processes:
            p.wait()


def cores() -> int:
    """The cores this process may run on (its affinity), which is what the spinners compete for."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        return os.cpu_count() or 1


def owner_alive(environ: Mapping[str, str]) -> bool:
    """A session above this one (an ancestor process) already runs the spinners."""
    pid = environ.get(OWNER, "")
    if not pid.isdigit() or int(pid) == os.getpid():
        return False
    try:
        os.kill(int(pid), 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def pytest_configure(config: pytest.Config) -> None:
    n = per_core(os.environ.get(ENV))
    if n == 0 or owner_alive(os.environ):
        return
    load = Load(n * cores())
    config.stash[STATE] = load
    os.environ[OWNER] = str(os.getpid())  # pytests this session starts load nothing more
    load.start()


def pytest_unconfigure(config: pytest.Config) -> None:
    load = config.stash.get(STATE, None)
    if load is not None:
        load.stop()
        if os.environ.get(OWNER) == str(os.getpid()):
            del os.environ[OWNER]


def pytest_report_header(config: pytest.Config) -> str | None:
    load = config.stash.get(STATE, None)
    if load is not None:
        return f"load mode ({ENV}): {load.count} busy processes beside the session ({load.count // cores()} per core)"
    if per_core(os.environ.get(ENV)) and owner_alive(os.environ):
        return f"load mode ({ENV}): the session of pid {os.environ[OWNER]} loads the machine; none started here"
    return None
