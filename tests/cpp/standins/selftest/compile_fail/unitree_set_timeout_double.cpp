// expect: ambiguous
// ClientBase::SetTimeout(int64_t) / SetTimeout(float): a double literal is ambiguous.
#include <unitree/robot/b2/motion_switcher/motion_switcher_client.hpp>

void f(unitree::robot::b2::MotionSwitcherClient & client)
{
#ifdef RHI_EXPECT_FAIL
  client.SetTimeout(5.0);
#else
  client.SetTimeout(5.0f);
#endif
}
