// expect: use of deleted function .*CommandInterface\(const hardware_interface::CommandInterface&\)
// distros: jazzy kilted rolling
// CommandInterface cannot be copied on 4.x+ either (handles are shared through SharedPtr).
#include <utility>
#include <hardware_interface/handle.hpp>

void f()
{
  hardware_interface::InterfaceInfo info{};
  info.name = "position";
  hardware_interface::CommandInterface a(hardware_interface::InterfaceDescription("joint", info));
#ifdef RHI_EXPECT_FAIL
  hardware_interface::CommandInterface b(a);
#else
  hardware_interface::CommandInterface b(std::move(a));
#endif
  (void)b;
}
