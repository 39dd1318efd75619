// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_TABLE_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_TABLE_HPP_

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "robot_hardware_interface/common/robot_spec.hpp"

namespace robot_hardware_interface
{

// Command limits of one SDK slot (URDF <limit>); infinite where there is none. A NaN target
// passes the clamp unchanged and is caught by the command guard.
struct SlotLimits
{
  double position_min;
  double position_max;
  double velocity;  // |velocity target| bound
  double effort;    // |feed-forward effort| bound
};

// The robot's joint table by SDK motor slot: what every slot drives, its limits, command mode and
// default gains. Built once from the RobotSpec, read-only afterwards (any thread may read it).
template<size_t N>
class SlotTable
{
public:
  explicit SlotTable(const RobotSpec & spec)
  : spec_(spec)
  {
    limits_.fill(SlotLimits{-kNoLimit, kNoLimit, kNoLimit, kNoLimit});
    joint_names_.fill("");
    modes_.fill(CommandMode::kPosition);
    default_stiffness_.fill(0.0);
    default_damping_.fill(0.0);
    mapped_slots_.reserve(spec.joint_count);
    commanded_slots_.reserve(spec.joint_count);
    for (size_t i = 0; i < spec.joint_count; ++i) {
      const JointSpec & joint = spec.joints[i];
      limits_[joint.slot] = SlotLimits{
        joint.position_min, joint.position_max, joint.velocity_max, joint.effort_max};
      joint_names_[joint.slot] = joint.name;
      modes_[joint.slot] = joint.mode;
      // No gains travel to a position-target joint: its default gains are zero.
      const bool gains = joint.mode != CommandMode::kPositionTarget;
      default_stiffness_[joint.slot] = gains ? joint.default_stiffness : 0.0;
      default_damping_[joint.slot] = gains ? joint.default_damping : 0.0;
      mapped_slots_.push_back(joint.slot);
      if (joint.mode != CommandMode::kStateOnly) {
        commanded_slots_.push_back(joint.slot);
      }
      if (joint.mode == CommandMode::kVelocity) {
        velocity_slots_[velocity_slot_count_++] = joint.slot;
      }
    }
    std::sort(mapped_slots_.begin(), mapped_slots_.end());
    std::sort(commanded_slots_.begin(), commanded_slots_.end());
  }

  // SDK slots that drive a URDF joint, ascending.
  const std::vector<size_t> & mapped_slots() const {return mapped_slots_;}
  // SDK slots whose joint this driver commands (all mapped slots but state-only ones), ascending.
  const std::vector<size_t> & commanded_slots() const {return commanded_slots_;}
  // URDF joint name of every slot ("" where the slot drives no joint).
  const std::array<const char *, N> & slot_joint_names() const {return joint_names_;}
  const SlotLimits & limits(size_t slot) const {return limits_[slot];}
  CommandMode mode_of(size_t slot) const {return modes_[slot];}
  double default_stiffness(size_t slot) const {return default_stiffness_[slot];}
  double default_damping(size_t slot) const {return default_damping_[slot];}
  // Slots of velocity-commanded joints: the first velocity_slot_count() entries.
  const std::array<size_t, N> & velocity_slots() const {return velocity_slots_;}
  size_t velocity_slot_count() const {return velocity_slot_count_;}

  // The SDK motor slot of a URDF joint, -1 for none.
  int slot_of(const std::string & joint_name) const
  {
    for (size_t i = 0; i < spec_.joint_count; ++i) {
      if (joint_name == spec_.joints[i].name) {
        return static_cast<int>(spec_.joints[i].slot);
      }
    }
    return -1;
  }

  // Position-commanded joints without default stiffness: limp under a position-only controller.
  size_t joints_without_default_stiffness() const
  {
    size_t count = 0;
    for (const size_t slot : mapped_slots_) {
      const bool position = modes_[slot] == CommandMode::kPosition;
      count += (position && default_stiffness_[slot] <= 0.0) ? 1U : 0U;
    }
    return count;
  }

private:
  const RobotSpec & spec_;
  std::array<SlotLimits, N> limits_{};
  std::array<const char *, N> joint_names_{};
  std::array<CommandMode, N> modes_{};
  std::array<double, N> default_stiffness_{};
  std::array<double, N> default_damping_{};
  std::vector<size_t> mapped_slots_;
  std::vector<size_t> commanded_slots_;
  std::array<size_t, N> velocity_slots_{};
  size_t velocity_slot_count_{0};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_TABLE_HPP_
