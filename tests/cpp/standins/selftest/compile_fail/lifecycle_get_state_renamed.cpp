// expect: no matching function for call to .*get_state\(\)
// distros: jazzy kilted rolling
// 4.x+ renamed the lifecycle getter get_state() to get_lifecycle_state() (get_state reads interfaces).
#include <hardware_interface/system_interface.hpp>

uint8_t f(const hardware_interface::SystemInterface & hw)
{
#ifdef RHI_EXPECT_FAIL
  return hw.get_state().id();
#else
  return hw.get_lifecycle_state().id();
#endif
}
