"""A fresh clone of the repository's HEAD with nothing beside it, and the README's commands run in it.

tests/cli/test_fresh_clone.py checks what they do. In a whole-suite session the clone starts when collection
ends (tests/conftest.py: ``start_early``), in a thread of its own, and runs the quick tier (the README's test
command word for word, its selection the tests without a compiler) and the benchmark while the session's C++
tier keeps the other core busy; after the session's last C++ test (``after_test``: only the session knows by
then which read ../shared), the C++ tests that read ../shared run in the same clone while the session runs the
rest of its quick tier, and the test checks both phases. The clone's pytest is a process of its
own: its tests read and write only the clone and its temporary folder.
"""
from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from tests.support import cpp_build, fresh_clone_selection
from tests.support.repo import REPO

OWN_FILE = "tests/cli/test_fresh_clone.py"
INNER = "RHI_FRESH_CLONE_INNER"
# What a user's machine does not have: the project's shared vendor data and this session's own settings.
DROPPED_ENV = ("RHI_UPSTREAM", "RHI_UPSTREAM_MSGS", "VIRTUAL_ENV", "PYTEST_ADDOPTS", "PYTEST_CURRENT_TEST",
               "PYTHONPATH")
TIMEOUT = 3600
EARLY = pytest.StashKey["FreshClone"]()


# Where the commands the clone runs, and the skip count it checks, are written for users.
README = "README.md"
BENCHMARKS_PAGE = "docs/benchmarks.md"
TESTING_PAGE = "docs/testing.md"


def sh_block(page: str, heading: str = "") -> str:
    """The first ```sh block of ``page`` (relative to the repository), within its ``## heading`` if given."""
    text = (REPO / page).read_text(encoding="utf-8")
    if heading:
        assert f"\n## {heading}\n" in text, f"{page}: no section {heading!r}"
        text = text.split(f"\n## {heading}\n", 1)[1].split("\n## ", 1)[0]
    match = re.search(r"```sh\n(.*?)```", text, re.S)
    assert match, f"{page}, {heading or 'the page'}: no ```sh block"
    return match[1].strip()


def readme_test_command() -> str:
    return sh_block(README, "Run the tests")


def benchmark_command() -> str:
    """The hot-path benchmark's command line (docs/benchmarks.md), its comment dropped."""
    return sh_block(BENCHMARKS_PAGE, "Hot paths").split("#", 1)[0].strip()


def documented_skip_count() -> int:
    """How many tests docs/testing.md says skip without the AimDK message definitions."""
    text = (REPO / TESTING_PAGE).read_text(encoding="utf-8")
    match = re.search(r"without the AimDK message definitions (\d+) tests skip", text)
    assert match, f"{TESTING_PAGE} does not say how many tests skip without the AimDK message definitions"
    return int(match[1])


def can_clone() -> str:
    """Why no clone can be made here ("" when one can)."""
    if os.environ.get(INNER):
        return (f"inner run of {OWN_FILE} ({INNER} is set): a fresh clone does not clone itself again")
    if not (REPO / ".git").exists() or shutil.which("git") is None:
        return "not a git checkout (or no git): nothing to clone"
    return ""


