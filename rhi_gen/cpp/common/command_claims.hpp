// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_CLAIMS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_CLAIMS_HPP_

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "robot_hardware_interface/common/data_buffer.hpp"
#include "robot_hardware_interface/common/motor_types.hpp"
#include "robot_hardware_interface/common/slot_kernels.hpp"
#include "robot_hardware_interface/common/slot_table.hpp"

namespace robot_hardware_interface
{

// Which command interfaces active controllers claim, and the command bounds that follow from
// them. Only claimed interfaces count: an unclaimed stiffness / damping is the joint's default
// gain while its position (or velocity) is claimed, and zero otherwise.
//
// Threads: the controller manager prepares and commits a mode switch (prepare_claims(),
// commit_claims(), non-real-time); write() takes and applies it at its next cycle
// (take_committed(), apply_committed(), the controller thread), never the switching thread, since
// write() may be running.
template<size_t N, typename T>
class CommandClaims
{
public:
  using Command = MotorCommand<N, T>;

  // One bit per command interface of a joint.
  static constexpr uint8_t kClaimPosition = 1U << 0;
  static constexpr uint8_t kClaimVelocity = 1U << 1;
  static constexpr uint8_t kClaimEffort = 1U << 2;
  static constexpr uint8_t kClaimStiffness = 1U << 3;
  static constexpr uint8_t kClaimDamping = 1U << 4;

  explicit CommandClaims(const SlotTable<N> & slots)
  : slots_(slots)
  {
  }

  // prepare_command_mode_switch: the claims after starting and stopping the given
  // "<joint>/<interface>" names; names of other components are ignored. Applied only if
  // commit_claims() follows.
  template<typename Names>
  void prepare_claims(const Names & start, const Names & stop)
  {
    Claims next = committed_;
    for (const auto & name : stop) {
      update_claim(next, name, false);
    }
    for (const auto & name : start) {
      update_claim(next, name, true);
    }
    next.generation = committed_.generation + 1;
    prepared_ = next;
    claims_prepared_.store(true, std::memory_order_release);
  }

  // on_configure after on_error: ros2_control deactivated every controller that used the component
  // when read() returned ERROR, without a mode switch (the one it attempts is refused: the
  // component's interfaces are already unavailable), so no claim survives the fault. Handed to
  // write() like a committed switch, so that the controllers activated after the recovery start
  // from nothing claimed: a position controller alone gets the default gains again, not the
  // stiffness a gain controller claimed before the fault. Not while a switch is prepared (the
  // controller manager serialises component state changes and switches).
  void release_all()
  {
    claims_prepared_.store(false, std::memory_order_relaxed);
    committed_.bits.fill(0U);
    ++committed_.generation;
    claim_buffer_.set_data(committed_);
  }

  // perform_command_mode_switch: hand the prepared claims to write().
  void commit_claims()
  {
    if (!claims_prepared_.exchange(false, std::memory_order_acquire)) {
      return;
    }
    committed_ = prepared_;
    claim_buffer_.set_data(committed_);
  }

  // Controller thread: adopt the claims a mode switch committed. True when a joint's claims
  // changed: then the claimed interfaces differ (SystemDriver fetches only those) and
  // apply_committed() resets the changed joints at its next call.
  bool take_committed()
  {
    const Claims * next = claim_buffer_.get_data();
    if (next == nullptr || next->generation == applied_generation_) {
      return false;
    }
    applied_generation_ = next->generation;
    bool changed = false;
    for (size_t i = 0; i < N; ++i) {
      if (next->bits[i] != claims_[i]) {
        claims_[i] = next->bits[i];
        changed_[i] = true;
        changed = true;
      }
    }
    unapplied_ = unapplied_ || changed;
    return changed;
  }

  // Controller thread (write(), after take_committed()): give every joint whose claims changed a
  // command that cannot jump or carry another controller's gains: target = measured position, no
  // velocity or effort, the default gains. Returns true when the storage changed.
  bool apply_committed(ControllerFrames<N, T> & frames)
  {
    if (!unapplied_) {
      return false;
    }
    unapplied_ = false;
    JointStorage<N> & joints = frames.joints;
    for (size_t i = 0; i < N; ++i) {
      if (!changed_[i]) {
        continue;
      }
      const bool position_mode = slots_.mode_of(i) == CommandMode::kPosition;
      joints.pos_des[i] = joints.pos[i];
      joints.vel_des[i] = 0.0;
      joints.ff[i] = 0.0;
      joints.kp[i] = position_mode ? slots_.default_stiffness(i) : 0.0;
      joints.kd[i] = slots_.default_damping(i);
      changed_[i] = false;
    }
    update_command_bounds(frames);
    return true;
  }

