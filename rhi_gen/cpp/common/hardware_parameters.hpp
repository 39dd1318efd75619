// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__HARDWARE_PARAMETERS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__HARDWARE_PARAMETERS_HPP_

#include <cinttypes>
#include <cstdint>
#include <string>
#include <string_view>

#include <rclcpp/logger.hpp>
#include <rclcpp/logging.hpp>

#include "robot_hardware_interface/common/robot_spec.hpp"

namespace robot_hardware_interface
{

// The <hardware> parameters of the ros2_control description, after parsing.
struct DriverParameters
{
  std::string network_interface;
  bool enable_monitor;
  uint64_t command_writer_period_us;
  CommandWriterMode command_writer_mode;
  uint32_t state_decimation;
  uint64_t state_timeout_ms;
  uint64_t fault_timeout_ms;  // no state for this long since the newest: read() returns ERROR
  uint64_t first_state_timeout_ms;  // no first state this long after activation: ERROR (>= fault)
  uint64_t diagnostics_period_ms;  // /diagnostics period, 0: none
  uint64_t motor_temperature_warn_c;  // /diagnostics: a motor this hot is WARN, ...
  uint64_t motor_temperature_error_c;  // ... this hot ERROR
  uint64_t motor_error_fault_mask;  // a motor error code with one of these bits faults, 0: never

  explicit DriverParameters(const ParameterDefaults & defaults)
  : network_interface(defaults.network_interface),
    enable_monitor(defaults.enable_monitor),
    command_writer_period_us(defaults.command_writer_period_us),
    command_writer_mode(defaults.command_writer_mode),
    state_decimation(defaults.state_decimation),
    state_timeout_ms(defaults.state_timeout_ms),
    fault_timeout_ms(defaults.fault_timeout_ms),
    first_state_timeout_ms(defaults.first_state_timeout_ms),
    diagnostics_period_ms(defaults.diagnostics_period_ms),
    motor_temperature_warn_c(defaults.motor_temperature_warn_c),
    motor_temperature_error_c(defaults.motor_temperature_error_c),
    motor_error_fault_mask(defaults.motor_error_fault_mask)
  {
  }
};

// Motor error codes are at most 32 bits wide (hg MotorState_.motorstate; AimDK's is 16).
inline constexpr uint64_t kMaxMotorErrorFaultMask = 0xFFFFFFFFU;

// ros2_control hands <param> values over as text. They are parsed by hand: std::stoul throws on
// garbage and silently turns "-1" into a huge number.
inline std::string_view trimmed(std::string_view text)
{
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) {
    return {};
  }
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

inline bool parse_unsigned(std::string_view text, uint64_t & value)
{
  text = trimmed(text);
  if (text.empty() || text.size() > 18) {  // 18 digits always fit in uint64_t
    return false;
  }
  uint64_t result = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') {
      return false;
    }
    result = result * 10U + static_cast<uint64_t>(c - '0');
  }
  value = result;
  return true;
}

inline bool parse_bool(std::string_view text, bool & value)
{
  text = trimmed(text);
  // xacro renders Python booleans as True/False.
  if (text == "true" || text == "True" || text == "TRUE" || text == "1") {
    value = true;
    return true;
  }
  if (text == "false" || text == "False" || text == "FALSE" || text == "0") {
    value = false;
    return true;
  }
  return false;
}

// Reads an optional unsigned parameter in [min, max]; a missing one keeps `value` (the default).
template<typename Parameters>
bool read_unsigned_parameter(
  const rclcpp::Logger & logger, const Parameters & parameters, const char * name,
  uint64_t min, uint64_t max, uint64_t & value)
{
  const auto it = parameters.find(name);
  if (it == parameters.end()) {
    return true;
  }
  uint64_t parsed = 0;
  if (!parse_unsigned(it->second, parsed) || parsed < min || parsed > max) {
    RCLCPP_ERROR(
      logger, "hardware parameter '%s' is '%s': expected an integer from %" PRIu64 " to %" PRIu64,
      name, it->second.c_str(), min, max);
    return false;
  }
  value = parsed;
  return true;
}

