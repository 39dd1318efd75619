// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__JOINT_TRANSMISSIONS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__JOINT_TRANSMISSIONS_HPP_

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "robot_hardware_interface/common/motor_types.hpp"
#include "robot_hardware_interface/common/robot_spec.hpp"
#include "robot_hardware_interface/common/slot_kernels.hpp"
#include "robot_hardware_interface/common/types.hpp"

namespace robot_hardware_interface
{

// Motors that are not joints: the robot's generated transmissions (TransmissionSpec) with a
// calibration on top, as data the slot loops of read() and write() apply (slot_kernels.hpp), and
// the few small matrices of coupled joints.
//
// Threads: built and calibrated while read() and write() do not run (construction, on_configure);
// read() and write() only read it (the command scratch is the controller thread's).
template<size_t N>
class JointTransmissions
{
public:
  explicit JointTransmissions(const TransmissionSpec * spec)
  : spec_(spec)
  {
    reset();
  }

  // Back to the generated transmissions, without calibration. Allocates (not for the hot path).
  void reset()
  {
    factors_.scale.fill(1.0);
    factors_.offset.fill(0.0);
    factors_.inverse.fill(1.0);
    coupled_.fill(false);
    groups_.clear();
    error_.clear();
    if (spec_ == nullptr) {
      active_ = false;
      return;
    }
    for (size_t i = 0; i < spec_->joint_count; ++i) {
      const JointTransmissionSpec & joint = spec_->joints[i];
      factors_.scale[joint.slot] = joint.direction / joint.reduction;
      factors_.inverse[joint.slot] = joint.reduction / joint.direction;
      factors_.offset[joint.slot] = joint.offset;
    }
    for (size_t g = 0; g < spec_->group_count; ++g) {
      add_group(spec_->groups[g]);
    }
    update_active();
  }

  // Empty, or why the generated transmissions cannot be used (a singular coupling matrix).
  const std::string & error() const {return error_;}

  // Whether read() and write() must convert at all: false for a robot whose motors are its joints
  // (then the plain slot loops run, at no extra cost).
  bool active() const {return active_;}

  bool is_coupled(size_t slot) const {return coupled_[slot];}

  // A calibration on top of the generated values: `direction` (+1 / -1) multiplies the joint's
  // direction, `offset` is added to its zero. A coupled joint takes only an offset.
  void calibrate(size_t slot, double direction, double offset)
  {
    factors_.scale[slot] *= direction;
    factors_.inverse[slot] *= direction;
    factors_.offset[slot] += offset;
    update_active();
  }

  const TransmissionFactors<N> & factors() const {return factors_;}

  // read(), after transmit_state_block: the coupled joints from their motors.
  template<typename T>
  void couple_state(const MotorState<N, T> & state, JointStorage<N> & joints) const
  {
    for (const Group & group : groups_) {
      const size_t n = group.slots.size();
      for (size_t j = 0; j < n; ++j) {
        double pos = 0.0;
        double vel = 0.0;
        double tau = 0.0;
        for (size_t k = 0; k < n; ++k) {
          const size_t motor = group.slots[k];
          pos += group.matrix[j * n + k] * static_cast<double>(state.q[motor]);
          vel += group.matrix[j * n + k] * static_cast<double>(state.dq[motor]);
          tau += group.inverse[k * n + j] * static_cast<double>(state.tau[motor]);  // inverse^T
        }
        const size_t slot = group.slots[j];
        joints.pos[slot] = pos + factors_.offset[slot];
        joints.vel[slot] = vel;
        joints.tau[slot] = tau;
      }
    }
  }

