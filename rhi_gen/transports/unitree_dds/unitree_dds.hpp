// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_HPP_

// Unitree robots over unitree_sdk2 DDS: LowCmd_ out on a recurrent SDK thread, LowState_ in on the
// SDK's listener thread, both CRC-protected. The message family (unitree_hg::Family for G1 and
// H1-2, unitree_go::Family for Go2, Go2-W, B2 and the original H1) is a template parameter.

#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <unitree/common/thread/recurrent_thread.hpp>
#include <unitree/common/thread/thread.hpp>
#include <unitree/robot/b2/motion_switcher/motion_switcher_client.hpp>
#include <unitree/robot/channel/channel_factory.hpp>
#include <unitree/robot/channel/channel_publisher.hpp>
#include <unitree/robot/channel/channel_subscriber.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/system_driver.hpp"
#include "robot_hardware_interface/transport/unitree_arm_sdk.hpp"

namespace robot_hardware_interface
{

// transport_options of the vendor YAML.
struct UnitreeDdsOptions
{
  int32_t domain_id;
  const char * lowcmd_topic;
  const char * lowstate_topic;
  uint8_t mode_pr;               // hg LowCmd_.mode_pr: 0 = PR (series pitch/roll), 1 = AB
  const uint8_t * motor_modes;   // go: MotorCmd_.mode of every slot (0x01 servo, 0x0A strong)
  bool release_motion_control;  // release the built-in motion controller before commanding
  bool verify_state_crc;        // drop LowState_ frames whose crc does not match
};

// A robot without hands that travel on their own topics (the default `Hands` of the transport).
template<size_t N, typename T>
struct UnitreeNoHands
{
  struct Options {};
  static constexpr size_t kSlots = 0;

  explicit UnitreeNoHands(const Options * /*options*/) {}
  void configure(DriverCore<N, T> & /*core*/) {}
  void start() {}
  void shutdown() {}
  bool merge(
    typename DriverCore<N, T>::State & /*state*/, MotorHealthFrame<N> * /*health*/,
    int64_t & /*oldest_ns*/)
  {
    return true;
  }
  void write(const typename DriverCore<N, T>::Command & /*cmd*/) {}
};

// `Hands`: the hands on their own topics after the LowCmd_ slots (UnitreeDex3Hands), if any.
template<size_t N, typename T, typename Family, typename Hands = UnitreeNoHands<N, T>>
class UnitreeDdsTransport final : public DriverTransport<N, T>
{
  using LowCmd = typename Family::LowCmd;
  using LowState = typename Family::LowState;
  static_assert(N <= Family::kMotorSlots + Hands::kSlots, "more motors than LowCmd_ slots");

  static constexpr int64_t kStateQueueLength = 1;  // only the newest LowState_ matters

public:
  // `arm_sdk`: authority upper_body (the arm SDK), nullptr: the whole robot on lowcmd_topic.
  // `hands`: the options of `Hands` (nullptr without hands).
  explicit UnitreeDdsTransport(
    const UnitreeDdsOptions & options, const UnitreeArmSdkOptions * arm_sdk = nullptr,
    const typename Hands::Options * hands = nullptr)
  : options_(options), arm_sdk_(arm_sdk), hands_(hands)
  {
  }

  const char * name() const override {return "unitree_dds";}
  uint8_t motor_health() const override {return Family::kMotorHealth;}

  bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & /*node*/) override
  {
    core_ = &core;
    const std::string & network_interface = core.parameters().network_interface;
    // One DDS participant per process, bound to the robot's network interface.
    ::unitree::robot::ChannelFactory::Instance()->Init(options_.domain_id, network_interface);
    // The LowCmd_ / LowState_ slots: the mapped ones before the hands' (which travel on their own).
    body_mapped_.clear();
    body_commanded_.clear();
    for (const size_t slot : core.slots().mapped_slots()) {
      if (slot < Family::kMotorSlots) {
        body_mapped_.push_back(slot);
      }
    }
    for (const size_t slot : core.slots().commanded_slots()) {
      if (slot < Family::kMotorSlots) {
        body_commanded_.push_back(slot);
      }
    }
    // The command message is reused for every send: fill the constant parts once. Only commanded
    // slots are enabled: under the arm SDK the legs' slots stay all zero.
    Family::init_command(low_cmd_, body_commanded_, options_.mode_pr, options_.motor_modes);
    const char * command_topic = arm_sdk_ != nullptr ? arm_sdk_->topic : options_.lowcmd_topic;
    if (arm_sdk_ != nullptr) {  // hg messages (the vendor YAML's validation)
      blend_ = BlendWeight(arm_sdk_->ramp_s, core.parameters().command_writer_period_us);
    }
    publisher_ = std::make_shared<::unitree::robot::ChannelPublisher<LowCmd>>(command_topic);
    publisher_->InitChannel();
    // State flows from now on, also while inactive, so read() reports the real robot early.
    subscriber_ = std::make_shared<::unitree::robot::ChannelSubscriber<LowState>>(
      options_.lowstate_topic);
    subscriber_->InitChannel(
      [this](const void * message) {on_low_state(*static_cast<const LowState *>(message));},
      kStateQueueLength);
    hands_.configure(core);  // on the same DDS participant
    RCLCPP_INFO(
      core.logger(), "unitree_sdk2 DDS (%s messages) on '%s', domain %d: publishing %s, "
      "subscribed to %s", Family::kName, network_interface.c_str(),
      static_cast<int>(options_.domain_id), command_topic, options_.lowstate_topic);
    return true;
  }

  bool start() override
  {
    if (options_.release_motion_control && !release_motion_control()) {
      return false;
    }
    hands_.start();
    if (arm_sdk_ != nullptr) {
      blend_.reset();
      RCLCPP_INFO(
        core_->logger(), "arm SDK (authority upper_body): %zu joints commanded on %s, the legs "
        "stay with the robot's own controller; the blend weight (LowCmd_ slot %zu) ramps to 1 "
        "over %.2f s once a controller drives them", core_->slots().commanded_slots().size(),
        arm_sdk_->topic, arm_sdk_->weight_slot, arm_sdk_->ramp_s);
    }
    const uint64_t period_us = core_->parameters().command_writer_period_us;
    if (OnWriteCommandWriter * writer = core_->on_write_writer()) {
      writer->start(period_us, [this]() {write_command();});
      writing_ = true;
      return true;
    }
    writer_thread_ = ::unitree::common::CreateRecurrentThreadEx(
      "command_writer", UT_CPU_ID_NONE, period_us, &UnitreeDdsTransport::write_command, this);
    writing_ = true;
    return true;
  }

  void stop() override
  {
    if (!writing_) {
      return;
    }
    writing_ = false;
    if (OnWriteCommandWriter * writer = core_->on_write_writer()) {
      writer->stop();
    }
    if (writer_thread_) {
      // The SDK creates its threads detached and does not join them on destruction: Wait()
      // (RecurrentThread's override sets the loop's quit flag, then waits for the loop to end)
      // is what guarantees write_command() has returned for good.
      writer_thread_->Wait();
      writer_thread_.reset();
    }
    if (arm_sdk_ != nullptr) {
      hand_back_upper_body();
    }
  }

  void shutdown() noexcept override
  {
    try {
      stop();
      if (subscriber_) {
        subscriber_->CloseChannel();
      }
      if (publisher_) {
        publisher_->CloseChannel();
      }
      hands_.shutdown();
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_->logger(), "shutting down unitree_sdk2 channels failed: %s", e.what());
    }
  }

