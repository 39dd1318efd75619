// expect: unsupported subscription callback signature
// A non-const reference parameter is not a signature rclcpp accepts.
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto sub = node.create_subscription<sensor_msgs::msg::Imu>(
    "imu", 1, [](sensor_msgs::msg::Imu & msg) {(void)msg;});
#else
  auto sub = node.create_subscription<sensor_msgs::msg::Imu>(
    "imu", 1, [](const sensor_msgs::msg::Imu & msg) {(void)msg;});
#endif
  (void)sub;
}
