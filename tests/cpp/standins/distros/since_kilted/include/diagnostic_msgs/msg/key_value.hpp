// rhi-gen test stand-in (not the real ROS 2 code): diagnostic_msgs/msg/KeyValue.
// Hand-written in the rosidl C++ shape (Name_<Allocator>, SharedPtr aliases, ==, traits); only
// Kilted and Rolling have it (ros2_control 5.x+ HardwareStatus hooks).
#ifndef DIAGNOSTIC_MSGS__MSG__KEY_VALUE_HPP_
#define DIAGNOSTIC_MSGS__MSG__KEY_VALUE_HPP_

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>


#include "rosidl_runtime_cpp/traits.hpp"

namespace diagnostic_msgs
{
namespace msg
{
template<class ContainerAllocator>
struct KeyValue_
{
  using Type = KeyValue_<ContainerAllocator>;
  KeyValue_() = default;

  std::string key{};
  std::string value{};


  using SharedPtr = std::shared_ptr<Type>;
  using ConstSharedPtr = std::shared_ptr<Type const>;
  using UniquePtr = std::unique_ptr<Type>;

  bool operator==(const KeyValue_ & other) const
  {
    return key == other.key &&
      value == other.value;
  }
  bool operator!=(const KeyValue_ & other) const {return !(*this == other);}
};

using KeyValue = KeyValue_<std::allocator<void>>;
}  // namespace msg
}  // namespace diagnostic_msgs

namespace rosidl_generator_traits
{
template<> struct is_message<diagnostic_msgs::msg::KeyValue>: std::true_type {};
template<> inline const char * data_type<diagnostic_msgs::msg::KeyValue>() {return "diagnostic_msgs::msg::KeyValue";}
template<> inline const char * name<diagnostic_msgs::msg::KeyValue>() {return "diagnostic_msgs/msg/KeyValue";}
}  // namespace rosidl_generator_traits

#endif  // DIAGNOSTIC_MSGS__MSG__KEY_VALUE_HPP_
