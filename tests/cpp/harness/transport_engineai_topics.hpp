// Fake robot side of the engineai_topics transport (interface_protocol): JointState arrays
// indexed by SDK slot, MotorDebug (motor temperatures, same index; with the EngineAI native SDK's
// release also voltage, error_code and offline) with every state, ImuInfo, JointCommand arrays out.
// Which release it is built against is said by robot_data.hpp (RHI_ENGINEAI_NATIVE_SDK) and checked
// here against the message itself; the members of the other release are never compiled.
#pragma once

#include <limits>
#include <type_traits>
#include <utility>

#include <interface_protocol/msg/imu_info.hpp>
#include <interface_protocol/msg/joint_command.hpp>
#include <interface_protocol/msg/joint_state.hpp>
#include <interface_protocol/msg/motor_debug.hpp>

#include "transport_ros_common.hpp"

namespace rhi_test {

// The harness's own test of what the message has (not the driver's trait): tau_cmd is
// engineai_ros2_workspace's, error_code the native SDK's.
template <typename Debug, typename = void>
struct HasTauCmd : std::false_type {};
template <typename Debug>
struct HasTauCmd<Debug, std::void_t<decltype(std::declval<Debug&>().tau_cmd)>> : std::true_type {};
template <typename Debug, typename = void>
struct HasErrorCode : std::false_type {};
template <typename Debug>
struct HasErrorCode<Debug, std::void_t<decltype(std::declval<Debug&>().error_code)>> : std::true_type {};

class Transport : public RosTransportBase {
public:
  using StateMsg = interface_protocol::msg::JointState;
  using CommandMsg = interface_protocol::msg::JointCommand;
  using ImuMsg = interface_protocol::msg::ImuInfo;
  using DebugMsg = interface_protocol::msg::MotorDebug;
  static constexpr const char* kName = "engineai_topics";
  static constexpr bool kHasGains = true;
  static constexpr bool kNativeSdk = HasErrorCode<DebugMsg>::value;
#if defined(RHI_ENGINEAI_NATIVE_SDK)
  static_assert(kNativeSdk && !HasTauCmd<DebugMsg>::value, "built for the native SDK's MotorDebug, got another");
#else
  static_assert(!kNativeSdk && HasTauCmd<DebugMsg>::value, "built for engineai_ros2_workspace's MotorDebug");
#endif

  Transport() {
    state_msg_.position.assign(N, 0.0);
    state_msg_.velocity.assign(N, 0.0);
    state_msg_.torque.assign(N, 0.0);
    size_debug(debug_msg_);
  }

  void prepare_state(const StateFrame& f) {
    state_msg_.position.resize(N);
    state_msg_.velocity.resize(N);
    state_msg_.torque.resize(N);
    for (size_t i = 0; i < N; ++i) {
      state_msg_.position[i] = f.q[i];
      state_msg_.velocity[i] = f.dq[i];
      state_msg_.torque[i] = f.tau[i];
    }
    fill_debug(f, debug_msg_);
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
      bad.motor_temperature[kJoints[0].slot] = std::numeric_limits<Celsius>::quiet_NaN();
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
  using Celsius = typename decltype(DebugMsg::motor_temperature)::value_type;

  template <typename Debug>
  static void size_debug(Debug& d) {
    if constexpr (HasTauCmd<Debug>::value) {
      d.tau_cmd.assign(N, 0.0);
    }
    d.mos_temperature.assign(N, 0.0F);
    d.motor_temperature.assign(N, 0.0F);
    if constexpr (HasErrorCode<Debug>::value) {
      d.voltage.assign(N, 0.0F);
      d.current.assign(N, 0.0F);
      d.error_code.assign(N, 0);
      d.offline.assign(N, 0U);
      d.enable.assign(N, 1U);
    }
  }

  // The frame's motor health (integers and quarter volts: exact as float32 too).
  template <typename Debug>
  static void fill_debug(const StateFrame& f, Debug& d) {
    for (size_t i = 0; i < N; ++i) {
      d.motor_temperature[i] = static_cast<Celsius>(f.temperature[i]);
      d.mos_temperature[i] = static_cast<Celsius>(20.0 + static_cast<double>(i));  // not exported
      if constexpr (HasErrorCode<Debug>::value) {
        d.voltage[i] = static_cast<float>(f.voltage[i]);
        d.current[i] = 1.5F;  // not exported
        d.error_code[i] = static_cast<int32_t>(static_cast<uint32_t>(f.error_code[i]));
        d.offline[i] = f.offline[i] ? 1U : 0U;
      }
    }
  }

  StateMsg state_msg_;
  DebugMsg debug_msg_;
  ImuMsg imu_info_;
  CommandMsg cmd_msg_;
};

}  // namespace rhi_test
