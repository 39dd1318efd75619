"""The C++ checks bite: break the generated driver on purpose and the harness must fail.

Each mutation renders the reference G1 (unitree_dds hg, float, CRC) and PM01 (a ROS topic transport,
double), or the robots it names (the harness's go2w test robot for the unitree go family, scara,
x2, pm01_native_sdk for the EngineAI native SDK's messages), with one thing broken, builds
tests/cpp/harness/driver_harness.cpp against the result (plain flavour) and runs it. The run must fail,
with failed checks in the section that guards the broken property. A mutation changes a parsed or
generated structure, never template text (tests/support/cpp_mutate.py):
- a data mutation (``SwapSlots``) changes the RobotModel before rendering;
- a logic mutation (``TokenEdit``) changes one generated file, named by its package path, as C++
  tokens: the pattern must match exactly ``count`` times (a renamed identifier fails loudly with
  "pattern not found in <file>"), formatting and comments do not count.
The harness's fake robot is built from the unmutated package (the robot as it really is, like the harness's
expectations) unless the mutation breaks the fake robot itself; its objects are then the control's. The
DataBuffer mutation builds tests/cpp/harness/data_buffer_stress.cpp instead. A control run of the
unmodified package must pass, so the failures come from the mutations, not from the machinery.

A TokenEdit that says how it is switched at run time (``switch``) is built into a mutation schema with the
robot's other such edits: one driver build, one harness run per mutant (``--mutant=N``), and a run with every
switch off that must pass (tests/cpp/harness/README.md, "Mutation tests").
"""
from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import Executor, Future, ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from tests.support import selected, shared_use, vendor_msgs
from tests.support.cpp_build import (
    DEFAULT_DISTRO,
    OVERLAP_WORKERS,
    PACKAGE,
    WAITING_WORKERS,
    HarnessRun,
    RenderedPackage,
    build_harness,
    compile_data_buffer_stress,
    fill_custom_regions,
    load_models,
    make_test_project,
    prepare_robot_builds,
    run_binary,
    run_parallel,
    session_builder,
)
from tests.support.cpp_mutate import (
    MutationError,
    SwapSlots,
    TokenEdit,
    apply_schema,
    code_of,
    disjoint_groups,
    tokenize,
)
from tests.support.repo import REPO

ROBOTS = ("unitree/g1", "engineai/pm01")
GO_ROBOTS = ("unitree/go2w",)  # tests/cpp/harness/robots/: the go message family
TRANSMISSION_ROBOTS = ("pal/talos_arm",)  # tests/cpp/harness/robots/: motors that are not joints
ARM_SDK_ROBOTS = ("unitree/g1_upper_body",)  # tests/cpp/harness/robots/: authority upper_body
DEX3_ROBOTS = ("unitree/g1_dex3",)  # tests/cpp/harness/robots/: hands: dex3
TAKE_CONTROL_ROBOTS = ("agibot/x2_take_control",)  # tests/cpp/harness/robots/: transport_options.take_control
OMNIHAND_ROBOTS = ("agibot/x2_omnihand",)  # tests/cpp/harness/robots/: hands: omnihand
# tests/cpp/harness/robots/: the PM01 built against the EngineAI native SDK's interface_protocol
NATIVE_SDK_ROBOTS = ("engineai/pm01_native_sdk",)
# every robot a mutation runs on passes unmodified
CONTROL_ROBOTS = (*ROBOTS, *GO_ROBOTS, *TRANSMISSION_ROBOTS, *ARM_SDK_ROBOTS, *NATIVE_SDK_ROBOTS)
THREADS_MS = 100
# A harness run of a mutant takes 7 to 67 s on an idle machine (its sections mostly wait on their timers): the
# time-out bounds a hang, with room for a machine busy with other work (issue 48).
RUN_TIMEOUT_S = 600

# Generated files, by their path in the package (what the edits change, wherever the source lives).
COMMON = "include/robot_hardware_interface/common/"
DRIVER_CORE = COMMON + "driver_core.hpp"
COMMAND_CLAIMS = COMMON + "command_claims.hpp"
STATE_FRESHNESS = COMMON + "state_freshness.hpp"
COMMAND_GUARD = COMMON + "command_guard.hpp"
COMMAND_WRITER = COMMON + "command_writer.hpp"
SLOT_KERNELS = COMMON + "slot_kernels.hpp"
JOINT_TRANSMISSIONS = COMMON + "joint_transmissions.hpp"
PARAMETERS = COMMON + "hardware_parameters.hpp"
SYSTEM_DRIVER = COMMON + "system_driver.hpp"
DATA_BUFFER = COMMON + "data_buffer.hpp"
COMPAT = COMMON + "ros2_control_compat.hpp"
DRIVER_DIAGNOSTICS = COMMON + "driver_diagnostics.hpp"
TRANSPORT = "include/robot_hardware_interface/transport/"
UNITREE_CRC = TRANSPORT + "unitree_crc.hpp"
UNITREE_HG = TRANSPORT + "unitree_hg.hpp"
UNITREE_GO = TRANSPORT + "unitree_go.hpp"
UNITREE_ARM_SDK = TRANSPORT + "unitree_arm_sdk.hpp"
UNITREE_DDS = TRANSPORT + "unitree_dds.hpp"
UNITREE_DEX3 = TRANSPORT + "unitree_dex3.hpp"
AGIBOT_TOPICS = TRANSPORT + "agibot_topics.hpp"
AGIBOT_SYSTEM_STATE = TRANSPORT + "agibot_system_state.hpp"
ENGINEAI_TOPICS = TRANSPORT + "engineai_topics.hpp"
AGIBOT_TOPICS = TRANSPORT + "agibot_topics.hpp"
PM01_FAKE_ROBOT = "src/engineai/pm01_fake_robot.cpp"
G1_FAKE_ROBOT = "src/unitree/g1_fake_robot.cpp"

