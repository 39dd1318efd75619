// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_MONITOR_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_MONITOR_HPP_

#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include <rclcpp/clock.hpp>
#include <rclcpp/logger.hpp>
#include <rclcpp/logging.hpp>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/common/hardware_parameters.hpp"
#include "robot_hardware_interface/common/monitor.hpp"

namespace robot_hardware_interface
{

// The driver's logger and the optional performance monitor (parameter enable_monitor): latency
// of read(), write(), the state callback and the command writer, and the writer's send jitter,
// each warned about at most once per WARN_THROTTLE_MS. Each path keeps its own throttle: no
// throttle state is shared between threads.
class DriverMonitor
{
public:
  DriverMonitor(const char * node_name, const DriverParameters & parameters)
  : parameters_(parameters), logger_(rclcpp::get_logger(node_name))
  {
  }

  const rclcpp::Logger & logger() const {return logger_;}
  void set_logger(const rclcpp::Logger & logger) {logger_ = logger;}
  // Throttles warnings; steady time, immune to sim time.
  rclcpp::Clock & throttle_clock() {return throttle_clock_;}

  // on_activate: the first send interval of an activation has no predecessor.
  void reset() {cmd_writer_last_time_us_.store(0);}

  // Latency of one call of a path; `start` is when it began. Each path belongs to one thread.
  void check_read_latency(std::chrono::steady_clock::time_point start) {check(read_, start);}
  void check_write_latency(std::chrono::steady_clock::time_point start) {check(write_, start);}
  void check_state_latency(std::chrono::steady_clock::time_point start) {check(state_, start);}
  void check_writer_latency(std::chrono::steady_clock::time_point start) {check(writer_, start);}

  // Writer thread, once per send: counts an overrun (the send came more than
  // CMD_INTERVAL_JITTER_WARN_US after command_writer_period_us; always, for the health GPIO) and,
  // with the monitor on, warns when the interval deviates from the period either way.
  void check_writer_jitter()
  {
    const uint64_t now_us = steady_now_us();
    const uint64_t last_us = cmd_writer_last_time_us_.exchange(now_us, std::memory_order_relaxed);
    if (last_us == 0 || now_us < last_us) {
      return;
    }
    const int64_t jitter_us = static_cast<int64_t>(now_us - last_us) -
      static_cast<int64_t>(parameters_.command_writer_period_us);
    if (jitter_us > static_cast<int64_t>(MonitorThresholds::CMD_INTERVAL_JITTER_WARN_US)) {
      writer_overruns_.add();
    }
    if (!parameters_.enable_monitor) {
      return;
    }
    if (static_cast<uint64_t>(std::llabs(jitter_us)) >
      MonitorThresholds::CMD_INTERVAL_JITTER_WARN_US)
    {
      RCLCPP_WARN_THROTTLE(
        logger_, throttle_clock_, MonitorThresholds::WARN_THROTTLE_MS,
        "command interval jitter: %" PRId64 " us (expected period: %" PRIu64 " us)", jitter_us,
        parameters_.command_writer_period_us);
    }
  }

  // Any thread: sends later than the period allows since on_init (health GPIO).
  const HealthCounter & writer_overruns() const {return writer_overruns_;}

private:
  // One monitored path: its threshold and its own warning throttle, touched only by the path's
  // thread (so no throttle state is shared between threads).
  struct LatencyPath
  {
    const char * what;
    uint64_t threshold_us;
    int64_t last_warning_ns;
  };

  void check(LatencyPath & path, std::chrono::steady_clock::time_point start)
  {
    if (!parameters_.enable_monitor) {
      return;
    }
    const uint64_t duration_us = elapsed_us(start);
    if (duration_us <= path.threshold_us) {
      return;
    }
    const int64_t now_ns = steady_now_ns();
    if (now_ns - path.last_warning_ns < kThrottleNs) {
      return;
    }
    path.last_warning_ns = now_ns;
    RCLCPP_WARN(
      logger_, "%s took %" PRIu64 " us (threshold: %" PRIu64 " us)", path.what, duration_us,
      path.threshold_us);
  }

  static constexpr int64_t kThrottleNs =
    static_cast<int64_t>(MonitorThresholds::WARN_THROTTLE_MS) * 1000000;
  static constexpr int64_t kNever = std::numeric_limits<int64_t>::min() / 2;

  const DriverParameters & parameters_;
  rclcpp::Logger logger_;
  rclcpp::Clock throttle_clock_{RCL_STEADY_TIME};
  std::atomic<uint64_t> cmd_writer_last_time_us_{0};  // writer: jitter detection
  HealthCounter writer_overruns_;                     // writer: late sends
  LatencyPath read_{"read()", MonitorThresholds::READ_WARN_US, kNever};
  LatencyPath write_{"write()", MonitorThresholds::WRITE_WARN_US, kNever};
  LatencyPath state_{"state callback", MonitorThresholds::STATE_HANDLER_WARN_US, kNever};
  LatencyPath writer_{"command writer", MonitorThresholds::CMD_WRITER_WARN_US, kNever};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_MONITOR_HPP_
