// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

#include <rclcpp/logging.hpp>

#include "robot_hardware_interface/common/calibration_file.hpp"
#include "robot_hardware_interface/common/command_claims.hpp"
#include "robot_hardware_interface/common/command_guard.hpp"
#include "robot_hardware_interface/common/command_writer.hpp"
#include "robot_hardware_interface/common/data_buffer.hpp"
#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/common/driver_monitor.hpp"
#include "robot_hardware_interface/common/hardware_parameters.hpp"
#include "robot_hardware_interface/common/joint_transmissions.hpp"
#include "robot_hardware_interface/common/motor_types.hpp"
#include "robot_hardware_interface/common/robot_spec.hpp"
#include "robot_hardware_interface/common/safe_start.hpp"
#include "robot_hardware_interface/common/slot_kernels.hpp"
#include "robot_hardware_interface/common/slot_table.hpp"
#include "robot_hardware_interface/common/state_freshness.hpp"
#include "robot_hardware_interface/common/types.hpp"

namespace robot_hardware_interface
{

// The robot-independent part of every driver: the hand-off of frames between its threads and the
// three-layer safe start (safe_start.hpp), built from parts with one job each: the joint table
// (SlotTable), command mode claims and bounds (CommandClaims), the command guard (CommandGuard),
// state freshness and decimation (StateFreshness), monitoring (DriverMonitor) and motors that are
// not joints (JointTransmissions: ros2_control sees joints, frames hold motors). It knows
// nothing of ros2_control's API (SystemDriver adapts it) nor of any SDK (transports feed it).
//
// Threads:
//   - controller: read() / write() through read_state() and write_command();
//   - state: the transport's callbacks fill state_frame() / imu_frame() and publish them; the
//     state callbacks never overlap each other, nor do the IMU ones (they share those frames);
//   - commands: the transport's writer takes next_command() every command_writer_period_us, or
//     (command_writer_mode on_write) the OnWriteCommandWriter's thread, woken by write().
// They hand frames over only through DataBuffers, never by sharing mutable data.
template<size_t N, typename T>
class DriverCore
{
  static_assert(N > 0, "a robot has at least one motor");
  static_assert(std::is_floating_point<T>::value, "SDK values are float or double");

public:
  using Command = MotorCommand<N, T>;
  using State = MotorState<N, T>;
  using Imu = ImuSample<T>;

  // `transmission`: the robot's motors that are not joints, nullptr when every motor is its joint.
  explicit DriverCore(const RobotSpec & spec, const TransmissionSpec * transmission = nullptr)
  : spec_(spec), parameters_(spec.parameters), slots_(spec), monitor_(spec.node_name, parameters_),
    claims_(slots_), guard_(monitor_, parameters_), transmissions_(transmission)
  {
    claims_.update_command_bounds(frames_);
  }

  DriverCore(const DriverCore &) = delete;
  DriverCore & operator=(const DriverCore &) = delete;

  // ---------------------------------------------------------------- configuration (on_init)
  const RobotSpec & spec() const {return spec_;}
  DriverParameters & parameters() {return parameters_;}
  const DriverParameters & parameters() const {return parameters_;}
  const SlotTable<N> & slots() const {return slots_;}
  DriverMonitor & monitor() {return monitor_;}
  const rclcpp::Logger & logger() const {return monitor_.logger();}
  rclcpp::Clock & throttle_clock() {return monitor_.throttle_clock();}
  bool has_imu() const {return spec_.imu_name != nullptr;}
  CommandClaims<N, T> & claims() {return claims_;}
  const JointTransmissions<N> & transmissions() const {return transmissions_;}

  // on_configure: the generated transmissions, then the calibration file at `path` ("" for none)
  // on top. Returns "" or the one line that says why the robot cannot be configured (the
  // generated transmissions are kept then). Not while read() / write() run.
  std::string calibrate(const std::string & path)
  {
    transmissions_.reset();
    if (!transmissions_.error().empty() || path.empty()) {
      return transmissions_.error();
    }
    CalibrationFile file;
    if (!file.read(path)) {
      return file.error();
    }
    for (const CalibrationEntry & entry : file.entries()) {
      const int slot = slots_.slot_of(entry.joint);
      if (slot < 0) {
        return file.describe(
          entry.line, "'" + entry.joint + "' is not a joint of " + spec_.plugin_name,
          "use the joint names of the ros2_control description");
      }
      if (entry.direction != 1.0 && transmissions_.is_coupled(static_cast<size_t>(slot))) {
        return file.describe(
          entry.line, "joint '" + entry.joint + "' is coupled: its direction is its group's matrix",
          "give a coupled joint an offset only");
      }
    }
    for (const CalibrationEntry & entry : file.entries()) {
      transmissions_.calibrate(
        static_cast<size_t>(slots_.slot_of(entry.joint)), entry.direction, entry.offset);
    }
    RCLCPP_INFO(
      logger(), "calibration_file '%s': %zu joint(s) calibrated", path.c_str(),
      file.entries().size());
    return "";
  }

