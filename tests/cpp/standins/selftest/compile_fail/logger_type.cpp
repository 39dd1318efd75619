// expect: First argument to logging macros must be an rclcpp::Logger
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node::SharedPtr node)
{
#ifdef RHI_EXPECT_FAIL
  RCLCPP_INFO(node, "hello");
#else
  RCLCPP_INFO(node->get_logger(), "hello");
#endif
}
