"""The Unitree robots rhi-gen knows: their real SDK motor order, message family, motor modes and the gains of
unitree_sdk2's own low-level examples, which `rhi-gen new` writes into a new robot's YAML."""
from __future__ import annotations

from collections.abc import Sequence

from ..base import KnownRobot
from .protocol import FAMILIES, GO_SERVO, GO_STRONG, NAME

# G1 29-DoF motor order, unitree_sdk2 enum G1JointIndex.
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
# G1 ankle-swing example gains: legs (hip pitch, roll, yaw, knee, ankle pitch, roll) x2, waist, arms.
_G1_KP = (60, 60, 60, 100, 40, 40) * 2 + (60, 40, 40) + (40,) * 14
_G1_KD = (1, 1, 1, 2, 1, 1) * 2 + (1,) * 17

# H1-2 27-DoF order, enum H1JointIndex of h1_27dof_example.cpp (= h1_2_handless.urdf file order).
_H1_2_SIDE = ("hip_yaw", "hip_pitch", "hip_roll", "knee", "ankle_pitch", "ankle_roll")
_H1_2_ARM = ("shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_roll", "wrist_pitch", "wrist_yaw")
H1_2_ORDER = (tuple(f"left_{j}_joint" for j in _H1_2_SIDE) + tuple(f"right_{j}_joint" for j in _H1_2_SIDE)
              + ("torso_joint",) + tuple(f"left_{j}_joint" for j in _H1_2_ARM)
              + tuple(f"right_{j}_joint" for j in _H1_2_ARM))

# Original H1 (go family), enum JointIndex of example/h1/low_level/motors.hpp: slot 9 drives no joint.
H1_ORDER = (
    "right_hip_roll_joint", "right_hip_pitch_joint", "right_knee_joint", "left_hip_roll_joint",
    "left_hip_pitch_joint", "left_knee_joint", "torso_joint", "left_hip_yaw_joint", "right_hip_yaw_joint", "",
    "left_ankle_joint", "right_ankle_joint", "right_shoulder_pitch_joint", "right_shoulder_roll_joint",
    "right_shoulder_yaw_joint", "right_elbow_joint", "left_shoulder_pitch_joint", "left_shoulder_roll_joint",
    "left_shoulder_yaw_joint", "left_elbow_joint",
)
# humanoid.hpp: strong motors (slots 0..9) mode 0x0A, kp 200 / kd 5; weak ones (10..19) 0x01, 60 / 1.5.
_H1_MODES = (GO_STRONG,) * 10 + (GO_SERVO,) * 10

# Quadrupeds: JointIndex of dds_wrapper/robots/go2/defines.h (FR, FL, RR, RL), then the wheels.
QUADRUPED_ORDER = tuple(f"{leg}_{part}_joint" for leg in ("FR", "FL", "RR", "RL")
                        for part in ("hip", "thigh", "calf"))
WHEELED_ORDER = QUADRUPED_ORDER + tuple(f"{leg}_foot_joint" for leg in ("FR", "FL", "RR", "RL"))


def _gains(order: Sequence[str], kp: Sequence[float], kd: Sequence[float]) -> tuple[tuple[str, float, float], ...]:
    return tuple((n, float(p), float(d)) for n, p, d in zip(order, kp, kd, strict=True) if n)


def _uniform(order: Sequence[str], kp: float, kd: float, wheel_kd: float | None = None
             ) -> tuple[tuple[str, float, float], ...]:
    """The same gains on every leg joint; wheels (…_foot_joint) take damping only."""
    return tuple((n, 0.0, wheel_kd) if wheel_kd is not None and n.endswith("_foot_joint") else (n, kp, kd)
                 for n in order if n)


def _quadruped(robot: str, order: tuple[str, ...], mode: int, kp: float, kd: float, wheel_kd: float | None,
               example: str, aliases: tuple[str, ...] = ()) -> KnownRobot:
    return KnownRobot(
        "unitree", robot, NAME, order, f"{robot} motor order: JointIndex of unitree_sdk2 dds_wrapper (FR, FL, RR, "
        "RL legs" + (", then the wheels 12..15)" if wheel_kd is not None else ")"), aliases=aliases, family="go",
        motor_modes=(mode,) * FAMILIES["go"], default_gains=_uniform(order, kp, kd, wheel_kd),
        gains_note=f"the gains of unitree_sdk2's {example}")


KNOWN_ROBOTS = (
    KnownRobot("unitree", "g1", NAME, G1_ORDER, "G1 29-DoF motor order from unitree_sdk2 enum G1JointIndex",
               family="hg", default_gains=_gains(G1_ORDER, _G1_KP, _G1_KD),
               gains_note="the gains of unitree_sdk2's g1_ankle_swing_example"),
    KnownRobot("unitree", "h1_2", NAME, H1_2_ORDER, "H1-2 27-DoF motor order from unitree_sdk2 enum H1JointIndex "
               "(h1_27dof_example.cpp)", aliases=("h12",), family="hg",
               gains_note="none: unitree_sdk2's H1-2 examples set no standing gains"),
    KnownRobot("unitree", "h1", NAME, H1_ORDER, "H1 motor order from unitree_sdk2 enum JointIndex "
               "(example/h1/low_level/motors.hpp; slot 9 drives no joint)", family="go", motor_modes=_H1_MODES,
               default_gains=tuple((n, 200.0, 5.0) if i < 10 else (n, 60.0, 1.5)
                                   for i, n in enumerate(H1_ORDER) if n),
               gains_note="the strong/weak motor gains of unitree_sdk2's example/h1/low_level/humanoid.hpp"),
    _quadruped("go2", QUADRUPED_ORDER, GO_SERVO, 60.0, 5.0, None, "go2_stand_example"),
    _quadruped("go2w", WHEELED_ORDER, GO_SERVO, 70.0, 5.0, 5.0, "go2w_stand_example", aliases=("go2_w",)),
    _quadruped("b2", QUADRUPED_ORDER, GO_STRONG, 1000.0, 10.0, None, "b2_stand_example"),
    _quadruped("b2w", WHEELED_ORDER, GO_SERVO, 1000.0, 10.0, 10.0, "b2w_stand_example", aliases=("b2_w",)),
)


def known_robot(vendor: str, robot: str) -> KnownRobot | None:
    """The Unitree robot rhi-gen knows by this name (its family, motor modes, arm SDK weight slot)."""
    return next((k for k in KNOWN_ROBOTS if k.vendor == vendor and k.named(robot)), None)
