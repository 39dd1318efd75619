// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::SystemInterface of
// ros2_control 4.x+: a HardwareComponentInterface whose write() is pure virtual again (read() is
// pure virtual in the base). Everything else is in hardware_component_interface.hpp.
#ifndef HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_
#define HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_

#include "hardware_interface/hardware_component_interface.hpp"

namespace hardware_interface
{
class SystemInterface : public HardwareComponentInterface
{
public:
  return_type write(const rclcpp::Time & time, const rclcpp::Duration & period) override = 0;
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_