  // write(), after transmit_command_block (which took the coupled joints' offsets off): the
  // motors of every coupled group from its joints. Positions and velocities by the inverse matrix,
  // the feed-forward effort by the transpose, and each motor's gain the diagonal of
  // transpose * diag(joint gains) * matrix: exact when the group's joints have equal gains and the
  // matrix's columns are orthogonal (a differential), the motor-side PD law's best fit otherwise.
  // A negative joint gain makes its motors' gain negative, for the command guard to reject.
  template<typename T>
  void couple_command(MotorCommand<N, T> & command)
  {
    for (const Group & group : groups_) {
      const size_t n = group.slots.size();
      for (size_t j = 0; j < n; ++j) {
        const size_t slot = group.slots[j];
        joint_q_[j] = static_cast<double>(command.q_target[slot]);
        joint_dq_[j] = static_cast<double>(command.dq_target[slot]);
        joint_kp_[j] = static_cast<double>(command.kp[slot]);
        joint_kd_[j] = static_cast<double>(command.kd[slot]);
        joint_ff_[j] = static_cast<double>(command.tau_ff[slot]);
      }
      for (size_t i = 0; i < n; ++i) {
        double q = 0.0;
        double dq = 0.0;
        double ff = 0.0;
        double kp = 0.0;
        double kd = 0.0;
        double kp_min = 0.0;
        double kd_min = 0.0;
        for (size_t j = 0; j < n; ++j) {
          const double weight = group.matrix[j * n + i];
          q += group.inverse[i * n + j] * joint_q_[j];
          dq += group.inverse[i * n + j] * joint_dq_[j];
          ff += weight * joint_ff_[j];
          kp += weight * weight * joint_kp_[j];
          kd += weight * weight * joint_kd_[j];
          kp_min = joint_kp_[j] < kp_min ? joint_kp_[j] : kp_min;
          kd_min = joint_kd_[j] < kd_min ? joint_kd_[j] : kd_min;
        }
        const size_t motor = group.slots[i];
        command.q_target[motor] = static_cast<T>(q);
        command.dq_target[motor] = static_cast<T>(dq);
        command.tau_ff[motor] = static_cast<T>(ff);
        command.kp[motor] = static_cast<T>(kp_min < 0.0 ? kp_min : kp);
        command.kd[motor] = static_cast<T>(kd_min < 0.0 ? kd_min : kd);
      }
    }
  }

private:
  struct Group
  {
    std::vector<size_t> slots;
    std::vector<double> matrix;   // joint per motor, row-major
    std::vector<double> inverse;  // motor per joint, row-major
  };

  void add_group(const CoupledJointsSpec & spec)
  {
    Group group;
    group.slots.assign(spec.slots, spec.slots + spec.size);
    group.matrix.assign(spec.matrix, spec.matrix + spec.size * spec.size);
    if (!invert(spec.size, group.matrix, group.inverse)) {
      error_ = std::string("coupled joints '") + spec.name + "': the matrix is singular";
      return;
    }
    for (const size_t slot : group.slots) {
      coupled_[slot] = true;
    }
    groups_.push_back(std::move(group));
  }

  // Gauss-Jordan elimination with partial pivoting; false for a (numerically) singular matrix.
  static bool invert(size_t n, const std::vector<double> & matrix, std::vector<double> & inverse)
  {
    std::vector<double> a(matrix);
    inverse.assign(n * n, 0.0);
    double largest = 0.0;
    for (size_t i = 0; i < n; ++i) {
      inverse[i * n + i] = 1.0;
    }
    for (const double value : a) {
      largest = std::fabs(value) > largest ? std::fabs(value) : largest;
    }
    for (size_t col = 0; col < n; ++col) {
      size_t pivot = col;
      for (size_t row = col + 1; row < n; ++row) {
        pivot = std::fabs(a[row * n + col]) > std::fabs(a[pivot * n + col]) ? row : pivot;
      }
      if (!(std::fabs(a[pivot * n + col]) > 1e-12 * largest)) {
        return false;
      }
      for (size_t k = 0; k < n; ++k) {
        std::swap(a[col * n + k], a[pivot * n + k]);
        std::swap(inverse[col * n + k], inverse[pivot * n + k]);
      }
      const double scale = 1.0 / a[col * n + col];
      for (size_t k = 0; k < n; ++k) {
        a[col * n + k] *= scale;
        inverse[col * n + k] *= scale;
      }
      for (size_t row = 0; row < n; ++row) {
        const double factor = a[row * n + col];
        if (row == col || factor == 0.0) {
          continue;
        }
        for (size_t k = 0; k < n; ++k) {
          a[row * n + k] -= factor * a[col * n + k];
          inverse[row * n + k] -= factor * inverse[col * n + k];
        }
      }
    }
    return true;
  }

  void update_active()
  {
    active_ = !groups_.empty();
    for (size_t i = 0; i < N; ++i) {
      active_ = active_ || factors_.scale[i] != 1.0 || factors_.offset[i] != 0.0;
    }
  }

  const TransmissionSpec * spec_;
  TransmissionFactors<N> factors_{};
  std::array<bool, N> coupled_{};
  std::vector<Group> groups_;
  std::string error_;
  bool active_{false};
  // couple_command()'s joint values of one group (controller thread)
  std::array<double, N> joint_q_{};
  std::array<double, N> joint_dq_{};
  std::array<double, N> joint_kp_{};
  std::array<double, N> joint_kd_{};
  std::array<double, N> joint_ff_{};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__JOINT_TRANSMISSIONS_HPP_
