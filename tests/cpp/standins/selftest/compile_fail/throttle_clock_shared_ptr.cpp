// expect: has no member named 'now'|request for member 'now'
// Humble's RCLCPP_*_THROTTLE takes the clock by reference: pass *node->get_clock().
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  RCLCPP_WARN_THROTTLE(node.get_logger(), node.get_clock(), 1000, "slow");
#else
  RCLCPP_WARN_THROTTLE(node.get_logger(), *node.get_clock(), 1000, "slow");
#endif
}
