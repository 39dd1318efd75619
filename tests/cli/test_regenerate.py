"""Regenerating after URDF changes: hand edits survive or block, diffs speak robot, nothing half-written.

Every test runs the real CLI (rhi_gen.cli.main) on a copy of the repository's robots/ in tmp_path and
compares whole trees byte for byte.
"""
from __future__ import annotations

import difflib
import errno
import os
import pty
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import jinja2
import pytest
import yaml

from rhi_gen.errors import WriteError
from rhi_gen.pipeline import generate as pipeline_generate
from rhi_gen.pipeline.load import load_robots
from rhi_gen.project import find_project
from rhi_gen.render import environment as render_environment
from rhi_gen.render.markers import REGION_BEGIN, REGION_END
from rhi_gen.render.package import render_package
from rhi_gen.write import transaction
from rhi_gen.write.regions import region_bodies
from tests.support.cli import cli, tree
from tests.support.repo import REPO

PKG = "generated/robot_hardware_interface"
G1_FILES = {f"{PKG}/include/robot_hardware_interface/unitree/g1.hpp", f"{PKG}/src/unitree/g1.cpp",
            f"{PKG}/description/g1.ros2_control.xacro", f"{PKG}/config/g1_controllers.yaml",
            f"{PKG}/test/test_g1_hardware_interface.cpp", f"{PKG}/urdf/g1.urdf", f"{PKG}/description/g1.urdf.xacro",
            f"{PKG}/launch/g1.launch.py", f"{PKG}/src/unitree/g1_fake_robot.cpp"}
# The bring-up files name no joint: a joint rename leaves them as they are.
G1_BRINGUP = {f"{PKG}/description/g1.urdf.xacro", f"{PKG}/launch/g1.launch.py"}
MANIFEST = "generated/.rhi-gen-manifest"
G1_CPP, G1_HPP, CMAKE = f"{PKG}/src/unitree/g1.cpp", f"{PKG}/include/robot_hardware_interface/unitree/g1.hpp", \
    f"{PKG}/CMakeLists.txt"


# ---------------------------------------------------------------- helpers
def rename_joint(root: Path, old: str = "left_knee_joint", new: str = "left_knee_pitch_joint") -> None:
    urdf = root / "robots/unitree/g1.urdf"
    text = urdf.read_text()
    assert text.count(f'name="{old}"') == 1
    urdf.write_text(text.replace(f'name="{old}"', f'name="{new}"'))
    yml = root / "robots/unitree/g1.yaml"
    text, n = re.subn(rf"^  {old}:", f"  {new}:", yml.read_text(), flags=re.M)
    assert n == 5  # its joint_map, default_gains, initial_positions, joint_damping and joint_frictionloss entries
    yml.write_text(text)


def set_limit(root: Path, joint: str, attr: str, value: str) -> None:
    urdf = root / "robots/unitree/g1.urdf"
    text = urdf.read_text()
    start = text.index(f'<joint name="{joint}"')
    end = text.index("</joint>", start)
    block = re.sub(rf'{attr}="[^"]*"', f'{attr}="{value}"', text[start:end], count=1)
    urdf.write_text(text[:start] + block + text[end:])


def set_yaml(root: Path, key: str, value: str) -> None:
    yml = root / "robots/unitree/g1.yaml"
    text, n = re.subn(rf"^{key}: .*$", f"{key}: {value}", yml.read_text(), flags=re.M)
    assert n == 1
    yml.write_text(text)


def fill_region(path: Path, name: str, body: str) -> None:
    text = path.read_text()
    lines = text.splitlines(keepends=True)
    begin = next(i for i, line in enumerate(lines) if line.strip().endswith(f"{REGION_BEGIN} {name}"))
    end = next(i for i, line in enumerate(lines) if line.strip().endswith(f"{REGION_END} {name}"))
    path.write_text("".join(lines[:begin + 1]) + body + "".join(lines[end:]))


def changed_lines(old: bytes, new: bytes) -> list[str]:
    return [line for line in difflib.unified_diff(old.decode().splitlines(), new.decode().splitlines(), lineterm="")
            if line[:1] in "+-" and not line.startswith(("+++", "---"))]


