// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_KERNELS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_KERNELS_HPP_

#include <array>
#include <cstddef>
#include <type_traits>

#include "robot_hardware_interface/common/motor_types.hpp"
#include "robot_hardware_interface/common/types.hpp"

namespace robot_hardware_interface
{

// The per-slot conversions of read() and write(), written so that the compiler's default -O2
// cost model turns them into vector code: every loop has a constant trip count (a block of
// kSlotBlock slots) and the arrays it touches provably never overlap (one object, or __restrict),
// so no scalar remainder loop and no run-time alias check is needed. With GCC on x86-64 Linux the
// kernels are also built for AVX2 and the CPU picks the build at load time (an ifunc, as glibc
// does for memcpy); not under ThreadSanitizer, whose runtime is not ready when ifuncs resolve.
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__) && \
  !defined(__SANITIZE_THREAD__)
#define ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
#endif

constexpr size_t kSlotBlock = 8;

// Calls kernel(count, begin) over [0, N): whole blocks of kSlotBlock slots, then, when N is not a
// multiple of it, one last block ending at N that overlaps the one before. Kernels are pure per
// slot (what they write never feeds what they read), so a slot done twice gets the same value.
// `count` is a std::integral_constant: the block size, or N for robots with fewer slots.
template<size_t N, typename Kernel>
void for_each_slot_block(Kernel && kernel)
{
  if constexpr (N < kSlotBlock) {
    kernel(std::integral_constant<size_t, N>{}, size_t{0});
  } else {
    for (size_t begin = 0; begin + kSlotBlock <= N; begin += kSlotBlock) {
      kernel(std::integral_constant<size_t, kSlotBlock>{}, begin);
    }
    if constexpr (N % kSlotBlock != 0U) {
      kernel(std::integral_constant<size_t, kSlotBlock>{}, N - kSlotBlock);
    }
  }
}

// What write() works on: one object, so that the compiler sees that no two arrays overlap.
template<size_t N, typename T>
struct ControllerFrames
{
  JointStorage<N> joints;      // the exported doubles (read() fills the state ones)
  MotorCommand<N, T> lower;    // per-slot bounds of every command value
  MotorCommand<N, T> upper;
  MotorCommand<N, T> command;  // the frame write() hands to the command writer
};

// read(): `Count` slots of a state frame, from `begin`, into the exported doubles.
template<size_t Count, size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void copy_state_block(
  const MotorState<N, T> & __restrict state, JointStorage<N> & __restrict joints, size_t begin)
{
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    joints.pos[i] = static_cast<double>(state.q[i]);
    joints.vel[i] = static_cast<double>(state.dq[i]);
    joints.tau[i] = static_cast<double>(state.tau[i]);
  }
}

// `value` in T, within [lower, upper]. Rounding to T is monotonic, so this equals bounding in
// double and rounding after. A NaN stays NaN, for next_command() to reject.
template<typename T>
T bounded(double value, T lower, T upper)
{
  const T rounded = static_cast<T>(value);
  const T raised = rounded < lower ? lower : rounded;
  return upper < raised ? upper : raised;
}

// write(): `Count` slots of the command frame, from `begin`: every exported command double
// bounded by its slot's [lower, upper] (limits for a claimed interface, a fixed value for an
// unclaimed one).
template<size_t Count, size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void bound_command_block(ControllerFrames<N, T> & frames, size_t begin)
{
  const JointStorage<N> & joints = frames.joints;
  const MotorCommand<N, T> & lower = frames.lower;
  const MotorCommand<N, T> & upper = frames.upper;
  MotorCommand<N, T> & command = frames.command;
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    command.q_target[i] = bounded(joints.pos_des[i], lower.q_target[i], upper.q_target[i]);
    command.dq_target[i] = bounded(joints.vel_des[i], lower.dq_target[i], upper.dq_target[i]);
    command.kp[i] = bounded(joints.kp[i], lower.kp[i], upper.kp[i]);
    command.kd[i] = bounded(joints.kd[i], lower.kd[i], upper.kd[i]);
    command.tau_ff[i] = bounded(joints.ff[i], lower.tau_ff[i], upper.tau_ff[i]);
  }
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_KERNELS_HPP_