@dataclass
class FreshClone:
    """``root``/clone, cloned from HEAD, and the environment its commands run in (none of this session's)."""
    root: Path
    dest: Path = field(init=False)
    env: dict[str, str] = field(init=False)
    quick_selection: Path | None = None   # started early: the quick tier's selection (else the whole suite)
    cpp_done_after: str = ""              # started early: the session's last C++ test (the record is then whole)
    shared_cpp: dict[str, list[str]] | None = None  # the C++ tests that read ../shared, once their run started
    _results: dict[str, tuple[subprocess.CompletedProcess, float]] = field(default_factory=dict)
    _threads: list[threading.Thread] = field(default_factory=list)
    _running: subprocess.Popen | None = None
    _stopped: bool = False

    def __post_init__(self) -> None:
        self.dest = self.root / "clone"            # root holds nothing else: no ../shared beside the clone
        subprocess.run(["git", "clone", "--quiet", str(REPO), str(self.dest)], check=True, capture_output=True)
        self.env = {k: v for k, v in os.environ.items() if k not in DROPPED_ENV}
        self.env[INNER] = "1"
        self.env["TMPDIR"] = str(self.root / "tmp")  # the inner pytest's basetemp, away from this session's
        (self.root / "tmp").mkdir()

    def run(self, name: str, cmd: str, extra_env: dict[str, str] | None = None
            ) -> tuple[subprocess.CompletedProcess, float]:
        """``cmd`` in the clone (bash), its own process group: ``stop`` ends it with everything it started."""
        start = time.monotonic()
        args = ["bash", "-c", cmd]
        with subprocess.Popen(args, cwd=self.dest, env={**self.env, **(extra_env or {})}, text=True,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True) as proc:
            self._running = proc
            try:
                out, err = proc.communicate(timeout=TIMEOUT)
            except subprocess.TimeoutExpired:
                self.stop()
                out, err = proc.communicate()
                err += f"\ntimed out after {TIMEOUT} s"
            finally:
                self._running = None
        self._results[name] = (subprocess.CompletedProcess(args, proc.returncode, out, err), time.monotonic() - start)
        return self._results[name]

    def stop(self) -> None:
        """End the command running now, if any (the session ends: nothing keeps running after it)."""
        self._stopped = True
        proc = self._running
        if proc is not None and proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)

    def start(self, steps: list[tuple[str, str, dict[str, str]]]) -> None:
        """Run ``steps`` ((name, command, extra environment), in order) in a thread, after the steps started
        before (one command at a time); ``result`` waits."""
        before = list(self._threads)

        def work() -> None:
            for thread in before:
                thread.join()
            for name, cmd, extra in steps:
                if self._stopped:
                    return
                self.run(name, cmd, extra)

        thread = threading.Thread(target=work, name="fresh-clone", daemon=True)
        self._threads.append(thread)
        thread.start()

    def start_shared_cpp(self, items: list[pytest.Item], cache: Path | None) -> None:
        """Start the C++ tests that read ../shared (the record's, over ``items``), by the README command's last
        step (its install is done), with the session's objects (``cache``: object keys hold contents, never
        paths, so they are cache hits)."""
        self.shared_cpp = fresh_clone_selection.shared_cpp(items, OWN_FILE)
        where = Path(tempfile.mkdtemp(dir=self.root)) / "shared_cpp.json"
        fresh_clone_selection.write(where, self.shared_cpp)
        env = {fresh_clone_selection.ENV: str(where), **({"RHI_CPP_CACHE": str(cache)} if cache else {})}
        self.start([(SHARED_CPP, readme_test_command().rsplit("&&", 1)[1].strip(), env)])

    def result(self, name: str) -> tuple[subprocess.CompletedProcess, float] | None:
        for thread in self._threads:
            thread.join()
        return self._results.get(name)


TESTS = "the README's test command"
SHARED_CPP = "C++ tests that read ../shared"
BENCHMARK = "benchmark"
BENCHMARK_X2 = "benchmark x2"
# One distro keeps the benchmark's cost where it was; jazzy runs every path (framework-owned handles).
BENCHMARK_ARGS = "--robot g1 --robot pm01 --distro jazzy"


def start_early(session: pytest.Session, items: list[pytest.Item]) -> None:
    """In a whole-suite session that runs OWN_FILE: clone now and run the quick tier and the benchmark in the
    background (the clone's C++ phase waits for the test, which knows by then what read ../shared)."""
    config = session.config
    if not fresh_clone_selection.whole_suite(config) or can_clone():
        return
    if not any(item.nodeid.startswith(OWN_FILE) for item in items):
        return
    root = Path(tempfile.mkdtemp(prefix="rhi_fresh_clone_"))
    clone = FreshClone(root)

    def cleanup() -> None:
        clone.stop()
        shutil.rmtree(root, ignore_errors=True)

    config.add_cleanup(cleanup)
    selection = root / "quick.json"
    fresh_clone_selection.write(selection, fresh_clone_selection.quick_tier(items, OWN_FILE))
    quick_env = {fresh_clone_selection.ENV: str(selection)}
    clone.start([(TESTS, readme_test_command(), quick_env),
                 (BENCHMARK, f"{benchmark_command()} {BENCHMARK_ARGS}", {}),
                 (BENCHMARK_X2, f"{benchmark_command()} --robot x2", {})])
    clone.quick_selection = selection
    cpp = [item.nodeid for item in items if item.get_closest_marker("cpp") and not item.nodeid.startswith(OWN_FILE)]
    clone.cpp_done_after = cpp[-1] if cpp else ""
    config.stash[EARLY] = clone


def after_test(item: pytest.Item) -> None:
    """After the session's last C++ test (its reads of ../shared recorded), the early clone starts the C++ tests
    that read ../shared, while the session runs the rest of its quick tier; the test waits for them."""
    clone = item.config.stash.get(EARLY, None)
    if clone is not None and clone.cpp_done_after and item.nodeid == clone.cpp_done_after:
        clone.start_shared_cpp(item.session.items, cpp_build.session_cache_dir())