# The seed's double buffer (also built by test_cpp_data_buffer.py): its namespace block, comments off.
BROKEN_DOUBLE_BUFFER = code_of((REPO / "tests/cpp/harness/mutants/double_buffer.inc").read_text())


@dataclass(frozen=True)
class Mutation:
    id: str
    what: str
    change: TokenEdit | SwapSlots   # a generated file's tokens, or the RobotModel before rendering
    sections: tuple[str, ...]       # the harness sections expected to catch it
    also: tuple[str, ...] = ()      # sections that must each catch it too (the on_write mode's guarantees)
    robots: tuple[str, ...] = ROBOTS
    data_buffer: bool = False       # run data_buffer_stress instead of the driver harness
    distro: str = DEFAULT_DISTRO    # the ros2_control stand-ins the harness is built against


# TokenEdit(file, pattern, replacement[, count]): C++ snippets; "$$" in a pattern is any balanced run of tokens.
# switch: how the mutant is switched on in a mutation schema (tests/support/cpp_mutate.py); none: built alone.
STATEMENTS, OPERAND = "statements", "operand"
MUTATIONS = (
    Mutation("layer1_writer_guard", "delete layer 1: the command writer no longer waits for the first state",
             TokenEdit(DRIVER_CORE, "if (!safe_start_.first_state_received()) { return nullptr; }", "",
                       switch=STATEMENTS),
             ("safety",), also=("on_write",)),
    Mutation("layer2_initial_command", "delete layer 2: the first state no longer seeds the hold command",
             TokenEdit(DRIVER_CORE, "motor_command_buffer_.set_data(initial_cmd_cache_);", "",
                       switch=STATEMENTS), ("safety",)),
    Mutation("layer3_write_guard", "delete layer 3: write() forwards commands before read() copied a state",
             TokenEdit(DRIVER_CORE, "if (!safe_start_.state_copied()) { return false; }", "", switch=STATEMENTS),
             ("safety",), also=("on_write",)),
    Mutation("layer3_first_write_seed", "layer 3: the first write() no longer targets the measured position",
             TokenEdit(DRIVER_CORE, "frames_.joints.pos_des = frames_.joints.pos;", "", switch=STATEMENTS), ("safety",),
             also=("on_write",)),
    Mutation("default_gains_ignored", "a position-only controller gets zero stiffness instead of the default",
             TokenEdit(COMMAND_CLAIMS,
                       "position_mode && (claims & kClaimPosition) != 0U ? slots_.default_stiffness(i) : 0.0", "0.0",
                       switch=OPERAND),
             ("command_modes",), robots=("unitree/g1",)),
    Mutation("velocity_joint_position_target", "a velocity-commanded joint is sent the stale position target",
             TokenEdit(DRIVER_CORE, "command.q_target[slot] = static_cast<T>(frames_.joints.pos[slot]);",
                       "command.q_target[slot] = static_cast<T>(frames_.joints.pos_des[slot]);", switch=STATEMENTS),
             ("command_modes",), robots=("acme/scara",)),
    Mutation("nan_command_bounded", "write() bounds a NaN command to the lower limit instead of passing it on",
             TokenEdit(SLOT_KERNELS, "const T raised = rounded < lower ? lower : rounded;",
                       "const T raised = !(rounded >= lower) ? lower : rounded;", switch=OPERAND), ("command_safety",)),
    Mutation("agibot_duplicate_entry", "a JointStateArray naming one joint twice stands in for a missing joint",
             TokenEdit(AGIBOT_TOPICS, "if (slot_stamps_[slot] == stamp)", "if (false)", switch=OPERAND), ("joint_map",),
             robots=("agibot/x2",)),
    Mutation("joint_map_swap", "the robot's joint table swaps the SDK slots of motors 0 and 1",
             SwapSlots(0, 1), ("joint_map",)),
    Mutation("crc_polynomial", "CRC32 with a wrong polynomial",
             TokenEdit(UNITREE_CRC, "kPolynomial = 0x04C11DB7U", "kPolynomial = 0x04C11DB6U"),
             ("crc", "commands", "safety"), robots=("unitree/g1",)),
    Mutation("crc_skips_lowcmd_field", "LowCmd_ CRC skips MotorCmd_.reserve",
             TokenEdit(UNITREE_HG, "{8, 24, kMotorSlots, 28}", "{8, 20, kMotorSlots, 28}"), ("crc", "commands"),
             robots=("unitree/g1",)),
    Mutation("crc_skips_lowstate_field", "LowState_ CRC skips MotorState_.reserve[3]",
             TokenEdit(UNITREE_HG, "{76, 52, kMotorSlots, 56}", "{76, 48, kMotorSlots, 56}"), ("crc", "safety"),
             robots=("unitree/g1",)),
    Mutation("crc_hashes_lowstate_padding", "hg LowState_ CRC hashes the 2 padding bytes after mode_machine",
             TokenEdit(UNITREE_HG, "{8, 2, 1, 0}", "{8, 4, 1, 0}"), ("crc", "safety"), robots=("unitree/g1",)),
    # unitree go family (Go2, Go2-W, B2, B2-W, H1), on the harness's go2w test robot.
    Mutation("go_crc_hashes_padding", "go LowState_ CRC hashes the 3 padding bytes after imu_state.temperature",
             TokenEdit(UNITREE_GO, "{24, 53, 1, 0}", "{24, 56, 1, 0}"), ("crc", "safety"), robots=GO_ROBOTS),
    Mutation("go_head_bytes", "go LowCmd_.head[0] is 0xEF instead of 0xFE",
             TokenEdit(UNITREE_GO, "kHead0 = 0xFE;", "kHead0 = 0xEF;"), ("commands",), robots=GO_ROBOTS),
    Mutation("go_motor_modes_ignored", "go LowCmd_ slots get mode 0x01 where motor_modes says 0 (stop)",
             TokenEdit(UNITREE_GO, "motor.mode() = motor_modes[slot];",
                       "motor.mode() = static_cast<uint8_t>(motor_modes[slot] | 0x01U);", switch=STATEMENTS),
             ("commands",), robots=GO_ROBOTS),
    Mutation("imu_quaternion_order", "read() exports x as orientation.w",
             TokenEdit(DRIVER_CORE, "imu_data_.orientation[3] = static_cast<double>(imu->quat[0]);",
                       "imu_data_.orientation[3] = static_cast<double>(imu->quat[1]);", switch=STATEMENTS), ("imu",)),
    Mutation("decimation", "state decimation off by one",
             TokenEdit(STATE_FRESHNESS, "frame_count % decimation", "frame_count % (decimation + 1)",
                       switch=OPERAND), ("decimation",)),
    Mutation("stale_ignores_decimated_frames", "decimated frames no longer count as state arriving",
             TokenEdit(STATE_FRESHNESS, "if (frames_valid_) { mark_fresh($$); }", "",
                       switch=STATEMENTS), ("decimation",)),
    Mutation("stale_masked_by_decimated_frames", "decimated frames keep the state fresh after a rejected frame",
             TokenEdit(STATE_FRESHNESS, "if (frames_valid_)", "if (true)", switch=OPERAND), ("decimation",)),
    Mutation("stale_state_never_held", "the command writer never notices that the state stopped",
             TokenEdit(STATE_FRESHNESS, "return age_ns > static_cast<int64_t>(timeout_ms) * 1000000;",
                       "return age_ns < 0 && timeout_ms == 0;", switch=STATEMENTS), ("command_safety",),
             also=("on_write",)),
    Mutation("dead_link_never_faults", "read() never returns ERROR: controllers keep running on a held state",
             TokenEdit(SYSTEM_DRIVER, "const bool link_dead = $$ && core_.link_dead($$);",
                       "const bool link_dead = false;", switch=OPERAND), ("faults",)),
    Mutation("dead_link_never_answered", "a robot that never answers after on_activate never faults: the "
             "wait for the first state is not counted",
             TokenEdit(STATE_FRESHNESS, "last_ns > activated_ns ? last_ns : activated_ns",
                       "last_ns > activated_ns ? last_ns : now_ns", switch=OPERAND),
             ("faults",)),
    Mutation("error_hold_released", "on_error does not latch the hold: once the state is back the last "
             "controller command is sent again",
             TokenEdit(SYSTEM_DRIVER, "core_.hold_until_activation();", "",
                       switch=STATEMENTS), ("faults",), also=("on_write",)),
    # command_writer_mode on_write (common/command_writer.hpp): the writer woken by write()
    Mutation("on_write_no_rate_limit", "on_write: the writer sends on every write(), faster than the period allows",
             TokenEdit(COMMAND_WRITER, "if (Clock::now() < allowed) { $$ }", "static_cast<void>(allowed);",
                       switch=STATEMENTS),
             ("on_write",),
             robots=("unitree/g1",)),
    Mutation("on_write_no_fallback", "on_write: the writer sends only when write() wakes it, so no hold flows "
             "once ros2_control stops calling write() (on_error)",
             TokenEdit(COMMAND_WRITER, "wake_.wait_until(lock, due, [this]() {return woken_ || stopping_;});",
                       "wake_.wait(lock, [this]() {return woken_ || stopping_;}); static_cast<void>(due);",
                       switch=STATEMENTS),
             ("on_write",), robots=("engineai/pm01",)),
    Mutation("on_write_not_woken", "on_write: write() does not wake the writer: commands leave on its period only",
             TokenEdit(DRIVER_CORE, "on_write_writer_.notify();", "",
                       switch=STATEMENTS), ("on_write",), robots=("unitree/g1",)),
    Mutation("negative_gain_forwarded", "the command guard forwards a negative gain",
             TokenEdit(COMMAND_GUARD, "&& cmd.kp[i] >= 0 && cmd.kd[i] >= 0", "&& true",
                       switch=OPERAND), ("command_safety",)),
    Mutation("fetch_unclaimed", "write() fetches every command handle, claimed or not (framework-owned handles)",
             TokenEdit(COMPAT, "fetched_links = claimed_links_;", "fetched_links = command_links_;", switch=OPERAND),
             ("command_modes",), robots=("unitree/g1",), distro="jazzy"),
    Mutation("fetch_torn", "write() keeps what it fetched when a handle a controller is writing refused its lock: "
             "the refused joint keeps the previous command (a frame mixing two commands, the async section's tear)",
             TokenEdit(COMPAT, "if (refused != 0U) { return false; }", "", switch=STATEMENTS),
             ("async",), robots=("unitree/g1",), distro="jazzy"),
    Mutation("parameter_range", "an out-of-range parameter (0) is accepted",
             TokenEdit(PARAMETERS, "|| parsed < min ||", "|| false ||", switch=OPERAND), ("parameters",)),
    Mutation("hot_path_allocation", "write() allocates",
             TokenEdit(SYSTEM_DRIVER, "fetch_command_values();",
                       "fetch_command_values(); { std::vector<double> rhi_mutant(8); (void)rhi_mutant; }",
                       switch=STATEMENTS),
             ("allocations",)),
    Mutation("transmission_effort_scaled", "read() scales a motor's effort like its position, not by the inverse",
             TokenEdit(SLOT_KERNELS, "joints.tau[i] = factors.inverse[i] *", "joints.tau[i] = factors.scale[i] *"),
             ("transmission",), robots=TRANSMISSION_ROBOTS),
    Mutation("coupled_command_untransformed", "write() sends a coupled group's joint targets to its motors as they are",
             TokenEdit(JOINT_TRANSMISSIONS, "command.q_target[motor] = static_cast<T>(q);", "", switch=STATEMENTS),
             ("transmission",), robots=TRANSMISSION_ROBOTS),
    Mutation("calibration_ignored", "on_configure reads the calibration file but does not apply it",
             TokenEdit(DRIVER_CORE, "transmissions_.calibrate($$);", "static_cast<void>(entry);",
                       switch=STATEMENTS), ("transmission",),
             robots=("engineai/pm01",)),
    Mutation("inactive_component_faults", "read() of an inactive, silent component returns ERROR",
             TokenEdit(SYSTEM_DRIVER, "const bool active = active_.load(std::memory_order_relaxed);",
                       "const bool active = true;", switch=OPERAND), ("faults",),
             robots=("engineai/pm01",)),
    Mutation("estop_ignored", "write() never presses the e-stop the health GPIO commands",
             TokenEdit(SYSTEM_DRIVER, "press_estop();", "", switch=STATEMENTS), ("health",), robots=("engineai/pm01",)),
    Mutation("invalid_states_uncounted", "a rejected state frame does not count in the health GPIO",
             TokenEdit(STATE_FRESHNESS, "return invalid_states_.add();", "return 0;", switch=STATEMENTS), ("health",),
             robots=("engineai/pm01",)),
    Mutation("stale_holds_per_send", "every send of a stale hold counts as a new stale episode",
             TokenEdit(COMMAND_GUARD, "if (!holding_) { stale_holds_.add(); }", "stale_holds_.add();",
                       switch=STATEMENTS),
             ("health",), robots=("unitree/g1",)),
    Mutation("motor_health_not_published", "read() takes a new motor health frame but never writes its handles "
             "(framework-owned handles)", TokenEdit(SYSTEM_DRIVER, "publish_slow_state_values();", "",
                                                    switch=STATEMENTS), ("health",),
             robots=("unitree/g1",), distro="jazzy"),
    Mutation("hg_second_temperature", "the hg transport reports MotorState_.temperature[1] as the temperature",
             TokenEdit(UNITREE_HG, "motor.temperature()[0]", "motor.temperature()[1]", switch=OPERAND), ("health",),
             robots=("unitree/g1",)),
    Mutation("first_state_wait_ignored", "a first state later than fault_timeout_ms faults the driver at start-up "
             "(the DDS discovery race): first_state_timeout_ms not applied",
             TokenEdit(DRIVER_CORE, "!safe_start_.first_state_received(), parameters_.fault_timeout_ms,",
                       "false, parameters_.fault_timeout_ms,", switch=OPERAND),
             ("faults",), robots=("engineai/pm01",)),
    Mutation("never_answered_not_said", "a robot that never answered is reported as a link that died",
             TokenEdit(SYSTEM_DRIVER, "if (!core_.first_state_received()) {", "if (false) {", switch=OPERAND),
             ("faults",), robots=("unitree/g1",)),
    Mutation("estop_not_diagnosed", "/diagnostics reports the safety of a robot held by the e-stop as fine",
             TokenEdit(DRIVER_DIAGNOSTICS, "if (facts.estop) {", "if (false) {", switch=OPERAND), ("diagnostics",),
             robots=("engineai/pm01",)),
    Mutation("hot_motor_ignored", "a motor at motor_temperature_error_c does not fault the driver",
             TokenEdit(SYSTEM_DRIVER, "faulty_slot_ = faulty_motor_slot();", "",
                       switch=STATEMENTS), ("health",), robots=("unitree/g1",)),
    Mutation("motor_error_mask_ignored", "a motor error code with a bit of motor_error_fault_mask does not fault",
             TokenEdit(SYSTEM_DRIVER, "core_.parameters().motor_error_fault_mask) != 0U;", "0U) != 0U;",
                       switch=OPERAND),
             ("diagnostics",), robots=("unitree/g1",)),
    Mutation("engineai_offline_ignored", "the EngineAI transport drops the native SDK's MotorDebug offline flags: "
             "an offline motor neither faults nor shows",
             TokenEdit(ENGINEAI_TOPICS, "health.offline[slot] = msg.offline[slot] != 0U;",
                       "health.offline[slot] = false;", switch=OPERAND),
             ("offline",), robots=NATIVE_SDK_ROBOTS),
    Mutation("motor_groups_mixed_up", "every /diagnostics motor group status lists the first group's joints",
             TokenEdit(DRIVER_DIAGNOSTICS, "if (joint.motor_group != group) {",
                       "if (joint.motor_group != 0 * group) {", switch=OPERAND),
             ("diagnostics",), robots=("engineai/pm01",)),
    Mutation("hardware_status_hides_estop", "ros2_control's ~/hardware_status does not name the e-stop (5.10+)",
             TokenEdit(SYSTEM_DRIVER, "state.error_domain.push_back(State::EMERGENCY_STOP_SW);", "", switch=STATEMENTS),
             ("diagnostics",), robots=("engineai/pm01",), distro="kilted"),
    Mutation("fake_robot_motor_map_wrong", "the fake robot drives the first joint on the second joint's motor",
             TokenEdit(PM01_FAKE_ROBOT, '{"J00_HIP_PITCH_L", 0,', '{"J00_HIP_PITCH_L", 1,'),
             ("fake_robot",), robots=("engineai/pm01",)),
    Mutation("fake_robot_motor_map_wrong_sdk", "the G1's fake robot drives its first joint on the second joint's motor",
             TokenEdit(G1_FAKE_ROBOT, '{"left_hip_pitch_joint", 0,', '{"left_hip_pitch_joint", 1,'),
             ("fake_robot",), robots=("unitree/g1",)),
    Mutation("arm_sdk_weight_jumps", "the arm SDK blend weight jumps from 0 to 1 (and back) in one message",
             TokenEdit(UNITREE_ARM_SDK, "step_(std::min(1.0, static_cast<double>(period_us) * 1e-6 / ramp_s))",
                       "step_(1.0 + 0.0 * ramp_s * static_cast<double>(period_us))", switch=OPERAND),
             ("arm_sdk",), robots=ARM_SDK_ROBOTS),
    Mutation("arm_sdk_legs_commanded", "under the arm SDK the command writer fills the legs' slots too",
             TokenEdit(UNITREE_DDS, "for (const size_t slot : core.slots().commanded_slots()) {",
                       "for (const size_t slot : core.slots().mapped_slots()) {"),
             ("arm_sdk",), robots=ARM_SDK_ROBOTS),
    Mutation("arm_sdk_no_hand_back", "on_deactivate stops the arm SDK at the weight it had, without ramping to 0",
             TokenEdit(UNITREE_DDS, "if (arm_sdk_ != nullptr) { hand_back_upper_body(); }", "", switch=STATEMENTS),
             ("arm_sdk",), robots=ARM_SDK_ROBOTS),
    Mutation("dex3_mode_timeout", "every Dex3-1 motor's mode byte carries the timeout bit (the SDK's stop)",
             TokenEdit(UNITREE_DEX3, "(kStatusRun << 4U)", "(kStatusRun << 4U) | 0x80U"),
             ("hands",), robots=DEX3_ROBOTS),
    Mutation("dex3_hands_swapped", "the left hand's HandState_ feeds the right hand's joints and back",
             TokenEdit(UNITREE_DEX3, "on_hand_state(side, *static_cast<const HandState *>(message));",
                       "on_hand_state(1 - side, *static_cast<const HandState *>(message));", switch=OPERAND),
             ("hands",), robots=DEX3_ROBOTS),
    Mutation("dex3_state_without_hands", "the body's state counts as complete before both hands have reported",
             TokenEdit(UNITREE_DEX3, "return complete;", "return true || complete;", switch=OPERAND),
             ("hands",), robots=DEX3_ROBOTS),
    Mutation("take_control_after_commands", "the driver starts commanding before it has taken control",
             TokenEdit(AGIBOT_TOPICS, "if (!control_.take(executor_, core_->logger())) { return false; }",
                       "executor_.start(core_->parameters().command_writer_period_us, core_->logger(), "
                       "core_->on_write_writer(), [this]() {write_command();}); "
                       "std::this_thread::sleep_for(std::chrono::milliseconds(20)); "
                       "executor_.stop(); if (!control_.take(executor_, core_->logger())) { return false; }",
                       switch=STATEMENTS),
             ("take_control",), robots=TAKE_CONTROL_ROBOTS),
    Mutation("take_control_refusal_ignored", "a refused Develop_MC is taken for an accepted one",
             TokenEdit(AGIBOT_SYSTEM_STATE, "if (header.header.code != 0 || header.status.value != "
                       "aimdk_msgs::msg::CommonState::SUCCESS) {", "if (false) {", switch=OPERAND),
             ("take_control",), robots=TAKE_CONTROL_ROBOTS),
    Mutation("take_control_never_released", "on_deactivate leaves the robot in Develop_MC",
             TokenEdit(AGIBOT_TOPICS, "control_.release(executor_, core_->logger());", "", switch=STATEMENTS),
             ("take_control",), robots=TAKE_CONTROL_ROBOTS),
    Mutation("omnihand_hands_swapped", "the left hand's HandStateArray entries feed the right hand's joints and back",
             TokenEdit(AGIBOT_TOPICS, "store(hands.first_slot + i, msg.left_hands[i]); "
                       "store(hands.first_slot + hands.axes + i, msg.right_hands[i]);",
                       "store(hands.first_slot + i, msg.right_hands[i]); "
                       "store(hands.first_slot + hands.axes + i, msg.left_hands[i]);", switch=STATEMENTS),
             ("hands",), robots=OMNIHAND_ROBOTS),
    Mutation("omnihand_type_unchecked", "a HandStateArray from hands of another type is taken for the OmniHands'",
             TokenEdit(AGIBOT_TOPICS, "if (msg.left_hand_type.value != hands.hand_type || "
                       "msg.right_hand_type.value != hands.hand_type) {", "if (false) {", switch=OPERAND),
             ("hands",), robots=OMNIHAND_ROBOTS),
    Mutation("omnihand_current_as_effort", "the OmniHand's motor current reaches the joints' effort",
             TokenEdit(AGIBOT_TOPICS, "state.tau[slot] = T{0};", "state.tau[slot] = static_cast<T>(axis.effort);",
                       switch=OPERAND),
             ("hands",), robots=OMNIHAND_ROBOTS),
    Mutation("double_buffer", "DataBuffer hands out a slot the producer can overwrite (the seed's double buffer)",
             TokenEdit(DATA_BUFFER, "namespace robot_hardware_interface { $$ }", BROKEN_DOUBLE_BUFFER),
             ("contract", "stress_1_producer", "stress_2_producers"), robots=(), data_buffer=True),
)


