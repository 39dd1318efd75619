// rhi-gen test stand-in (not the real ROS 2 code): what the framework passes to
// HardwareComponentInterface::init() on ros2_control 4.x+ (the ResourceManager fills it).
#ifndef HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_PARAMS_HPP_
#define HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_PARAMS_HPP_

#include <memory>
#include <string>

#include "hardware_interface/hardware_info.hpp"
#include "rclcpp/rclcpp.hpp"

namespace hardware_interface
{
struct HardwareComponentParams
{
  HardwareComponentParams() = default;
  /// The component's <ros2_control> description.
  hardware_interface::HardwareInfo hardware_info;
  /// Logger given by the resource manager.
  rclcpp::Logger logger = rclcpp::get_logger("resource_manager");
  /// Clock shared with the controller manager.
  rclcpp::Clock::SharedPtr clock = nullptr;
  /// Namespace of the component's node (the controller manager's).
  std::string node_namespace = "";
  /// The controller manager's executor; init() adds the component's node to it.
  rclcpp::Executor::WeakPtr executor;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_PARAMS_HPP_
