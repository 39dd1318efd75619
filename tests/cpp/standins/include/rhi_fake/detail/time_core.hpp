// rhi-gen test stand-in (not the real ROS 2 code). Optional fake "now" for rclcpp::Clock.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

#include "rcl/time.h"

namespace rhi_fake {
namespace detail {

struct TimeCore
{
  std::atomic<bool> fake{false};
  std::atomic<std::int64_t> fake_ns{0};
};

inline TimeCore & time_core()
{
  static TimeCore core;
  return core;
}

// Current time in ns for a clock type: the fake time if one is set, else system time
// (ROS / system clocks) or steady time (steady clocks). Never allocates.
inline std::int64_t clock_now_ns(rcl_clock_type_t type)
{
  TimeCore & core = time_core();
  if (core.fake.load(std::memory_order_acquire)) {
    return core.fake_ns.load(std::memory_order_acquire);
  }
  if (type == RCL_STEADY_TIME) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace detail
}  // namespace rhi_fake
