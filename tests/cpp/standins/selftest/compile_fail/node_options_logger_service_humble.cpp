// expect: has no member named 'enable_logger_service'
// distros: humble
// NodeOptions::enable_logger_service() came with rclcpp 21 (Iron); Humble is rclcpp 16.
#include <rclcpp/node_options.hpp>

void f(rclcpp::NodeOptions & options)
{
#ifdef RHI_EXPECT_FAIL
  options.enable_logger_service(true);
#else
  options.arguments({"--ros-args"});
#endif
}
