// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <rclcpp/clock.hpp>
#include <rclcpp/logger.hpp>
#include <rclcpp/logging.hpp>

#include "robot_hardware_interface/common/data_buffer.hpp"
#include "robot_hardware_interface/common/hardware_parameters.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/motor_types.hpp"
#include "robot_hardware_interface/common/robot_spec.hpp"
#include "robot_hardware_interface/common/slot_kernels.hpp"
#include "robot_hardware_interface/common/types.hpp"

namespace robot_hardware_interface
{

// True when every value is finite: NaN and infinity never reach ros2_control or the motors.
template<typename ... Values>
bool all_finite(Values... values)
{
  for (const double value : {static_cast<double>(values)...}) {
    if (!std::isfinite(value)) {
      return false;
    }
  }
  return true;
}

// The robot-independent part of every driver: the thread hand-off, the three-layer safe start,
// command safety, decimation, the stale-state hold and monitoring. It knows nothing of
// ros2_control's API (SystemDriver adapts it) nor of any SDK (transports feed it).
//
// Threads:
//   - controller: read() / write() through read_state() and write_command();
//   - state: the transport's callbacks fill state_frame() / imu_frame() and publish them; the
//     state callbacks never overlap each other, nor do the IMU ones (they share those frames);
//   - commands: the transport's writer takes next_command() every command_writer_period_us.
// They hand frames over only through DataBuffers, never by sharing mutable data.
//
// Safe start (three layers): (1) next_command() yields nothing before the first valid state of an
// activation; (2) that first state seeds the command buffer with "hold the measured position, all
// gains zero"; (3) write_command() forwards nothing until read_state() has copied a real state, and
// its first command is the measured position with zero gains.
//
// Command safety: write_command() clamps targets to the URDF limits; next_command() turns a joint
// with a non-finite command or a negative gain, and every joint while no valid state has arrived
// for state_timeout_ms, into damping only (last safe target, kp = 0, no velocity or feed-forward).
template<size_t N, typename T>
class DriverCore
{
  static_assert(N > 0, "a robot has at least one motor");
  static_assert(std::is_floating_point<T>::value, "SDK values are float or double");

public:
  using Command = MotorCommand<N, T>;
  using State = MotorState<N, T>;
  using Imu = ImuSample<T>;

  explicit DriverCore(const RobotSpec & spec)
  : spec_(spec), parameters_(spec.parameters), logger_(rclcpp::get_logger(spec.node_name))
  {
    slot_limits_.fill(SlotLimits{-kNoLimit, kNoLimit, kNoLimit, kNoLimit});
    slot_joint_names_.fill("");
    slot_modes_.fill(CommandMode::kPosition);
    default_stiffness_.fill(0.0);
    default_damping_.fill(0.0);
    mapped_slots_.reserve(spec.joint_count);
    for (size_t i = 0; i < spec.joint_count; ++i) {
      const JointSpec & joint = spec.joints[i];
      slot_limits_[joint.slot] = SlotLimits{
        joint.position_min, joint.position_max, joint.velocity_max, joint.effort_max};
      slot_joint_names_[joint.slot] = joint.name;
      slot_modes_[joint.slot] = joint.mode;
      default_stiffness_[joint.slot] = joint.default_stiffness;
      default_damping_[joint.slot] = joint.default_damping;
      mapped_slots_.push_back(joint.slot);
      if (joint.mode == CommandMode::kVelocity) {
        velocity_slots_[velocity_slot_count_++] = joint.slot;
      }
    }
    std::sort(mapped_slots_.begin(), mapped_slots_.end());
    update_command_bounds();
  }

  DriverCore(const DriverCore &) = delete;
  DriverCore & operator=(const DriverCore &) = delete;

