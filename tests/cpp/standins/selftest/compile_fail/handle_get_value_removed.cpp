// expect: no matching function for call to .*get_value\(\)
// distros: kilted rolling
// 5.x+ removed Handle::get_value(): use get_optional().
#include <hardware_interface/handle.hpp>

double f(const hardware_interface::StateInterface & s)
{
#ifdef RHI_EXPECT_FAIL
  return s.get_value();
#else
  return s.get_optional().value_or(0.0);
#endif
}