template<typename Parameters>
bool read_bool_parameter(
  const rclcpp::Logger & logger, const Parameters & parameters, const char * name, bool & value)
{
  const auto it = parameters.find(name);
  if (it == parameters.end()) {
    return true;
  }
  if (!parse_bool(it->second, value)) {
    RCLCPP_ERROR(
      logger, "hardware parameter '%s' is '%s': expected true or false", name,
      it->second.c_str());
    return false;
  }
  return true;
}

// command_writer_mode: "timer" or "on_write"; a missing one keeps `value` (the default).
template<typename Parameters>
bool read_writer_mode_parameter(
  const rclcpp::Logger & logger, const Parameters & parameters, CommandWriterMode & value)
{
  const auto it = parameters.find("command_writer_mode");
  if (it == parameters.end()) {
    return true;
  }
  const std::string_view text = trimmed(it->second);
  if (text == "timer") {
    value = CommandWriterMode::kTimer;
  } else if (text == "on_write") {
    value = CommandWriterMode::kOnWrite;
  } else {
    RCLCPP_ERROR(
      logger, "hardware parameter 'command_writer_mode' is '%s': expected timer or on_write",
      it->second.c_str());
    return false;
  }
  return true;
}

// Every <hardware> parameter of the driver, over the defaults in `out`, in the ranges rhi-gen
// accepts in the vendor YAML. false (with an error line naming the parameter) on a bad value.
template<typename Parameters>
bool read_driver_parameters(
  const rclcpp::Logger & logger, const Parameters & parameters, DriverParameters & out)
{
  uint64_t decimation = out.state_decimation;
  if (!read_bool_parameter(logger, parameters, "enable_monitor", out.enable_monitor) ||
    !read_unsigned_parameter(
      logger, parameters, "command_writer_period_us", 100, 10000000,
      out.command_writer_period_us) ||
    !read_writer_mode_parameter(logger, parameters, out.command_writer_mode) ||
    !read_unsigned_parameter(logger, parameters, "state_decimation", 1, 10000, decimation) ||
    !read_unsigned_parameter(
      logger, parameters, "state_timeout_ms", 1, 600000, out.state_timeout_ms) ||
    !read_unsigned_parameter(
      logger, parameters, "fault_timeout_ms", 2, 3600000, out.fault_timeout_ms) ||
    !read_unsigned_parameter(
      logger, parameters, "first_state_timeout_ms", 2, 3600000, out.first_state_timeout_ms) ||
    !read_unsigned_parameter(
      logger, parameters, "diagnostics_period_ms", 0, 60000, out.diagnostics_period_ms) ||
    !read_unsigned_parameter(
      logger, parameters, "motor_temperature_warn_c", 1, 200, out.motor_temperature_warn_c) ||
    !read_unsigned_parameter(
      logger, parameters, "motor_temperature_error_c", 1, 200, out.motor_temperature_error_c) ||
    !read_unsigned_parameter(
      logger, parameters, "motor_error_fault_mask", 0, kMaxMotorErrorFaultMask,
      out.motor_error_fault_mask))
  {
    return false;
  }
  if (out.motor_temperature_error_c <= out.motor_temperature_warn_c) {
    RCLCPP_ERROR(
      logger, "hardware parameter 'motor_temperature_error_c' is %" PRIu64 ": expected more than "
      "motor_temperature_warn_c (%" PRIu64 ")", out.motor_temperature_error_c,
      out.motor_temperature_warn_c);
    return false;
  }
  // The driver holds the joints after state_timeout_ms, then faults after fault_timeout_ms.
  if (out.fault_timeout_ms <= out.state_timeout_ms) {
    RCLCPP_ERROR(
      logger, "hardware parameter 'fault_timeout_ms' is %" PRIu64 ": expected more than "
      "state_timeout_ms (%" PRIu64 ")", out.fault_timeout_ms, out.state_timeout_ms);
    return false;
  }
  out.state_decimation = static_cast<uint32_t>(decimation);
  const auto network_interface = parameters.find("network_interface");
  if (network_interface != parameters.end()) {
    out.network_interface = std::string(trimmed(network_interface->second));
  }
  return true;
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__HARDWARE_PARAMETERS_HPP_