  // ros2_control storage, exported as interfaces: controller thread only.
  JointStorage<N> & joints() {return frames_.joints;}
  ImuData & imu_data() {return imu_data_;}
  DriverHealthData & health() {return health_;}
  MotorHealthFrame<N> & motor_health() {return motor_health_;}
  const MotorHealthFrame<N> & motor_health() const {return motor_health_;}

  // read() of a robot whose state carries motor health: the newest health frame into the exported
  // storage, true when a new one came (only then do its values change).
  bool read_motor_health()
  {
    // The usual cycle: no new frame, one relaxed load (a stale answer only delays by a cycle).
    if (motor_health_published_.load(std::memory_order_relaxed) == motor_health_.sequence) {
      return false;
    }
    const MotorHealthFrame<N> * frame = motor_health_buffer_.get_data();
    if (frame == nullptr || frame->sequence == motor_health_.sequence) {
      return false;
    }
    motor_health_ = *frame;
    return true;
  }

  // on_activate: re-arm the safe start. After a deactivation the robot may have moved, so nothing
  // from the previous activation may be sent. Called while no transport thread runs.
  void reset_for_activation()
  {
    safe_start_.reset();
    freshness_.reset();
    monitor_.reset();
    guard_.reset();
  }

  // Any thread, at steady time `now_ns`: nanoseconds without a valid state since the newest one
  // or, before the first, since the activation (-1 before either).
  int64_t silence_ns(int64_t now_ns) const {return freshness_.silence_ns(now_ns);}

  // read(): after `silence_ns` the link is dead (no valid state for more than fault_timeout_ms,
  // or first_state_timeout_ms while the first state of the activation is awaited).
  bool link_dead(int64_t silence_ns) const
  {
    return HealthFacts::silent_for(
      silence_ns, HealthFacts::dead_after_ms(
        !safe_start_.first_state_received(), parameters_.fault_timeout_ms,
        parameters_.first_state_timeout_ms));
  }

  // on_error: the command writer holds every joint damping-only until the next activation.
  void hold_until_activation() {guard_.latch_hold(CommandGuard<N, T>::HoldReason::kError);}

  // write(): the health GPIO's estop command is pressed. Latches the damping-only hold until the
  // next activation (releasing the e-stop does not release the robot); true the first time.
  bool press_estop()
  {
    if (guard_.latched() == CommandGuard<N, T>::HoldReason::kEstop) {
      return false;
    }
    guard_.latch_hold(CommandGuard<N, T>::HoldReason::kEstop);
    return true;
  }

  // Any thread (/diagnostics), at steady time `now_ns`: the health from atomics only.
  HealthFacts health_facts(int64_t now_ns, bool active) const
  {
    HealthFacts facts;
    facts.active = active;
    facts.now_ns = now_ns;
    facts.silence_ns = freshness_.silence_ns(now_ns);
    facts.valid_messages = freshness_.valid_messages().get();
    facts.invalid_states = freshness_.invalid_states().get();
    facts.stale_holds = guard_.stale_holds().get();
    facts.rejected_commands = guard_.rejected_commands().get();
    facts.writer_overruns = monitor_.writer_overruns().get();
    const auto latched = guard_.latched();
    facts.error_hold = latched == CommandGuard<N, T>::HoldReason::kError;
    facts.estop = latched == CommandGuard<N, T>::HoldReason::kEstop;
    facts.awaiting_first_state = !safe_start_.first_state_received();
    return facts;
  }

  // The /diagnostics thread (its one consumer): the newest motor health frame, nullptr before one.
  const MotorHealthFrame<N> * diagnostics_motor_health()
  {
    return motor_health_diagnostics_buffer_.get_data();
  }

  // read(): the health GPIO's states, `silence_ns` after the newest state (`fault`: read()
  // returns ERROR, the link is dead or a motor too hot).
  void read_health(int64_t silence_ns, bool fault)
  {
    health_.state_age_ms = HealthFacts::age_ms_of(silence_ns);
    health_.invalid_states = freshness_.invalid_states().value();
    health_.stale_holds = guard_.stale_holds().value();
    health_.rejected_commands = guard_.rejected_commands().value();
    health_.writer_overruns = monitor_.writer_overruns().value();
    const auto latched = guard_.latched();
    health_.fault = fault || latched != CommandGuard<N, T>::HoldReason::kNone ? 1.0 : 0.0;
    health_.estop = latched == CommandGuard<N, T>::HoldReason::kEstop ? 1.0 : 0.0;
  }

