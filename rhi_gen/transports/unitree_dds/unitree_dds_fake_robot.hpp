// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_FAKE_ROBOT_HPP_

// The robot's side of unitree_dds (unitree_sdk2 DDS, hg and go messages), for the fake robot: on
// the loopback interface (--network-interface changes it), it reads LowCmd_ on the driver's command
// topic (a frame with a wrong CRC is dropped, as the motor board drops it; a slot whose
// MotorCmd_.mode is 0 is passive) and writes LowState_ every step (500 Hz) with a valid CRC: the
// motors, the IMU (at rest, or the physics'), temperatures (and, hg, supply voltage and error
// codes), hg's mode_machine. `corrupt` sends frames whose CRC does not match, which the driver must
// drop. The SDK calls the command handler on its own thread: commands wait under a lock until the
// next step.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <unitree/robot/channel/channel_factory.hpp>
#include <unitree/robot/channel/channel_publisher.hpp>
#include <unitree/robot/channel/channel_subscriber.hpp>

#include "robot_hardware_interface/common/fake_robot.hpp"
#include "robot_hardware_interface/transport/unitree_dds.hpp"
#include "robot_hardware_interface/transport/unitree_dex3.hpp"
#include "robot_hardware_interface/transport/unitree_go.hpp"
#include "robot_hardware_interface/transport/unitree_hg.hpp"

namespace robot_hardware_interface
{
// What differs between the message families on the robot's side (overloads by message type).
struct UnitreeFakeFields
{
  // hg LowState_.mode_machine of the fake robot: 5 is the G1 29-DoF rev 1.0 (SDK_FACTS.md); the
  // driver only echoes it back.
  static constexpr uint8_t kHgModeMachine = 5;
  static constexpr float kHgSupplyVolts = 48.0F;

  static int16_t hg_celsius(double celsius)
  {
    return static_cast<int16_t>(std::lround(std::clamp(celsius, -32768.0, 32767.0)));
  }

  // The parts of a LowState_ that stay the same.
  static void init_state(::unitree_hg::msg::dds_::LowState_ & state)
  {
    state.mode_machine() = kHgModeMachine;
  }
  static void init_state(::unitree_go::msg::dds_::LowState_ & state)
  {
    state.head()[0] = unitree_go::kHead0;
    state.head()[1] = unitree_go::kHead1;
  }

  // Motor health, as each family's MotorState_ carries it.
  static void write_health(
    ::unitree_hg::msg::dds_::MotorState_ & motor, double celsius, uint32_t error_code)
  {
    motor.temperature()[0] = hg_celsius(celsius);  // winding
    motor.temperature()[1] = hg_celsius(celsius);  // housing
    motor.vol() = kHgSupplyVolts;
    motor.motorstate() = error_code;
  }
  static void write_health(
    ::unitree_go::msg::dds_::MotorState_ & motor, double celsius, uint32_t /*error_code*/)
  {
    motor.temperature() = static_cast<uint8_t>(std::lround(std::clamp(celsius, 0.0, 255.0)));
  }

  static constexpr bool carries_error_codes(const ::unitree_hg::msg::dds_::LowState_ *)
  {
    return true;
  }
  static constexpr bool carries_error_codes(const ::unitree_go::msg::dds_::LowState_ *)
  {
    return false;
  }
};

// The robot's own controller as the fake robot plays it under the arm SDK (authority
// upper_body): every motor held where it started, stiff and critically damped, and the arm SDK's
// command mixed in by its blend weight, tau = w tau_sdk + (1 - w) tau_own, which is again a PD law.
struct FakeBalanceController
{
  static constexpr double kStiffness = 400.0;  // per kg m^2 of the joint's inertia: about 3 Hz
  static constexpr double kDamping = 40.0;     // critical damping at that stiffness

  static FakeMotorCommand hold(const FakeJointSpec & joint)
  {
    const double inertia = joint.inertia > 0.0 ? joint.inertia : 1.0;
    return FakeMotorCommand{joint.initial_position, 0.0, 0.0, kStiffness * inertia,
      kDamping * inertia};
  }

