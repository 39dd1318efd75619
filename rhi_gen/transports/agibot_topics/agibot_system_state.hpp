// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_HPP_

// Taking control of an AgiBot robot the vendor's way (transport_options.take_control): whole-body
// joint commands need AgiBot's motion control (MC) stopped, which AimDK's system-state service does
// (MigrateSystemState "Develop_MC"; "Ready" gives MC back). A migration is accepted by the service
// and then carried out: it is done once GetSystemState reports the state and IN_READY. Service
// calls follow the vendor examples: wait for the service, then up to 8 attempts of 250 ms (remote
// peers are not handled well by ROS, say the examples). Every request and its answer is logged.
//
// Runs on the caller's thread (on_activate / on_deactivate) while the transport's executor does not
// spin: the responses are taken by spinning that executor here.

#include <cctype>
#include <cinttypes>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include <aimdk_msgs/msg/common_state.hpp>
#include <aimdk_msgs/msg/system_status.hpp>
#include <aimdk_msgs/srv/get_system_state.hpp>
#include <aimdk_msgs/srv/migrate_system_state.hpp>
#include <rclcpp/client.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/utilities.hpp>

#include "robot_hardware_interface/transport/ros_topics.hpp"

namespace robot_hardware_interface
{

class AimdkSystemState
{
  using Migrate = aimdk_msgs::srv::MigrateSystemState;
  using GetState = aimdk_msgs::srv::GetSystemState;
  using SystemStatus = aimdk_msgs::msg::SystemStatus;

public:
  static constexpr const char * kMigrateService = "/aimdk_5Fmsgs/srv/MigrateSystemState";
  static constexpr const char * kGetStateService = "/aimdk_5Fmsgs/srv/GetSystemState";
  static constexpr const char * kDevelopMc = "Develop_MC";  // MC stopped: joint commands are ours
  static constexpr const char * kReady = "Ready";           // the default state: MC runs
  static constexpr int kAttempts = 8;
  static constexpr std::chrono::milliseconds kAttemptTimeout{250};
  static constexpr std::chrono::milliseconds kPollPeriod{200};

  // `timeout_s`: how long taking control may wait for Develop_MC
  // (transport_options.take_control_timeout_s).
  explicit AimdkSystemState(double timeout_s)
  : timeout_s_(timeout_s)
  {
  }

  // AgibotTopicsTransport's `Control`: configure(), take() before the first command, release()
  // after the last.
  void configure(const rclcpp::Node::SharedPtr & node)
  {
    node_ = node;
    migrate_ = node->create_client<Migrate>(kMigrateService);
    get_state_ = node->create_client<GetState>(kGetStateService);
  }

  bool take(TopicExecutor & executor, const rclcpp::Logger & logger)
  {
    return migrate(executor, kDevelopMc, timeout_s_, logger);
  }

  void release(TopicExecutor & executor, const rclcpp::Logger & logger)
  {
    if (!migrate(executor, kReady, timeout_s_, logger)) {
      RCLCPP_ERROR(
        logger, "AgiBot's motion control may still be stopped: migrate the robot to '%s' yourself "
        "(the AimDK migrate_system_state example) or reboot it", kReady);
    }
  }

  // Asks for system state `state` and waits until the robot reports it ready, at most `timeout_s`.
  // False (logged with the reason) when the service is missing, refuses, or the state never comes.
  bool migrate(
    TopicExecutor & executor, const char * state, double timeout_s, const rclcpp::Logger & logger)
  {
    const auto deadline = std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(timeout_s));
    auto request = std::make_shared<Migrate::Request>();
    request->header.header.stamp = node_->now();
    request->state = state;
    RCLCPP_INFO(logger, "%s: requesting system state '%s'", kMigrateService, state);
    std::shared_ptr<Migrate::Response> response;
    if (!call(executor, migrate_, request, deadline, response, logger)) {
      return false;
    }
    const auto & header = response->header;
    RCLCPP_INFO(
      logger, "%s answered: code %" PRId64 ", status %d, message '%s'", kMigrateService,
      static_cast<int64_t>(header.header.code), static_cast<int>(header.status.value),
      header.message.c_str());
    if (header.header.code != 0 || header.status.value != aimdk_msgs::msg::CommonState::SUCCESS) {
      const char * reason = header.message.empty() ? "no reason given" : header.message.c_str();
      RCLCPP_ERROR(
        logger, "the robot refused system state '%s' (%s): see the AimDK system state "
        "documentation", state, reason);
      return false;
    }
    return wait_until_ready(executor, state, deadline, logger);
  }

  // AimDK compares state names without case.
  static bool same_state(const std::string & a, const char * b)
  {
    const std::string other(b);
    if (a.size() != other.size()) {
      return false;
    }
    for (size_t i = 0; i < a.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(other[i])))
      {
        return false;
      }
    }
    return true;
  }

private:
  template<typename ClientPtr, typename RequestPtr, typename ResponsePtr>
  bool call(
    TopicExecutor & executor, const ClientPtr & client, const RequestPtr & request,
    std::chrono::steady_clock::time_point deadline, ResponsePtr & response,
    const rclcpp::Logger & logger)
  {
    while (!client->wait_for_service(std::chrono::milliseconds(100))) {
      if (!rclcpp::ok() || std::chrono::steady_clock::now() >= deadline) {
        RCLCPP_ERROR(
          logger, "service %s is not available: is AimDK running, on this ROS domain?",
          client->get_service_name());
        return false;
      }
    }
    for (int attempt = 1; attempt <= kAttempts; ++attempt) {
      auto pending = client->async_send_request(request);
      if (executor.spin_until(pending.future, kAttemptTimeout)) {
        response = pending.future.get();
        return true;
      }
      client->remove_pending_request(pending.request_id);
      if (std::chrono::steady_clock::now() >= deadline) {
        break;
      }
    }
    RCLCPP_ERROR(
      logger, "service %s did not answer (%d attempts of %" PRId64 " ms)",
      client->get_service_name(), kAttempts, static_cast<int64_t>(kAttemptTimeout.count()));
    return false;
  }

  // GetSystemState until `state` is reported with IN_READY, one request every kPollPeriod.
  bool wait_until_ready(
    TopicExecutor & executor, const char * state, std::chrono::steady_clock::time_point deadline,
    const rclcpp::Logger & logger)
  {
    const auto start = std::chrono::steady_clock::now();
    std::string last_state;
    unsigned last_status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      auto request = std::make_shared<GetState::Request>();
      request->header.header.stamp = node_->now();
      std::shared_ptr<GetState::Response> response;
      if (!call(executor, get_state_, request, deadline, response, logger)) {
        return false;
      }
      last_state = response->cur_state;
      last_status = response->curr_status.value;
      if (same_state(last_state, state) && last_status == SystemStatus::IN_READY) {
        RCLCPP_INFO(
          logger, "%s: system state '%s' ready after %.1f s", kGetStateService, state,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        return true;
      }
      std::this_thread::sleep_for(kPollPeriod);
    }
    RCLCPP_ERROR(
      logger, "system state '%s' not ready in time: the robot reports '%s' (status %u)", state,
      last_state.c_str(), last_status);
    return false;
  }

  const double timeout_s_;
  rclcpp::Node::SharedPtr node_;
  typename rclcpp::Client<Migrate>::SharedPtr migrate_;
  typename rclcpp::Client<GetState>::SharedPtr get_state_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_SYSTEM_STATE_HPP_
