// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_DIAGNOSTICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_DIAGNOSTICS_HPP_

#include <pthread.h>

#include <chrono>
#include <cinttypes>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <diagnostic_msgs/msg/diagnostic_array.hpp>
#include <diagnostic_msgs/msg/diagnostic_status.hpp>
#include <diagnostic_msgs/msg/key_value.hpp>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/common/robot_spec.hpp"

namespace robot_hardware_interface
{

// The thresholds the levels come from (the driver's parameters).
struct DiagnosticsLimits
{
  uint64_t state_timeout_ms;
  uint64_t fault_timeout_ms;
  uint64_t first_state_timeout_ms;
  double temperature_warn_c;
  double temperature_error_c;
  uint64_t error_fault_mask;  // motor error code bits that fault (ERROR), others WARN
};

// The statuses of /diagnostics, as text (static members: no free function a vendor namespace
// robot_hardware_interface::<vendor> could clash with). The /diagnostics thread only: it allocates.
class DriverDiagnostics
{
public:
  using Status = diagnostic_msgs::msg::DiagnosticStatus;

  // "<hardware>: link": OK while the state is fresh, WARN while the driver holds a stale one (or
  // an inactive robot is silent), ERROR once it is dead (fault_timeout_ms, active only); the rate
  // of valid state messages since `previous`.
  static void describe_link(
    Status & status, const HealthFacts & facts, const HealthFacts & previous,
    const DiagnosticsLimits & limits)
  {
    const double age_ms = facts.age_ms();
    const std::string silence = "no valid state for " + number(age_ms, "%.0f") + " ms";
    const bool awaiting = facts.active && facts.awaiting_first_state;
    const bool dead = facts.link_dead(limits.fault_timeout_ms, limits.first_state_timeout_ms);
    if (facts.no_state()) {
      set(status, Status::WARN, "no state from the robot yet");
    } else if (awaiting && dead) {
      set(
        status, Status::ERROR, "the robot never answered: no valid state in " +
        number(age_ms, "%.0f") + " ms since activation (first_state_timeout_ms " +
        std::to_string(limits.first_state_timeout_ms) + ")");
    } else if (dead) {
      set(
        status, Status::ERROR, "link lost: " + silence + " (fault_timeout_ms " +
        std::to_string(limits.fault_timeout_ms) + ")");
    } else if (awaiting) {
      set(
        status, Status::WARN, "waiting for the robot's first state: " + number(age_ms, "%.0f") +
        " ms since activation, nothing sent yet");
    } else if (facts.stale(limits.state_timeout_ms)) {
      set(
        status, Status::WARN, std::string(
          facts.active ? "state stale: joints held damping-only, " :
          "robot silent (component inactive), ") + silence);
    } else {
      set(status, Status::OK, facts.active ? "state fresh" : "state fresh (inactive)");
    }
    add(status, "state age [ms]", number(age_ms));
    const double rate = facts.message_rate_since(previous);
    add(status, "valid state messages [1/s]", rate >= 0.0 ? number(rate, "%.0f") : "n/a");
    add(status, "valid state messages", std::to_string(facts.valid_messages));
    add(status, "invalid state frames", std::to_string(facts.invalid_states));
    add(status, "stale holds", std::to_string(facts.stale_holds));
    add(status, "active", facts.active ? "true" : "false");
  }

  // "<hardware>: safety": ERROR while the driver holds every joint for good (e-stop, error), WARN
  // when commands were rejected or sends came late since `previous`, OK otherwise.
  static void describe_safety(
    Status & status, const HealthFacts & facts, const HealthFacts & previous)
  {
    if (facts.estop) {
      set(status, Status::ERROR, "e-stop: every joint held damping-only until re-activation");
    } else if (facts.error_hold) {
      set(status, Status::ERROR, "in error: every joint held damping-only until re-activation");
    } else if (facts.rejected_commands > previous.rejected_commands) {
      set(
        status, Status::WARN,
        std::to_string(facts.rejected_commands - previous.rejected_commands) +
        " command cycle(s) held a joint: non-finite command or negative gain");
    } else if (facts.writer_overruns > previous.writer_overruns) {
      set(
        status, Status::WARN,
        std::to_string(facts.writer_overruns - previous.writer_overruns) + " late command send(s)");
    } else {
      set(status, Status::OK, "commands forwarded");
    }
    add(status, "e-stop", facts.estop ? "pressed" : "released");
    add(status, "error hold", facts.error_hold ? "true" : "false");
    add(status, "rejected command cycles", std::to_string(facts.rejected_commands));
    add(status, "writer overruns", std::to_string(facts.writer_overruns));
  }

