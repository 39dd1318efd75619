// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// Drives FakeMujocoPhysics (rhi_gen/cpp/common/fake_physics_mujoco.hpp) against the real MuJoCo
// for tests/cpp/test_cpp_fake_physics_mujoco.py, which asserts on what it prints (key=value lines).
//
//   fake_physics_check SCENARIO TABLE URDF BASE PACKAGE_PATH IMU_LINK [SECONDS [TIMESTEP]]
//
// TABLE: one joint a line, "name slot min max velocity_max effort_max initial kp kd amplitude"
// (rhi-gen's reading of the URDF and the vendor YAML, written by the test), optionally followed
// by "gain offset", the motor's transmission (then the row is in motor units). Scenarios:
//   load   load only: ok=1 or error=<the one line>, warning=<line> each, the model's sizes
//   armature  load with a rotor inertia of 0.01 k kg m^2 on the k-th joint of the table: armature.<joint>=
//          <what the model holds> given=<what the table gave>, each
//   track  the YAML's gains, the joints following sines of their amplitude (0.5 Hz) from their
//          start pose under gravity, after a second at rest, with a controller's gravity
//          feed-forward (tau_ff: a perfect model's gravity torque at the target); then a hold
//          without feed-forward (at rest, kp * error = gravity, up to the joint's friction)
//   sag    every motor passive (kp = kd = 0): how far gravity moves the joints
//   engine the sag scenario through FakeJointDynamics::use_engine, as a fake robot would run it
//   hold   (free or band base) the YAML's gains holding the start pose: base height and IMU
//   drop   (band) the same, the band released half-way: where the base goes
//   rate   the track scenario's loop without the feed-forward's model, timed: physics steps per
//          wall second, real-time factor; and the allocations step() made (C++ and MuJoCo's)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "robot_hardware_interface/common/fake_physics_mujoco.hpp"

namespace rhi = robot_hardware_interface;

// Allocations made inside FakeMujocoPhysics::step(): C++ ones through operator new, MuJoCo's
// through its allocator hook (mju_user_malloc, installed before anything is loaded).
namespace
{
bool g_counting = false;
uint64_t g_step_allocations = 0;
uint64_t g_mujoco_allocations = 0;  // all of them: the hook is live

void * mujoco_malloc(size_t bytes)
{
  ++g_mujoco_allocations;
  if (g_counting) {
    ++g_step_allocations;
  }
  // MuJoCo's own allocator aligns to 64 bytes; aligned_alloc wants a multiple of the alignment.
  return std::aligned_alloc(64, (bytes + 63) / 64 * 64);
}
}  // namespace

void * operator new(size_t bytes)
{
  if (g_counting) {
    ++g_step_allocations;
  }
  void * p = std::malloc(bytes == 0 ? 1 : bytes);
  if (p == nullptr) {
    throw std::bad_alloc();
  }
  return p;
}
void operator delete(void * p) noexcept {std::free(p);}
void operator delete(void * p, size_t) noexcept {std::free(p);}

namespace
{

constexpr size_t kSlots = 64;
constexpr double kCommandPeriod = 0.002;  // the driver's 500 Hz: each step() is two physics steps

struct Row
{
  std::string name;
  rhi::FakeJointSpec spec{};
  double kp{0.0};
  double kd{0.0};
  double amplitude{0.0};  // of the track scenario's sine [rad or m]
  rhi::FakeTransmission transmission{};
};

double number(const std::string & text)
{
  if (text == "inf") {
    return INFINITY;
  }
  if (text == "-inf") {
    return -INFINITY;
  }
  return std::strtod(text.c_str(), nullptr);
}

std::vector<Row> read_table(const char * path)
{
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    Row r;
    std::string slot, lo, hi, vel, eff, init, kp, kd, amplitude, damping, friction;
    if (!(words >> r.name >> slot >> lo >> hi >> vel >> eff >> init >> kp >> kd >> amplitude >> damping >>
      friction))
    {
      continue;
    }
    r.spec.slot = static_cast<size_t>(std::strtoul(slot.c_str(), nullptr, 10));
    r.spec.position_min = number(lo);
    r.spec.position_max = number(hi);
    r.spec.velocity_max = number(vel);
    r.spec.effort_max = number(eff);
    r.spec.inertia = 0.01;
    r.spec.damping = 0.0;
    r.spec.armature = 0.01;  // the vendor YAML default (rhi_gen/model/config.py ARMATURE_DEFAULT)
    r.spec.physics_damping = number(damping);  // the URDF's <dynamics>, as rhi-gen reads it
    r.spec.frictionloss = number(friction);
    r.spec.initial_position = number(init);
    r.kp = number(kp);
    r.kd = number(kd);
    r.amplitude = number(amplitude);
    std::string gain, offset;
    if (words >> gain >> offset) {
      r.transmission = rhi::FakeTransmission{number(gain), number(offset)};
    }
    rows.push_back(r);
  }
  for (Row & r : rows) {
    r.spec.name = r.name.c_str();  // after the vector stopped growing
  }
  return rows;
}

