"""unitree_dds: unitree_sdk2 over DDS, LowCmd_/LowState_ with CRC32, float.

Two message families (SDK_FACTS.md sections A and D): "hg" (35 motor slots, mode_pr and
mode_machine) for G1 and H1-2; "go" (20 slots, head/level_flag framing, a motor mode per slot)
for the original H1, Go2, Go2-W, B2 and B2-W. Known robots bring their family, their real SDK motor
order, motor modes and the gains of the SDK's own low-level examples; an unknown Unitree robot must
name its family (sending one family's bytes to the other commands garbage). The CRC and message
headers are shared by every Unitree driver of the package, so they are generated once.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from ...errors import ConfigError
from ...model import TransportOptions
from ...typed_yaml.validator import TOPIC_RE, Validator
from ..base import PLAIN_CMAKE, Dependency, HandSuggestion, KnownRobot, Transport, check_hand_choice, transport_header

NAME = "unitree_dds"
FAMILIES = {"hg": 35, "go": 20}  # message family -> motor slots of its LowCmd_
FAMILY_ROBOTS = {"hg": "G1, H1-2", "go": "H1, Go2, Go2-W, B2, B2-W"}
GO_SERVO = 0x01   # MotorCmd_.mode of the go examples ("servo (PMSM) mode")
GO_STRONG = 0x0A  # the H1's hip/knee/torso motors and the B2's motors in the C++ examples
# The arm SDK (authority upper_body): LowCmd_ on rt/arm_sdk, the blend weight in the q of the first unused
# slot, kNotUsedJoint of unitree_sdk2's example/g1/high_level/g1_arm7_sdk_dds_example.cpp (G1: 29) and
# example/h1/high_level/h1_2_arm_sdk_dds_example.cpp (H1-2: 27). Both examples publish hg messages.
ARM_SDK_TOPIC = "rt/arm_sdk"
ARM_SDK_WEIGHT_SLOT = {"g1": 29, "h1_2": 27}
ARM_SDK_RAMP_S = 2.0  # the examples' arm initialisation time (init_time = 2.0 s)
# The G1's Dex3-1 hands (hands: dex3), from unitree_sdk2's example/g1/dex3/g1_dex3_example.cpp: HandCmd_ on
# rt/dex3/<side>/cmd, HandState_ on rt/lf/dex3/<side>/state (Unitree's teleoperation app reads
# rt/dex3/<side>/state: hand_state_topic changes it), 7 motors per hand in the order of Unitree's G1
# documentation. The hand motors take the joint_map slots after the 35 LowCmd_ slots: left, then right.
DEX3_SIDES = ("left", "right")
DEX3_ORDER = ("thumb_0", "thumb_1", "thumb_2", "middle_0", "middle_1", "index_0", "index_1")
DEX3_COMMAND_TOPIC = "rt/dex3/{side}/cmd"
DEX3_STATE_TOPIC = "rt/lf/dex3/{side}/state"
DEX3_FIRST_SLOT = 35  # = FAMILIES["hg"]
DEX3_MOTORS = len(DEX3_SIDES) * len(DEX3_ORDER)
DEX3_GRIP_GAINS = (1.5, 0.1)  # kp, kd of the example's grip (its sweep uses kp 0.5)


# unitree_sdk2 is a plain CMake package: no package.xml, no rosdep key, a non-namespaced target.
UNITREE_SDK2 = Dependency("unitree_sdk2", PLAIN_CMAKE, cmake_target="RHI_UNITREE_SDK2_TARGET", cmake_find="""\
# unitree_sdk2 is a plain CMake package (not a ROS package): install it with
#   cmake -S unitree_sdk2 -B build -DCMAKE_INSTALL_PREFIX=/opt/unitree_robotics && cmake --build build --target install
# or point CMAKE_PREFIX_PATH / unitree_sdk2_DIR at its installation. Its config file defines the
# non-namespaced imported target `unitree_sdk2` (static library) plus the `ddsc`/`ddscxx` CycloneDDS
# libraries it ships; a namespaced unitree_sdk2::unitree_sdk2 is accepted too.
find_package(unitree_sdk2 QUIET PATHS /opt/unitree_robotics)
set(RHI_UNITREE_SDK2_TARGET "")
if(TARGET unitree_sdk2::unitree_sdk2)
  set(RHI_UNITREE_SDK2_TARGET unitree_sdk2::unitree_sdk2)