# ---------------------------------------------------------------- rename: diff, then a minimal regeneration
def test_renamed_joint_is_one_rename_and_touches_only_its_lines(project, capsys):
    before = tree(project)
    rename_joint(project)

    code, out, err = cli(capsys, project, "diff", "g1")
    assert code == 1
    robot_lines = out.split("\n\n", 1)[0].splitlines()
    assert robot_lines == ["unitree/g1: robots/unitree/g1.yaml changed, robots/unitree/g1.urdf changed",
                           "  renamed     joint 3: left_knee_joint -> left_knee_pitch_joint"]
    assert "\x1b[" not in out  # captured output is not a terminal: plain text
    assert "+++ b/generated/robot_hardware_interface/src/unitree/g1.cpp" in out
    # the header holds no joint names (the joint table is in the source), nor do the description and the
    # launch file: 6 of the robot's 9 files (the installed URDF copy is one, the fake robot's table another)
    assert "6 file(s) and generated/.rhi-gen-manifest would change" in err
    assert tree(project) == {**before, **{k: v for k, v in tree(project).items() if k.startswith("robots/")}}

    code, out, _ = cli(capsys, project, "generate")
    assert code == 0
    after = tree(project)
    changed = {k for k in after if after[k] != before.get(k)} | {k for k in before if k not in after}
    assert changed == (G1_FILES - {G1_HPP} - G1_BRINGUP) | {MANIFEST, "robots/unitree/g1.urdf",
                                                             "robots/unitree/g1.yaml"}
    for rel in G1_FILES - {G1_HPP} - G1_BRINGUP:
        lines = changed_lines(before[rel], after[rel])
        assert lines, rel
        for line in lines:
            continuation = line[1:].startswith("    ") and '"' not in line  # the rest of the joint's table row
            assert ("left_knee_joint" in line if line[0] == "-" else "left_knee_pitch_joint" in line) \
                or "Generated by rhi-gen" in line or continuation, (rel, line)
        assert len(before[rel].splitlines()) == len(after[rel].splitlines())
    # the manifest diff is the rename plus the hashes
    manifest_lines = changed_lines(before[MANIFEST], after[MANIFEST])
    assert '-        [3, "left_knee_joint", "revolute", -0.087267, 2.8798, 20.0, 139.0],' in manifest_lines
    assert '+        [3, "left_knee_pitch_joint", "revolute", -0.087267, 2.8798, 20.0, 139.0],' in manifest_lines
    assert cli(capsys, project, "check")[0] == 0
    assert cli(capsys, project, "diff")[0] == 0


def test_diff_reports_limits_remap_motor_count_and_float_type(project, capsys):
    set_limit(project, "left_hip_pitch_joint", "upper", "2.5")
    yml = project / "robots/unitree/g1.yaml"
    text = yml.read_text().replace("  waist_roll_joint: 13\n", "  waist_roll_joint: 14\n") \
        .replace("  waist_pitch_joint: 14\n", "  waist_pitch_joint: 13\n")
    yml.write_text(text)
    set_yaml(project, "motor_count", "30")
    code, out, _ = cli(capsys, project, "diff")
    assert code == 1
    head = out.split("\n\n", 1)[0].splitlines()
    assert head == [
        "agibot/x2: inputs unchanged",
        "engineai/pm01: inputs unchanged",
        "unitree/g1: robots/unitree/g1.yaml changed, robots/unitree/g1.urdf changed",
        "  remapped    joint waist_pitch_joint: index 14 -> 13",
        "  remapped    joint waist_roll_joint: index 13 -> 14",
        "  limits      joint 0 left_hip_pitch_joint: upper 2.8798 -> 2.5",
        "  motor_count 29 -> 30",
    ]


def test_float_type_change_is_reported(project, capsys):
    yml = project / "robots/engineai/pm01.yaml"
    text, n = re.subn(r"^float_type: double$", "float_type: float", yml.read_text(), flags=re.M)
    assert n == 1
    yml.write_text(text)
    code, out, _ = cli(capsys, project, "diff", "pm01")
    assert code == 1
    assert out.splitlines()[:2] == ["engineai/pm01: robots/engineai/pm01.yaml changed",
                                    "  float_type  double -> float"]


