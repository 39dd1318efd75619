// expect: must derive from hardware_interface::SystemInterface
#include <pluginlib/class_list_macros.hpp>
#include <hardware_interface/system_interface.hpp>

namespace demo
{
struct NotAHardware {};
}  // namespace demo

#ifdef RHI_EXPECT_FAIL
PLUGINLIB_EXPORT_CLASS(demo::NotAHardware, hardware_interface::SystemInterface)
#endif