def mutated_plan(models, mutation: Mutation | None) -> dict[str, str]:
    """The package plan for ``models`` with ``mutation`` applied to the models (before rendering) or
    to the rendered plan (after). Raises MutationError when the mutation does not apply as written."""
    from rhi_gen.render.package import render_package

    change = mutation.change if mutation else None
    if isinstance(change, SwapSlots):
        models = [change.apply_to_model(m) for m in models]
    plan = render_package(models)
    if isinstance(change, TokenEdit):
        assert mutation is not None
        change.apply_to_plan(plan, mutation.id)
    return plan


def render_mutated_package(root: Path, mutation: Mutation | None, robots: tuple[str, ...],
                           schema: Sequence[tuple[TokenEdit, int]] = ()) -> RenderedPackage:
    """tests/support/cpp_build.py: render_test_package, with ``mutation`` applied (and the
    ``schema``'s (edit, mutant number) pairs switched in). robot_data.hpp comes from
    the unmodified models and the vendor YAMLs: what the harness expects is what the robot really is."""
    extra = any(label not in ROBOTS for label in robots)  # the harness's test robots
    project = make_test_project(root / "project", extra_robots=extra, only=robots)
    loaded = load_models(project)
    plan = mutated_plan([r.model for r in loaded], mutation)
    if schema:
        apply_schema(plan, schema)
    package_dir = root / "generated" / PACKAGE
    for rel, text in plan.items():
        path = package_dir / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    fill_custom_regions(loaded, package_dir)
    return RenderedPackage(project, package_dir, loaded, prepare_robot_builds(loaded, package_dir, root / "work"))


