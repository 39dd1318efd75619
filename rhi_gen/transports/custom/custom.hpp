// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__CUSTOM_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__CUSTOM_HPP_

// Bring your own SDK: the robot's source file derives a small class from CustomTransport and
// writes the SDK calls into its user regions (connect, disconnect, send); everything else is here
// and in the shared core. Threads:
//   - on_activate (controller manager thread): connect(), then the command writer starts;
//   - command writer (an executor thread spinning the driver's node, a wall timer at
//     command_writer_period_us; with command_writer_mode on_write the driver's own writer thread,
//     woken by write()): send(command), never two at once, never before the first valid state;
//   - the SDK's own thread(s): receive_state() / receive_imu() from its callbacks, never two
//     receive_state() (or two receive_imu()) calls at once;
//   - on_deactivate and destruction: the writer stops and is joined, then disconnect().

#include <array>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/system_driver.hpp"
#include "robot_hardware_interface/transport/ros_topics.hpp"

namespace robot_hardware_interface
{

// What a robot's source passes to its custom transport.
struct CustomOptions
{
  const char * source_file;      // "src/<vendor>/<robot>.cpp", for log lines
  const char * unfilled_region;  // the first function region still "not filled in", or nullptr
};

template<size_t N, typename T>
class CustomTransport : public DriverTransport<N, T>
{
public:
  using Command = MotorCommand<N, T>;
  using State = MotorState<N, T>;
  using Imu = ImuSample<T>;
  using Float = T;
  static constexpr size_t kMotors = N;

  explicit CustomTransport(const CustomOptions & options)
  : options_(options)
  {
  }

  const char * name() const final {return "custom";}

  bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node) final
  {
    core_ = &core;
    node_ = node;
    executor_.configure(node);
    return true;
  }

  bool start() final
  {
    if (options_.unfilled_region != nullptr) {
      RCLCPP_ERROR(
        core_->logger(),
          "custom transport: region '%s' of %s is not filled in: refusing to activate "
        "(write the SDK calls there and delete its RHI_CUSTOM_NOT_FILLED_IN line)",
        options_.unfilled_region, options_.source_file);
      return false;
    }
    if (!connect()) {
      RCLCPP_ERROR(
        core_->logger(), "custom transport: connect() (region 'transport_connect' of %s) failed: "
        "refusing to activate", options_.source_file);
      disconnect();
      return false;
    }
    connected_ = true;
    activated_ns_ = steady_now_ns();
    no_state_warned_ = false;
    executor_.start(
      core_->parameters().command_writer_period_us, core_->logger(), core_->on_write_writer(),
      [this]() {write_command();});
    return true;
  }

  void stop() final
  {
    executor_.stop();  // send() is never called again once this returns
    if (connected_) {
      connected_ = false;
      disconnect();
    }
  }

  void shutdown() noexcept final
  {
    try {
      stop();
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_->logger(), "custom transport: stopping failed: %s", e.what());
    }
  }

