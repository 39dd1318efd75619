// Fake robot side of the agibot_topics transport (aimdk_msgs): one JointStateArray per joint
// group (entry p of group g is SDK slot offset_g + p, named after the joint the YAML maps there),
// sensor_msgs/Imu, one JointCommandArray per group out.
#pragma once

#include <array>

#include <aimdk_msgs/msg/joint_command_array.hpp>
#include <aimdk_msgs/msg/joint_state_array.hpp>

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

  Transport() {
#if defined(RHI_TAKE_CONTROL)
    system_state_.serve();  // every section's activation takes control first
#endif
    for (size_t g = 0; g < kGroupCount; ++g) {
      state_msgs_[g].joints.resize(kGroups[g].size);
      for (size_t p = 0; p < kGroups[g].size; ++p) {
        const Joint* j = joint_of_slot(kGroups[g].offset + p);
        state_msgs_[g].joints[p].name = j != nullptr ? j->name : "";
      }
    }
  }

  void prepare_state(const StateFrame& f) {
    for (size_t g = 0; g < kGroupCount; ++g) {
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
    prepare_ros_imu(f);
  }
  // Every group, in group order; returns the number of groups that reached a subscription.
  size_t deliver_prepared() {
    size_t reached = 0;
    for (size_t g = 0; g < kGroupCount; ++g) {
      reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]) > 0 ? 1U : 0U;
    }
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
  // single group: a non-finite position).
  size_t deliver_invalid_state(const StateFrame& f) {
    prepare_state(f);
    if (kGroupCount > 1) {
      size_t reached = 0;
      for (size_t g = 0; g + 1 < kGroupCount; ++g) {
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
  // (p + rotate) % size, its name and its values): a publisher that changed its joint order.
  size_t deliver_rotated(const StateFrame& f, size_t rotate) {
    prepare_state(f);
    size_t reached = 0;
    for (size_t g = 0; g < kGroupCount; ++g) {
      StateMsg& m = rotated_msgs_[g];
      m = state_msgs_[g];
      const size_t size = kGroups[g].size;
      for (size_t p = 0; p < size; ++p) {
        m.joints[p] = state_msgs_[g].joints[(p + rotate) % size];
      }
      reached += rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, m) > 0 ? 1U : 0U;
    }
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
    for (size_t g = 1; g < kGroupCount; ++g) {
      rhi_fake::ros::deliver<StateMsg>(kGroups[g].state_topic, state_msgs_[g]);
    }
    return true;
  }
  // The motor slots of group 0 (the one deliver_with_duplicate() corrupts).
  static bool in_first_group(size_t slot) { return slot >= kGroups[0].offset && slot < kGroups[0].offset + kGroups[0].size; }

  uint64_t sent_messages() const {
    uint64_t total = 0;
    for (size_t g = 0; g < kGroupCount; ++g) {
      total += rhi_fake::ros::publish_count(kGroups[g].command_topic);
    }
    return total;
  }
  static constexpr size_t command_messages_per_cycle() { return kGroupCount; }

  bool last_command(CommandFrame& out) {
    out.has_gains = true;
    out.present.fill(false);
    bool any = false;
    names_ok_ = true;
    for (size_t g = 0; g < kGroupCount; ++g) {
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
  std::array<StateMsg, kGroupCount> state_msgs_;
  std::array<StateMsg, kGroupCount> rotated_msgs_;
  std::array<CommandMsg, kGroupCount> cmd_msgs_;
  bool names_ok_{true};
#if defined(RHI_TAKE_CONTROL)
  AimdkSystemStateServer system_state_{[this]() { return sent_messages(); }};
#endif
};

}  // namespace rhi_test
