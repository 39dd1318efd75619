// expect: is deprecated: Replaced by CallbackReturn init
// distros: jazzy kilted
// init(info, logger, clock) is deprecated on 4.x/5.x (and gone on 6.x): the framework calls init(params).
#include <memory>
#include <hardware_interface/system_interface.hpp>

void f(hardware_interface::SystemInterface & hw, const hardware_interface::HardwareInfo & info)
{
  auto clock = std::make_shared<rclcpp::Clock>(RCL_ROS_TIME);
#ifdef RHI_EXPECT_FAIL
  hw.init(info, rclcpp::get_logger("hw"), clock);
#else
  hardware_interface::HardwareComponentParams params;
  params.hardware_info = info;
  params.clock = clock;
  hw.init(params);
#endif
}
