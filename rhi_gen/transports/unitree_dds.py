"""unitree_dds: unitree_sdk2 over DDS, "hg" LowCmd_/LowState_ with 35 motor slots, float, CRC32.

Facts from unitree_sdk2: topics rt/lowcmd and rt/lowstate, 35 slots in every hg message (the G1
uses 29), mode_pr 0 = pitch/roll, 1 = A/B ankle mode. The CRC header is shared by every Unitree
driver of the package, so it is generated once.
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..errors import ConfigError
from ..inputs.validator import Validator
from ..model import TransportOptions
from .base import PLAIN_CMAKE, Dependency, KnownRobot, Transport, transport_header

NAME = "unitree_dds"
HG_SLOTS = 35

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


class UnitreeDds(Transport):
    name = NAME
    summary = "unitree_sdk2 DDS: hg LowCmd_/LowState_ with CRC32, 35 motor slots"
    option_keys = ("lowcmd_topic", "lowstate_topic", "sdk_slots", "domain_id", "mode_pr", "release_motion_control")
    default_float_type = "float"
    dependencies = (Dependency("unitree_sdk2", PLAIN_CMAKE),)
    shared_files = tuple(transport_header(name) for name in
                         ("unitree_crc.hpp", "unitree_hg.hpp", "unitree_go.hpp", "unitree_dds.hpp"))
    vendors = ("unitree",)
    known_robots = (
        KnownRobot("unitree", "g1", NAME, G1_ORDER, "G1 29-DoF motor order from unitree_sdk2 enum G1JointIndex"),
    )
    motor_slots = HG_SLOTS
    slots_holder = "a unitree hg LowCmd_"

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> TransportOptions:
        p = "transport_options"
        sdk_slots = v.optional(options, p, "sdk_slots", v.integer_in(1, 1024), HG_SLOTS)
        if motor_count > sdk_slots:
            raise ConfigError(f"motor_count {motor_count} exceeds the {sdk_slots} motor slots of the "
                              "unitree hg LowCmd_", file=v.source, line=v.lines.get("motor_count"),
                              key="motor_count", fix=f"use at most {sdk_slots} motors")
        if sdk_slots != HG_SLOTS:
            raise v.error(f"{p}.sdk_slots", f"unitree hg messages have exactly {HG_SLOTS} motor slots, not {sdk_slots}",
                          fix="remove sdk_slots or set it to 35")
        return TransportOptions(
            lowcmd_topic=v.optional(options, p, "lowcmd_topic", v.topic, "rt/lowcmd"),
            lowstate_topic=v.optional(options, p, "lowstate_topic", v.topic, "rt/lowstate"),
            sdk_slots=sdk_slots,
            domain_id=v.optional(options, p, "domain_id", v.integer_in(0, 232), 0),
            mode_pr=v.optional(options, p, "mode_pr", v.integer_in(0, 1), 0),
            release_motion_control=v.optional(options, p, "release_motion_control", v.boolean, False),
        )

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None) -> list[str]:
        return ["  lowcmd_topic: rt/lowcmd", "  lowstate_topic: rt/lowstate", f"  sdk_slots: {HG_SLOTS}",
                "  domain_id: 0", "  mode_pr: 0",
                "  release_motion_control: false  # true: release the built-in motion controller first"]


TRANSPORT = UnitreeDds()