# ---------------------------------------------------------------- user regions
def test_user_region_edits_survive_three_regenerations(project, capsys):
    bodies = {
        (G1_CPP, "includes"): "// hand-written: the vendor's warm-up helper\n#include <vendor/warm_up.hpp>\n",
        (G1_CPP, "callbacks"): "static void on_fault(int code) {  \t// odd spacing kept\n  (void)code;\n}\n\n",
        (G1_HPP, "members"): "  int fault_count_{0};  // µ-controller faults\n",
        (CMAKE, "dependencies"): "# our extra package\nfind_package(vendor_tools QUIET)\n",
        (f"{PKG}/config/g1_controllers.yaml", "controller_parameters"): "my_controller:\n  ros__parameters: {}\n",
    }
    for (rel, name), body in bodies.items():
        fill_region(project / rel, name, body)
    assert cli(capsys, project, "check")[0] == 0  # region edits are not hand edits
    edits = [lambda: rename_joint(project),
             lambda: set_limit(project, "left_hip_pitch_joint", "upper", "2.75"),
             lambda: set_yaml(project, "motor_count", "30")]
    previous = tree(project)
    for round_, edit in enumerate(edits, start=1):
        edit()
        code, _, err = cli(capsys, project, "generate")
        assert code == 0, err
        now = tree(project)
        # Every edit changes the driver source; the header only when its content does (banners carry no hashes).
        # the joint table is in the source, the motor count in the header
        assert now[G1_CPP] != previous[G1_CPP] or now[G1_HPP] != previous[G1_HPP], round_
        for (rel, name), body in bodies.items():
            assert region_bodies(now[rel].decode())[name] == body, (round_, rel, name)
        assert cli(capsys, project, "check")[0] == 0
        previous = now


def test_edit_outside_a_region_blocks_generate_and_changes_nothing(project, capsys):
    hpp = project / G1_HPP
    guard = "#define ROBOT_HARDWARE_INTERFACE__UNITREE__G1_HPP_\n"
    assert guard in hpp.read_text()
    hpp.write_text(hpp.read_text().replace(guard, guard + "#include <my_hack.hpp>\n", 1))
    fill_region(project / G1_CPP, "includes", "#include <vendor/warm_up.hpp>\n")
    rename_joint(project)
    before = tree(project)
    code, out, err = cli(capsys, project, "generate")
    assert code == 2
    assert tree(project) == before
    assert out == ""
    assert f"error: {G1_HPP}: edited outside its user regions" in err
    assert "nothing was written" in err
    assert "move the edit into a user region" in err and "--force" in err and ".rhi-gen-backup" in err
    # the same refusal for one robot and for a dry run; check and diff show the edit
    assert cli(capsys, project, "generate", "g1")[0] == 2
    assert cli(capsys, project, "generate", "--dry-run")[0] == 2
    code, out, err = cli(capsys, project, "check")
    assert code == 1 and f"hand edit: {G1_HPP}: edited outside its user regions" in out
    assert "-#include <my_hack.hpp>" in out
    code, out, err = cli(capsys, project, "diff", "g1")
    assert code == 1 and "would refuse" in err
    assert tree(project) == before


def test_several_blocked_files_are_all_listed(project, capsys):
    for rel in (G1_HPP, CMAKE):
        (project / rel).write_text((project / rel).read_text() + "# appended by hand\n")
    rename_joint(project)
    before = tree(project)
    code, out, err = cli(capsys, project, "generate")
    assert code == 2 and tree(project) == before
    # each file and its reason on stdout; stderr is the one error line naming both
    assert f"blocked: {G1_HPP}: edited outside" in out and f"blocked: {CMAKE}: edited outside" in out
    assert err.count("\n") == 1 and "2 generated files hold hand-written code" in err
    assert G1_HPP in err and CMAKE in err


