"""Bad input is exactly one line on stderr, for every command; progress is quiet.

A user who mistyped one motor index must read one line, not a "loading <yaml>" line per robot and
then the error. Progress (the YAMLs being loaded) is for `generate --verbose`, on stdout. Usage
errors (a missing option, an unknown command) follow the same rule instead of click's four-line block.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cli import (
    YAML_REL,
    assert_rejected,
    edit_yaml,
    run_cli,
    snapshot,
    write_project,
)
from tests.support.repo import HOSTILE
from tests.support.repo import URDF_FIXTURES as FIXTURES

ANY = -1  # assert_rejected(line=ANY): some line number


@pytest.fixture
def three_robots(tmp_path: Path) -> Path:
    """A generated project with three robots, so a per-robot progress line would show three times."""
    root = write_project(tmp_path / "proj")
    for robot, urdf in (("gripper", "mimic_gripper.urdf"), ("wheel", "continuous_wheel.urdf")):
        result = run_cli("new", "--vendor", "acme", "--robot", robot, "--urdf", FIXTURES / urdf, "--project", root)
        assert result.code == 0, result.err
    assert run_cli("generate", "--project", root).code == 0
    return root


@pytest.mark.parametrize("command", [["generate"], ["generate", "arm"], ["generate", "--dry-run"],
                                     ["generate", "--verbose"], ["diff"], ["diff", "arm"], ["check"]])
def test_one_fault_is_one_line_on_stderr(three_robots, command):
    edit_yaml(three_robots, "elbow: 2", "elbow: 1")
    before = snapshot(three_robots)
    result = run_cli(*command, "--project", three_robots)
    assert_rejected(result, file=YAML_REL, line=10, key="joint_map.elbow", words=("already used by",))
    assert result.err.count("\n") == 1, result.err
    assert snapshot(three_robots) == before


def edit(root: Path, robot: str, old: str, new: str) -> None:
    path = root / "robots" / "acme" / f"{robot}.yaml"
    text = path.read_text()
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new))


def test_generate_success_says_nothing_on_stderr(three_robots):
    edit(three_robots, "gripper", "state_decimation: 1", "state_decimation: 2")
    result = run_cli("generate", "--project", three_robots)
    assert result.code == 0 and result.err == ""
    assert "loading" not in result.out
    assert "robots: acme/arm (3 joints), acme/gripper (2 joints), acme/wheel (2 joints)" in result.out


def test_generate_verbose_shows_each_yaml_on_stdout(three_robots):
    result = run_cli("generate", "--verbose", "--project", three_robots)
    assert result.code == 0 and result.err == ""
    assert [line for line in result.out.splitlines() if line.startswith("loading ")] == [
        "loading robots/acme/arm.yaml", "loading robots/acme/gripper.yaml", "loading robots/acme/wheel.yaml"]


def test_diff_with_nothing_to_do_is_quiet_about_loading(three_robots):
    result = run_cli("diff", "--project", three_robots)
    assert result.code == 0
    assert result.err.splitlines() == ["nothing to regenerate: generated/ matches the inputs"]


def test_a_broken_second_robot_is_still_one_line(three_robots):
    """The fault is in the last YAML loaded: nothing about the ones loaded before it."""
    edit(three_robots, "wheel", "motor_count: 2", "motor_count: two")
    result = run_cli("generate", "--project", three_robots)
    assert_rejected(result, file="robots/acme/wheel.yaml", line=ANY, key="motor_count")



def test_inspect_and_new_faults_are_one_line(tmp_path):
    xacro = HOSTILE / "needs_arg.urdf.xacro"
    assert_rejected(run_cli("inspect", "--urdf", xacro), file=str(xacro), line=ANY, words=("--xacro-arg prefix=",))
    root = tmp_path / "proj"
    root.mkdir()
    assert_rejected(run_cli("new", "--vendor", "acme", "--robot", "arm", "--urdf", xacro, "--project", root),
                    file=str(xacro), line=ANY, words=("--xacro-arg prefix=",))
    assert list(root.iterdir()) == []


@pytest.mark.parametrize("args, words", [
    (["new", "--vendor", "acme"], ("Missing option '--robot'", "rhi-gen new --help")),
    (["generate", "--bogus"], ("No such option: --bogus", "rhi-gen generate --help")),
    (["frobnicate"], ("No such command 'frobnicate'", "rhi-gen --help")),
    (["inspect"], ("Missing option '--urdf'", "rhi-gen inspect --help")),
])
def test_usage_errors_are_one_line(tmp_path, args, words):
    result = run_cli(*args)
    assert result.code == 2 and result.out == ""
    lines = result.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and " -> " in lines[0], result.err
    for word in words:
        assert word in lines[0]


@pytest.mark.parametrize("args, line", [
    (["new", "--vendor", "acme"], "error: Missing option '--robot' -> see `rhi-gen new --help`"),
    (["new", "--forc"], "error: No such option: --forc (Possible options: --force) -> see `rhi-gen new --help`"),
    (["frobnicate"], "error: No such command 'frobnicate' -> see `rhi-gen --help`"),
    (["chek"], "error: No such command 'chek'. Did you mean 'check'? -> see `rhi-gen --help`"),
    (["inspect", "--urdf"], "error: Option '--urdf' requires an argument -> see `rhi-gen inspect --help`"),
    (["check", "-C"], "error: Option '-C' requires an argument -> see `rhi-gen check --help`"),
    (["check", "extra"], "error: Got unexpected extra argument(s) (extra) -> see `rhi-gen check --help`"),
    (["generate", "--dry-run=yes"], "error: Option '--dry-run' does not take a value -> see `rhi-gen generate --help`"),
    (["check", "--version"], "error: No such option: --version -> see `rhi-gen check --help`"),
])
def test_click_usage_errors_are_exactly_one_line(args, line):
    """Click's own errors (missing option, unknown option or command, an option without its value, an extra
    argument), not its "Usage: ... Try ... Error: ..." block: the one line, exit 2, nothing on stdout."""
    result = run_cli(*args)
    assert (result.code, result.out, result.err) == (2, "", line + "\n")


def test_rhi_gen_alone_prints_the_help_and_exits_2():
    result = run_cli()
    assert result.code == 2 and result.err == ""
    assert result.out.startswith("Usage: rhi-gen [OPTIONS] COMMAND [ARGS]...") and "Commands:" in result.out


def test_several_blocked_files_list_on_stdout_and_fail_in_one_line(three_robots):
    package = three_robots / "generated/robot_hardware_interface"
    for rel in ("src/acme/arm.cpp", "src/acme/wheel.cpp"):
        path = package / rel
        path.write_text(path.read_text() + "// hand edit\n")
    for robot in ("arm", "wheel"):  # both drivers would change
        path = three_robots / "robots" / "acme" / f"{robot}.yaml"
        path.write_text(path.read_text() + "parameters:\n  state_decimation: 4\n" if robot == "arm" else
                        path.read_text().replace("state_decimation: 1", "state_decimation: 4"))
    before = snapshot(three_robots)
    result = run_cli("generate", "--project", three_robots)
    assert result.code == 2 and "Traceback" not in result.err
    (message,) = result.err.splitlines()
    assert message.startswith("error: 2 generated files hold hand-written code") and " -> " in message
    assert "src/acme/arm.cpp" in message and "src/acme/wheel.cpp" in message and "--force" in message
    reason = "edited outside its user regions since the last `rhi-gen generate`"
    assert [line for line in result.out.splitlines() if line.startswith("blocked: ")] == [
        f"blocked: generated/robot_hardware_interface/src/acme/arm.cpp: {reason}",
        f"blocked: generated/robot_hardware_interface/src/acme/wheel.cpp: {reason}"]
    assert snapshot(three_robots) == before
