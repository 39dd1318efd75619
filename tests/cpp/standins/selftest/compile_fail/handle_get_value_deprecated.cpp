// expect: get_value\(\) const.* is deprecated
// distros: jazzy
// 4.x deprecates Handle::get_value(): use get_optional().
#include <hardware_interface/handle.hpp>

double f(const hardware_interface::StateInterface & s)
{
#ifdef RHI_EXPECT_FAIL
  return s.get_value();
#else
  return s.get_optional().value_or(0.0);
#endif
}