  // ---------------------------------------------------------------- configuration (on_init)
  const RobotSpec & spec() const {return spec_;}
  DriverParameters & parameters() {return parameters_;}
  const DriverParameters & parameters() const {return parameters_;}
  const rclcpp::Logger & logger() const {return logger_;}
  void set_logger(const rclcpp::Logger & logger) {logger_ = logger;}
  rclcpp::Clock & throttle_clock() {return throttle_clock_;}
  bool has_imu() const {return spec_.imu_name != nullptr;}
  // SDK slots that drive a URDF joint, ascending; fixed after construction.
  const std::vector<size_t> & mapped_slots() const {return mapped_slots_;}
  // URDF joint name of every slot ("" where the slot drives no joint).
  const std::array<const char *, N> & slot_joint_names() const {return slot_joint_names_;}

  CommandMode mode_of(size_t slot) const {return slot_modes_[slot];}

  // The SDK motor slot of a URDF joint, -1 for none.
  int slot_of(const std::string & joint_name) const
  {
    for (size_t i = 0; i < spec_.joint_count; ++i) {
      if (joint_name == spec_.joints[i].name) {
        return static_cast<int>(spec_.joints[i].slot);
      }
    }
    return -1;
  }

  // ros2_control storage, exported as interfaces: controller thread only.
  JointStorage<N> & joints() {return frames_.joints;}
  ImuData & imu_data() {return imu_data_;}

  // on_activate: re-arm the safe start. After a deactivation the robot may have moved, so nothing
  // from the previous activation may be sent. Called while no transport thread runs.
  void reset_for_activation()
  {
    first_state_received_.store(false);
    command_initialized_.store(false);
    state_copied_.store(false);
    last_state_time_ns_.store(0);
    cmd_writer_last_time_us_.store(0);
    state_frame_counter_.store(0);
    state_frames_valid_ = false;
    safe_cmd_ = Command{};
    holding_ = false;
  }

  // ---------------------------------------------------------------- state thread (transport)
  // Decimation of a single state stream: true when this frame must be parsed. The first frame of
  // an activation always is. A skipped frame still proves that state arrives: it keeps the state
  // fresh for the stale-state check, unless the last parsed frame was rejected.
  bool start_state_frame()
  {
    const bool is_first_state = !first_state_received_.load(std::memory_order_acquire);
    const uint32_t frame_count = state_frame_counter_.fetch_add(1, std::memory_order_relaxed);
    if (is_first_state || (frame_count % parameters_.state_decimation) == 0U) {
      return true;
    }
    if (state_frames_valid_) {
      mark_state_fresh(steady_now_ns());
    }
    return false;
  }

  // The parsing buffer of the state thread.
  State & state_frame() {return motor_state_cache_;}

  // The frame in state_frame() is complete and valid: hand it to read(), and on the first one of
  // an activation seed the command buffer (layer 2) before the writer may send.
  void publish_state(int64_t state_time_ns)
  {
    state_frames_valid_ = true;
    motor_state_buffer_.set_data(motor_state_cache_);
    mark_state_fresh(state_time_ns);
    if (first_state_received_.load(std::memory_order_acquire)) {
      return;
    }
    // Layer 2: the first command is "stay where you are": measured position, all gains zero.
    initial_cmd_cache_ = Command{};
    initial_cmd_cache_.q_target = motor_state_cache_.q;
    motor_command_buffer_.set_data(initial_cmd_cache_);
    first_state_received_.store(true, std::memory_order_release);
    RCLCPP_INFO(
      logger_, "first state received: command initialized to the measured position with zero "
      "gains");
  }

  // The frame being parsed is invalid: count it and return the count. Until a parsed frame is
  // accepted again, skipped (decimated) frames no longer keep the state fresh.
  uint64_t reject_state()
  {
    state_frames_valid_ = false;
    return ++invalid_state_count_;
  }

  // The newest valid state is this old (steady time): multi-stream transports report the age of
  // their oldest stream here instead of calling start_state_frame().
  void mark_state_fresh(int64_t state_time_ns)
  {
    last_state_time_ns_.store(state_time_ns, std::memory_order_release);
  }

  bool first_state_received() const {return first_state_received_.load(std::memory_order_acquire);}