def test_force_overwrites_and_keeps_numbered_backups(project, capsys):
    hpp = project / G1_HPP
    clean = hpp.read_bytes()
    guard = b"#define ROBOT_HARDWARE_INTERFACE__UNITREE__G1_HPP_\n"
    assert guard in clean
    edited = clean.replace(guard, guard + b"// first hand edit\n", 1)
    hpp.write_bytes(edited)
    fill_region(project / G1_CPP, "callbacks", "void keep_me() {}\n")
    code, out, _ = cli(capsys, project, "generate", "--force")
    assert code == 0
    backup_dir = project / "generated/.rhi-gen-backup"
    backup = backup_dir / "robot_hardware_interface/include/robot_hardware_interface/unitree/g1.hpp.1"
    assert backup.read_bytes() == edited
    kept = ("kept your version of robot_hardware_interface/include/robot_hardware_interface/unitree/g1.hpp in "
            "generated/.rhi-gen-backup/robot_hardware_interface/include/robot_hardware_interface/unitree/g1.hpp.1")
    assert kept in out
    assert hpp.read_bytes() == clean
    assert region_bodies((project / G1_CPP).read_text())["callbacks"] == "void keep_me() {}\n"
    # colcon and git leave the backups alone; nothing of them is inside the package
    assert (backup_dir / "COLCON_IGNORE").is_file() and (backup_dir / ".gitignore").read_text().endswith("*\n")
    assert not [p for p in (project / PKG).rglob("*") if ".rhi-" in p.name or p.name.endswith(".1")]
    assert cli(capsys, project, "check")[0] == 0
    # a second forced overwrite gets the next number; the first backup stays
    second = clean.replace(guard, guard + b"// second hand edit\n", 1)
    hpp.write_bytes(second)
    assert cli(capsys, project, "generate", "--force")[0] == 0
    assert backup.read_bytes() == edited
    assert backup.with_name("g1.hpp.2").read_bytes() == second
    # --force without anything blocked makes no backup
    assert cli(capsys, project, "generate", "--force")[0] == 0
    assert not backup.with_name("g1.hpp.3").exists()


def test_region_the_template_dropped_is_refused_not_lost(project, capsys, monkeypatch):
    fill_region(project / G1_CPP, "callbacks", "void precious() {}\n")
    original = render_package  # the function rhi_gen.pipeline.generate calls, before the patch

    def without_callbacks(models, **kwargs):
        out = original(models, **kwargs)
        text = out["src/unitree/g1.cpp"]
        out["src/unitree/g1.cpp"] = re.sub(rf"// {REGION_BEGIN} callbacks\n// {REGION_END} callbacks\n", "", text)
        return out

    monkeypatch.setattr(pipeline_generate, "render_package", without_callbacks)
    before = tree(project)
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and tree(project) == before
    assert re.search(rf"{G1_CPP}:\d+: user region 'callbacks' \(line \d+\) holds code but the new template has no "
                     "such region", err)
    assert cli(capsys, project, "generate", "--force")[0] == 0
    backup = project / "generated/.rhi-gen-backup/robot_hardware_interface/src/unitree/g1.cpp.1"
    assert "void precious() {}" in backup.read_text()


def test_removed_robot_with_user_code_is_refused(project, capsys):
    fill_region(project / G1_CPP, "callbacks", "void arm_brakes() {}\n")
    (project / "robots/unitree/g1.yaml").unlink()
    before = tree(project)
    code, out, err = cli(capsys, project, "diff")
    assert code == 1 and "unitree/g1: robot removed" in out and "would refuse" in err
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and tree(project) == before
    assert "user region 'callbacks'" in err and "no longer generated" in err
    assert cli(capsys, project, "generate", "--force")[0] == 0
    assert not (project / G1_CPP).exists() and not (project / G1_HPP).exists()
    backup = project / "generated/.rhi-gen-backup/robot_hardware_interface/src/unitree/g1.cpp.1"
    assert "void arm_brakes() {}" in backup.read_text()
    assert cli(capsys, project, "check")[0] == 0


def test_removed_robot_without_user_code_is_removed(project, capsys):
    (project / "robots/unitree/g1.yaml").unlink()
    code, out, _ = cli(capsys, project, "generate")
    assert code == 0 and "16 removed" in out  # 9 robot files + the 7 unitree transport headers
    assert not any((project / rel).exists() for rel in G1_FILES)
    assert not (project / f"{PKG}/src/unitree").exists()
    for header in ("unitree_crc.hpp", "unitree_hg.hpp", "unitree_go.hpp", "unitree_dds.hpp"):
        assert not (project / f"{PKG}/include/robot_hardware_interface/transport/{header}").exists()


