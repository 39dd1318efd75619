// expect: no matching function for call to .*publish
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <std_msgs/msg/header.hpp>

void f(rclcpp::Publisher<std_msgs::msg::Header> & pub)
{
#ifdef RHI_EXPECT_FAIL
  pub.publish(sensor_msgs::msg::Imu());
#else
  pub.publish(std_msgs::msg::Header());
#endif
}
