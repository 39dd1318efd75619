// expect: must be a ROS service type
// create_client<T> needs a service type (<pkg>/srv/...), not a message (the real rclcpp fails on the
// missing service type support).
#include <lifecycle_msgs/msg/state.hpp>
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto client = node.create_client<lifecycle_msgs::msg::State>("get_state");
#else
  auto client = node.create_client<lifecycle_msgs::srv::GetState>("get_state");
#endif
  (void)client;
}