@dataclass
class Outcome:
    mutation: Mutation | None
    robot: str            # "vendor/robot" or "data_buffer"
    built: bool
    build_error: str
    run: HarnessRun | None    # None when it did not build
    seconds: float
    skipped: str | None = None   # why this robot was not built (its vendor messages are missing)
    not_applied: str | None = None  # the mutation does not apply as written (MutationError)
    schema: str = ""      # the mutation schema it ran in (its mutant switched on), "" when built alone


def breaks_the_robot(mutation: Mutation) -> bool:
    """Whether ``mutation`` breaks the fake robot (its own sources) rather than the driver."""
    change = mutation.change
    return isinstance(change, TokenEdit) and Path(change.file).stem.endswith("_fake_robot")


class RenderedOnce:
    """Packages rendered once each, by key, however many jobs ask (their objects are then compiled once too): the
    unmutated package of a set of robots (a mutation of the driver runs against the fake robot as the robot really
    is, as the harness's expectations, robot_data.hpp, already are) or a schema's package."""

    def __init__(self, root: Path, render: Callable[[Any, Path], RenderedPackage]) -> None:
        self._root = root
        self._render = render
        self._lock = threading.Lock()
        self._packages: dict[Any, RenderedPackage] = {}

    def package(self, key: Any) -> RenderedPackage:
        with self._lock:
            if key not in self._packages:
                self._packages[key] = self._render(key, self._root / f"package{len(self._packages)}")
            return self._packages[key]


