"""The Dex3-1 facts of tests/support/dex3_facts.py against the vendor files the repository carries."""
from __future__ import annotations

import pytest
from lxml import etree

from tests.support import dex3_facts as dex3
from tests.support import upstream_urdf
from tests.support.repo import REPO

HG_MSGS = REPO / "tests/data/vendor_msgs/unitree_hg/msg"


def _fields(name: str) -> tuple[tuple[str, str], ...]:
    lines = (HG_MSGS / f"{name}.msg").read_text(encoding="utf-8").splitlines()
    return tuple((parts[0], parts[1]) for parts in (line.split() for line in lines) if len(parts) >= 2
                 and not parts[0].startswith("#"))


def _revolute(urdf) -> list[etree._Element]:
    root = etree.parse(str(urdf)).getroot()
    return [j for j in root.iter("joint") if j.get("type") == "revolute"]


def test_hand_messages_are_the_ones_described_and_carry_no_crc():
    assert _fields("HandCmd") == dex3.HAND_CMD_FIELDS
    assert _fields("HandState") == dex3.HAND_STATE_FIELDS
    assert all(name != "crc" for _, name in _fields("HandCmd") + _fields("HandState"))
    assert ("uint32", "crc") in _fields("LowCmd")  # the body's command does carry one


def test_mode_byte_packs_id_status_and_timeout():
    assert [dex3.mode_byte(i) for i in range(dex3.MOTORS_PER_HAND)] == list(range(0x10, 0x17))
    assert [dex3.mode_byte(i, timeout=True) for i in range(dex3.MOTORS_PER_HAND)] == list(range(0x90, 0x97))
    assert dex3.mode_byte(6, status=0) == 0x06


@pytest.mark.parametrize("side", dex3.SIDES)
def test_hand_joints_follow_their_wrist_in_motor_order(side):
    names = [j.get("name") for j in _revolute(upstream_urdf.require("unitree_g1_with_hand.urdf"))]
    assert len(names) == 29 + 2 * dex3.MOTORS_PER_HAND
    first = names.index(f"{side}_wrist_yaw_joint") + 1
    assert names[first:first + dex3.MOTORS_PER_HAND] == [dex3.joint_name(side, m)
                                                         for m in range(dex3.MOTORS_PER_HAND)]


def test_right_hand_limits_mirror_the_left_except_thumb_0():
    joints = {j.get("name"): j for j in _revolute(upstream_urdf.require("unitree_g1_with_hand.urdf"))}

    def limits(name: str) -> tuple[float, float]:
        limit = joints[name].find("limit")
        assert limit is not None, name
        return float(limit.get("lower", "nan")), float(limit.get("upper", "nan"))

    for motor, part in enumerate(dex3.MOTOR_ORDER):
        left, right = limits(dex3.joint_name("left", motor)), limits(dex3.joint_name("right", motor))
        expected = left if part == "thumb_0" else (-left[1], -left[0])
        assert right == pytest.approx(expected), part


def test_topics_name_each_side():
    assert [dex3.COMMAND_TOPIC.format(side=s) for s in dex3.SIDES] == ["rt/dex3/left/cmd", "rt/dex3/right/cmd"]
    assert all(t.startswith("rt/") for t in (dex3.STATE_TOPIC.format(side=s) for s in dex3.SIDES))
