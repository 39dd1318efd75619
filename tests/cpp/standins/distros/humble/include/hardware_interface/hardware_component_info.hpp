// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::HardwareComponentInfo of
// Humble (2.x), hardware_interface/include/hardware_interface/hardware_component_info.hpp.
// Only the members common to every Humble release: the plugin-name member (class_type in early
// releases, plugin_name in later ones) and the later additions (group, is_async, rw_rate,
// statistics) are deliberately absent, so a test does not come to depend on them.
#ifndef HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_
#define HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_

#include <string>
#include <vector>

#include "rclcpp_lifecycle/state.hpp"

namespace hardware_interface
{
/// Hardware Component Information
struct HardwareComponentInfo
{
  /// Component name.
  std::string name;

  /// Component "classification": "actuator", "sensor" or "system"
  std::string type;

  /// Component current state.
  rclcpp_lifecycle::State state;

  /// List of provided state interfaces by the component.
  std::vector<std::string> state_interfaces;

  /// List of provided command interfaces by the component.
  std::vector<std::string> command_interfaces;
};

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_
