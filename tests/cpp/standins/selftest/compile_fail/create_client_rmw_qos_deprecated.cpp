// expect: is deprecated: use rclcpp::QoS instead of rmw_qos_profile_t
// distros: jazzy
// Jazzy (rclcpp 28) deprecates the rmw_qos_profile_t overloads of create_client / create_service:
// -Werror makes it an error. The default and rclcpp::QoS forms compile on every distro since Iron.
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
