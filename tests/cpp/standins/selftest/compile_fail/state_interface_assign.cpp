// expect: use of deleted function .*StateInterface::operator=
// distros: humble
// StateInterface is copyable but not assignable (its move constructor is user-declared).
#include <vector>
#include <hardware_interface/handle.hpp>

void f()
{
  double value = 0.0;
  std::vector<hardware_interface::StateInterface> v;
  v.emplace_back("joint", "position", &value);
#ifdef RHI_EXPECT_FAIL
  v[0] = hardware_interface::StateInterface("joint", "velocity", &value);
#else
  hardware_interface::StateInterface copy(v[0]);
  (void)copy;
#endif
}
