"""The record of reads of ../shared (tests/support/shared_use.py) that decides what a fresh clone re-runs:
every way a test can learn something from the folder counts, and nothing else does."""
from __future__ import annotations

import glob
import os
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.support import shared_use


@pytest.fixture
def watched(tmp_path: Path) -> Iterator[tuple[Path, Path]]:
    """(a watched folder holding data/x.msg, a folder beside it that is not watched)."""
    root, other = tmp_path / "shared", tmp_path / "other"
    for folder in (root / "data", other):
        folder.mkdir(parents=True)
    (root / "data" / "x.msg").write_text("int32 a\n")
    (other / "y.msg").write_text("int32 b\n")
    shared_use.install()
    shared_use.watch(root)
    yield root, other
    shared_use.unwatch(root)


def reads(action) -> bool:
    with shared_use.recording() as used:
        action()
    return bool(used)


@pytest.mark.parametrize("how", ["open", "read_text", "exists", "is_dir", "listdir", "iterdir", "glob", "walk",
                                 "subprocess_include_flag", "subprocess_cwd"])
def test_each_way_of_reading_the_folder_counts(watched, how):
    root, _ = watched
    f = root / "data" / "x.msg"
    actions = {
        "open": lambda: open(f).close(),
        "read_text": f.read_text,
        "exists": lambda: (root / "data" / "missing.msg").exists(),  # a test that skips on a missing file
        "is_dir": (root / "data").is_dir,
        "listdir": lambda: os.listdir(root),
        "iterdir": lambda: list((root / "data").iterdir()),
        "glob": lambda: glob.glob(str(root / "*" / "*.msg")),
        "walk": lambda: list(os.walk(root)),
        "subprocess_include_flag": lambda: subprocess.run([sys.executable, "-c", "pass", f"-I{root}/data"], check=True),
        "subprocess_cwd": lambda: subprocess.run([sys.executable, "-c", "pass"], cwd=root, check=True),
    }
    assert reads(actions[how]), how


def test_other_folders_and_a_name_that_only_starts_alike_do_not_count(watched, tmp_path):
    _, other = watched
    alike = tmp_path / "shared_not"  # "/.../shared" is a prefix of its text, not of its path
    alike.mkdir()
    assert not reads(lambda: (other / "y.msg").read_text())
    assert not reads(lambda: os.listdir(alike))
    assert not reads(lambda: subprocess.run([sys.executable, "-c", "pass", f"-I{other}"], check=True))


def test_a_cached_value_counts_at_every_use(watched):
    root, other = watched
    calls = []

    @shared_use.cached
    def load(path: Path) -> str:
        calls.append(path)
        return path.read_text()

    assert reads(lambda: load(root / "data" / "x.msg"))
    assert reads(lambda: load(root / "data" / "x.msg")), "the second use reads nothing from disk, and still counts"
    assert not reads(lambda: load(other / "y.msg"))
    assert len(calls) == 2


def test_recorded_results_count_only_for_the_item_looked_up(watched):
    root, other = watched
    items = {}
    for name, folder in (("x2", root / "data"), ("g1", other)):
        with shared_use.recording() as used:
            os.listdir(folder)
        items[name] = (name.upper(), set(used))
    results = shared_use.Recorded(items)
    assert reads(lambda: results["x2"]) and not reads(lambda: results["g1"])
    assert not reads(lambda: results.quietly("x2"))
    assert not reads(lambda: "x2" in results), "asking whether a result is there is not a use of it"
    assert "x2" in results and "go2" not in results


def test_a_worker_thread_without_its_own_record_counts_for_the_running_test(watched):
    root, _ = watched
    with shared_use.recording(main=True) as used:
        worker = threading.Thread(target=lambda: (root / "data" / "x.msg").read_bytes())
        worker.start()
        worker.join()
    assert used
