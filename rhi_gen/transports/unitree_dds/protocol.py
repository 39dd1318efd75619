"""unitree_sdk2's two low-level message families (SDK_FACTS.md sections A and D), their LowCmd_ slot counts and
motor modes, and the arm SDK's topic and blend weight slot: facts every other module of this transport reads."""
from __future__ import annotations

NAME = "unitree_dds"
FAMILIES = {"hg": 35, "go": 20}  # message family -> motor slots of its LowCmd_
FAMILY_ROBOTS = {"hg": "G1, H1-2", "go": "H1, Go2, Go2-W, B2, B2-W"}
GO_SERVO = 0x01   # MotorCmd_.mode of the go examples ("servo (PMSM) mode")
GO_STRONG = 0x0A  # the H1's hip/knee/torso motors and the B2's motors in the C++ examples
# The arm SDK (authority upper_body, arm_sdk.py): its topic, the blend weight's slot per robot (kNotUsedJoint of
# the examples) and the examples' arm initialisation time (init_time = 2.0 s).
ARM_SDK_TOPIC = "rt/arm_sdk"
ARM_SDK_WEIGHT_SLOT = {"g1": 29, "h1_2": 27}
ARM_SDK_RAMP_S = 2.0
