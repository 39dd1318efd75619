// Fake robot side of the agibot_topics transport (aimdk_msgs): one JointStateArray per joint
// group (entry p of group g is SDK slot offset_g + p, named after the joint the YAML maps there),
// sensor_msgs/Imu, one JointCommandArray per group out. With hands: omnihand (RHI_AIMDK_HANDS) also
// one HandStateArray after the groups (both hands: HandType 1, 10 entries each, matched by index and
// unnamed as the HAL sends them: left entry i = slot kHandFirstSlot + i, right entry i = kHandFirstSlot
// + 10 + i) and one HandCommandArray in. kGroups' last group is then the hands' ("hands"), the
// JointStateArray groups are the first kBodyGroupCount.
#pragma once

#include <array>
#include <limits>

#include <aimdk_msgs/msg/joint_command_array.hpp>
#include <aimdk_msgs/msg/joint_state_array.hpp>
#if defined(RHI_AIMDK_HANDS)
#include <aimdk_msgs/msg/hand_command_array.hpp>
#include <aimdk_msgs/msg/hand_state_array.hpp>
#endif

#include "transport_ros_common.hpp"
#if defined(RHI_TAKE_CONTROL)
#include "aimdk_system_state_server.hpp"
#endif

namespace rhi_test {

class Transport : public RosTransportBase {
public:
  using StateMsg = aimdk_msgs::msg::JointStateArray;
  using CommandMsg = aimdk_msgs::msg::JointCommandArray;
  static constexpr const char* kName = "agibot_topics";
  static constexpr bool kHasGains = true;
#if defined(RHI_AIMDK_HANDS)
  using HandStateMsg = aimdk_msgs::msg::HandStateArray;
  using HandCommandMsg = aimdk_msgs::msg::HandCommandArray;
  static constexpr size_t kHandAxes = 10;     // per hand (OmniHand, HandType NIMBLE_HANDS)
  static constexpr uint8_t kOmniHandType = 1;  // HandType::NIMBLE_HANDS
  static constexpr double kHandEffortScale = 0.125;  // the reported current [A], not a torque: never stored
  static constexpr size_t hand_slot(size_t side, size_t axis) { return kHandFirstSlot + side * kHandAxes + axis; }
  static_assert(kGroupCount == kBodyGroupCount + 1, "robot_data.hpp: the hands are the last group");
  static_assert(kHandFirstSlot + 2 * kHandAxes <= N, "robot_data.hpp: the hand slots are SDK slots");
#endif

  Transport() {
#if defined(RHI_TAKE_CONTROL)
    system_state_.serve();  // every section's activation takes control first
#endif
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      state_msgs_[g].joints.resize(kGroups[g].size);
      for (size_t p = 0; p < kGroups[g].size; ++p) {
        const Joint* j = joint_of_slot(kGroups[g].offset + p);
        state_msgs_[g].joints[p].name = j != nullptr ? j->name : "";
      }
    }
#if defined(RHI_AIMDK_HANDS)
    hand_state_msg_.left_hand_type.value = kOmniHandType;
    hand_state_msg_.right_hand_type.value = kOmniHandType;
    hand_state_msg_.left_hands.resize(kHandAxes);  // names empty, as the HAL sends them
    hand_state_msg_.right_hands.resize(kHandAxes);
#endif
  }

  void prepare_state(const StateFrame& f) {
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      StateMsg& m = state_msgs_[g];
      m.header.sequence = f.sequence;
      m.state.value = 0;  // DomainErrorState::NONE
      for (size_t p = 0; p < kGroups[g].size; ++p) {
        const size_t slot = kGroups[g].offset + p;
        m.joints[p].position = f.q[slot];
        m.joints[p].velocity = f.dq[slot];
        m.joints[p].effort = f.tau[slot];
        m.joints[p].error_code = static_cast<uint16_t>(f.error_code[slot]);
      }
    }
#if defined(RHI_AIMDK_HANDS)
    prepare_hands(f);
#endif
    prepare_ros_imu(f);
  }
  // Every group, in group order, then the hands; returns 1 when every message reached a subscription.
  size_t deliver_prepared() {
    size_t reached = 0;
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]) > 0 ? 1U : 0U;
    }
#if defined(RHI_AIMDK_HANDS)
    reached += deliver_prepared_hands() > 0 ? 1U : 0U;
