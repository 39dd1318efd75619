// expect: could not convert|no matching function|cannot convert
// QoS(const QoSInitialization &) is explicit: wrap KeepLast in rclcpp::QoS(...).
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto pub = node.create_publisher<std_msgs::msg::Header>("t", rclcpp::KeepLast(1));
#else
  auto pub = node.create_publisher<std_msgs::msg::Header>("t", rclcpp::QoS(rclcpp::KeepLast(1)));
#endif
  (void)pub;
}
