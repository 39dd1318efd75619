// expect: is deprecated: FutureAndRequestId: use .future.share\(\) instead of an implicit conversion
// distros: humble jazzy
// Converting async_send_request's FutureAndRequestId to a Client::SharedFuture is deprecated in
// Humble and Jazzy (removed from Kilted on): use .future.share() (or .share()).
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

using GetState = lifecycle_msgs::srv::GetState;

void f(rclcpp::Node & node)
{
  auto client = node.create_client<GetState>("get_state");
#ifdef RHI_EXPECT_FAIL
  rclcpp::Client<GetState>::SharedFuture future = client->async_send_request(std::make_shared<GetState::Request>());
#else
  rclcpp::Client<GetState>::SharedFuture future =
    client->async_send_request(std::make_shared<GetState::Request>()).future.share();
#endif
  (void)future;
}