private:
  // DDS listener thread: every LowState_ frame (500 Hz - 1 kHz).
  void on_low_state(const LowState & low_state)
  {
    const auto start = std::chrono::steady_clock::now();
    // Every frame: integrity and the safety-critical fields (lightweight).
    if (options_.verify_state_crc && low_state.crc() != Family::state_crc(low_state)) {
      ++crc_error_count_;
      core_->reject_state();  // the health GPIO's invalid_states
      RCLCPP_WARN_THROTTLE(
        core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "dropped LowState_ with a bad CRC (%" PRIu64 " so far; if every frame is dropped, the "
        "publisher does not fill LowState_.crc: set transport_options.verify_state_crc to false)",
        crc_error_count_);
      return;
    }
    state_tag_.store(Family::state_tag(low_state), std::memory_order_relaxed);
    if (!core_->start_state_frame()) {
      return;  // decimated
    }
    auto & state = core_->state_frame();
    const auto & motors = low_state.motor_state();
    for (const size_t slot : body_mapped_) {
      const auto & motor = motors[slot];
      if (!all_finite(motor.q(), motor.dq(), motor.tau_est())) {
        const uint64_t dropped = core_->reject_state();
        RCLCPP_WARN_THROTTLE(
          core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
          "dropped state frame: non-finite value in motor slot %zu (%" PRIu64
          " dropped so far)", slot, dropped);
        return;
      }
      state.q[slot] = static_cast<T>(motor.q());
      state.dq[slot] = static_cast<T>(motor.dq());
      state.tau[slot] = static_cast<T>(motor.tau_est());
    }
    if (core_->has_imu()) {
      publish_imu(low_state.imu_state());
    }
    const int64_t now_ns = steady_ns(start);
    const bool health_due = core_->motor_health_due(now_ns);
    // The hands' newest states: the state is as old as its oldest stream, and complete only once
    // every hand has reported in this activation.
    int64_t state_time_ns = now_ns;
    if (!hands_.merge(state, health_due ? &core_->motor_health_frame() : nullptr, state_time_ns)) {
      return;
    }
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(health_due)) {
      auto & health = core_->motor_health_frame();
      for (const size_t slot : body_mapped_) {
        Family::read_motor_health(motors[slot], health, slot);
      }
      core_->publish_motor_health(now_ns);
    }
    core_->publish_state(state_time_ns);
    core_->monitor().check_state_latency(start);
  }

  template<typename ImuState>
  void publish_imu(const ImuState & imu_state)
  {
    const auto & quat = imu_state.quaternion();  // w, x, y, z
    const auto & gyro = imu_state.gyroscope();
    const auto & acc = imu_state.accelerometer();
    if (!all_finite(quat[0], quat[1], quat[2], quat[3]) || !all_finite(gyro[0], gyro[1], gyro[2]) ||
      !all_finite(acc[0], acc[1], acc[2]))
    {
      const uint64_t dropped = core_->reject_imu();
      RCLCPP_WARN_THROTTLE(
        core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "dropped IMU sample with non-finite values (%" PRIu64 " dropped so far)", dropped);
      return;
    }
    auto & imu = core_->imu_frame();
    for (size_t i = 0; i < 4; ++i) {
      imu.quat[i] = static_cast<T>(quat[i]);
    }
    for (size_t i = 0; i < 3; ++i) {
      imu.omega[i] = static_cast<T>(gyro[i]);
      imu.acc[i] = static_cast<T>(acc[i]);
    }
    core_->publish_imu();
  }

  // SDK recurrent thread: one LowCmd_ every command_writer_period_us (on_write mode: the
  // OnWriteCommandWriter's thread, woken by write()).
  void write_command()
  {
    const auto start = std::chrono::steady_clock::now();
    core_->monitor().check_writer_jitter();
    const auto * cmd = core_->next_command();
    if (cmd == nullptr) {
      return;
    }
    Family::apply_state_tag(low_cmd_, state_tag_.load(std::memory_order_relaxed));
    if (arm_sdk_ != nullptr) {
      // Towards 1 only while the controllers drive the upper body: never on a hold, never while
      // no controller commands it (the arms would fall).
      const bool engage = !core_->command_is_hold() &&
        BlendWeight::drives_any(*cmd, body_commanded_);
      set_blend_weight(blend_.next(engage));
    }
    for (const size_t slot : body_commanded_) {
      auto & motor = low_cmd_.motor_cmd()[slot];
      motor.q() = static_cast<float>(cmd->q_target[slot]);
      motor.dq() = static_cast<float>(cmd->dq_target[slot]);
      motor.tau() = static_cast<float>(cmd->tau_ff[slot]);
      motor.kp() = static_cast<float>(cmd->kp[slot]);
      motor.kd() = static_cast<float>(cmd->kd[slot]);
    }
    low_cmd_.crc() = Family::command_crc(low_cmd_);
    publisher_->Write(low_cmd_);
    hands_.write(*cmd);
    core_->monitor().check_writer_latency(start);
  }

  void set_blend_weight(double weight)
  {
    low_cmd_.motor_cmd()[arm_sdk_->weight_slot].q() = static_cast<float>(weight);
  }

  // stop() of the arm SDK, once the writer has stopped: the blend weight back to 0 at the writer's
  // pace, one step per command, over the last command sent (the robot's controller takes over
  // from where the arms are). Blocks for at most arm_sdk_ramp_s.
  void hand_back_upper_body()
  {
    if (blend_.value() <= 0.0) {
      return;
    }
    RCLCPP_INFO(
      core_->logger(), "arm SDK: handing the upper body back to the robot's controller (blend "
      "weight %.2f to 0)", blend_.value());
    const auto period = std::chrono::microseconds(core_->parameters().command_writer_period_us);
    auto next = std::chrono::steady_clock::now();
    while (blend_.value() > 0.0) {
      set_blend_weight(blend_.next(false));
      low_cmd_.crc() = Family::command_crc(low_cmd_);
      publisher_->Write(low_cmd_);
      next += period;
      std::this_thread::sleep_until(next);
    }
    RCLCPP_INFO(core_->logger(), "arm SDK: blend weight 0, the robot's controller has the body");
  }

  // Unitree robots boot into a built-in motion controller (sport / locomotion mode) that also
  // writes the low-level command topic. As in the SDK's low-level examples it is released before
  // low-level control, otherwise both command the motors. Once released nothing holds the robot
  // until this driver's controllers do: support it first.
  bool release_motion_control()
  {
    constexpr int kMaxAttempts = 3;
    ::unitree::robot::b2::MotionSwitcherClient client;
    client.SetTimeout(5.0F);
    client.Init();
    std::string form;
    std::string mode;
    for (int attempt = 0; ; ++attempt) {
      if (client.CheckMode(form, mode) != 0) {
        RCLCPP_ERROR(
          core_->logger(), "MotionSwitcherClient::CheckMode failed: is the robot reachable?");
        return false;
      }
      if (mode.empty()) {
        RCLCPP_INFO(core_->logger(), "built-in motion control is released");
        return true;
      }
      if (attempt == kMaxAttempts) {
        RCLCPP_ERROR(
          core_->logger(), "motion mode '%s' is still active after %d release attempts",
          mode.c_str(), kMaxAttempts);
        return false;
      }
      RCLCPP_INFO(
        core_->logger(), "releasing built-in motion mode '%s' (form '%s')", mode.c_str(),
        form.c_str());
      client.ReleaseMode();
      std::this_thread::sleep_for(std::chrono::seconds(5));  // as the SDK example does
    }
  }

  const UnitreeDdsOptions options_;
  const UnitreeArmSdkOptions * const arm_sdk_;  // nullptr: the whole robot on lowcmd_topic
  Hands hands_;  // the hands on their own topics (none by default)
  std::vector<size_t> body_mapped_;     // mapped slots of LowCmd_ / LowState_ (configure())
  std::vector<size_t> body_commanded_;  // commanded slots of LowCmd_ (configure())
  BlendWeight blend_;  // arm SDK: writer thread, then stop() once the writer has stopped
  DriverCore<N, T> * core_{nullptr};
  LowCmd low_cmd_;  // writer thread: the message sent (constant parts filled in configure())
  ::unitree::robot::ChannelPublisherPtr<LowCmd> publisher_;
  ::unitree::robot::ChannelSubscriberPtr<LowState> subscriber_;
  ::unitree::common::ThreadPtr writer_thread_;  // the timer mode's writer
  bool writing_{false};  // caller's thread (start / stop): a writer was started and not stopped
  std::atomic<uint8_t> state_tag_{0};  // hg mode_machine: from every valid LowState_, echoed back
  uint64_t crc_error_count_{0};           // listener thread: frames dropped for a bad CRC
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_DDS_HPP_
