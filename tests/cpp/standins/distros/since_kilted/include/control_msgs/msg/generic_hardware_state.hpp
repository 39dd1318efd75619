// rhi-gen test stand-in (not the real ROS 2 code): control_msgs/msg/GenericHardwareState.
// Hand-written in the rosidl C++ shape (Name_<Allocator>, SharedPtr aliases, ==, traits); only
// Kilted and Rolling have it (ros2_control 5.x+ HardwareStatus hooks).
#ifndef CONTROL_MSGS__MSG__GENERIC_HARDWARE_STATE_HPP_
#define CONTROL_MSGS__MSG__GENERIC_HARDWARE_STATE_HPP_

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "diagnostic_msgs/msg/key_value.hpp"
#include "rosidl_runtime_cpp/traits.hpp"

namespace control_msgs
{
namespace msg
{
template<class ContainerAllocator>
struct GenericHardwareState_
{
  using Type = GenericHardwareState_<ContainerAllocator>;
  GenericHardwareState_() = default;

  uint8_t health_status{};
  std::vector<uint8_t> error_domain{};
  uint8_t operational_mode{};
  uint8_t power_state{};
  uint8_t connectivity_status{};
  std::string manufacturer{};
  std::string model{};
  std::string firmware_version{};
  std::vector<diagnostic_msgs::msg::KeyValue> state_details{};
  static constexpr uint8_t HEALTH_UNKNOWN = 0;
  static constexpr uint8_t HEALTH_OK = 1;
  static constexpr uint8_t HEALTH_DEGRADED = 2;
  static constexpr uint8_t HEALTH_WARNING = 3;
  static constexpr uint8_t HEALTH_ERROR = 4;
  static constexpr uint8_t HEALTH_FATAL = 5;
  static constexpr uint8_t ERROR_NONE = 0;
  static constexpr uint8_t ERROR_UNKNOWN = 1;
  static constexpr uint8_t ERROR_HW = 2;
  static constexpr uint8_t ERROR_SW = 3;
  static constexpr uint8_t ERROR_OVER_TRAVEL = 4;
  static constexpr uint8_t EMERGENCY_STOP_HW = 5;
  static constexpr uint8_t EMERGENCY_STOP_SW = 6;
  static constexpr uint8_t PROTECTIVE_STOP_HW = 7;
  static constexpr uint8_t PROTECTIVE_STOP_SW = 8;
  static constexpr uint8_t SAFETY_STOP = 9;
  static constexpr uint8_t CALIBRATION_REQUIRED = 10;
  static constexpr uint8_t MODE_UNKNOWN = 0;
  static constexpr uint8_t MODE_MANUAL = 1;
  static constexpr uint8_t MODE_AUTO = 2;
  static constexpr uint8_t MODE_SAFE = 3;
  static constexpr uint8_t MODE_MAINTENANCE = 4;
  static constexpr uint8_t MODE_JOG_MANUAL = 5;
  static constexpr uint8_t MODE_ADMITTANCE = 6;
  static constexpr uint8_t MODE_MONITORED_STOP = 7;
  static constexpr uint8_t MODE_HOLD_TO_RUN = 8;
  static constexpr uint8_t MODE_CARTESIAN_TWIST = 9;
  static constexpr uint8_t MODE_CARTESIAN_POSE = 10;
  static constexpr uint8_t MODE_TRAJECTORY_FORWARDING = 11;
  static constexpr uint8_t MODE_TRAJECTORY_STREAMING = 12;
  static constexpr uint8_t POWER_UNKNOWN = 0;
  static constexpr uint8_t POWER_OFF = 1;
  static constexpr uint8_t POWER_STANDBY = 2;
  static constexpr uint8_t POWER_ON = 3;
  static constexpr uint8_t POWER_SLEEP = 4;
  static constexpr uint8_t POWER_ERROR = 5;
  static constexpr uint8_t POWER_LEVEL_LOW = 6;
  static constexpr uint8_t POWER_LEVEL_CRITICAL = 7;
  static constexpr uint8_t POWER_CHARGING = 8;
  static constexpr uint8_t POWER_CHARGING_ERROR = 9;
  static constexpr uint8_t CONNECT_UNKNOWN = 0;
  static constexpr uint8_t CONNECT_UP = 1;
  static constexpr uint8_t CONNECT_DOWN = 2;
  static constexpr uint8_t CONNECT_FAILURE = 3;
  static constexpr uint8_t CONNECTION_SLOW = 4;

  using SharedPtr = std::shared_ptr<Type>;
  using ConstSharedPtr = std::shared_ptr<Type const>;
  using UniquePtr = std::unique_ptr<Type>;

  bool operator==(const GenericHardwareState_ & other) const
  {
    return health_status == other.health_status &&
      error_domain == other.error_domain &&
      operational_mode == other.operational_mode &&
      power_state == other.power_state &&
      connectivity_status == other.connectivity_status &&
      manufacturer == other.manufacturer &&
      model == other.model &&
      firmware_version == other.firmware_version &&
      state_details == other.state_details;
  }
  bool operator!=(const GenericHardwareState_ & other) const {return !(*this == other);}
};

using GenericHardwareState = GenericHardwareState_<std::allocator<void>>;
}  // namespace msg
}  // namespace control_msgs

namespace rosidl_generator_traits
{
template<> struct is_message<control_msgs::msg::GenericHardwareState>: std::true_type {};
template<> inline const char * data_type<control_msgs::msg::GenericHardwareState>() {return "control_msgs::msg::GenericHardwareState";}
template<> inline const char * name<control_msgs::msg::GenericHardwareState>() {return "control_msgs/msg/GenericHardwareState";}
}  // namespace rosidl_generator_traits

#endif  // CONTROL_MSGS__MSG__GENERIC_HARDWARE_STATE_HPP_
