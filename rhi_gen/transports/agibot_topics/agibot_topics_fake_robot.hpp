// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_FAKE_ROBOT_HPP_

// The robot's side of agibot_topics (AimDK HAL), for the fake robot: per joint group it takes the
// JointCommandArray (entries matched by name, position as the fallback for an unnamed entry) and
// publishes the JointStateArray every step (1000 Hz, entries named, error codes where the message
// has them, DomainErrorState 0), and sensor_msgs/Imu (at rest, or the physics') every other step
// (500 Hz), on the driver's topics with the driver's QoS. With hands it takes the HandCommandArray
// (entries by index, position targets tracked by the hand's own position loop, kHandStiffness /
// kHandDamping) and publishes the HandStateArray every step, entries unnamed and effort 0 as the
// X2's HAL reports them. `corrupt` puts a NaN in every group's first position (and the left
// hand's), which the driver must drop.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <aimdk_msgs/msg/hand_command_array.hpp>
#include <aimdk_msgs/msg/hand_state_array.hpp>
#include <aimdk_msgs/msg/joint_command_array.hpp>
#include <aimdk_msgs/msg/joint_state_array.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>
#include <sensor_msgs/msg/imu.hpp>

#include "robot_hardware_interface/common/fake_robot.hpp"
#include "robot_hardware_interface/transport/agibot_topics.hpp"

namespace robot_hardware_interface
{

// A fake robot without AimDK's system-state services (the default `Control`).
struct AimdkNoFakeControl
{
  void configure(const rclcpp::Node::SharedPtr & /*node*/) {}
};

// `Control`: the robot's side of taking control (AimdkFakeSystemState for take_control: true).
template<size_t N, typename Control = AimdkNoFakeControl>
class AgibotTopicsFakeRobot final : public FakeRobotTransport<N>
{
  using CommandArray = aimdk_msgs::msg::JointCommandArray;
  using StateArray = aimdk_msgs::msg::JointStateArray;
  using HandCommands = aimdk_msgs::msg::HandCommandArray;
  using HandStates = aimdk_msgs::msg::HandStateArray;
  using Imu = sensor_msgs::msg::Imu;
  using JointStateEntry = typename decltype(StateArray::joints)::value_type;
  static constexpr uint64_t kImuEvery = 2;
  static constexpr size_t kNoSlot = std::numeric_limits<size_t>::max();
  // The hand's own position loop, which AgiBot does not document: stiff enough to follow a
  // controller's slow targets within a hundredth of a radian (it lags by about kd / kp = 10 ms),
  // damped well past critical for the light finger links.
  static constexpr double kHandStiffness = 50.0;  // [N m / rad]
  static constexpr double kHandDamping = 0.5;     // [N m s / rad]

  // hal/msg/JointState v1.0.0 ends with `uint16 error_code`; later AimDK versions drop it.
  template<typename Entry, typename = void>
  struct HasErrorCode : std::false_type {};
  template<typename Entry>
  struct HasErrorCode<Entry, std::void_t<decltype(std::declval<Entry &>().error_code)>>
    : std::true_type {};

public:
  explicit AgibotTopicsFakeRobot(const AgibotTopicsOptions & options)
  : options_(options), groups_(options.group_count)
  {
  }

  const char * name() const override {return "agibot_topics";}
  bool carries_error_codes() const override {return HasErrorCode<JointStateEntry>::value;}

  void configure(const rclcpp::Node::SharedPtr & node, FakeRobotModel<N> & model) override
  {
    model_ = &model;
    node_ = node;
    const rclcpp::QoS qos = make_qos(options_.qos);
    for (size_t g = 0; g < groups_.size(); ++g) {
      const AimdkJointGroup & spec = options_.groups[g];
      Group & group = groups_[g];
      group.spec = &spec;
      group.state.joints.resize(spec.size);
      for (size_t i = 0; i < spec.size; ++i) {
        group.state.joints[i].name = joint_name(spec.offset + i);
      }
      group.publisher = node->create_publisher<StateArray>(spec.state_topic, qos);
      group.subscription = node->create_subscription<CommandArray>(
        spec.command_topic, qos, [this, g](const CommandArray & msg) {on_command(g, msg);});
    }
    if (options_.hands != nullptr) {
      configure_hands(node, qos);
    }
    imu_.orientation.w = 1.0;              // at rest, level
    imu_.linear_acceleration.z = kStandardGravity;
    imu_publisher_ = node->create_publisher<Imu>(options_.imu_topic, qos);
    control_.configure(node);
  }

  void publish(const FakeRobotModel<N> & model) override
  {
    const auto & joints = model.dynamics;
    const auto stamp = node_->now();
    ++sequence_;
    for (Group & group : groups_) {
      StateArray & msg = group.state;
      msg.header.stamp = stamp;
      msg.header.sequence = sequence_;
      for (size_t i = 0; i < group.spec->size; ++i) {
        const size_t slot = group.spec->offset + i;
        auto & entry = msg.joints[i];
        entry.position = joints.position(slot);
        entry.velocity = joints.velocity(slot);
        entry.effort = joints.effort(slot);
        store_error_code(entry, model.error_code[slot]);
      }
      if (model.faults.corrupt && !msg.joints.empty()) {
        msg.joints[0].position = std::numeric_limits<double>::quiet_NaN();
      }
      group.publisher->publish(msg);
    }
    if (options_.hands != nullptr) {
      publish_hands(model, stamp);
    }
    if (model.steps % kImuEvery == 0) {
      model.imu.to_ros(imu_.orientation, imu_.angular_velocity, imu_.linear_acceleration);
      imu_.header.stamp = stamp;
      imu_publisher_->publish(imu_);
    }
  }

private:
  struct Group
  {
    const AimdkJointGroup * spec{nullptr};
    StateArray state;  // sized and named in configure(): no allocation per step
    typename rclcpp::Publisher<StateArray>::SharedPtr publisher;
    typename rclcpp::Subscription<CommandArray>::SharedPtr subscription;
  };

