// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__MOTOR_TYPES_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__MOTOR_TYPES_HPP_

#include <array>
#include <cstddef>

namespace robot_hardware_interface
{

// One command frame for N motors in the SDK's scalar type T, indexed by SDK motor slot.
// The SDK's PD law: tau = kp * (q_target - q) + kd * (dq_target - dq) + tau_ff.
template<size_t N, typename T = float>
struct MotorCommand
{
  std::array<T, N> q_target{};
  std::array<T, N> dq_target{};
  std::array<T, N> kp{};
  std::array<T, N> kd{};
  std::array<T, N> tau_ff{};
};

// One state frame for N motors in the SDK's scalar type T, indexed by SDK motor slot.
template<size_t N, typename T = float>
struct MotorState
{
  std::array<T, N> q{};
  std::array<T, N> dq{};
  std::array<T, N> tau{};
};

// One IMU sample in the SDK's scalar type T (ImuState is the double one): quaternion w, x, y, z.
template<typename T = float>
struct ImuSample
{
  std::array<T, 4> quat{};
  std::array<T, 3> omega{};
  std::array<T, 3> acc{};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__MOTOR_TYPES_HPP_
