// rhi-gen test stand-in (not the real ROS 2 code): LifecycleNodeInterface as in Humble. The
// CallbackReturn values are those of lifecycle_msgs/msg/Transition TRANSITION_CALLBACK_*.
#ifndef RCLCPP_LIFECYCLE__NODE_INTERFACES__LIFECYCLE_NODE_INTERFACE_HPP_
#define RCLCPP_LIFECYCLE__NODE_INTERFACES__LIFECYCLE_NODE_INTERFACE_HPP_

#include <cstdint>

#include "lifecycle_msgs/msg/transition.hpp"
#include "rclcpp_lifecycle/state.hpp"

namespace rclcpp_lifecycle
{
namespace node_interfaces
{

class LifecycleNodeInterface
{
protected:
  LifecycleNodeInterface() {}

public:
  enum class CallbackReturn : uint8_t
  {
    SUCCESS = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_SUCCESS,
    FAILURE = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_FAILURE,
    ERROR = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_ERROR
  };

  virtual CallbackReturn on_configure(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual CallbackReturn on_cleanup(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual CallbackReturn on_shutdown(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual CallbackReturn on_activate(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual CallbackReturn on_deactivate(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual CallbackReturn on_error(const rclcpp_lifecycle::State & previous_state)
  {
    (void)previous_state;
    return CallbackReturn::SUCCESS;
  }

  virtual ~LifecycleNodeInterface() {}
};

}  // namespace node_interfaces
}  // namespace rclcpp_lifecycle

#endif  // RCLCPP_LIFECYCLE__NODE_INTERFACES__LIFECYCLE_NODE_INTERFACE_HPP_
