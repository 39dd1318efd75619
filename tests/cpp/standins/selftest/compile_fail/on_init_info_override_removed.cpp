// expect: marked 'override', but does not override
// distros: rolling
// 6.x removed on_init(const HardwareInfo &): override on_init(const HardwareComponentInterfaceParams &).
#include <hardware_interface/system_interface.hpp>

class Hw : public hardware_interface::SystemInterface
{
public:
#ifdef RHI_EXPECT_FAIL
  hardware_interface::CallbackReturn on_init(const hardware_interface::HardwareInfo & info) override
  {
    (void)info;
    return hardware_interface::CallbackReturn::SUCCESS;
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
