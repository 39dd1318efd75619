// expect: ignoring return value|unused-result
// distros: jazzy kilted rolling
// set_value() is [[nodiscard]] on 4.x+: it returns false when another thread holds the lock.
#include <hardware_interface/handle.hpp>

bool f(hardware_interface::CommandInterface & c)
{
#ifdef RHI_EXPECT_FAIL
  c.set_value(1.0);
  return true;
#else
  return c.set_value(1.0);
#endif
}