  // ---------------------------------------------------------------- state thread (transport)
  // Decimation of a single state stream: true when this frame must be parsed.
  bool start_state_frame()
  {
    const bool first = !safe_start_.first_state_received();
    return freshness_.start_frame(first, parameters_.state_decimation);
  }

  // The parsing buffer of the state thread.
  State & state_frame() {return motor_state_cache_;}

  // The frame in state_frame() is complete and valid: hand it to read(), and on the first one of
  // an activation seed the command buffer (layer 2) before the writer may send.
  void publish_state(int64_t state_time_ns)
  {
    motor_state_buffer_.set_data(motor_state_cache_);
    freshness_.accept(state_time_ns);
    if (safe_start_.first_state_received()) {
      return;
    }
    // Layer 2: the first command is "stay where you are": measured position, all gains zero.
    initial_cmd_cache_ = Command{};
    initial_cmd_cache_.q_target = motor_state_cache_.q;
    motor_command_buffer_.set_data(initial_cmd_cache_);
    safe_start_.mark_first_state_received();
    RCLCPP_INFO(
      logger(), "first state received: command initialized to the measured position with zero "
      "gains");
  }

  // Motor health (transports whose state carries it): at steady time `now_ns`, whether a new health
  // frame is due; if so, fill motor_health_frame() for the mapped slots and publish it.
  bool motor_health_due(int64_t now_ns) const
  {
    return motor_health_cache_.sequence == 0 ||
           now_ns - motor_health_time_ns_ >= kMotorHealthPeriodNs;
  }
  MotorHealthFrame<N> & motor_health_frame() {return motor_health_cache_;}
  void publish_motor_health(int64_t now_ns)
  {
    ++motor_health_cache_.sequence;
    motor_health_time_ns_ = now_ns;
    motor_health_buffer_.set_data(motor_health_cache_);
    motor_health_diagnostics_buffer_.set_data(motor_health_cache_);
    motor_health_published_.store(motor_health_cache_.sequence, std::memory_order_relaxed);
  }

  // The frame being parsed is invalid: count it and return the count.
  uint64_t reject_state() {return freshness_.reject();}

  // Multi-stream transports report the age of their oldest stream here instead of calling
  // start_state_frame().
  void mark_state_fresh(int64_t state_time_ns) {freshness_.mark_fresh(state_time_ns);}

  bool first_state_received() const {return safe_start_.first_state_received();}

  // The parsing buffer of the IMU callback and its hand-off.
  Imu & imu_frame() {return imu_state_cache_;}
  void publish_imu() {imu_state_buffer_.set_data(imu_state_cache_);}
  uint64_t reject_imu() {return freshness_.reject_imu();}

  // ---------------------------------------------------------------- writer thread (transport)
  // Layer 1 and the command guard: the frame to send now, or nullptr while nothing may be sent.
  const Command * next_command()
  {
    // Layer 1: send nothing before the first valid state of this activation.
    if (!safe_start_.first_state_received()) {
      return nullptr;
    }
    const Command * cmd = motor_command_buffer_.get_data();
    if (cmd == nullptr) {
      return nullptr;  // unreachable: layer 2 published a command before setting the flag
    }
    return guard_.guard(*cmd, freshness_.stale(parameters_.state_timeout_ms));
  }

  // The writer thread of the on_write mode, nullptr in the timer mode (the transport's own timer
  // sends). Transports start it in start() and stop it in stop().
  OnWriteCommandWriter * on_write_writer()
  {
    return parameters_.command_writer_mode == CommandWriterMode::kOnWrite ? &on_write_writer_ :
           nullptr;
  }

  // Writer thread, after next_command(): whether that frame holds every joint damping-only (stale
  // state, on_error or the e-stop) rather than carrying what the controllers command.
  bool command_is_hold() const {return guard_.holding();}

