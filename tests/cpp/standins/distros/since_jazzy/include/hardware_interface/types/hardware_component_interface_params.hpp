// rhi-gen test stand-in (not the real ROS 2 code): what init() passes to
// on_init(const HardwareComponentInterfaceParams &) on ros2_control 4.x+.
#ifndef HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_INTERFACE_PARAMS_HPP_
#define HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_INTERFACE_PARAMS_HPP_

#include <memory>

#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/types/hardware_component_params.hpp"
#include "rclcpp/rclcpp.hpp"

namespace hardware_interface
{
struct HardwareComponentInterfaceParams
{
  HardwareComponentInterfaceParams() = default;
  /// The component's <ros2_control> description.
  hardware_interface::HardwareInfo hardware_info;
  /// The controller manager's executor (do not spin() or cancel() it).
  rclcpp::Executor::WeakPtr executor;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__HARDWARE_COMPONENT_INTERFACE_PARAMS_HPP_
