// expect: cannot convert 'rclcpp::ServicesQoS' to 'const rmw_qos_profile_t&'
// distros: humble
// Humble's Node::create_client / create_service take an rmw_qos_profile_t (default
// rmw_qos_profile_services_default); the rclcpp::QoS overloads came with rclcpp 21 (Iron).
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto client = node.create_client<lifecycle_msgs::srv::GetState>("get_state", rclcpp::ServicesQoS());
#else
  auto client = node.create_client<lifecycle_msgs::srv::GetState>("get_state", rmw_qos_profile_services_default);
#endif
  (void)client;
}
