// rhi-gen test stand-in (not the real ROS 2 code): return values of ros2_control 4.x+ (Jazzy,
// Kilted, Rolling): DEACTIVATE (a component asks to be deactivated) and the cycle status the
// framework's trigger_read()/trigger_write() report.
#ifndef HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_RETURN_VALUES_HPP_
#define HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_RETURN_VALUES_HPP_

#include <chrono>
#include <cstdint>
#include <optional>

namespace hardware_interface
{
enum class return_type : std::uint8_t
{
  OK = 0,
  ERROR = 1,
  DEACTIVATE = 2,
};

/// Result of one triggered read or write: triggered at all, what it returned, how long it took.
struct HardwareComponentCycleStatus
{
  bool successful = true;
  return_type result = return_type::OK;
  std::optional<std::chrono::nanoseconds> execution_time = std::nullopt;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_RETURN_VALUES_HPP_
