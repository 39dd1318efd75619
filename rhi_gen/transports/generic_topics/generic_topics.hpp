// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_HPP_

// Any robot over ROS 2 topics, in the manner of topic_based_ros2_control: sensor_msgs/JointState
// for state and commands (entries matched by joint name), sensor_msgs/Imu for the IMU.
// sensor_msgs/JointState carries no stiffness or damping: the receiver applies its own gains.

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <sensor_msgs/msg/joint_state.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/system_driver.hpp"
#include "robot_hardware_interface/transport/ros_topics.hpp"

namespace robot_hardware_interface
{

// transport_options of the vendor YAML.
struct GenericTopicsOptions
{
  const char * command_topic;
  const char * state_topic;
  const char * imu_topic;
  TopicQos qos;
};

template<size_t N, typename T>
class GenericTopicsTransport final : public DriverTransport<N, T>
{
  using JointState = sensor_msgs::msg::JointState;
  using Imu = sensor_msgs::msg::Imu;

public:
  explicit GenericTopicsTransport(const GenericTopicsOptions & options)
  : options_(options)
  {
  }

  const char * name() const override {return "generic_topics";}
  // sensor_msgs/JointState has no stiffness or damping: the receiver applies its own gains.
  bool carries_gains() const override {return false;}

  bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node) override
  {
    core_ = &core;
    node_ = node;
    // State entries are matched by joint name: build the lookup once, so the callback only reads
    // it. Commands name every driven joint in slot order; sized once, the writer fills in numbers.
    const auto & slots = core.slots().mapped_slots();
    slot_by_joint_name_.reserve(slots.size());
    command_msg_.name.clear();
    for (const size_t slot : slots) {
      slot_by_joint_name_.emplace(core.slots().slot_joint_names()[slot], slot);
      command_msg_.name.emplace_back(core.slots().slot_joint_names()[slot]);
    }
    command_msg_.position.assign(slots.size(), 0.0);
    command_msg_.velocity.assign(slots.size(), 0.0);
    command_msg_.effort.assign(slots.size(), 0.0);
    const rclcpp::QoS qos = make_qos(options_.qos);
    publisher_ = node->create_publisher<JointState>(options_.command_topic, qos);
    state_subscription_ = node->create_subscription<JointState>(
      options_.state_topic, qos, [this](const JointState & msg) {on_joint_state(msg);});
    if (core.has_imu()) {
      imu_subscription_ = node->create_subscription<Imu>(
        options_.imu_topic, qos, [this](const Imu & msg) {
          publish_ros_imu(*core_, msg.orientation, msg.angular_velocity, msg.linear_acceleration);
        });
    }
    executor_.configure(node);
    return true;
  }

  bool start() override
  {
    // Every joint has to be reported again before the first state of this activation.
    slot_reported_.fill(false);
    slots_reported_ = 0;
    slot_state_time_ns_.fill(0);
    executor_.start(
      core_->parameters().command_writer_period_us, core_->logger(), core_->on_write_writer(),
      [this]() {write_command();});
    return true;
  }

  void stop() override {executor_.stop();}

  void shutdown() noexcept override
  {
    try {
      executor_.stop();
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_->logger(), "stopping the executor thread failed: %s", e.what());
    }
  }

