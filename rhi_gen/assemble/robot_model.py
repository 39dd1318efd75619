"""Cross-check a vendor YAML against its URDF and decide every name: -> RobotModel.

This is where "joint not in the URDF", "actuated joint not mapped" and "mimic joint mapped to a
motor" are caught, each with the YAML line and a fix; each joint's transmission is decided by
``transmissions.py``. No file is written here.
"""
from __future__ import annotations

import hashlib
import os
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from .. import transports
from ..errors import ConfigError, UrdfError
from ..inputs.urdf_meshes import find_meshes
from ..model.config import ARMATURE_DEFAULT, ContactGeom, VendorConfig
from ..model.motor_groups import is_leg
from ..model.naming import joint_name_problem, pascal_case, plugin_name, suggest, upper_snake
from ..model.robot import InputProvenance, JointTransmission, KdlRoot, MotorJoint, RobotModel
from ..model.urdf import UrdfJoint, UrdfRobot, limits_problem, safe_position
from .joint_inertia import JointDynamics, joint_dynamics
from .transmissions import decide_transmissions


def sha256_hex(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def project_relative(path: str | Path, root: Path) -> str:
    """A POSIX path relative to the project root (never absolute: outputs must not depend on the machine)."""
    rel = os.path.relpath(os.path.abspath(path), os.path.abspath(root))
    return Path(rel).as_posix()


def build_model(config: VendorConfig, urdf: UrdfRobot, *, yaml_path: Path, project_root: Path) -> RobotModel:
    """Check ``config`` against ``urdf`` and decide every name the templates print."""
    lines = config.key_lines
    src = config.source

    def err(key: str, message: str, fix: str | None = None) -> ConfigError:
        return ConfigError(message, file=src, line=lines.get(key), key=key, fix=fix)

    by_name = {j.name: j for j in urdf.joints}
    all_names = [j.name for j in urdf.joints]
    urdf_shown = config.urdf_relative
    mapped: dict[str, int] = dict(config.joint_map)

    for name, _index in config.joint_map:
        key = f"joint_map.{name}"
        joint = by_name.get(name)
        if joint is None:
            hint = suggest(name, all_names)
            fix = f"did you mean {hint!r}?" if hint else "run `rhi-gen inspect --urdf` to list the joints"
            raise err(key, f"joint {name!r} is not in {urdf_shown}", fix)
        if joint.mimic is not None:
            raise err(key, f"joint {name!r} mimics {joint.mimic.joint!r}; a mimic joint has no motor "
                      "(ros2_control gives it no command interfaces)",
                      f"remove it from joint_map and map {joint.mimic.joint!r} instead")
        if not joint.actuated:
            raise err(key, f"joint {name!r} is a {joint.type} joint; only revolute, continuous and "
                      "prismatic joints are driven by motors", "remove it from joint_map")
        if (problem := joint_name_problem(name)):
            raise err(key, problem, f"rename the joint in {urdf_shown} (line {joint.line})")

    for i, name in enumerate(config.unmapped_joints):
        key = f"unmapped_joints[{i}]"
        joint = by_name.get(name)
        if joint is None:
            hint = suggest(name, all_names)
            raise err(key, f"joint {name!r} is not in {urdf_shown}",
                      f"did you mean {hint!r}?" if hint else "remove it")
        if not joint.actuated:
            raise err(key, f"joint {name!r} is not an actuated joint ({joint.type}"
                      f"{', mimic' if joint.mimic else ''}); only actuated joints need listing", "remove it")

    # The URDF as the loader names it (project-relative, or as given to `new`), not as the YAML spells it.
    _check_existing_ros2_control(urdf, by_name, urdf.source)

    actuated = urdf.actuated_joints
    if not actuated:
        raise ConfigError(f"{urdf_shown} has no actuated joints (revolute, continuous or prismatic "
                          "without <mimic>)", file=src, line=lines.get("urdf"), key="urdf",
                          fix="point urdf at the robot's full description")
    missing = [j.name for j in actuated if j.name not in mapped and j.name not in config.unmapped_joints]
    if missing:
        shown = ", ".join(repr(n) for n in missing[:4]) + (f" and {len(missing) - 4} more" if len(missing) > 4 else "")
        raise err("joint_map", f"{len(missing)} actuated joint(s) of {urdf_shown} have no motor index: {shown}",
                  "add them to joint_map, or list them under unmapped_joints if they are intentionally not driven")

    transport = transports.get(config.transport)
    modes = dict(config.command_modes)
    gains = {name: (kp, kd) for name, kp, kd in config.default_gains}
    for name, kp, _ in config.default_gains:
        if kp > 0 and modes.get(name, "velocity" if by_name[name].type == "continuous" else "position") == "velocity":
            raise err(f"default_gains.{name}.stiffness", f"joint {name!r} is velocity-commanded, so it takes no "
                      "stiffness", "remove stiffness (a velocity-commanded joint uses damping only), or set "
                      f"command_modes.{name}: position")
    targets = config.transport_options.position_target_slots()
    for name in [n for n, _ in config.command_modes] + [n for n, _, _ in config.default_gains]:
        if mapped.get(name) in targets:
            key = "command_modes" if name in modes else "default_gains"
            raise err(f"{key}.{name}", f"joint {name!r} is a hand axis that takes position targets only (hands: "
                      f"{config.hands}): the hand's own controller tracks them, so it takes no command mode or gains",
                      f"remove {key}.{name}")
    initial = dict(config.initial_positions)
    armatures = dict(config.armatures)
    joint_damping, joint_frictionloss = dict(config.joint_damping), dict(config.joint_frictionloss)
    for name, value in config.initial_positions:
        joint = by_name[name]
        if (problem := limits_problem(joint.type, joint.limits, value)):
            raise err(f"initial_positions.{name}", f"joint {name!r}: {problem} ({urdf_shown} line {joint.line})",
                      f"use a position inside the limits, e.g. {safe_position(joint.type, joint.limits):g}")
    decided = decide_transmissions(config, urdf)
    dynamics = joint_dynamics(urdf.canonical_xml.decode("utf-8", errors="replace"))
    joints = []
    for joint in actuated:
        if joint.name not in mapped:
            continue
        index = mapped[joint.name]
        group, position = config.transport_options.joint_group(index) or (None, None)
        mode = modes.get(joint.name, "velocity" if joint.type == "continuous" else "position")
        if config.authority == "upper_body" and is_leg(joint.name):
            mode = "state"  # the robot's own controller keeps it: no command interfaces, no gains
        if index in targets:
            mode = "position_target"  # the hand's own controller tracks a position target: no gains
        stiffness, damping = gains.get(joint.name, (0.0, 0.0)) if mode != "state" else (0.0, 0.0)
        joints.append(MotorJoint(name=joint.name, index=index, type=joint.type, limits=joint.limits,
                                 group=group, group_position=position, command_mode=mode,
                                 command_interfaces=transport.command_interfaces(mode) if mode != "state" else (),
                                 state_interfaces=("position", "velocity", "effort",
                                                   *transport.motor_health(config.transport_options)),
                                 default_stiffness=stiffness if mode == "position" else 0.0,
                                 default_damping=damping,
                                 initial_position=initial.get(joint.name, safe_position(joint.type, joint.limits)),
                                 transmission=decided.joints.get(joint.name, JointTransmission()),
                                 armature=armatures.get(joint.name, ARMATURE_DEFAULT),
                                 **_simulated(dynamics.get(joint.name), joint_damping.get(joint.name),
                                              joint_frictionloss.get(joint.name))))

    if config.authority == "upper_body" and all(j.command_mode == "state" for j in joints):
        raise err("authority", "upper_body leaves the legs (hip, knee, ankle joints) to the robot's own controller, "
                  "and every joint of joint_map is a leg", "remove authority (the default is full)")

    imu = config.imu
    if imu.enabled:
        links = list(urdf.links)
        if "imu.frame_id" in lines:
            if imu.frame_id not in links:
                hint = suggest(imu.frame_id, links)
                raise err("imu.frame_id", f"{imu.frame_id!r} is not a link of {urdf_shown}",
                          (f"did you mean {hint!r}? " if hint else "") + "or set imu.enabled: false")
        else:
            imu = replace(imu, frame_id=default_imu_frame(urdf))

    pascal = config.class_prefix or pascal_case(config.robot)
    provenance = InputProvenance(
        yaml_path=project_relative(yaml_path, project_root),
        urdf_path=project_relative(config.urdf, project_root),
        yaml_sha256=config.content_sha256,
        urdf_sha256=sha256_hex(urdf.canonical_xml),
    )
    meshes, missing_meshes = find_meshes(urdf.canonical_xml, config.urdf, project_root, config.robot)
    return RobotModel(
        vendor=config.vendor, robot=config.robot, robot_pascal=pascal,
        robot_upper=upper_snake(config.robot) if not config.class_prefix else upper_snake(pascal),
        class_name=f"{pascal}HardwareInterface", plugin_name=plugin_name(config.vendor, f"{pascal}HardwareInterface"),
        node_name=f"{config.robot}_hardware_interface", transport=config.transport,
        motor_count=config.motor_count, float_type=config.float_type, joints=tuple(joints),
        unmapped_joints=tuple(config.unmapped_joints),
        mimic_joints=tuple(j.name for j in urdf.mimic_joints),
        imu=imu, parameters=config.parameters, transport_options=config.transport_options,
        provenance=provenance, coupled_groups=decided.groups, urdf_name=urdf.name,
        urdf_xml=urdf.canonical_xml.decode("utf-8", errors="replace"), authority=config.authority,
        hands=config.hands, kdl_root=kdl_root(urdf), contacts=_contacts(config, urdf, err), body=urdf.body,
        meshes=meshes, missing_meshes=missing_meshes,
    )


def kdl_root(urdf: UrdfRobot) -> KdlRoot | None:
    """The massless root the installed URDF puts above a root link with an inertia (None when the root has
    none): KDL, and so robot_state_publisher, ignores a root's inertia with a warning on every launch.
    ``base_link`` as ROS descriptions name it, unless the robot already has a link of that name."""
    if not urdf.root_has_inertia:
        return None
    link = "base_link"
    while link in urdf.links:
        link = f"{urdf.root_link}_root" if link == "base_link" else link + "_"
    joints = {j.name for j in urdf.joints}
    joint = f"{link}_to_{urdf.root_link}"
    while joint in joints:
        joint += "_"
    return KdlRoot(link=link, joint=joint, child=urdf.root_link)


def _check_existing_ros2_control(urdf: UrdfRobot, by_name: dict[str, UrdfJoint], urdf_shown: str) -> None:
    """Apply ros2_control's own rules to a <ros2_control> tag already in the URDF.

    The controller manager loads the whole robot_description, so a broken tag there breaks the
    generated driver too: every joint must exist, and a mimic joint takes no command interface.
    """
    for block in urdf.ros2_control:
        for rc_joint in block.joints:
            joint = by_name.get(rc_joint.name)
            if joint is None:
                raise UrdfError(f"<ros2_control name={block.name!r}> names joint {rc_joint.name!r}, which is "
                                "not a joint of the URDF (ros2_control rejects this)", file=urdf_shown,
                                line=rc_joint.line, fix="fix the joint name or remove it from the tag")
            if joint.mimic is not None and rc_joint.command_interfaces:
                raise UrdfError(f"<ros2_control name={block.name!r}> gives mimic joint {rc_joint.name!r} command "
                                "interfaces; ros2_control allows only state interfaces on mimic joints",
                                file=urdf_shown, line=rc_joint.line, fix="remove its <command_interface> tags")


def default_imu_frame(urdf: UrdfRobot) -> str:
    """A link whose name says IMU, else the root link: a frame that exists in the robot."""
    for link in urdf.links:
        if "imu" in link.lower():
            return link
    children = {j.child for j in urdf.joints}
    roots = [link for link in urdf.links if link not in children]
    return roots[0] if roots else (urdf.links[0] if urdf.links else "base_link")


def _simulated(dynamics: JointDynamics | None, damping: float | None, frictionloss: float | None) -> dict[str, float]:
    """The fake robot's inertia and damping of a joint (the defaults when the URDF parse found none), and the
    physics' damping and dry friction: the vendor YAML's, else the URDF's <dynamics>."""
    out = {} if dynamics is None else {"inertia": dynamics.inertia, "damping": dynamics.damping,
                                       "physics_damping": dynamics.urdf_damping,
                                       "frictionloss": dynamics.urdf_friction}
    if damping is not None:
        out["physics_damping"] = damping
    if frictionloss is not None:
        out["frictionloss"] = frictionloss
    return out


def _contacts(config: VendorConfig, urdf: UrdfRobot, err: Callable[..., ConfigError]) -> tuple[ContactGeom, ...]:
    """The YAML's contacts, each on a link of the URDF."""
    links = list(urdf.links)
    for c in config.contacts:
        if c.link not in links:
            hint = suggest(c.link, links)
            raise err(f"contacts.{c.link}", f"{c.link!r} is not a link of {config.urdf_relative}",
                      (f"did you mean {hint!r}? " if hint else "") + "name the URDF link the shapes belong to")
    return config.contacts