  // "<hardware>: left leg motors": one entry per joint of motor group `group` of `robot` and
  // field the state carries; ERROR when the robot reports a motor offline, a motor is at or above
  // temperature_error_c or reports an error code with a bit of error_fault_mask, WARN with another
  // error code or at or above temperature_warn_c. `fields`: MotorHealthField bits.
  template<typename Frame>
  static void describe_motors(
    Status & status, const Frame & frame, const RobotSpec & robot, size_t group, uint8_t fields,
    const DiagnosticsLimits & limits)
  {
    const char * hottest = nullptr;
    double hottest_c = 0.0;
    std::string in_error;
    std::string faulted;
    std::string offline;
    for (size_t j = 0; j < robot.joint_count; ++j) {
      const JointSpec & joint = robot.joints[j];
      if (joint.motor_group != group) {
        continue;
      }
      const size_t slot = joint.slot;
      const std::string name(joint.name);
      if ((fields & kMotorTemperature) != 0U) {
        add(status, name + " temperature [C]", number(frame.temperature[slot]));
        if (hottest == nullptr || frame.temperature[slot] > hottest_c) {
          hottest = joint.name;
          hottest_c = frame.temperature[slot];
        }
      }
      if ((fields & kMotorVoltage) != 0U) {
        add(status, name + " voltage [V]", number(frame.voltage[slot], "%.2f"));
      }
      if ((fields & kMotorErrorCode) != 0U) {
        const uint64_t bits = motor_error_bits(frame.error_code[slot]);
        const std::string code = hex(bits);
        add(status, name + " error code", code);
        std::string & list = (bits & limits.error_fault_mask) != 0U ? faulted : in_error;
        if (bits != 0U) {
          list += (list.empty() ? "" : ", ") + name + " (" + code + ")";
        }
      }
      if ((fields & kMotorOffline) != 0U) {
        add(status, name + " offline", frame.offline[slot] ? "true" : "false");
        if (frame.offline[slot]) {
          offline += (offline.empty() ? "" : ", ") + name;
        }
      }
    }
    const std::string hot =
      hottest == nullptr ? std::string() : std::string(hottest) + " at " + number(hottest_c) + " C";
    if (!offline.empty()) {
      set(status, Status::ERROR, "motor offline: " + offline);
    } else if (hottest != nullptr && hottest_c >= limits.temperature_error_c) {
      set(
        status, Status::ERROR, "motor too hot: " + hot + " (motor_temperature_error_c " +
        number(limits.temperature_error_c, "%.0f") + ")");
    } else if (!faulted.empty()) {
      set(
        status, Status::ERROR, "motor error: " + faulted + " (motor_error_fault_mask " +
        hex(limits.error_fault_mask) + ")");
    } else if (!in_error.empty()) {
      set(status, Status::WARN, "motor error code: " + in_error);
    } else if (hottest != nullptr && hottest_c >= limits.temperature_warn_c) {
      set(
        status, Status::WARN, "motor hot: " + hot + " (motor_temperature_warn_c " +
        number(limits.temperature_warn_c, "%.0f") + ")");
    } else {
      set(status, Status::OK, hot.empty() ? "no motor error" : "hottest: " + hot);
    }
  }

  static void set(Status & status, uint8_t level, const std::string & message)
  {
    status.level = level;
    status.message = message;
  }

private:
  static void add(Status & status, const std::string & key, const std::string & value)
  {
    diagnostic_msgs::msg::KeyValue pair;
    pair.key = key;
    pair.value = value;
    status.values.push_back(std::move(pair));
  }

  static std::string number(double value, const char * format = "%.1f")
  {
    char text[64];
    std::snprintf(text, sizeof(text), format, value);
    return text;
  }

  static std::string hex(uint64_t bits)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "0x%" PRIx64, bits);
    return text;
  }
};

// A thread that calls `tick` every `period`, and at once when stopped no more. Its own thread, not
// an executor's: the driver's node is spun only by topic transports, and publishing needs none.
class PeriodicThread
{
public:
  static constexpr const char * kThreadName = "rhi_diagnostics";  // at most 15 characters

  PeriodicThread() = default;
  PeriodicThread(const PeriodicThread &) = delete;
  PeriodicThread & operator=(const PeriodicThread &) = delete;
  ~PeriodicThread() {stop();}

  void start(std::chrono::milliseconds period, std::function<void()> tick)
  {
    stop();
    stopping_ = false;
    thread_ = std::thread(
      [this, period, tick = std::move(tick)]() {
        pthread_setname_np(pthread_self(), kThreadName);  // tools (top -H, gdb) see what it is
        std::unique_lock<std::mutex> lock(mutex_);
        while (!stopping_) {
          lock.unlock();
          tick();
          lock.lock();
          wake_.wait_for(lock, period, [this]() {return stopping_;});
        }
      });
  }

  void stop() noexcept
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) {
      thread_.join();
    }
  }

private:
  std::mutex mutex_;  // only this thread and stop(): never the controller or state threads
  std::condition_variable wake_;
  bool stopping_{false};
  std::thread thread_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_DIAGNOSTICS_HPP_
