"""How AgiBot's AimDK hands control of an X2 to another program, as data (issue 20: facts first).

Sources: the AimDK v1.0.0 copy sorrowfeng/aimdk at 2ec31d5474e601bf89eef70e97f28ac3c1013995 (vendor examples
src/examples/src/mc/set_mc_input_source.cpp, set_mc_action.cpp, src/examples/src/utils/migrate_system_state.cpp,
src/examples/src/hal/motocontrol.cpp, the file topics_and_services) and the AimDK documentation
(x2-aimdk.agibot.com: faq, Interface/system_state, Interface/control_mod/MC_control, upper_body_control). What they
say, in short:

- whole-body joint commands on /aima/hal/joint/*/command need the native motion control (MC) stopped: from v1.0.0
  MigrateSystemState("Develop_MC"), then GetSystemState until cur_state is Develop_MC and curr_status IN_READY;
  "Ready" gives the robot back. The joint example itself calls no MC service;
- input sources (SetMcInputSource) arbitrate MC's inputs (the docs tie them to velocity control), not the HAL
  joint topics: there is no vendor way to command /aima/hal/joint/arm/command while MC balances the legs;
- arms-only control while MC keeps the legs is /mc/upper_body_command (UpperBodyCommandArray, position targets
  only, 50 Hz) after SetMcAction "UPPERBODY_REMOTE_SPLIT", from AimDK 1.1.0 (its message is not in v1.0.0).

The X2's hands (AimDK documentation Interface/control_mod/endeffector, the vendor examples
src/examples/src/hal/hand_control.cpp and omnihand_control.cpp of the same copy, AgibotTech/agibot_x2_urdf
X2_URDF-v1.4.0/X2-Ultra_omnihand.urdf at 575cc6b988f976c23550e0db85aa1e5475d3652d for the joint names): one
HandCommandArray on /aima/hal/joint/hand/command carries both hands, each with its HandType and an array sized for
it; the OmniHand takes 10 position targets per hand (rad; velocity, acceleration, deceleration, effort unused),
matched by index (the examples put placeholder names), the OmniPicker gripper 1 entry of fractions 0..1; MC
publishes the same topic while it runs, so the hands need it stopped like the body.

tests/unit/facts/test_aimdk_facts.py checks the service definitions and the hand messages against the shared
vendor .msg/.srv files.
"""
from __future__ import annotations

SERVICE_PREFIX = "/aimdk_5Fmsgs/srv/"
SET_INPUT_SOURCE = SERVICE_PREFIX + "SetMcInputSource"
GET_INPUT_SOURCE = SERVICE_PREFIX + "GetCurrentInputSource"
SET_ACTION = SERVICE_PREFIX + "SetMcAction"
GET_ACTION = SERVICE_PREFIX + "GetMcAction"
MIGRATE_SYSTEM_STATE = SERVICE_PREFIX + "MigrateSystemState"
GET_SYSTEM_STATE = SERVICE_PREFIX + "GetSystemState"

# McInputAction values (mc/motion/msg/McInputAction.msg).
INPUT_ACTIONS = {"INPUTACTION_ADD": 1001, "INPUTACTION_MODIFY": 1002, "INPUTACTION_DELETE": 1003,
                 "INPUTACTION_ENABLE": 2001, "INPUTACTION_DISABLE": 2002}
# The vendor example's input source: name, priority (0-100), timeout [ms]; built-in sources rc 80, vr 70,
# app_proxy 60, interaction 50, pnc 40 (MC_control docs).
EXAMPLE_INPUT_SOURCE = ("node", 40, 1000)
# CommonState.SUCCESS: SetMcAction and MigrateSystemState answer status.value == 1; ResponseHeader.code 0 is success.
SUCCESS = 1
# System states MigrateSystemState takes (sm examples): Develop_MC disables MC for whole-body control.
SYSTEM_STATES = ("Ready", "Develop_Nav", "Develop_Audio_Linux", "Develop_Audio_ROS", "Develop_MC")
# Vendor examples wait for a service in 2 s loops, then try a call up to 8 times, 250 ms each.
SERVICE_ATTEMPTS = 8
SERVICE_ATTEMPT_S = 0.25

# Request fields, as the .srv files give them (before "---").
SET_INPUT_SOURCE_REQUEST = (("CommonRequest", "request"), ("McInputAction", "action"),
                            ("McInputSource", "input_source"))
SET_ACTION_REQUEST = (("RequestHeader", "header"), ("string", "source"), ("McActionCommand", "command"))
MIGRATE_REQUEST = (("CommonRequest", "header"), ("string", "state"))

