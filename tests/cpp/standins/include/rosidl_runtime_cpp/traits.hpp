// rhi-gen test stand-in (not the real ROS 2 code). rosidl type traits; every stand-in message
// specializes is_message and name(). rclcpp stand-ins require is_message<T> (the real rclcpp
// needs generated type support, so a non-message type never works there either).
#ifndef ROSIDL_RUNTIME_CPP__TRAITS_HPP_
#define ROSIDL_RUNTIME_CPP__TRAITS_HPP_

#include <type_traits>

namespace rosidl_generator_traits
{
template<typename T>
struct is_message : std::false_type {};

template<typename T>
inline const char * data_type();

template<typename T>
inline const char * name();
}  // namespace rosidl_generator_traits

// Declares the traits of one stand-in message type (used by the message stand-ins only).
#define RHI_ROSIDL_MESSAGE_TRAITS(CppType, DataTypeString, NameString) \
  namespace rosidl_generator_traits \
  { \
  template<> struct is_message<CppType>: std::true_type {}; \
  template<> inline const char * data_type<CppType>() {return DataTypeString;} \
  template<> inline const char * name<CppType>() {return NameString;} \
  }

#endif  // ROSIDL_RUNTIME_CPP__TRAITS_HPP_
