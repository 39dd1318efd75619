"""What the vendor YAML says, validated: plain frozen data, no I/O.

Built by inputs/vendor_config.py (the transport_options by the robot's transport, whose options
subclass of ``TransportOptions`` lives in its folder transports/<name>/); cross-checked against the
URDF by assemble/robot_model.py.
"""
from __future__ import annotations

from dataclasses import dataclass, field

FLOAT_TYPES = ("float", "double")
# Who commands the robot (vendor YAML `authority`): the driver alone, or the driver for everything above
# the legs while the robot's own balance controller keeps the legs (Unitree's arm SDK).
AUTHORITIES = ("full", "upper_body")
# The robot's hands (vendor YAML `hands`): none, or a hand its transport drives beside the body (the G1's
# Dex3-1 over unitree_sdk2, the X2's OmniHands over AimDK; hand motors in the joint_map slots after the body's).
HANDS = ("none", "dex3", "omnihand")
# The rotor inertia reflected to a joint the vendor YAML gives none for [kg m^2, or kg for a prismatic joint]: what
# unitree_mujoco's robot models give their joints (armature 0.01), the order of a humanoid's geared motors.
ARMATURE_DEFAULT = 0.01
MAX_ARMATURE = 100.0  # far above any real rotor; a typo of a few zeros still fails
MAX_JOINT_FRICTION = 1e4  # [N m or N s/m] joint_damping / joint_frictionloss: far above any real joint
# The collision shapes vendor YAML `contacts` take, as URDF <geometry> names them.
CONTACT_SHAPES = ("sphere", "box", "cylinder")
MAX_CONTACTS = 256  # per robot: a foot is a few primitives; far more is a mistake
MAX_MOTORS = 4096  # per robot: far above any real robot, low enough to keep the generated tables sane


@dataclass(frozen=True)
class ContactGeom:
    """A collision primitive the vendor YAML `contacts` give a URDF link, in the URDF's terms. It stands in for
    the link's mesh collisions when the meshes are not installed (the fake robot's physics), so that the
    contacts that matter (feet) stay: the vendor's own MuJoCo model's primitives."""
    link: str
    shape: str                                 # CONTACT_SHAPES
    size: tuple[float, float, float]           # sphere (radius, 0, 0); box (x, y, z); cylinder (radius, length, 0)
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)   # [m] origin in the link's frame
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)   # [rad] URDF <origin rpy>


@dataclass(frozen=True)
class PackageInfo:
    """robots/package.yaml: who owns the generated package (copyright and license lines of every
    generated file, package.xml's license and maintainer). The defaults name no one: they say the
    package belongs to its authors under the license package.xml declares until the project says
    otherwise."""
    copyright: str = "the robot_hardware_interface authors"  # text after "Copyright"
    license: str = "Apache-2.0"                             # SPDX identifier
    maintainer_name: str = "rhi-gen user"
    maintainer_email: str = "rhi-gen-user@example.com"
    source: str = ""  # project-relative path of the file, "" when the project has none


@dataclass(frozen=True)
class Parameters:
    """hardware_parameters written into the ros2_control description (spec defaults)."""
    network_interface: str = "lo"
    enable_monitor: bool = False          # console timing warnings; overruns are on /diagnostics anyway
    command_writer_period_us: int = 2000
    command_writer_mode: str = "timer"    # or "on_write": the command leaves when write() has built it
    state_decimation: int = 1
    state_timeout_ms: int = 100
    fault_timeout_ms: int = 1000
    first_state_timeout_ms: int = 10000   # after activation, until the first state (DDS discovery)
    diagnostics_period_ms: int = 1000     # /diagnostics every this long, 0: none
    motor_temperature_warn_c: int = 70    # /diagnostics: a motor this hot is WARN ...
    motor_temperature_error_c: int = 85   # ... and this hot ERROR (rhi-gen's defaults, not a vendor's)
    motor_error_fault_mask: int = 0       # motor error code bits that fault the robot (0: codes never do)
    # Attributes of the <ros2_control> tag rather than driver parameters (ros2_control runs the component):
    is_async: bool = False                # read()/write() in a thread of their own (Jazzy and later)
    rw_rate: int = 0                      # read()/write() per second, 0: the controller manager's rate


@dataclass(frozen=True)
class ImuConfig:
    enabled: bool = True
    name: str = "base_imu"
    frame_id: str = "imu_link"


@dataclass(frozen=True)
class TransportOptions:
    """What every transport's options have in common; each transport subclasses it in its own folder
    (transports/<name>/: its fields, their defaults and validation), and the robot's transport fills
    the subclass. Templates read the fields by name: ``robot.transport_options.<field>``."""
    sdk_slots: int = 0  # motor slots of the SDK message (the motor count where the SDK has no fixed size)

    def joint_group(self, index: int) -> tuple[str, int] | None:
        """(group name, position in the group) of SDK slot ``index``, for a transport that groups its
        slots (AgiBot); None by default."""
        return None

    def hand_slots(self) -> range:
        """The joint_map slots the transport drives as hand motors (their own messages); none by default."""
        return range(0)

    def position_target_slots(self) -> range:
        """Slots whose motor takes a position target only, tracked by the robot's own controller (an OmniHand):
        their joints export the position command alone; none by default."""
        return range(0)


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
    # joint -> (stiffness, damping) applied while no controller claims them (YAML default_gains)
    default_gains: tuple[tuple[str, float, float], ...] = ()
    # joint -> "position" | "velocity" (YAML command_modes); continuous joints default to velocity
    command_modes: tuple[tuple[str, str], ...] = ()
    # joint -> rad (or m) the description starts the joint at (YAML initial_positions); checked against
    # the URDF limits in assemble/robot_model.py
    initial_positions: tuple[tuple[str, float], ...] = ()
    # joint -> kg m^2 (kg for a prismatic joint): the rotor inertia reflected to the joint, for the fake robot's
    # physics (YAML armatures; ARMATURE_DEFAULT for a joint not listed)
    armatures: tuple[tuple[str, float], ...] = ()
    # joint -> N m s/rad (N s/m) and N m (N): the physics' passive damping and dry friction, in place of the
    # URDF's <dynamics damping friction> (YAML joint_damping, joint_frictionloss: the vendor's MuJoCo model's)
    joint_damping: tuple[tuple[str, float], ...] = ()
    joint_frictionloss: tuple[tuple[str, float], ...] = ()
    # collision primitives per link, for the physics when the URDF's meshes are missing (YAML contacts)
    contacts: tuple[ContactGeom, ...] = ()
    # joint -> (direction, reduction, offset): joint = direction * motor / reduction + offset (YAML transmissions)
    transmissions: tuple[tuple[str, int, float, float], ...] = ()
    # (group, joints, matrix): joint = matrix @ motor + offset, motor k in the slot of joints[k] (YAML coupled_joints)
    coupled_joints: tuple[tuple[str, tuple[str, ...], tuple[tuple[float, ...], ...]], ...] = ()
    urdf_transmissions: bool = True  # apply the URDF's <transmission>s (YAML urdf_transmissions)
    authority: str = "full"  # AUTHORITIES: upper_body leaves the legs to the robot's own controller
    hands: str = "none"      # HANDS: the hands the transport drives beside the body
    # sha256 of the parsed YAML content (typed_yaml/yaml_source.content_sha256): comments and layout do not count
    content_sha256: str = ""
    key_lines: dict[str, int] = field(default_factory=dict, compare=False, hash=False)
