// expect: is deprecated: Use InterfaceDescription
// distros: kilted rolling
// 5.x+ no longer silences StateInterface's inherited raw-pointer constructor: with the headers on
// -I (as here) the deprecation is an error inside handle.hpp, where no pragma of the caller reaches.
#include <hardware_interface/handle.hpp>

double value = 0.0;

void f()
{
#ifdef RHI_EXPECT_FAIL
  hardware_interface::StateInterface s("joint", "position", &value);
#else
  hardware_interface::InterfaceInfo info{};
  info.name = "position";
  hardware_interface::StateInterface s(hardware_interface::InterfaceDescription("joint", info));
#endif
  (void)s;
}
