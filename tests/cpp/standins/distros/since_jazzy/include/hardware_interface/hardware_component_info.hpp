// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::HardwareComponentInfo of
// ros2_control 4.x+ as ResourceManager::get_components_status() reports it. Not here: the
// read/write statistics members (pal_statistics types).
#ifndef HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_
#define HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_

#include <memory>
#include <string>
#include <vector>

#include "rclcpp/time.hpp"
#include "rclcpp_lifecycle/state.hpp"

namespace hardware_interface
{
struct HardwareComponentInfo
{
  std::string name;
  /// "actuator", "sensor" or "system"
  std::string type;
  std::string group;
  /// The <plugin> lookup name.
  std::string plugin_name;
  bool is_async;  // no initializer upstream
  unsigned int rw_rate;  // no initializer upstream
  rclcpp_lifecycle::State state;
  std::vector<std::string> state_interfaces;
  std::vector<std::string> command_interfaces;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__HARDWARE_COMPONENT_INFO_HPP_