  // The parsing buffer of the IMU callback and its hand-off.
  Imu & imu_frame() {return imu_state_cache_;}
  void publish_imu() {imu_state_buffer_.set_data(imu_state_cache_);}
  uint64_t reject_imu() {return ++invalid_imu_count_;}

  // State-thread latency check; `start` is when the callback began. (Each path has its own
  // check: a throttled log call site must not be shared between threads.)
  void check_state_latency(std::chrono::steady_clock::time_point start)
  {
    uint64_t duration_us = 0;
    if (too_slow(start, MonitorThresholds::STATE_HANDLER_WARN_US, duration_us)) {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "state callback took %" PRIu64 " us (threshold: %" PRIu64 " us)", duration_us,
        MonitorThresholds::STATE_HANDLER_WARN_US);
    }
  }

  // ---------------------------------------------------------------- writer thread (transport)
  // Warns when the send interval deviates from command_writer_period_us (monitor on).
  void check_writer_jitter()
  {
    if (!parameters_.enable_monitor) {
      return;
    }
    const uint64_t now_us = steady_now_us();
    const uint64_t last_us = cmd_writer_last_time_us_.exchange(now_us, std::memory_order_relaxed);
    if (last_us == 0 || now_us < last_us) {
      return;
    }
    const int64_t jitter_us = static_cast<int64_t>(now_us - last_us) -
      static_cast<int64_t>(parameters_.command_writer_period_us);
    if (static_cast<uint64_t>(std::llabs(jitter_us)) >
      MonitorThresholds::CMD_INTERVAL_JITTER_WARN_US)
    {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "command interval jitter: %" PRId64 " us (expected period: %" PRIu64 " us)", jitter_us,
        parameters_.command_writer_period_us);
    }
  }

  // Layer 1 and command safety: the frame to send now, or nullptr while nothing may be sent.
  const Command * next_command()
  {
    // Layer 1: send nothing before the first valid state of this activation.
    if (!first_state_received_.load(std::memory_order_acquire)) {
      return nullptr;
    }
    const Command * cmd = motor_command_buffer_.get_data();
    if (cmd == nullptr) {
      return nullptr;  // unreachable: layer 2 published a command before setting the flag
    }
    // Stale state: the controller is working blind, so every joint holds its last safe target
    // with damping only (kp = 0, no velocity target, no feed-forward).
    const bool stale = state_is_stale();
    if (stale) {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "no valid state for more than %" PRIu64 " ms: holding the last safe command with kp = 0",
        parameters_.state_timeout_ms);
    } else if (holding_) {
      RCLCPP_INFO(logger_, "state is back: forwarding commands again");
    }
    holding_ = stale;

    // Fresh state and a wholly valid command (the normal cycle): forwarded as it is. One
    // branch-free pass finds any non-finite value or negative gain; only then does the per-joint
    // pass below decide joint by joint.
    if (!stale) {
      unsigned invalid = 0U;
      for (size_t i = 0; i < N; ++i) {
        invalid |= static_cast<unsigned>(!std::isfinite(cmd->q_target[i])) |
          static_cast<unsigned>(!std::isfinite(cmd->dq_target[i])) |
          static_cast<unsigned>(!std::isfinite(cmd->kp[i])) |
          static_cast<unsigned>(!std::isfinite(cmd->kd[i])) |
          static_cast<unsigned>(!std::isfinite(cmd->tau_ff[i])) |
          static_cast<unsigned>(cmd->kp[i] < 0) | static_cast<unsigned>(cmd->kd[i] < 0);
      }
      if (invalid == 0U) {
        safe_cmd_ = *cmd;
        return &safe_cmd_;
      }
    }

    bool rejected = false;
    for (size_t i = 0; i < N; ++i) {
      // Non-finite values or negative gains are never forwarded: that joint holds damping only.
      const bool valid =
        all_finite(cmd->q_target[i], cmd->dq_target[i], cmd->kp[i], cmd->kd[i], cmd->tau_ff[i]) &&
        cmd->kp[i] >= 0 && cmd->kd[i] >= 0;
      if (stale || !valid) {
        // Keep the last safe position target and damping of this joint.
        safe_cmd_.dq_target[i] = 0;
        safe_cmd_.kp[i] = 0;
        safe_cmd_.tau_ff[i] = 0;
        rejected = rejected || !valid;
        continue;
      }
      safe_cmd_.q_target[i] = cmd->q_target[i];
      safe_cmd_.dq_target[i] = cmd->dq_target[i];
      safe_cmd_.kp[i] = cmd->kp[i];
      safe_cmd_.kd[i] = cmd->kd[i];
      safe_cmd_.tau_ff[i] = cmd->tau_ff[i];
    }
    if (rejected) {
      ++invalid_command_count_;
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "non-finite command or negative gain: joint(s) held with damping only (%" PRIu64
        " cycles so far)", invalid_command_count_);
    }
    return &safe_cmd_;
  }

  // Writer-thread latency check; `start` is when the cycle began.
  void check_writer_latency(std::chrono::steady_clock::time_point start)
  {
    uint64_t duration_us = 0;
    if (too_slow(start, MonitorThresholds::CMD_WRITER_WARN_US, duration_us)) {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "command writer took %" PRIu64 " us (threshold: %" PRIu64 " us)", duration_us,
        MonitorThresholds::CMD_WRITER_WARN_US);
    }
  }

  // ---------------------------------------------------------------- command mode switches
  // Which command interfaces of a joint active controllers claim: one bit each.
  static constexpr uint8_t kClaimPosition = 1U << 0;
  static constexpr uint8_t kClaimVelocity = 1U << 1;
  static constexpr uint8_t kClaimEffort = 1U << 2;
  static constexpr uint8_t kClaimStiffness = 1U << 3;
  static constexpr uint8_t kClaimDamping = 1U << 4;

  // prepare_command_mode_switch (controller manager, non-real-time): the claims after starting
  // and stopping the given "<joint>/<interface>" names; names of other components are ignored.
  // Applied only if commit_claims() follows.
  template<typename Names>
  void prepare_claims(const Names & start, const Names & stop)
  {
    Claims next = committed_;
    for (const auto & name : stop) {
      update_claim(next, name, false);
    }
    for (const auto & name : start) {
      update_claim(next, name, true);
    }
    next.generation = committed_.generation + 1;
    prepared_ = next;
    claims_prepared_.store(true, std::memory_order_release);
  }

  // perform_command_mode_switch: hand the prepared claims to write(), which applies them at its
  // next cycle (never from this thread: write() may be running).
  void commit_claims()
  {
    if (!claims_prepared_.exchange(false, std::memory_order_acquire)) {
      return;
    }
    committed_ = prepared_;
    claim_buffer_.set_data(committed_);
  }

  // Position-commanded joints without default stiffness: limp under a position-only controller.
  size_t joints_without_default_stiffness() const
  {
    size_t count = 0;
    for (const size_t slot : mapped_slots_) {
      const bool position = slot_modes_[slot] == CommandMode::kPosition;
      count += (position && default_stiffness_[slot] <= 0.0) ? 1U : 0U;
    }
    return count;
  }

  // ---------------------------------------------------------------- controller thread
  // read(): the newest state and IMU sample into the exported storage.
  void read_state()
  {
    // Load the flag before fetching: the state thread sets it only after publishing the first
    // state of this activation, so when it is set the frame fetched below is at least that new.
    const bool state_is_current = first_state_received_.load(std::memory_order_acquire);
    const State * state = motor_state_buffer_.get_data();
    if (state != nullptr) {
      for_each_slot_block<N>(
        [this, state](auto count, size_t begin) {
          copy_state_block<decltype(count)::value>(*state, frames_.joints, begin);
        });
      if (state_is_current) {
        state_copied_.store(true, std::memory_order_relaxed);
      }
    }
    const Imu * imu = imu_state_buffer_.get_data();
    if (imu != nullptr) {
      imu_data_.orientation[0] = static_cast<double>(imu->quat[1]);  // x
      imu_data_.orientation[1] = static_cast<double>(imu->quat[2]);  // y
      imu_data_.orientation[2] = static_cast<double>(imu->quat[3]);  // z
      imu_data_.orientation[3] = static_cast<double>(imu->quat[0]);  // w
      for (size_t i = 0; i < 3; ++i) {
        imu_data_.angular_velocity[i] = static_cast<double>(imu->omega[i]);
        imu_data_.linear_acceleration[i] = static_cast<double>(imu->acc[i]);
      }
    }
  }

  // write(): what the active controllers command, clamped to the URDF limits, to the command
  // writer. Only claimed interfaces count: an unclaimed stiffness / damping is the joint's default
  // gain while its position (or velocity) is claimed, and zero otherwise. Returns true when it
  // rewrote the command storage itself (safe start, mode switch), false otherwise.
  bool write_command()
  {
    // Layer 3: nothing is forwarded before read_state() has copied a state of this activation;
    // stale zeros in the storage must never become a position target.
    if (!state_copied_.load(std::memory_order_relaxed)) {
      return false;
    }
    // A mode switch first, so that the safe start below has the last word on a first cycle.
    bool rewritten = apply_claim_changes();
    if (!command_initialized_.load(std::memory_order_relaxed)) {
      // Target = measured position, zero gains: the robot stays passive until a controller
      // commands it.
      frames_.joints.pos_des = frames_.joints.pos;
      frames_.joints.vel_des.fill(0.0);
      frames_.joints.kp.fill(0.0);
      frames_.joints.kd.fill(0.0);
      frames_.joints.ff.fill(0.0);
      command_initialized_.store(true, std::memory_order_relaxed);
      rewritten = true;
      RCLCPP_INFO(logger_, "command initialized to the measured position with zero gains");
    }
    for_each_slot_block<N>(
      [this](auto count, size_t begin) {
        bound_command_block<decltype(count)::value>(frames_, begin);
      });
    // A velocity-commanded joint has no position target: its measured position (its kp is 0).
    for (size_t k = 0; k < velocity_slot_count_; ++k) {
      const size_t slot = velocity_slots_[k];
      frames_.command.q_target[slot] = static_cast<T>(frames_.joints.pos[slot]);
    }
    motor_command_buffer_.set_data(frames_.command);
    return rewritten;
  }

  // Controller-thread latency checks of read() and write().
  void check_read_latency(std::chrono::steady_clock::time_point start)
  {
    uint64_t duration_us = 0;
    if (too_slow(start, MonitorThresholds::READ_WARN_US, duration_us)) {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "read() took %" PRIu64 " us (threshold: %" PRIu64 " us)", duration_us,
        MonitorThresholds::READ_WARN_US);
    }
  }

  void check_write_latency(std::chrono::steady_clock::time_point start)
  {
    uint64_t duration_us = 0;
    if (too_slow(start, MonitorThresholds::WRITE_WARN_US, duration_us)) {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "write() took %" PRIu64 " us (threshold: %" PRIu64 " us)", duration_us,
        MonitorThresholds::WRITE_WARN_US);
    }
  }

