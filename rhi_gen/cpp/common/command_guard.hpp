// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_GUARD_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_GUARD_HPP_

#include <atomic>
#include <cinttypes>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

#include <rclcpp/logging.hpp>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/common/driver_monitor.hpp"
#include "robot_hardware_interface/common/hardware_parameters.hpp"
#include "robot_hardware_interface/common/motor_types.hpp"

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

// The last word before a command reaches the motors (writer thread only): a joint with a
// non-finite command or a negative gain, and every joint while the state is stale, gets damping
// only (its last safe position target, kp = 0, no velocity target or feed-forward).
template<size_t N, typename T>
class CommandGuard
{
public:
  using Command = MotorCommand<N, T>;

  CommandGuard(DriverMonitor & monitor, const DriverParameters & parameters)
  : monitor_(monitor), parameters_(parameters)
  {
  }

  // on_activate: nothing of the previous activation may be sent.
  void reset()
  {
    safe_cmd_ = Command{};
    holding_ = false;
    latched_.store(HoldReason::kNone, std::memory_order_release);
  }

  // Why every joint is held damping-only until the next activation.
  enum class HoldReason : uint8_t
  {
    kNone,
    kError,  // on_error: the controllers that wrote the last command are no longer running
    kEstop,  // the health GPIO's estop command
  };

  // Any thread: hold every joint damping-only until the next reset(), even once the state is back
  // or the e-stop is released. The first reason stays.
  void latch_hold(HoldReason reason)
  {
    HoldReason none = HoldReason::kNone;
    latched_.compare_exchange_strong(none, reason, std::memory_order_acq_rel);
  }
  HoldReason latched() const {return latched_.load(std::memory_order_acquire);}

  // Writer cycles that held a joint for a non-finite command or a negative gain, and the times the
  // writer started holding because the state went stale (health GPIO).
  const HealthCounter & rejected_commands() const {return rejected_commands_;}
  const HealthCounter & stale_holds() const {return stale_holds_;}
  // Writer thread: whether the last guard() held every joint (stale state, error or e-stop).
  bool holding() const {return holding_;}

  // The frame to send for `cmd`; `stale`: no valid state for state_timeout_ms.
  const Command * guard(const Command & cmd, bool stale)
  {
    const HoldReason latched = latched_.load(std::memory_order_acquire);
    if (latched != HoldReason::kNone) {
      RCLCPP_WARN_THROTTLE(
        monitor_.logger(), monitor_.throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "%s: every joint held with kp = 0 until the component is activated again",
        latched == HoldReason::kEstop ? "e-stop" :
        "the driver is in error (no valid state for fault_timeout_ms, or a failed transition)");
      holding_ = true;
      return hold();
    }
    if (stale) {
      if (!holding_) {
        stale_holds_.add();
      }
      RCLCPP_WARN_THROTTLE(
        monitor_.logger(), monitor_.throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "no valid state for more than %" PRIu64 " ms: holding the last safe command with kp = 0",
        parameters_.state_timeout_ms);
    } else if (holding_) {
      RCLCPP_INFO(monitor_.logger(), "state is back: forwarding commands again");
    }
    holding_ = stale;

    // Fresh state and a wholly valid command (the normal cycle): forwarded as it is. One
    // branch-free pass finds any non-finite value or negative gain; only then does the per-joint
    // pass below decide joint by joint.
    if (!stale) {
      unsigned invalid = 0U;
      for (size_t i = 0; i < N; ++i) {
        invalid |= static_cast<unsigned>(!std::isfinite(cmd.q_target[i])) |
          static_cast<unsigned>(!std::isfinite(cmd.dq_target[i])) |
          static_cast<unsigned>(!std::isfinite(cmd.kp[i])) |
          static_cast<unsigned>(!std::isfinite(cmd.kd[i])) |
          static_cast<unsigned>(!std::isfinite(cmd.tau_ff[i])) |
          static_cast<unsigned>(cmd.kp[i] < 0) | static_cast<unsigned>(cmd.kd[i] < 0);
      }
      if (invalid == 0U) {
        safe_cmd_ = cmd;
        return &safe_cmd_;
      }
    }

    if (stale) {
      return hold();
    }
    bool rejected = false;
    for (size_t i = 0; i < N; ++i) {
      // Non-finite values or negative gains are never forwarded: that joint holds damping only.
      const bool valid =
        all_finite(cmd.q_target[i], cmd.dq_target[i], cmd.kp[i], cmd.kd[i], cmd.tau_ff[i]) &&
        cmd.kp[i] >= 0 && cmd.kd[i] >= 0;
      if (!valid) {
        hold_joint(i);
        rejected = true;
        continue;
      }
      safe_cmd_.q_target[i] = cmd.q_target[i];
      safe_cmd_.dq_target[i] = cmd.dq_target[i];
      safe_cmd_.kp[i] = cmd.kp[i];
      safe_cmd_.kd[i] = cmd.kd[i];
      safe_cmd_.tau_ff[i] = cmd.tau_ff[i];
    }
    if (rejected) {
      const uint64_t cycles = rejected_commands_.add();
      RCLCPP_WARN_THROTTLE(
        monitor_.logger(), monitor_.throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "non-finite command or negative gain: joint(s) held with damping only (%" PRIu64
        " cycles so far)", cycles);
    }
    return &safe_cmd_;
  }

private:
  // Keep the last safe position target and damping of joint `i`.
  void hold_joint(size_t i)
  {
    safe_cmd_.dq_target[i] = 0;
    safe_cmd_.kp[i] = 0;
    safe_cmd_.tau_ff[i] = 0;
  }

  // Every joint damping-only.
  const Command * hold()
  {
    for (size_t i = 0; i < N; ++i) {
      hold_joint(i);
    }
    return &safe_cmd_;
  }

  DriverMonitor & monitor_;
  const DriverParameters & parameters_;
  Command safe_cmd_;                   // the frame actually sent
  bool holding_{false};                // holding because the state is stale (or latched)
  std::atomic<HoldReason> latched_{HoldReason::kNone};  // hold until the next activation
  HealthCounter rejected_commands_;    // writer: cycles with a rejected joint command
  HealthCounter stale_holds_;          // writer: times the state went stale
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_GUARD_HPP_
