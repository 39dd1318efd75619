// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_HPP_

// EngineAI robots over ROS 2 topics (interface_protocol): JointCommand / JointState arrays indexed
// by motor slot, ImuInfo for the IMU, MotorDebug for the motor health (temperatures; with the
// native SDK's release also voltages, error codes and offline motors). The robot must be in
// joint_bridge mode.
//
// EngineAI publishes two releases of interface_protocol whose MotorDebug differs:
// engineai_ros2_workspace has float64[] tau_cmd, mos_temperature, motor_temperature;
// engineai_robotics_native_sdk has float32[] mos_temperature, motor_temperature, voltage, current,
// int32[] error_code, uint8[] offline, enable (no tau_cmd). The same source builds against either:
// what the message has is detected at compile time (the traits below), never configured.

#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <interface_protocol/msg/imu_info.hpp>
#include <interface_protocol/msg/joint_command.hpp>
#include <interface_protocol/msg/joint_state.hpp>
#include <interface_protocol/msg/motor_debug.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/system_driver.hpp"
#include "robot_hardware_interface/transport/ros_topics.hpp"

namespace robot_hardware_interface
{

// Whether a MotorDebug has the member tau_cmd (only engineai_ros2_workspace's does).
// Code that touches such a member goes through a template on the message type, so the branch for a
// member the message lacks is discarded (if constexpr), never compiled.
template<typename Debug, typename = void>
struct MotorDebugHasTauCmd : std::false_type {};
template<typename Debug>
struct MotorDebugHasTauCmd<Debug, std::void_t<decltype(std::declval<Debug &>().tau_cmd)>>
  : std::true_type {};

// Whether a MotorDebug has the native SDK's per-motor health: voltage, error_code and offline
// (all three or none: engineai_robotics_native_sdk's release has them, engineai_ros2_workspace's
// does not). With them the driver exports `voltage` and `error_code` per joint beyond the
// description (DriverTransport::detected_motor_health()) and an offline motor faults the robot.
template<typename Debug, typename = void>
struct MotorDebugHasMotorHealth : std::false_type {};
template<typename Debug>
struct MotorDebugHasMotorHealth<Debug, std::void_t<
    decltype(std::declval<Debug &>().voltage), decltype(std::declval<Debug &>().error_code),
    decltype(std::declval<Debug &>().offline)>>
  : std::true_type {};

// transport_options of the vendor YAML.
struct EngineaiTopicsOptions
{
  const char * command_topic;
  const char * state_topic;
  const char * imu_topic;
  const char * motor_debug_topic;
  uint8_t parallel_parser_type;  // 0 CLASSIC_PARSER, 1 RL_PARSER
  TopicQos qos;
};

template<size_t N, typename T>
class EngineaiTopicsTransport final : public DriverTransport<N, T>
{
  using JointCommand = interface_protocol::msg::JointCommand;
  using JointState = interface_protocol::msg::JointState;
  using ImuInfo = interface_protocol::msg::ImuInfo;
  using MotorDebug = interface_protocol::msg::MotorDebug;
  // The MotorHealthField bits the MotorDebug carries: the temperature (both releases), and the
  // native SDK's voltage, error code and offline flag.
  static constexpr uint8_t kDebugHealth = MotorDebugHasMotorHealth<MotorDebug>::value ?
    static_cast<uint8_t>(kMotorTemperature | kMotorVoltage | kMotorErrorCode | kMotorOffline) :
    static_cast<uint8_t>(kMotorTemperature);

public:
  explicit EngineaiTopicsTransport(const EngineaiTopicsOptions & options)
  : options_(options)
  {
  }

  const char * name() const override {return "engineai_topics";}
  uint8_t motor_health() const override {return kDebugHealth;}
  // The description lists the temperature (both releases carry it); the rest is found here.
  uint8_t detected_motor_health() const override
  {
    return static_cast<uint8_t>(kDebugHealth & ~kMotorTemperature);
  }
  const char * no_error_codes_reason() const override
  {
    return "its interface_protocol MotorDebug has no error_code (engineai_ros2_workspace's "
           "release; the EngineAI native SDK's has one)";
  }

  bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node) override
  {
    core_ = &core;
    node_ = node;
    // Size the command arrays once (index = motor slot): the writer only fills in numbers.
    // `torque` is a direct torque command that stays 0: this driver commands through the PD law
    // (position, velocity, stiffness, damping) plus feed_forward_torque.
    command_msg_.position.assign(N, 0.0);
    command_msg_.velocity.assign(N, 0.0);
    command_msg_.feed_forward_torque.assign(N, 0.0);
    command_msg_.torque.assign(N, 0.0);
    command_msg_.stiffness.assign(N, 0.0);
    command_msg_.damping.assign(N, 0.0);
    command_msg_.parallel_parser_type = options_.parallel_parser_type;
    const rclcpp::QoS qos = make_qos(options_.qos);
    publisher_ = node->create_publisher<JointCommand>(options_.command_topic, qos);
    state_subscription_ = node->create_subscription<JointState>(
      options_.state_topic, qos, [this](const JointState & msg) {on_joint_state(msg);});
    if (core.has_imu()) {
      imu_subscription_ = node->create_subscription<ImuInfo>(
        options_.imu_topic, qos, [this](const ImuInfo & msg) {
          publish_ros_imu(*core_, msg.quaternion, msg.angular_velocity, msg.linear_acceleration);
        });
    }
    motor_debug_subscription_ = node->create_subscription<MotorDebug>(
      options_.motor_debug_topic, qos, [this](const MotorDebug & msg) {on_motor_debug(msg);});
    executor_.configure(node);
    return true;
  }