def mutant_number(mutation: Mutation) -> int:
    """The mutant's switch in a mutation schema (--mutant=N of the harness binary; 0 runs none)."""
    return MUTATIONS.index(mutation) + 1


def switched(mutation: Mutation) -> bool:
    """Whether ``mutation`` is built into a mutation schema (tests/support/cpp_mutate.py) rather than alone: an
    edit of the driver that says how it is switched at run time."""
    change = mutation.change
    return isinstance(change, TokenEdit) and bool(change.switch) and not mutation.data_buffer \
        and not breaks_the_robot(mutation)


@dataclass(frozen=True)
class Schema:
    """One robot's driver with ``mutants`` switched in, built once against ``distro``'s stand-ins."""
    robot: str
    distro: str
    index: int                       # the robot's schemata are numbered (their matches must not overlap)
    mutants: tuple[Mutation, ...]

    @property
    def name(self) -> str:
        return f"schema_{self.robot.replace('/', '_')}_{self.distro}_{self.index}"


def plan_schemata(mutations: list[Mutation], root: Path) -> dict[tuple[str, str], Schema]:
    """{(mutation id, robot): its schema} for the switched ``mutations``: per robot and distro, the mutants in as
    few schemata as their non-overlapping matches allow."""
    wanted: dict[tuple[str, str], list[Mutation]] = {}
    for mutation in mutations:
        for robot in mutation.robots:
            wanted.setdefault((robot, mutation.distro), []).append(mutation)
    plans: dict[str, dict[str, str]] = {}
    where: dict[tuple[str, str], Schema] = {}
    for (robot, distro), members in sorted(wanted.items()):
        if robot not in plans:
            loaded = load_models(make_test_project(root / robot.replace("/", "_"), extra_robots=robot not in ROBOTS,
                                                   only=(robot,)))
            plans[robot] = mutated_plan([r.model for r in loaded], None)
        edits = [(m.change, mutant_number(m)) for m in members]
        by_number = {mutant_number(m): m for m in members}
        for index, group in enumerate(disjoint_groups(plans[robot], edits)):  # type: ignore[arg-type]
            schema = Schema(robot, distro, index, tuple(by_number[n] for _, n in group))
            for mutant in schema.mutants:
                where[(mutant.id, robot)] = schema
    return where