  // w * sdk + (1 - w) * own, as one PD command: gains blend linearly, the targets by their gains.
  static FakeMotorCommand blend(
    double weight, const FakeMotorCommand & sdk, const FakeMotorCommand & own)
  {
    const double w = std::isfinite(weight) ? std::clamp(weight, 0.0, 1.0) : 0.0;
    FakeMotorCommand c;
    c.kp = w * sdk.kp + (1.0 - w) * own.kp;
    c.kd = w * sdk.kd + (1.0 - w) * own.kd;
    c.q = c.kp > 0.0 ? (w * sdk.kp * sdk.q + (1.0 - w) * own.kp * own.q) / c.kp : own.q;
    c.dq = c.kd > 0.0 ? (w * sdk.kd * sdk.dq + (1.0 - w) * own.kd * own.dq) / c.kd : 0.0;
    c.tau_ff = w * sdk.tau_ff + (1.0 - w) * own.tau_ff;
    return c;
  }
};

// A fake robot without hands on their own topics (the default `Hands` of UnitreeDdsFakeRobot).
template<size_t N>
struct UnitreeNoFakeHands
{
  using Options = typename UnitreeNoHands<N, float>::Options;
  static constexpr size_t kSlots = 0;

  explicit UnitreeNoFakeHands(const Options * /*options*/) {}
  void configure() {}
  void close() {}
  void take_commands(FakeRobotModel<N> & /*model*/) {}
  void publish(const FakeRobotModel<N> & /*model*/) {}
};

// The Dex3-1 hands' side (hands: dex3): HandCmd_ in per hand (a motor runs only when its mode
// byte carries its own id and status 1 without the timeout bit, as the hand's firmware addresses
// it; otherwise it is passive), HandState_ out per hand with 7 motors and 9 pressure sensors.
template<size_t N>
class UnitreeDex3FakeHands
{
  using HandCmd = unitree_dex3::HandCmd;
  using HandState = unitree_dex3::HandState;
  static constexpr size_t kMotors = unitree_dex3::kMotorsPerHand;
  static constexpr size_t kPressureSensors = 9;  // SENSOR_MAX of unitree_sdk2's g1_dex3_example

public:
  using Options = UnitreeDex3Options;
  static constexpr size_t kSlots = unitree_dex3::kHands * kMotors;

  explicit UnitreeDex3FakeHands(const Options * options)
  : options_(*options)
  {
  }

  // After ChannelFactory::Init.
  void configure()
  {
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      HandState & state = states_[side];
      state.motor_state().resize(kMotors);
      state.press_sensor_state().resize(kPressureSensors);
      state.imu_state().quaternion()[0] = 1.0F;
      state.power_v() = UnitreeFakeFields::kHgSupplyVolts;
      publishers_[side] = std::make_shared<::unitree::robot::ChannelPublisher<HandState>>(
        options_.state_topics[side]);
      publishers_[side]->InitChannel();
      subscribers_[side] = std::make_shared<::unitree::robot::ChannelSubscriber<HandCmd>>(
        options_.command_topics[side]);
      subscribers_[side]->InitChannel(
        [this, side](const void * message) {
          on_hand_cmd(side, *static_cast<const HandCmd *>(message));
        }, 1);
    }
  }

  // Before the members the SDK's threads use go.
  void close()
  {
    for (auto & subscriber : subscribers_) {
      if (subscriber) {
        subscriber->CloseChannel();
      }
    }
  }

  void take_commands(FakeRobotModel<N> & model)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_) {
      return;
    }
    pending_ = false;
    for (size_t k = 0; k < kSlots; ++k) {
      model.dynamics.command(unitree_dex3::kFirstSlot + k, commands_[k]);
    }
  }

  void publish(const FakeRobotModel<N> & model)
  {
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      auto & motors = states_[side].motor_state();
      for (size_t id = 0; id < kMotors; ++id) {
        const size_t slot = unitree_dex3::first_slot(side) + id;
        auto & motor = motors[id];
        motor.mode() = unitree_dex3::motor_mode(id);
        motor.q() = static_cast<float>(model.dynamics.position(slot));
        motor.dq() = static_cast<float>(model.dynamics.velocity(slot));
        motor.tau_est() = static_cast<float>(model.dynamics.effort(slot));
        UnitreeFakeFields::write_health(motor, model.temperature[slot], model.error_code[slot]);
      }
      publishers_[side]->Write(states_[side]);
    }
  }

