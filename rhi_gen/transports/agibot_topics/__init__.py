"""agibot_topics: AgiBot AimDK (aimdk_msgs) ROS 2 topics, one command/state topic pair per joint group.

Facts from AimDK: the X2's 31 motors form four groups (leg 12, waist 3, arm 14, head 2), each on
/aima/hal/joint/<group>/{command,state} (JointCommandArray / JointStateArray); the IMU is
sensor_msgs/Imu on /aima/hal/imu/torso/state. A joint's SDK index is (group offset + position).

Taking control the vendor's way (``take_control: true``, AimDK v1.0.0 and later): whole-body joint commands need
AgiBot's motion control (MC) stopped, which the system-state service MigrateSystemState("Develop_MC") does; the
driver asks for it and waits for GetSystemState to report Develop_MC ready before its first command, and asks for
"Ready" (MC back) after its last (AimDK documentation Interface/system_state, the vendor example
migrate_system_state.cpp; tests/support/aimdk_facts.py).

The X2's OmniHands (``hands: omnihand``, AimDK endeffector docs and the vendor's omnihand_control example): one
HandCommandArray for both hands on /aima/hal/joint/hand/command, HandStateArray on .../hand/state; per hand 10
entries, matched by index, in the axis order OMNIHAND_AXES, each a position target in rad (the HAL ignores the
other fields). The hand joints take the 20 joint_map slots after the body's groups, left hand first.
"""
from __future__ import annotations

import re
import textwrap
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from ...errors import ConfigError
from ...model import MAX_MOTORS, TransportOptions
from ...typed_yaml.validator import Validator
from ..base import (
    ROSDISTRO,
    VENDOR_SOURCE,
    Dependency,
    HandSuggestion,
    KnownRobot,
    Transport,
    check_hand_choice,
    transport_header,
)
from ..ros_topics import QosConfig, TopicOptions, qos_line, read_qos

NAME = "agibot_topics"
DEFAULT_GROUPS = (("leg", 12), ("waist", 3), ("arm", 14), ("head", 2))
GROUP_KEYS = ("name", "size", "command_topic", "state_topic")
GROUP_NAME_RE = re.compile(r"^[a-z][a-z0-9_]*$")
IMU_TOPIC = "/aima/hal/imu/torso/state"
TAKE_CONTROL_TIMEOUT_S = 30.0  # how long activation waits for Develop_MC (the vendor example polls up to 5 min)
HAND_COMMAND_TOPIC = "/aima/hal/joint/hand/command"  # HandCommandArray, both hands
HAND_STATE_TOPIC = "/aima/hal/joint/hand/state"      # HandStateArray
OMNIHAND_AXES = ("thumb_roll", "thumb_abad", "thumb_mcp", "index_abad", "index_pip", "middle_pip", "ring_abad",
                 "ring_pip", "pinky_abad", "pinky_pip")
OMNIHAND_SIDES = (("left", "L_"), ("right", "R_"))  # AgibotTech's X2-Ultra_omnihand.urdf joint name prefixes
OMNIHAND_MOTORS = len(OMNIHAND_SIDES) * len(OMNIHAND_AXES)
OMNIHAND_TYPE = 1        # hal/msg/HandType NIMBLE_HANDS: AgiBot's own dexterous hand, the OmniHand
OMNIHAND_VELOCITY = 0.1  # HandCommand.velocity the vendor's omnihand_control example sends (the docs: unused)

_X2_LEG = tuple(f"{side}_{j}_joint" for side in ("left", "right")
                for j in ("hip_pitch", "hip_roll", "hip_yaw", "knee", "ankle_pitch", "ankle_roll"))
_X2_WAIST = ("waist_yaw_joint", "waist_pitch_joint", "waist_roll_joint")
_X2_ARM = tuple(f"{side}_{j}_joint" for side in ("left", "right")
                for j in ("shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_yaw",
                          "wrist_pitch", "wrist_roll"))
_X2_HEAD = ("head_yaw_joint", "head_pitch_joint")
X2_GROUPS = (("leg", _X2_LEG), ("waist", _X2_WAIST), ("arm", _X2_ARM), ("head", _X2_HEAD))
X2_ORDER = _X2_LEG + _X2_WAIST + _X2_ARM + _X2_HEAD