elseif(TARGET unitree_sdk2)
  set(RHI_UNITREE_SDK2_TARGET unitree_sdk2)
endif()
""", package_xml_note=(
    "unitree_sdk2 is deliberately not declared: it is a plain CMake package without a",
    "package.xml and has no rosdep key, so declaring it would make every `rosdep install` fail.",
    "CMakeLists.txt finds it with find_package(unitree_sdk2) (default prefix /opt/unitree_robotics,",
    "or set CMAKE_PREFIX_PATH) and skips the Unitree robots when it is missing."))


@dataclass(frozen=True)
class UnitreeDdsOptions(TransportOptions):
    family: str = "hg"                 # hg (G1, H1-2) | go (H1, Go2, Go2-W, B2, B2-W) low-level messages
    motor_modes: tuple[int, ...] = ()  # go: MotorCmd_.mode of every slot (0x01 servo, 0x0A strong motor)
    verify_state_crc: bool = True      # drop LowState_ frames whose crc does not match
    lowcmd_topic: str = "rt/lowcmd"
    lowstate_topic: str = "rt/lowstate"
    sdk_slots: int = 35
    domain_id: int = 0
    mode_pr: int = 0
    release_motion_control: bool = False
    upper_body: bool = False           # authority upper_body: arm SDK commands, the legs left to the robot
    arm_sdk_topic: str = ARM_SDK_TOPIC
    arm_sdk_weight_slot: int = -1      # the LowCmd_ slot whose q carries the blend weight (-1: the robot's)
    arm_sdk_ramp_s: float = ARM_SDK_RAMP_S  # seconds for the blend weight from 0 to 1 (and back)
    hands: str = "none"                # dex3: the G1's Dex3-1 hands in slots 35..48 (HandCmd_/HandState_)
    hand_command_topic: str = DEX3_COMMAND_TOPIC  # "{side}" is left or right
    hand_state_topic: str = DEX3_STATE_TOPIC

    def hand_slots(self) -> range:
        """Dex3-1: the 14 slots after the 35 of a LowCmd_, the left hand's 7 motors then the right's."""
        return range(DEX3_FIRST_SLOT, DEX3_FIRST_SLOT + DEX3_MOTORS) if self.hands == "dex3" else range(0)

    def hand_topics(self, side: str) -> tuple[str, str]:
        """(command, state) topic of one hand."""
        return self.hand_command_topic.replace("{side}", side), self.hand_state_topic.replace("{side}", side)

# G1 29-DoF motor order, unitree_sdk2 enum G1JointIndex.
G1_ORDER = (
    "left_hip_pitch_joint", "left_hip_roll_joint", "left_hip_yaw_joint", "left_knee_joint",
    "left_ankle_pitch_joint", "left_ankle_roll_joint", "right_hip_pitch_joint", "right_hip_roll_joint",
    "right_hip_yaw_joint", "right_knee_joint", "right_ankle_pitch_joint", "right_ankle_roll_joint",
    "waist_yaw_joint", "waist_roll_joint", "waist_pitch_joint", "left_shoulder_pitch_joint",
    "left_shoulder_roll_joint", "left_shoulder_yaw_joint", "left_elbow_joint", "left_wrist_roll_joint",
    "left_wrist_pitch_joint", "left_wrist_yaw_joint", "right_shoulder_pitch_joint",
    "right_shoulder_roll_joint", "right_shoulder_yaw_joint", "right_elbow_joint",
    "right_wrist_roll_joint", "right_wrist_pitch_joint", "right_wrist_yaw_joint",
)
# G1 ankle-swing example gains: legs (hip pitch, roll, yaw, knee, ankle pitch, roll) x2, waist, arms.
_G1_KP = (60, 60, 60, 100, 40, 40) * 2 + (60, 40, 40) + (40,) * 14
_G1_KD = (1, 1, 1, 2, 1, 1) * 2 + (1,) * 17

# H1-2 27-DoF order, enum H1JointIndex of h1_27dof_example.cpp (= h1_2_handless.urdf file order).
_H1_2_SIDE = ("hip_yaw", "hip_pitch", "hip_roll", "knee", "ankle_pitch", "ankle_roll")
_H1_2_ARM = ("shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_roll", "wrist_pitch", "wrist_yaw")
H1_2_ORDER = (tuple(f"left_{j}_joint" for j in _H1_2_SIDE) + tuple(f"right_{j}_joint" for j in _H1_2_SIDE)
              + ("torso_joint",) + tuple(f"left_{j}_joint" for j in _H1_2_ARM)
              + tuple(f"right_{j}_joint" for j in _H1_2_ARM))

# Original H1 (go family), enum JointIndex of example/h1/low_level/motors.hpp: slot 9 drives no joint.
H1_ORDER = (
    "right_hip_roll_joint", "right_hip_pitch_joint", "right_knee_joint", "left_hip_roll_joint",
    "left_hip_pitch_joint", "left_knee_joint", "torso_joint", "left_hip_yaw_joint", "right_hip_yaw_joint", "",
    "left_ankle_joint", "right_ankle_joint", "right_shoulder_pitch_joint", "right_shoulder_roll_joint",
    "right_shoulder_yaw_joint", "right_elbow_joint", "left_shoulder_pitch_joint", "left_shoulder_roll_joint",
    "left_shoulder_yaw_joint", "left_elbow_joint",
)
# humanoid.hpp: strong motors (slots 0..9) mode 0x0A, kp 200 / kd 5; weak ones (10..19) 0x01, 60 / 1.5.
_H1_MODES = (GO_STRONG,) * 10 + (GO_SERVO,) * 10

# Quadrupeds: JointIndex of dds_wrapper/robots/go2/defines.h (FR, FL, RR, RL), then the wheels.
QUADRUPED_ORDER = tuple(f"{leg}_{part}_joint" for leg in ("FR", "FL", "RR", "RL")
                        for part in ("hip", "thigh", "calf"))
WHEELED_ORDER = QUADRUPED_ORDER + tuple(f"{leg}_foot_joint" for leg in ("FR", "FL", "RR", "RL"))


def _gains(order: Sequence[str], kp: Sequence[float], kd: Sequence[float]) -> tuple[tuple[str, float, float], ...]:
    return tuple((n, float(p), float(d)) for n, p, d in zip(order, kp, kd, strict=True) if n)


def _uniform(order: Sequence[str], kp: float, kd: float, wheel_kd: float | None = None
             ) -> tuple[tuple[str, float, float], ...]:
    """The same gains on every leg joint; wheels (…_foot_joint) take damping only."""
    return tuple((n, 0.0, wheel_kd) if wheel_kd is not None and n.endswith("_foot_joint") else (n, kp, kd)
                 for n in order if n)


def _quadruped(robot: str, order: tuple[str, ...], mode: int, kp: float, kd: float, wheel_kd: float | None,
               example: str, aliases: tuple[str, ...] = ()) -> KnownRobot:
    return KnownRobot(
        "unitree", robot, NAME, order, f"{robot} motor order: JointIndex of unitree_sdk2 dds_wrapper (FR, FL, RR, "
        "RL legs" + (", then the wheels 12..15)" if wheel_kd is not None else ")"), aliases=aliases, family="go",
        motor_modes=(mode,) * FAMILIES["go"], default_gains=_uniform(order, kp, kd, wheel_kd),
        gains_note=f"the gains of unitree_sdk2's {example}")


KNOWN_ROBOTS = (
    KnownRobot("unitree", "g1", NAME, G1_ORDER, "G1 29-DoF motor order from unitree_sdk2 enum G1JointIndex",
               family="hg", default_gains=_gains(G1_ORDER, _G1_KP, _G1_KD),
               gains_note="the gains of unitree_sdk2's g1_ankle_swing_example"),
    KnownRobot("unitree", "h1_2", NAME, H1_2_ORDER, "H1-2 27-DoF motor order from unitree_sdk2 enum H1JointIndex "
               "(h1_27dof_example.cpp)", aliases=("h12",), family="hg",
               gains_note="none: unitree_sdk2's H1-2 examples set no standing gains"),
    KnownRobot("unitree", "h1", NAME, H1_ORDER, "H1 motor order from unitree_sdk2 enum JointIndex "
               "(example/h1/low_level/motors.hpp; slot 9 drives no joint)", family="go", motor_modes=_H1_MODES,
               default_gains=tuple((n, 200.0, 5.0) if i < 10 else (n, 60.0, 1.5)
                                   for i, n in enumerate(H1_ORDER) if n),
               gains_note="the strong/weak motor gains of unitree_sdk2's example/h1/low_level/humanoid.hpp"),
    _quadruped("go2", QUADRUPED_ORDER, GO_SERVO, 60.0, 5.0, None, "go2_stand_example"),
    _quadruped("go2w", WHEELED_ORDER, GO_SERVO, 70.0, 5.0, 5.0, "go2w_stand_example", aliases=("go2_w",)),
    _quadruped("b2", QUADRUPED_ORDER, GO_STRONG, 1000.0, 10.0, None, "b2_stand_example"),
    _quadruped("b2w", WHEELED_ORDER, GO_SERVO, 1000.0, 10.0, 10.0, "b2w_stand_example", aliases=("b2_w",)),
)


class UnitreeDds(Transport):
    name = NAME
    summary = "unitree_sdk2 DDS: LowCmd_/LowState_ with CRC32, hg (35 motor slots) or go (20) messages"
    option_keys = ("family", "lowcmd_topic", "lowstate_topic", "sdk_slots", "domain_id", "mode_pr",
                   "motor_modes", "release_motion_control", "verify_state_crc", "arm_sdk_topic",
                   "arm_sdk_weight_slot", "arm_sdk_ramp_s", "hand_command_topic", "hand_state_topic")
    default_float_type = "float"
    dependencies = (UNITREE_SDK2,)
    shared_files = tuple(transport_header(NAME, name) for name in
                         ("unitree_crc.hpp", "unitree_hg.hpp", "unitree_go.hpp", "unitree_arm_sdk.hpp",
                          "unitree_dds.hpp", "unitree_dex3.hpp",
                          "unitree_dds_fake_robot.hpp"))
    fake_robot_header = "robot_hardware_interface/transport/unitree_dds_fake_robot.hpp"
    fake_state_rate_hz = 500.0  # LowState_ at 500 Hz (unitree_ros2 "HIGH_FREQ" lowstate)
    vendors = ("unitree",)
    known_robots = KNOWN_ROBOTS
    motor_slots = FAMILIES["hg"]
    slots_holder = "a unitree hg LowCmd_"

    def detect_hands(self, known: KnownRobot | None, actuated: Sequence[str]) -> HandSuggestion:
        """A G1 whose URDF has both Dex3-1 hands (g1_29dof_with_hand_rev_1_0.urdf): hands: dex3, the hand joints in
        the Dex3-1 motor order after the LowCmd_ slots, with the grip gains of unitree_sdk2's g1_dex3_example."""
        names = [f"{side}_hand_{motor}_joint" for side in DEX3_SIDES for motor in DEX3_ORDER]
        if known is None or known.robot != "g1" or not set(names) <= set(actuated):
            return HandSuggestion()
        return HandSuggestion("dex3", tuple((n, DEX3_FIRST_SLOT + i) for i, n in enumerate(names)),
                              tuple((n, *DEX3_GRIP_GAINS) for n in names),
                              "the grip gains of unitree_sdk2's example/g1/dex3/g1_dex3_example.cpp")

    def suggest_hands(self, known: KnownRobot | None, hands: HandSuggestion) -> list[str]:
        """The G1 can carry Dex3-1 hands: say how they are driven, or how to drive them (none stays the default)."""
        if hands.hands == "dex3":
            return ["# hands: dex3 drives the Dex3-1 hands too: motor_count 49, the hand joints in slots 35..41",
                    "# (left) and 42..48 (right) in the order " + ", ".join(DEX3_ORDER) + ",",
                    "# on HandCmd_ / HandState_ (see docs/hands.md).",
                    "hands: dex3"]
        if known is None or known.robot != "g1":
            return []
        return ["# hands: none drives the body only; dex3 drives the Dex3-1 hands too (motor_count 49, the",
                "# hand joints in slots 35..41 left and 42..48 right, in the order " + ", ".join(DEX3_ORDER) + ";",
                "# use the URDF with hands): see docs/hands.md.",
                "hands: none"]

    def suggest_authority(self, known: KnownRobot | None) -> list[str]:
        """A robot whose arm SDK rhi-gen knows gets the choice spelled out (full stays the default)."""
        if known is None or known.robot not in ARM_SDK_WEIGHT_SLOT:
            return []
        return ["# authority: full commands every joint (release the robot's motion controller first);",
                "# upper_body leaves the legs to the robot's balance controller and commands the waist and",
                f"# arms through the arm SDK ({ARM_SDK_TOPIC}): see docs/sharing-control.md.",
                "authority: full"]

    def motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """hg MotorState_: temperature[0], vol and motorstate; go MotorState_: one temperature (SDK_FACTS.md)."""
        assert isinstance(options, UnitreeDdsOptions)
        return ("temperature", "voltage", "error_code") if options.family == "hg" else ("temperature",)

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> UnitreeDdsOptions:
        p = "transport_options"
        family = v.optional(options, p, "family", lambda x, q: v.choice(x, q, tuple(FAMILIES)), "")
        sdk_slots = v.optional(options, p, "sdk_slots", v.integer_in(1, 1024), 0)
        modes: tuple[int, ...] = ()
        if "motor_modes" in options:
            modes = self._motor_modes(v, options["motor_modes"], f"{p}.motor_modes")
        return UnitreeDdsOptions(
            family=family,
            motor_modes=modes,
            verify_state_crc=v.optional(options, p, "verify_state_crc", v.boolean, True),
            lowcmd_topic=v.optional(options, p, "lowcmd_topic", v.topic, "rt/lowcmd"),
            lowstate_topic=v.optional(options, p, "lowstate_topic", v.topic, "rt/lowstate"),
            sdk_slots=sdk_slots,
            domain_id=v.optional(options, p, "domain_id", v.integer_in(0, 232), 0),
            mode_pr=v.optional(options, p, "mode_pr", v.integer_in(0, 1), 0),
            release_motion_control=v.optional(options, p, "release_motion_control", v.boolean, False),
            arm_sdk_topic=v.optional(options, p, "arm_sdk_topic", v.topic, ARM_SDK_TOPIC),
            arm_sdk_weight_slot=v.optional(options, p, "arm_sdk_weight_slot", v.integer_in(0, FAMILIES["hg"] - 1),
                                           -1),
            arm_sdk_ramp_s=v.optional(options, p, "arm_sdk_ramp_s",
                                      v.seconds_in(0.1, 60.0, "the blend weight's ramp time", 2.0), ARM_SDK_RAMP_S),
            hand_command_topic=v.optional(options, p, "hand_command_topic", self._hand_topic(v),
                                          DEX3_COMMAND_TOPIC),
            hand_state_topic=v.optional(options, p, "hand_state_topic", self._hand_topic(v), DEX3_STATE_TOPIC),
        )

    @staticmethod
    def _hand_topic(v: Validator) -> Any:
        """A hand topic pattern: "{side}" stands for left and right, and each must be a topic name."""
        def read(raw: Any, path: str) -> str:
            pattern = v.string(raw, path)
            fix = "e.g. rt/dex3/{side}/cmd"
            if pattern.count("{side}") != 1:
                raise v.error(path, f"{pattern!r} must contain {{side}} once (it stands for left and right)", fix=fix)
            if not TOPIC_RE.match(pattern.replace("{side}", "left")):
                raise v.error(path, f"{pattern!r} is not a ROS topic name once {{side}} is left or right (letters, "
                              "digits, _ and / separators)", fix=fix)
            return pattern
        return read

    def resolve_hands(self, v: Validator, hands: str, options: TransportOptions, *, vendor: str,
                      robot: str) -> UnitreeDdsOptions:
        """dex3: the hand motors become slots 35..48 (resolve_options then checks the family and motor_count)."""
        assert isinstance(options, UnitreeDdsOptions)
        check_hand_choice(v, hands, "dex3", NAME, "the G1 Dex3-1")
        return replace(options, hands=hands)

    def check_hand_map(self, v: Validator, options: TransportOptions,
                       joint_map: tuple[tuple[str, int], ...]) -> None:
        """Every Dex3-1 motor drives a joint: a HandCmd_ carries all 7 of a hand, and an unmapped one would be
        commanded to 0 with zero gains forever."""
        assert isinstance(options, UnitreeDdsOptions)
        mapped = {slot for _, slot in joint_map}
        missing = [slot for slot in options.hand_slots() if slot not in mapped]
        if missing:
            side = DEX3_SIDES[(missing[0] - DEX3_FIRST_SLOT) // len(DEX3_ORDER)]
            motor = DEX3_ORDER[(missing[0] - DEX3_FIRST_SLOT) % len(DEX3_ORDER)]
            last = DEX3_FIRST_SLOT + DEX3_MOTORS - 1
            raise v.error("joint_map", f"hands: dex3 drives slots {DEX3_FIRST_SLOT}..{last}, and no joint has "
                          f"slot {missing[0]} (the {side} hand's {motor} motor)",
                          fix=f"map {side}_hand_{motor}_joint: {missing[0]} (left hand 35..41, right 42..48, "
                              f"in the order {', '.join(DEX3_ORDER)})")

    def resolve_authority(self, v: Validator, authority: str, options: TransportOptions, *, vendor: str,
                          robot: str, mapped_slots: frozenset[int]) -> UnitreeDdsOptions:
        """upper_body speaks the arm SDK: hg messages only, the blend weight in a slot no joint drives."""
        assert isinstance(options, UnitreeDdsOptions)
        p = "transport_options"
        arm_keys = [k for k in ("arm_sdk_topic", "arm_sdk_weight_slot", "arm_sdk_ramp_s") if f"{p}.{k}" in v.lines]
        if authority == "full":
            if arm_keys:
                raise v.error(f"{p}.{arm_keys[0]}", "is an arm SDK option, used only with authority: upper_body",
                              fix=f"remove {arm_keys[0]}, or set authority: upper_body")
            return options
        if options.family != "hg":
            raise v.error("authority", f"upper_body speaks Unitree's arm SDK, which takes hg messages ("
                          f"{FAMILY_ROBOTS['hg']}); {vendor}/{robot} speaks {options.family}",
                          fix="remove authority (the default is full)")
        if options.release_motion_control:
            raise v.error(f"{p}.release_motion_control", "release_motion_control would stop the robot's own "
                          "controller, which keeps the legs under authority upper_body",
                          fix="set release_motion_control: false (the arm SDK needs the controller running)")
        known = _known(vendor, robot)
        slot = options.arm_sdk_weight_slot
        if slot < 0:
            slot = ARM_SDK_WEIGHT_SLOT.get(known.robot, -1) if known is not None else -1
        if slot < 0:
            raise v.error("authority", f"rhi-gen does not know which LowCmd_ slot carries {vendor}/{robot}'s "
                          "arm SDK blend weight", fix="set transport_options.arm_sdk_weight_slot (the "
                          "kNotUsedJoint of unitree_sdk2's arm SDK example for the robot)")
        if slot in mapped_slots:
            where = f"{p}.arm_sdk_weight_slot" if f"{p}.arm_sdk_weight_slot" in v.lines else "authority"
            raise v.error(where, f"slot {slot} carries the arm SDK blend weight, but joint_map drives a joint "
                          "with it", fix="give arm_sdk_weight_slot the robot's unused slot (kNotUsedJoint)")
        return replace(options, upper_body=True, arm_sdk_weight_slot=slot)

    @staticmethod
    def _motor_modes(v: Validator, raw: Any, path: str) -> tuple[int, ...]:
        if not isinstance(raw, list):
            raise v.error(path, f"must be a list of {FAMILIES['go']} motor modes, one per LowCmd_ slot",
                          fix="e.g. [1, 1, ...] (0x01 servo; the H1's strong motors use 10)")
        return tuple(v.integer(item, f"{path}[{i}]", 0, 255) for i, item in enumerate(raw))

    def resolve_options(self, v: Validator, options: TransportOptions, *, vendor: str, robot: str,
                        motor_count: int) -> UnitreeDdsOptions:
        """The message family (a known robot's, else the YAML must name it), its slot count and motor modes."""
        assert isinstance(options, UnitreeDdsOptions)  # made by read_options
        p = "transport_options"
        known = _known(vendor, robot)
        family = options.family or (known.family if known else "")
        if not family:
            raise v.error(f"{p}.family" if f"{p}.family" in v.lines else p,
                          f"rhi-gen does not know which low-level messages {vendor}/{robot} speaks",
                          fix="set transport_options.family: hg (" + FAMILY_ROBOTS["hg"] + ") or go ("
                              + FAMILY_ROBOTS["go"] + ")")
        slots = FAMILIES[family]
        if options.sdk_slots not in (0, slots):
            raise v.error(f"{p}.sdk_slots", f"unitree {family} messages have exactly {slots} motor slots, "
                          f"not {options.sdk_slots}", fix=f"remove sdk_slots or set it to {slots}")
        if options.hands == "dex3":
            if family != "hg":
                raise v.error("hands", f"the Dex3-1 hands speak hg messages ({FAMILY_ROBOTS['hg']}); "
                              f"{vendor}/{robot} speaks {family}", fix="remove hands (the default is none)")
            if motor_count != DEX3_FIRST_SLOT + DEX3_MOTORS:
                raise v.error("motor_count", f"with hands: dex3 the hand motors take slots {DEX3_FIRST_SLOT}.."
                              f"{DEX3_FIRST_SLOT + DEX3_MOTORS - 1} after the {slots} of a LowCmd_, so "
                              f"motor_count is {DEX3_FIRST_SLOT + DEX3_MOTORS}, not {motor_count}",
                              fix=f"set motor_count: {DEX3_FIRST_SLOT + DEX3_MOTORS}")
        elif motor_count > slots:
            raise ConfigError(f"motor_count {motor_count} exceeds the {slots} motor slots of the unitree {family} "
                              "LowCmd_", file=v.source, line=v.lines.get("motor_count"), key="motor_count",
                              fix=f"use at most {slots} motors, or check transport_options.family")
        modes = options.motor_modes
        if family == "go":
            modes = modes or (known.motor_modes if known and known.motor_modes else (GO_SERVO,) * slots)
            if len(modes) != slots:
                raise v.error(f"{p}.motor_modes", f"has {len(modes)} entries; a go LowCmd_ has {slots} slots",
                              fix=f"give one motor mode per slot ({slots} entries)")
        elif modes:
            raise v.error(f"{p}.motor_modes", "hg messages take no per-slot motor mode (driven slots are enabled)",
                          fix="remove motor_modes, or set family: go")
        return replace(options, family=family, sdk_slots=slots, motor_modes=modes)

    def slots_for(self, known: KnownRobot | None, given: Mapping[str, str]) -> tuple[int | None, str]:
        family = _new_family(known, given)
        if family:
            return FAMILIES[family], f"a unitree {family} LowCmd_"
        return self.motor_slots, self.slots_holder

    def check_new(self, vendor: str, robot: str, known: KnownRobot | None, given: Mapping[str, str]) -> None:
        """An unknown Unitree robot: the family cannot be guessed (one family's bytes are garbage to the other)."""
        if not (given.get("family") or (known.family if known is not None else "")):
            raise ConfigError(f"rhi-gen does not know which low-level messages {vendor}/{robot} speaks",
                              key="--transport-option",
                              fix="add --transport-option family=hg (" + FAMILY_ROBOTS["hg"] + ") or "
                                  "--transport-option family=go (" + FAMILY_ROBOTS["go"] + ")")
        if "family" in given and given["family"] not in FAMILIES:
            raise ConfigError(f"unknown unitree message family {given['family']!r}", key="--transport-option",
                              fix="use --transport-option family=hg or family=go")

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        family = _new_family(known, given or {})
        lines = [f"  family: {family}  # " + ("; ".join(f"{f}: {r}" for f, r in FAMILY_ROBOTS.items()))] \
            if family else []  # unknown robot: validation then asks for the family
        lines += ["  lowcmd_topic: rt/lowcmd", "  lowstate_topic: rt/lowstate"]
        if family:
            lines.append(f"  sdk_slots: {FAMILIES[family]}  # motor slots of a {family} LowCmd_ (fixed by the family)")
        lines.append("  domain_id: 0")
        if family == "go" and known is not None and known.motor_modes:
            lines.append(f"  motor_modes: [{', '.join(str(m) for m in known.motor_modes)}]  # MotorCmd_.mode per slot")
        if family != "go":
            lines.append("  mode_pr: 0  # hg: 0 PR (series pitch/roll), 1 AB (parallel ankle)")
        lines += ["  release_motion_control: false  # true: release the built-in motion controller first",
                  "  verify_state_crc: true"]
        return lines


def _known(vendor: str, robot: str) -> KnownRobot | None:
    """The Unitree robot rhi-gen knows by this name (its family, motor modes, arm SDK weight slot)."""
    return next((k for k in KNOWN_ROBOTS if k.vendor == vendor and k.named(robot)), None)


def _new_family(known: KnownRobot | None, given: Mapping[str, str]) -> str:
    """The family `rhi-gen new` writes: ``--transport-option family=`` over a known robot's; "" when
    there is none or it is not a family (check_new and the validator report those)."""
    family = given.get("family") or (known.family if known is not None else "")
    return family if family in FAMILIES else ""


TRANSPORT = UnitreeDds()
