// expect: conversion from .*FutureAndRequestId.* to non-scalar type .*SharedFuture
// distros: kilted rolling
// Kilted and later removed the implicit FutureAndRequestId -> Client::SharedFuture conversion
// (deprecated in Humble and Jazzy): use .future.share() (or .share()).
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
    client->async_send_request(std::make_shared<GetState::Request>()).share();
#endif
  (void)future;
}