@dataclass(frozen=True)
class JointGroup:
    """A contiguous slice of SDK slots published/subscribed on its own topics."""
    name: str
    size: int
    command_topic: str
    state_topic: str
    offset: int = 0  # first global slot index of this group (decided by the transport)


@dataclass(frozen=True)
class AgibotTopicsOptions(TopicOptions):
    groups: tuple[JointGroup, ...] = ()
    take_control: bool = False  # Develop_MC before the first command, Ready after the last
    take_control_timeout_s: float = TAKE_CONTROL_TIMEOUT_S
    hands: str = "none"         # omnihand: the X2's OmniHands in the 20 slots after the groups' (HandCommandArray)
    hand_command_topic: str = HAND_COMMAND_TOPIC
    hand_state_topic: str = HAND_STATE_TOPIC

    @property
    def body_slots(self) -> int:
        """Slots of the joint groups (the body); the hands' follow them."""
        return sum(g.size for g in self.groups)

    def hand_slots(self) -> range:
        """omnihand: the 20 slots after the groups', the left hand's 10 axes then the right's."""
        return range(self.body_slots, self.body_slots + OMNIHAND_MOTORS) if self.hands == "omnihand" else range(0)

    def position_target_slots(self) -> range:
        """An OmniHand axis takes a position target only (the hand's own controller tracks it)."""
        return self.hand_slots()

    @property
    def hand_axes(self) -> int:
        return len(OMNIHAND_AXES)

    @property
    def hand_type(self) -> int:
        return OMNIHAND_TYPE

    @property
    def hand_velocity(self) -> float:
        return OMNIHAND_VELOCITY

    def joint_group(self, index: int) -> tuple[str, int] | None:
        for g in self.groups:
            if g.offset <= index < g.offset + g.size:
                return g.name, index - g.offset
        return None


def command_topic(group: str) -> str:
    return f"/aima/hal/joint/{group}/command"


def state_topic(group: str) -> str:
    return f"/aima/hal/joint/{group}/state"


