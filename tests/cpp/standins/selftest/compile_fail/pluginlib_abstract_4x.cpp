// expect: is abstract
// distros: jazzy kilted rolling
// SystemInterface makes write() pure virtual again on 4.x+: a driver without one cannot be exported.
#include <hardware_interface/system_interface.hpp>
#include <pluginlib/class_list_macros.hpp>

namespace demo
{
class Hw : public hardware_interface::SystemInterface
{
public:
  hardware_interface::return_type read(const rclcpp::Time &, const rclcpp::Duration &) override
  {
    return hardware_interface::return_type::OK;
  }
#ifndef RHI_EXPECT_FAIL
  hardware_interface::return_type write(const rclcpp::Time &, const rclcpp::Duration &) override
  {
    return hardware_interface::return_type::OK;
  }
#endif
};
}  // namespace demo

PLUGINLIB_EXPORT_CLASS(demo::Hw, hardware_interface::SystemInterface)
