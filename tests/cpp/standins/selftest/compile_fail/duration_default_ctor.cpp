// expect: private within this context|is private
// rclcpp::Duration has no public default constructor.
#include <rclcpp/duration.hpp>

void f()
{
#ifdef RHI_EXPECT_FAIL
  rclcpp::Duration d;
#else
  rclcpp::Duration d(0, 0);
#endif
  (void)d;
}
