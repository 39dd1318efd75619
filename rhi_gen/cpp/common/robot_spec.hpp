// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__ROBOT_SPEC_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__ROBOT_SPEC_HPP_

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

namespace robot_hardware_interface
{

// A limit the URDF does not give.
constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// How ros2_control commands a joint: a position-commanded joint takes the motor's whole PD command
// (position, velocity, stiffness, damping, effort); a velocity-commanded one (a wheel) velocity,
// damping and effort, never a position target or stiffness. A state-only joint takes no command:
// the robot's own controller keeps it (authority upper_body: the legs under the vendor's balance
// controller), so it exports state interfaces only and its motor never hears from this driver.
// A position-target joint takes a position target and nothing else: the robot's own controller
// tracks it (an AgiBot OmniHand axis), so no gains, velocity or effort travel and it exports the
// position command interface alone; bounds and holds are a position-commanded joint's.
enum class CommandMode : uint8_t
{
  kPosition,
  kVelocity,
  kStateOnly,
  kPositionTarget,
};

// Whether ros2_control commands the joint's position (bounded by its URDF limits).
constexpr bool takes_position(CommandMode mode)
{
  return mode == CommandMode::kPosition || mode == CommandMode::kPositionTarget;
}

// One URDF joint driven by one SDK motor slot, with the URDF limits write() clamps to and the
// gains applied while a controller commands the joint without claiming them.
struct JointSpec
{
  const char * name;         // URDF joint name, as the ros2_control description names it
  size_t slot;               // SDK motor slot
  CommandMode mode;
  double position_min;       // URDF <limit lower>, -kNoLimit when there is none
  double position_max;       // URDF <limit upper>, kNoLimit when there is none
  double velocity_max;       // bound of |velocity target|
  double effort_max;         // bound of |feed-forward effort|
  double default_stiffness;  // vendor YAML default_gains: kp while stiffness is not claimed
  double default_damping;    // kd while damping is not claimed
  size_t motor_group;        // its motor's /diagnostics status: index into RobotSpec::motor_groups
};

// /diagnostics has one status per motor group, the joints by limb ("left leg motors"): at most
// this many (rhi_gen/model/motor_groups.py MAX_MOTOR_GROUPS: 7 sides by 6 limbs).
inline constexpr size_t kMaxMotorGroups = 48;

// How the command leaves the driver (hardware parameter command_writer_mode).
enum class CommandWriterMode : uint8_t
{
  kTimer,    // "timer": the transport's writer sends every command_writer_period_us
  kOnWrite,  // "on_write": sent as soon as write() has built it (command_writer.hpp)
};

// Defaults of the <hardware> parameters (the vendor YAML's `parameters`).
struct ParameterDefaults
{
  const char * network_interface;
  bool enable_monitor;
  uint64_t command_writer_period_us;
  CommandWriterMode command_writer_mode;
  uint32_t state_decimation;
  uint64_t state_timeout_ms;
  uint64_t fault_timeout_ms;
  uint64_t first_state_timeout_ms;     // after activation, until the robot's first state
  uint64_t diagnostics_period_ms;      // 0: no /diagnostics
  uint64_t motor_temperature_warn_c;   // /diagnostics levels of the motors
  uint64_t motor_temperature_error_c;
  uint64_t motor_error_fault_mask;     // motor error code bits that fault the robot, 0: none do
};

// Everything the driver core needs to know about one robot; each robot's source file defines one.
struct RobotSpec
{
  const char * plugin_name;  // "<vendor>/<Robot>HardwareInterface", for log lines
  const char * node_name;    // "<robot>_hardware_interface"
  const JointSpec * joints;  // URDF order
  size_t joint_count;
  const char * imu_name;     // sensor name of the IMU interfaces; nullptr: the robot has no IMU
  std::array<const char *, kMaxMotorGroups> motor_groups;  // names; nullptr after the last
  ParameterDefaults parameters;
  // The controllers launch/<robot>.launch.py activates, space-separated: what the error line of a
  // fault tells the operator to activate again after the recovery; nullptr: none named.
  const char * launch_controllers{nullptr};
};

// How one joint follows its motor, ros2_control's SimpleTransmission convention:
// joint = direction * motor / reduction + offset; velocity without the offset; effort times
// direction * reduction (power is conserved). A coupled joint (CoupledJointsSpec) has direction 1
// and reduction 1 here: its group's matrix says how it follows the motors, `offset` is its zero.
struct JointTransmissionSpec
{
  size_t slot;       // the joint's SDK motor slot
  double direction;  // +1 or -1
  double reduction;  // motor turns per joint turn, > 0
  double offset;     // joint value at motor zero [rad or m]
};

// n joints driven by n motors through a constant matrix (a differential wrist, a parallel ankle):
// joint = matrix * motor + offset, where motor k is the SDK slot of joint k (ros2_control's
// DifferentialTransmission is one such matrix). Velocities map by the same matrix, efforts by its
// inverse transpose.
struct CoupledJointsSpec
{
  const char * name;      // the group's name, for log lines
  size_t size;            // n
  const size_t * slots;   // the joints' SDK slots, n of them: rows of the matrix and its motors
  const double * matrix;  // n x n, row-major: joint per motor
};

// The robot's transmissions: only joints that are not their motor are listed (and every joint of
// a coupled group, for its offset). A robot without any has none (nullptr in SystemDriver).
struct TransmissionSpec
{
  const JointTransmissionSpec * joints;
  size_t joint_count;
  const CoupledJointsSpec * groups;
  size_t group_count;
};

// True when every joint has its own slot below `motor_count`: robot sources static_assert it.
template<size_t M>
constexpr bool slots_are_valid(const std::array<JointSpec, M> & joints, size_t motor_count)
{
  for (size_t i = 0; i < M; ++i) {
    if (joints[i].slot >= motor_count) {
      return false;
    }
    for (size_t j = 0; j < i; ++j) {
      if (joints[j].slot == joints[i].slot) {
        return false;
      }
    }
  }
  return true;
}

// The spec's joint_index_map (URDF joint name -> SDK motor slot), built from a joint table.
template<size_t M>
std::map<std::string, size_t> make_joint_index_map(const std::array<JointSpec, M> & joints)
{
  std::map<std::string, size_t> map;
  for (const JointSpec & joint : joints) {
    map.emplace(joint.name, joint.slot);
  }
  return map;
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__ROBOT_SPEC_HPP_
