// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_FAKE_ROBOT_HPP_

// The robot's side of generic_topics (sensor_msgs), for the fake robot: it takes the driver's
// JointState commands (entries by name: position, velocity and effort targets, no gains) and
// publishes every joint's JointState and a sensor_msgs/Imu (at rest, or the physics') every step,
// on the driver's topics with the driver's QoS. The commands carry no gains, so each joint is its
// own servo, as the bridge or simulator behind such topics is: kp = 2500 I, kd = 100 I + 10 b
// (critically damped at 50 rad/s, and stiff against the joint's own friction b); a
// velocity-commanded joint (a wheel) damping only. `corrupt` publishes a position array one entry
// short, which the driver must drop.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <sensor_msgs/msg/joint_state.hpp>

#include "robot_hardware_interface/common/fake_robot.hpp"
#include "robot_hardware_interface/transport/generic_topics.hpp"

namespace robot_hardware_interface
{

template<size_t N>
class GenericTopicsFakeRobot final : public FakeRobotTransport<N>
{
  using JointState = sensor_msgs::msg::JointState;
  using Imu = sensor_msgs::msg::Imu;
  static constexpr size_t kNoJoint = std::numeric_limits<size_t>::max();
  static constexpr double kServoStiffness = 2500.0;  // per kg m^2 of the joint's inertia
  static constexpr double kServoDamping = 100.0;
  static constexpr double kFrictionDamping = 10.0;  // per N m s / rad of the joint's own damping

public:
  explicit GenericTopicsFakeRobot(const GenericTopicsOptions & options)
  : options_(options)
  {
  }

  const char * name() const override {return "generic_topics";}

  void configure(const rclcpp::Node::SharedPtr & node, FakeRobotModel<N> & model) override
  {
    model_ = &model;
    node_ = node;
    const auto & joints = model.dynamics;
    const size_t count = joints.joint_count();
    state_.name.clear();
    for (size_t k = 0; k < count; ++k) {
      state_.name.emplace_back(joints.joints()[k].name);
    }
    state_.position.assign(count, 0.0);
    state_.velocity.assign(count, 0.0);
    state_.effort.assign(count, 0.0);
    short_state_ = state_;
    if (!short_state_.position.empty()) {
      short_state_.position.pop_back();
    }
    entry_joints_.assign(count, kNoJoint);
    imu_.orientation.w = 1.0;              // at rest, level
    imu_.linear_acceleration.z = kStandardGravity;
    const rclcpp::QoS qos = make_qos(options_.qos);
    state_publisher_ = node->create_publisher<JointState>(options_.state_topic, qos);
    imu_publisher_ = node->create_publisher<Imu>(options_.imu_topic, qos);
    command_subscription_ = node->create_subscription<JointState>(
      options_.command_topic, qos, [this](const JointState & msg) {on_command(msg);});
  }

  void publish(const FakeRobotModel<N> & model) override
  {
    const auto & joints = model.dynamics;
    const auto stamp = node_->now();
    for (size_t k = 0; k < joints.joint_count(); ++k) {
      const size_t slot = joints.joints()[k].slot;
      state_.position[k] = joints.position(slot);
      state_.velocity[k] = joints.velocity(slot);
      state_.effort[k] = joints.effort(slot);
    }
    JointState & msg = model.faults.corrupt ? short_state_ : state_;
    msg.header.stamp = stamp;
    state_publisher_->publish(msg);
    model.imu.to_ros(imu_.orientation, imu_.angular_velocity, imu_.linear_acceleration);
    imu_.header.stamp = stamp;
    imu_publisher_->publish(imu_);
  }

private:
  // The joint (index into the fake robot's table) entry `i` names: the one it named in the last
  // message when the name still agrees, else found by name; kNoJoint for an unknown name.
  size_t entry_joint(size_t i, const std::string & name)
  {
    const auto & joints = model_->dynamics;
    if (i < entry_joints_.size() && entry_joints_[i] != kNoJoint &&
      name == joints.joints()[entry_joints_[i]].name)
    {
      return entry_joints_[i];
    }
    for (size_t k = 0; k < joints.joint_count(); ++k) {
      if (name == joints.joints()[k].name) {
        if (i < entry_joints_.size()) {
          entry_joints_[i] = k;
        }
        return k;
      }
    }
    return kNoJoint;
  }

  // Entries by name; a message whose arrays disagree with its names is ignored whole.
  void on_command(const JointState & msg)
  {
    const size_t count = msg.name.size();
    if (msg.position.size() != count || (!msg.velocity.empty() && msg.velocity.size() != count) ||
      (!msg.effort.empty() && msg.effort.size() != count))
    {
      return;
    }
    for (size_t i = 0; i < count; ++i) {
      const size_t k = entry_joint(i, msg.name[i]);
      if (k == kNoJoint) {
        continue;
      }
      const FakeJointSpec & joint = model_->dynamics.joints()[k];
      FakeMotorCommand c;
      c.q = msg.position[i];
      c.dq = msg.velocity.empty() ? 0.0 : msg.velocity[i];
      c.tau_ff = msg.effort.empty() ? 0.0 : msg.effort[i];
      c.kp = joint.velocity_commanded ? 0.0 : kServoStiffness * joint.inertia;
      c.kd = kServoDamping * joint.inertia + kFrictionDamping * joint.damping;
      model_->dynamics.command(joint.slot, c);
    }
  }

  const GenericTopicsOptions options_;
  FakeRobotModel<N> * model_{nullptr};
  rclcpp::Node::SharedPtr node_;
  JointState state_;        // sized and named in configure(): no allocation per step
  JointState short_state_;  // what `corrupt` publishes
  Imu imu_;
  std::vector<size_t> entry_joints_;  // per command entry, the joint it named last time
  typename rclcpp::Publisher<JointState>::SharedPtr state_publisher_;
  typename rclcpp::Publisher<Imu>::SharedPtr imu_publisher_;
  typename rclcpp::Subscription<JointState>::SharedPtr command_subscription_;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__GENERIC_TOPICS_FAKE_ROBOT_HPP_