def render_schema_package(root: Path, schema: Schema) -> RenderedPackage:
    """render_mutated_package for a schema: the robot's package with every mutant of ``schema`` switched in."""
    return render_mutated_package(root, None, (schema.robot,),
                                  [(m.change, mutant_number(m)) for m in schema.mutants])  # type: ignore[misc]


@dataclass(frozen=True)
class Plan:
    """Where the fixture's jobs build (the unmutated robots, and the schemata of the switched mutants), and where
    their binaries run."""
    robot_sides: RenderedOnce   # by robots: their unmutated package
    schemata: dict[tuple[str, str], Schema]
    packages: RenderedOnce      # by Schema: its package
    runs: Executor              # the runs' own threads: a job's thread goes on to the next build meanwhile


def _run_later(plan: Plan, mutation: Mutation | None, robot: str, link, args: list[str], start: float,
               schema: str = "") -> Future[Outcome]:
    """The Outcome of running ``link``'s binary with ``args`` (no run when it did not link), on the runs' threads."""
    def run() -> Outcome:
        ran = run_binary(link.path, args, timeout=RUN_TIMEOUT_S) if link.ok else None
        return Outcome(mutation, robot, link.ok, link.stderr, ran, time.monotonic() - start, schema=schema)
    return plan.runs.submit(run)