  bool start() override
  {
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
  // Executor thread: JointState arrays indexed by motor slot.
  void on_joint_state(const JointState & msg)
  {
    const auto start = std::chrono::steady_clock::now();
    // Every frame: a frame too short to cover every motor is malformed.
    if (msg.position.size() < N || msg.velocity.size() < N || msg.torque.size() < N) {
      reject("position/velocity/torque arrays shorter than the motor count");
      return;
    }
    if (!core_->start_state_frame()) {
      return;  // decimated
    }
    // A frame rejected half-way leaves partial values in the parsing buffer; harmless, because
    // only a fully accepted frame is published and it rewrites every driven slot.
    auto & state = core_->state_frame();
    for (const size_t slot : core_->slots().mapped_slots()) {
      const double q = msg.position[slot];
      const double dq = msg.velocity[slot];
      const double tau = msg.torque[slot];
      if (!all_finite(q, dq, tau)) {
        reject("non-finite value in a driven motor slot");
        return;
      }
      state.q[slot] = static_cast<T>(q);
      state.dq[slot] = static_cast<T>(dq);
      state.tau[slot] = static_cast<T>(tau);
    }
    core_->publish_state(steady_ns(start));
    core_->monitor().check_state_latency(start);
  }

  // Executor thread: MotorDebug (50 Hz or more), arrays indexed by motor slot like JointState.
  // Both interface_protocol versions have motor_temperature (float64 in engineai_ros2_workspace,
  // float32 in the native SDK); the native SDK's also voltage, error_code and offline. A message
  // too short or with a non-finite value is dropped: the last good health stays.
  void on_motor_debug(const MotorDebug & msg)
  {
    const int64_t now_ns = steady_ns(std::chrono::steady_clock::now());
    if (!core_->motor_health_due(now_ns)) {
      return;
    }
    const char * problem = motor_debug_problem(msg);
    if (problem != nullptr) {
      reject_motor_debug(problem);
      return;
    }
    auto & health = core_->motor_health_frame();
    for (const size_t slot : core_->slots().mapped_slots()) {
      health.temperature[slot] = static_cast<double>(msg.motor_temperature[slot]);
    }
    fill_native_health(msg, health);
    core_->publish_motor_health(now_ns);
  }

  // Why a MotorDebug cannot be used, nullptr when it can. A template on the message type: the
  // native SDK's members are only compiled where the message has them.
  template<typename Debug>
  const char * motor_debug_problem(const Debug & msg) const
  {
    if (msg.motor_temperature.size() < N) {
      return "motor_temperature shorter than the motor count";
    }
    if constexpr (MotorDebugHasMotorHealth<Debug>::value) {
      if (msg.voltage.size() < N || msg.error_code.size() < N || msg.offline.size() < N) {
        return "voltage/error_code/offline shorter than the motor count";
      }
    }
    for (const size_t slot : core_->slots().mapped_slots()) {
      if (!all_finite(msg.motor_temperature[slot])) {
        return "non-finite temperature in a driven motor slot";
      }
      if constexpr (MotorDebugHasMotorHealth<Debug>::value) {
        if (!all_finite(msg.voltage[slot])) {
          return "non-finite voltage in a driven motor slot";
        }
      }
    }
    return nullptr;
  }

  // The native SDK's voltage, error code (int32: its bits as the vendor's unsigned code) and
  // offline flag; nothing with engineai_ros2_workspace's MotorDebug.
  template<typename Debug>
  void fill_native_health(const Debug & msg, MotorHealthFrame<N> & health) const
  {
    if constexpr (MotorDebugHasMotorHealth<Debug>::value) {
      for (const size_t slot : core_->slots().mapped_slots()) {
        health.voltage[slot] = static_cast<double>(msg.voltage[slot]);
        health.error_code[slot] = static_cast<double>(static_cast<uint32_t>(msg.error_code[slot]));
        health.offline[slot] = msg.offline[slot] != 0U;
      }
    } else {
      static_cast<void>(msg);
      static_cast<void>(health);
    }
  }

  void reject_motor_debug(const char * reason)
  {
    RCLCPP_WARN_THROTTLE(
      core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "dropped MotorDebug message on %s: %s", options_.motor_debug_topic, reason);
  }

  void reject(const char * reason)
  {
    const uint64_t dropped = core_->reject_state();
    RCLCPP_WARN_THROTTLE(
      core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "dropped state frame: %s (%" PRIu64 " dropped so far)", reason, dropped);
  }

  // Executor thread (wall timer): one JointCommand every command_writer_period_us. Slots that
  // drive no URDF joint carry zero gains, i.e. stay passive.
  void write_command()
  {
    const auto start = std::chrono::steady_clock::now();
    core_->monitor().check_writer_jitter();
    const auto * cmd = core_->next_command();
    if (cmd == nullptr) {
      return;
    }
    command_msg_.header.stamp = node_->now();
    for (size_t i = 0; i < N; ++i) {
      command_msg_.position[i] = static_cast<double>(cmd->q_target[i]);
      command_msg_.velocity[i] = static_cast<double>(cmd->dq_target[i]);
      command_msg_.feed_forward_torque[i] = static_cast<double>(cmd->tau_ff[i]);
      command_msg_.stiffness[i] = static_cast<double>(cmd->kp[i]);
      command_msg_.damping[i] = static_cast<double>(cmd->kd[i]);
    }
    publisher_->publish(command_msg_);
    core_->monitor().check_writer_latency(start);
  }

  const EngineaiTopicsOptions options_;
  DriverCore<N, T> * core_{nullptr};
  rclcpp::Node::SharedPtr node_;
  JointCommand command_msg_;  // pre-sized in configure(): no allocation per cycle
  typename rclcpp::Publisher<JointCommand>::SharedPtr publisher_;
  typename rclcpp::Subscription<JointState>::SharedPtr state_subscription_;
  typename rclcpp::Subscription<ImuInfo>::SharedPtr imu_subscription_;
  typename rclcpp::Subscription<MotorDebug>::SharedPtr motor_debug_subscription_;
  TopicExecutor executor_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_HPP_
