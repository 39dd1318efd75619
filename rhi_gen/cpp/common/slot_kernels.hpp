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
// so no scalar remainder loop and no run-time alias check is needed. Each conversion is one
// kernel over all N slots (the *_slots functions below), its blocks inlined into it: one call per
// frame, not one per block. With GCC on x86-64 Linux the kernels are also built for AVX2 and the
// CPU picks the build at load time (an ifunc, as glibc does for memcpy); not under
// ThreadSanitizer, whose runtime is not ready when ifuncs resolve.
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__) && \
  !defined(__SANITIZE_THREAD__)
#define ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
#endif

// The conversions of a robot whose motors are not its joints are called out of line, behind a
// branch marked unlikely, so that every other robot's read() and write() stay the plain loops.
#if defined(__GNUC__)
#define ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE __attribute__((noinline))
#define ROBOT_HARDWARE_INTERFACE_UNLIKELY(condition) __builtin_expect(!!(condition), 0)
#else
#define ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE
#define ROBOT_HARDWARE_INTERFACE_UNLIKELY(condition) (condition)
#endif

// The blocks of a kernel, and the loop over them, are always inlined into the kernel: only there
// are they compiled for the kernel's target (AVX2 above); a block left out of line would be the
// baseline build.
#if defined(__GNUC__)
#define ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK inline __attribute__((always_inline))
#define ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA __attribute__((always_inline))
#else
#define ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK inline
#define ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA
#endif

constexpr size_t kSlotBlock = 8;

// Calls kernel(count, begin) over [0, N): whole blocks of kSlotBlock slots, then, when N is not a
// multiple of it, one last block ending at N that overlaps the one before. Kernels are pure per
// slot (what they write never feeds what they read), so a slot done twice gets the same value.
// `count` is a std::integral_constant: the block size, or N for robots with fewer slots.
template<size_t N, typename Kernel>
ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK void for_each_slot_block(Kernel && kernel)
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

// What write() works on: one object, so that the compiler sees that no two arrays overlap. The
// frame write() hands to the command writer is built in the command buffer's slot (__restrict).
template<size_t N, typename T>
struct ControllerFrames
{
  JointStorage<N> joints;      // the exported doubles (read() fills the state ones)
  MotorCommand<N, T> lower;    // per-slot bounds of every command value
  MotorCommand<N, T> upper;
};

// read(): `Count` slots of a state frame, from `begin`, into the exported doubles.
template<size_t Count, size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK void copy_state_block(
  const MotorState<N, T> & __restrict state, JointStorage<N> & __restrict joints, size_t begin)
{
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    joints.pos[i] = static_cast<double>(state.q[i]);
    joints.vel[i] = static_cast<double>(state.dq[i]);
    joints.tau[i] = static_cast<double>(state.tau[i]);
  }
}

// Per slot, how the joint follows its motor (JointTransmissions builds it): joint = scale * motor +
// offset, scale = direction / reduction; `inverse` = 1 / scale. The identity for an unmapped slot
// and for a coupled joint (its group's matrix is applied after these kernels).
template<size_t N>
struct TransmissionFactors
{
  std::array<double, N> scale{};
  std::array<double, N> offset{};
  std::array<double, N> inverse{};
};

// read() on a robot with transmissions: copy_state_block through the factors (effort: power is
// conserved, so it scales by the inverse).
template<size_t Count, size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK void transmit_state_block(
  const MotorState<N, T> & __restrict state, const TransmissionFactors<N> & __restrict factors,
  JointStorage<N> & __restrict joints, size_t begin)
{
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    joints.pos[i] = factors.scale[i] * static_cast<double>(state.q[i]) + factors.offset[i];
    joints.vel[i] = factors.scale[i] * static_cast<double>(state.dq[i]);
    joints.tau[i] = factors.inverse[i] * static_cast<double>(state.tau[i]);
  }
}

