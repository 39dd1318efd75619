// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DEX3_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DEX3_HPP_

// The G1's Dex3-1 hands (vendor YAML hands: dex3) beside the body, on the body's DDS participant:
// one HandCmd_ per hand out on the body's writer thread, one HandState_ per hand in on the SDK's
// listener threads (no CRC in either). The hand motors are joints of the body's driver in the
// motor slots after the 35 of a LowCmd_ (left hand 35..41, right 42..48), so the body's safety
// core (safe start, stale hold, non-finite guard, clamps) is theirs too. A hand's state reaches
// read() through the body's state frame: each hand hands its newest frame to the body's listener,
// which merges both into every body frame, and the state is as old as its oldest stream.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <memory>

#include <rclcpp/logging.hpp>
#include <unitree/idl/hg/HandCmd_.hpp>
#include <unitree/idl/hg/HandState_.hpp>
#include <unitree/robot/channel/channel_publisher.hpp>
#include <unitree/robot/channel/channel_subscriber.hpp>

#include "robot_hardware_interface/common/data_buffer.hpp"
#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"

namespace robot_hardware_interface
{

// transport_options of the vendor YAML for hands: dex3 (index 0 left, 1 right).
struct UnitreeDex3Options
{
  std::array<const char *, 2> command_topics;
  std::array<const char *, 2> state_topics;
};

namespace unitree_dex3
{

using HandCmd = ::unitree_hg::msg::dds_::HandCmd_;
using HandState = ::unitree_hg::msg::dds_::HandState_;

constexpr size_t kHands = 2;
constexpr size_t kMotorsPerHand = 7;  // thumb_0..2, middle_0..1, index_0..1
constexpr size_t kFirstSlot = 35;     // the first slot after a hg LowCmd_'s
constexpr const char * kSideNames[kHands] = {"left", "right"};

// MotorCmd_.mode of a hand motor: id (bits 0..3) | status (bits 4..6) << 4 | timeout (bit 7) << 7,
// as unitree_sdk2's g1_dex3_example.cpp packs it. Status 1 runs the motor; the timeout bit stays 0.
constexpr uint8_t kStatusRun = 0x01;
constexpr uint8_t motor_mode(size_t id)
{
  return static_cast<uint8_t>((id & 0x0FU) | (kStatusRun << 4U));
}

// The first driver slot of hand `side`.
constexpr size_t first_slot(size_t side) {return kFirstSlot + side * kMotorsPerHand;}

}  // namespace unitree_dex3

template<size_t N, typename T>
class UnitreeDex3Hands
{
public:
  using Options = UnitreeDex3Options;
  static constexpr size_t kSlots = unitree_dex3::kHands * unitree_dex3::kMotorsPerHand;

private:
  static_assert(
    N == unitree_dex3::kFirstSlot + unitree_dex3::kHands * unitree_dex3::kMotorsPerHand,
    "hands: dex3 puts 14 hand motors after the 35 LowCmd_ slots");

  using HandCmd = unitree_dex3::HandCmd;
  using HandState = unitree_dex3::HandState;
  static constexpr size_t kMotors = unitree_dex3::kMotorsPerHand;
  static constexpr int64_t kStateQueueLength = 1;  // only the newest HandState_ matters

public:
  // One hand's newest valid state, handed from its listener to the body's.
  struct Frame
  {
    std::array<T, kMotors> q{};
    std::array<T, kMotors> dq{};
    std::array<T, kMotors> tau{};
    std::array<double, kMotors> temperature{};
    std::array<double, kMotors> voltage{};
    std::array<double, kMotors> error_code{};
    int64_t time_ns{0};       // steady time it was received
    uint64_t activation{0};   // the activation it belongs to (start() counts them)
  };

  explicit UnitreeDex3Hands(const UnitreeDex3Options * options)
  : options_(*options)
  {
  }

  // on_configure, after the body's ChannelFactory::Init: the hands' channels on the same
  // participant, and each HandCmd_ sized and addressed once (the writer only fills in numbers).
  void configure(DriverCore<N, T> & core)
  {
    core_ = &core;
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      HandCmd & cmd = commands_[side];
      cmd = HandCmd{};
      cmd.motor_cmd().resize(kMotors);
      for (size_t id = 0; id < kMotors; ++id) {
        cmd.motor_cmd()[id].mode() = unitree_dex3::motor_mode(id);
      }
      publishers_[side] = std::make_shared<::unitree::robot::ChannelPublisher<HandCmd>>(
        options_.command_topics[side]);
      publishers_[side]->InitChannel();
      subscribers_[side] = std::make_shared<::unitree::robot::ChannelSubscriber<HandState>>(
        options_.state_topics[side]);
      subscribers_[side]->InitChannel(
        [this, side](const void * message) {
          on_hand_state(side, *static_cast<const HandState *>(message));
        }, kStateQueueLength);
      RCLCPP_INFO(
        core.logger(), "Dex3-1 %s hand: publishing %s, subscribed to %s (slots %zu..%zu)",
        unitree_dex3::kSideNames[side], options_.command_topics[side], options_.state_topics[side],
        unitree_dex3::first_slot(side), unitree_dex3::first_slot(side) + kMotors - 1);
    }
  }