private:
  // Executor thread: entries matched by name. velocity and effort may be empty (sensor_msgs
  // allows it); then the previous values are kept. state_decimation counts JointState messages:
  // keep it at 1 when the joints arrive spread over several publishers.
  void on_joint_state(const JointState & msg)
  {
    const auto start = std::chrono::steady_clock::now();
    // Every frame: array sizes must agree with the names.
    const size_t count = msg.name.size();
    const bool has_velocity = !msg.velocity.empty();
    const bool has_effort = !msg.effort.empty();
    if (msg.position.size() != count || (has_velocity && msg.velocity.size() != count) ||
      (has_effort && msg.effort.size() != count))
    {
      reject("name/position/velocity/effort sizes differ");
      return;
    }
    if (!core_->start_state_frame()) {
      return;  // decimated
    }
    // Validate the whole frame before touching the parsing buffer: a rejected frame must leave
    // no trace.
    for (size_t i = 0; i < count; ++i) {
      if (slot_by_joint_name_.find(msg.name[i]) == slot_by_joint_name_.end()) {
        continue;  // a joint this driver does not drive
      }
      if (!all_finite(msg.position[i]) || (has_velocity && !all_finite(msg.velocity[i])) ||
        (has_effort && !all_finite(msg.effort[i])))
      {
        reject("non-finite value for a driven joint");
        return;
      }
    }
    const int64_t now_ns = steady_ns(start);
    auto & state = core_->state_frame();
    for (size_t i = 0; i < count; ++i) {
      const auto it = slot_by_joint_name_.find(msg.name[i]);
      if (it == slot_by_joint_name_.end()) {
        continue;
      }
      const size_t slot = it->second;
      state.q[slot] = static_cast<T>(msg.position[i]);
      if (has_velocity) {
        state.dq[slot] = static_cast<T>(msg.velocity[i]);
      }
      if (has_effort) {
        state.tau[slot] = static_cast<T>(msg.effort[i]);
      }
      slot_state_time_ns_[slot] = now_ns;
      if (!slot_reported_[slot]) {
        slot_reported_[slot] = true;
        ++slots_reported_;
      }
    }
    // First-state rule: only once every driven joint has been reported is the state complete.
    // Its age is the age of the joint reported longest ago.
    if (slots_reported_ == core_->slots().mapped_slots().size()) {
      int64_t oldest_ns = now_ns;
      for (const size_t slot : core_->slots().mapped_slots()) {
        oldest_ns = std::min(oldest_ns, slot_state_time_ns_[slot]);
      }
      core_->publish_state(oldest_ns);
    }
    core_->monitor().check_state_latency(start);
  }

  void reject(const char * reason)
  {
    const uint64_t dropped = core_->reject_state();
    RCLCPP_WARN_THROTTLE(
      core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "dropped state frame: %s (%" PRIu64 " dropped so far)", reason, dropped);
  }

  // Executor thread (wall timer): one JointState command every command_writer_period_us. Only
  // position, velocity and effort travel; a held joint gets its last safe position with zero
  // velocity and effort.
  void write_command()
  {
    const auto start = std::chrono::steady_clock::now();
    core_->monitor().check_writer_jitter();
    const auto * cmd = core_->next_command();
    if (cmd == nullptr) {
      return;
    }
    command_msg_.header.stamp = node_->now();
    const auto & slots = core_->slots().mapped_slots();
    for (size_t i = 0; i < slots.size(); ++i) {
      command_msg_.position[i] = static_cast<double>(cmd->q_target[slots[i]]);
      command_msg_.velocity[i] = static_cast<double>(cmd->dq_target[slots[i]]);
      command_msg_.effort[i] = static_cast<double>(cmd->tau_ff[slots[i]]);
    }
    publisher_->publish(command_msg_);
    core_->monitor().check_writer_latency(start);
  }

  const GenericTopicsOptions options_;
  DriverCore<N, T> * core_{nullptr};
  rclcpp::Node::SharedPtr node_;
  std::unordered_map<std::string, size_t> slot_by_joint_name_;
  JointState command_msg_;  // pre-sized in configure(): no allocation per cycle
  typename rclcpp::Publisher<JointState>::SharedPtr publisher_;
  typename rclcpp::Subscription<JointState>::SharedPtr state_subscription_;
  typename rclcpp::Subscription<Imu>::SharedPtr imu_subscription_;
  TopicExecutor executor_;
  // Executor thread: a state is complete once every driven joint has been reported.
  std::array<bool, N> slot_reported_{};
  size_t slots_reported_{0};
  std::array<int64_t, N> slot_state_time_ns_{};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_HPP_
