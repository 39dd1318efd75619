// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_FAKE_ROBOT_HPP_

// The robot's side of AimDK's system-state services for the fake robot (take_control: true): it
// starts in "Ready", accepts a migration to a state AimDK documents and refuses any other, and
// reports the new state IN_MOVE for a few queries before IN_READY, as a real migration takes time.

#include <array>
#include <memory>
#include <mutex>
#include <string>

#include <aimdk_msgs/msg/common_state.hpp>
#include <aimdk_msgs/msg/system_status.hpp>
#include <aimdk_msgs/srv/get_system_state.hpp>
#include <aimdk_msgs/srv/migrate_system_state.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/service.hpp>

#include "robot_hardware_interface/transport/agibot_system_state.hpp"

namespace robot_hardware_interface
{

class AimdkFakeSystemState
{
  using Migrate = aimdk_msgs::srv::MigrateSystemState;
  using GetState = aimdk_msgs::srv::GetSystemState;
  using SystemStatus = aimdk_msgs::msg::SystemStatus;
  using CommonState = aimdk_msgs::msg::CommonState;
  static constexpr int kQueriesInMove = 2;  // GetSystemState answers IN_MOVE this often first

public:
  // The states MigrateSystemState takes (AimDK system_state documentation).
  static constexpr std::array<const char *, 5> kStates = {
    "Ready", "Develop_Nav", "Develop_Audio_Linux", "Develop_Audio_ROS", "Develop_MC"};

  void configure(const rclcpp::Node::SharedPtr & node)
  {
    migrate_ = node->create_service<Migrate>(
      AimdkSystemState::kMigrateService,
      [this](
        const std::shared_ptr<Migrate::Request> request,
        std::shared_ptr<Migrate::Response> response) {on_migrate(*request, *response);});
    get_state_ = node->create_service<GetState>(
      AimdkSystemState::kGetStateService,
      [this](
        const std::shared_ptr<GetState::Request>,
        std::shared_ptr<GetState::Response> response) {on_get_state(*response);});
  }

  // The state the fake robot is in (tests).
  std::string state() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
  }

private:
  static const char * known_state(const std::string & name)
  {
    for (const char * state : kStates) {
      if (AimdkSystemState::same_state(name, state)) {
        return state;
      }
    }
    return nullptr;
  }

  void on_migrate(const Migrate::Request & request, Migrate::Response & response)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const char * state = known_state(request.state);
    response.header.header.code = 0;
    if (state == nullptr) {
      response.header.status.value = CommonState::FAILURE;
      response.header.message = "unknown system state '" + request.state + "'";
      return;
    }
    state_ = state;
    queries_in_move_ = kQueriesInMove;
    response.header.status.value = CommonState::SUCCESS;
    response.header.message = "migrating to " + state_;
  }

  void on_get_state(GetState::Response & response)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    response.header.header.code = 0;
    response.header.status.value = CommonState::SUCCESS;
    response.cur_state = state_;
    response.curr_status.value =
      queries_in_move_ > 0 ? SystemStatus::IN_MOVE : SystemStatus::IN_READY;
    if (queries_in_move_ > 0) {
      --queries_in_move_;
    }
  }

  mutable std::mutex mutex_;  // the service callbacks and state()
  std::string state_{"Ready"};
  int queries_in_move_{0};
  rclcpp::Service<Migrate>::SharedPtr migrate_;
  rclcpp::Service<GetState>::SharedPtr get_state_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_FAKE_ROBOT_HPP_
