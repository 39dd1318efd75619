// expect: unsupported service callback signature
// A service callback taking the request and response by reference is none of the forms
// rclcpp::AnyServiceCallback accepts (they take shared_ptrs).
#include <lifecycle_msgs/srv/change_state.hpp>
#include <rclcpp/rclcpp.hpp>

using ChangeState = lifecycle_msgs::srv::ChangeState;

void f(rclcpp::Node & node)
{
#ifdef RHI_EXPECT_FAIL
  auto service = node.create_service<ChangeState>(
    "change_state", [](const ChangeState::Request & request, ChangeState::Response & response) {
      response.success = request.transition.id == 3;
    });
#else
  auto service = node.create_service<ChangeState>(
    "change_state",
    [](const std::shared_ptr<ChangeState::Request> request, std::shared_ptr<ChangeState::Response> response) {
      response->success = request->transition.id == 3;
    });
#endif
  (void)service;
}
