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