private:
  void on_hand_cmd(size_t side, const HandCmd & cmd)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto & motors = cmd.motor_cmd();
    for (size_t id = 0; id < kMotors; ++id) {
      FakeMotorCommand & command = commands_[side * kMotors + id];
      if (id >= motors.size() || motors[id].mode() != unitree_dex3::motor_mode(id)) {
        command = FakeMotorCommand{};  // not addressed to this motor, or stopped: passive
        continue;
      }
      const auto & motor = motors[id];
      command = FakeMotorCommand{
        static_cast<double>(motor.q()), static_cast<double>(motor.dq()),
        static_cast<double>(motor.tau()), static_cast<double>(motor.kp()),
        static_cast<double>(motor.kd())};
    }
    pending_ = true;
  }

  const Options options_;
  std::array<HandState, unitree_dex3::kHands> states_;  // loop thread (sized in configure())
  std::array<::unitree::robot::ChannelPublisherPtr<HandState>, unitree_dex3::kHands> publishers_;
  std::array<::unitree::robot::ChannelSubscriberPtr<HandCmd>, unitree_dex3::kHands> subscribers_;
  std::mutex mutex_;  // commands_, pending_: the SDK's threads and the loop
  std::array<FakeMotorCommand, kSlots> commands_{};
  bool pending_{false};
};

template<size_t N, typename Family, typename Hands = UnitreeNoFakeHands<N>>
class UnitreeDdsFakeRobot final : public FakeRobotTransport<N>
{
  using LowCmd = typename Family::LowCmd;
  using LowState = typename Family::LowState;
  static_assert(N <= Family::kMotorSlots + Hands::kSlots, "more motors than LowState_ slots");
  static constexpr size_t kBodySlots = N < Family::kMotorSlots ? N : Family::kMotorSlots;

public:
  // `arm_sdk`: authority upper_body (the driver speaks the arm SDK, the fake robot also plays the
  // robot's balance controller), nullptr: the driver commands every motor on lowcmd_topic.
  // `hands`: the options of `Hands` (nullptr without hands).
  explicit UnitreeDdsFakeRobot(
    const UnitreeDdsOptions & options, const UnitreeArmSdkOptions * arm_sdk = nullptr,
    const typename Hands::Options * hands = nullptr)
  : options_(options), arm_sdk_(arm_sdk), hands_(hands)
  {
  }

  // The SDK's thread may be in on_low_cmd(): close the channel (which waits for it) before the
  // members it uses go.
  ~UnitreeDdsFakeRobot() override
  {
    if (subscriber_) {
      subscriber_->CloseChannel();
    }
    hands_.close();
  }

  const char * name() const override {return "unitree_dds";}
  const char * network_interface() const override {return network_interface_.c_str();}
  bool set_network_interface(const char * name) override
  {
    network_interface_ = name;
    return true;
  }
  bool carries_temperatures() const override {return true;}
  bool carries_error_codes() const override
  {
    return UnitreeFakeFields::carries_error_codes(static_cast<const LowState *>(nullptr));
  }

  void configure(const rclcpp::Node::SharedPtr & node, FakeRobotModel<N> & model) override
  {
    if (arm_sdk_ != nullptr) {
      // The robot's own controller holds everything until the arm SDK's weight says otherwise.
      std::lock_guard<std::mutex> lock(mutex_);
      const FakeJointSpec * joints = model.dynamics.joints();
      for (size_t k = 0; k < model.dynamics.joint_count(); ++k) {
        if (joints[k].slot < kBodySlots) {
          holds_[joints[k].slot] = FakeBalanceController::hold(joints[k]);
        }
      }
      commands_ = holds_;
      pending_ = true;
    }
    if (options_.release_motion_control) {
      RCLCPP_WARN(
        node->get_logger(), "transport_options.release_motion_control is true: the driver asks "
        "the motion switcher service to release the built-in controller, which this fake robot "
        "does not answer, so its activation fails (set it to false to use the fake robot)");
    }
    state_ = LowState{};
    UnitreeFakeFields::init_state(state_);
    auto & imu = state_.imu_state();
    imu.quaternion()[0] = 1.0F;          // w, x, y, z: at rest, level
    imu.accelerometer()[2] = static_cast<float>(kStandardGravity);
    ::unitree::robot::ChannelFactory::Instance()->Init(options_.domain_id, network_interface_);
    publisher_ = std::make_shared<::unitree::robot::ChannelPublisher<LowState>>(
      options_.lowstate_topic);
    publisher_->InitChannel();
    subscriber_ = std::make_shared<::unitree::robot::ChannelSubscriber<LowCmd>>(
      arm_sdk_ != nullptr ? arm_sdk_->topic : options_.lowcmd_topic);
    subscriber_->InitChannel(
      [this](const void * message) {on_low_cmd(*static_cast<const LowCmd *>(message));}, 1);
    hands_.configure();
  }