  // on_activate, before the writer starts: both hands must report again before the first state.
  void start() {activation_.fetch_add(1, std::memory_order_acq_rel);}

  void shutdown()
  {
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      if (subscribers_[side]) {
        subscribers_[side]->CloseChannel();
      }
      if (publishers_[side]) {
        publishers_[side]->CloseChannel();
      }
    }
  }

  // Body listener thread, while it parses a LowState_: each hand's newest frame of this
  // activation into the state (and the health frame when `health` is not nullptr). False while a
  // hand has not reported in this activation; `oldest_ns` becomes the older of itself and the
  // hands' frame times. Counts the hands' rejected frames into the body's invalid states.
  bool merge(
    typename DriverCore<N, T>::State & state, MotorHealthFrame<N> * health, int64_t & oldest_ns)
  {
    for (uint64_t rejected = rejected_.exchange(0, std::memory_order_relaxed); rejected > 0;
      --rejected)
    {
      core_->reject_state();
    }
    const uint64_t activation = activation_.load(std::memory_order_acquire);
    bool complete = true;
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      const Frame * frame = frames_[side].get_data();
      if (frame == nullptr || frame->activation != activation) {
        complete = false;
        continue;
      }
      const size_t first = unitree_dex3::first_slot(side);
      for (size_t id = 0; id < kMotors; ++id) {
        state.q[first + id] = frame->q[id];
        state.dq[first + id] = frame->dq[id];
        state.tau[first + id] = frame->tau[id];
        if (health != nullptr) {
          health->temperature[first + id] = frame->temperature[id];
          health->voltage[first + id] = frame->voltage[id];
          health->error_code[first + id] = frame->error_code[id];
        }
      }
      oldest_ns = std::min(oldest_ns, frame->time_ns);
    }
    return complete;
  }

  // Writer thread, with the frame the body sends: one HandCmd_ per hand.
  void write(const typename DriverCore<N, T>::Command & cmd)
  {
    for (size_t side = 0; side < unitree_dex3::kHands; ++side) {
      const size_t first = unitree_dex3::first_slot(side);
      auto & motors = commands_[side].motor_cmd();
      for (size_t id = 0; id < kMotors; ++id) {
        auto & motor = motors[id];
        motor.q() = static_cast<float>(cmd.q_target[first + id]);
        motor.dq() = static_cast<float>(cmd.dq_target[first + id]);
        motor.tau() = static_cast<float>(cmd.tau_ff[first + id]);
        motor.kp() = static_cast<float>(cmd.kp[first + id]);
        motor.kd() = static_cast<float>(cmd.kd[first + id]);
      }
      publishers_[side]->Write(commands_[side]);
    }
  }

private:
  // A hand's listener thread: every HandState_. A frame with fewer than 7 motors or a non-finite
  // value is dropped whole (and counted by the body's listener).
  void on_hand_state(size_t side, const HandState & msg)
  {
    const auto start = std::chrono::steady_clock::now();
    const auto & motors = msg.motor_state();
    const char * problem = motors.size() < kMotors ? "fewer than 7 motors" : nullptr;
    for (size_t id = 0; problem == nullptr && id < kMotors; ++id) {
      if (!all_finite(motors[id].q(), motors[id].dq(), motors[id].tau_est())) {
        problem = "a non-finite value";
      }
    }
    if (problem != nullptr) {
      rejected_.fetch_add(1, std::memory_order_relaxed);
      RCLCPP_WARN_THROTTLE(
        core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "dropped Dex3-1 %s hand state: %s", unitree_dex3::kSideNames[side], problem);
      return;
    }
    Frame & frame = caches_[side];
    for (size_t id = 0; id < kMotors; ++id) {
      const auto & motor = motors[id];
      frame.q[id] = static_cast<T>(motor.q());
      frame.dq[id] = static_cast<T>(motor.dq());
      frame.tau[id] = static_cast<T>(motor.tau_est());
      frame.temperature[id] = static_cast<double>(motor.temperature()[0]);
      frame.voltage[id] = static_cast<double>(motor.vol());
      frame.error_code[id] = static_cast<double>(motor.motorstate());
    }
    frame.time_ns = steady_ns(start);
    frame.activation = activation_.load(std::memory_order_acquire);
    frames_[side].set_data(frame);
  }

  const UnitreeDex3Options options_;
  DriverCore<N, T> * core_{nullptr};
  std::array<HandCmd, unitree_dex3::kHands> commands_;  // writer thread (sized in configure())
  std::array<::unitree::robot::ChannelPublisherPtr<HandCmd>, unitree_dex3::kHands> publishers_;
  std::array<::unitree::robot::ChannelSubscriberPtr<HandState>, unitree_dex3::kHands>
  subscribers_;
  std::array<Frame, unitree_dex3::kHands> caches_{};  // each hand's listener: its parsing buffer
  // each hand's listener -> the body's listener
  std::array<DataBuffer<Frame, Producers::kOne>, unitree_dex3::kHands> frames_;
  std::atomic<uint64_t> activation_{0};  // start() -> every listener
  std::atomic<uint64_t> rejected_{0};    // the hands' listeners -> the body's listener
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DEX3_HPP_
