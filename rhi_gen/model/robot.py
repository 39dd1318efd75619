"""The decided robot: URDF and vendor YAML cross-checked, every C++ name chosen.

Built by assemble/robot_model.py; the templates read only this (see docs/ARCHITECTURE.md "Template context").
"""
from __future__ import annotations

from dataclasses import dataclass

from ..project import PACKAGE_NAME
from .body import BodySummary
from .config import ARMATURE_DEFAULT, ContactGeom, ImuConfig, Parameters, TransportOptions
from .motor_groups import MotorGroup, motor_groups
from .naming import PACKAGE_NAMESPACE
from .urdf import JointLimits


@dataclass(frozen=True)
class JointTransmission:
    """How a joint follows its motor, ros2_control's SimpleTransmission convention:
    joint = direction * motor / reduction + offset (velocity without the offset, effort times
    direction * reduction). The identity (1, 1.0, 0.0) is what the firmware of every reference robot
    already applies. A coupled joint (``CoupledGroup``) keeps direction 1 and reduction 1: its matrix
    says how it follows the motors, ``offset`` is still its zero."""
    direction: int = 1       # +1 or -1
    reduction: float = 1.0   # motor turns per joint turn, > 0
    offset: float = 0.0      # joint value at motor zero [rad or m]
    source: str = ""         # for messages: "" (default), "vendor YAML", "URDF <transmission name='...'>"

    @property
    def is_identity(self) -> bool:
        return self.direction == 1 and self.reduction == 1.0 and self.offset == 0.0


@dataclass(frozen=True)
class CoupledGroup:
    """n joints driven by n motors through a constant matrix (a differential wrist, a parallel ankle
    the firmware does not solve): joint = matrix @ motor + offset, where motor k is the SDK slot of
    ``joints[k]`` and offsets are the joints' ``JointTransmission.offset``. Velocities map by the same
    matrix; efforts by the inverse transpose (power is conserved), as ros2_control's
    DifferentialTransmission does."""
    name: str                                  # the YAML entry's name or the URDF transmission's
    joints: tuple[str, ...]                    # URDF joint names: the matrix's rows, and its columns' motors
    matrix: tuple[tuple[float, ...], ...]      # joint per motor, len(joints) x len(joints), invertible
    source: str = ""                           # "vendor YAML" | "URDF <transmission name='...'>"


@dataclass(frozen=True)
class MotorJoint:
    """A URDF joint driven by SDK slot ``index``."""
    name: str              # URDF joint name, raw text (escape with |cpp_string / |xml in templates)
    index: int             # SDK motor slot
    type: str              # revolute | continuous | prismatic
    limits: JointLimits | None
    group: str | None = None           # AgiBot group name
    group_position: int | None = None  # position inside the group
    command_mode: str = "position"     # position | velocity (wheels: continuous joints by default) | state
    #                                    (authority upper_body: a leg the robot's own controller keeps) |
    #                                    position_target (the robot tracks a position target: an OmniHand axis)
    command_interfaces: tuple[str, ...] = ("position", "velocity", "stiffness", "damping", "effort")
    state_interfaces: tuple[str, ...] = ("position", "velocity", "effort")  # + the transport's motor health
    default_stiffness: float = 0.0     # applied while no controller claims stiffness
    default_damping: float = 0.0       # applied while no controller claims damping
    initial_position: float = 0.0      # the description's initial_value (YAML initial_positions, or safe_pose)
    transmission: JointTransmission = JointTransmission()  # motor -> joint (identity unless YAML / URDF say)
    # What the fake robot simulates (assemble/joint_inertia.py): the URDF subtree about the joint axis
    # [kg m^2, or kg for a prismatic joint] and the URDF <dynamics damping> or a default.
    inertia: float = 0.01
    damping: float = 0.1
    # The rotor inertia reflected to the joint [kg m^2, or kg], the fake robot's physics adds it to the joint
    # (MuJoCo's armature): the YAML's armatures, or ARMATURE_DEFAULT.
    armature: float = ARMATURE_DEFAULT
    # The physics' passive damping [N m s/rad, N s/m] and dry friction [N m, N] (MuJoCo's damping and
    # frictionloss): the vendor YAML's joint_damping / joint_frictionloss, else the URDF's <dynamics>.
    physics_damping: float = 0.0
    frictionloss: float = 0.0


@dataclass(frozen=True)
class InputProvenance:
    """Where the robot came from: named in banners, fingerprinted in generated/.rhi-gen-manifest."""
    yaml_path: str          # project-relative, POSIX
    urdf_path: str          # project-relative, POSIX
    yaml_sha256: str        # of the parsed YAML content: comments and layout do not count
    urdf_sha256: str        # of the expanded URDF without the volatile xacro header


