// expect: has no member named 'thread_priority'
// distros: rolling
// 6.x removed HardwareInfo::thread_priority: use async_params.thread_priority.
#include <hardware_interface/hardware_info.hpp>

void f(hardware_interface::HardwareInfo & info)
{
#ifdef RHI_EXPECT_FAIL
  info.thread_priority = 50;
#else
  info.async_params.thread_priority = 50;
#endif
}
