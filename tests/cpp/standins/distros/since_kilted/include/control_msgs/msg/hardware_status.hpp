// rhi-gen test stand-in (not the real ROS 2 code): control_msgs/msg/HardwareStatus.
// Hand-written in the rosidl C++ shape (Name_<Allocator>, SharedPtr aliases, ==, traits); only
// Kilted and Rolling have it (ros2_control 5.x+ HardwareStatus hooks).
#ifndef CONTROL_MSGS__MSG__HARDWARE_STATUS_HPP_
#define CONTROL_MSGS__MSG__HARDWARE_STATUS_HPP_

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "std_msgs/msg/header.hpp"
#include "control_msgs/msg/hardware_device_status.hpp"
#include "rosidl_runtime_cpp/traits.hpp"

namespace control_msgs
{
namespace msg
{
template<class ContainerAllocator>
struct HardwareStatus_
{
  using Type = HardwareStatus_<ContainerAllocator>;
  HardwareStatus_() = default;

  std_msgs::msg::Header header{};
  std::string hardware_id{};
  std::vector<control_msgs::msg::HardwareDeviceStatus> hardware_device_states{};


  using SharedPtr = std::shared_ptr<Type>;
  using ConstSharedPtr = std::shared_ptr<Type const>;
  using UniquePtr = std::unique_ptr<Type>;

  bool operator==(const HardwareStatus_ & other) const
  {
    return header == other.header &&
      hardware_id == other.hardware_id &&
      hardware_device_states == other.hardware_device_states;
  }
  bool operator!=(const HardwareStatus_ & other) const {return !(*this == other);}
};

using HardwareStatus = HardwareStatus_<std::allocator<void>>;
}  // namespace msg
}  // namespace control_msgs

namespace rosidl_generator_traits
{
template<> struct is_message<control_msgs::msg::HardwareStatus>: std::true_type {};
template<> inline const char * data_type<control_msgs::msg::HardwareStatus>() {return "control_msgs::msg::HardwareStatus";}
template<> inline const char * name<control_msgs::msg::HardwareStatus>() {return "control_msgs/msg/HardwareStatus";}
}  // namespace rosidl_generator_traits

#endif  // CONTROL_MSGS__MSG__HARDWARE_STATUS_HPP_
