"""Sharing a Unitree robot with its own controller (``authority: upper_body``) through the arm SDK.

The arm SDK takes a LowCmd_ on rt/arm_sdk, the blend weight in the q of the first unused slot: kNotUsedJoint
of unitree_sdk2's example/g1/high_level/g1_arm7_sdk_dds_example.cpp (G1: 29) and
example/h1/high_level/h1_2_arm_sdk_dds_example.cpp (H1-2: 27). Both examples publish hg messages.
"""
from __future__ import annotations

from dataclasses import replace

from ...typed_yaml.validator import Validator
from ..base import KnownRobot
from .options import UnitreeDdsOptions
from .protocol import ARM_SDK_TOPIC, ARM_SDK_WEIGHT_SLOT, FAMILY_ROBOTS

ARM_SDK_KEYS = ("arm_sdk_topic", "arm_sdk_weight_slot", "arm_sdk_ramp_s")


def authority_yaml_lines(known: KnownRobot | None) -> list[str]:
    """A robot whose arm SDK rhi-gen knows gets the choice spelled out (full stays the default)."""
    if known is None or known.robot not in ARM_SDK_WEIGHT_SLOT:
        return []
    return ["# authority: full commands every joint (release the robot's motion controller first);",
            "# upper_body leaves the legs to the robot's balance controller and commands the waist and",
            f"# arms through the arm SDK ({ARM_SDK_TOPIC}): see docs/sharing-control.md.",
            "authority: full"]


def resolve_arm_sdk(v: Validator, authority: str, options: UnitreeDdsOptions, known: KnownRobot | None, *,
                    vendor: str, robot: str, mapped_slots: frozenset[int]) -> UnitreeDdsOptions:
    """upper_body speaks the arm SDK: hg messages only, the blend weight in a slot no joint drives."""
    p = "transport_options"
    arm_keys = [k for k in ARM_SDK_KEYS if f"{p}.{k}" in v.lines]
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