  template<typename Entry>
  static void store_error_code(Entry & entry, uint32_t code)
  {
    if constexpr (HasErrorCode<Entry>::value) {
      entry.error_code = static_cast<decltype(entry.error_code)>(code);
    } else {
      static_cast<void>(entry);
      static_cast<void>(code);
    }
  }

  // The joint the fake robot simulates on `slot`, "" for a slot no joint drives.
  const char * joint_name(size_t slot) const
  {
    const auto & joints = model_->dynamics;
    for (size_t k = 0; k < joints.joint_count(); ++k) {
      if (joints.joints()[k].slot == slot) {
        return joints.joints()[k].name;
      }
    }
    return "";
  }

  // The group slot an entry commands: its position when the name agrees (or is empty), else the
  // slot of the group whose joint has that name; kNoSlot for a name the group does not have.
  size_t entry_slot(const Group & group, size_t position, const std::string & name) const
  {
    const AimdkJointGroup & spec = *group.spec;
    if (position < spec.size &&
      (name.empty() || name == group.state.joints[position].name))
    {
      return spec.offset + position;
    }
    for (size_t i = 0; i < spec.size; ++i) {
      if (!name.empty() && name == group.state.joints[i].name) {
        return spec.offset + i;
      }
    }
    return kNoSlot;
  }

  void configure_hands(const rclcpp::Node::SharedPtr & node, const rclcpp::QoS & qos)
  {
    const AimdkHandsOptions & hands = *options_.hands;
    hand_state_.left_hand_type.value = hands.hand_type;
    hand_state_.right_hand_type.value = hands.hand_type;
    hand_state_.left_hands.resize(hands.axes);
    hand_state_.right_hands.resize(hands.axes);
    hand_publisher_ = node->create_publisher<HandStates>(hands.state_topic, qos);
    hand_subscription_ = node->create_subscription<HandCommands>(
      hands.command_topic, qos, [this](const HandCommands & msg) {on_hand_command(msg);});
  }

  template<typename Stamp>
  void publish_hands(const FakeRobotModel<N> & model, const Stamp & stamp)
  {
    const AimdkHandsOptions & hands = *options_.hands;
    const auto & joints = model.dynamics;
    hand_state_.header.stamp = stamp;
    hand_state_.header.sequence = sequence_;
    const auto fill = [&joints, &model](auto & entry, size_t slot) {
        entry.position = joints.position(slot);
        entry.velocity = joints.velocity(slot);
        entry.effort = 0.0;  // a motor current on the X2, "to be implemented" (AimDK docs)
        entry.faultcode = static_cast<int32_t>(model.error_code[slot]);
      };
    for (size_t i = 0; i < hands.axes; ++i) {
      fill(hand_state_.left_hands[i], hands.first_slot + i);
      fill(hand_state_.right_hands[i], hands.first_slot + hands.axes + i);
    }
    if (model.faults.corrupt && !hand_state_.left_hands.empty()) {
      hand_state_.left_hands[0].position = std::numeric_limits<double>::quiet_NaN();
    }
    hand_publisher_->publish(hand_state_);
  }

  // Both hands' targets, entries by index; a hand of another type or a short side is ignored (the
  // X2's HAL takes all axes of a hand at once).
  void on_hand_command(const HandCommands & msg)
  {
    const AimdkHandsOptions & hands = *options_.hands;
    const auto take = [this, &hands](uint8_t type, const auto & entries, size_t first) {
        if (type != hands.hand_type || entries.size() < hands.axes) {
          return;
        }
        for (size_t i = 0; i < hands.axes; ++i) {
          model_->dynamics.command(
            first + i,
            FakeMotorCommand{entries[i].position, 0.0, 0.0, kHandStiffness, kHandDamping});
        }
      };
    take(msg.left_hand_type.value, msg.left_hands, hands.first_slot);
    take(msg.right_hand_type.value, msg.right_hands, hands.first_slot + hands.axes);
  }

  void on_command(size_t index, const CommandArray & msg)
  {
    const Group & group = groups_[index];
    for (size_t i = 0; i < msg.joints.size(); ++i) {
      const auto & joint = msg.joints[i];
      const size_t slot = entry_slot(group, i, joint.name);
      if (slot != kNoSlot) {
        model_->dynamics.command(
          slot, FakeMotorCommand{joint.position, joint.velocity, joint.effort, joint.stiffness,
            joint.damping});
      }
    }
  }

  const AgibotTopicsOptions options_;
  FakeRobotModel<N> * model_{nullptr};
  rclcpp::Node::SharedPtr node_;
  std::vector<Group> groups_;  // sized at construction
  Imu imu_;
  typename rclcpp::Publisher<Imu>::SharedPtr imu_publisher_;
  uint32_t sequence_{0};
  HandStates hand_state_;  // sized in configure(): no allocation per step
  typename rclcpp::Publisher<HandStates>::SharedPtr hand_publisher_;
  typename rclcpp::Subscription<HandCommands>::SharedPtr hand_subscription_;
  Control control_;  // the services of taking control, if any
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_FAKE_ROBOT_HPP_