#endif
    return reached == kGroupCount ? 1U : 0U;
  }
  size_t deliver_state(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared();
  }
  size_t deliver_prepared_imu() { return deliver_ros_imu(); }
  size_t deliver_imu(const StateFrame& f) {
    prepare_ros_imu(f);
    return deliver_ros_imu();
  }
  // A state that must not count as the first valid one: the last group never reports (with a
  // single group: a non-finite position). With hands the last group is the hands': every joint
  // group reports, the hands do not.
  size_t deliver_invalid_state(const StateFrame& f) {
    prepare_state(f);
    if (kGroupCount > 1) {
      size_t reached = 0;
      for (size_t g = 0; g < kBodyGroupCount && g + 1 < kGroupCount; ++g) {
        reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]);
      }
      return reached;
    }
    StateMsg bad = state_msgs_[0];
    bad.joints[0].position = std::numeric_limits<double>::quiet_NaN();
    return rhi_fake::ros::deliver<StateMsg>(kGroups[0].state_topic, bad);
  }

  // One frame the driver must reject and count (health GPIO invalid_states): a non-finite position
  // in the first group.
  size_t deliver_corrupt_state(const StateFrame& f) {
    prepare_state(f);
    StateMsg bad = state_msgs_[0];
    bad.joints[0].position = std::numeric_limits<double>::quiet_NaN();
    return rhi_fake::ros::deliver<StateMsg>(kGroups[0].state_topic, bad);
  }

  // Every group with its entries rotated by `rotate` (entry p carries the joint of position
  // (p + rotate) % size, its name and its values): a publisher that changed its joint order. The
  // hands, matched by index and unnamed, come unrotated.
  size_t deliver_rotated(const StateFrame& f, size_t rotate) {
    prepare_state(f);
    size_t reached = 0;
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      StateMsg& m = rotated_msgs_[g];
      m = state_msgs_[g];
      const size_t size = kGroups[g].size;
      for (size_t p = 0; p < size; ++p) {
        m.joints[p] = state_msgs_[g].joints[(p + rotate) % size];
      }
      reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, m) > 0 ? 1U : 0U;
    }
#if defined(RHI_AIMDK_HANDS)
    reached += deliver_prepared_hands() > 0 ? 1U : 0U;
#endif
    return reached == kGroupCount ? 1U : 0U;
  }

  // Every group as usual, except that in group 0 entry 1 repeats entry 0 (its name and values):
  // joint 1 of that group is missing, a duplicate stands in for it. Returns whether group 0 has
  // a second entry at all.
  bool deliver_with_duplicate(const StateFrame& f) {
    prepare_state(f);
    if (kGroups[0].size < 2) {
      return false;
    }
    StateMsg& m = rotated_msgs_[0];
    m = state_msgs_[0];
    m.joints[1] = m.joints[0];
    rhi_fake::ros::deliver<StateMsg>(kGroups[0].state_topic, m);
    for (size_t g = 1; g < kBodyGroupCount; ++g) {
      rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]);
    }
#if defined(RHI_AIMDK_HANDS)
    deliver_prepared_hands();
#endif
    return true;
  }
  // The motor slots of group 0 (the one deliver_with_duplicate() corrupts).
  static bool in_first_group(size_t slot) { return slot >= kGroups[0].offset && slot < kGroups[0].offset + kGroups[0].size; }

  // Every command message: the groups' JointCommandArrays and the hands' HandCommandArray.
  uint64_t sent_messages() const {
    uint64_t total = 0;
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      total += rhi_fake::ros::publish_count(kGroups[g].command_topic);
    }
#if defined(RHI_AIMDK_HANDS)
    total += sent_hand_messages();
#endif
    return total;
  }
  static constexpr size_t command_messages_per_cycle() { return kGroupCount; }

  // Only the joint groups' JointStateArrays (no hands).
  size_t deliver_prepared_groups() {
    size_t reached = 0;
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]) > 0 ? 1U : 0U;
    }
    return reached;
  }

#if defined(RHI_AIMDK_HANDS)
  // The HandStateArray from the frame's hand slots: position q, velocity dq, effort a current that is
  // not the frame's tau (the driver must not store it), faultcode the slot's error code.
  void prepare_hands(const StateFrame& f) {
    hand_state_msg_.header.sequence = f.sequence;
    for (size_t side = 0; side < 2; ++side) {
      auto& hands = side == 0 ? hand_state_msg_.left_hands : hand_state_msg_.right_hands;
      for (size_t a = 0; a < kHandAxes && a < hands.size(); ++a) {
        const size_t slot = hand_slot(side, a);
        hands[a].position = f.q[slot];
        hands[a].velocity = f.dq[slot];
        hands[a].effort = 1.0 + kHandEffortScale * static_cast<double>(slot) - 0.5 * f.tau[slot];
        hands[a].state = 0;
        hands[a].faultcode = static_cast<int32_t>(f.error_code[slot]);
      }
    }
  }
  HandStateMsg& prepared_hands() { return hand_state_msg_; }
  size_t deliver_prepared_hands() { return rhi_fake::ros::deliver<HandStateMsg>(kHandStateTopic, hand_state_msg_); }
  // The last HandCommandArray the robot received (false before the first).
  bool last_hand_command(HandCommandMsg& out) const {
    return rhi_fake::ros::last_published<HandCommandMsg>(kHandCommandTopic, out);
  }
  uint64_t sent_hand_messages() const { return rhi_fake::ros::publish_count(kHandCommandTopic); }
  // The last JointCommandArray of group g (false before the first).
  bool last_group_command(size_t g, CommandMsg& out) const {
    return rhi_fake::ros::last_published<CommandMsg>(kGroups[g].command_topic, out);
  }