// write() on a robot with transmissions: the bounded joint-space command, in place, into motor
// space. The motor's PD law reproduces the joint's: kp and kd scale by scale^2, the feed-forward
// effort by scale. Signs are kept (a negative gain stays negative for the command guard), NaN
// stays NaN.
template<size_t Count, size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK void transmit_command_block(
  const TransmissionFactors<N> & __restrict factors, MotorCommand<N, T> & __restrict command,
  size_t begin)
{
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    const double scale = factors.scale[i];
    const double inverse = factors.inverse[i];
    command.q_target[i] =
      static_cast<T>((static_cast<double>(command.q_target[i]) - factors.offset[i]) * inverse);
    command.dq_target[i] = static_cast<T>(static_cast<double>(command.dq_target[i]) * inverse);
    command.kp[i] = static_cast<T>(static_cast<double>(command.kp[i]) * (scale * scale));
    command.kd[i] = static_cast<T>(static_cast<double>(command.kd[i]) * (scale * scale));
    command.tau_ff[i] = static_cast<T>(static_cast<double>(command.tau_ff[i]) * scale);
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
ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK void bound_command_block(
  const ControllerFrames<N, T> & __restrict frames, MotorCommand<N, T> & __restrict command,
  size_t begin)
{
  const JointStorage<N> & joints = frames.joints;
  const MotorCommand<N, T> & lower = frames.lower;
  const MotorCommand<N, T> & upper = frames.upper;
  for (size_t k = 0; k < Count; ++k) {
    const size_t i = begin + k;
    command.q_target[i] = bounded(joints.pos_des[i], lower.q_target[i], upper.q_target[i]);
    command.dq_target[i] = bounded(joints.vel_des[i], lower.dq_target[i], upper.dq_target[i]);
    command.kp[i] = bounded(joints.kp[i], lower.kp[i], upper.kp[i]);
    command.kd[i] = bounded(joints.kd[i], lower.kd[i], upper.kd[i]);
    command.tau_ff[i] = bounded(joints.ff[i], lower.tau_ff[i], upper.tau_ff[i]);
  }
}

// The kernels read() and write() call: each block function above over all N slots, in one call.

// read(): the state frame into the exported doubles.
template<size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void copy_state_slots(
  const MotorState<N, T> & __restrict state, JointStorage<N> & __restrict joints)
{
  for_each_slot_block<N>(
    [&](auto count, size_t begin) ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA {
      copy_state_block<decltype(count)::value>(state, joints, begin);
    });
}

// read() on a robot with transmissions: the state frame through the factors.
template<size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void transmit_state_slots(
  const MotorState<N, T> & __restrict state, const TransmissionFactors<N> & __restrict factors,
  JointStorage<N> & __restrict joints)
{
  for_each_slot_block<N>(
    [&](auto count, size_t begin) ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA {
      transmit_state_block<decltype(count)::value>(state, factors, joints, begin);
    });
}

// write(): every slot of `command` (all of it: it may hold an older frame) from the exported
// command doubles, bounded.
template<size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void bound_command_slots(
  const ControllerFrames<N, T> & __restrict frames, MotorCommand<N, T> & __restrict command)
{
  for_each_slot_block<N>(
    [&](auto count, size_t begin) ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA {
      bound_command_block<decltype(count)::value>(frames, command, begin);
    });
}

// write() on a robot with transmissions: the bounded command, in place, into motor space.
template<size_t N, typename T>
ROBOT_HARDWARE_INTERFACE_SLOT_KERNEL
void transmit_command_slots(
  const TransmissionFactors<N> & __restrict factors, MotorCommand<N, T> & __restrict command)
{
  for_each_slot_block<N>(
    [&](auto count, size_t begin) ROBOT_HARDWARE_INTERFACE_SLOT_BLOCK_LAMBDA {
      transmit_command_block<decltype(count)::value>(factors, command, begin);
    });
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__SLOT_KERNELS_HPP_
