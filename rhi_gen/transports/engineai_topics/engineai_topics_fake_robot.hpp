// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_FAKE_ROBOT_HPP_

// The robot's side of engineai_topics (EngineAI interface_protocol), for the fake robot: it takes
// JointCommand arrays indexed by motor slot (the PD law: position, velocity, stiffness, damping,
// feed_forward_torque; the direct `torque` field is not simulated) and publishes JointState (every
// step), ImuInfo (at rest, or the physics'; every step) and MotorDebug temperatures (every 10th
// step: 50 Hz at the robot's 500 Hz), on the driver's topics with the driver's QoS. `corrupt`
// publishes JointState arrays one motor short, which the driver must drop. MotorDebug is filled as
// far as the release of interface_protocol it is built against has the members
// (engineai_topics.hpp): with the native SDK's, also a 48 V supply, the `error` codes and the
// `offline` motors.

#include <array>
#include <cstddef>
#include <cstdint>

#include <interface_protocol/msg/imu_info.hpp>
#include <interface_protocol/msg/joint_command.hpp>
#include <interface_protocol/msg/joint_state.hpp>
#include <interface_protocol/msg/motor_debug.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>

#include "robot_hardware_interface/common/fake_robot.hpp"
#include "robot_hardware_interface/transport/engineai_topics.hpp"

namespace robot_hardware_interface
{

template<size_t N>
class EngineaiTopicsFakeRobot final : public FakeRobotTransport<N>
{
  using JointCommand = interface_protocol::msg::JointCommand;
  using JointState = interface_protocol::msg::JointState;
  using ImuInfo = interface_protocol::msg::ImuInfo;
  using MotorDebug = interface_protocol::msg::MotorDebug;
  static constexpr uint64_t kMotorDebugEvery = 10;
  static constexpr double kFakeSupplyVoltage = 48.0;  // [V], the native SDK's MotorDebug only

public:
  explicit EngineaiTopicsFakeRobot(const EngineaiTopicsOptions & options)
  : options_(options)
  {
  }

  const char * name() const override {return "engineai_topics";}
  bool carries_temperatures() const override {return true;}
  // The native SDK's MotorDebug only (engineai_topics.hpp: MotorDebugHasMotorHealth).
  bool carries_error_codes() const override {return MotorDebugHasMotorHealth<MotorDebug>::value;}
  bool carries_offline() const override {return MotorDebugHasMotorHealth<MotorDebug>::value;}

  void configure(const rclcpp::Node::SharedPtr & node, FakeRobotModel<N> & model) override
  {
    model_ = &model;
    node_ = node;
    state_.position.assign(N, 0.0);
    state_.velocity.assign(N, 0.0);
    state_.torque.assign(N, 0.0);
    short_state_.position.assign(N - 1, 0.0);
    short_state_.velocity.assign(N - 1, 0.0);
    short_state_.torque.assign(N - 1, 0.0);
    size_motor_debug(debug_);
    imu_.quaternion.w = 1.0;              // at rest, level
    imu_.linear_acceleration.z = kStandardGravity;
    const rclcpp::QoS qos = make_qos(options_.qos);
    state_publisher_ = node->create_publisher<JointState>(options_.state_topic, qos);
    imu_publisher_ = node->create_publisher<ImuInfo>(options_.imu_topic, qos);
    debug_publisher_ = node->create_publisher<MotorDebug>(options_.motor_debug_topic, qos);
    command_subscription_ = node->create_subscription<JointCommand>(
      options_.command_topic, qos, [this](const JointCommand & msg) {on_command(msg);});
  }

