// expect: has no member named 'hardware_plugin_name'
// distros: humble
// Humble calls the <plugin> hardware_class_type.
#include <string>
#include <hardware_interface/hardware_info.hpp>

std::string f(const hardware_interface::HardwareInfo & info)
{
#ifdef RHI_EXPECT_FAIL
  return info.hardware_plugin_name;
#else
  return info.hardware_class_type;
#endif
}
