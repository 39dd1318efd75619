"""unitree_dds: unitree_sdk2 over DDS, LowCmd_/LowState_ with CRC32, float.

Two message families (SDK_FACTS.md sections A and D): "hg" (35 motor slots, mode_pr and
mode_machine) for G1 and H1-2; "go" (20 slots, head/level_flag framing, a motor mode per slot)
for the original H1, Go2, Go2-W, B2 and B2-W. Known robots bring their family, their real SDK motor
order, motor modes and the gains of the SDK's own low-level examples; an unknown Unitree robot must
name its family (sending one family's bytes to the other commands garbage). The CRC and message
headers are shared by every Unitree driver of the package, so they are generated once.

This module is the transport's interface to rhi-gen; the facts live beside it: protocol.py (message
families, arm SDK), known_robots.py (motor orders and example gains), options.py (transport_options),
dex3.py (the Dex3-1 hands) and arm_sdk.py (authority upper_body).
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

from ...errors import ConfigError
from ...model import TransportOptions
from ...typed_yaml.validator import Validator
from ..base import PLAIN_CMAKE, Dependency, HandSuggestion, KnownRobot, Transport, check_hand_choice, transport_header
from .arm_sdk import authority_yaml_lines, resolve_arm_sdk
from .dex3 import (
    DEX3_COMMAND_TOPIC,
    DEX3_FIRST_SLOT,
    DEX3_MOTORS,
    DEX3_STATE_TOPIC,
    check_dex3_map,
    detect_dex3,
    dex3_yaml_lines,
    hand_topic_reader,
)
from .known_robots import KNOWN_ROBOTS, known_robot
from .options import UnitreeDdsOptions
from .protocol import ARM_SDK_RAMP_S, ARM_SDK_TOPIC, FAMILIES, FAMILY_ROBOTS, GO_SERVO, NAME

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
        return detect_dex3(known, actuated)

    def suggest_hands(self, known: KnownRobot | None, hands: HandSuggestion) -> list[str]:
        return dex3_yaml_lines(known, hands)

    def suggest_authority(self, known: KnownRobot | None) -> list[str]:
        return authority_yaml_lines(known)

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
            hand_command_topic=v.optional(options, p, "hand_command_topic", hand_topic_reader(v),
                                          DEX3_COMMAND_TOPIC),
            hand_state_topic=v.optional(options, p, "hand_state_topic", hand_topic_reader(v), DEX3_STATE_TOPIC),
        )

    def resolve_hands(self, v: Validator, hands: str, options: TransportOptions, *, vendor: str,
                      robot: str) -> UnitreeDdsOptions:
        """dex3: the hand motors become slots 35..48 (resolve_options then checks the family and motor_count)."""
        assert isinstance(options, UnitreeDdsOptions)
        check_hand_choice(v, hands, "dex3", NAME, "the G1 Dex3-1")
        return replace(options, hands=hands)

    def check_hand_map(self, v: Validator, options: TransportOptions,
                       joint_map: tuple[tuple[str, int], ...]) -> None:
        assert isinstance(options, UnitreeDdsOptions)
        check_dex3_map(v, options.hand_slots(), joint_map)

    def resolve_authority(self, v: Validator, authority: str, options: TransportOptions, *, vendor: str,
                          robot: str, mapped_slots: frozenset[int]) -> UnitreeDdsOptions:
        assert isinstance(options, UnitreeDdsOptions)
        return resolve_arm_sdk(v, authority, options, known_robot(vendor, robot), vendor=vendor, robot=robot,
                               mapped_slots=mapped_slots)

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
        known = known_robot(vendor, robot)
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


def _new_family(known: KnownRobot | None, given: Mapping[str, str]) -> str:
    """The family `rhi-gen new` writes: ``--transport-option family=`` over a known robot's; "" when
    there is none or it is not a family (check_new and the validator report those)."""
    family = given.get("family") or (known.family if known is not None else "")
    return family if family in FAMILIES else ""


TRANSPORT = UnitreeDds()
