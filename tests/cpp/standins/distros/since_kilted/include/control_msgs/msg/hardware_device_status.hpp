// rhi-gen test stand-in (not the real ROS 2 code): control_msgs/msg/HardwareDeviceStatus.
// Subset: canopen_states, ethercat_states and vda5050_states are not here.
// Hand-written in the rosidl C++ shape (Name_<Allocator>, SharedPtr aliases, ==, traits); only
// Kilted and Rolling have it (ros2_control 5.x+ HardwareStatus hooks).
#ifndef CONTROL_MSGS__MSG__HARDWARE_DEVICE_STATUS_HPP_
#define CONTROL_MSGS__MSG__HARDWARE_DEVICE_STATUS_HPP_

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "std_msgs/msg/header.hpp"
#include "control_msgs/msg/generic_hardware_state.hpp"
#include "rosidl_runtime_cpp/traits.hpp"

namespace control_msgs
{
namespace msg
{
template<class ContainerAllocator>
struct HardwareDeviceStatus_
{
  using Type = HardwareDeviceStatus_<ContainerAllocator>;
  HardwareDeviceStatus_() = default;

  std_msgs::msg::Header header{};
  std::string device_id{};
  std::vector<control_msgs::msg::GenericHardwareState> hardware_status{};


  using SharedPtr = std::shared_ptr<Type>;
  using ConstSharedPtr = std::shared_ptr<Type const>;
  using UniquePtr = std::unique_ptr<Type>;

  bool operator==(const HardwareDeviceStatus_ & other) const
  {
    return header == other.header &&
      device_id == other.device_id &&
      hardware_status == other.hardware_status;
  }
  bool operator!=(const HardwareDeviceStatus_ & other) const {return !(*this == other);}
};

using HardwareDeviceStatus = HardwareDeviceStatus_<std::allocator<void>>;
}  // namespace msg
}  // namespace control_msgs

namespace rosidl_generator_traits
{
template<> struct is_message<control_msgs::msg::HardwareDeviceStatus>: std::true_type {};
template<> inline const char * data_type<control_msgs::msg::HardwareDeviceStatus>() {return "control_msgs::msg::HardwareDeviceStatus";}
template<> inline const char * name<control_msgs::msg::HardwareDeviceStatus>() {return "control_msgs/msg/HardwareDeviceStatus";}
}  // namespace rosidl_generator_traits

#endif  // CONTROL_MSGS__MSG__HARDWARE_DEVICE_STATUS_HPP_
