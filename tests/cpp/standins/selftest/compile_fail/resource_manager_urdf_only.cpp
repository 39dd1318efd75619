// expect: no matching function for call to .*ResourceManager
// distros: jazzy kilted rolling
// The 4.x+ ResourceManager needs a clock and a logger (Humble's took the URDF alone).
#include <memory>
#include <string>
#include <hardware_interface/resource_manager.hpp>
#include <rclcpp/rclcpp.hpp>

void f(const std::string & urdf)
{
#ifdef RHI_EXPECT_FAIL
  hardware_interface::ResourceManager rm(urdf);
#else
  auto clock = std::make_shared<rclcpp::Clock>(RCL_ROS_TIME);
  hardware_interface::ResourceManager rm(urdf, clock, rclcpp::get_logger("test"));
#endif
  (void)rm;
}
