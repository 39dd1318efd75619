// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_HPP_

// AgiBot robots over ROS 2 topics (AimDK, aimdk_msgs): one JointCommandArray / JointStateArray
// topic pair per joint group, entries named; sensor_msgs/Imu for the IMU; with hands, one
// HandCommandArray / HandStateArray pair for both hands, entries matched by index.

#include <algorithm>
#include <array>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <aimdk_msgs/msg/hand_command_array.hpp>
#include <aimdk_msgs/msg/hand_state_array.hpp>
#include <aimdk_msgs/msg/joint_command_array.hpp>
#include <aimdk_msgs/msg/joint_state_array.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/subscription.hpp>
#include <sensor_msgs/msg/imu.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"
#include "robot_hardware_interface/common/system_driver.hpp"
#include "robot_hardware_interface/transport/joint_names.hpp"
#include "robot_hardware_interface/transport/ros_topics.hpp"

namespace robot_hardware_interface
{

// One AimDK joint group: a contiguous range of motor slots with its own command and state topic.
struct AimdkJointGroup
{
  const char * name;
  size_t offset;  // first motor slot
  size_t size;    // entries in the group's messages
  const char * command_topic;
  const char * state_topic;
};

// The robot's hands (hands: omnihand): both on one HandCommandArray / HandStateArray, each hand
// `axes` entries matched by index, the left hand's in the slots from `first_slot`, the right's
// after. The HAL tracks position targets itself: no gains travel (CommandMode::kPositionTarget).
struct AimdkHandsOptions
{
  size_t first_slot;
  size_t axes;          // entries per hand (OmniHand: 10)
  uint8_t hand_type;    // HandType sent and expected of both hands (OmniHand: NIMBLE_HANDS)
  double velocity;      // HandCommand.velocity sent with every target
  const char * command_topic;
  const char * state_topic;
};

// transport_options of the vendor YAML.
struct AgibotTopicsOptions
{
  const AimdkJointGroup * groups;
  size_t group_count;
  const char * imu_topic;
  TopicQos qos;
  double take_control_timeout_s{30.0};  // take_control: how long activation waits for Develop_MC
  const AimdkHandsOptions * hands{nullptr};  // nullptr: no hands for this driver to drive
};

// A robot whose driver does not take control through AimDK's services (the default `Control`).
struct AimdkNoControl
{
  explicit AimdkNoControl(double /*timeout_s*/) {}
  void configure(const rclcpp::Node::SharedPtr & /*node*/) {}
  bool take(TopicExecutor & /*executor*/, const rclcpp::Logger & /*logger*/) {return true;}
  void release(TopicExecutor & /*executor*/, const rclcpp::Logger & /*logger*/) {}
};

// `Control`: how the driver takes control of the robot before its first command and gives it back
// after its last (AimdkSystemState of agibot_system_state.hpp for take_control: true).
template<size_t N, typename T, typename Control = AimdkNoControl>
class AgibotTopicsTransport final : public DriverTransport<N, T>
{
  using CommandArray = aimdk_msgs::msg::JointCommandArray;
  using StateArray = aimdk_msgs::msg::JointStateArray;
  using HandCommands = aimdk_msgs::msg::HandCommandArray;
  using HandStates = aimdk_msgs::msg::HandStateArray;
  using Imu = sensor_msgs::msg::Imu;

public:
  // The hands, if any, are one more message group after the joint groups: the state is complete
  // once they have reported too, and as old as the oldest group.
  explicit AgibotTopicsTransport(const AgibotTopicsOptions & options)
  : options_(options), groups_(options.group_count + (options.hands != nullptr ? 1U : 0U)),
    control_(options.take_control_timeout_s)
  {
    if (options.hands != nullptr) {
      const AimdkHandsOptions & hands = *options.hands;
      hands_group_ = AimdkJointGroup{
        "hands", hands.first_slot, 2 * hands.axes, hands.command_topic, hands.state_topic};
    }
  }

  const char * name() const override {return "agibot_topics";}
  uint8_t motor_health() const override {return kMotorErrorCode;}

  bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node) override
  {
    core_ = &core;
    node_ = node;
    const rclcpp::QoS qos = make_qos(options_.qos);
    names_.assign(core.slots().slot_joint_names());
    for (size_t g = 0; g < options_.group_count; ++g) {
      const AimdkJointGroup & spec = options_.groups[g];
      Group & group = groups_[g];
      group.spec = &spec;
      group.driven = 0;
      // Size the command message and name its entries once: the writer only fills in numbers.
      group.command.joints.resize(spec.size);
      // The slot of every entry of the last state message, tried first on the next one: a
      // publisher that keeps its order (or keeps a changed one) costs one name check per entry.
      group.entry_slots.assign(spec.size, kNoSlot);
      for (size_t i = 0; i < spec.size; ++i) {
        const char * joint = core.slots().slot_joint_names()[spec.offset + i];
        group.command.joints[i].name = joint;
        group.driven += joint[0] != '\0' ? 1U : 0U;
      }
      group.publisher = node->create_publisher<CommandArray>(spec.command_topic, qos);
      group.subscription = node->create_subscription<StateArray>(
        spec.state_topic, qos, [this, g](const StateArray & msg) {on_group_state(g, msg);});
    }
    if (options_.hands != nullptr) {
      configure_hands(core, node, qos);
    }
    if (core.has_imu()) {
      imu_subscription_ = node->create_subscription<Imu>(
        options_.imu_topic, qos, [this](const Imu & msg) {
          publish_ros_imu(*core_, msg.orientation, msg.angular_velocity, msg.linear_acceleration);
        });
    }
    executor_.configure(node);
    control_.configure(node);
    return true;
  }

  bool start() override
  {
    // Every group has to report again before the first state of this activation.
    for (Group & group : groups_) {
      group.reported = false;
      group.frame_counter = 0;
      group.state_time_ns = 0;
      group.frames_valid = false;
    }
    groups_reported_ = 0;
    // Control first: a refusal refuses the activation before anything is sent.
    if (!control_.take(executor_, core_->logger())) {
      return false;
    }
    controlling_ = true;
    executor_.start(
      core_->parameters().command_writer_period_us, core_->logger(), core_->on_write_writer(),
      [this]() {write_command();});
    return true;
  }

  // The writer's last command has gone once the executor has stopped: then control goes back.
  void stop() override
  {
    executor_.stop();
    if (controlling_) {
      controlling_ = false;
      control_.release(executor_, core_->logger());
    }
  }

  // Also gives control back when the component is shut down without a deactivation.
  void shutdown() noexcept override
  {
    try {
      stop();
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_->logger(), "stopping the executor thread failed: %s", e.what());
    }
  }

