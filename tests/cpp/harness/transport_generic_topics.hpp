// Fake robot side of the generic_topics transport (sensor_msgs/JointState by joint name,
// sensor_msgs/Imu; JointState commands out: position, velocity, effort only).
#pragma once

#include <limits>

#include <sensor_msgs/msg/joint_state.hpp>

#include "transport_ros_common.hpp"

namespace rhi_test {

class Transport : public RosTransportBase {
public:
  using StateMsg = sensor_msgs::msg::JointState;
  using CommandMsg = sensor_msgs::msg::JointState;
  static constexpr const char* kName = "generic_topics";
  static constexpr bool kHasGains = false;
  static constexpr char kUnknownJoint[] = "rhi_test_not_a_joint_of_this_robot";

  // Entries in reverse YAML order plus one joint the driver does not drive: the driver must
  // match by name, not by position.
  Transport() {
    for (size_t k = kJointCount; k-- > 0;) {
      state_msg_.name.push_back(kJoints[k].name);
      order_.push_back(kJoints[k].slot);
    }
    state_msg_.name.push_back(kUnknownJoint);
    state_msg_.position.assign(state_msg_.name.size(), 0.0);
    state_msg_.velocity.assign(state_msg_.name.size(), 0.0);
    state_msg_.effort.assign(state_msg_.name.size(), 0.0);
  }

  void prepare_state(const StateFrame& f) {
    for (size_t i = 0; i < order_.size(); ++i) {
      state_msg_.position[i] = f.q[order_[i]];
      state_msg_.velocity[i] = f.dq[order_[i]];
      state_msg_.effort[i] = f.tau[order_[i]];
    }
    const size_t u = order_.size();
    state_msg_.position[u] = 4242.0;
    state_msg_.velocity[u] = -4242.0;
    state_msg_.effort[u] = 4343.0;
    prepare_ros_imu(f);
  }
  size_t deliver_prepared() { return rhi_fake::ros::deliver<StateMsg>(kStateTopic, state_msg_); }
  size_t deliver_state(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared();
  }
  size_t deliver_prepared_imu() { return deliver_ros_imu(); }
  size_t deliver_imu(const StateFrame& f) {
    prepare_ros_imu(f);
    return deliver_ros_imu();
  }
  // A state that must not count as the first valid one: one driven joint missing (with a single
  // joint: a non-finite position).
  size_t deliver_invalid_state(const StateFrame& f) {
    prepare_state(f);
    StateMsg bad = state_msg_;
    if (kJointCount > 1) {
      bad.name.erase(bad.name.begin());
      bad.position.erase(bad.position.begin());
      bad.velocity.erase(bad.velocity.begin());
      bad.effort.erase(bad.effort.begin());
    } else {
      bad.position[0] = std::numeric_limits<double>::quiet_NaN();
    }
    return rhi_fake::ros::deliver<StateMsg>(kStateTopic, bad);
  }

  // One frame the driver must reject and count (health GPIO invalid_states): a non-finite position.
  size_t deliver_corrupt_state(const StateFrame& f) {
    prepare_state(f);
    StateMsg bad = state_msg_;
    bad.position[0] = std::numeric_limits<double>::quiet_NaN();
    return rhi_fake::ros::deliver<StateMsg>(kStateTopic, bad);
  }

  uint64_t sent_messages() const { return rhi_fake::ros::publish_count(kCommandTopic); }
  static constexpr size_t command_messages_per_cycle() { return 1; }

  bool last_command(CommandFrame& out) {
    if (!rhi_fake::ros::last_published<CommandMsg>(kCommandTopic, cmd_msg_)) {
      return false;
    }
    out.has_gains = false;
    out.present.fill(false);
    names_ok_ = cmd_msg_.name.size() == kJointCount && cmd_msg_.position.size() == kJointCount &&
                cmd_msg_.velocity.size() == kJointCount && cmd_msg_.effort.size() == kJointCount;
    for (size_t i = 0; i < cmd_msg_.name.size(); ++i) {
      const Joint* joint = nullptr;
      for (const Joint& j : kJoints) {
        if (cmd_msg_.name[i] == j.name) {
          joint = &j;
        }
      }
      if (joint == nullptr || out.present[joint->slot] || i >= cmd_msg_.position.size() ||
          i >= cmd_msg_.velocity.size() || i >= cmd_msg_.effort.size()) {
        names_ok_ = false;  // unknown or repeated joint name
        continue;
      }
      out.q[joint->slot] = cmd_msg_.position[i];
      out.dq[joint->slot] = cmd_msg_.velocity[i];
      out.tau[joint->slot] = cmd_msg_.effort[i];
      out.present[joint->slot] = true;
    }
    return true;
  }
  bool command_names_ok() const { return names_ok_; }

private:
  StateMsg state_msg_;
  CommandMsg cmd_msg_;
  std::vector<size_t> order_;
  bool names_ok_{true};
};

}  // namespace rhi_test