  // ---------------------------------------------------------------- controller thread
  // read(): the newest state and IMU sample into the exported storage.
  void read_state()
  {
    // Load the flag before fetching: the state thread sets it only after publishing the first
    // state of this activation, so when it is set the frame fetched below is at least that new.
    const bool state_is_current = safe_start_.first_state_received();
    const State * state = motor_state_buffer_.get_data();
    if (state != nullptr) {
      if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(transmissions_.active())) {
        transmit_state(*state);
      } else {
        copy_state_slots(*state, frames_.joints);
      }
      if (state_is_current) {
        safe_start_.mark_state_copied();
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

  // write(): what the active controllers command, bounded by the claims (CommandClaims), to the
  // command writer. Returns true when it rewrote the command storage itself (safe start, mode
  // switch), false otherwise.
  bool write_command()
  {
    // Layer 3: nothing is forwarded before read_state() has copied a state of this activation;
    // stale zeros in the storage must never become a position target.
    if (!safe_start_.state_copied()) {
      return false;
    }
    // A mode switch first (claims SystemDriver::write() took), so that the safe start below has the
    // last word on a first cycle.
    bool rewritten = claims_.apply_committed(frames_);
    if (!safe_start_.command_initialized()) {
      // Target = measured position, zero gains: the robot stays passive until a controller
      // commands it.
      frames_.joints.pos_des = frames_.joints.pos;
      frames_.joints.vel_des.fill(0.0);
      frames_.joints.kp.fill(0.0);
      frames_.joints.kd.fill(0.0);
      frames_.joints.ff.fill(0.0);
      safe_start_.mark_command_initialized();
      rewritten = true;
      RCLCPP_INFO(logger(), "command initialized to the measured position with zero gains");
    }
    // The command is built in the command buffer's back slot itself (no frame to copy there).
    motor_command_buffer_.fill_data(
      [this](Command & command) {
        bound_command_slots(frames_, command);
        // A velocity-commanded joint has no position target: its measured position (its kp is 0).
        for (size_t k = 0; k < slots_.velocity_slot_count(); ++k) {
          const size_t slot = slots_.velocity_slots()[k];
          command.q_target[slot] = static_cast<T>(frames_.joints.pos[slot]);
        }
        // Bounded in joint space above; the motors' command from here.
        if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(transmissions_.active())) {
          transmit_command(command);
        }
      });
    return rewritten;
  }

  // write(), once the command is published: in the on_write mode the writer sends it now.
  void command_written()
  {
    if (parameters_.command_writer_mode == CommandWriterMode::kOnWrite) {
      on_write_writer_.notify();
    }
  }

private:
  // read() and write() of a robot whose motors are not its joints (kept out of line, so that the
  // plain loops of every other robot stay as they were).
  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE void transmit_state(const State & state)
  {
    transmit_state_slots(state, transmissions_.factors(), frames_.joints);
    transmissions_.couple_state(state, frames_.joints);
  }

  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE void transmit_command(Command & command)
  {
    transmit_command_slots(transmissions_.factors(), command);
    transmissions_.couple_command(command);
  }

  const RobotSpec & spec_;
  DriverParameters parameters_;
  SlotTable<N> slots_;
  DriverMonitor monitor_;
  CommandClaims<N, T> claims_;
  CommandGuard<N, T> guard_;
  SafeStart safe_start_;
  StateFreshness freshness_;
  JointTransmissions<N> transmissions_;  // read() / write(); calibrated in on_configure
  OnWriteCommandWriter on_write_writer_;  // command_writer_mode on_write: started by the transport

  // Thread-safe state/command exchange (producer -> one consumer each)
  // The state and IMU callbacks never overlap (they share the parsing buffers state_frame() and
  // imu_frame()), so their buffers need no producer mutex; commands come from two threads.
  DataBuffer<State, Producers::kOne> motor_state_buffer_;  // state thread -> read()
  DataBuffer<Command> motor_command_buffer_;  // write() / layer 2 -> command writer
  DataBuffer<Imu, Producers::kOne> imu_state_buffer_;      // IMU callback -> read()
  DataBuffer<MotorHealthFrame<N>, Producers::kOne> motor_health_buffer_;  // state thread -> read()
  // state thread -> the /diagnostics thread
  DataBuffer<MotorHealthFrame<N>, Producers::kOne> motor_health_diagnostics_buffer_;

  // ros2_control storage and the per-slot command bounds: controller thread only
  ControllerFrames<N, T> frames_{};
  ImuData imu_data_{};
  DriverHealthData health_{};
  MotorHealthFrame<N> motor_health_{};  // exported: controller thread

  // Pre-allocated frames (no heap allocation in hot paths)
  State motor_state_cache_;    // state thread: parsing buffer
  Imu imu_state_cache_;        // IMU callback: parsing buffer
  Command initial_cmd_cache_;  // state thread: layer-2 initial command
  MotorHealthFrame<N> motor_health_cache_{};  // state thread: the health frame being filled
  int64_t motor_health_time_ns_{0};           // state thread: when the last one was published
  std::atomic<uint64_t> motor_health_published_{0};  // sequence of the newest published frame
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_CORE_HPP_
