"""Each joint's transmission decided from the URDF's <transmission>s and the vendor YAML (the YAML wins)."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from rhi_gen.assemble.robot_model import build_model
from rhi_gen.assemble.transmissions import decide_transmissions
from rhi_gen.errors import ConfigError
from rhi_gen.inputs.urdf_loader import load_urdf
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.model import CoupledGroup, JointTransmission
from tests.support.repo import URDF_FIXTURES

URDF = URDF_FIXTURES / "transmission_arm.urdf"
HEAD = f"""\
vendor: acme
robot: arm
urdf: {URDF}
transport: generic_topics
motor_count: 4
joint_map:
  wrist_pitch: 2
  wrist_roll: 3
  elbow: 0
unmapped_joints: [gripper]
"""  # the next line is line 11
WRIST_SOURCE = "URDF <transmission name='wrist_trans'> line 21"
ELBOW_SOURCE = "URDF <transmission name='elbow_trans'> line 16"


def loaded(tmp_path: Path, extra: str = ""):
    yml = tmp_path / "arm.yaml"
    yml.write_text(HEAD + textwrap.dedent(extra), encoding="utf-8")
    cfg = load_config(yml)
    urdf = load_urdf(cfg.urdf, display_path="arm.urdf")
    return cfg, urdf, build_model(cfg, urdf, yaml_path=yml, project_root=tmp_path)


def transmissions(model):
    return {j.name: j.transmission for j in model.joints}


def test_urdf_simple_and_differential_are_applied(tmp_path):
    _, _, m = loaded(tmp_path)
    t = transmissions(m)
    assert t["elbow"] == JointTransmission(-1, 50.0, 0.25, ELBOW_SOURCE)
    assert t["wrist_pitch"] == JointTransmission(offset=0.1, source=WRIST_SOURCE)
    assert t["wrist_roll"] == JointTransmission()  # offset 0 in a group: the identity, nothing to say
    assert m.coupled_groups == (CoupledGroup("wrist_trans", ("wrist_pitch", "wrist_roll"),
                                             ((0.5, 0.5), (0.5, -0.5)), WRIST_SOURCE),)
    assert m.has_transmission


def test_what_is_not_applied_is_one_warning_per_kind_of_reason(tmp_path):
    cfg, urdf, _ = loaded(tmp_path)
    decided = decide_transmissions(cfg, urdf)
    lines = [str(w) for w in decided.warnings]
    assert (decided.urdf_applied, decided.urdf_skipped) == (2, 3)
    assert lines == [
        ("arm.urdf:28: <transmission> 'gripper_trans' (SimpleTransmission) not applied: names joint 'gripper', "
         "which has no motor in joint_map -> nothing to do if no motor of joint_map drives that joint; else map "
         "it in joint_map"),
        ("arm.urdf:33: <transmission> 'finger_trans' of kind acme_transmissions/FingerReducer not applied: rhi-gen "
         "applies only SimpleTransmission and DifferentialTransmission -> if a motor is not its joint, write it in "
         "the vendor YAML: transmissions: {joint: {direction, reduction, offset}} or coupled_joints: {group: "
         "{joints, matrix}} (docs/transmissions.md)"),
        ("arm.urdf:38: <transmission> 'broken_trans' (SimpleTransmission) not applied: <mechanicalReduction> of "
         "actuator 'x' is 'zero', not a number -> fix the <transmission> in the URDF, or write the joint's "
         "transmission in the vendor YAML (transmissions: or coupled_joints:) and set urdf_transmissions: false"),
    ]


def test_yaml_entry_replaces_the_urdf_one_for_its_joint(tmp_path):
    _, _, m = loaded(tmp_path, "transmissions:\n  elbow: {reduction: 10}\n  wrist_roll: {offset: -0.2}\n")
    t = transmissions(m)
    assert t["elbow"] == JointTransmission(1, 10.0, 0.0, "vendor YAML")  # not merged with the URDF's -50
    assert t["wrist_roll"] == JointTransmission(offset=-0.2, source="vendor YAML")  # stays in the URDF group
    assert [g.name for g in m.coupled_groups] == ["wrist_trans"]


def test_yaml_group_replaces_a_urdf_group_sharing_a_joint(tmp_path):
    _, _, m = loaded(tmp_path, """\
        coupled_joints:
          wrist:
            joints: [wrist_roll, elbow]
            matrix: [[1, 1], [0, 2]]
        """)
    t = transmissions(m)
    assert m.coupled_groups == (CoupledGroup("wrist", ("wrist_roll", "elbow"), ((1.0, 1.0), (0.0, 2.0)),
                                             "vendor YAML"),)
    # the URDF's wrist group is gone whole (wrist_pitch loses its offset), elbow's URDF Simple too
    assert t["wrist_pitch"] == t["elbow"] == t["wrist_roll"] == JointTransmission()


def test_urdf_transmissions_false_ignores_the_urdf_and_its_warnings(tmp_path):
    cfg, urdf, m = loaded(tmp_path, "urdf_transmissions: false\n")
    assert not m.has_transmission and m.coupled_groups == ()
    assert decide_transmissions(cfg, urdf).warnings == ()


def test_direction_on_a_joint_the_urdf_couples_is_refused_at_its_yaml_line(tmp_path):
    with pytest.raises(ConfigError) as info:
        loaded(tmp_path, "transmissions:\n  wrist_pitch: {direction: -1}\n")
    err = info.value
    assert (err.line, err.key) == (12, "transmissions.wrist_pitch.direction")
    assert f"coupled by {WRIST_SOURCE}" in str(err) and "urdf_transmissions: false" in str(err)


def test_identity_changes_nothing(tmp_path):
    _, _, m = loaded(tmp_path, """\
        urdf_transmissions: false
        transmissions:
          elbow: {direction: 1, reduction: 1, offset: 0}
        coupled_joints:
          b: {joints: [wrist_roll, wrist_pitch], matrix: [[1, 0], [0, 1]]}
        """)
    assert not m.has_transmission and all(j.transmission == JointTransmission() for j in m.joints)


def test_groups_are_ordered_by_their_lowest_slot(tmp_path):
    yml = HEAD.replace("unmapped_joints: [gripper]\n", "").replace("  elbow: 0\n", "  elbow: 0\n  gripper: 1\n")
    path = tmp_path / "arm.yaml"
    path.write_text(yml + textwrap.dedent("""\
        coupled_joints:
          a_wrist: {joints: [wrist_roll, wrist_pitch], matrix: [[1, 1], [1, -1]]}
          z_hand: {joints: [gripper, elbow], matrix: [[2, 0], [1, 1]]}
        """), encoding="utf-8")
    cfg = load_config(path)
    m = build_model(cfg, load_urdf(cfg.urdf), yaml_path=path, project_root=tmp_path)
    assert [g.name for g in m.coupled_groups] == ["z_hand", "a_wrist"]  # slots 0-1 before 2-3
