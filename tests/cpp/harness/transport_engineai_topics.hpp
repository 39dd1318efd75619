// Fake robot side of the engineai_topics transport (interface_protocol): JointState arrays
// indexed by SDK slot, MotorDebug (motor temperatures, same index) with every state, ImuInfo,
// JointCommand arrays out.
#pragma once

#include <limits>

#include <interface_protocol/msg/imu_info.hpp>
#include <interface_protocol/msg/joint_command.hpp>
#include <interface_protocol/msg/joint_state.hpp>
#include <interface_protocol/msg/motor_debug.hpp>

#include "transport_ros_common.hpp"

namespace rhi_test {

class Transport : public RosTransportBase {
public:
  using StateMsg = interface_protocol::msg::JointState;
  using CommandMsg = interface_protocol::msg::JointCommand;
  using ImuMsg = interface_protocol::msg::ImuInfo;
  using DebugMsg = interface_protocol::msg::MotorDebug;
  static constexpr const char* kName = "engineai_topics";
  static constexpr bool kHasGains = true;

  Transport() {
    state_msg_.position.assign(N, 0.0);
    state_msg_.velocity.assign(N, 0.0);
    state_msg_.torque.assign(N, 0.0);
    debug_msg_.tau_cmd.assign(N, 0.0);
    debug_msg_.mos_temperature.assign(N, 0.0);
    debug_msg_.motor_temperature.assign(N, 0.0);
  }

  void prepare_state(const StateFrame& f) {
    state_msg_.position.resize(N);
    state_msg_.velocity.resize(N);
    state_msg_.torque.resize(N);
    for (size_t i = 0; i < N; ++i) {
      state_msg_.position[i] = f.q[i];
      state_msg_.velocity[i] = f.dq[i];
      state_msg_.torque[i] = f.tau[i];
      debug_msg_.motor_temperature[i] = f.temperature[i];
      debug_msg_.mos_temperature[i] = 20.0 + static_cast<double>(i);  // not exported
    }
    // ImuInfo: geometry_msgs quaternion x, y, z, w.
    imu_info_.quaternion.w = f.quat_wxyz[0];
    imu_info_.quaternion.x = f.quat_wxyz[1];
    imu_info_.quaternion.y = f.quat_wxyz[2];
    imu_info_.quaternion.z = f.quat_wxyz[3];
    imu_info_.angular_velocity.x = f.gyro[0];
    imu_info_.angular_velocity.y = f.gyro[1];
    imu_info_.angular_velocity.z = f.gyro[2];
    imu_info_.linear_acceleration.x = f.acc[0];
    imu_info_.linear_acceleration.y = f.acc[1];
    imu_info_.linear_acceleration.z = f.acc[2];
    imu_info_.rpy.x = 0.125;  // not exported; present as on the robot
  }
  size_t deliver_prepared() { return rhi_fake::ros::deliver<StateMsg>(kStateTopic, state_msg_); }
  // Motor temperatures travel in MotorDebug (50 Hz or more on the robot): deliver_state() sends one after
  // every state (the driver keeps one every 10 ms).
  static constexpr bool kHealthMessage = true;
  size_t deliver_prepared_health() { return rhi_fake::ros::deliver<DebugMsg>(kMotorDebugTopic, debug_msg_); }
  // A MotorDebug the driver must drop (the temperatures stay): one motor short, or a NaN.
  size_t deliver_bad_motor_debug(bool short_array) {
    DebugMsg bad = debug_msg_;
    if (short_array) {
      bad.motor_temperature.pop_back();
    } else {
      bad.motor_temperature[kJoints[0].slot] = std::numeric_limits<double>::quiet_NaN();
    }
    return rhi_fake::ros::deliver<DebugMsg>(kMotorDebugTopic, bad);
  }
  size_t deliver_state(const StateFrame& f) {
    prepare_state(f);
    const size_t reached = deliver_prepared();
    deliver_prepared_health();
    return reached;
  }
  size_t deliver_prepared_imu() { return rhi_fake::ros::deliver<ImuMsg>(kImuTopic, imu_info_); }
  size_t deliver_imu(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared_imu();
  }
  // A first frame that must not count as a valid state: arrays one motor short.
  size_t deliver_invalid_state(const StateFrame& f) {
    StateMsg bad;
    for (size_t i = 0; i + 1 < N; ++i) {
      bad.position.push_back(f.q[i]);
      bad.velocity.push_back(f.dq[i]);
      bad.torque.push_back(f.tau[i]);
    }
    return rhi_fake::ros::deliver<StateMsg>(kStateTopic, bad);
  }

  // One frame the driver must reject and count (health GPIO invalid_states): arrays one motor short.
  size_t deliver_corrupt_state(const StateFrame& f) { return deliver_invalid_state(f); }

  uint64_t sent_messages() const { return rhi_fake::ros::publish_count(kCommandTopic); }
  static constexpr size_t command_messages_per_cycle() { return 1; }
  bool command_names_ok() const { return true; }  // slots are positions: nothing to name

  bool last_command(CommandFrame& out) {
    if (!rhi_fake::ros::last_published<CommandMsg>(kCommandTopic, cmd_msg_)) {
      return false;
    }
    out.has_gains = true;
    out.present.fill(false);
    for (size_t i = 0; i < N; ++i) {
      if (i >= cmd_msg_.position.size() || i >= cmd_msg_.velocity.size() ||
          i >= cmd_msg_.feed_forward_torque.size() || i >= cmd_msg_.stiffness.size() ||
          i >= cmd_msg_.damping.size()) {
        continue;
      }
      out.q[i] = cmd_msg_.position[i];
      out.dq[i] = cmd_msg_.velocity[i];
      out.tau[i] = cmd_msg_.feed_forward_torque[i];
      out.kp[i] = cmd_msg_.stiffness[i];
      out.kd[i] = cmd_msg_.damping[i];
      out.present[i] = true;
    }
    return true;
  }
  // The last JointCommand the robot received (fetched again on every call).
  const CommandMsg& last_raw_command() {
    rhi_fake::ros::last_published<CommandMsg>(kCommandTopic, cmd_msg_);
    return cmd_msg_;
  }

private:
  StateMsg state_msg_;
  DebugMsg debug_msg_;
  ImuMsg imu_info_;
  CommandMsg cmd_msg_;
};

}  // namespace rhi_test
