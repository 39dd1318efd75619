"""What the URDF says: joints, limits, mimic joints, links and any existing <ros2_control> tag.

Built by inputs/urdf_loader.py; plain frozen data, no I/O.
"""
from __future__ import annotations

from dataclasses import dataclass

from .body import BodySummary

ACTUATED_TYPES = ("revolute", "continuous", "prismatic")
TRANSMISSION_KINDS = ("SimpleTransmission", "DifferentialTransmission")  # the <transmission>s rhi-gen applies


@dataclass(frozen=True)
class JointLimits:
    lower: float | None = None
    upper: float | None = None
    velocity: float | None = None
    effort: float | None = None


def safe_position(joint_type: str, limits: JointLimits | None) -> float:
    """The pose a joint starts from when the vendor YAML names none: zero, clamped into the URDF limits
    of a revolute or prismatic joint (a continuous joint has none)."""
    if joint_type not in ("revolute", "prismatic") or limits is None:
        return 0.0
    value = 0.0
    if limits.lower is not None:
        value = max(value, limits.lower)
    if limits.upper is not None:
        value = min(value, limits.upper)
    return value


def limits_problem(joint_type: str, limits: JointLimits | None, value: float) -> str | None:
    """Why ``value`` cannot be the position of a joint with these URDF limits, or None."""
    if joint_type not in ("revolute", "prismatic") or limits is None:
        return None
    if (limits.lower is not None and value < limits.lower) or (limits.upper is not None and value > limits.upper):
        return f"{value:g} is outside the URDF limits [{limits.lower:g}, {limits.upper:g}]" \
            if limits.lower is not None and limits.upper is not None else f"{value:g} is outside the URDF limits"
    return None


@dataclass(frozen=True)
class Mimic:
    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class UrdfJoint:
    name: str
    type: str  # revolute | continuous | prismatic | fixed | floating | planar
    parent: str
    child: str
    axis: tuple[float, float, float] = (1.0, 0.0, 0.0)
    limits: JointLimits | None = None
    mimic: Mimic | None = None
    line: int | None = None  # line in the (expanded) URDF, for error messages

    @property
    def actuated(self) -> bool:
        """A joint a motor drives: movable and not a mimic of another joint (ros2_control's view)."""
        return self.type in ACTUATED_TYPES and self.mimic is None


@dataclass(frozen=True)
class Ros2ControlJoint:
    """A <joint> inside an existing <ros2_control> tag of the URDF."""
    name: str
    command_interfaces: tuple[str, ...]
    state_interfaces: tuple[str, ...]
    line: int | None = None


@dataclass(frozen=True)
class Ros2ControlBlock:
    name: str
    type: str
    plugin: str | None
    joints: tuple[Ros2ControlJoint, ...]
    line: int | None = None


@dataclass(frozen=True)
class UrdfTransmission:
    """A <transmission> of the URDF (ROS 1 top-level ``<type>`` form, or ros2_control's ``<plugin>`` form
    inside <ros2_control>), read by inputs/urdf_transmissions.py into ros2_control's convention.

    Simple (one joint): joint = motor / reduction + offset, ``reduction`` signed (negative: the motor
    turns the other way). Differential (two joints): joint = matrix @ motor + offsets, motor k being
    the motor of ``joints[k]``. ``problem`` says why rhi-gen does not apply it ("" when it can)."""
    name: str
    kind: str                                  # the type as written, e.g. transmission_interface/SimpleTransmission
    joints: tuple[str, ...]                    # joint names in role order (joint1, joint2)
    offsets: tuple[float, ...] = ()            # per joint [rad or m]
    reduction: float = 1.0                     # Simple: actuator x joint mechanical reduction, signed
    matrix: tuple[tuple[float, ...], ...] = ()  # Differential: joint per motor
    problem: str = ""                          # why it is not applied ("" when it is)
    line: int | None = None                    # line in the URDF (None in a xacro expansion)

    @property
    def short_kind(self) -> str:
        """``SimpleTransmission`` for ``transmission_interface/SimpleTransmission``."""
        return self.kind.rsplit("/", 1)[-1] or "?"


@dataclass(frozen=True)
class UrdfRobot:
    name: str
    source: str  # path as given (for messages)
    joints: tuple[UrdfJoint, ...]  # document order
    links: tuple[str, ...]
    ros2_control: tuple[Ros2ControlBlock, ...] = ()
    transmissions: tuple[UrdfTransmission, ...] = ()  # document order
    canonical_xml: bytes = b""  # expanded XML without the volatile xacro header, for hashing
    root_link: str = ""         # the one link that is no joint's child
    root_has_inertia: bool = False  # the root link has an <inertial> (KDL refuses that root)
    body: BodySummary | None = None  # inertials and geometry summed up (None: not read, as in hand-built tests)

    @property
    def actuated_joints(self) -> tuple[UrdfJoint, ...]:
        return tuple(j for j in self.joints if j.actuated)

    @property
    def mimic_joints(self) -> tuple[UrdfJoint, ...]:
        return tuple(j for j in self.joints if j.mimic is not None and j.type in ACTUATED_TYPES)

    def joint(self, name: str) -> UrdfJoint | None:
        for j in self.joints:
            if j.name == name:
                return j
        return None
