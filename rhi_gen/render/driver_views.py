"""View-model of a robot's driver source: its motors that are not joints and each joint's motor group,
as the tables the C++ reads.

The templates place these values (``|cpp_double``); which joints are listed and in which order is
decided here: every joint whose transmission is not the identity and every joint of a coupled group
(for its offset), in URDF order; groups in model order, named by position so no joint name has to
become a C++ identifier.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..model import RobotModel
from .bringup_views import start_controllers


@dataclass(frozen=True)
class TransmissionLine:
    joint: str         # URDF joint name, for the comment
    slot: int
    direction: float
    reduction: float
    offset: float


@dataclass(frozen=True)
class CoupledView:
    name: str                      # the group's name (a C++ string)
    identifier: str                # kCoupled<k>: the prefix of its slot and matrix arrays
    joints: tuple[str, ...]        # for the comment
    slots: tuple[int, ...]
    matrix: tuple[float, ...]      # row-major, joint per motor


@dataclass(frozen=True)
class DriverView:
    transmissions: tuple[TransmissionLine, ...]
    groups: tuple[CoupledView, ...]
    motor_group_of: dict[int, int] | None = None  # SDK slot -> index of its motor group (RobotSpec)
    launch_controllers: str = ""  # the controllers the robot's launch file activates, space-separated

    @property
    def has_transmission(self) -> bool:
        return bool(self.transmissions or self.groups)


def driver_view(robot: RobotModel) -> DriverView:
    coupled = {name for group in robot.coupled_groups for name in group.joints}
    slot = {joint.name: joint.index for joint in robot.joints}
    lines = tuple(TransmissionLine(joint.name, joint.index, float(joint.transmission.direction),
                                   joint.transmission.reduction, joint.transmission.offset)
                  for joint in robot.joints if joint.name in coupled or not joint.transmission.is_identity)
    groups = tuple(CoupledView(group.name, f"kCoupled{k}", group.joints, tuple(slot[name] for name in group.joints),
                               tuple(value for row in group.matrix for value in row))
                   for k, group in enumerate(robot.coupled_groups))
    return DriverView(lines, groups, {slot: k for k, group in enumerate(robot.motor_groups) for slot in group.slots},
                      " ".join(start_controllers(robot)[0]))
