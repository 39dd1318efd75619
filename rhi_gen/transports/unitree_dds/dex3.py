"""The G1's Dex3-1 hands (``hands: dex3``), from unitree_sdk2's example/g1/dex3/g1_dex3_example.cpp.

HandCmd_ on rt/dex3/<side>/cmd, HandState_ on rt/lf/dex3/<side>/state (Unitree's teleoperation app reads
rt/dex3/<side>/state: hand_state_topic changes it), 7 motors per hand in the order of Unitree's G1
documentation. The hand motors take the joint_map slots after the 35 LowCmd_ slots: left, then right.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from ...typed_yaml.validator import TOPIC_RE, Validator
from ..base import HandSuggestion, KnownRobot

DEX3_SIDES = ("left", "right")
DEX3_ORDER = ("thumb_0", "thumb_1", "thumb_2", "middle_0", "middle_1", "index_0", "index_1")
DEX3_COMMAND_TOPIC = "rt/dex3/{side}/cmd"
DEX3_STATE_TOPIC = "rt/lf/dex3/{side}/state"
DEX3_FIRST_SLOT = 35  # = FAMILIES["hg"]
DEX3_MOTORS = len(DEX3_SIDES) * len(DEX3_ORDER)
DEX3_GRIP_GAINS = (1.5, 0.1)  # kp, kd of the example's grip (its sweep uses kp 0.5)


def detect_dex3(known: KnownRobot | None, actuated: Sequence[str]) -> HandSuggestion:
    """A G1 whose URDF has both Dex3-1 hands (g1_29dof_with_hand_rev_1_0.urdf): hands: dex3, the hand joints in
    the Dex3-1 motor order after the LowCmd_ slots, with the grip gains of unitree_sdk2's g1_dex3_example."""
    names = [f"{side}_hand_{motor}_joint" for side in DEX3_SIDES for motor in DEX3_ORDER]
    if known is None or known.robot != "g1" or not set(names) <= set(actuated):
        return HandSuggestion()
    return HandSuggestion("dex3", tuple((n, DEX3_FIRST_SLOT + i) for i, n in enumerate(names)),
                          tuple((n, *DEX3_GRIP_GAINS) for n in names),
                          "the grip gains of unitree_sdk2's example/g1/dex3/g1_dex3_example.cpp")


def dex3_yaml_lines(known: KnownRobot | None, hands: HandSuggestion) -> list[str]:
    """The G1 can carry Dex3-1 hands: say how they are driven, or how to drive them (none stays the default)."""
    if hands.hands == "dex3":
        return ["# hands: dex3 drives the Dex3-1 hands too: motor_count 49, the hand joints in slots 35..41",
                "# (left) and 42..48 (right) in the order " + ", ".join(DEX3_ORDER) + ",",
                "# on HandCmd_ / HandState_ (see docs/hands.md).",
                "hands: dex3"]
    if known is None or known.robot != "g1":
        return []
    return ["# hands: none drives the body only; dex3 drives the Dex3-1 hands too (motor_count 49, the",
            "# hand joints in slots 35..41 left and 42..48 right, in the order " + ", ".join(DEX3_ORDER) + ";",
            "# use the URDF with hands): see docs/hands.md.",
            "hands: none"]


def hand_topic_reader(v: Validator) -> Callable[[Any, str], str]:
    """A hand topic pattern: "{side}" stands for left and right, and each must be a topic name."""
    def read(raw: Any, path: str) -> str:
        pattern = v.string(raw, path)
        fix = "e.g. rt/dex3/{side}/cmd"
        if pattern.count("{side}") != 1:
            raise v.error(path, f"{pattern!r} must contain {{side}} once (it stands for left and right)", fix=fix)
        if not TOPIC_RE.match(pattern.replace("{side}", "left")):
            raise v.error(path, f"{pattern!r} is not a ROS topic name once {{side}} is left or right (letters, "
                          "digits, _ and / separators)", fix=fix)
        return pattern
    return read


def check_dex3_map(v: Validator, hand_slots: range, joint_map: tuple[tuple[str, int], ...]) -> None:
    """Every Dex3-1 motor drives a joint: a HandCmd_ carries all 7 of a hand, and an unmapped one would be
    commanded to 0 with zero gains forever."""
    mapped = {slot for _, slot in joint_map}
    missing = [slot for slot in hand_slots if slot not in mapped]
    if missing:
        side = DEX3_SIDES[(missing[0] - DEX3_FIRST_SLOT) // len(DEX3_ORDER)]
        motor = DEX3_ORDER[(missing[0] - DEX3_FIRST_SLOT) % len(DEX3_ORDER)]
        last = DEX3_FIRST_SLOT + DEX3_MOTORS - 1
        raise v.error("joint_map", f"hands: dex3 drives slots {DEX3_FIRST_SLOT}..{last}, and no joint has "
                      f"slot {missing[0]} (the {side} hand's {motor} motor)",
                      fix=f"map {side}_hand_{motor}_joint: {missing[0]} (left hand 35..41, right 42..48, "
                          f"in the order {', '.join(DEX3_ORDER)})")
