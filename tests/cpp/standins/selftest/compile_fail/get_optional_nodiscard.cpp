// expect: ignoring return value|unused-result
// distros: jazzy kilted rolling
// get_optional() is [[nodiscard]] on 4.x+.
#include <hardware_interface/handle.hpp>

void f(const hardware_interface::StateInterface & s)
{
#ifdef RHI_EXPECT_FAIL
  s.get_optional();
#else
  (void)s.get_optional();
#endif
}
