// expect: no matching function for call to .*create_wall_timer
// Wall timer callbacks are void() or void(rclcpp::TimerBase &).
#include <chrono>
#include <rclcpp/rclcpp.hpp>

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto t = node.create_wall_timer(std::chrono::milliseconds(2), [](int) {});
#else
  auto t = node.create_wall_timer(std::chrono::milliseconds(2), []() {});
#endif
  (void)t;
}
