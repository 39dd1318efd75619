// expect: no matching function for call to .*ResourceManager|could not convert|cannot convert
// distros: jazzy kilted rolling
// Humble's ResourceManager(urdf, validate_interfaces, activate_all) form is gone on 4.x+.
#include <string>
#include <hardware_interface/resource_manager.hpp>

void f(const std::string & urdf, rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  hardware_interface::ResourceManager rm(urdf, true, false);
#else
  hardware_interface::ResourceManager rm(
    urdf, node.get_node_clock_interface(), node.get_node_logging_interface(), false);
#endif
  (void)rm;
}
