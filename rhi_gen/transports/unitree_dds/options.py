"""The unitree_dds section of a robot YAML's transport_options, as the driver's glue reads it."""
from __future__ import annotations

from dataclasses import dataclass

from ...model import TransportOptions
from .dex3 import DEX3_COMMAND_TOPIC, DEX3_FIRST_SLOT, DEX3_MOTORS, DEX3_STATE_TOPIC
from .protocol import ARM_SDK_RAMP_S, ARM_SDK_TOPIC


@dataclass(frozen=True)
class UnitreeDdsOptions(TransportOptions):
    family: str = "hg"                 # hg (G1, H1-2) | go (H1, Go2, Go2-W, B2, B2-W) low-level messages
    motor_modes: tuple[int, ...] = ()  # go: MotorCmd_.mode of every slot (0x01 servo, 0x0A strong motor)
    verify_state_crc: bool = True      # drop LowState_ frames whose crc does not match
    lowcmd_topic: str = "rt/lowcmd"
    lowstate_topic: str = "rt/lowstate"
    sdk_slots: int = 35
    domain_id: int = 0
    mode_pr: int = 0
    release_motion_control: bool = False
    upper_body: bool = False           # authority upper_body: arm SDK commands, the legs left to the robot
    arm_sdk_topic: str = ARM_SDK_TOPIC
    arm_sdk_weight_slot: int = -1      # the LowCmd_ slot whose q carries the blend weight (-1: the robot's)
    arm_sdk_ramp_s: float = ARM_SDK_RAMP_S  # seconds for the blend weight from 0 to 1 (and back)
    hands: str = "none"                # dex3: the G1's Dex3-1 hands in slots 35..48 (HandCmd_/HandState_)
    hand_command_topic: str = DEX3_COMMAND_TOPIC  # "{side}" is left or right
    hand_state_topic: str = DEX3_STATE_TOPIC

    def hand_slots(self) -> range:
        """Dex3-1: the 14 slots after the 35 of a LowCmd_, the left hand's 7 motors then the right's."""
        return range(DEX3_FIRST_SLOT, DEX3_FIRST_SLOT + DEX3_MOTORS) if self.hands == "dex3" else range(0)

    def hand_topics(self, side: str) -> tuple[str, str]:
        """(command, state) topic of one hand."""
        return self.hand_command_topic.replace("{side}", side), self.hand_state_topic.replace("{side}", side)