# The hands (hal/msg/Hand*.msg).
HAND_COMMAND_TOPIC = "/aima/hal/joint/hand/command"  # HandCommandArray
HAND_STATE_TOPIC = "/aima/hal/joint/hand/state"      # HandStateArray
GET_HAND_TYPE = SERVICE_PREFIX + "GetHandType"
HAND_TYPES = {"NONE": 0, "NIMBLE_HANDS": 1, "CLAW": 2, "LEISAI_NIMBLE_HANDS": 3, "ERROR": 0xFF}
HAND_COMMAND_ARRAY_FIELDS = (("MessageHeader", "header"), ("HandType", "left_hand_type"),
                             ("HandCommand[]", "left_hands"), ("HandType", "right_hand_type"),
                             ("HandCommand[]", "right_hands"))
HAND_COMMAND_FIELDS = (("string", "name"), ("float64", "position"), ("float64", "velocity"),
                       ("float64", "acceleration"), ("float64", "deceleration"), ("float64", "effort"))
HAND_STATE_FIELDS = (("string", "name"), ("float64", "position"), ("float64", "velocity"), ("float64", "effort"),
                     ("int32", "state"), ("int32", "faultcode"))
HAND_STATE_ARRAY_FIELDS = (("MessageHeader", "header"), ("HandType", "left_hand_type"), ("HandState[]", "left_hands"),
                           ("HandTouchSensorData", "left_touch_sensors"), ("HandType", "right_hand_type"),
                           ("HandState[]", "right_hands"), ("HandTouchSensorData", "right_touch_sensors"))
# OmniHand (HandType NIMBLE_HANDS): 10 axes per hand in this index order (endeffector docs), the URDF's joints
# {L,R}_<axis>_joint; position in rad, the only field the HAL uses.
OMNIHAND_AXES = ("thumb_roll", "thumb_abad", "thumb_mcp", "index_abad", "index_pip", "middle_pip", "ring_abad",
                 "ring_pip", "pinky_abad", "pinky_pip")
OMNIHAND_SIDE_PREFIX = {"left": "L_", "right": "R_"}
# Each axis's position range (lower, upper) in rad, per side: the OmniHand 2025 SDK's joint tables
# (AgibotTech/Omnihand-2025-SDK document/en/API_CPP.md at 2d898a9779bb8eb795f87f117a6996a9c40f0292), which
# AgibotTech/agibot_x2_urdf X2_URDF-v1.4.0/X2-Ultra_omnihand.urdf at 575cc6b988f976c23550e0db85aa1e5475d3652d
# repeats as its joint limits (research facts_x2_hands.md section 2). Left mirrors right: the signs of
# thumb_roll, thumb_abad, thumb_mcp, index_abad, ring_abad and pinky_abad flip, the pip joints keep theirs.
OMNIHAND_LIMITS = {
    "right": {"thumb_roll": (-0.17453, 0.87266), "thumb_abad": (-1.74533, 0.0), "thumb_mcp": (0.0, 0.85521),
              "index_abad": (-0.20944, 0.0), "index_pip": (0.0, 1.5708), "middle_pip": (0.0, 1.5708),
              "ring_abad": (0.0, 0.17453), "ring_pip": (0.0, 1.5708), "pinky_abad": (0.0, 0.17453),
              "pinky_pip": (0.0, 1.5708)},
    "left": {"thumb_roll": (-0.87266, 0.17453), "thumb_abad": (0.0, 1.74533), "thumb_mcp": (-0.85521, 0.0),
             "index_abad": (0.0, 0.20944), "index_pip": (0.0, 1.5708), "middle_pip": (0.0, 1.5708),
             "ring_abad": (-0.17453, 0.0), "ring_pip": (0.0, 1.5708), "pinky_abad": (-0.17453, 0.0),
             "pinky_pip": (0.0, 1.5708)},
}
# HandCommand.velocity of every OmniHand entry: what AgiBot's example sends (sorrowfeng/aimdk at the commit above,
# src/examples/src/hal/omnihand_control.cpp and src/py_examples/py_examples/omnihand_control.py: velocity 0.1,
# acceleration, deceleration and effort 0); the endeffector docs call the field unused.
OMNIHAND_VELOCITY_SENT = 0.1
# OmniPicker (HandType CLAW): one entry per hand, every field a fraction 0..1 (position 1 = open).
OMNIPICKER_ENTRIES = 1
