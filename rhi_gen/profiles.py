"""What rhi-gen knows about vendors' SDKs: transport, float type and the real motor order.

Used by `rhi-gen new` to suggest a joint map; the facts come from the vendors' SDK sources
(see README "Vendor profiles").
"""
from __future__ import annotations

from dataclasses import dataclass, field

G1_ORDER = (
    "left_hip_pitch_joint", "left_hip_roll_joint", "left_hip_yaw_joint", "left_knee_joint",
    "left_ankle_pitch_joint", "left_ankle_roll_joint", "right_hip_pitch_joint", "right_hip_roll_joint",
    "right_hip_yaw_joint", "right_knee_joint", "right_ankle_pitch_joint", "right_ankle_roll_joint",
    "waist_yaw_joint", "waist_roll_joint", "waist_pitch_joint", "left_shoulder_pitch_joint",
    "left_shoulder_roll_joint", "left_shoulder_yaw_joint", "left_elbow_joint", "left_wrist_roll_joint",
    "left_wrist_pitch_joint", "left_wrist_yaw_joint", "right_shoulder_pitch_joint",
    "right_shoulder_roll_joint", "right_shoulder_yaw_joint", "right_elbow_joint",
    "right_wrist_roll_joint", "right_wrist_pitch_joint", "right_wrist_yaw_joint",
)

_X2_LEG = tuple(f"{side}_{j}_joint" for side in ("left", "right")
                for j in ("hip_pitch", "hip_roll", "hip_yaw", "knee", "ankle_pitch", "ankle_roll"))
_X2_WAIST = ("waist_yaw_joint", "waist_pitch_joint", "waist_roll_joint")
_X2_ARM = tuple(f"{side}_{j}_joint" for side in ("left", "right")
                for j in ("shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_yaw",
                          "wrist_pitch", "wrist_roll"))
_X2_HEAD = ("head_yaw_joint", "head_pitch_joint")
X2_GROUPS = (("leg", _X2_LEG), ("waist", _X2_WAIST), ("arm", _X2_ARM), ("head", _X2_HEAD))
X2_ORDER = _X2_LEG + _X2_WAIST + _X2_ARM + _X2_HEAD

PM01_ORDER = (
    "J00_HIP_PITCH_L", "J01_HIP_ROLL_L", "J02_HIP_YAW_L", "J03_KNEE_PITCH_L", "J04_ANKLE_PITCH_L",
    "J05_ANKLE_ROLL_L", "J06_HIP_PITCH_R", "J07_HIP_ROLL_R", "J08_HIP_YAW_R", "J09_KNEE_PITCH_R",
    "J10_ANKLE_PITCH_R", "J11_ANKLE_ROLL_R", "J12_WAIST_YAW", "J13_SHOULDER_PITCH_L",
    "J14_SHOULDER_ROLL_L", "J15_SHOULDER_YAW_L", "J16_ELBOW_PITCH_L", "J17_ELBOW_YAW_L",
    "J18_SHOULDER_PITCH_R", "J19_SHOULDER_ROLL_R", "J20_SHOULDER_YAW_R", "J21_ELBOW_PITCH_R",
    "J22_ELBOW_YAW_R", "J23_HEAD_YAW",
)


@dataclass(frozen=True)
class VendorProfile:
    vendor: str
    robot: str | None            # None: the vendor's default for robots we have no profile of
    transport: str
    float_type: str
    joint_order: tuple[str, ...] = ()   # SDK motor index order
    motor_count: int | None = None
    groups: tuple[tuple[str, tuple[str, ...]], ...] = ()
    transport_options: dict = field(default_factory=dict)
    note: str = ""


PROFILES = (
    VendorProfile("unitree", "g1", "unitree_dds", "float", G1_ORDER, 29,
                  transport_options={"lowcmd_topic": "rt/lowcmd", "lowstate_topic": "rt/lowstate",
                                     "sdk_slots": 35, "domain_id": 0, "mode_pr": 0,
                                     "release_motion_control": False},
                  note="G1 29-DoF motor order from unitree_sdk2 enum G1JointIndex"),
    VendorProfile("agibot", "x2", "agibot_topics", "double", X2_ORDER, 31, groups=X2_GROUPS,
                  transport_options={"imu_topic": "/aima/hal/imu/torso/state"},
                  note="X2 motor order = AimDK joint groups leg, waist, arm, head"),
    VendorProfile("engineai", "pm01", "engineai_topics", "double", PM01_ORDER, 24,
                  transport_options={"command_topic": "/hardware/joint_command",
                                     "state_topic": "/hardware/joint_state",
                                     "imu_topic": "/hardware/imu_info", "parallel_parser_type": 0},
                  note="PM01 motor order = interface_protocol array index J00..J23"),
    VendorProfile("unitree", None, "unitree_dds", "float"),
    VendorProfile("agibot", None, "agibot_topics", "double"),
    VendorProfile("engineai", None, "engineai_topics", "double"),
)


def find_profile(vendor: str, robot: str) -> VendorProfile | None:
    """The robot's own profile, else the vendor's default, else None (generic)."""
    for p in PROFILES:
        if p.vendor == vendor and p.robot == robot:
            return p
    for p in PROFILES:
        if p.vendor == vendor and p.robot is None:
            return p
    return None


def suggest_order(actuated: list[str], profile: VendorProfile | None) -> list[str]:
    """Actuated joints in SDK order: the profile's order where names match, the rest in URDF order."""
    if profile is None or not profile.joint_order:
        return list(actuated)
    known = [n for n in profile.joint_order if n in actuated]
    return known + [n for n in actuated if n not in known]
