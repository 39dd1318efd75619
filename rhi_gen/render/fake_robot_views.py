"""View-model of a robot's fake robot source: its joints as the motors the fake robot simulates.

The fake robot stands on the robot's side of the transport, so it simulates motors: a joint whose
motor is not the joint itself (a SimpleTransmission: joint = direction * motor / reduction + offset)
is simulated in motor units, its limits, inertia and start pose converted the way the firmware sees
them. A coupled joint's motors get no limits (a matrix mixes them); rows are in slot order.
For the physics (--physics mujoco, common/fake_physics_mujoco.hpp), which simulates the URDF's joints,
each row also carries its transmission (gain, offset; a coupled joint's is one to one), and the view
the package's URDF and the IMU's link.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .. import transports
from ..model import RobotModel
from ..model.config import ContactGeom
from ..model.robot import MotorJoint


@dataclass(frozen=True)
class FakeJointLine:
    joint: str
    slot: int
    position_min: float   # -inf / inf: no limit
    position_max: float
    velocity_max: float
    effort_max: float
    inertia: float
    damping: float
    initial_position: float
    velocity_commanded: bool = False  # a wheel
    armature: float = 0.01  # [kg m^2 or kg] the rotor inertia reflected to the URDF joint, for the physics
    gain: float = 1.0     # its transmission, for the physics: motor = gain * (joint - offset)
    offset: float = 0.0
    physics_damping: float = 0.0  # the physics' passive damping and dry friction of the URDF joint
    frictionloss: float = 0.0


@dataclass(frozen=True)
class FakeRobotView:
    joints: tuple[FakeJointLine, ...]
    rate_hz: float        # the robot's state rate: the fake robot's loop
    node_name: str        # also its executable's name
    urdf: str             # its URDF in the package's share folder, for --physics mujoco
    imu_link: str         # the URDF link of its IMU, "" without one (the physics then puts it at the root)
    contacts: tuple[ContactGeom, ...] = ()  # the YAML's, for the physics when meshes are missing

    @property
    def has_transmissions(self) -> bool:
        return any((j.gain, j.offset) != (1.0, 0.0) for j in self.joints)

    @property
    def uses_no_limit(self) -> bool:
        return any(math.isinf(v) for j in self.joints
                   for v in (j.position_min, j.position_max, j.velocity_max, j.effort_max))


def _bound(value: float | None) -> float:
    return value if value is not None and value > 0 else math.inf


def _line(joint: MotorJoint, coupled: bool) -> FakeJointLine:
    lim = joint.limits
    lower, upper = -math.inf, math.inf
    if joint.type != "continuous" and lim is not None and lim.lower is not None and lim.upper is not None \
            and lim.lower < lim.upper:
        lower, upper = lim.lower, lim.upper
    bounded = not math.isinf(lower)
    velocity = _bound(lim.velocity if lim is not None else None)
    effort = _bound(lim.effort if lim is not None else None)
    t = joint.transmission
    if coupled:
        return FakeJointLine(joint.name, joint.index, -math.inf, math.inf, math.inf, math.inf, joint.inertia,
                             joint.damping, 0.0)
    if t.is_identity:
        return FakeJointLine(joint.name, joint.index, lower, upper, velocity, effort, joint.inertia, joint.damping,
                             joint.initial_position)
    gain = t.direction * t.reduction  # motor = gain * (joint - offset)
    ends = sorted((gain * (lower - t.offset), gain * (upper - t.offset))) if bounded else [-math.inf, math.inf]
    return FakeJointLine(joint.name, joint.index, ends[0], ends[1], velocity * t.reduction, effort / t.reduction,
                         float(f"{joint.inertia / t.reduction ** 2:.6g}"), joint.damping,
                         gain * (joint.initial_position - t.offset), gain=float(gain), offset=t.offset)


def has_fake_robot(robot: RobotModel) -> bool:
    """Whether the robot's transport has a fake robot side (the package then builds <robot>_fake_robot)."""
    return bool(transports.get(robot.transport).fake_robot_header)


def fake_robot_view(robot: RobotModel) -> FakeRobotView:
    coupled = {name for group in robot.coupled_groups for name in group.joints}
    transport = transports.get(robot.transport)
    lines = (replace(_line(j, j.name in coupled), velocity_commanded=j.command_mode == "velocity",
                     armature=j.armature, physics_damping=j.physics_damping, frictionloss=j.frictionloss)
             for j in robot.joints_by_index)
    return FakeRobotView(tuple(lines),
                         transport.fake_state_rate_hz, f"{robot.robot}_fake_robot", f"urdf/{robot.robot}.urdf",
                         robot.imu.frame_id if robot.imu.enabled else "", robot.contacts)