protected:
  // ------------------------------------------------------------ the regions' side (user code)
  // on_activate, before the command writer starts: open the SDK, register its state callback.
  // May block and allocate. Return false (after logging why) to refuse the activation.
  virtual bool connect() = 0;
  // on_deactivate and destruction, after the writer thread has stopped (also after a failed
  // connect()): no SDK callback may call receive_state() / receive_imu() once it returns.
  virtual void disconnect() = 0;
  // Command writer thread, every command_writer_period_us once a valid state has arrived: send
  // `command` (slots 0..N-1: q_target, dq_target, kp, kd, tau_ff; already safe: limits clamped,
  // non-finite values and stale state turned into damping-only holds). Must not allocate, block
  // or throw.
  virtual void send(const Command & command) = 0;

  // From the SDK's state callback (one thread at a time): `fill(State & state)` writes q, dq and
  // tau of every slot that drives a joint and returns true, or false to drop the frame. Frames
  // with a non-finite value in a driven slot are dropped too. Decimation (state_decimation), the
  // first-state safe start and the stale-state clock are handled here. Allocates nothing itself.
  template<typename Fill>
  void receive_state(Fill && fill)
  {
    const auto start = std::chrono::steady_clock::now();
    if (core_ == nullptr || !core_->start_state_frame()) {
      return;  // not configured, or decimated
    }
    if (!fill(state_scratch_)) {
      reject_state("the state callback dropped it");
      return;
    }
    for (const size_t slot : core_->slots().mapped_slots()) {
      if (!all_finite(state_scratch_.q[slot], state_scratch_.dq[slot], state_scratch_.tau[slot])) {
        reject_state("non-finite value for a driven joint");
        return;
      }
    }
    core_->state_frame() = state_scratch_;
    core_->publish_state(steady_ns(start));
    core_->monitor().check_state_latency(start);
  }

  // From the SDK's IMU callback: `fill(Imu & imu)` writes quat (w, x, y, z), omega and acc and
  // returns true, or false to drop the sample; non-finite samples are dropped.
  template<typename Fill>
  void receive_imu(Fill && fill)
  {
    if (core_ == nullptr || !core_->has_imu()) {
      return;
    }
    if (!fill(imu_scratch_) ||
      !all_finite(imu_scratch_.quat[0], imu_scratch_.quat[1], imu_scratch_.quat[2],
        imu_scratch_.quat[3]) ||
      !all_finite(imu_scratch_.omega[0], imu_scratch_.omega[1], imu_scratch_.omega[2]) ||
      !all_finite(imu_scratch_.acc[0], imu_scratch_.acc[1], imu_scratch_.acc[2]))
    {
      const uint64_t dropped = core_->reject_imu();
      RCLCPP_WARN_THROTTLE(
        core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "custom transport: dropped IMU sample (%" PRIu64 " dropped so far)", dropped);
      return;
    }
    core_->imu_frame() = imu_scratch_;
    core_->publish_imu();
  }

  // The <hardware> parameter network_interface, the driver's logger and node, and the joints:
  // for connect().
  const std::string & network_interface() const {return core_->parameters().network_interface;}
  const rclcpp::Logger & logger() const {return core_->logger();}
  const rclcpp::Node::SharedPtr & node() const {return node_;}
  // Slots that drive a URDF joint (ascending) and the joint name of every slot ("" for none).
  const std::vector<size_t> & mapped_slots() const {return core_->slots().mapped_slots();}
  const std::array<const char *, N> & slot_joint_names() const
  {
    return core_->slots().slot_joint_names();
  }

private:
  void reject_state(const char * reason)
  {
    const uint64_t dropped = core_->reject_state();
    RCLCPP_WARN_THROTTLE(
      core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "custom transport: dropped state frame: %s (%" PRIu64 " dropped so far)", reason, dropped);
  }

  // Executor thread (wall timer).
  void write_command()
  {
    const auto start = std::chrono::steady_clock::now();
    core_->monitor().check_writer_jitter();
    const Command * cmd = core_->next_command();
    if (cmd == nullptr) {
      warn_without_state();
      return;
    }
    send(*cmd);
    core_->monitor().check_writer_latency(start);
  }

  // Nothing is sent before the first valid state: say so once if none has come in time.
  void warn_without_state()
  {
    const int64_t waited_ns = steady_now_ns() - activated_ns_;
    if (no_state_warned_ ||
      waited_ns <= static_cast<int64_t>(core_->parameters().state_timeout_ms) * 1000000)
    {
      return;
    }
    no_state_warned_ = true;
    RCLCPP_WARN(
      core_->logger(), "custom transport: no valid state %" PRIu64 " ms after activation, so "
      "nothing is sent: does the SDK callback that connect() registers call receive_state()?",
      core_->parameters().state_timeout_ms);
  }

  const CustomOptions options_;
  DriverCore<N, T> * core_{nullptr};
  rclcpp::Node::SharedPtr node_;
  TopicExecutor executor_;
  bool connected_{false};      // controller manager thread
  int64_t activated_ns_{0};    // set before the writer starts
  bool no_state_warned_{false};  // writer thread
  State state_scratch_{};      // SDK state thread: the frame being filled
  Imu imu_scratch_{};          // SDK IMU thread
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__CUSTOM_HPP_
