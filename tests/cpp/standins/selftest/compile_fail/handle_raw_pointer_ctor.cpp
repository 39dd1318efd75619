// expect: Handle\(const string&, const string&, double\*\).* is deprecated|is deprecated: Use InterfaceDescription
// distros: jazzy kilted rolling
// Handle(prefix, name, double *) is deprecated on 4.x+: build handles from an InterfaceDescription.
#include <hardware_interface/handle.hpp>

double value = 0.0;

void f()
{
#ifdef RHI_EXPECT_FAIL
  hardware_interface::Handle h("joint", "position", &value);
#else
  hardware_interface::InterfaceInfo info{};
  info.name = "position";
  hardware_interface::Handle h(hardware_interface::InterfaceDescription("joint", info));
#endif
  (void)h;
}
