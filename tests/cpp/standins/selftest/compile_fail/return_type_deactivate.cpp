// expect: 'DEACTIVATE' is not a member
// distros: humble
// Humble's return_type has only OK and ERROR.
#include <hardware_interface/types/hardware_interface_return_values.hpp>

hardware_interface::return_type f()
{
#ifdef RHI_EXPECT_FAIL
  return hardware_interface::return_type::DEACTIVATE;
#else
  return hardware_interface::return_type::ERROR;
#endif
}