def test_broken_marker_is_reported_with_file_and_line(project, capsys):
    cpp = project / G1_CPP
    lines = cpp.read_text().splitlines(keepends=True)
    end = next(i for i, line in enumerate(lines) if line.strip() == f"// {REGION_END} includes")
    begin = next(i for i, line in enumerate(lines) if line.strip() == f"// {REGION_BEGIN} includes")
    nested = next(i for i, line in enumerate(lines) if line.strip() == f"// {REGION_BEGIN} callbacks")
    cpp.write_text("".join(lines[:end] + lines[end + 1:]))
    before = tree(project)
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and tree(project) == before
    assert f"error: {G1_CPP}:{nested}: region 'callbacks' begins inside region 'includes' (line {begin + 1})" \
        in err
    assert "restore the marker lines" in err
    assert cli(capsys, project, "check")[0] == 1
    # the last region left open
    last = next(i for i, line in enumerate(lines) if line.strip() == f"// {REGION_END} callbacks")
    begin = next(i for i, line in enumerate(lines) if line.strip() == f"// {REGION_BEGIN} callbacks")
    cpp.write_text("".join(lines[:last] + lines[last + 1:]))
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and f"{G1_CPP}:{begin + 1}: region 'callbacks' is never closed" in err
    # --force rewrites it (keeping a backup)
    assert cli(capsys, project, "generate", "--force")[0] == 0
    assert cli(capsys, project, "check")[0] == 0


def test_files_without_a_manifest_record_are_not_overwritten_blindly(project, capsys):
    (project / MANIFEST).unlink()
    code, out, _ = cli(capsys, project, "check")
    assert code == 1 and "stale: generated/.rhi-gen-manifest is missing" in out
    # nothing but the manifest would change: generate just records the tree
    code, out, _ = cli(capsys, project, "generate")
    assert code == 0 and "created   .rhi-gen-manifest" in out and "0 changed" in out
    (project / MANIFEST).unlink()
    rename_joint(project)
    before = tree(project)
    code, out, err = cli(capsys, project, "generate")
    assert code == 2 and tree(project) == before
    # each unrecorded file and why on stdout, the one error line on stderr
    assert "there is no generated/.rhi-gen-manifest" in out and err.count("\n") == 1 and "--force" in err


# ---------------------------------------------------------------- check: stale inputs as well as file diffs
def test_check_reports_stale_inputs_and_file_differences(project, capsys):
    assert cli(capsys, project, "check")[:2] == (0, "generated/ is up to date (3 robots)\n")
    rename_joint(project)
    code, out, err = cli(capsys, project, "check")
    assert code == 1
    assert out.startswith("stale: unitree/g1: robots/unitree/g1.yaml changed, robots/unitree/g1.urdf changed\n"
                          "  renamed     joint 3: left_knee_joint -> left_knee_pitch_joint\n")
    assert "+++ b/generated/robot_hardware_interface/src/unitree/g1.cpp" in out
    assert "1 robot(s) with changed inputs, 6 file(s) differ" in err


def test_check_catches_a_stale_manifest_even_when_files_match(project, capsys):
    manifest = project / MANIFEST
    text = manifest.read_text()
    found = re.search(r'"path": "robots/unitree/g1.yaml", "sha256": "([0-9a-f]{64})"', text)
    assert found is not None, text
    g1_yaml_hash = found.group(1)
    manifest.write_text(text.replace(g1_yaml_hash, "0" * 64))
    code, out, _ = cli(capsys, project, "check")
    assert code == 1 and out.startswith("stale: unitree/g1: robots/unitree/g1.yaml changed\n")


def test_generate_one_robot_keeps_the_others_stale(project, capsys):
    rename_joint(project)
    x2 = project / "robots/agibot/x2.yaml"
    # A real change (a comment no longer counts: the manifest fingerprints the YAML's content).
    x2.write_text(x2.read_text() + "parameters:\n  state_decimation: 2\n")
    assert cli(capsys, project, "generate", "g1")[0] == 0
    code, out, _ = cli(capsys, project, "check")
    assert code == 1 and out.startswith("stale: agibot/x2: robots/agibot/x2.yaml changed\n")
    assert "unitree/g1" not in out
    assert cli(capsys, project, "generate")[0] == 0
    assert cli(capsys, project, "check")[0] == 0


def test_new_robot_carries_shared_regions_and_records_itself(project, capsys):
    fill_region(project / CMAKE, "targets", "# our own target\n")
    code, _, err = cli(capsys, project, "new", "--vendor", "acme", "--robot", "arm", "--urdf",
                         str(project / "robots/engineai/pm01.urdf"))
    assert code == 0, err
    assert region_bodies((project / CMAKE).read_text())["targets"] == "# our own target\n"
    assert '"acme/arm"' in (project / MANIFEST).read_text()
    assert cli(capsys, project, "check")[0] == 0


def test_pre_commit_hook_definition():
    hooks = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text())
    hook = next(h for h in hooks if h["id"] == "rhi-gen-check")
    assert hook["entry"] == "rhi-gen check" and hook["pass_filenames"] is False and hook["language"] == "python"