private:
  static constexpr size_t kNoSlot = std::numeric_limits<size_t>::max();

  struct Group
  {
    const AimdkJointGroup * spec{nullptr};
    size_t driven{0};  // slots of the group that drive a URDF joint
    CommandArray command;  // pre-sized in configure(): no allocation per cycle
    typename rclcpp::Publisher<CommandArray>::SharedPtr publisher;
    typename rclcpp::Subscription<StateArray>::SharedPtr subscription;
    // Executor thread only:
    bool reported{false};       // sent a valid frame this activation
    uint32_t frame_counter{0};  // decimation, per group
    int64_t state_time_ns{0};   // steady time of the group's last valid frame
    bool frames_valid{false};   // the group's last parsed frame was accepted
    std::vector<size_t> entry_slots;  // slot of each entry of the last state message (sized once)
    bool distinct_slots{false};  // no two entry_slots name the same slot (checked when they change)
    bool health_stored{false};   // stored its error codes since the last motor health frame
  };

  // The motor slot of entry `position` of a group's state message. A named entry is first tried
  // against the slot the same entry had in the group's last message (a publisher keeps its
  // order, also a changed one), then matched by position when the name agrees (or is empty:
  // names are optional in AimDK), otherwise by name within the group. Every match compares the
  // full name, so a reordered publisher never feeds a value to the wrong joint. kNoSlot for a
  // joint this driver does not drive. Compares in place.
  size_t resolve_slot(const Group & group, size_t position, const std::string & name) const
  {
    const AimdkJointGroup & spec = *group.spec;
    if (!name.empty() && position < group.entry_slots.size()) {
      const size_t cached = group.entry_slots[position];
      if (cached != kNoSlot && names_.matches(name, cached)) {
        return cached;
      }
    }
    if (position < spec.size) {
      const size_t slot = spec.offset + position;
      if (names_.drives(slot) && (name.empty() || names_.matches(name, slot))) {
        return slot;
      }
    }
    if (name.empty()) {
      return kNoSlot;
    }
    for (size_t slot = spec.offset; slot < spec.offset + spec.size; ++slot) {
      if (names_.drives(slot) && names_.matches(name, slot)) {
        return slot;
      }
    }
    return kNoSlot;
  }

  // The number of distinct driven slots a group's message names; also records whether the
  // group's cached entry slots are distinct (then a message whose entries all hit the cache
  // names as many joints as it has driven entries).
  size_t match_distinct_slots(Group & group, const StateArray & msg)
  {
    const uint32_t stamp = ++message_stamp_;
    size_t distinct = 0;
    group.distinct_slots = true;
    for (size_t i = 0; i < msg.joints.size(); ++i) {
      const bool cached = i < group.entry_slots.size();
      const size_t slot =
        cached ? group.entry_slots[i] : resolve_slot(group, i, msg.joints[i].name);
      if (slot == kNoSlot) {
        continue;
      }
      if (slot_stamps_[slot] == stamp) {
        group.distinct_slots = group.distinct_slots && !cached;
        continue;
      }
      slot_stamps_[slot] = stamp;
      ++distinct;
    }
    return distinct;
  }

  // The age of the state is the age of the oldest group: one silent group makes it stale.
  int64_t oldest_group_time() const
  {
    int64_t oldest = groups_.front().state_time_ns;
    for (const Group & group : groups_) {
      oldest = std::min(oldest, group.state_time_ns);
    }
    return oldest;
  }

  // Executor thread: the JointStateArray of one group.
  void on_group_state(size_t index, const StateArray & msg)
  {
    const auto start = std::chrono::steady_clock::now();
    Group & group = groups_[index];
    const AimdkJointGroup & spec = *group.spec;
    if (msg.state.value != 0U) {  // DomainErrorState: 1 damping, 2 power down, 3 disable, ...
      RCLCPP_WARN_THROTTLE(
        core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
        "AimDK HAL reports error state %u for joint group '%s'",
        static_cast<unsigned>(msg.state.value), spec.name);
    }
    if (decimated(group, start)) {
      return;
    }
    // Validate the whole frame before touching the parsing buffer: a rejected frame leaves no
    // trace.
    const size_t count = msg.joints.size();
    const size_t remembered = std::min(count, group.entry_slots.size());
    size_t * const entry_slots = group.entry_slots.data();
    double non_finite = 0.0;  // stays 0 while every value is finite: x * 0 is NaN for inf and NaN
    const auto check = [&non_finite](const auto & joint) {
        non_finite += joint.position * 0.0 + joint.velocity * 0.0 + joint.effort * 0.0;
      };
    // The usual message: every entry names the joint it named in the last message. This loop
    // calls nothing, so that its sum stays in a register; the first other entry ends it.
    size_t first_miss = 0;
    while (first_miss < remembered && entry_slots[first_miss] != kNoSlot &&
      names_.matches(msg.joints[first_miss].name, entry_slots[first_miss]))
    {
      check(msg.joints[first_miss]);
      ++first_miss;
    }
    size_t matched = first_miss;
    bool resolved = count > remembered;  // some entry was matched by the slow path
    for (size_t i = first_miss; i < remembered; ++i) {
      const auto & joint = msg.joints[i];
      size_t slot = entry_slots[i];
      if (slot == kNoSlot || !names_.matches(joint.name, slot)) {
        slot = resolve_slot(group, i, joint.name);
        entry_slots[i] = slot;  // tried first on the next message, reused below
        resolved = true;
      }
      if (slot != kNoSlot) {
        check(joint);
        ++matched;
      }
    }
    for (size_t i = remembered; i < count; ++i) {  // more entries than the group has
      if (resolve_slot(group, i, msg.joints[i].name) != kNoSlot) {
        check(msg.joints[i]);
        ++matched;
      }
    }
    // A joint counts once however often the message repeats it: a duplicate must not stand in
    // for a joint that is missing. Entries that all hit the cache of a group whose cached slots
    // are distinct cannot repeat one; otherwise count the distinct slots.
    if (resolved || !group.distinct_slots) {
      matched = match_distinct_slots(group, msg);
    }
    if (!(non_finite == 0.0)) {
      reject(group, "non-finite value for a joint");
      return;
    }
    if (matched < group.driven) {
      reject(group, "the group did not report all of its joints");
      return;
    }
    auto & state = core_->state_frame();
    auto & health = core_->motor_health_frame();  // JointState.error_code (v1.0.0)
    // `with_health`: std::true_type while a motor health frame is due (health_frame_due()).
    const auto store_all = [&](auto with_health) {
        const auto store = [&state, &health](size_t slot, const auto & joint) {
            state.q[slot] = static_cast<T>(joint.position);
            state.dq[slot] = static_cast<T>(joint.velocity);
            state.tau[slot] = static_cast<T>(joint.effort);
            if constexpr (decltype(with_health)::value) {
              store_error_code(health, slot, joint);
            }
          };
        for (size_t i = 0; i < remembered; ++i) {
          if (entry_slots[i] != kNoSlot) {
            store(entry_slots[i], msg.joints[i]);
          }
        }
        for (size_t i = remembered; i < count; ++i) {
          const size_t slot = resolve_slot(group, i, msg.joints[i].name);
          if (slot != kNoSlot) {
            store(slot, msg.joints[i]);
          }
        }
      };
    const bool health_due = health_frame_due(start);
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(health_due)) {
      store_all(std::true_type{});
    } else {
      store_all(std::false_type{});
    }
    accept(group, start, health_due);
  }

  // Whether the motor health frame is due for a frame that started at `start`: only then do the
  // callbacks store their error codes into it. Nothing reads the frame between two publications,
  // and once it is due every group stores into it until the last one of the round publishes it
  // (collect_motor_health()), so it holds each group's newest codes, as if stored every time.
  bool health_frame_due(std::chrono::steady_clock::time_point start) const
  {
    return core_->motor_health_due(steady_ns(start));
  }

  // Decimation per group: the first frame of a group in an activation is always processed. A
  // skipped frame still proves that the group reports: it keeps the group fresh, unless the
  // group's last processed frame was rejected. True when the frame is skipped.
  bool decimated(Group & group, std::chrono::steady_clock::time_point start)
  {
    const uint32_t frame_count = group.frame_counter++;
    if (!group.reported || (frame_count % core_->parameters().state_decimation) == 0U) {
      return false;
    }
    if (group.frames_valid) {
      group.state_time_ns = steady_ns(start);
      if (groups_reported_ == groups_.size()) {
        core_->mark_state_fresh(oldest_group_time());
      }
    }
    return true;
  }

  // A group's frame has been stored in the state frame (its error codes too when `health_due`).
  void accept(Group & group, std::chrono::steady_clock::time_point start, bool health_due)
  {
    group.state_time_ns = steady_ns(start);
    group.frames_valid = true;
    if (!group.reported) {
      group.reported = true;
      ++groups_reported_;
    }
    // A motor health frame holds one round of every group's error codes: once one is due, each
    // group stores into it once, and the last one publishes it.
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(health_due)) {
      collect_motor_health(group);
    }
    // First-state rule: only once every group has reported is the state complete.
    if (groups_reported_ == groups_.size()) {
      core_->publish_state(oldest_group_time());
    }
    core_->monitor().check_state_latency(start);
  }

  void configure_hands(
    DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node, const rclcpp::QoS & qos)
  {
    const AimdkHandsOptions & hands = *options_.hands;
    Group & group = groups_.back();
    group.spec = &hands_group_;
    group.driven = hands_group_.size;
    // Sized, named and given its fixed fields once: the writer only fills in the targets.
    hand_command_.left_hand_type.value = hands.hand_type;
    hand_command_.right_hand_type.value = hands.hand_type;
    hand_command_.left_hands.resize(hands.axes);
    hand_command_.right_hands.resize(hands.axes);
    for (size_t i = 0; i < 2 * hands.axes; ++i) {
      auto & entry = i < hands.axes ? hand_command_.left_hands[i] :
        hand_command_.right_hands[i - hands.axes];
      entry.name = core.slots().slot_joint_names()[hands.first_slot + i];
      entry.velocity = hands.velocity;  // acceleration, deceleration and effort stay 0
    }
    hand_publisher_ = node->create_publisher<HandCommands>(hands.command_topic, qos);
    hand_subscription_ = node->create_subscription<HandStates>(
      hands.state_topic, qos, [this](const HandStates & msg) {on_hand_state(msg);});
  }

  // Executor thread: the HandStateArray of both hands, entries by index (the HAL names none). The
  // OmniHand's effort field is a motor current, not a torque: the joints' effort stays 0.
  void on_hand_state(const HandStates & msg)
  {
    const auto start = std::chrono::steady_clock::now();
    Group & group = groups_.back();
    if (decimated(group, start)) {
      return;
    }
    const AimdkHandsOptions & hands = *options_.hands;
    if (msg.left_hand_type.value != hands.hand_type ||
      msg.right_hand_type.value != hands.hand_type)
    {
      reject(group, "a hand of another type reports (see the HandType of the hand state)");
      return;
    }
    if (msg.left_hands.size() < hands.axes || msg.right_hands.size() < hands.axes) {
      reject(group, "a hand reported fewer axes than it has");
      return;
    }
    double non_finite = 0.0;  // stays 0 while every value is finite
    for (size_t i = 0; i < hands.axes; ++i) {
      non_finite += msg.left_hands[i].position * 0.0 + msg.left_hands[i].velocity * 0.0 +
        msg.right_hands[i].position * 0.0 + msg.right_hands[i].velocity * 0.0;
    }
    if (!(non_finite == 0.0)) {
      reject(group, "non-finite value for a hand axis");
      return;
    }
    auto & state = core_->state_frame();
    auto & health = core_->motor_health_frame();
    const bool health_due = health_frame_due(start);
    const auto store = [&state, &health, health_due](size_t slot, const auto & axis) {
        state.q[slot] = static_cast<T>(axis.position);
        state.dq[slot] = static_cast<T>(axis.velocity);
        state.tau[slot] = T{0};
        if (health_due) {
          health.error_code[slot] = static_cast<double>(axis.faultcode);
        }
      };
    for (size_t i = 0; i < hands.axes; ++i) {
      store(hands.first_slot + i, msg.left_hands[i]);
      store(hands.first_slot + hands.axes + i, msg.right_hands[i]);
    }
    accept(group, start, health_due);
  }

  // Executor thread (writer): both hands' position targets, in the writer cycle of the groups'.
  void write_hands(const MotorCommand<N, T> & cmd, const rclcpp::Time & now)
  {
    const AimdkHandsOptions & hands = *options_.hands;
    hand_command_.header.stamp = now;
    hand_command_.header.sequence = command_sequence_;
    const size_t left = hands.first_slot;
    const size_t right = hands.first_slot + hands.axes;
    for (size_t i = 0; i < hands.axes; ++i) {
      hand_command_.left_hands[i].position = static_cast<double>(cmd.q_target[left + i]);
      hand_command_.right_hands[i].position = static_cast<double>(cmd.q_target[right + i]);
    }
    hand_publisher_->publish(hand_command_);
  }

  // hal/msg/JointState v1.0.0 ends with `uint16 error_code`; AimDK's later documented JointState
  // has motor temperatures instead (SDK_FACTS.md): without the field the interface stays 0.
  template<typename Joint, typename = void>
  struct HasErrorCode : std::false_type {};
  template<typename Joint>
  struct HasErrorCode<Joint, std::void_t<decltype(std::declval<const Joint &>().error_code)>>
    : std::true_type {};

  template<typename Health, typename Joint>
  static void store_error_code(Health & health, size_t slot, const Joint & joint)
  {
    if constexpr (HasErrorCode<Joint>::value) {
      health.error_code[slot] = static_cast<double>(joint.error_code);
    } else {
      static_cast<void>(health);
      static_cast<void>(slot);
      static_cast<void>(joint);
    }
  }

  void collect_motor_health(Group & group)
  {
    if (groups_health_stored_ == 0) {
      for (Group & other : groups_) {
        other.health_stored = false;
      }
    }
    if (!group.health_stored) {
      group.health_stored = true;
      ++groups_health_stored_;
    }
    if (groups_health_stored_ == groups_.size()) {
      core_->publish_motor_health(group.state_time_ns);
      groups_health_stored_ = 0;
    }
  }

  void reject(Group & group, const char * reason)
  {
    group.frames_valid = false;
    const uint64_t dropped = core_->reject_state();
    RCLCPP_WARN_THROTTLE(
      core_->logger(), core_->throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "dropped state frame of joint group '%s': %s (%" PRIu64 " dropped so far)",
      group.spec->name, reason, dropped);
  }

  // Executor thread (wall timer): one JointCommandArray per group every
  // command_writer_period_us.
  void write_command()
  {
    const auto start = std::chrono::steady_clock::now();
    core_->monitor().check_writer_jitter();
    const auto * cmd = core_->next_command();
    if (cmd == nullptr) {
      return;
    }
    const rclcpp::Time now = node_->now();
    ++command_sequence_;
    for (size_t g = 0; g < options_.group_count; ++g) {
      Group & group = groups_[g];
      CommandArray & msg = group.command;
      msg.header.stamp = now;
      msg.header.sequence = command_sequence_;
      for (size_t i = 0; i < group.spec->size; ++i) {
        const size_t slot = group.spec->offset + i;
        auto & joint = msg.joints[i];
        joint.position = static_cast<double>(cmd->q_target[slot]);
        joint.velocity = static_cast<double>(cmd->dq_target[slot]);
        joint.effort = static_cast<double>(cmd->tau_ff[slot]);
        joint.stiffness = static_cast<double>(cmd->kp[slot]);
        joint.damping = static_cast<double>(cmd->kd[slot]);
      }
      group.publisher->publish(msg);
    }
    if (options_.hands != nullptr) {
      write_hands(*cmd, now);
    }
    core_->monitor().check_writer_latency(start);
  }

  const AgibotTopicsOptions options_;
  DriverCore<N, T> * core_{nullptr};
  rclcpp::Node::SharedPtr node_;
  std::vector<Group> groups_;  // sized at construction; the hands' group last
  AimdkJointGroup hands_group_{};  // the hands as a message group (hands only)
  HandCommands hand_command_;  // pre-sized in configure(): no allocation per cycle
  typename rclcpp::Publisher<HandCommands>::SharedPtr hand_publisher_;
  typename rclcpp::Subscription<HandStates>::SharedPtr hand_subscription_;
  std::array<uint32_t, N> slot_stamps_{};  // executor thread: match_distinct_slots() marks
  uint32_t message_stamp_{0};
  JointNames<N> names_;  // each slot's joint name, matched against the entries of a message
  size_t groups_reported_{0};  // executor thread
  size_t groups_health_stored_{0};  // executor thread: groups with health_stored
  uint32_t command_sequence_{0};
  typename rclcpp::Subscription<Imu>::SharedPtr imu_subscription_;
  TopicExecutor executor_;
  Control control_;
  bool controlling_{false};  // caller's thread (start / stop): control taken and not released
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__AGIBOT_TOPICS_HPP_
