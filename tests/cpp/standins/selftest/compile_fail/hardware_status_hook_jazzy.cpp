// expect: marked 'override', but does not override|control_msgs
// distros: jazzy
// The HardwareStatus hooks (and control_msgs/msg/hardware_status.hpp) came with 5.x.
#include <hardware_interface/system_interface.hpp>
#ifdef RHI_EXPECT_FAIL
#include <control_msgs/msg/hardware_status.hpp>
#endif

class Hw : public hardware_interface::SystemInterface
{
public:
#ifdef RHI_EXPECT_FAIL
  hardware_interface::CallbackReturn init_hardware_status_message(
    control_msgs::msg::HardwareStatus & msg) override
  {
    (void)msg;
    return hardware_interface::CallbackReturn::SUCCESS;
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
