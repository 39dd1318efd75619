// expect: no matching function for call to .*async_send_request
// async_send_request(request, callback) requires a callback taking exactly Client::SharedFuture (or
// SharedFutureWithRequest) by value: rclcpp matches it with function_traits::same_arguments, so a
// const reference parameter selects no overload.
#include <lifecycle_msgs/srv/get_state.hpp>
#include <rclcpp/rclcpp.hpp>

using GetState = lifecycle_msgs::srv::GetState;

void f(rclcpp::Node & node)
{
  auto client = node.create_client<GetState>("get_state");
#ifdef RHI_EXPECT_FAIL
  auto pending = client->async_send_request(
    std::make_shared<GetState::Request>(),
    [](const rclcpp::Client<GetState>::SharedFuture & future) {(void)future;});
#else
  auto pending = client->async_send_request(
    std::make_shared<GetState::Request>(),
    [](rclcpp::Client<GetState>::SharedFuture future) {(void)future;});
#endif
  (void)pending;
}