def _run_schema_mutant(mutation: Mutation | None, schema: Schema, builder, plan: Plan) -> Future[Outcome]:
    """``mutation`` switched on in ``schema``'s harness binary (None: every switch off, the schema's control)."""
    start = time.monotonic()
    package = plan.packages.package(schema)
    link, _ = build_harness(builder, package.build(schema.robot), "plain", schema.distro,
                            plan.robot_sides.package((schema.robot,)).build(schema.robot))
    mutant = [f"--mutant={mutant_number(mutation)}"] if mutation else []
    return _run_later(plan, mutation, schema.robot, link, [f"--threads-ms={THREADS_MS}", *mutant], start, schema.name)


def _run_one(job, tmp_root: Path, builder, plan: Plan) -> list[Outcome | Future[Outcome]]:
    """Builds ``job`` (a Schema's control, a mutation or the control) and starts its runs (the futures)."""
    if isinstance(job, Schema):
        reason = vendor_msgs.skip_reason(plan.robot_sides.package((job.robot,)).build(job.robot).model.transport)
        if reason:
            return [Outcome(None, job.robot, False, "", None, 0.0, skipped=reason, schema=job.name)]
        return [_run_schema_mutant(None, job, builder, plan)]
    mutation: Mutation | None = job
    name = mutation.id if mutation else "control"
    root = tmp_root / name
    start = time.monotonic()
    robots = mutation.robots if mutation else CONTROL_ROBOTS
    outcomes: list[Outcome | Future[Outcome]] = []
    if mutation is not None and switched(mutation):
        for label in robots:
            reason = vendor_msgs.skip_reason(plan.robot_sides.package((label,)).build(label).model.transport)
            if reason:
                outcomes.append(Outcome(mutation, label, False, "", None, 0.0, skipped=reason))
                continue
            outcomes.append(_run_schema_mutant(mutation, plan.schemata[(mutation.id, label)], builder, plan))
        return outcomes
    try:
        package = render_mutated_package(root, mutation, robots or ROBOTS[:1])
    except MutationError as err:  # this mutation's test fails with the message; the others run
        return [Outcome(mutation, "-", False, "", None, time.monotonic() - start, not_applied=str(err))]
    robot_side = package if mutation is None or breaks_the_robot(mutation) or not robots else \
        plan.robot_sides.package(robots)
    if mutation is None or mutation.data_buffer:
        buffer = compile_data_buffer_stress(builder, package.package_dir, "plain")
        outcomes.append(_run_later(plan, mutation, "data_buffer", buffer, [], start))
    for label in robots:
        reason = vendor_msgs.skip_reason(package.build(label).model.transport)
        if reason:
            outcomes.append(Outcome(mutation, label, False, "", None, 0.0, skipped=reason))
            continue
        distro = mutation.distro if mutation else DEFAULT_DISTRO
        link, _ = build_harness(builder, package.build(label), "plain", distro, robot_side.build(label))
        outcomes.append(_run_later(plan, mutation, label, link, [f"--threads-ms={THREADS_MS}"], start))
    return outcomes


@pytest.fixture(scope="module")
def outcomes(tmp_path_factory, request):
    """The control (None), the mutations the session's selected tests name (all of them in a whole run) and the
    control of each schema they are switched into (its name)."""
    builder = session_builder(tmp_path_factory)
    tmp_root = tmp_path_factory.mktemp("mutations")
    chosen = selected.keep([None, *MUTATIONS], selected.values(request, "mutation", unparametrized=None))
    try:
        schemata = plan_schemata([m for m in chosen if m is not None and switched(m)], tmp_root / "plan")
    except MutationError as err:
        pytest.fail(f"the mutation schemata cannot be planned: {err}")
    robot_sides = RenderedOnce(tmp_root / "robot_sides",
                               lambda robots, where: render_mutated_package(where, None, robots))
    packages = RenderedOnce(tmp_root / "schemata", lambda schema, where: render_schema_package(where, schema))
    # A job's thread builds, then hands its binary to the runs' threads: a run takes 7 to 67 s, mostly waiting on
    # timers, and many run at once while the builds go on (the builder keeps one compiler per core).
    runs = ThreadPoolExecutor(max_workers=WAITING_WORKERS)
    plan = Plan(robot_sides, schemata, packages, runs)
    # The mutants built alone first: theirs are the longest runs (a CRC table that drops every frame waits out every
    # check's deadline: a minute). Then the schemata's controls, each building its schema, which its mutants' jobs
    # then wait for: the schemata with the most mutants (G1's and PM01's, 23 each) first, so that the runs left
    # when the last build is done are few.
    alone = [m for m in chosen if m is None or not switched(m)]
    by_size = sorted(set(schemata.values()), key=lambda s: (-len(s.mutants), s.name))
    first_schema = {mid: min(by_size.index(s) for (m, _), s in schemata.items() if m == mid) for mid, _ in schemata}
    jobs = [*alone, *by_size, *sorted((m for m in chosen if m not in alone), key=lambda m: first_schema[m.id])]

    def run_one(job):  # each job records what it read of ../shared (the X2's mutations), not the whole fixture
        with shared_use.recording() as used:
            return _run_one(job, tmp_root, builder, plan), set(used)

    with runs:
        started = run_parallel(jobs, run_one, OVERLAP_WORKERS)
        results = [([o.result() if isinstance(o, Future) else o for o in pending], used) for pending, used in started]
    return shared_use.Recorded({(job.name if isinstance(job, Schema) else job.id if job else "control"): result
                                for job, result in zip(jobs, results, strict=True)})


