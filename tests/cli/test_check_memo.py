"""`rhi-gen check` with nothing changed answers from the memo of the last check that passed
(rhi_gen/pipeline/verified.py), and only then: any byte that check read, changed, runs the full check.

Each test settles the project first (its files dated an hour back): the memo skips files written
while a check might have been reading them, and a fixture's files are seconds old.
"""
from __future__ import annotations

import os
import shutil
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

import rhi_gen
from rhi_gen.pipeline import load as pipeline_load
from rhi_gen.pipeline import verified
from rhi_gen.project import find_project
from rhi_gen.render.markers import REGION_BEGIN
from tests.support.cli import cli

PKG = "generated/robot_hardware_interface"
MANIFEST = "generated/.rhi-gen-manifest"


def settle(root: Path) -> None:
    """Date every file under ``root`` an hour back, as files are when a pre-commit hook runs."""
    past = time.time() - 3600
    for path in root.rglob("*"):
        os.utime(path, (past, past))


@pytest.fixture
def full_checks(monkeypatch) -> list[Path]:
    """The projects the full check loaded robots for, in order (empty: every check answered from the memo)."""
    loads: list[Path] = []
    real = pipeline_load.load_robots

    def counting(project, *args, **kwargs):
        loads.append(project.root)
        return real(project, *args, **kwargs)

    monkeypatch.setattr(pipeline_load, "load_robots", counting)
    return loads


@pytest.fixture
def memoised(project, capsys, monkeypatch, tmp_path, full_checks) -> Path:
    """``project`` settled, checked once in full (which passed and was memoised) in a cache of its own."""
    monkeypatch.setenv("RHI_GEN_CACHE", str(tmp_path / "cache"))
    settle(project)
    assert cli(capsys, project, "check")[:2] == (0, "generated/ is up to date (3 robots)\n")
    assert verified.memo_path(find_project(project)).is_file()
    full_checks.clear()
    return project


def test_nothing_changed_answers_without_loading_a_robot(memoised, capsys, full_checks):
    assert cli(capsys, memoised, "check") == (0, "generated/ is up to date (3 robots)\n", "")
    assert cli(capsys, memoised, "check")[0] == 0
    assert full_checks == []


def _append(path: Path, text: str) -> None:
    path.write_text(path.read_text() + text)


def _replace(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert text.count(old) >= 1, old
    path.write_text(text.replace(old, new, 1))


# (what changes, the full check's verdict): each must reach the full check, which decides
CHANGES = {
    "generated file edited outside its regions": (lambda p: _append(p / PKG / "CMakeLists.txt", "# mine\n"), 1),
    "generated file removed": (lambda p: (p / PKG / "src/unitree/g1.cpp").unlink(), 1),
    "generated file emptied": (lambda p: (p / PKG / "launch/g1.launch.py").write_text(""), 1),
    "manifest edited": (lambda p: _replace(p / MANIFEST, '"motor_count": 29', '"motor_count": 30'), 1),
    "manifest removed": (lambda p: (p / MANIFEST).unlink(), 1),
    "yaml value": (lambda p: _replace(p / "robots/unitree/g1.yaml", "state_decimation: 1", "state_decimation: 2"), 1),
    "yaml comment only": (lambda p: _append(p / "robots/unitree/g1.yaml", "# a note\n"), 0),
    "urdf limit": (lambda p: _replace(p / "robots/agibot/x2.urdf", 'effort="', 'effort="1'), 1),
    "package.yaml added": (lambda p: (p / "robots/package.yaml").write_text("copyright: Someone Else\n"), 1),
    "robot yaml removed": (lambda p: (p / "robots/engineai/pm01.yaml").unlink(), 1),
    "robot yaml added": (lambda p: shutil.copy(p / "robots/engineai/pm01.yaml", p / "robots/engineai/pm02.yaml"), 2),
}


@pytest.mark.parametrize("change", list(CHANGES))
def test_any_change_runs_the_full_check(memoised, capsys, full_checks, change):
    edit, verdict = CHANGES[change]
    edit(memoised)
    code, out, err = cli(capsys, memoised, "check")
    assert code == verdict, out + err
    assert full_checks == [memoised.resolve()]


def test_an_edit_inside_a_user_region_passes_the_full_check(memoised, capsys, full_checks):
    cpp = memoised / PKG / "src/unitree/g1.cpp"
    text = cpp.read_text()
    end_of_line = text.index("\n", text.index(f"{REGION_BEGIN} callbacks")) + 1
    cpp.write_text(text[:end_of_line] + "void mine() {}\n" + text[end_of_line:])
    assert cli(capsys, memoised, "check")[0] == 0
    assert full_checks == [memoised.resolve()]


def test_another_rhi_gen_version_runs_the_full_check(memoised, capsys, full_checks, monkeypatch):
    monkeypatch.setattr(rhi_gen, "__version__", "99.0.0")
    code, out, _ = cli(capsys, memoised, "check")
    assert code == 1 and "not by this rhi-gen 99.0.0" in out
    assert full_checks == [memoised.resolve()]


def test_the_stamp_covers_every_file_of_rhi_gen(tmp_path):
    """Templates edited between releases (same version) must miss: the stamp reads the package's files."""
    copy = tmp_path / "rhi_gen"
    shutil.copytree(Path(rhi_gen.__file__).parent, copy, ignore=shutil.ignore_patterns("__pycache__"))
    before = verified.code_stamp(copy)
    assert verified.code_stamp(copy) == before
    template = next(copy.glob("templates/**/*.j2"))
    template.write_bytes(template.read_bytes() + b" ")
    assert verified.code_stamp(copy) != before
    template.write_bytes(template.read_bytes()[:-1])
    assert verified.code_stamp(copy) == before
    (copy / "render" / "extra.py").write_text("")
    assert verified.code_stamp(copy) != before


def test_files_written_just_before_the_check_are_not_memoised(project, capsys, monkeypatch, tmp_path, full_checks):
    monkeypatch.setenv("RHI_GEN_CACHE", str(tmp_path / "cache"))
    assert cli(capsys, project, "check")[0] == 0  # the fixture generated it seconds ago
    assert not verified.memo_path(find_project(project)).exists()
    assert cli(capsys, project, "check")[0] == 0
    assert len(full_checks) == 2


def test_a_xacro_description_is_never_memoised(tmp_path, monkeypatch):
    monkeypatch.setenv("RHI_GEN_CACHE", str(tmp_path / "cache"))
    project = find_project(tmp_path)
    robot = SimpleNamespace(yaml_path=tmp_path / "robots/acme/arm.yaml", config=SimpleNamespace(urdf="arm.urdf.xacro"))
    assert verified.record(project, [robot], [], began=time.time() + 3600) is False  # type: ignore[list-item]
    assert not verified.memo_path(project).exists()


def test_an_unwritable_cache_costs_time_not_a_verdict(project, capsys, monkeypatch, tmp_path, full_checks):
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("")
    monkeypatch.setenv("RHI_GEN_CACHE", str(blocker))
    settle(project)
    assert cli(capsys, project, "check")[:2] == (0, "generated/ is up to date (3 robots)\n")
    assert cli(capsys, project, "check")[0] == 0
    assert len(full_checks) == 2


def test_a_damaged_memo_is_ignored(memoised, capsys, full_checks):
    memo = verified.memo_path(find_project(memoised))
    memo.write_text(memo.read_text()[:40])
    assert cli(capsys, memoised, "check")[0] == 0
    assert full_checks == [memoised.resolve()]
