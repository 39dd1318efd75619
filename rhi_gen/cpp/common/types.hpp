// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__TYPES_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__TYPES_HPP_

#include <array>
#include <cstddef>

#include <hardware_interface/types/hardware_interface_return_values.hpp>
#include <rclcpp_lifecycle/node_interfaces/lifecycle_node_interface.hpp>

namespace robot_hardware_interface
{

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
using return_type = hardware_interface::return_type;

// ros2_control storage of every joint, by SDK motor slot: one array per interface (a structure of
// arrays, so that read() and write() convert whole arrays in vector registers). The exported
// interfaces point into these doubles, so they are only touched from the controller thread
// (read() / write()).
template<size_t N>
struct JointStorage
{
  std::array<double, N> pos{};      // state: position [rad or m]
  std::array<double, N> vel{};      // state: velocity
  std::array<double, N> tau{};      // state: effort
  std::array<double, N> pos_des{};  // command: position target
  std::array<double, N> vel_des{};  // command: velocity target
  std::array<double, N> kp{};       // command: stiffness
  std::array<double, N> kd{};       // command: damping
  std::array<double, N> ff{};       // command: feed-forward effort
};

// ros2_control storage of the IMU, in the order of the exported interfaces.
struct ImuData
{
  double orientation[4]{0.0, 0.0, 0.0, 0.0};  // x, y, z, w (all zero until the first sample)
  double angular_velocity[3]{0.0, 0.0, 0.0};     // [rad/s]
  double linear_acceleration[3]{0.0, 0.0, 0.0};  // [m/s^2]
};

// IMU sample as handed from a transport callback to read(). Quaternion order is w, x, y, z
// whatever the SDK uses; read() reorders it once for ros2_control.
struct ImuState
{
  std::array<double, 4> quat{};   // w, x, y, z
  std::array<double, 3> omega{};  // angular velocity [rad/s]
  std::array<double, 3> acc{};    // linear acceleration [m/s^2]
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__TYPES_HPP_