  // Controller thread: whether a controller claims the command interface behind `value`, one of
  // the doubles of `joints` (false for any other address).
  bool claims_value(const JointStorage<N> & joints, const double * value) const
  {
    const std::array<std::pair<const std::array<double, N> *, uint8_t>, 5> interfaces{{
      {&joints.pos_des, kClaimPosition}, {&joints.vel_des, kClaimVelocity},
      {&joints.ff, kClaimEffort}, {&joints.kp, kClaimStiffness}, {&joints.kd, kClaimDamping}}};
    for (const auto & [values, bit] : interfaces) {
      const double * first = values->data();
      if (std::less_equal<const double *>()(first, value) &&
        std::less<const double *>()(value, first + N))
      {
        return (claims_[static_cast<size_t>(value - first)] & bit) != 0U;
      }
    }
    return false;
  }

  // The bounds write() applies per slot, from the claims. A claimed interface is bounded by the
  // URDF limits (a claimed gain is not bounded: the command guard rejects a negative one). An
  // unclaimed one is pinned: to the joint's default gain while its position (stiffness) or its
  // position or velocity (damping) is claimed, to zero otherwise. Velocity-commanded joints get
  // kp = 0 and their measured position (DriverCore::write_command()).
  void update_command_bounds(ControllerFrames<N, T> & frames) const
  {
    constexpr T kUnbounded = std::numeric_limits<T>::infinity();
    Command & lower = frames.lower;
    Command & upper = frames.upper;
    for (size_t i = 0; i < N; ++i) {
      const uint8_t claims = claims_[i];
      const SlotLimits & limits = slots_.limits(i);
      const bool position_mode = slots_.mode_of(i) == CommandMode::kPosition;
      const bool bounded_position = takes_position(slots_.mode_of(i));
      const bool driven = (claims & (kClaimPosition | kClaimVelocity)) != 0U;
      const auto velocity = static_cast<T>((claims & kClaimVelocity) != 0U ? limits.velocity : 0.0);
      const auto effort = static_cast<T>((claims & kClaimEffort) != 0U ? limits.effort : 0.0);
      const auto stiffness = static_cast<T>(
        position_mode && (claims & kClaimPosition) != 0U ? slots_.default_stiffness(i) : 0.0);
      const auto damping = static_cast<T>(driven ? slots_.default_damping(i) : 0.0);
      if (bounded_position) {
        pin(
          lower.q_target, upper.q_target, i, static_cast<T>(limits.position_min),
          static_cast<T>(limits.position_max));
      } else {
        pin(lower.q_target, upper.q_target, i, -kUnbounded, kUnbounded);
      }
      pin(lower.dq_target, upper.dq_target, i, -velocity, velocity);
      pin(lower.tau_ff, upper.tau_ff, i, -effort, effort);
      if (position_mode && (claims & kClaimStiffness) != 0U) {
        pin(lower.kp, upper.kp, i, -kUnbounded, kUnbounded);
      } else {
        pin(lower.kp, upper.kp, i, stiffness, stiffness);
      }
      if ((claims & kClaimDamping) != 0U) {
        pin(lower.kd, upper.kd, i, -kUnbounded, kUnbounded);
      } else {
        pin(lower.kd, upper.kd, i, damping, damping);
      }
    }
  }

private:
  struct Claims
  {
    std::array<uint8_t, N> bits{};
    uint64_t generation{0};
  };

  static void pin(std::array<T, N> & lower, std::array<T, N> & upper, size_t slot, T min, T max)
  {
    lower[slot] = min;
    upper[slot] = max;
  }

  // "<joint>/<interface>": the claim bit it sets or clears (joint names may contain '/').
  template<typename Name>
  void update_claim(Claims & claims, const Name & full_name, bool claimed) const
  {
    const std::string name(full_name);
    const auto separator = name.rfind('/');
    if (separator == std::string::npos) {
      return;
    }
    const int slot = slots_.slot_of(name.substr(0, separator));
    if (slot < 0) {
      return;  // another component's interface
    }
    const std::string interface = name.substr(separator + 1);
    const uint8_t bit = interface == "position" ? kClaimPosition :
      interface == "velocity" ? kClaimVelocity : interface == "effort" ? kClaimEffort :
      interface == "stiffness" ? kClaimStiffness : interface == "damping" ? kClaimDamping : 0U;
    uint8_t & bits = claims.bits[static_cast<size_t>(slot)];
    bits = static_cast<uint8_t>(claimed ? (bits | bit) : (bits & ~bit));
  }

  const SlotTable<N> & slots_;
  Claims prepared_{};                 // controller manager: prepare_claims()
  Claims committed_{};                // controller manager: commit_claims()
  std::atomic<bool> claims_prepared_{false};
  DataBuffer<Claims> claim_buffer_;   // commit_claims() -> write()
  std::array<uint8_t, N> claims_{};   // controller thread: the claims write() applies
  std::array<bool, N> changed_{};     // controller thread: claims taken, joint not reset yet
  bool unapplied_{false};             // controller thread: some changed_ is set
  uint64_t applied_generation_{0};    // controller thread
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__COMMAND_CLAIMS_HPP_
