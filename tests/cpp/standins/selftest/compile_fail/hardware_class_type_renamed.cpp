// expect: has no member named 'hardware_class_type'
// distros: jazzy kilted rolling
// 4.x+ renamed HardwareInfo::hardware_class_type to hardware_plugin_name.
#include <string>
#include <hardware_interface/hardware_info.hpp>

std::string f(const hardware_interface::HardwareInfo & info)
{
#ifdef RHI_EXPECT_FAIL
  return info.hardware_class_type;
#else
  return info.hardware_plugin_name;
#endif
}
