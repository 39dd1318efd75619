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

tests/unit/facts/test_aimdk_facts.py checks the service definitions against the shared vendor .msg/.srv files.
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
