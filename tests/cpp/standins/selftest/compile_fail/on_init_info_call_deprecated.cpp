// expect: on_init\(const hardware_interface::HardwareInfo&\).* is deprecated
// distros: jazzy kilted
// Overriding the deprecated on_init(info) compiles without a warning; calling the base one does not.
#include <hardware_interface/system_interface.hpp>

class Hw : public hardware_interface::SystemInterface
{
public:
#ifdef RHI_EXPECT_FAIL
  hardware_interface::CallbackReturn on_init(const hardware_interface::HardwareInfo & info) override
  {
    return hardware_interface::SystemInterface::on_init(info);
  }
#else
  hardware_interface::CallbackReturn on_init(
    const hardware_interface::HardwareComponentInterfaceParams & params) override
  {
    return hardware_interface::SystemInterface::on_init(params);
  }
#endif
  hardware_interface::return_type read(const rclcpp::Time &, const rclcpp::Duration &) override
  {
    return hardware_interface::return_type::OK;
  }
  hardware_interface::return_type write(const rclcpp::Time &, const rclcpp::Duration &) override
  {
    return hardware_interface::return_type::OK;
  }
};
