"""`rhi-gen new`: write a vendor YAML whose joint map is suggested from the URDF.

The YAML text is built here (with comments a reviewer can read), then parsed back through the
normal validator, so `new` can never write a YAML that `generate` would reject.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Mapping

from .build import joint_name_problem
from .cpp_literals import yaml_string
from .errors import ConfigError, UrdfError
from .model import TRANSPORTS, UrdfJoint, UrdfRobot
from .naming import suggest
from .profiles import VendorProfile, find_profile, suggest_order
from .vendor_config import AGIBOT_DEFAULT_GROUPS, DEFAULT_FLOAT, MAX_MOTORS

UNITREE_SLOTS = 35


def _limits_comment(joint: UrdfJoint) -> str:
    lim = joint.limits
    parts = [joint.type]
    if lim is not None and lim.lower is not None and lim.upper is not None and joint.type != "continuous":
        parts.append(f"[{lim.lower:g}, {lim.upper:g}]")
    return " ".join(parts)


def suggest_yaml(*, vendor: str, robot: str, urdf: UrdfRobot, urdf_relative: str,
                 transport: str | None = None, xacro_args: Mapping[str, str] | None = None,
                 package_paths: Mapping[str, str] | None = None) -> str:
    """The text of a new vendor YAML for ``urdf``."""
    profile = find_profile(vendor, robot)
    if transport is None:
        transport = profile.transport if profile else "generic_topics"
    if transport not in TRANSPORTS:
        hint = suggest(transport, TRANSPORTS)
        raise ConfigError(f"unknown transport {transport!r}", key="--transport",
                          fix=(f"did you mean {hint!r}? " if hint else "") + f"use one of {', '.join(TRANSPORTS)}")
    if profile is not None and profile.transport != transport:
        profile = None  # the vendor order belongs to the vendor's own transport
    actuated = [j for j in urdf.actuated_joints]
    if not actuated:
        raise ConfigError("has no actuated joints (revolute, continuous or prismatic without <mimic>)",
                          file=urdf.source, fix="give the robot's full description")
    # Checked here, against the URDF, because the YAML does not exist yet: an error must name the
    # file and line the user can fix, not a line of a YAML that was never written.
    for joint in actuated:
        if (problem := joint_name_problem(joint.name)):
            raise UrdfError(problem, file=urdf.source, line=joint.line,
                            fix="rename the joint in the URDF (letters, digits and _ . / - : + [ ] ( ) # @)")
    if len(actuated) > MAX_MOTORS:
        raise ConfigError(f"has {len(actuated)} actuated joints; rhi-gen drives at most {MAX_MOTORS} motors "
                          "per robot", file=urdf.source,
                          fix="split the robot into several descriptions, or make the joints that no motor "
                              "drives fixed")
    by_name = {j.name: j for j in actuated}
    order = suggest_order([j.name for j in actuated], profile)
    motor_count = len(order)
    unmapped: list[str] = []
    if transport == "unitree_dds" and motor_count > UNITREE_SLOTS:
        raise ConfigError(f"has {motor_count} actuated joints but a unitree hg LowCmd_ has {UNITREE_SLOTS} "
                          "motor slots", file=urdf.source,
                          fix="use --transport generic_topics, or map a subset and list the rest under unmapped_joints")

    float_type = profile.float_type if profile else DEFAULT_FLOAT[transport]
    lines = [
        f"# Vendor YAML for {vendor}/{robot}, written by `rhi-gen new`.",
        "# Edit freely, then run `rhi-gen generate`; README.md has the full YAML reference.",
    ]
    if profile is not None and profile.note:
        lines.append(f"# joint_map follows the vendor's motor order: {profile.note}.")
    else:
        lines.append("# joint_map follows the URDF order: check it against your SDK's motor indices.")
    lines += [
        f"vendor: {vendor}",
        f"robot: {robot}",
        f"urdf: {yaml_string(urdf_relative)}",
        f"transport: {transport}",
        f"motor_count: {motor_count}",
        f"float_type: {float_type}",
    ]
    if xacro_args:
        lines.append("xacro_args:")
        lines += [f"  {yaml_string(k)}: {yaml_string(v)}" for k, v in xacro_args.items()]
    if package_paths:
        lines.append("package_paths:")
        lines += [f"  {yaml_string(k)}: {yaml_string(v)}" for k, v in package_paths.items()]
    lines += [
        "imu:",
        "  enabled: true",
        "parameters:",
        "  network_interface: lo",
        "  enable_monitor: true",
        "  command_writer_period_us: 2000",
        "  state_decimation: 1",
        "  state_timeout_ms: 100",
    ]
    lines += _transport_lines(transport, profile, order, motor_count)
    group_of = _group_labels(transport, profile, order)
    lines.append("joint_map:")
    for index, name in enumerate(order):
        label = f"{group_of[index]}, " if group_of else ""
        lines.append(f"  {yaml_string(name)}: {index}  # {label}{_limits_comment(by_name[name])}")
    lines.append("unmapped_joints: []" if not unmapped else "unmapped_joints:")
    lines += [f"  - {yaml_string(n)}" for n in unmapped]
    return "\n".join(lines) + "\n"


def _groups_for(profile: VendorProfile | None, order: list[str]) -> list[tuple[str, int]]:
    if profile is not None and profile.groups and sum(len(g) for _, g in profile.groups) == len(order):
        return [(name, len(members)) for name, members in profile.groups]
    if sum(size for _, size in AGIBOT_DEFAULT_GROUPS) == len(order):
        return list(AGIBOT_DEFAULT_GROUPS)
    return [("all", len(order))]


def _group_labels(transport: str, profile: VendorProfile | None, order: list[str]) -> list[str]:
    if transport != "agibot_topics":
        return []
    labels = []
    for name, size in _groups_for(profile, order):
        labels += [f"{name}[{i}]" for i in range(size)]
    return labels


def _transport_lines(transport: str, profile: VendorProfile | None, order: list[str], motor_count: int) -> list[str]:
    lines = ["transport_options:"]
    if transport == "unitree_dds":
        lines += ["  lowcmd_topic: rt/lowcmd", "  lowstate_topic: rt/lowstate", "  sdk_slots: 35",
                  "  domain_id: 0", "  mode_pr: 0",
                  "  release_motion_control: false  # true: release the built-in motion controller first"]
    elif transport == "agibot_topics":
        lines.append("  groups:")
        for name, size in _groups_for(profile, order):
            lines += [f"    - name: {name}", f"      size: {size}",
                      f"      command_topic: /aima/hal/joint/{name}/command",
                      f"      state_topic: /aima/hal/joint/{name}/state"]
        lines += ["  imu_topic: /aima/hal/imu/torso/state",
                  "  qos: {reliability: best_effort, durability: volatile, depth: 1}"]
    elif transport == "engineai_topics":
        lines += ["  command_topic: /hardware/joint_command", "  state_topic: /hardware/joint_state",
                  "  imu_topic: /hardware/imu_info", "  parallel_parser_type: 0  # 0 CLASSIC_PARSER, 1 RL_PARSER",
                  "  qos: {reliability: best_effort, durability: volatile, depth: 3}"]
    else:
        lines += ["  command_topic: /hardware/joint_commands", "  state_topic: /hardware/joint_states",
                  "  imu_topic: /hardware/imu",
                  "  qos: {reliability: best_effort, durability: volatile, depth: 1}"]
    return lines


def relative_urdf_path(urdf: Path, yaml_dir: Path) -> str:
    return Path(os.path.relpath(urdf.resolve(), yaml_dir.resolve())).as_posix()
