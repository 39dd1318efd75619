// rhi-gen test stand-in (not the real ROS 2 code): what the spin_until_future_complete functions
// return (the same enum on every distro: rclcpp humble, jazzy and rolling).
#ifndef RCLCPP__FUTURE_RETURN_CODE_HPP_
#define RCLCPP__FUTURE_RETURN_CODE_HPP_

#include <ostream>
#include <string>
#include <type_traits>

#include "rclcpp/visibility_control.hpp"

namespace rclcpp
{

enum class FutureReturnCode {SUCCESS, INTERRUPTED, TIMEOUT};

/// "SUCCESS (0)", "INTERRUPTED (1)", "TIMEOUT (2)" ("Unknown enum value (n)" otherwise), as rclcpp.
inline std::string to_string(const FutureReturnCode & future_return_code)
{
  const auto value = static_cast<std::underlying_type_t<FutureReturnCode>>(future_return_code);
  std::string name = "Unknown enum value";
  switch (future_return_code) {
    case FutureReturnCode::SUCCESS: name = "SUCCESS"; break;
    case FutureReturnCode::INTERRUPTED: name = "INTERRUPTED"; break;
    case FutureReturnCode::TIMEOUT: name = "TIMEOUT"; break;
  }
  return name + " (" + std::to_string(value) + ")";
}

inline std::ostream & operator<<(std::ostream & os, const FutureReturnCode & future_return_code)
{
  return os << to_string(future_return_code);
}

}  // namespace rclcpp

#endif  // RCLCPP__FUTURE_RETURN_CODE_HPP_
