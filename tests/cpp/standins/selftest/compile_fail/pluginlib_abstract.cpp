// expect: is abstract
// distros: humble
// A driver that forgets to override a pure virtual (here write()) cannot be exported.
#include <vector>
#include <hardware_interface/system_interface.hpp>
#include <pluginlib/class_list_macros.hpp>

namespace demo
{
class Hw : public hardware_interface::SystemInterface
{
public:
  std::vector<hardware_interface::StateInterface> export_state_interfaces() override {return {};}
  std::vector<hardware_interface::CommandInterface> export_command_interfaces() override {return {};}
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
