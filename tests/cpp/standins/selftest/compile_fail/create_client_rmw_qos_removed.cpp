// expect: cannot convert 'const rmw_qos_profile_t' .* to 'const rclcpp::QoS&'
// distros: kilted rolling
// Kilted and later (rclcpp 29+) removed the rmw_qos_profile_t overloads of create_client /
// create_service (deprecated in Jazzy).
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto client = node.create_client<lifecycle_msgs::srv::GetState>("get_state", rmw_qos_profile_services_default);
#else
  auto client = node.create_client<lifecycle_msgs::srv::GetState>("get_state", rclcpp::ServicesQoS());
#endif
  (void)client;
}
