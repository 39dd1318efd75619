"""Motors that are not joints, end to end: `new` lists the URDF's <transmission>s and warns about those it
cannot apply, `inspect` lists them, `diff` explains a changed one in robot terms, and a bad YAML value is
one error line with file:line and key."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

from tests.support.cli import edit_yaml, generate_rejected, run_cli
from tests.support.corpus import example_robot
from tests.support.repo import URDF_FIXTURES

YAML_REL = "robots/acme/arm.yaml"


def new_arm(root: Path):
    """`rhi-gen new` on tests/fixtures/urdf/transmission_arm.urdf, copied into the project first."""
    (root / "robots/acme").mkdir(parents=True)
    shutil.copy(URDF_FIXTURES / "transmission_arm.urdf", root / "robots/acme/arm.urdf")
    result = run_cli("new", "--vendor", "acme", "--robot", "arm", "--urdf", root / "robots/acme/arm.urdf",
                     "--project", root)
    assert result.code == 0, result.err
    return result


def test_new_lists_the_transmissions_and_warns_once_per_kind(tmp_path):
    root = tmp_path / "proj"
    result = new_arm(root)
    assert ("transmissions: 5 in the URDF, 3 applied, 2 not (listed in robots/acme/arm.yaml; docs/"
            "transmissions.md)") in result.out.splitlines()
    warnings = [line for line in result.err.splitlines() if line.startswith("warning: ")]
    urdf = root / "robots/acme/arm.urdf"
    assert [w.split(": <transmission>")[0] for w in warnings] == [f"warning: {urdf}:33", f"warning: {urdf}:38"]
    assert "acme_transmissions/FingerReducer" in warnings[0] and "coupled_joints:" in warnings[0]
    assert "'zero', not a number" in warnings[1]
    text = (root / YAML_REL).read_text()
    assert "urdf_transmissions: true\n" in text
    assert "#   elbow: SimpleTransmission 'elbow_trans': reduction 50, direction -1, offset 0.25\n" in text
    assert ("#   wrist_pitch, wrist_roll: DifferentialTransmission 'wrist_trans': matrix [[0.5, 0.5], [0.5, -0.5]]"
            ", offset 0.1\n") in text
    manifest = json.loads((root / "generated/.rhi-gen-manifest").read_text())["robots"]["acme/arm"]
    assert manifest["transmissions"] == {"elbow": [-1, 50.0, 0.25], "gripper": [1, 100.0, 0.0],
                                         "wrist_pitch": [1, 1.0, 0.1]}
    assert manifest["coupled_groups"] == {"wrist_trans": {"joints": ["wrist_pitch", "wrist_roll"],
                                                          "matrix": [[0.5, 0.5], [0.5, -0.5]]}}
    assert run_cli("check", "--project", root).code == 0


YAML_OVERRIDES = """\
urdf_transmissions: true
transmissions:
  elbow: {reduction: 10}
coupled_joints:
  wrist:
    joints: [wrist_roll, wrist_pitch]
    matrix: [[1, 0], [0, 2]]
"""


def test_diff_explains_a_yaml_transmission_in_robot_terms(tmp_path):
    root = tmp_path / "proj"
    new_arm(root)
    edit_yaml(root, "urdf_transmissions: true\n", YAML_OVERRIDES)
    result = run_cli("diff", "--project", root)
    assert result.code == 1, result.err
    lines = result.out.splitlines()
    assert "  elbow: transmission reduction 50 -> 10, direction -1 -> +1, offset 0.25 -> 0" in lines
    assert "  wrist_pitch: transmission offset 0.1 -> 0" in lines
    assert "  coupled group wrist: added (wrist_roll, wrist_pitch), matrix [[1, 0], [0, 2]]" in lines
    assert "  coupled group wrist_trans: removed (wrist_pitch, wrist_roll)" in lines


def test_bad_transmission_in_the_yaml_is_one_line(tmp_path):
    root = tmp_path / "proj"
    new_arm(root)
    edit_yaml(root, "urdf_transmissions: true\n", "urdf_transmissions: true\ntransmissions:\n  elbow: {reduction: 0}\n")
    line = (root / YAML_REL).read_text().splitlines().index("  elbow: {reduction: 0}") + 1
    message = generate_rejected(root, file=YAML_REL, line=line, key="transmissions.elbow.reduction")
    assert "direction: -1" in message


def test_inspect_lists_tiago_transmissions_and_why_hey5_is_not_applied():
    result = run_cli("inspect", "--urdf", example_robot("tiago_description/robots/tiago.urdf"))
    assert result.code == 0, result.err
    lines = result.out.splitlines()
    assert any(line.startswith("transmissions: 47 <transmission>") for line in lines)
    assert ("  arm_6_joint, arm_7_joint: DifferentialTransmission 'wrist_trans': matrix [[-0.5, 0.5], [0.5, 0.5]]"
            in lines)
    assert ("  hand_thumb_abd_joint: Hey5Reducer 'hand_thumb_abd_trans': not applied, rhi-gen applies only "
            "SimpleTransmission and DifferentialTransmission") in lines


def test_new_on_talos_applies_its_differential_wrists(tmp_path):
    root = tmp_path / "proj"
    root.mkdir()
    result = run_cli("new", "--vendor", "pal", "--robot", "talos", "--urdf",
                     example_robot("talos_data/robots/talos_reduced.urdf"), "--project", root)
    assert result.code == 0, result.err
    assert "transmissions: 28 in the URDF, 27 applied, 1 not" in result.out
    warnings = [line for line in result.err.splitlines() if line.startswith("warning: ")]
    assert len(warnings) == 1 and "HalfDifferentialTransmission" in warnings[0]
    manifest = json.loads((root / "generated/.rhi-gen-manifest").read_text())["robots"]["pal/talos"]
    assert sorted(manifest["coupled_groups"]) == ["talos_torso_trans", "wrist_left_trans", "wrist_right_trans"]
    assert "transmissions" not in manifest  # every SimpleTransmission of TALOS is the identity


def test_generate_warns_and_check_and_diff_stay_quiet(tmp_path):
    root = tmp_path / "proj"
    new_arm(root)
    generate = run_cli("generate", "--project", root)
    assert generate.code == 0, generate.err
    assert [line.split(": <transmission> ")[1].split(" ")[0] for line in generate.err.splitlines()] == [
        "'finger_trans'", "'broken_trans'"]
    for command in ("check", "diff"):
        result = run_cli(command, "--project", root)
        assert result.code == 0 and "warning" not in result.err + result.out, (command, result.err)
