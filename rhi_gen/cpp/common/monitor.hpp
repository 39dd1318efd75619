// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__MONITOR_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__MONITOR_HPP_

#include <chrono>
#include <cstdint>

namespace robot_hardware_interface
{

// Latency thresholds of the optional performance monitor (parameter enable_monitor). A warning is
// logged, at most once per WARN_THROTTLE_MS per call site, only when a threshold is exceeded:
// normal operation logs nothing.
struct MonitorThresholds
{
  static constexpr uint64_t READ_WARN_US = 100;                 // read()
  static constexpr uint64_t WRITE_WARN_US = 100;                // write()
  static constexpr uint64_t STATE_HANDLER_WARN_US = 200;        // state callback
  static constexpr uint64_t CMD_WRITER_WARN_US = 200;           // one command writer cycle
  static constexpr uint64_t CMD_INTERVAL_JITTER_WARN_US = 500;  // |send interval - period|
  // Default send period. Drivers measure jitter against their configured
  // command_writer_period_us, never against this constant.
  static constexpr uint64_t CMD_INTERVAL_EXPECTED_US = 2000;
  static constexpr int WARN_THROTTLE_MS = 1000;                 // throttle of every warning
};

// Monotonic time stamps for latency, jitter and stale-state checks (never the ROS clock, which
// may be simulated or jump).
inline int64_t steady_now_ns()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The steady time of `t` in nanoseconds, on the scale of steady_now_ns(): a callback that read the
// clock when it started stamps its frame with that reading instead of reading the clock again.
inline int64_t steady_ns(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

inline uint64_t steady_now_us()
{
  return static_cast<uint64_t>(
    std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now().time_since_epoch()).count());
}

// Microseconds elapsed since `start` (steady clock), never negative.
inline uint64_t elapsed_us(std::chrono::steady_clock::time_point start)
{
  const auto elapsed = std::chrono::duration_cast<std::chrono::microseconds>(
    std::chrono::steady_clock::now() - start).count();
  return elapsed > 0 ? static_cast<uint64_t>(elapsed) : 0U;
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__MONITOR_HPP_
