// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__STATE_FRESHNESS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__STATE_FRESHNESS_HPP_

#include <atomic>
#include <cstdint>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/common/monitor.hpp"

namespace robot_hardware_interface
{

// How new the newest valid state is, and which frames of a single state stream are parsed
// (decimation). The state thread writes it; the command writer asks whether the state is stale.
class StateFreshness
{
public:
  // on_activate (no transport thread runs): nothing of the previous activation counts; the wait
  // for its first state starts now.
  void reset()
  {
    activated_ns_.store(steady_now_ns(), std::memory_order_relaxed);
    last_state_time_ns_.store(0);
    frame_counter_.store(0);
    frames_valid_ = false;
  }

  // State thread: true when this frame must be parsed (`first`: the first of an activation always
  // is). A skipped frame still proves that state arrives: it keeps the state fresh, unless the
  // last parsed frame was rejected.
  bool start_frame(bool first, uint32_t decimation)
  {
    const uint32_t frame_count = frame_counter_.fetch_add(1, std::memory_order_relaxed);
    if (first || (frame_count % decimation) == 0U) {
      return true;
    }
    if (frames_valid_) {
      mark_fresh(steady_now_ns());
    }
    return false;
  }

  // State thread: the parsed frame stamped `state_time_ns` (steady time) is valid.
  void accept(int64_t state_time_ns)
  {
    frames_valid_ = true;
    mark_fresh(state_time_ns);
  }

  // State thread: the parsed frame is invalid; until one is accepted again, skipped frames no
  // longer keep the state fresh. Returns the count of rejected frames.
  uint64_t reject()
  {
    frames_valid_ = false;
    return invalid_states_.add();
  }

  // Any thread: rejected state frames since on_init (the health GPIO's invalid_states).
  const HealthCounter & invalid_states() const {return invalid_states_;}

  // IMU callback: a rejected sample; returns the count.
  uint64_t reject_imu() {return ++invalid_imu_count_;}

  // Any thread: valid state messages since on_init (each group's message, for a transport that
  // sends the state in parts), for the link's message rate on /diagnostics.
  const HealthCounter & valid_messages() const {return valid_messages_;}

  // State thread: a valid state message; the newest valid state is this old (steady time):
  // multi-stream transports report the age of their oldest stream here.
  void mark_fresh(int64_t state_time_ns)
  {
    valid_messages_.add();
    last_state_time_ns_.store(state_time_ns, std::memory_order_release);
  }

  // Writer thread: no valid state for more than `timeout_ms`.
  bool stale(uint64_t timeout_ms) const
  {
    const int64_t age_ns = steady_now_ns() - last_state_time_ns_.load(std::memory_order_acquire);
    return age_ns > static_cast<int64_t>(timeout_ms) * 1000000;
  }

  // Any thread, at steady time `now_ns`: nanoseconds without a valid state, counted from
  // the newest valid state or, before the first one, from the activation (a robot that never
  // answers is as dead as one that stopped answering); -1 before any state or activation.
  int64_t silence_ns(int64_t now_ns) const
  {
    const int64_t last_ns = last_state_time_ns_.load(std::memory_order_acquire);
    const int64_t activated_ns = activated_ns_.load(std::memory_order_relaxed);
    const int64_t since_ns = last_ns > activated_ns ? last_ns : activated_ns;
    return since_ns == 0 ? -1 : now_ns - since_ns;
  }

private:
  std::atomic<int64_t> last_state_time_ns_{0};  // steady time of the newest valid state
  std::atomic<uint32_t> frame_counter_{0};      // decimation frame counter
  std::atomic<int64_t> activated_ns_{0};        // steady time of the last reset() (any reader)
  bool frames_valid_{false};                    // state thread: the last parsed frame was valid
  HealthCounter invalid_states_;                // state thread: rejected frames
  HealthCounter valid_messages_;                // state thread: mark_fresh() calls
  uint64_t invalid_imu_count_{0};               // IMU callback: rejected samples
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__STATE_FRESHNESS_HPP_
