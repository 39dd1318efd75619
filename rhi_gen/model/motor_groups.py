"""Motor groups: a robot's joints by limb ("left leg motors", ...), for one /diagnostics status each.

Why: an operator looking at /diagnostics wants to see which limb is hot or in error, not scroll one
status with every motor of the robot. Every vendor studied names its joints by limb and side (Unitree
``left_hip_pitch_joint`` / ``FL_calf_joint``, AgiBot ``left_elbow_joint``, EngineAI
``J03_KNEE_PITCH_L``, PAL ``leg_left_1_joint``), so the groups come from the names, the same rule for
every robot. A robot whose names tell nothing gets one group, ``motors``. A group's name is the
status name after "<hardware>: ".
"""
from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

SINGLE_GROUP = "motors"
MAX_MOTOR_GROUPS = 48  # RobotSpec::motor_groups (robot_spec.hpp kMaxMotorGroups): 7 sides by 6 limbs fit
UNNAMED_GROUP = "other motors"

# The first token of a joint name that names a limb decides its limb (hands before arms: a finger joint's
# name may also say "wrist" later, never first).
LIMB_TOKENS = {
    **dict.fromkeys(("hip", "thigh", "knee", "calf", "shin", "ankle", "foot", "toe", "leg", "wheel"), "leg"),
    **dict.fromkeys(("shoulder", "elbow", "wrist", "arm", "forearm"), "arm"),
    **dict.fromkeys(("hand", "finger", "thumb", "index", "middle", "ring", "pinky", "little", "palm",
                     "gripper"), "hand"),
    **dict.fromkeys(("waist", "torso", "trunk", "spine", "chest"), "waist"),
    **dict.fromkeys(("head", "neck"), "head"),
}
# Side tokens, alone in the name: humanoids say left/right (or L/R), quadrupeds front/rear and left/right.
SIDE_TOKENS = {
    "left": "left", "l": "left", "right": "right", "r": "right",
    "fl": "front left", "lf": "front left", "fr": "front right", "rf": "front right",
    "rl": "rear left", "hl": "rear left", "lh": "rear left", "bl": "rear left",
    "rr": "rear right", "hr": "rear right", "rh": "rear right", "br": "rear right",
}
_TOKEN = re.compile(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|[0-9]+")


@dataclass(frozen=True)
class MotorGroup:
    """A named set of motors ("left leg motors"): the SDK slots of its joints, ascending."""
    name: str
    slots: tuple[int, ...]


def limb_of(joint_name: str) -> str:
    """"left leg", "waist", "front right leg", "" when the name says neither side nor limb."""
    tokens = [t.lower() for t in _TOKEN.findall(joint_name)]
    limb = next((LIMB_TOKENS[t] for t in tokens if t in LIMB_TOKENS), "")
    side = next((SIDE_TOKENS[t] for t in tokens if t in SIDE_TOKENS), "")
    return " ".join(part for part in (side, limb) if part)


def is_leg(joint_name: str) -> bool:
    """Whether the name says leg (hip, knee, ankle, ...): the joints authority upper_body leaves to the
    robot's own balance controller, which are exactly the arm SDK's uncommanded ones on the G1 and H1-2."""
    return limb_of(joint_name).endswith("leg")


def motor_groups(joints: Sequence[tuple[str, int]]) -> tuple[MotorGroup, ...]:
    """Groups of (joint name, SDK slot) pairs, in the order their first slot comes; one ``motors`` group
    when the names give fewer than two groups."""
    by_name: dict[str, list[int]] = {}
    for name, slot in sorted(joints, key=lambda joint: joint[1]):
        limb = limb_of(name)
        by_name.setdefault(f"{limb} motors" if limb else UNNAMED_GROUP, []).append(slot)
    if len(by_name) < 2:
        return (MotorGroup(SINGLE_GROUP, tuple(sorted(slot for _, slot in joints))),) if joints else ()
    return tuple(MotorGroup(name, tuple(slots)) for name, slots in by_name.items())