@dataclass(frozen=True)
class KdlRoot:
    """A massless root link the installed URDF adds above the robot's root, joined by a fixed joint: KDL
    (robot_state_publisher) cannot use a root link with an inertia and warns on every launch."""
    link: str    # the new root link
    joint: str   # the fixed joint from it to the robot's root
    child: str   # the robot's root link


@dataclass(frozen=True)
class MeshCopy:
    """A mesh the URDF names by a relative (or file://) path, found inside the project: the package carries
    a copy and its installed URDF names that (inputs/urdf_meshes.py)."""
    reference: str   # the filename attribute as the vendor wrote it
    source: str      # project-relative, POSIX: the file copied
    path: str        # package-relative, POSIX: meshes/<robot>/<path beside the URDF>

    @property
    def uri(self) -> str:
        return f"package://{PACKAGE_NAME}/{self.path}"


@dataclass(frozen=True)
class MissingMesh:
    """A mesh the URDF names by a relative (or file://) path that is not in the project: left as written."""
    reference: str   # the filename attribute as the vendor wrote it
    looked: str      # where rhi-gen looked for it, project-relative POSIX (may climb out with ..)


@dataclass(frozen=True)
class RobotModel:
    vendor: str               # C++ namespace robot_hardware_interface::<vendor> and folder, e.g. "unitree"
    robot: str                # file stem, e.g. "g1"
    robot_pascal: str         # "G1", "PM01", "MyArm"
    robot_upper: str          # "G1", "PM01", "MY_ARM"
    class_name: str           # "G1HardwareInterface"
    plugin_name: str          # "robot_hardware_interface/unitree/G1HardwareInterface"
    node_name: str            # "g1_hardware_interface"
    transport: str            # a name registered in rhi_gen/transports/
    motor_count: int          # N of MotorCommand<N, T>
    float_type: str           # "float" | "double"
    joints: tuple[MotorJoint, ...]        # mapped joints, URDF order
    unmapped_joints: tuple[str, ...]      # actuated joints intentionally left out
    mimic_joints: tuple[str, ...]         # follow another joint, no interfaces
    imu: ImuConfig
    parameters: Parameters
    transport_options: TransportOptions
    provenance: InputProvenance
    coupled_groups: tuple[CoupledGroup, ...] = ()  # joints driven through a matrix of motors
    urdf_name: str = ""
    urdf_xml: str = ""        # the expanded URDF (no xacro banner, no machine paths): urdf/<robot>.urdf
    authority: str = "full"   # vendor YAML authority: full | upper_body (model/config.py AUTHORITIES)
    hands: str = "none"       # vendor YAML hands: none | dex3 (model/config.py HANDS)
    kdl_root: KdlRoot | None = None  # the installed URDF's massless root, where the URDF's root has an inertia
    contacts: tuple[ContactGeom, ...] = ()  # the YAML's collision primitives, for the physics without meshes
    body: BodySummary | None = None  # the URDF's inertials and geometry summed up (the manifest records it)
    meshes: tuple[MeshCopy, ...] = ()             # copied into the package, by package path
    missing_meshes: tuple[MissingMesh, ...] = ()  # named by a relative path, not found: URDF order

    @property
    def cpp_namespace(self) -> str:
        """The driver's C++ namespace: robot_hardware_interface::unitree."""
        return f"{PACKAGE_NAMESPACE}::{self.vendor}"

    @property
    def qualified_class_name(self) -> str:
        """The plugin's C++ type: robot_hardware_interface::unitree::G1HardwareInterface."""
        return f"{self.cpp_namespace}::{self.class_name}"

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
    def motor_groups(self) -> tuple[MotorGroup, ...]:
        """The mapped joints by limb, one /diagnostics motors status each (model/motor_groups.py)."""
        return motor_groups([(j.name, j.index) for j in self.joints])

    @property
    def has_transmission(self) -> bool:
        """Whether any joint's motor is not the joint itself (the driver then converts in read/write)."""
        return bool(self.coupled_groups) or any(not j.transmission.is_identity for j in self.joints)

    @property
    def hand_joints(self) -> tuple[MotorJoint, ...]:
        """The joints of the hands the transport drives in their own messages (hands: dex3, omnihand), URDF order."""
        slots = self.transport_options.hand_slots()
        return tuple(j for j in self.joints if j.index in slots)

    @property
    def commanded_joints(self) -> tuple[MotorJoint, ...]:
        """The joints this driver commands (all but the state-only legs of an upper_body robot)."""
        return tuple(j for j in self.joints if j.command_mode != "state")

    @property
    def vendor_pascal(self) -> str:
        return "".join(p[:1].upper() + p[1:] for p in self.vendor.split("_"))
