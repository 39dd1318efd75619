// expect: use of deleted function .*CommandInterface\(const hardware_interface::CommandInterface&\)
// distros: humble
// Humble deletes CommandInterface's copy constructor: vectors must be built by moving.
#include <utility>
#include <vector>
#include <hardware_interface/handle.hpp>

void f()
{
  double value = 0.0;
  hardware_interface::CommandInterface a("joint", "position", &value);
#ifdef RHI_EXPECT_FAIL
  hardware_interface::CommandInterface b(a);
#else
  hardware_interface::CommandInterface b(std::move(a));
#endif
  std::vector<hardware_interface::CommandInterface> v;
  v.push_back(std::move(b));
}
