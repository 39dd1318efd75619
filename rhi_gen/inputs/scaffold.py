"""`rhi-gen new`: write a vendor YAML whose joint map is suggested from the URDF.

The YAML text is built here (with comments a reviewer can read), then parsed back through the
normal validator, so `new` can never write a YAML that `generate` would reject.
"""
from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from .. import transports
from ..errors import ConfigError, UrdfError
from ..model import MAX_MOTORS, UrdfJoint, UrdfRobot
from ..model.naming import joint_name_problem
from ..render.literals import yaml_string


def _limits_comment(joint: UrdfJoint) -> str:
    lim = joint.limits
    parts = [joint.type]
    if lim is not None and lim.lower is not None and lim.upper is not None and joint.type != "continuous":
        parts.append(f"[{lim.lower:g}, {lim.upper:g}]")
    return " ".join(parts)


def suggest_yaml(*, vendor: str, robot: str, urdf: UrdfRobot, urdf_relative: str,
                 transport: str | None = None, xacro_args: Mapping[str, str] | None = None,
                 package_paths: Mapping[str, str] | None = None, class_prefix: str | None = None,
                 urdf_comment: Sequence[str] = ()) -> str:
    """The text of a new vendor YAML for ``urdf``; ``urdf_comment``: comment lines above ``urdf:``."""
    known = transports.known_robot(vendor, robot)
    chosen = transports.for_vendor(vendor) if transport is None else transports.get(transport, key="--transport")
    if known is not None and known.transport != chosen.name:
        known = None  # the vendor order belongs to the vendor's own transport
    actuated = list(urdf.actuated_joints)
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
    order = transports.suggest_order([j.name for j in actuated], known)
    motor_count = len(order)
    if chosen.motor_slots is not None and motor_count > chosen.motor_slots:
        raise ConfigError(f"has {motor_count} actuated joints but {chosen.slots_holder} has {chosen.motor_slots} "
                          "motor slots", file=urdf.source,
                          fix=f"use --transport {transports.DEFAULT}, or map a subset and list the rest under "
                              "unmapped_joints")

    lines = [
        f"# Vendor YAML for {vendor}/{robot}, written by `rhi-gen new`.",
        "# Edit freely, then run `rhi-gen generate`; README.md has the full YAML reference.",
    ]
    if known is not None:
        lines.append(f"# joint_map follows the vendor's motor order: {known.note}.")
    else:
        lines.append("# joint_map follows the URDF order: check it against your SDK's motor indices.")
    lines += [
        f"vendor: {vendor}",
        f"robot: {robot}",
        *urdf_comment,
        f"urdf: {yaml_string(urdf_relative)}",
        f"transport: {chosen.name}",
        f"motor_count: {motor_count}",
        f"float_type: {chosen.default_float_type}",
    ]
    if class_prefix is not None:
        lines.append(f"class_prefix: {class_prefix}")
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
    lines += ["transport_options:", *chosen.suggest_options(order, known)]
    group_of = chosen.joint_labels(order, known)
    lines.append("joint_map:")
    for index, name in enumerate(order):
        label = f"{group_of[index]}, " if group_of else ""
        lines.append(f"  {yaml_string(name)}: {index}  # {label}{_limits_comment(by_name[name])}")
    lines.append("unmapped_joints: []")
    return "\n".join(lines) + "\n"


def relative_urdf_path(urdf: Path, yaml_dir: Path) -> str:
    """How the YAML in ``yaml_dir`` names ``urdf`` (POSIX, relative: the project moves between machines)."""
    return Path(os.path.relpath(urdf.resolve(), yaml_dir.resolve())).as_posix()
