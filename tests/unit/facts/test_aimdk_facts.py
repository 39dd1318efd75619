"""The AimDK facts of tests/support/aimdk_facts.py against the shared aimdk_msgs definitions (skipped in one
line, saying how to provide them, where ../shared is not beside the clone)."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.support import aimdk_facts as aimdk
from tests.support import vendor_msgs

ROBOT = vendor_msgs.UPSTREAM_MSGS / "aimdk_msgs" / "interface" / "robot"


def _definition(relative: str) -> Path:
    path = ROBOT / relative
    if not path.is_file():
        pytest.skip(f"aimdk_msgs {relative}: not carried in the repository, and {vendor_msgs.UPSTREAM_MSGS} is "
                    "missing it: put the project's shared folder beside the clone or set RHI_UPSTREAM_MSGS")
    return path


def _request_fields(relative: str) -> tuple[tuple[str, str], ...]:
    lines = _definition(relative).read_text(encoding="utf-8").splitlines()
    request = lines[:[line.strip() for line in lines].index("---")]  # the separator line, not a comment of dashes
    words = (line.split("#")[0].split() for line in request)
    return tuple((w[0], w[1]) for w in words if len(w) >= 2 and "=" not in w[1])


def _constants(relative: str) -> dict[str, int]:
    words = (line.split("#")[0].replace("=", " = ").split() for line in
             _definition(relative).read_text(encoding="utf-8").splitlines())
    return {w[1]: int(w[3], 0) for w in words if len(w) == 4 and w[2] == "="}  # 0x.. too


def test_input_source_actions():
    assert _constants("mc/motion/msg/McInputAction.msg") == aimdk.INPUT_ACTIONS


def test_service_requests():
    assert _request_fields("mc/motion/srv/SetMcInputSource.srv") == aimdk.SET_INPUT_SOURCE_REQUEST
    assert _request_fields("mc/action/srv/SetMcAction.srv") == aimdk.SET_ACTION_REQUEST
    assert _request_fields("sm/srv/MigrateSystemState.srv") == aimdk.MIGRATE_REQUEST


def test_success_is_common_state_success():
    assert _constants("common/msg/CommonState.msg")["SUCCESS"] == aimdk.SUCCESS


def test_service_names_are_the_type_names():
    for name in (aimdk.SET_INPUT_SOURCE, aimdk.GET_INPUT_SOURCE, aimdk.SET_ACTION, aimdk.GET_ACTION,
                 aimdk.MIGRATE_SYSTEM_STATE, aimdk.GET_SYSTEM_STATE):
        srv = name.removeprefix(aimdk.SERVICE_PREFIX)
        assert list(ROBOT.rglob(f"{srv}.srv")) or not ROBOT.is_dir(), srv


def _fields(relative: str) -> tuple[tuple[str, str], ...]:
    words = (line.split("#")[0].split() for line in _definition(relative).read_text(encoding="utf-8").splitlines())
    return tuple((w[0], w[1]) for w in words if len(w) >= 2 and "=" not in w[1] and not w[1].startswith("="))


def test_hand_messages():
    assert _fields("hal/msg/HandCommandArray.msg") == aimdk.HAND_COMMAND_ARRAY_FIELDS
    assert _fields("hal/msg/HandCommand.msg") == aimdk.HAND_COMMAND_FIELDS
    assert _fields("hal/msg/HandState.msg") == aimdk.HAND_STATE_FIELDS
    assert _constants("hal/msg/HandType.msg") == aimdk.HAND_TYPES


def test_hand_state_array_carries_each_hands_type_and_states():
    fields = {name: kind for kind, name in _fields("hal/msg/HandStateArray.msg")}
    assert fields["left_hand_type"] == fields["right_hand_type"] == "HandType"
    assert fields["left_hands"] == fields["right_hands"] == "HandState[]"
    assert _fields("hal/msg/HandStateArray.msg") == aimdk.HAND_STATE_ARRAY_FIELDS


# The harness's test robot with two OmniHands (tests/cpp/harness/README.md): its URDF and YAML against the facts.
HARNESS_ROBOT = Path(__file__).resolve().parents[2] / "cpp" / "harness" / "robots" / "agibot"


def _xacro_axis_calls() -> list[dict[str, str]]:
    """The omnihand_axis macro calls of x2_omnihand.urdf.xacro, their attributes, in file order."""
    import xml.etree.ElementTree as ET

    root = ET.parse(HARNESS_ROBOT / "x2_omnihand.urdf.xacro").getroot()
    return [dict(e.attrib) for e in root if e.tag == "{http://www.ros.org/wiki/xacro}omnihand_axis"]


def _omnihand_joints() -> list[tuple[str, str, str, float, float]]:
    """(side, axis, joint name, lower, upper) per hand joint of the facts, left hand first, in AimDK's order."""
    return [(side, axis, aimdk.OMNIHAND_SIDE_PREFIX[side] + axis + "_joint", *aimdk.OMNIHAND_LIMITS[side][axis])
            for side in ("left", "right") for axis in aimdk.OMNIHAND_AXES]


def test_omnihand_limits_cover_every_axis_of_both_sides():
    assert set(aimdk.OMNIHAND_LIMITS) == set(aimdk.OMNIHAND_SIDE_PREFIX) == {"left", "right"}
    for side, limits in aimdk.OMNIHAND_LIMITS.items():
        assert tuple(limits) == aimdk.OMNIHAND_AXES, side
        assert all(lower < upper for lower, upper in limits.values()), side
    # the pip joints bend the same way on both hands; the others mirror
    for axis in aimdk.OMNIHAND_AXES:
        left, right = aimdk.OMNIHAND_LIMITS["left"][axis], aimdk.OMNIHAND_LIMITS["right"][axis]
        assert left == (right if axis.endswith("_pip") else (-right[1], -right[0])), axis
    assert aimdk.OMNIHAND_VELOCITY_SENT == 0.1


def test_harness_omnihand_urdf_carries_the_facts_joints_and_limits():
    calls = _xacro_axis_calls()
    got = [(c["prefix"] + c["axis"] + "_joint", float(c["lower"]), float(c["upper"])) for c in calls]
    assert got == [(name, lower, upper) for _, _, name, lower, upper in _omnihand_joints()]


def test_harness_omnihand_yaml_maps_the_hands_after_the_body_in_aimdk_order():
    import yaml

    data = yaml.safe_load((HARNESS_ROBOT / "x2_omnihand.yaml").read_text(encoding="utf-8"))
    assert data["hands"] == "omnihand" and data["transport"] == "agibot_topics"
    joint_map = {str(k): int(v) for k, v in data["joint_map"].items()}
    hands = {name: slot for name, slot in joint_map.items() if slot >= 31}
    assert hands == {name: 31 + i for i, (_, _, name, _, _) in enumerate(_omnihand_joints())}
    assert sorted(set(joint_map.values()) - set(hands.values())) == list(range(31))
    assert data["motor_count"] == 31 + 2 * len(aimdk.OMNIHAND_AXES)