// The gravity torque of a perfect model at `q` (what a model-based controller sends as tau_ff).
void gravity_at(const mjModel * m, mjData * scratch, const rhi::FakeMujocoPhysics<kSlots> & sim,
  const std::vector<Row> & rows, const std::vector<double> & q, std::vector<double> * tau)
{
  mju_copy(scratch->qpos, sim.data()->qpos, m->nq);
  mju_zero(scratch->qvel, m->nv);
  for (size_t k = 0; k < rows.size(); ++k) {
    const int id = mj_name2id(m, mjOBJ_JOINT, rows[k].name.c_str());
    scratch->qpos[m->jnt_qposadr[id]] = q[k];
  }
  mj_forward(m, scratch);
  for (size_t k = 0; k < rows.size(); ++k) {
    const int id = mj_name2id(m, mjOBJ_JOINT, rows[k].name.c_str());
    (*tau)[k] = scratch->qfrc_bias[m->jnt_dofadr[id]];
  }
}

// FakeMujocoPhysics stands where FakeJointDynamics stands: every call the fake robot's runner and
// the transports' fake sides make on FakeRobotModel::dynamics compiles, with the same types, on
// both (checked at compile time, for both classes).
template<class Dynamics>
constexpr bool drop_in()
{
  using D = const Dynamics &;
  static_assert(std::is_same_v<decltype(std::declval<Dynamics &>().command(
      size_t{}, rhi::FakeMotorCommand{})), void>);
  static_assert(std::is_same_v<decltype(std::declval<Dynamics &>().release()), void>);
  static_assert(std::is_same_v<decltype(std::declval<Dynamics &>().step(0.0)), void>);
  static_assert(std::is_same_v<decltype(std::declval<Dynamics &>().place(size_t{}, 0.0)), void>);
  static_assert(std::is_same_v<decltype(std::declval<D>().position(size_t{})), double>);
  static_assert(std::is_same_v<decltype(std::declval<D>().velocity(size_t{})), double>);
  static_assert(std::is_same_v<decltype(std::declval<D>().effort(size_t{})), double>);
  static_assert(std::is_same_v<decltype(std::declval<D>().last_command(size_t{})),
    const rhi::FakeMotorCommand &>);
  static_assert(std::is_same_v<decltype(std::declval<D>().rejected_commands()), uint64_t>);
  static_assert(std::is_same_v<decltype(std::declval<D>().joints()), const rhi::FakeJointSpec *>);
  static_assert(std::is_same_v<decltype(std::declval<D>().joint_count()), size_t>);
  static_assert(std::is_constructible_v<Dynamics, const rhi::FakeJointSpec *, size_t>);
  return true;
}
static_assert(drop_in<rhi::FakeJointDynamics<kSlots>>());
static_assert(drop_in<rhi::FakeMujocoPhysics<kSlots>>());

}  // namespace

