"""What Unitree's public code says about the Dex3-1 hand of the G1, as data (issue 20: facts first).

Read from unitreerobotics/unitree_sdk2 at 21d0a3b2c46ee48c8fdf2783becb6be3beb0a59b:
example/g1/dex3/g1_dex3_example.cpp (topics, the mode byte, gains) and include/unitree/idl/hg/HandCmd_.hpp,
HandState_.hpp (no CRC field); the motor order from unitreerobotics/xr_teleoperate
teleop/robot_control/hand_retargeting.py at 540f34fe3d137e663cf386d2badd864740483813 (Unitree's teleoperation
app, which maps hand motors by name citing Unitree's G1 developer documentation, "dexterous hand"), consistent
with the SDK example's per-index limit tables. tests/unit/facts/test_dex3_facts.py checks them against the
vendor files the repository carries (the URDF with hands, the unitree_hg .msg definitions).
"""
from __future__ import annotations

SIDES = ("left", "right")
# SDK example: ChannelPublisher<HandCmd_> on "rt/dex3/<side>/cmd", ChannelSubscriber<HandState_> on
# "rt/lf/dex3/<side>/state" (Unitree's teleoperation app subscribes to "rt/dex3/<side>/state": open question).
COMMAND_TOPIC = "rt/dex3/{side}/cmd"
STATE_TOPIC = "rt/lf/dex3/{side}/state"
MOTORS_PER_HAND = 7
# Motor index 0..6 of each hand -> the URDF joint {side}_hand_<part>_joint (g1_29dof_with_hand_rev_1_0.urdf).
MOTOR_ORDER = ("thumb_0", "thumb_1", "thumb_2", "middle_0", "middle_1", "index_0", "index_1")
# MotorCmd_.mode of a hand motor: id in bits 0-3, status in bits 4-6, timeout in bit 7 (the example packs
# RIS_Mode_t explicitly); the example always sends status 1, and timeout 1 only to stop the hand.
STATUS_RUN = 1
# SDK example gains: the sine sweep, and the grip; stop sends every field 0 with the timeout bit.
SWEEP_GAINS = (0.5, 0.1)
GRIP_GAINS = (1.5, 0.1)


def mode_byte(motor_id: int, status: int = STATUS_RUN, timeout: bool = False) -> int:
    """The packed MotorCmd_.mode of hand motor ``motor_id``."""
    return (motor_id & 0x0F) | ((status & 0x07) << 4) | ((1 if timeout else 0) << 7)


def joint_name(side: str, motor: int) -> str:
    return f"{side}_hand_{MOTOR_ORDER[motor]}_joint"


# The .msg fields (unitree_ros2 cyclonedds_ws/src/unitree/unitree_hg/msg): unlike LowCmd_ / LowState_, no crc.
HAND_CMD_FIELDS = (("MotorCmd[]", "motor_cmd"), ("uint32[4]", "reserve"))
HAND_STATE_FIELDS = (("MotorState[]", "motor_state"), ("PressSensorState[]", "press_sensor_state"),
                     ("IMUState", "imu_state"), ("float32", "power_v"), ("float32", "power_a"),
                     ("float32", "system_v"), ("float32", "device_v"), ("uint32[2]", "error"),
                     ("uint32[2]", "reserve"))