# ---------------------------------------------------------------- atomicity
def test_template_error_halfway_writes_nothing(project, capsys, monkeypatch):
    rename_joint(project)
    set_limit(project, "left_knee_pitch_joint", "effort", "150")
    before = tree(project)
    rendered: list[str] = []

    def broken_env():
        env = render_environment.make_environment()
        broken = jinja2.DictLoader({"templates/robot/test.cpp.j2": "{{ robot.no_such_field }}"})
        assert env.loader is not None
        env.loader = jinja2.ChoiceLoader([broken, env.loader])
        real = env.get_template

        def recording_get_template(name, *args, **kwargs):
            rendered.append(name)
            return real(name, *args, **kwargs)

        monkeypatch.setattr(env, "get_template", recording_get_template)
        return env

    original = render_package  # the function rhi_gen.pipeline.generate calls, before the patch
    monkeypatch.setattr(pipeline_generate, "render_package",
                        lambda models, **kwargs: original(models, env_factory=broken_env, **kwargs))
    code, _, err = cli(capsys, project, "generate")
    assert code == 2
    assert "template templates/robot/test.cpp.j2 failed" in err and "no_such_field" in err
    assert len(rendered) > 8 and rendered[-1] == "templates/robot/test.cpp.j2"  # halfway: the package and a driver done
    assert tree(project) == before
    # on a fresh project too: no generated/ folder appears
    shutil.rmtree(project / "generated")
    before = tree(project)
    assert cli(capsys, project, "generate")[0] == 2
    assert tree(project) == before and not (project / "generated").exists()


def test_bad_yaml_changes_nothing(project, capsys):
    rename_joint(project)
    (project / "robots/engineai/pm01.yaml").write_text("vendor: engineai\nrobot: pm01\n  bad: indent\n")
    before = tree(project)
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and err.strip().splitlines()[-1].startswith("error: robots/engineai/pm01.yaml:")
    assert tree(project) == before


def _big_change(project: Path, capsys) -> None:
    """A regeneration that changes, creates, removes and backs up files (with a region to carry)."""
    fill_region(project / G1_CPP, "includes", "#include <vendor/warm_up.hpp>\n")
    x2 = project / f"{PKG}/include/robot_hardware_interface/agibot/x2.hpp"
    x2.write_text(x2.read_text() + "// hand edit, forced away\n")
    rename_joint(project)
    text = (project / "robots/unitree/g1.yaml").read_text()
    (project / "robots/unitree/g1b.yaml").write_text(re.sub(r"^robot: g1$", "robot: g1b", text, flags=re.M))
    (project / "robots/engineai/pm01.yaml").unlink()


def _count_calls(monkeypatch, module, name: str) -> list[int]:
    calls = [0]
    real = getattr(module, name)

    def counting(*a, **k):
        calls[0] += 1
        return real(*a, **k)

    monkeypatch.setattr(module, name, counting)
    return calls