int main(int argc, char ** argv)
{
  if (argc < 7) {
    std::fprintf(stderr,
      "usage: %s SCENARIO TABLE URDF BASE PACKAGE_PATH IMU_LINK [SECONDS [TIMESTEP]]\n",
      argv[0]);
    return 2;
  }
  mju_user_malloc = mujoco_malloc;
  mju_user_free = std::free;
  const std::string scenario = argv[1];
  std::vector<Row> rows = read_table(argv[2]);
  std::vector<rhi::FakeJointSpec> specs;
  for (const Row & r : rows) {
    specs.push_back(r.spec);
    if (scenario == "armature") {  // a distinct rotor inertia per joint, to find in the model
      specs.back().armature = 0.01 * static_cast<double>(specs.size());
    }
  }
  rhi::FakePhysicsOptions options;
  options.urdf_path = argv[3];
  if (!rhi::FakePhysicsOptions::parse_base(argv[4], &options.base)) {
    std::fprintf(stderr, "base: free, band or fixed, not %s\n", argv[4]);
    return 2;
  }
  options.package_path = argv[5];
  for (const Row & r : rows) {
    if (r.transmission.gain != 1.0 || r.transmission.offset != 0.0) {
      for (const Row & each : rows) {
        options.transmissions.push_back(each.transmission);
      }
      break;
    }
  }
  options.imu_link = argv[6];
  const double seconds = argc > 7 ? std::strtod(argv[7], nullptr) : 4.0;
  if (argc > 8) {
    options.timestep = std::strtod(argv[8], nullptr);
  }

  rhi::FakeMujocoPhysics<kSlots> sim(specs.data(), specs.size());
  std::string error;
  std::vector<std::string> warnings;
  const bool ok = sim.load(options, &error, &warnings);
  for (const std::string & w : warnings) {
    std::printf("warning=%s\n", w.c_str());
  }
  if (!ok) {
    std::printf("error=%s\n", error.c_str());
    return 1;
  }
  const mjModel * m = sim.model();
  std::printf("ok=1\nnbody=%lld\nngeom=%lld\nnmesh=%lld\nnq=%lld\ntimestep=%g\nfloor=%g\n",
    static_cast<long long>(m->nbody), static_cast<long long>(m->ngeom),  // NOLINT(runtime/int)
    static_cast<long long>(m->nmesh), static_cast<long long>(m->nq),  // NOLINT(runtime/int)
    m->opt.timestep, sim.floor_height());
  if (scenario == "load") {
    return 0;
  }
  if (scenario == "armature") {
    for (const rhi::FakeJointSpec & j : specs) {
      const int id = mj_name2id(m, mjOBJ_JOINT, j.name);
      std::printf("armature.%s=%.17g given=%.17g\n", j.name, id >= 0 ? m->dof_armature[m->jnt_dofadr[id]] : -1.0,
        j.armature);
    }
    return 0;
  }

  const size_t n = rows.size();
  std::vector<double> start(n), target(n), tau_ff(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    start[k] = sim.position(rows[k].spec.slot);
  }
  mjData * scratch = mj_makeData(m);
  const int steps = static_cast<int>(std::lround(seconds / kCommandPeriod));

  if (scenario == "sag" || scenario == "engine") {
    // engine: the same through FakeJointDynamics with the physics as its engine, as the fake robot
    // runs it (its runner and transports only know FakeJointDynamics); a place() first, which
    // must reach the engine, then the joints let go.
    rhi::FakeJointDynamics<kSlots> dynamics(specs.data(), specs.size());
    const bool through = scenario == "engine";
    if (through) {
      dynamics.use_engine(&sim);
      for (size_t k = 0; k < n; ++k) {
        dynamics.place(rows[k].spec.slot, start[k]);
      }
    }
    sim.release();
    double worst = 0.0;
    std::string worst_joint;
    for (int i = 0; i < steps; ++i) {
      if (through) {
        dynamics.step(kCommandPeriod);
      } else {
        sim.step(kCommandPeriod);
      }
    }
    for (size_t k = 0; k < n; ++k) {
      const size_t s = rows[k].spec.slot;
      const double now = through ? dynamics.position(s) : sim.position(s);
      if (through && (now != sim.position(s) || dynamics.velocity(s) != sim.velocity(s))) {
        std::printf("error=FakeJointDynamics reads %g, the engine has %g\n", now, sim.position(s));
        return 1;
      }
      const double moved = std::fabs(now - start[k]);
      std::printf("sag.%s=%.6f\npos.%s=%.17g\n", rows[k].name.c_str(), moved, rows[k].name.c_str(),
        now);
      if (moved > worst) {
        worst = moved;
        worst_joint = rows[k].name;
      }
    }
    std::printf("sag_max=%.6f\nsag_joint=%s\nphysics_steps=%llu\n", worst, worst_joint.c_str(),
      static_cast<unsigned long long>(sim.physics_steps()));  // NOLINT(runtime/int)
    for (size_t k = 0; k < n; ++k) {
      std::printf("vel.%s=%.17g\n", rows[k].name.c_str(), sim.velocity(rows[k].spec.slot));
    }
    const rhi::FakeImuReading & imu = sim.imu();
    std::printf("imu_quat=%.17g %.17g %.17g %.17g\nimu_gyro=%.17g %.17g %.17g\n",
      imu.orientation[0], imu.orientation[1], imu.orientation[2], imu.orientation[3],
      imu.angular_velocity[0], imu.angular_velocity[1], imu.angular_velocity[2]);
  } else if (scenario == "track" || scenario == "rate") {
    const double w = 2.0 * M_PI * 0.5;
    double worst = 0.0;
    double sum_sq = 0.0;
    long samples = 0;  // NOLINT(runtime/int)
    std::vector<double> joint_worst(n, 0.0);
    const auto wall0 = std::chrono::steady_clock::now();
    const uint64_t physics0 = sim.physics_steps();
    std::vector<double> velocity(n);
    for (int i = 0; i < steps; ++i) {
      const double t = (i + 1) * kCommandPeriod;
      for (size_t k = 0; k < n; ++k) {
        const double phase = 0.7 * static_cast<double>(k);
        const double a = rows[k].amplitude;
        target[k] = start[k] +
          (t < 1.0 ? 0.0 : a * (std::sin(w * (t - 1.0) + phase) - std::sin(phase)));
        velocity[k] = t < 1.0 ? 0.0 : a * w * std::cos(w * (t - 1.0) + phase);
      }
      if (scenario == "track") {
        gravity_at(m, scratch, sim, rows, target, &tau_ff);
      }
      for (size_t k = 0; k < n; ++k) {
        sim.command(rows[k].spec.slot,
          rhi::FakeMotorCommand{target[k], velocity[k], tau_ff[k], rows[k].kp, rows[k].kd});
      }
      g_counting = true;
      sim.step(kCommandPeriod);
      g_counting = false;
      if (t > 1.0) {
        for (size_t k = 0; k < n; ++k) {
          const double e = std::fabs(sim.position(rows[k].spec.slot) - target[k]);
          worst = std::max(worst, e);
          joint_worst[k] = std::max(joint_worst[k], e);
          sum_sq += e * e;
          ++samples;
        }
      }
    }
    const double wall = std::chrono::duration<double>(
      std::chrono::steady_clock::now() - wall0).count();
    const double physics = static_cast<double>(sim.physics_steps() - physics0);
    for (size_t k = 0; k < n; ++k) {
      std::printf("track.%s=%.6f\n", rows[k].name.c_str(), joint_worst[k]);
    }
    std::printf("track_max=%.6f\ntrack_rms=%.6f\n", worst,
      samples > 0 ? std::sqrt(sum_sq / static_cast<double>(samples)) : 0.0);
    std::printf("step_allocations=%llu\nmujoco_allocations=%llu\n",
      static_cast<unsigned long long>(g_step_allocations),  // NOLINT(runtime/int)
      static_cast<unsigned long long>(g_mujoco_allocations));  // NOLINT(runtime/int)
    std::printf("physics_steps=%.0f\nsimulated=%.6f\nwall=%.6f\nphysics_hz=%.1f\nrtf=%.3f\n",
      physics, physics * m->opt.timestep, wall, physics / wall, physics * m->opt.timestep / wall);
    // Then hold the last target without feed-forward: at rest, kp (q_t - q) = gravity(q), up to
    // the joints' friction.
    for (int i = 0; i < static_cast<int>(2.0 / kCommandPeriod); ++i) {
      for (size_t k = 0; k < n; ++k) {
        sim.command(rows[k].spec.slot,
          rhi::FakeMotorCommand{target[k], 0.0, 0.0, rows[k].kp, rows[k].kd});
      }
      sim.step(kCommandPeriod);
    }
    std::vector<double> now(n), gravity(n);
    for (size_t k = 0; k < n; ++k) {
      now[k] = sim.position(rows[k].spec.slot);
    }
    gravity_at(m, scratch, sim, rows, now, &gravity);
    double hold_worst = 0.0;
    double balance_worst = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const double e = target[k] - now[k];
      hold_worst = std::max(hold_worst, std::fabs(e));
      const int id = mj_name2id(m, mjOBJ_JOINT, rows[k].name.c_str());
      const double friction = m->dof_frictionloss[m->jnt_dofadr[id]];
      // What is left of kp e - gravity beyond what friction can hold.
      const double unbalanced = std::max(0.0, std::fabs(rows[k].kp * e - gravity[k]) - friction);
      balance_worst = std::max(balance_worst, unbalanced);
      std::printf("hold.%s=%.6f gravity=%.4f motor=%.4f\n", rows[k].name.c_str(), e, gravity[k],
        sim.effort(rows[k].spec.slot));
    }
    std::printf("hold_max=%.6f\nunbalanced_max=%.6f\n", hold_worst, balance_worst);
  } else if (scenario == "hold") {
    double height_min = INFINITY;
    double height_max = -INFINITY;
    double worst = 0.0;
    double acc_z_sum = 0.0;
    const double base0 = sim.base_position()[2];
    for (int i = 0; i < steps; ++i) {
      for (size_t k = 0; k < n; ++k) {
        sim.command(rows[k].spec.slot,
          rhi::FakeMotorCommand{start[k], 0.0, 0.0, rows[k].kp, rows[k].kd});
      }
      sim.step(kCommandPeriod);
      const double z = sim.base_position()[2];
      height_min = std::min(height_min, z);
      height_max = std::max(height_max, z);
      for (size_t k = 0; k < n; ++k) {
        worst = std::max(worst, std::fabs(sim.position(rows[k].spec.slot) - start[k]));
      }
      acc_z_sum += sim.imu().linear_acceleration[2];
    }
    for (size_t k = 0; k < n; ++k) {
      std::printf("hold.%s=%.6f\npos.%s=%.17g\neffort.%s=%.17g\n", rows[k].name.c_str(),
        std::fabs(sim.position(rows[k].spec.slot) - start[k]), rows[k].name.c_str(),
        sim.position(rows[k].spec.slot), rows[k].name.c_str(), sim.effort(rows[k].spec.slot));
    }
    const rhi::FakeImuReading & imu = sim.imu();
    std::printf("base_start=%.6f\nbase_min=%.6f\nbase_max=%.6f\njoint_max=%.6f\n",
      base0, height_min, height_max, worst);
    std::printf("imu_acc=%.4f %.4f %.4f\nimu_acc_z_mean=%.4f\nimu_quat=%.5f %.5f %.5f %.5f\n",
      imu.linear_acceleration[0], imu.linear_acceleration[1], imu.linear_acceleration[2],
      acc_z_sum / steps, imu.orientation[0], imu.orientation[1], imu.orientation[2],
      imu.orientation[3]);
  } else if (scenario == "drop") {
    // Half the time on the band, then released: the base's height at the release and its lowest.
    double released_at = 0.0;
    double lowest = INFINITY;
    for (int i = 0; i < steps; ++i) {
      if (i == steps / 2) {
        sim.release_band();
        released_at = sim.base_position()[2];
      }
      for (size_t k = 0; k < n; ++k) {
        sim.command(rows[k].spec.slot,
          rhi::FakeMotorCommand{start[k], 0.0, 0.0, rows[k].kp, rows[k].kd});
      }
      sim.step(kCommandPeriod);
      if (i >= steps / 2) {
        lowest = std::min(lowest, sim.base_position()[2]);
      }
    }
    std::printf("band_holding=%d\nreleased_at=%.6f\nlowest_after=%.6f\n",
      sim.band_holding() ? 1 : 0, released_at, lowest);
  } else {
    std::fprintf(stderr, "unknown scenario %s\n", scenario.c_str());
    mj_deleteData(scratch);
    return 2;
  }
  mj_deleteData(scratch);
  return 0;
}
