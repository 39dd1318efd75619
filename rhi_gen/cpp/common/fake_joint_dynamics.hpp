// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_JOINT_DYNAMICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_JOINT_DYNAMICS_HPP_

// The joints of a fake robot (the generated <robot>_fake_robot executable): every motor slot a
// joint drives is one rotor (or slider) under the vendor's motor law
//   tau = kp * (q_target - q) + kd * (dq_target - dq) + tau_ff,
// clamped to the URDF effort limit, with the URDF velocity and position limits as hard stops, an
// inertia estimated from the URDF's link masses and a viscous damping. No gravity, no contact.
// Integrated with implicit Euler, so that any gains a controller sends are stable at any rate.
// Or, handed to a FakeJointEngine (use_engine), moved by a physics engine instead.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace robot_hardware_interface
{

// One joint of the fake robot, generated from the URDF (rhi_gen/assemble/joint_inertia.py).
struct FakeJointSpec
{
  const char * name;        // URDF joint name
  size_t slot;              // SDK motor slot, as in the driver's joint table
  double position_min;      // URDF limits, -kNoLimit / kNoLimit when there are none
  double position_max;
  double velocity_max;
  double effort_max;
  double inertia;           // [kg m^2] or [kg]: the URDF subtree about the joint axis
  double damping;           // [N m s / rad] or [N s / m]: URDF <dynamics damping> or a default
  double initial_position;  // where the fake robot starts: the description's initial_value
  bool velocity_commanded;  // a wheel: a servo without gains in the command keeps its velocity
  // [kg m^2] or [kg]: the rotor inertia reflected to the URDF joint (vendor YAML armatures, default
  // 0.01), which the physics adds to the joint (fake_physics_mujoco.hpp); the vacuum ignores it
  double armature;
  // For the physics (the vacuum ignores them): MuJoCo's passive joint damping [N m s / rad] and
  // dry friction [N m] (frictionloss), the vendor YAML's joint_damping / joint_frictionloss,
  // else the URDF's <dynamics damping friction> (0 where it has none), as MuJoCo reads a URDF
  double physics_damping;
  double frictionloss;
};

// What one motor was last told, in the vendor's terms.
struct FakeMotorCommand
{
  double q{0.0};
  double dq{0.0};
  double tau_ff{0.0};
  double kp{0.0};
  double kd{0.0};
};

// The motors' last commands, as their boards keep them (FakeJointDynamics and a physics engine
// standing in for it hold one each): a command with a non-finite number is dropped, as a real motor
// board drops it, and counted; a slot past N is never commanded.
template<size_t N>
class FakeMotorCommands
{
public:
  void set(size_t slot, const FakeMotorCommand & c)
  {
    if (slot >= N) {
      return;
    }
    if (!std::isfinite(c.q) || !std::isfinite(c.dq) || !std::isfinite(c.tau_ff) ||
      !std::isfinite(c.kp) || !std::isfinite(c.kd))
    {
      ++rejected_;
      return;
    }
    commands_[slot] = c;
  }

  // Every motor passive (zero gains, zero torque), as when nobody commands the robot.
  void release() {commands_.fill(FakeMotorCommand{});}
  // An engine's copy of its FakeJointDynamics's commands, already checked there.
  void assign(const std::array<FakeMotorCommand, N> & commands) {commands_ = commands;}

  const FakeMotorCommand & operator[](size_t slot) const {return commands_[slot];}
  const std::array<FakeMotorCommand, N> & all() const {return commands_;}
  uint64_t rejected() const {return rejected_;}

private:
  std::array<FakeMotorCommand, N> commands_{};
  uint64_t rejected_{0};
};

// A physics engine the joints can be handed to instead (fake_physics_mujoco.hpp: MuJoCo, with
// gravity, contacts and the links' coupling). FakeJointDynamics then keeps the commands and the
// state the transports read, and the engine moves the joints.
template<size_t N>
class FakeJointEngine
{
public:
  virtual ~FakeJointEngine() = default;
  // Advance by dt seconds under `command`; leave each driven slot's position, velocity and motor
  // torque in q, dq and tau.
  virtual void advance(
    double dt, const std::array<FakeMotorCommand, N> & command, std::array<double, N> & q,
    std::array<double, N> & dq, std::array<double, N> & tau) = 0;
  // Put a joint at rest at `q` (already clamped into its limits).
  virtual void place(size_t slot, double q) = 0;
};

template<size_t N>
class FakeJointDynamics
{
public:
  FakeJointDynamics(const FakeJointSpec * joints, size_t count)
  : joints_(joints), count_(count)
  {
    for (size_t k = 0; k < count_; ++k) {
      if (joints_[k].slot < N) {
        q_[joints_[k].slot] = joints_[k].initial_position;
      }
    }
  }

  // A motor's new command (FakeMotorCommands::set: non-finite ones dropped and counted). A slot no
  // joint drives is never moved.
  void command(size_t slot, const FakeMotorCommand & c) {command_.set(slot, c);}
  // Every motor passive (zero gains, zero torque), as when nobody commands the robot.
  void release() {command_.release();}

  // Hand the joints to a physics engine (nullptr: back to the rotors above). Not owned; it starts
  // from its own model of the robot, and place() reaches it too.
  void use_engine(FakeJointEngine<N> * engine) {engine_ = engine;}
  bool has_engine() const {return engine_ != nullptr;}

  // Advance every joint by dt seconds.
  void step(double dt)
  {
    if (engine_ != nullptr) {
      engine_->advance(dt, command_.all(), q_, dq_, tau_);
      return;
    }
    for (size_t k = 0; k < count_; ++k) {
      step_joint(joints_[k], dt);
    }
  }

  // Put a joint at rest at `q` (start-up pose, tests): clamped into its limits.
  void place(size_t slot, double q)
  {
    for (size_t k = 0; k < count_; ++k) {
      if (joints_[k].slot == slot) {
        q_[slot] = std::clamp(q, joints_[k].position_min, joints_[k].position_max);
        dq_[slot] = 0.0;
        tau_[slot] = 0.0;
        if (engine_ != nullptr) {
          engine_->place(slot, q_[slot]);
        }
      }
    }
  }

  double position(size_t slot) const {return q_[slot];}
  double velocity(size_t slot) const {return dq_[slot];}
  double effort(size_t slot) const {return tau_[slot];}
  const FakeMotorCommand & last_command(size_t slot) const {return command_[slot];}
  uint64_t rejected_commands() const {return command_.rejected();}
  const FakeJointSpec * joints() const {return joints_;}
  size_t joint_count() const {return count_;}

private:
  void step_joint(const FakeJointSpec & j, double h)
  {
    const size_t s = j.slot;
    if (s >= N || !(h > 0.0)) {
      return;
    }
    const FakeMotorCommand & c = command_[s];
    const double inertia = j.inertia > 0.0 ? j.inertia : 1.0;
    const double b = j.damping > 0.0 ? j.damping : 0.0;
    const double q0 = q_[s];
    const double dq0 = dq_[s];
    // Implicit Euler of I ddq = kp (qt - q) + kd (dqt - dq) + tau_ff - b dq, q1 = q0 + h dq1.
    double dq1 = (inertia * dq0 / h + c.kp * (c.q - q0) + c.kd * c.dq + c.tau_ff) /
      (inertia / h + c.kp * h + c.kd + b);
    double tau = c.kp * (c.q - q0 - h * dq1) + c.kd * (c.dq - dq1) + c.tau_ff;
    if (std::fabs(tau) > j.effort_max) {
      // The motor saturates: the clamped torque drives the joint, only the damping stays implicit.
      tau = std::copysign(j.effort_max, tau);
      dq1 = (inertia * dq0 / h + tau) / (inertia / h + b);
    }
    dq1 = std::clamp(dq1, -j.velocity_max, j.velocity_max);
    double q1 = q0 + h * dq1;
    if (q1 <= j.position_min) {
      q1 = j.position_min;
      dq1 = std::max(dq1, 0.0);
    } else if (q1 >= j.position_max) {
      q1 = j.position_max;
      dq1 = std::min(dq1, 0.0);
    }
    q_[s] = q1;
    dq_[s] = dq1;
    tau_[s] = tau;
  }

  const FakeJointSpec * joints_;
  size_t count_;
  std::array<double, N> q_{};
  std::array<double, N> dq_{};
  std::array<double, N> tau_{};
  FakeMotorCommands<N> command_;
  FakeJointEngine<N> * engine_{nullptr};
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_JOINT_DYNAMICS_HPP_
