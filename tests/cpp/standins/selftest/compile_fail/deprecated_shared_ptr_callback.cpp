// expect: is deprecated: use 'void\(std::shared_ptr<const MessageT>\)' instead
// distros: humble
// Humble deprecates void(std::shared_ptr<MessageT>) callbacks: -Werror makes it an error.
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto sub = node.create_subscription<sensor_msgs::msg::Imu>(
    "imu", 1, [](sensor_msgs::msg::Imu::SharedPtr msg) {(void)msg;});
#else
  auto sub = node.create_subscription<sensor_msgs::msg::Imu>(
    "imu", 1, [](sensor_msgs::msg::Imu::ConstSharedPtr msg) {(void)msg;});
#endif
  (void)sub;
}
