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
// damping and effort, never a position target or stiffness.
enum class CommandMode : uint8_t
{
  kPosition,
  kVelocity,
};

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
};

// Defaults of the <hardware> parameters (the vendor YAML's `parameters`).
struct ParameterDefaults
{
  const char * network_interface;
  bool enable_monitor;
  uint64_t command_writer_period_us;
  uint32_t state_decimation;
  uint64_t state_timeout_ms;
};

// Everything the driver core needs to know about one robot; each robot's source file defines one.
struct RobotSpec
{
  const char * plugin_name;  // "<vendor>/<Robot>HardwareInterface", for log lines
  const char * node_name;    // "<robot>_hardware_interface"
  const JointSpec * joints;  // URDF order
  size_t joint_count;
  const char * imu_name;     // sensor name of the IMU interfaces; nullptr: the robot has no IMU
  ParameterDefaults parameters;
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
