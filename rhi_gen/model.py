"""What a robot is: plain frozen data, no I/O.

Three layers, each built by its own module:
- ``UrdfRobot``   what the URDF says (urdf_loader.py)
- ``VendorConfig`` what the vendor YAML says (vendor_config.py)
- ``RobotModel``   both cross-checked, every C++ name decided (build.py); templates only read this.
"""
from __future__ import annotations

from dataclasses import dataclass, field

ACTUATED_TYPES = ("revolute", "continuous", "prismatic")
TRANSPORTS = ("unitree_dds", "agibot_topics", "engineai_topics", "generic_topics")
FLOAT_TYPES = ("float", "double")


# ---------------------------------------------------------------- URDF layer
@dataclass(frozen=True)
class JointLimits:
    lower: float | None = None
    upper: float | None = None
    velocity: float | None = None
    effort: float | None = None


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
class UrdfRobot:
    name: str
    source: str  # path as given (for messages)
    joints: tuple[UrdfJoint, ...]  # document order
    links: tuple[str, ...]
    ros2_control: tuple[Ros2ControlBlock, ...] = ()
    canonical_xml: bytes = b""  # expanded XML without the volatile xacro header, for hashing

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


# ---------------------------------------------------------------- vendor YAML layer
@dataclass(frozen=True)
class Parameters:
    """hardware_parameters written into the ros2_control description (spec defaults)."""
    network_interface: str = "lo"
    enable_monitor: bool = True
    command_writer_period_us: int = 2000
    state_decimation: int = 1
    state_timeout_ms: int = 100


@dataclass(frozen=True)
class ImuConfig:
    enabled: bool = True
    name: str = "base_imu"
    frame_id: str = "imu_link"


@dataclass(frozen=True)
class QosConfig:
    reliability: str = "best_effort"  # best_effort | reliable
    durability: str = "volatile"      # volatile | transient_local
    depth: int = 1


@dataclass(frozen=True)
class JointGroup:
    """A contiguous slice of SDK slots published/subscribed on its own topics (AgiBot)."""
    name: str
    size: int
    command_topic: str
    state_topic: str
    offset: int = 0  # first global slot index of this group (decided by vendor_config)


@dataclass(frozen=True)
class TransportOptions:
    """Union of every transport's options; vendor_config fills the ones its transport uses."""
    # unitree_dds
    lowcmd_topic: str = "rt/lowcmd"
    lowstate_topic: str = "rt/lowstate"
    sdk_slots: int = 35
    domain_id: int = 0
    mode_pr: int = 0
    release_motion_control: bool = False
    # ROS 2 topic transports
    command_topic: str = ""
    state_topic: str = ""
    imu_topic: str = ""
    groups: tuple[JointGroup, ...] = ()
    qos: QosConfig = field(default_factory=QosConfig)
    parallel_parser_type: int = 0  # engineai: 0 CLASSIC_PARSER, 1 RL_PARSER


@dataclass(frozen=True)
class VendorConfig:
    source: str            # YAML path as given (for messages)
    vendor: str
    robot: str
    urdf: str              # resolved path of the URDF/xacro
    urdf_relative: str     # as written in the YAML (relative to the YAML)
    transport: str
    motor_count: int
    float_type: str
    joint_map: tuple[tuple[str, int], ...]      # YAML order
    unmapped_joints: tuple[str, ...] = ()
    imu: ImuConfig = field(default_factory=ImuConfig)
    transport_options: TransportOptions = field(default_factory=TransportOptions)
    parameters: Parameters = field(default_factory=Parameters)
    xacro_args: tuple[tuple[str, str], ...] = ()
    package_paths: tuple[tuple[str, str], ...] = ()  # ROS package name -> directory (for $(find))
    class_prefix: str | None = None
    key_lines: dict[str, int] = field(default_factory=dict, compare=False, hash=False)


# ---------------------------------------------------------------- the decided model
@dataclass(frozen=True)
class MotorJoint:
    """A URDF joint driven by SDK slot ``index``."""
    name: str              # URDF joint name, raw text (escape with |cpp_string / |xml in templates)
    index: int             # SDK motor slot
    type: str              # revolute | continuous | prismatic
    limits: JointLimits | None
    group: str | None = None           # AgiBot group name
    group_position: int | None = None  # position inside the group


@dataclass(frozen=True)
class InputProvenance:
    yaml_path: str          # project-relative, POSIX
    urdf_path: str          # project-relative, POSIX
    yaml_sha256: str
    urdf_sha256: str        # of the expanded URDF without the volatile xacro header
    generator_version: str


@dataclass(frozen=True)
class RobotModel:
    vendor: str               # C++ namespace and folder, e.g. "unitree"
    robot: str                # file stem, e.g. "g1"
    robot_pascal: str         # "G1", "PM01", "MyArm"
    robot_upper: str          # "G1", "PM01", "MY_ARM"
    class_name: str           # "G1HardwareInterface"
    plugin_name: str          # "unitree/G1HardwareInterface"
    node_name: str            # "g1_hardware_interface"
    transport: str
    motor_count: int          # N of MotorCommand<N, T>
    float_type: str           # "float" | "double"
    joints: tuple[MotorJoint, ...]        # mapped joints, URDF order
    unmapped_joints: tuple[str, ...]      # actuated joints intentionally left out
    mimic_joints: tuple[str, ...]         # follow another joint, no interfaces
    imu: ImuConfig
    parameters: Parameters
    transport_options: TransportOptions
    provenance: InputProvenance
    urdf_name: str = ""

    @property
    def joints_by_index(self) -> tuple[MotorJoint, ...]:
        return tuple(sorted(self.joints, key=lambda j: j.index))

    @property
    def slot_names(self) -> tuple[str | None, ...]:
        """Joint name per SDK slot 0..motor_count-1, None where the slot is not mapped."""
        names: list[str | None] = [None] * self.motor_count
        for j in self.joints:
            names[j.index] = j.name
        return tuple(names)

    @property
    def vendor_pascal(self) -> str:
        return "".join(p[:1].upper() + p[1:] for p in self.vendor.split("_"))
