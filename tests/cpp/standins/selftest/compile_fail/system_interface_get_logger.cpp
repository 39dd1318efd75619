// expect: has no member named 'get_logger'
// distros: humble
// Humble's SystemInterface has no get_logger()/get_node()/get_clock().
#include <string>
#include <hardware_interface/system_interface.hpp>

void f(hardware_interface::SystemInterface & hw)
{
#ifdef RHI_EXPECT_FAIL
  (void)hw.get_logger();
#else
  std::string name = hw.get_name();
  (void)name;
#endif
}