  void take_commands(FakeRobotModel<N> & model) override
  {
    hands_.take_commands(model);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pending_) {
      return;
    }
    pending_ = false;
    for (size_t slot = 0; slot < kBodySlots; ++slot) {
      model.dynamics.command(slot, commands_[slot]);
    }
  }

  void placed(size_t slot, double q) override
  {
    if (arm_sdk_ == nullptr || slot >= kBodySlots) {
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    holds_[slot].q = q;  // the robot's controller keeps it where it was put
    commands_[slot] = holds_[slot];
    pending_ = true;
  }

  void publish(const FakeRobotModel<N> & model) override
  {
    const auto & joints = model.dynamics;
    for (size_t slot = 0; slot < kBodySlots; ++slot) {
      auto & motor = state_.motor_state()[slot];
      motor.q() = static_cast<float>(joints.position(slot));
      motor.dq() = static_cast<float>(joints.velocity(slot));
      motor.tau_est() = static_cast<float>(joints.effort(slot));
      UnitreeFakeFields::write_health(motor, model.temperature[slot], model.error_code[slot]);
    }
    auto & imu = state_.imu_state();  // the model's: at rest, or the physics'
    const std::array<double, 3> rpy = model.imu.rpy();
    for (size_t i = 0; i < 4; ++i) {
      imu.quaternion()[i] = static_cast<float>(model.imu.orientation[i]);  // w, x, y, z
    }
    for (size_t i = 0; i < 3; ++i) {
      imu.gyroscope()[i] = static_cast<float>(model.imu.angular_velocity[i]);
      imu.accelerometer()[i] = static_cast<float>(model.imu.linear_acceleration[i]);
      imu.rpy()[i] = static_cast<float>(rpy[i]);
    }
    state_.tick() = static_cast<uint32_t>(model.steps * 2U);  // ms at 500 Hz
    state_.crc() = Family::state_crc(state_) ^ (model.faults.corrupt ? 1U : 0U);
    publisher_->Write(state_);
    hands_.publish(model);
  }

  // Commands dropped for a wrong CRC (tests).
  uint64_t bad_crc_commands() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return bad_crc_commands_;
  }

private:
  // The SDK's thread: a LowCmd_ with a valid CRC becomes every motor's next command.
  void on_low_cmd(const LowCmd & cmd)
  {
    const bool valid = cmd.crc() == Family::command_crc(cmd);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!valid) {
      ++bad_crc_commands_;
      return;
    }
    const double weight = arm_sdk_ != nullptr ?
      static_cast<double>(cmd.motor_cmd()[arm_sdk_->weight_slot].q()) : 1.0;
    for (size_t slot = 0; slot < kBodySlots; ++slot) {
      const auto & motor = cmd.motor_cmd()[slot];
      const FakeMotorCommand sdk{
        static_cast<double>(motor.q()), static_cast<double>(motor.dq()),
        static_cast<double>(motor.tau()), static_cast<double>(motor.kp()),
        static_cast<double>(motor.kd())};
      if (arm_sdk_ == nullptr) {
        commands_[slot] = motor.mode() == 0U ? FakeMotorCommand{} : sdk;  // disabled: passive
      } else {  // the arm SDK's slots blended in; the others (the legs) the robot's own
        commands_[slot] = motor.mode() == 0U ? holds_[slot] :
          FakeBalanceController::blend(weight, sdk, holds_[slot]);
      }
    }
    pending_ = true;
  }

  const UnitreeDdsOptions options_;
  const UnitreeArmSdkOptions * const arm_sdk_;  // nullptr: no balance controller to play
  Hands hands_;  // the hands on their own topics (none by default)
  std::string network_interface_{"lo"};
  LowState state_;  // the constant parts filled once: no allocation per step
  ::unitree::robot::ChannelPublisherPtr<LowState> publisher_;
  ::unitree::robot::ChannelSubscriberPtr<LowCmd> subscriber_;
  // commands_, holds_, pending_, bad_crc_commands_: SDK thread and loop
  mutable std::mutex mutex_;
  std::array<FakeMotorCommand, kBodySlots> commands_{};
  std::array<FakeMotorCommand, kBodySlots> holds_{};  // arm SDK: the robot's own controller
  bool pending_{false};
  uint64_t bad_crc_commands_{0};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_FAKE_ROBOT_HPP_