@pytest.mark.parametrize("target", ["os.replace", "tempfile.mkstemp"])
def test_disk_error_at_every_step_restores_every_file(tmp_path, project, capsys, monkeypatch, target):
    """Fail the k-th os.replace (or temp-file creation) for every k: every file is as it was, no temp left."""
    _big_change(project, capsys)
    module, name = (os, "replace") if target == "os.replace" else (tempfile, "mkstemp")
    proj = find_project(project)
    plan = pipeline_generate.plan_generation(proj, load_robots(proj), force=True)
    statuses = {c.status for c in plan.changes}
    assert {"created", "changed", "removed"} <= statuses and plan.backups and plan.blocked

    # How many calls a successful apply makes (on a copy).
    dry = tmp_path / "dry"
    shutil.copytree(project, dry)
    with monkeypatch.context() as m:
        calls = _count_calls(m, module, name)
        transaction.apply(dry / "generated", plan.changes)
    total = calls[0]
    assert total > 20
    expected_after = tree(dry)

    before = tree(project)
    real = getattr(module, name)

    def fail_at(k: int):
        seen = [0]

        def failing(*a, **kw):
            seen[0] += 1
            if seen[0] == k:
                raise OSError(errno.ENOSPC, "No space left on device", str(a[0]) if a else None)
            return real(*a, **kw)
        return failing

    for k in range(1, total + 1):
        with monkeypatch.context() as m:
            m.setattr(module, name, fail_at(k))
            with pytest.raises(WriteError) as info:
                transaction.apply(project / "generated", plan.changes)
        assert "No space left on device" in str(info.value)
        assert tree(project) == before, f"failure at call {k} of {total} left a trace"

    # Through the CLI: exit 2, one line, nothing changed.
    with monkeypatch.context() as m:
        m.setattr(module, name, fail_at(total // 2 + 1))
        code, _, err = cli(capsys, project, "generate", "--force")
    assert code == 2 and "No space left on device" in err
    assert "every file was restored" in err or "nothing was changed" in err
    assert tree(project) == before
    assert cli(capsys, project, "generate", "--force")[0] == 0
    assert tree(project) == expected_after


# ---------------------------------------------------------------- colour
def _run_on_tty(args: list[str], env: dict[str, str]) -> str:
    leader, follower = pty.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "rhi_gen.cli", *args], stdout=follower,
                            stderr=subprocess.DEVNULL, env=env)
    os.close(follower)
    chunks = []
    while True:
        try:
            data = os.read(leader, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    proc.wait(timeout=600)
    os.close(leader)
    return b"".join(chunks).decode()


def test_diff_is_coloured_on_a_terminal_only(project, capsys):
    rename_joint(project)
    env = {k: v for k, v in os.environ.items() if k != "NO_COLOR"}
    args = ["diff", "g1", "--project", str(project)]
    on_tty = _run_on_tty(args, env)
    assert "\x1b[32m+" in on_tty and "\x1b[31m-" in on_tty and "\x1b[1munitree/g1:" in on_tty
    assert "\x1b[" not in _run_on_tty(args, {**env, "NO_COLOR": "1"})
    piped = subprocess.run([sys.executable, "-m", "rhi_gen.cli", *args], capture_output=True, text=True, env=env)
    assert piped.returncode == 1 and "\x1b[" not in piped.stdout and "renamed     joint 3" in piped.stdout


def test_code_in_a_region_retired_by_the_shared_core_names_the_hook_that_takes_it(project, capsys):
    """A driver written before the shared core kept SDK set-up in regions such as 'on_activate';
    regenerating must neither drop that code nor leave the user guessing where it goes now."""
    src = project / "generated/robot_hardware_interface/src/unitree/g1.cpp"
    src.write_text(src.read_text().replace(
        "}  // namespace unitree\n",
        "// rhi-gen:begin-user-region on_activate\n  startArmBrakes();\n// rhi-gen:end-user-region on_activate\n"
        "}  // namespace unitree\n"))
    before = tree(project)
    rename_joint(project)
    inputs = tree(project)
    code, _, err = cli(capsys, project, "generate")
    assert code == 2 and len(err.splitlines()) == 1, err
    assert "generated/robot_hardware_interface/src/unitree/g1.cpp:" in err and "'on_activate'" in err
    assert "override on_activate_hook()" in err and "'callbacks' region" in err and "--force" in err
    assert tree(project) == inputs and inputs != before  # nothing written


def test_old_api_names_in_user_regions_are_renamed_and_reported(project, capsys):
    """Code a user wrote against the lowerCamel API (before the snake_case rename) is carried over
    with the new names, `diff` says it would be, `generate` says where it was, and only once."""
    body = ("static bool arm_ready(const G1HardwareInterface & driver)\n"
            "{\n  return driver.getJointIndex(\"left_elbow_joint\") >= 0;  // getData() stays\n}\n")
    fill_region(project / G1_CPP, "callbacks", body)
    line = next(i for i, text in enumerate((project / G1_CPP).read_text().splitlines(), start=1)
                if "getJointIndex" in text)
    code, out, _ = cli(capsys, project, "diff")
    where = f"{G1_CPP}:{line}: user region 'callbacks': getJointIndex -> get_joint_index"
    assert code == 1 and f"would rename in {where}" in out, out
    code, out, err = cli(capsys, project, "generate")
    assert code == 0, err
    assert f"renamed in {where}" in out, out
    kept = region_bodies((project / G1_CPP).read_text())["callbacks"]
    assert kept == body.replace("getJointIndex", "get_joint_index")
    assert cli(capsys, project, "check")[0] == 0
    code, out, _ = cli(capsys, project, "generate")
    assert code == 0 and "renamed" not in out
