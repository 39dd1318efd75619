// rhi-gen test stand-in (not the real ROS 2 code). Only the type exists; the fake runs every
// callback of a node mutually exclusively (the default group of a real node).
#ifndef RCLCPP__CALLBACK_GROUP_HPP_
#define RCLCPP__CALLBACK_GROUP_HPP_

#include "rclcpp/macros.hpp"

namespace rclcpp
{
enum class CallbackGroupType
{
  MutuallyExclusive,
  Reentrant
};

class CallbackGroup
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(CallbackGroup)
  explicit CallbackGroup(CallbackGroupType group_type)
  : type_(group_type) {}
  CallbackGroupType type() const {return type_;}

private:
  CallbackGroupType type_;
};
}  // namespace rclcpp

#endif  // RCLCPP__CALLBACK_GROUP_HPP_
