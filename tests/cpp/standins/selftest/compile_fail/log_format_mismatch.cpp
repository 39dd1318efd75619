// expect: -Werror=format
// The RCLCPP_* format string is printf-checked like rcutils_log().
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Logger logger, long value)
{
#ifdef RHI_EXPECT_FAIL
  RCLCPP_INFO(logger, "value %d", value);
#else
  RCLCPP_INFO(logger, "value %ld", value);
#endif
}
