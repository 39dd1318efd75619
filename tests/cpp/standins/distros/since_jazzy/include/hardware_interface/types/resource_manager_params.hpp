// rhi-gen test stand-in (not the real ROS 2 code): ResourceManager construction parameters of
// ros2_control 4.x+ (same members and defaults as upstream).
#ifndef HARDWARE_INTERFACE__TYPES__RESOURCE_MANAGER_PARAMS_HPP_
#define HARDWARE_INTERFACE__TYPES__RESOURCE_MANAGER_PARAMS_HPP_

#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"

namespace hardware_interface
{
struct ResourceManagerParams
{
  ResourceManagerParams() = default;
  std::string robot_description = "";
  rclcpp::Clock::SharedPtr clock = nullptr;
  rclcpp::Logger logger = rclcpp::get_logger("resource_manager");
  std::string node_namespace = "";
  rclcpp::Executor::SharedPtr executor = nullptr;
  bool activate_all = false;
  bool allow_controller_activation_with_inactive_hardware = false;
  bool return_failed_hardware_names_on_return_deactivate_write_cycle_ = true;
  unsigned int update_rate = 100;
  bool handle_exceptions = true;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__RESOURCE_MANAGER_PARAMS_HPP_