#endif

  bool last_command(CommandFrame& out) {
    out.has_gains = true;
    out.present.fill(false);
    bool any = false;
    names_ok_ = true;
    for (size_t g = 0; g < kBodyGroupCount; ++g) {
      if (!rhi_fake::ros::last_published<CommandMsg>(kGroups[g].command_topic, cmd_msgs_[g])) {
        continue;
      }
      any = true;
      const CommandMsg& m = cmd_msgs_[g];
      if (m.joints.size() != kGroups[g].size) {
        names_ok_ = false;
      }
      for (size_t p = 0; p < m.joints.size() && p < kGroups[g].size; ++p) {
        const size_t slot = kGroups[g].offset + p;
        const Joint* j = joint_of_slot(slot);
        // AimDK names every entry: the name must be the joint the YAML maps to this slot.
        if (m.joints[p].name != (j != nullptr ? j->name : "")) {
          names_ok_ = false;
        }
        out.q[slot] = m.joints[p].position;
        out.dq[slot] = m.joints[p].velocity;
        out.tau[slot] = m.joints[p].effort;
        out.kp[slot] = m.joints[p].stiffness;
        out.kd[slot] = m.joints[p].damping;
        out.present[slot] = true;
      }
    }
#if defined(RHI_AIMDK_HANDS)
    // The hands: position targets only (the message's other fields are fixed; the hands section checks
    // them), so velocity, effort and gains are 0 here. Both sides must be OmniHands of 10 entries named
    // after the joints of their slots.
    if (rhi_fake::ros::last_published<HandCommandMsg>(kHandCommandTopic, hand_cmd_msg_)) {
      any = true;
      if (hand_cmd_msg_.left_hand_type.value != kOmniHandType || hand_cmd_msg_.right_hand_type.value != kOmniHandType) {
        names_ok_ = false;
      }
      for (size_t side = 0; side < 2; ++side) {
        const auto& hands = side == 0 ? hand_cmd_msg_.left_hands : hand_cmd_msg_.right_hands;
        if (hands.size() != kHandAxes) {
          names_ok_ = false;
        }
        for (size_t a = 0; a < hands.size() && a < kHandAxes; ++a) {
          const size_t slot = hand_slot(side, a);
          const Joint* j = joint_of_slot(slot);
          if (hands[a].name != (j != nullptr ? j->name : "")) {
            names_ok_ = false;
          }
          out.q[slot] = hands[a].position;
          out.dq[slot] = 0.0;
          out.tau[slot] = 0.0;
          out.kp[slot] = 0.0;
          out.kd[slot] = 0.0;
          out.present[slot] = true;
        }
      }
    }
#endif
    return any;
  }
  // True when every published group carried the right joint names in slot order.
  bool command_names_ok() const { return names_ok_; }
#if defined(RHI_TAKE_CONTROL)
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;
  ~Transport() {  // the servers' handlers point here
    rhi_fake::services::unserve(AimdkSystemStateServer::kMigrate);
    rhi_fake::services::unserve(AimdkSystemStateServer::kGetState);
  }
  AimdkSystemStateServer& system_state() { return system_state_; }
#endif

private:
  std::array<StateMsg, kBodyGroupCount> state_msgs_;
  std::array<StateMsg, kBodyGroupCount> rotated_msgs_;
  std::array<CommandMsg, kBodyGroupCount> cmd_msgs_;
#if defined(RHI_AIMDK_HANDS)
  HandStateMsg hand_state_msg_;
  HandCommandMsg hand_cmd_msg_;
#endif
  bool names_ok_{true};
#if defined(RHI_TAKE_CONTROL)
  AimdkSystemStateServer system_state_{[this]() { return sent_messages(); }};
#endif
};

}  // namespace rhi_test
