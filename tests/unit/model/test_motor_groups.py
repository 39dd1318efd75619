"""Motor groups for /diagnostics: the joints by limb, from their names (rhi_gen/model/motor_groups.py).

The expected groups are written out from the vendors' own grouping where one exists (SDK_FACTS.md: EngineAI
motor.yaml 6/6/1/5/5/1, AgiBot leg/waist/arm/head, Unitree G1 legs 0-11, waist 12-14, arms 15-28)."""
from __future__ import annotations

import pytest

from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.model.motor_groups import LIMB_TOKENS, MAX_MOTOR_GROUPS, SIDE_TOKENS, MotorGroup, limb_of, motor_groups
from tests.support.repo import REPO


@pytest.mark.parametrize(("joint", "limb"), [
    ("left_hip_pitch_joint", "left leg"), ("right_wrist_yaw_joint", "right arm"), ("waist_roll_joint", "waist"),
    ("J03_KNEE_PITCH_L", "left leg"), ("J21_ELBOW_PITCH_R", "right arm"), ("J23_HEAD_YAW", "head"),
    ("FL_calf_joint", "front left leg"), ("RR_thigh_joint", "rear right leg"), ("RL_foot_joint", "rear left leg"),
    ("leg_left_1_joint", "left leg"), ("arm_right_7_joint", "right arm"), ("torso_2_joint", "waist"),
    ("left_hand_thumb_0_joint", "left hand"), ("gripper_right_joint", "right hand"),
    ("LeftKneePitch", "left leg"), ("FL_HFE", "front left"), ("panda_joint1", ""), ("joint_2", ""),
])
def test_limb_from_the_joint_name(joint, limb):
    assert limb_of(joint) == limb


def _groups(robot: str) -> list[tuple[str, tuple[int, ...]]]:
    cfg = load_config(REPO / "robots" / f"{robot}.yaml")
    return [(g.name, g.slots) for g in motor_groups(cfg.joint_map)]


def test_g1_groups_follow_the_sdk_order():
    assert _groups("unitree/g1") == [
        ("left leg motors", tuple(range(6))), ("right leg motors", tuple(range(6, 12))),
        ("waist motors", (12, 13, 14)), ("left arm motors", tuple(range(15, 22))),
        ("right arm motors", tuple(range(22, 29)))]


def test_pm01_groups_are_engineais_motor_yaml_groups():
    assert [len(slots) for _, slots in _groups("engineai/pm01")] == [6, 6, 1, 5, 5, 1]
    assert [name for name, _ in _groups("engineai/pm01")] == [
        "left leg motors", "right leg motors", "waist motors", "left arm motors", "right arm motors", "head motors"]


def test_x2_groups_split_aimdks_groups_by_side():
    assert [(name, len(slots)) for name, slots in _groups("agibot/x2")] == [
        ("left leg motors", 6), ("right leg motors", 6), ("waist motors", 3), ("left arm motors", 7),
        ("right arm motors", 7), ("head motors", 2)]


def test_names_that_say_nothing_make_one_group():
    assert motor_groups([("joint_a", 3), ("joint_b", 1)]) == (MotorGroup("motors", (1, 3)),)
    assert motor_groups([("left_knee", 0)]) == (MotorGroup("motors", (0,)),)
    assert motor_groups([]) == ()


def test_joints_of_no_limb_beside_limbs_are_other_motors_and_every_slot_is_in_one_group():
    joints = [("left_knee", 4), ("mystery", 0), ("right_knee", 2), ("left_hip", 1)]
    groups = motor_groups(joints)
    assert [(g.name, g.slots) for g in groups] == [
        ("other motors", (0,)), ("left leg motors", (1, 4)), ("right leg motors", (2,))]
    assert sorted(s for g in groups for s in g.slots) == [0, 1, 2, 4]


def test_every_possible_group_fits_the_drivers_table():
    """Sides x limbs (each also absent) bound the groups; the C++ RobotSpec holds MAX_MOTOR_GROUPS names."""
    sides, limbs = set(SIDE_TOKENS.values()) | {""}, set(LIMB_TOKENS.values()) | {""}
    assert len(sides) * len(limbs) <= MAX_MOTOR_GROUPS
    header = (REPO / "rhi_gen/cpp/common/robot_spec.hpp").read_text(encoding="utf-8")
    assert f"inline constexpr size_t kMaxMotorGroups = {MAX_MOTOR_GROUPS};" in header
