// expect: export_state_interfaces\(\).* is deprecated
// distros: jazzy kilted rolling
// export_state_interfaces() is deprecated on 4.x+: the framework calls on_export_state_interfaces().
#include <hardware_interface/system_interface.hpp>

void f(hardware_interface::SystemInterface & hw)
{
#ifdef RHI_EXPECT_FAIL
  auto states = hw.export_state_interfaces();
#else
  auto states = hw.on_export_state_interfaces();
#endif
  (void)states;
}
