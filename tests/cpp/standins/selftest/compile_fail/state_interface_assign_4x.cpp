// expect: use of deleted function .*StateInterface::operator=
// distros: jazzy kilted rolling
// StateInterface is copyable but not assignable on 4.x+ too.
#include <hardware_interface/handle.hpp>

void f()
{
  hardware_interface::InterfaceInfo info{};
  info.name = "position";
  hardware_interface::StateInterface a(hardware_interface::InterfaceDescription("joint", info));
  hardware_interface::StateInterface b(a);
#ifdef RHI_EXPECT_FAIL
  b = a;
#endif
  (void)b;
}
