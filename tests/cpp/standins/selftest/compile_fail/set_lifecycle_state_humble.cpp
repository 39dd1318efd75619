// expect: has no member named 'set_lifecycle_state'|has no member named 'get_lifecycle_state'
// distros: humble
// Humble's lifecycle accessors are get_state() / set_state(); the *_lifecycle_state names are 4.x+.
#include <hardware_interface/system_interface.hpp>

void f(hardware_interface::SystemInterface & hw, const rclcpp_lifecycle::State & s)
{
#ifdef RHI_EXPECT_FAIL
  hw.set_lifecycle_state(s);
#else
  hw.set_state(s);
#endif
}
