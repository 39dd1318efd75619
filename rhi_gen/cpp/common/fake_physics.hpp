// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_HPP_

// The fake robot's physics as its executable chooses it (--physics vacuum|mujoco, --base
// free|band|fixed), without MuJoCo: what fake_robot.hpp and fake_robot_main.hpp need whether or
// not the package was built with MuJoCo. The physics itself is fake_physics_mujoco.hpp.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace robot_hardware_interface
{

// How the robot's root link is held.
enum class FakeBase
{
  kFree,   // a free joint: the robot stands or falls on the floor
  kBand,   // free, held up by an elastic band until release_band()
  kFixed,  // no floating base: the root link is welded to the world
};

// How a motor drives its joint: motor = gain * (joint - offset); the joint's torque is gain times
// the motor's.
struct FakeTransmission
{
  double gain{1.0};    // direction * reduction
  double offset{0.0};  // [rad or m] the joint's value at motor zero
};

// A collision shape the vendor YAML's `contacts` give a link, in the URDF's terms: where the
// vendor's URDF collides with meshes (feet), the vendor's own MuJoCo model's primitives stand in
// for them when the meshes are not installed (fake_physics_mujoco.hpp).
enum class FakeContactShape { kSphere, kBox, kCylinder };

struct FakeContactGeom
{
  const char * link;            // URDF link
  FakeContactShape shape;
  // sphere {radius}; box {x, y, z} (full lengths); cylinder {radius, length} [m]
  std::array<double, 3> size;
  std::array<double, 3> xyz;    // [m] the shape's origin in the link's frame (URDF <origin xyz>)
  std::array<double, 3> rpy;    // [rad] its orientation (URDF <origin rpy>: fixed-axis x, y, z)
};

struct FakePhysicsOptions
{
  // "free" | "band" | "fixed" -> FakeBase; false for anything else. (Members, not free functions:
  // the package namespace keeps no name a vendor could want, rhi_gen/model/naming.py.)
  static bool parse_base(const char * text, FakeBase * base)
  {
    if (std::strcmp(text, "free") == 0) {
      *base = FakeBase::kFree;
    } else if (std::strcmp(text, "band") == 0) {
      *base = FakeBase::kBand;
    } else if (std::strcmp(text, "fixed") == 0) {
      *base = FakeBase::kFixed;
    } else {
      return false;
    }
    return true;
  }
  static const char * base_name(FakeBase base)
  {
    return base == FakeBase::kFree ? "free" : base == FakeBase::kBand ? "band" : "fixed";
  }

  std::string urdf_path;          // the package's installed URDF
  FakeBase base{FakeBase::kBand};
  double timestep{0.001};         // [s] one physics step: 1 kHz (at most kLongestTimestep)
  // Rotor inertia reflected to each joint of the table [kg m^2] (slider: [kg]): FakeJointSpec's
  // armature, unless this has one value per joint of the table (FakeJointSpec order).
  std::vector<double> armatures;
  // One per joint of the table (FakeJointSpec order), or none: every motor is its joint.
  std::vector<FakeTransmission> transmissions;
  // Added to their links when a mesh is missing and the mesh geoms are left out (see
  // FakeContactGeom); none: the robot's own (FakePhysicsSpec::contacts).
  std::vector<FakeContactGeom> contacts;
  std::string imu_link;           // URDF link of the IMU; "" = the root link
  // ':'-separated prefixes to resolve package:// under: a ROS 2 executable passes
  // AMENT_PREFIX_PATH (<prefix>/share/<package>/ is where colcon installs a package's files).
  std::string package_path;
  // The band: stiffness [N/m] and damping [N s/m]; 0 = the robot's weight stretches it by
  // kBandSagDefault, critically damped for the robot's mass (the damping is bounded to what an
  // explicit force on the root link can take at the timestep). Its anchor is above where it
  // starts by the stretch of the robot's full weight, so a robot hanging in it hangs there.
  double band_stiffness{0.0};
  double band_damping{0.0};
  // [m] how far above the robot's centre of mass the band holds it: above it, the robot hangs
  // upright (held at its root link's origin, a humanoid's pelvis, it would topple about it).
  double band_arm{0.5};
  // free and band: the robot starts with its lowest point this high above the floor [m].
  double start_clearance{0.0};
  // Whether the robot's links collide with each other (the floor always collides with them).
  // Off by default: collision meshes of neighbouring links often overlap where the URDF puts
  // them, and MuJoCo then pushes them apart as hard as it can.
  bool self_collision{false};
};

// The IMU as the simulation measures it (fake_physics_mujoco.hpp), or at rest: level, gravity on
// the accelerometer.
struct FakeImuReading
{
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z: the link in the world
  std::array<double, 3> angular_velocity{};               // [rad/s] in the link's frame
  std::array<double, 3> linear_acceleration{};            // [m/s^2] in the link's frame, gravity in

  // Into a message's geometry_msgs fields (sensor_msgs/Imu: orientation, angular_velocity,
  // linear_acceleration).
  template<typename Quaternion, typename Vector3>
  void to_ros(Quaternion & q, Vector3 & gyro, Vector3 & acc) const
  {
    q.w = orientation[0];
    q.x = orientation[1];
    q.y = orientation[2];
    q.z = orientation[3];
    gyro.x = angular_velocity[0];
    gyro.y = angular_velocity[1];
    gyro.z = angular_velocity[2];
    acc.x = linear_acceleration[0];
    acc.y = linear_acceleration[1];
    acc.z = linear_acceleration[2];
  }

  // Roll, pitch, yaw [rad] of the orientation (z-y-x Euler angles), for messages that carry them.
  std::array<double, 3> rpy() const
  {
    const double w = orientation[0];
    const double x = orientation[1];
    const double y = orientation[2];
    const double z = orientation[3];
    return {std::atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y)),
      std::asin(std::clamp(2.0 * (w * y - z * x), -1.0, 1.0)),
      std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))};
  }
};

// What the robot's own source (src/<vendor>/<robot>_fake_robot.cpp) tells the physics about it.
struct FakePhysicsSpec
{
  const char * urdf;      // its URDF in the package's share folder ("urdf/<robot>.urdf")
  const char * imu_link;  // the URDF link of its IMU ("": its root link)
  // One per joint of the table (FakeJointSpec order), or nullptr: every motor is its joint.
  const FakeTransmission * transmissions;
  // The vendor YAML's contacts (FakeContactGeom), contact_count of them (nullptr: none).
  const FakeContactGeom * contacts;
  size_t contact_count;
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_PHYSICS_HPP_
