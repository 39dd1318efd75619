// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_ARM_SDK_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_ARM_SDK_HPP_

// Unitree's arm SDK (authority upper_body): the robot's own balance controller keeps the legs while
// this driver commands the arms and the waist. Facts from unitree_sdk2
// example/g1/high_level/g1_arm7_sdk_dds_example.cpp and h1_2_arm_sdk_dds_example.cpp: the hg
// LowCmd_ goes to "rt/arm_sdk" instead of "rt/lowcmd", and the q of the first unused motor slot
// (kNotUsedJoint: 29 on the G1, 27 on the H1-2) is the blend weight, 0 = the robot's controller,
// 1 = these commands. The examples change it by at most weight_rate * dt per message.

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace robot_hardware_interface
{

// transport_options of an upper_body robot.
struct UnitreeArmSdkOptions
{
  const char * topic;  // arm_sdk_topic: "rt/arm_sdk"
  size_t weight_slot;  // arm_sdk_weight_slot: the LowCmd_ slot whose q carries the weight
  double ramp_s;       // arm_sdk_ramp_s: seconds for the weight from 0 to 1, and from 1 to 0
};

// The blend weight, one step per command sent, never a jump: towards 1 while the controllers drive
// the upper body, towards 0 otherwise (a hold for stale state, error or e-stop; no controller
// driving; a deactivation). The writer thread's, and stop()'s once the writer has stopped.
class BlendWeight
{
public:
  BlendWeight() = default;
  BlendWeight(double ramp_s, uint64_t period_us)
  : step_(std::min(1.0, static_cast<double>(period_us) * 1e-6 / ramp_s))
  {
  }

  // The weight of the next command: one step towards 1 (`engage`) or towards 0.
  double next(bool engage)
  {
    weight_ = engage ? std::min(1.0, weight_ + step_) : std::max(0.0, weight_ - step_);
    return weight_;
  }
  double value() const {return weight_;}
  void reset() {weight_ = 0.0;}

  // Whether a command drives any of `slots` (a stiffness, a damping or a feed-forward effort):
  // only then may the weight hand the upper body to this driver. A command with all of them zero
  // (the safe start, no controller claiming) would let the arms fall.
  template<typename Command, typename Slots>
  static bool drives_any(const Command & cmd, const Slots & slots)
  {
    for (const size_t slot : slots) {
      if (cmd.kp[slot] > 0 || cmd.kd[slot] > 0 || cmd.tau_ff[slot] != 0) {
        return true;
      }
    }
    return false;
  }

private:
  double step_{1.0};
  double weight_{0.0};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_ARM_SDK_HPP_