class AgibotTopics(Transport):
    name = NAME
    summary = "AgiBot aimdk_msgs ROS 2 topics, one command/state pair per joint group"
    option_keys = ("groups", "imu_topic", "qos", "take_control", "take_control_timeout_s", "hand_command_topic",
                   "hand_state_topic")
    default_float_type = "double"
    dependencies = (Dependency("aimdk_msgs", VENDOR_SOURCE), Dependency("sensor_msgs", ROSDISTRO))
    shared_files = (transport_header("ros_topics", "ros_topics.hpp"), transport_header(NAME, "joint_names.hpp"),
                    transport_header(NAME, "agibot_topics.hpp"), transport_header(NAME, "agibot_topics_fake_robot.hpp"),
                    transport_header(NAME, "agibot_system_state.hpp"),
                    transport_header(NAME, "agibot_system_state_fake_robot.hpp"))
    fake_robot_header = "robot_hardware_interface/transport/agibot_topics_fake_robot.hpp"
    fake_state_rate_hz = 1000.0  # JointStateArray per group at 1000 Hz, IMU 500 Hz (x2_rl_deploy README)
    vendors = ("agibot",)
    known_robots = (
        KnownRobot("agibot", "x2", NAME, X2_ORDER, "X2 motor order = AimDK joint groups leg, waist, arm, head",
                   groups=X2_GROUPS),
    )

    def motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """hal/msg/JointState v1.0.0 (the aimdk_msgs this driver is built with): uint16 error_code."""
        return ("error_code",)

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> AgibotTopicsOptions:
        p = "transport_options"
        return AgibotTopicsOptions(
            groups=_read_groups(v, options.get("groups")),
            imu_topic=v.optional(options, p, "imu_topic", v.topic, IMU_TOPIC),
            qos=read_qos(v, options.get("qos"), f"{p}.qos", QosConfig(depth=1)),
            sdk_slots=motor_count,
            take_control=v.optional(options, p, "take_control", v.boolean, False),
            take_control_timeout_s=v.optional(
                options, p, "take_control_timeout_s",
                v.seconds_in(1.0, 600.0, "how long activation may wait for Develop_MC", 30.0), TAKE_CONTROL_TIMEOUT_S),
            hand_command_topic=v.optional(options, p, "hand_command_topic", v.topic, HAND_COMMAND_TOPIC),
            hand_state_topic=v.optional(options, p, "hand_state_topic", v.topic, HAND_STATE_TOPIC),
        )

    def resolve_hands(self, v: Validator, hands: str, options: TransportOptions, *, vendor: str,
                      robot: str) -> AgibotTopicsOptions:
        """omnihand: the X2's OmniHands; a Dex3-1 is a Unitree hand."""
        assert isinstance(options, AgibotTopicsOptions)
        check_hand_choice(v, hands, "omnihand", NAME, "the X2 OmniHand")
        return replace(options, hands=hands)

    def resolve_options(self, v: Validator, options: TransportOptions, *, vendor: str, robot: str,
                        motor_count: int) -> AgibotTopicsOptions:
        """The groups and the hands fill motor_count exactly."""
        assert isinstance(options, AgibotTopicsOptions)
        hands = len(options.hand_slots())
        total = options.body_slots + hands
        if total != motor_count:
            held = f"the groups hold {options.body_slots} slots" + (f" and the OmniHands {hands}" if hands else "")
            raise ConfigError(f"motor_count is {motor_count} but {held}", file=v.source,
                              line=v.lines.get("motor_count"), key="motor_count",
                              fix=f"set motor_count: {total}, or change the group sizes")
        return options

    def check_hand_map(self, v: Validator, options: TransportOptions,
                       joint_map: tuple[tuple[str, int], ...]) -> None:
        """Every OmniHand axis drives a joint: the HAL takes all 10 axes of a hand at once (AimDK endeffector docs),
        so an unmapped one would be sent a target no controller owns."""
        assert isinstance(options, AgibotTopicsOptions)
        mapped = {slot for _, slot in joint_map}
        missing = [slot for slot in options.hand_slots() if slot not in mapped]
        if missing:
            first = options.hand_slots().start
            side, prefix = OMNIHAND_SIDES[(missing[0] - first) // len(OMNIHAND_AXES)]
            axis = OMNIHAND_AXES[(missing[0] - first) % len(OMNIHAND_AXES)]
            raise v.error("joint_map", f"hands: omnihand drives slots {first}..{first + OMNIHAND_MOTORS - 1}, and no "
                          f"joint has slot {missing[0]} (the {side} hand's {axis} axis)",
                          fix=f"map {prefix}{axis}_joint: {missing[0]} (left hand {first}..{first + 9}, right "
                              f"{first + 10}..{first + 19}, in the order {', '.join(OMNIHAND_AXES)})")

    def detect_hands(self, known: KnownRobot | None, actuated: Sequence[str]) -> HandSuggestion:
        """An X2 whose URDF has both OmniHands' axes (X2-Ultra_omnihand.urdf): hands: omnihand, the axes after the
        body's 31 slots."""
        names = omnihand_joints()
        if known is None or not set(names) <= set(actuated):
            return HandSuggestion()
        first = len(known.joint_order)
        return HandSuggestion("omnihand", tuple((n, first + i) for i, n in enumerate(names)))

    def suggest_hands(self, known: KnownRobot | None, hands: HandSuggestion) -> list[str]:
        """An X2 can carry OmniHands: say how they are driven, or how to drive them (none stays the default)."""
        if known is None:
            return []
        first = len(known.joint_order)
        text = (f"motor_count {first + OMNIHAND_MOTORS}, the hand joints in slots {first}..{first + 9} (left) and "
                f"{first + 10}..{first + 19} (right), in the order {', '.join(OMNIHAND_AXES)}")
        if hands.hands == "omnihand":
            return ["# hands: omnihand drives the OmniHands too (position targets only, one HandCommandArray):",
                    *(f"# {line}" for line in textwrap.wrap(text + ".", 96)), "hands: omnihand"]
        return ["# hands: none drives the body only; omnihand drives the OmniHands too (use the URDF with hands):",
                *(f"# {line}" for line in textwrap.wrap(text + "; see docs/hands.md.", 96)), "hands: none"]

    def resolve_authority(self, v: Validator, authority: str, options: TransportOptions, *, vendor: str,
                          robot: str, mapped_slots: frozenset[int]) -> TransportOptions:
        """Only full: AgiBot documents no way to command the arm joints while MC balances the legs."""
        assert isinstance(options, AgibotTopicsOptions)
        if authority != "full":
            raise v.error("authority", "AgiBot's AimDK offers no joint-level control of the arms while its motion "
                          "control keeps the legs (its arms-only route, AimDK 1.1's /mc/upper_body_command, takes "
                          "position targets only and is not in the v1.0.0 messages)",
                          fix="remove authority (full), and set transport_options.take_control: true to stop the "
                              "motion control the vendor's way")
        if "transport_options.take_control_timeout_s" in v.lines and not options.take_control:
            raise v.error("transport_options.take_control_timeout_s", "is used only with take_control: true",
                          fix="remove take_control_timeout_s, or set take_control: true")
        return options

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        lines = ["  groups:"]
        for name, size in _suggested_groups(order, known):
            lines += [f"    - name: {name}", f"      size: {size}",
                      f"      command_topic: {command_topic(name)}",
                      f"      state_topic: {state_topic(name)}"]
        return [*lines, f"  imu_topic: {IMU_TOPIC}", qos_line(1),
                "  take_control: true  # Develop_MC (AgiBot's motion control stopped) on activation, Ready after"]

    def joint_labels(self, order: Sequence[str], known: KnownRobot | None) -> list[str]:
        groups = [f"{name}[{i}]" for name, size in _suggested_groups(order, known) for i in range(size)]
        hands = [f"{side} OmniHand[{i}]" for side, _ in OMNIHAND_SIDES for i in range(len(OMNIHAND_AXES))]
        return groups + (hands if _has_omnihands(order) else [])


def _has_omnihands(order: Sequence[str]) -> bool:
    return set(omnihand_joints()) <= set(order)


def _suggested_groups(order: Sequence[str], known: KnownRobot | None) -> list[tuple[str, int]]:
    """The known robot's groups, else AimDK's default groups when the count fits, else one group; the OmniHands'
    axes (when all are there: rhi-gen new writes hands: omnihand) are in no group."""
    if _has_omnihands(order):
        order = [n for n in order if n not in omnihand_joints()]
    if known is not None and known.groups and sum(len(g) for _, g in known.groups) == len(order):
        return [(name, len(members)) for name, members in known.groups]
    if sum(size for _, size in DEFAULT_GROUPS) == len(order):
        return list(DEFAULT_GROUPS)
    return [("all", len(order))]


def omnihand_joints() -> tuple[str, ...]:
    """The OmniHand axes' URDF joint names in slot order: left hand, then right."""
    return tuple(f"{prefix}{axis}_joint" for _, prefix in OMNIHAND_SIDES for axis in OMNIHAND_AXES)


def _read_groups(v: Validator, raw: Any) -> tuple[JointGroup, ...]:
    path = "transport_options.groups"
    if raw is None:
        specs = [(name, size, command_topic(name), state_topic(name)) for name, size in DEFAULT_GROUPS]
    else:
        if not isinstance(raw, list) or not raw:
            raise v.error(path, "must be a non-empty list of {name, size, command_topic, state_topic}",
                          fix="e.g. [{name: leg, size: 12}] or remove groups for the AgiBot defaults")
        specs = []
        for i, item in enumerate(raw):
            q = f"{path}[{i}]"
            m = v.mapping(item, q, GROUP_KEYS)
            for key in ("name", "size"):
                if key not in m:
                    raise v.error(q, f"group needs {key!r}", fix=f"add {key}: to the group")
            name = v.string(m["name"], f"{q}.name", GROUP_NAME_RE, "group name")
            size = v.integer(m["size"], f"{q}.size", 1, MAX_MOTORS)
            cmd = v.optional(m, q, "command_topic", v.topic, command_topic(name))
            state = v.optional(m, q, "state_topic", v.topic, state_topic(name))
            if any(s[0] == name for s in specs):
                raise v.error(f"{q}.name", f"group {name!r} is defined twice", fix="give every group its own name")
            specs.append((name, size, cmd, state))
    groups, offset = [], 0
    for name, size, cmd, state in specs:
        groups.append(JointGroup(name=name, size=size, command_topic=cmd, state_topic=state, offset=offset))
        offset += size
    return tuple(groups)


TRANSPORT = AgibotTopics()