def _built(outcomes_of_one: list[Outcome]) -> list[Outcome]:
    """The outcomes that were attempted; a skip when none was (no robot had its vendor messages)."""
    for o in outcomes_of_one:
        assert o.not_applied is None, o.not_applied
    attempted = [o for o in outcomes_of_one if o.skipped is None]
    if not attempted:
        pytest.skip("; ".join(o.skipped for o in outcomes_of_one if o.skipped is not None))
    return attempted


def test_control_unmodified_package_passes(outcomes):
    for o in _built(outcomes["control"]):
        assert o.built, f"control {o.robot} does not build:\n{o.build_error[:4000]}"
        assert o.run is not None
        assert o.run.returncode == 0 and o.run.failed == 0, f"control {o.robot}: {o.run.describe()}"


def test_every_schema_passes_with_its_mutants_off(outcomes):
    """A schema with every switch off is the robot as generated: it builds, and every check passes."""
    schemata = [name for name in outcomes if name.startswith("schema_")]
    assert bool(schemata) == any(switched(m) and m.id in outcomes for m in MUTATIONS), schemata
    if not schemata:
        pytest.skip("no switched mutation is selected: run with test_mutation_is_caught to build their schemata")
    # quietly: what the X2's schemata read of ../shared does not make this test one that reads it; without it
    # they are skipped here, and their mutants' own tests (which a fresh clone runs) say so
    ran = {name: outcomes.quietly(name) for name in schemata}
    if all(o.skipped is not None for runs in ran.values() for o in runs):
        pytest.skip("; ".join(o.skipped for runs in ran.values() for o in runs if o.skipped is not None))
    for name, runs in ran.items():
        for o in (o for o in runs if o.skipped is None):
            assert o.built, f"{name} does not build:\n{o.build_error[:4000]}"
            assert o.run is not None
            assert o.run.returncode == 0 and o.run.failed == 0, f"{name}, every mutant off: {o.run.describe()}"


@pytest.mark.parametrize("mutation", MUTATIONS, ids=[m.id for m in MUTATIONS])
def test_mutation_is_caught(outcomes, mutation):
    for o in _built(outcomes[mutation.id]):
        assert o.built, (f"{mutation.id} ({mutation.what}): {o.robot} no longer compiles, so this mutation "
                         f"proves nothing; adjust it:\n{o.build_error[:4000]}")
        run = o.run
        assert run is not None
        failed_sections = sorted(name for name, (_, f) in run.sections.items() if f > 0)
        assert run.returncode != 0, (f"{mutation.id} ({mutation.what}) was NOT caught for {o.robot}: "
                                     f"{run.passed} checks passed, none failed")
        assert set(failed_sections) & set(mutation.sections), (
            f"{mutation.id} ({mutation.what}) on {o.robot} failed, but not in {mutation.sections}: "
            f"failed sections {failed_sections}\n{run.describe()}")
        assert not set(mutation.also) - set(failed_sections), (
            f"{mutation.id} ({mutation.what}) on {o.robot} was not caught by {sorted(mutation.also)}: "
            f"failed sections {failed_sections}\n{run.describe()}")


def test_every_mutation_applies_and_changes_the_code(tmp_path):
    """Without a compiler: each mutation applies to the package as generated today (patterns found the
    expected number of times, slots mapped) and changes the C++ tokens of what it should, and nothing
    shared with other robots: a TokenEdit its one file; SwapSlots each robot's driver source (and only
    files of that robot)."""
    from rhi_gen.render.package import robot_paths

    models = {f"{m.vendor}/{m.robot}": m for m in (r.model for r in load_models(make_test_project(tmp_path)))}
    references: dict[tuple[str, ...], dict[str, str]] = {}
    for mutation in MUTATIONS:
        labels = mutation.robots or ROBOTS[:1]
        robots = [models[label] for label in labels]
        if labels not in references:
            references[labels] = mutated_plan(robots, None)
        reference = references[labels]
        plan = mutated_plan(robots, mutation)
        assert plan.keys() == reference.keys(), mutation.id
        changed = {path for path in plan
                   if plan[path] != reference[path] and _code(path, plan[path]) != _code(path, reference[path])}
        if isinstance(mutation.change, TokenEdit):
            assert changed == {mutation.change.file}, f"{mutation.id} changed {sorted(changed)}"
        else:
            drivers = {f"src/{m.vendor}/{m.robot}.cpp" for m in robots}
            own = {path for m in robots for path in robot_paths(m.vendor, m.robot)}
            assert drivers <= changed <= own, f"{mutation.id} changed {sorted(changed)}"


def _code(path: str, text: str):
    """What a change of the file must change: C++ tokens, or the text of any other file."""
    return [(t.kind, t.text) for t in tokenize(text)] if path.endswith((".hpp", ".cpp")) else text


def test_every_schema_switches_each_of_its_mutants(tmp_path):
    """Without a compiler: the switched mutations fall into schemata (per robot and distro, matches apart), and
    each schema's package asks for each of its mutants where its edit matches, as often as it matches."""
    schemata = plan_schemata([m for m in MUTATIONS if switched(m)], tmp_path / "plan")
    assert {(m.id, robot) for m in MUTATIONS if switched(m) for robot in m.robots} == set(schemata)
    for schema in sorted(set(schemata.values()), key=lambda s: s.name):
        plan = render_schema_package(tmp_path / schema.name, schema)
        for mutant in schema.mutants:
            assert isinstance(mutant.change, TokenEdit)
            text = (plan.package_dir / mutant.change.file).read_text(encoding="utf-8")
            assert text.count(f"rhi_mutant_on({mutant_number(mutant)})") == mutant.change.count, (schema, mutant.id)
