// expect: 'HW_IF_POSITION' is not a member
// distros: humble
// Humble's system_interface.hpp does not include hardware_interface_type_values.hpp.
#include <string>
#include <hardware_interface/system_interface.hpp>
#ifndef RHI_EXPECT_FAIL
#include <hardware_interface/types/hardware_interface_type_values.hpp>
#endif

std::string f()
{
  return hardware_interface::HW_IF_POSITION;
}