  void publish(const FakeRobotModel<N> & model) override
  {
    const auto & joints = model.dynamics;
    const auto stamp = node_->now();
    if (model.faults.corrupt) {
      short_state_.header.stamp = stamp;
      state_publisher_->publish(short_state_);
    } else {
      for (size_t i = 0; i < N; ++i) {
        state_.position[i] = joints.position(i);
        state_.velocity[i] = joints.velocity(i);
        state_.torque[i] = joints.effort(i);
      }
      state_.header.stamp = stamp;
      state_publisher_->publish(state_);
    }
    model.imu.to_ros(imu_.quaternion, imu_.angular_velocity, imu_.linear_acceleration);
    const std::array<double, 3> rpy = model.imu.rpy();
    imu_.rpy.x = rpy[0];
    imu_.rpy.y = rpy[1];
    imu_.rpy.z = rpy[2];
    imu_.header.stamp = stamp;
    imu_publisher_->publish(imu_);
    if (model.steps % kMotorDebugEvery == 0) {
      for (size_t i = 0; i < N; ++i) {
        debug_.motor_temperature[i] = static_cast<Celsius>(model.temperature[i]);
      }
      fill_native_health(model, debug_);
      debug_publisher_->publish(debug_);
    }
  }

private:
  // float64 in engineai_ros2_workspace, float32 in the native SDK.
  using Celsius = typename decltype(MotorDebug::motor_temperature)::value_type;

  // Every array of the message, one value per motor slot (configure(): no allocation per step).
  // A template on the message type, so the member the release lacks is never compiled.
  template<typename Debug>
  static void size_motor_debug(Debug & debug)
  {
    if constexpr (MotorDebugHasTauCmd<Debug>::value) {
      debug.tau_cmd.assign(N, 0.0);  // the driver commands through the PD law: no torque command
    }
    debug.mos_temperature.assign(N, static_cast<Celsius>(kFakeAmbientTemperature));
    debug.motor_temperature.assign(N, static_cast<Celsius>(kFakeAmbientTemperature));
    if constexpr (MotorDebugHasMotorHealth<Debug>::value) {
      using Volts = typename decltype(Debug::voltage)::value_type;
      debug.voltage.assign(N, static_cast<Volts>(kFakeSupplyVoltage));
      debug.current.assign(N, 0.0F);
      debug.error_code.assign(N, 0);
      debug.offline.assign(N, 0U);
      debug.enable.assign(N, 1U);
    }
  }

  // The native SDK's error codes (the vendor's bits, int32 on the wire) and offline flags.
  template<typename Debug>
  static void fill_native_health(const FakeRobotModel<N> & model, Debug & debug)
  {
    if constexpr (MotorDebugHasMotorHealth<Debug>::value) {
      for (size_t i = 0; i < N; ++i) {
        debug.error_code[i] = static_cast<int32_t>(model.error_code[i]);
        debug.offline[i] = model.offline[i] ? 1U : 0U;
      }
    } else {
      static_cast<void>(model);
      static_cast<void>(debug);
    }
  }

  // A JointCommand too short for every motor is ignored whole, as a malformed frame.
  void on_command(const JointCommand & msg)
  {
    if (msg.position.size() < N || msg.velocity.size() < N || msg.feed_forward_torque.size() < N ||
      msg.stiffness.size() < N || msg.damping.size() < N)
    {
      return;
    }
    for (size_t i = 0; i < N; ++i) {
      model_->dynamics.command(
        i, FakeMotorCommand{msg.position[i], msg.velocity[i], msg.feed_forward_torque[i],
          msg.stiffness[i], msg.damping[i]});
    }
  }

  const EngineaiTopicsOptions options_;
  FakeRobotModel<N> * model_{nullptr};
  rclcpp::Node::SharedPtr node_;
  JointState state_;        // pre-sized in configure(): no allocation per step
  JointState short_state_;  // what `corrupt` publishes
  ImuInfo imu_;
  MotorDebug debug_;
  typename rclcpp::Publisher<JointState>::SharedPtr state_publisher_;
  typename rclcpp::Publisher<ImuInfo>::SharedPtr imu_publisher_;
  typename rclcpp::Publisher<MotorDebug>::SharedPtr debug_publisher_;
  typename rclcpp::Subscription<JointCommand>::SharedPtr command_subscription_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__ENGINEAI_TOPICS_FAKE_ROBOT_HPP_
