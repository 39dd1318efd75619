// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__SAFE_START_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__SAFE_START_HPP_

#include <atomic>

namespace robot_hardware_interface
{

// Where an activation stands in the three-layer safe start (DriverCore runs the layers):
//   (1) the command writer sends nothing before the first valid state of the activation;
//   (2) that first state seeds the command buffer with "hold the measured position, gains zero";
//   (3) write() forwards nothing until read() has copied a state of this activation, and its first
//       command is the measured position with zero gains.
class SafeStart
{
public:
  // on_activate: re-arm every layer (no transport thread runs).
  void reset()
  {
    first_state_received_.store(false);
    command_initialized_.store(false);
    state_copied_.store(false);
  }

  // Layers 1 and 2: the state thread published the first valid state and seeded the command
  // buffer (release: whoever sees the flag sees that command and that state).
  bool first_state_received() const {return first_state_received_.load(std::memory_order_acquire);}
  void mark_first_state_received() {first_state_received_.store(true, std::memory_order_release);}

  // Layer 3, controller thread only.
  bool state_copied() const {return state_copied_.load(std::memory_order_relaxed);}
  void mark_state_copied() {state_copied_.store(true, std::memory_order_relaxed);}
  bool command_initialized() const {return command_initialized_.load(std::memory_order_relaxed);}
  void mark_command_initialized() {command_initialized_.store(true, std::memory_order_relaxed);}

private:
  std::atomic<bool> first_state_received_{false};  // layers 1/2: a valid state of this activation
  std::atomic<bool> command_initialized_{false};   // layer 3: write() seeded its command
  std::atomic<bool> state_copied_{false};          // layer 3: read() copied a current state
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__SAFE_START_HPP_
