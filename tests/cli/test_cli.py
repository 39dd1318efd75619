"""The commands as a user runs them: new, inspect, list, help, shell completion and exit codes."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

from rhi_gen.cli import main
from rhi_gen.transports.unitree_dds.known_robots import G1_ORDER
from tests.support import upstream_urdf
from tests.support.cpp_build import syntax_check_driver
from tests.support.repo import REPO, copy_project
from tests.support.repo import URDF_FIXTURES as FIXTURES

UPSTREAM_G1 = upstream_urdf.find("unitree_g1.urdf")  # the repository's copy (tests/data/upstream_urdf)


def run(args: list[str], capsys) -> tuple[int, str, str]:
    code = main(args)
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
def test_new_on_upstream_g1_uses_the_sdk_order_and_compiles(tmp_path, capsys):
    assert UPSTREAM_G1 is not None, "tests/data/upstream_urdf/unitree_g1.urdf is missing"
    code, _, err = run(["new", "--vendor", "unitree", "--robot", "g1", "--urdf", str(UPSTREAM_G1),
                          "--project", str(tmp_path)], capsys)
    assert code == 0, err
    data = yaml.safe_load((tmp_path / "robots/unitree/g1.yaml").read_text())
    assert data["transport"] == "unitree_dds" and data["float_type"] == "float" and data["motor_count"] == 29
    assert list(data["joint_map"]) == list(G1_ORDER)
    assert list(data["joint_map"].values()) == list(range(29))
    package = tmp_path / "generated/robot_hardware_interface"
    assert (package / "src/unitree/g1.cpp").is_file()
    syntax_check_driver(package, "unitree", "g1")
    # The package it wrote is exactly what generate writes: no hand edit needed.
    assert run(["check", "--project", str(tmp_path)], capsys)[0] == 0


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
def test_new_on_an_unknown_robot_uses_generic_transport_and_compiles(tmp_path, capsys):
    code, out, err = run(["new", "--vendor", "acme", "--robot", "gripper", "--urdf",
                          str(FIXTURES / "mimic_gripper.urdf"), "--project", str(tmp_path)], capsys)
    assert code == 0, err
    data = yaml.safe_load((tmp_path / "robots/acme/gripper.yaml").read_text())
    assert data["transport"] == "generic_topics"
    # mimic joints never get a motor
    assert set(data["joint_map"]) == {"wrist", "left_finger_joint"}
    syntax_check_driver(tmp_path / "generated/robot_hardware_interface", "acme", "gripper")
    assert "wrote robots/acme/gripper.yaml" in out


def test_new_refuses_to_overwrite_and_leaves_everything(tmp_path, capsys):
    args = ["new", "--vendor", "acme", "--robot", "arm", "--urdf", str(FIXTURES / "simple_arm.urdf"),
            "--project", str(tmp_path)]
    assert run(args, capsys)[0] == 0
    yml = tmp_path / "robots/acme/arm.yaml"
    yml.write_text(yml.read_text().replace("state_decimation: 1", "state_decimation: 3"))
    code, _, err = run(args, capsys)
    assert code == 2 and "already exists" in err and "--force" in err
    assert "state_decimation: 3" in yml.read_text()
    assert run([*args, "--force"], capsys)[0] == 0
    assert "state_decimation: 1" in yml.read_text()


@pytest.mark.parametrize("vendor, robot, words", [
    ("../x", "arm", "lowercase"), ("acme", "/abs", "lowercase"), ("class", "arm", "C++ keyword"),
    ("acme", "int", "C++ keyword"), ("acme", "Arm", "lowercase"),
])
def test_new_rejects_unsafe_names_before_writing(tmp_path, capsys, vendor, robot, words):
    code, _, err = run(["new", "--vendor", vendor, "--robot", robot, "--urdf", str(FIXTURES / "simple_arm.urdf"),
                          "--project", str(tmp_path)], capsys)
    assert code == 2 and words in err and err.count("\n") == 1
    assert not (tmp_path / "robots").exists() and not (tmp_path / "generated").exists()


def test_new_with_unknown_transport_suggests(tmp_path, capsys):
    code, _, err = run(["new", "--vendor", "acme", "--robot", "arm", "--urdf", str(FIXTURES / "simple_arm.urdf"),
                        "--transport", "generic_topic", "--project", str(tmp_path)], capsys)
    assert code == 2 and "did you mean 'generic_topics'" in err


def test_inspect_lists_joints_and_suggests_a_map(capsys):
    code, out, err = run(["inspect", "--urdf", str(FIXTURES / "mimic_gripper.urdf")], capsys)
    assert code == 0, err
    assert "mimics left_finger_joint" in out
    assert "suggested joint_map" in out and "  wrist: 0" in out


def test_inspect_with_vendor_profile_orders_like_the_sdk(capsys):
    code, out, _ = run(["inspect", "--urdf", str(REPO / "robots/agibot/x2.urdf"), "--vendor", "agibot",
                        "--robot", "x2"], capsys)
    assert code == 0
    suggested = out.split("suggested joint_map")[1].splitlines()[1:]
    assert suggested[12].strip() == "waist_yaw_joint: 12" and suggested[15].strip() == "left_shoulder_pitch_joint: 15"


def test_inspect_missing_file_is_exit_2(tmp_path, capsys):
    code, _, err = run(["inspect", "--urdf", str(tmp_path / "none.urdf")], capsys)
    assert code == 2 and "none.urdf" in err and err.count("\n") == 1


def test_list_and_version(capsys):
    code, out, _ = run(["list", "--project", str(REPO)], capsys)
    assert code == 0 and "unitree/g1" in out and "agibot/x2" in out and "engineai/pm01" in out
    code, out, _ = run(["--version"], capsys)
    assert code == 0 and out.startswith("rhi-gen ")


def test_console_script_help_and_usage_errors():
    exe = Path(sys.executable).with_name("rhi-gen")
    help_run = subprocess.run([str(exe), "--help"], capture_output=True, text=True)
    assert help_run.returncode == 0 and "generate" in help_run.stdout and "Traceback" not in help_run.stderr
    bad = subprocess.run([str(exe), "frobnicate"], capture_output=True, text=True)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr
    missing = subprocess.run([str(exe), "new", "--vendor", "x"], capture_output=True, text=True)
    assert missing.returncode == 2 and "Traceback" not in missing.stderr


BIN = Path(sys.executable).parent  # where the console script rhi-gen is installed


def in_bash(script: str, **env: str) -> subprocess.CompletedProcess[str]:
    """``script`` run by bash, as a user's shell runs it: typer detects the shell from the processes above it."""
    return subprocess.run(["bash", "-c", script], capture_output=True, text=True,
                          env={**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ['PATH']}", **env})


def test_bash_completion_script_completes_commands_and_options():
    shown = in_bash("rhi-gen --show-completion bash")
    assert shown.returncode == 0 and shown.stderr == ""
    assert "_RHI_GEN_COMPLETE=complete_bash $1" in shown.stdout
    assert shown.stdout.rstrip().endswith("complete -o default -F _rhi_gen_completion rhi-gen")
    # bash with the script loaded, asked to complete what a user typed
    complete = ('eval "$(rhi-gen --show-completion bash)"; COMP_WORDS=({words}); COMP_CWORD={cword}; '
                '_rhi_gen_completion rhi-gen; printf "%s\\n" "${{COMPREPLY[@]}}"')
    assert in_bash(complete.format(words="rhi-gen ch", cword=1)).stdout.split() == ["check"]
    assert in_bash(complete.format(words="rhi-gen check --pr", cword=2)).stdout.split() == ["--project"]
    assert in_bash(complete.format(words="rhi-gen generate --dr", cword=2)).stdout.split() == ["--dry-run"]


def test_completion_protocol_answers_without_a_shell():
    """What the script asks rhi-gen: the words so far in COMP_WORDS, the one to complete in COMP_CWORD."""
    env = {**os.environ, "_RHI_GEN_COMPLETE": "complete_bash", "COMP_WORDS": "rhi-gen ch", "COMP_CWORD": "1"}
    answer = subprocess.run([str(BIN / "rhi-gen")], capture_output=True, text=True, env=env)
    assert (answer.returncode, answer.stdout, answer.stderr) == (0, "check\n", "")


def test_install_completion_writes_the_script_and_sources_it(tmp_path):
    installed = in_bash("rhi-gen --install-completion bash", HOME=str(tmp_path))
    assert installed.returncode == 0, installed.stderr
    script = tmp_path / ".bash_completions/rhi-gen.sh"
    assert f"source '{script}'" in (tmp_path / ".bashrc").read_text()
    assert script.read_text() == in_bash("rhi-gen --show-completion bash").stdout.rstrip("\n")


# Runs the command given after it with no terminal and no shell among its ancestors, as nohup, setsid or a job
# runner can: forks, and the child waits until it is orphaned (reparented away from this process), starts
# a session of its own, then runs the command through nohup with stdin from /dev/null and prints its exit code.
DETACHED = """
import os, subprocess, sys, time
me = os.getpid()
if os.fork():
    os._exit(0)
while os.getppid() == me:
    time.sleep(0.01)
os.setsid()
code = subprocess.call(["nohup", *sys.argv[1:]], stdin=subprocess.DEVNULL, stderr=subprocess.STDOUT)
print(f"exit {code}", flush=True)
"""


def detached(*args: str, home: Path) -> list[str]:
    """``rhi-gen ARGS`` with no shell above it (see DETACHED), SHELL unset: the lines it printed, then its exit code."""
    env = {k: v for k, v in os.environ.items() if k != "SHELL"}
    done = subprocess.run([sys.executable, "-c", DETACHED, str(BIN / "rhi-gen"), *args], stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, env={**env, "HOME": str(home)}, timeout=120)
    return done.stdout.splitlines()  # read to the end of the pipe: the orphan holds it until it exits


@pytest.mark.skipif(shutil.which("nohup") is None, reason="needs nohup")
def test_completion_for_a_named_shell_needs_no_shell_parent(tmp_path):
    """`--show-completion bash` and `--install-completion bash` name the shell: no detection, whatever the parent."""
    shown = detached("--show-completion", "bash", home=tmp_path)
    assert shown[-1] == "exit 0" and "_RHI_GEN_COMPLETE=complete_bash $1" in "\n".join(shown), shown
    assert shown[-2] == "complete -o default -F _rhi_gen_completion rhi-gen"
    installed = detached("--install-completion", "bash", home=tmp_path)
    assert installed[-1] == "exit 0", installed
    script = tmp_path / ".bash_completions/rhi-gen.sh"
    assert f"source '{script}'" in (tmp_path / ".bashrc").read_text()
    assert script.read_text().splitlines() == shown[:-1]


def test_check_with_nothing_changed_loads_and_renders_nothing(tmp_path):
    """`rhi-gen check` runs as a pre-commit hook: with nothing changed since the last check that passed, it
    answers from that check's memo (rhi_gen/pipeline/verified.py), importing neither the loaders (PyYAML,
    lxml, xacro), the model nor the renderer (Jinja), and never rich (help is plain text).

    pydantic is imported: typer 0.29 converts every option value through a pydantic TypeAdapter, and its
    public API has no way to declare an option without one (its parser= runs inside that adapter too).
    """
    project = copy_project(tmp_path / "proj", generated=True)
    past = time.time() - 3600  # settled files: the memo skips those written while a check may read them
    for path in project.rglob("*"):
        os.utime(path, (past, past))
    env = {**os.environ, "RHI_GEN_CACHE": str(tmp_path / "cache")}
    probe = ("import sys; from rhi_gen.cli import main; code = main(['check', '--project', sys.argv[1]]); "
             "print(code, sorted({m for m in sys.modules if m.split('.')[0] in "
             "('yaml', 'lxml', 'xacro', 'jinja2', 'rich') or m.startswith(('rhi_gen.model', 'rhi_gen.render', "
             "'rhi_gen.inputs', 'rhi_gen.assemble'))}))")
    first = subprocess.run([sys.executable, "-c", probe, str(project)], capture_output=True, text=True, env=env)
    assert first.returncode == 0 and "'yaml'" in first.stdout.splitlines()[-1], first.stdout + first.stderr
    again = subprocess.run([sys.executable, "-c", probe, str(project)], capture_output=True, text=True, env=env)
    assert again.returncode == 0 and again.stdout.splitlines()[-1] == "0 []", again.stdout + again.stderr


def test_generate_with_no_robots_is_a_clear_error(tmp_path, capsys):
    code, _, err = run(["generate", "--project", str(tmp_path)], capsys)
    assert code == 2 and "no robots found" in err and "rhi-gen new" in err


def test_diff_into_a_reader_that_stops_early_ends_quietly(robots_project):
    """`rhi-gen diff | head`: the reader closes the pipe after a line; rhi-gen stops as a command killed by
    SIGPIPE does (141), with no traceback or 'internal error' on stderr."""
    exe = BIN / "rhi-gen"
    proc = subprocess.Popen([str(exe), "diff", "-C", str(robots_project)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    assert proc.stdout is not None and proc.stderr is not None
    assert proc.stdout.readline()  # nothing generated yet: the diff has many lines, the reader takes one
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=600) == 141, err
    assert err == ""
