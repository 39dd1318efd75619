// expect: private within this context|is private
// rclcpp::Logger has no public default constructor: initialize with rclcpp::get_logger(name).
#include <rclcpp/logger.hpp>

struct Driver
{
#ifdef RHI_EXPECT_FAIL
  rclcpp::Logger logger_;
#else
  rclcpp::Logger logger_{rclcpp::get_logger("driver")};
#endif
};

void f()
{
  Driver d;
  (void)d;
}