private:
  // Command limits of one SDK slot (URDF <limit>); infinite where there is none. A NaN target
  // passes the clamp unchanged and is caught by next_command().
  struct SlotLimits
  {
    double position_min;
    double position_max;
    double velocity;  // |velocity target| bound
    double effort;    // |feed-forward effort| bound
  };

  // Monitor on and the path took longer than `threshold_us` (then `duration_us` is set).
  bool too_slow(
    std::chrono::steady_clock::time_point start, uint64_t threshold_us,
    uint64_t & duration_us) const
  {
    if (!parameters_.enable_monitor) {
      return false;
    }
    duration_us = elapsed_us(start);
    return duration_us > threshold_us;
  }

  struct Claims
  {
    std::array<uint8_t, N> bits{};
    uint64_t generation{0};
  };

  // "<joint>/<interface>": the claim bit it sets or clears (joint names may contain '/').
  template<typename Name>
  void update_claim(Claims & claims, const Name & full_name, bool claimed) const
  {
    const std::string name(full_name);
    const auto separator = name.rfind('/');
    if (separator == std::string::npos) {
      return;
    }
    const int slot = slot_of(name.substr(0, separator));
    if (slot < 0) {
      return;  // another component's interface
    }
    const std::string interface = name.substr(separator + 1);
    const uint8_t bit = interface == "position" ? kClaimPosition :
      interface == "velocity" ? kClaimVelocity : interface == "effort" ? kClaimEffort :
      interface == "stiffness" ? kClaimStiffness : interface == "damping" ? kClaimDamping : 0U;
    uint8_t & bits = claims.bits[static_cast<size_t>(slot)];
    bits = static_cast<uint8_t>(claimed ? (bits | bit) : (bits & ~bit));
  }

  // Controller thread: take over claims a mode switch committed. A joint whose claims changed
  // starts from a command that cannot jump or carry another controller's gains: target = measured
  // position, no velocity or effort, the default gains. Returns true when the storage changed.
  bool apply_claim_changes()
  {
    const Claims * next = claim_buffer_.get_data();
    if (next == nullptr || next->generation == applied_generation_) {
      return false;
    }
    applied_generation_ = next->generation;
    bool changed = false;
    for (size_t i = 0; i < N; ++i) {
      if (next->bits[i] == claims_[i]) {
        continue;
      }
      frames_.joints.pos_des[i] = frames_.joints.pos[i];
      frames_.joints.vel_des[i] = 0.0;
      frames_.joints.ff[i] = 0.0;
      frames_.joints.kp[i] = slot_modes_[i] == CommandMode::kPosition ? default_stiffness_[i] : 0.0;
      frames_.joints.kd[i] = default_damping_[i];
      claims_[i] = next->bits[i];
      changed = true;
    }
    if (changed) {
      update_command_bounds();
    }
    return changed;
  }

  static void pin(std::array<T, N> & lower, std::array<T, N> & upper, size_t slot, T min, T max)
  {
    lower[slot] = min;
    upper[slot] = max;
  }

  // The bounds write() applies per slot, from the claims. A claimed interface is bounded by the
  // URDF limits (a claimed gain is not bounded: next_command() rejects a negative one). An
  // unclaimed one is pinned: to the joint's default gain while its position (stiffness) or its
  // position or velocity (damping) is claimed, to zero otherwise. Velocity-commanded joints get
  // kp = 0 and their measured position (write_command()).
  void update_command_bounds()
  {
    constexpr T kUnbounded = std::numeric_limits<T>::infinity();
    for (size_t i = 0; i < N; ++i) {
      const uint8_t claims = claims_[i];
      const SlotLimits & limits = slot_limits_[i];
      const bool position_mode = slot_modes_[i] == CommandMode::kPosition;
      const bool driven = (claims & (kClaimPosition | kClaimVelocity)) != 0U;
      const auto velocity = static_cast<T>((claims & kClaimVelocity) != 0U ? limits.velocity : 0.0);
      const auto effort = static_cast<T>((claims & kClaimEffort) != 0U ? limits.effort : 0.0);
      const auto stiffness = static_cast<T>(
        position_mode && (claims & kClaimPosition) != 0U ? default_stiffness_[i] : 0.0);
      const auto damping = static_cast<T>(driven ? default_damping_[i] : 0.0);
      Command & lower = frames_.lower;
      Command & upper = frames_.upper;
      if (position_mode) {
        pin(
          lower.q_target, upper.q_target, i, static_cast<T>(limits.position_min),
          static_cast<T>(limits.position_max));
      } else {
        pin(lower.q_target, upper.q_target, i, -kUnbounded, kUnbounded);
      }
      pin(lower.dq_target, upper.dq_target, i, -velocity, velocity);
      pin(lower.tau_ff, upper.tau_ff, i, -effort, effort);
      if (position_mode && (claims & kClaimStiffness) != 0U) {
        pin(lower.kp, upper.kp, i, -kUnbounded, kUnbounded);
      } else {
        pin(lower.kp, upper.kp, i, stiffness, stiffness);
      }
      if ((claims & kClaimDamping) != 0U) {
        pin(lower.kd, upper.kd, i, -kUnbounded, kUnbounded);
      } else {
        pin(lower.kd, upper.kd, i, damping, damping);
      }
    }
  }

  bool state_is_stale() const
  {
    const int64_t age_ns = steady_now_ns() - last_state_time_ns_.load(std::memory_order_acquire);
    return age_ns > static_cast<int64_t>(parameters_.state_timeout_ms) * 1000000;
  }

  const RobotSpec & spec_;
  DriverParameters parameters_;
  rclcpp::Logger logger_;
  rclcpp::Clock throttle_clock_{RCL_STEADY_TIME};  // throttles warnings, immune to sim time
  std::array<SlotLimits, N> slot_limits_{};
  std::array<const char *, N> slot_joint_names_{};
  std::array<CommandMode, N> slot_modes_{};
  std::array<double, N> default_stiffness_{};
  std::array<double, N> default_damping_{};
  std::vector<size_t> mapped_slots_;
  std::array<size_t, N> velocity_slots_{};  // slots of velocity-commanded joints, fixed
  size_t velocity_slot_count_{0};

  // Command mode switches: prepared and committed by the controller manager, applied by write().
  Claims prepared_{};
  Claims committed_{};
  std::atomic<bool> claims_prepared_{false};
  DataBuffer<Claims> claim_buffer_;   // commit_claims() -> write()
  std::array<uint8_t, N> claims_{};   // controller thread: the claims write() applies
  uint64_t applied_generation_{0};    // controller thread

  // Thread-safe state/command exchange (producer -> one consumer each)
  // The state and IMU callbacks never overlap (they share the parsing buffers state_frame() and
  // imu_frame()), so their buffers need no producer mutex; commands come from two threads.
  DataBuffer<State, Producers::kOne> motor_state_buffer_;  // state thread -> read()
  DataBuffer<Command> motor_command_buffer_;  // write() / layer 2 -> command writer
  DataBuffer<Imu, Producers::kOne> imu_state_buffer_;      // IMU callback -> read()

  // ros2_control storage, the per-slot command bounds and write()'s frame: controller thread only
  ControllerFrames<N, T> frames_{};
  ImuData imu_data_{};

  // Pre-allocated frames (no heap allocation in hot paths)
  State motor_state_cache_;    // state thread: parsing buffer
  Imu imu_state_cache_;        // IMU callback: parsing buffer
  Command initial_cmd_cache_;  // state thread: layer-2 initial command
  Command safe_cmd_;           // writer: the frame actually sent

  // Safety
  std::atomic<bool> first_state_received_{false};  // layer 1/2: a valid state of this activation
  std::atomic<bool> command_initialized_{false};   // layer 3: write() seeded its command
  std::atomic<bool> state_copied_{false};          // layer 3: read() copied a current state
  std::atomic<int64_t> last_state_time_ns_{0};     // steady time of the newest valid state
  std::atomic<uint32_t> state_frame_counter_{0};   // decimation frame counter
  bool state_frames_valid_{false};                 // state thread: the last parsed frame was valid
  bool holding_{false};                            // writer: holding because the state is stale
  uint64_t invalid_command_count_{0};              // writer: cycles with a rejected joint command
  uint64_t invalid_state_count_{0};                // state thread: rejected frames
  uint64_t invalid_imu_count_{0};                  // IMU callback: rejected samples

  // Monitoring
  std::atomic<uint64_t> cmd_writer_last_time_us_{0};  // jitter detection
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_
