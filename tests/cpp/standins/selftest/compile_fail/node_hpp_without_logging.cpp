// expect: 'RCLCPP_INFO' was not declared|RCLCPP_INFO
// rclcpp/node.hpp does not define the logging macros: include rclcpp/logging.hpp.
#include <rclcpp/node.hpp>
#ifndef RHI_EXPECT_FAIL
#include <rclcpp/logging.hpp>
#endif

void f(rclcpp::Node & node)
{
  RCLCPP_INFO(node.get_logger(), "hello");
}
