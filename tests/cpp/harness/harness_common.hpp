// Shared pieces of the driver harness: frames exchanged with the fake robot, value encodings,
// the HardwareInfo built from the generated ros2_control description, interface lookup.
//
// robot_data.hpp (written per robot by tests/support/cpp_build.py) provides namespace rhi_data: the
// expected joint -> SDK slot table read from the vendor YAML (NOT from the generated
// joint_index_map), limits from the URDF, transport topics, parameter defaults and kInfoRecords,
// the <ros2_control> block of the expanded xacro. Interfaces are read and written through
// rhi_fake/hw.hpp, so the same code runs on every distro's stand-ins.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <hardware_interface/hardware_info.hpp>

#include "rhi_fake/hw.hpp"

#include "robot_data.hpp"

namespace rhi_test {

using namespace rhi_data;  // NOLINT: the per-robot tables

constexpr size_t N = kMotorCount;

// What the fake robot reports, per SDK slot (values already representable in SdkFloat).
struct StateFrame {
  std::array<double, N> q{};
  std::array<double, N> dq{};
  std::array<double, N> tau{};
  std::array<double, 4> quat_wxyz{1.0, 0.0, 0.0, 0.0};
  std::array<double, 3> gyro{};
  std::array<double, 3> acc{};
  uint8_t mode_machine{5};
  uint32_t sequence{0};
  // Motor health, where the message carries it (integers and quarter volts: exact in every type).
  std::array<double, N> temperature{};
  std::array<double, N> voltage{};
  std::array<double, N> error_code{};
  std::array<bool, N> offline{};  // the robot reports the motor offline (EngineAI native SDK)
};

// What the fake robot received, per SDK slot.
struct CommandFrame {
  std::array<double, N> q{};
  std::array<double, N> dq{};
  std::array<double, N> tau{};
  std::array<double, N> kp{};
  std::array<double, N> kd{};
  std::array<bool, N> present{};  // the message carried this slot
  bool has_gains{true};           // sensor_msgs/JointState carries no kp/kd
};

inline double sdk(double v) { return static_cast<double>(static_cast<SdkFloat>(v)); }

// kJoints' command modes (robot_data.hpp): what a joint takes from ros2_control.
enum JointMode : int {
  kModePosition = 0,        // the full PD command: position, velocity, stiffness, damping, effort
  kModeVelocity = 1,        // a wheel: velocity, damping, effort (its position target follows the measurement)
  kModeStateOnly = 2,       // authority upper_body's legs: no command at all
  kModePositionTarget = 3,  // an OmniHand axis: a position target alone, the robot's own controller tracks it
};
// The joint's position target comes from ros2_control, clamped into its URDF limits; held, it is the
// measured position.
inline bool commands_position(const Joint& j) { return j.mode == kModePosition || j.mode == kModePositionTarget; }

// Whether `name` is an entry of the comma-separated `list` (a harness option: --only, --physics, ...).
inline bool in_list(const std::string& list, const std::string& name) {
  return ("," + list + ",").find("," + name + ",") != std::string::npos;
}
// Velocity, damping and effort travel (a position-target joint sends 0 for each, a state-only one nothing).
inline bool takes_pd_command(const Joint& j) { return j.mode == kModePosition || j.mode == kModeVelocity; }
// The command interface a position- or velocity-only controller claims: its target.
inline const char* target_interface(const Joint& j) { return commands_position(j) ? "position" : "velocity"; }
inline const char* mode_name(const Joint& j) {
  switch (j.mode) {
    case kModePosition: return "position";
    case kModeVelocity: return "velocity";
    case kModeStateOnly: return "state-only";
    case kModePositionTarget: return "position-target";
    default: return "unknown-mode";
  }
}

// Whether the robot reports joint j's effort: an OmniHand reports a motor current in A where a torque
// would be (AimDK endeffector docs), which the driver must not store, so its effort state stays 0.
#if defined(RHI_AIMDK_HANDS)
inline bool is_hand_slot(size_t slot) { return slot >= kHandFirstSlot && slot < kHandFirstSlot + 20; }
#else
inline bool is_hand_slot(size_t) { return false; }
#endif
inline bool effort_reported(const Joint& j) {
#if defined(RHI_AIMDK_HANDS)
  return !is_hand_slot(j.slot);
#else
  (void)j;
  return true;
#endif
}

// The joint the YAML maps to `slot`, or nullptr.
inline const Joint* joint_of_slot(size_t slot) {
  for (const Joint& j : kJoints) {
    if (j.slot == slot) {
      return &j;
    }
  }
  return nullptr;
}

// A position range inside the URDF limits (continuous joints: [-1, 1]).
struct Range {
  double lo;
  double hi;
  bool usable() const { return hi - lo > 1e-6; }
};
inline Range position_range(const Joint& j) {
  Range r{std::isfinite(j.lower) ? j.lower : -1.0, std::isfinite(j.upper) ? j.upper : 1.0};
  return r;
}

// Distinct position per slot, inside the joint's limits; unmapped slots get 1000 + slot.
inline double distinct_position(size_t slot, uint32_t frame) {
  const Joint* j = joint_of_slot(slot);
  if (j == nullptr) {
    return sdk(1000.0 + static_cast<double>(slot) + 0.5 * frame);
  }
  const Range r = position_range(*j);
  const double f = (static_cast<double>(slot) + 1.0 + 0.37 * (frame % 2)) / (static_cast<double>(N) + 2.0);
  return sdk(r.lo + (r.hi - r.lo) * f);
}

inline StateFrame distinct_state(uint32_t frame) {
  StateFrame s;
  for (size_t i = 0; i < N; ++i) {
    s.q[i] = distinct_position(i, frame);
    s.dq[i] = sdk(10.0 + 0.5 * static_cast<double>(i) + 100.0 * frame);
    s.tau[i] = sdk(-20.0 - 0.25 * static_cast<double>(i) - 100.0 * frame);
  }
  // Distinct, exactly representable in float: a w/x/y/z mix-up cannot go unnoticed.
  s.quat_wxyz = {0.5, -0.25, 0.125, 0.8125};
  s.gyro = {1.5, -2.5, 3.25 + frame};
  s.acc = {0.375, 9.8125, -4.5 - frame};
  s.sequence = frame;
  for (size_t i = 0; i < N; ++i) {
    s.temperature[i] = static_cast<double>(30 + (i + frame) % 25);  // below every warn threshold
    s.voltage[i] = 24.0 + 0.25 * static_cast<double>((i + 3 * frame) % 32);
    s.error_code[i] = static_cast<double>((7 * i + 13 * frame) % 4096);
  }
  return s;
}

// Consistency code used by the threaded scenario: every joint of a frame encodes the same j.
constexpr int kCodes = 1000;
inline double encode_position(const Joint& j, uint32_t code) {
  const Range r = position_range(j);
  return sdk(r.lo + (r.hi - r.lo) * ((code % kCodes) + 0.5) / kCodes);
}
inline int decode_position(const Joint& j, double v) {
  const Range r = position_range(j);
  return static_cast<int>(std::floor((v - r.lo) / (r.hi - r.lo) * kCodes));
}

inline void motors_for_joints(const std::array<double, N>& joint, std::array<double, N>& motor);

// Every joint at the code's position (for a robot with transmissions: the motor positions that put
// it there), so that a command holding the measured pose carries the code too.
inline StateFrame coded_state(uint32_t code) {
  StateFrame s = distinct_state(0);
  std::array<double, N> joint{};
  for (const Joint& j : kJoints) {
    joint[j.slot] = encode_position(j, code);
  }
  motors_for_joints(joint, s.q);
  s.sequence = code;
  return s;
}

// ---------------------------------------------------------------- HardwareInfo
// Value-initialised: 4.x+ HardwareInfo/InterfaceInfo have members without initializers.
inline hardware_interface::HardwareInfo make_hardware_info() {
  hardware_interface::HardwareInfo info{};
  hardware_interface::ComponentInfo* component = nullptr;
  for (const InfoRecord& r : kInfoRecords) {
    switch (r.kind) {
      case 'N':  // <ros2_control name type>
        info.name = r.a;
        info.type = r.b;
        break;
      case 'L':  // <plugin>
        rhi_fake::hw::set_plugin_name(info, r.a);
        break;
      case 'H':  // <hardware><param>
        info.hardware_parameters[r.a] = r.b;
        break;
      case 'J':  // <joint>
        info.joints.emplace_back();
        component = &info.joints.back();
        component->name = r.a;
        component->type = "joint";
        break;
      case 'S':  // <sensor>
        info.sensors.emplace_back();
        component = &info.sensors.back();
        component->name = r.a;
        component->type = "sensor";
        break;
      case 'G':  // <gpio>
        info.gpios.emplace_back();
        component = &info.gpios.back();
        component->name = r.a;
        component->type = "gpio";
        break;
      case 'C': {  // <command_interface> (+ min/max params)
        hardware_interface::InterfaceInfo i{};
        i.name = r.a;
        i.min = r.b;
        i.max = r.c;
        i.size = 1;
        component->command_interfaces.push_back(i);
        break;
      }
      case 'T': {  // <state_interface>
        hardware_interface::InterfaceInfo i{};
        i.name = r.a;
        i.size = 1;
        component->state_interfaces.push_back(i);
        break;
      }
      case 'P':  // component <param>
        component->parameters[r.a] = r.b;
        break;
      default:
        break;
    }
  }
  return info;
}

// ---------------------------------------------------------------- exported interfaces
constexpr std::array<const char*, 10> kImuInterfaces = {
    "orientation.x",      "orientation.y",      "orientation.z",        "orientation.w",
    "angular_velocity.x", "angular_velocity.y", "angular_velocity.z",   "linear_acceleration.x",
    "linear_acceleration.y", "linear_acceleration.z"};
constexpr std::array<const char*, 3> kJointStates = {"position", "velocity", "effort"};
constexpr std::array<const char*, 5> kJointCommands = {"position", "velocity", "stiffness", "damping",
                                                       "effort"};

// The command interfaces joint k exports (its mode, and whether the transport carries gains).
inline std::vector<std::string> joint_commands(size_t k) {
  std::vector<std::string> out;
  for (const char* name : kJointCommands) {
    const std::string n = name;
    if (kJoints[k].mode == kModeStateOnly) continue;  // state-only: no command interface at all
    if (kJoints[k].mode == kModePositionTarget && n != "position") continue;  // the position target alone
    if ((n == "position" || n == "stiffness") && kJoints[k].mode == kModeVelocity) continue;
    if ((n == "stiffness" || n == "damping") && !kHasGains) continue;
    out.push_back(n);
  }
  return out;
}

// Motor health per joint, after position, velocity and effort: what each robot's state message carries
// (SDK_FACTS.md: hg MotorState_ temperature[0], vol, motorstate; go MotorState_ temperature; AimDK
// hal JointState v1.0.0 error_code; EngineAI MotorDebug motor_temperature, and with the native SDK's
// interface_protocol (RHI_ENGINEAI_NATIVE_SDK, robot_data.hpp) voltage and error_code, which the driver
// exports beyond the description; the others nothing). kMotorOffline: the message reports offline motors.
constexpr std::array<const char*, 3> kMotorHealthNames = {"temperature", "voltage", "error_code"};
#if defined(RHI_TRANSPORT_UNITREE_DDS) && defined(RHI_UNITREE_FAMILY_GO)
constexpr std::array<bool, 3> kMotorHealth = {true, false, false};
#elif defined(RHI_TRANSPORT_UNITREE_DDS)
constexpr std::array<bool, 3> kMotorHealth = {true, true, true};
#elif defined(RHI_TRANSPORT_AGIBOT_TOPICS)
constexpr std::array<bool, 3> kMotorHealth = {false, false, true};
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS) && defined(RHI_ENGINEAI_NATIVE_SDK)
constexpr std::array<bool, 3> kMotorHealth = {true, true, true};
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
constexpr std::array<bool, 3> kMotorHealth = {true, false, false};
#else
constexpr std::array<bool, 3> kMotorHealth = {false, false, false};
#endif
constexpr size_t kMotorHealthCount = (kMotorHealth[0] ? 1U : 0U) + (kMotorHealth[1] ? 1U : 0U) +
                                     (kMotorHealth[2] ? 1U : 0U);
#if defined(RHI_ENGINEAI_NATIVE_SDK)
constexpr bool kMotorOffline = true;
#else
constexpr bool kMotorOffline = false;
#endif

// The driver's health GPIO (README "See the driver's health"): its state interfaces and its e-stop.
constexpr std::array<const char*, 7> kHealthStates = {"state_age_ms", "invalid_states", "stale_holds",
                                                      "rejected_commands", "writer_overruns", "fault", "estop"};
enum HealthState : size_t { kStateAge, kInvalidStates, kStaleHolds, kRejectedCommands, kWriterOverruns, kFault,
                            kEstopState };
constexpr bool kHasHealthGpio = kHealthGpio[0] != '\0';

struct Interfaces {
  rhi_fake::hw::Exported exported;  // what the driver exported, in its order
  // per kJoints entry (nullptr when missing)
  std::vector<const rhi_fake::hw::StateRef*> pos, vel, eff;
  std::vector<std::array<const rhi_fake::hw::StateRef*, 3>> motor_health;  // per joint, kMotorHealthNames
  std::vector<const rhi_fake::hw::CommandRef*> cpos, cvel, ckp, ckd, cff;
  std::array<const rhi_fake::hw::StateRef*, 10> imu{};
  std::array<const rhi_fake::hw::StateRef*, kHealthStates.size()> health{};
  const rhi_fake::hw::CommandRef* estop{nullptr};

  void index() {
    pos.assign(kJointCount, nullptr);
    vel.assign(kJointCount, nullptr);
    eff.assign(kJointCount, nullptr);
    motor_health.assign(kJointCount, {nullptr, nullptr, nullptr});
    cpos.assign(kJointCount, nullptr);
    cvel.assign(kJointCount, nullptr);
    ckp.assign(kJointCount, nullptr);
    ckd.assign(kJointCount, nullptr);
    cff.assign(kJointCount, nullptr);
    imu.fill(nullptr);
    health.fill(nullptr);
    estop = nullptr;
    for (const auto& s : exported.states()) {
      for (size_t k = 0; k < kJointCount; ++k) {
        if (s.prefix() != kJoints[k].name) {
          continue;
        }
        const std::string& n = s.interface();
        if (n == "position") pos[k] = &s;
        if (n == "velocity") vel[k] = &s;
        if (n == "effort") eff[k] = &s;
        for (size_t h = 0; h < kMotorHealthNames.size(); ++h) {
          if (n == kMotorHealthNames[h]) motor_health[k][h] = &s;
        }
      }
      if (kImuEnabled && s.prefix() == kImuName) {
        for (size_t i = 0; i < kImuInterfaces.size(); ++i) {
          if (s.interface() == kImuInterfaces[i]) imu[i] = &s;
        }
      }
      if (kHasHealthGpio && s.prefix() == kHealthGpio) {
        for (size_t i = 0; i < kHealthStates.size(); ++i) {
          if (s.interface() == kHealthStates[i]) health[i] = &s;
        }
      }
    }
    for (const auto& c : exported.commands()) {
      if (kHasHealthGpio && c.prefix() == kHealthGpio && c.interface() == "estop") {
        estop = &c;
      }
      for (size_t k = 0; k < kJointCount; ++k) {
        if (c.prefix() != kJoints[k].name) {
          continue;
        }
        const std::string& n = c.interface();
        if (n == "position") cpos[k] = &c;
        if (n == "velocity") cvel[k] = &c;
        if (n == "stiffness") ckp[k] = &c;
        if (n == "damping") ckd[k] = &c;
        if (n == "effort") cff[k] = &c;
      }
    }
  }

  // Every interface the joint's command mode and the transport call for, and no other: a
  // velocity-commanded joint has no position or stiffness command, a position-target joint only a
  // position command, a transport without gains no stiffness or damping.
  bool complete() const {
    for (size_t k = 0; k < kJointCount; ++k) {
      const bool position_mode = kJoints[k].mode == kModePosition;
      if (!pos[k] || !vel[k] || !eff[k]) {
        return false;
      }
      for (size_t h = 0; h < kMotorHealthNames.size(); ++h) {
        if ((motor_health[k][h] != nullptr) != kMotorHealth[h]) {
          return false;
        }
      }
      if (kJoints[k].mode == kModeStateOnly) {  // state-only: no command interface
        if (cpos[k] || cvel[k] || ckp[k] || ckd[k] || cff[k]) {
          return false;
        }
        continue;
      }
      if (kJoints[k].mode == kModePositionTarget) {  // the position command alone
        if (!cpos[k] || cvel[k] || ckp[k] || ckd[k] || cff[k]) {
          return false;
        }
        continue;
      }
      if (!cvel[k] || !cff[k]) {
        return false;
      }
      if ((cpos[k] != nullptr) != position_mode || (ckp[k] != nullptr) != (position_mode && kHasGains) ||
          (ckd[k] != nullptr) != kHasGains) {
        return false;
      }
    }
    if (kImuEnabled) {
      for (const auto* i : imu) {
        if (!i) return false;
      }
    }
    if (kHasHealthGpio) {
      for (const auto* h : health) {
        if (!h) return false;
      }
      if (!estop) return false;
    }
    return true;
  }
};

// Values a controller writes: distinct per joint, inside the URDF limits, NOT representable in
// float (so a float SDK visibly rounds them and a double SDK must not).
struct ControllerCommand {
  std::array<double, N> q{}, dq{}, kp{}, kd{}, ff{};
};
inline ControllerCommand distinct_command(uint32_t variant) {
  ControllerCommand c;
  for (const Joint& j : kJoints) {
    const size_t s = j.slot;
    const Range r = position_range(j);
    c.q[s] = r.lo + (r.hi - r.lo) * (0.1 + 0.8 * (static_cast<double>(s) + 0.5) / static_cast<double>(N)) +
             1e-9 * (variant + 1);
    const double v = std::isfinite(j.velocity) && j.velocity > 0 ? 0.5 * j.velocity : 1.0;
    c.dq[s] = v * (0.1 + 0.01 * static_cast<double>(s)) * ((s % 2) != 0U ? -1.0 : 1.0) + 1e-9;
    c.kp[s] = 10.1 + static_cast<double>(s) + variant;
    c.kd[s] = 0.7 + 0.03 * static_cast<double>(s) + 0.001 * variant;
    const double e = std::isfinite(j.effort) && j.effort > 0 ? 0.5 * j.effort : 1.0;
    c.ff[s] = e * (0.05 + 0.01 * static_cast<double>(s)) * ((s % 3) == 0U ? -1.0 : 1.0) + 1e-9;
  }
  return c;
}

inline void apply_command(Interfaces& ifs, const ControllerCommand& c) {
  for (size_t k = 0; k < kJointCount; ++k) {
    const size_t s = kJoints[k].slot;
    if (ifs.cpos[k]) ifs.cpos[k]->set(c.q[s]);
    if (ifs.cvel[k]) ifs.cvel[k]->set(c.dq[s]);
    if (ifs.ckp[k]) ifs.ckp[k]->set(c.kp[s]);
    if (ifs.ckd[k]) ifs.ckd[k]->set(c.kd[s]);
    if (ifs.cff[k]) ifs.cff[k]->set(c.ff[s]);
  }
}

// ---------------------------------------------------------------- motors that are not joints
// robot_data.hpp's kTransmissions (per kJoints entry) and kCoupledWeights, written from the model
// by formula; identity for a robot whose motors are its joints.
inline size_t index_of(const Joint& j) { return static_cast<size_t>(&j - kJoints); }
inline bool is_coupled(const Joint& j) { return kTransmissions[index_of(j)].group >= 0; }

// The joint value motor values `m` (positions, or velocities without the offset) make.
inline double joint_value(const Joint& j, const std::array<double, N>& m, bool with_offset) {
  const Transmission& t = kTransmissions[index_of(j)];
  double v = with_offset ? t.offset : 0.0;
  if (t.group < 0) {
    return v + t.scale * m[j.slot];
  }
  for (size_t e = 0; e < kCoupledWeightCount; ++e) {
    if (kCoupledWeights[e].joint_slot == j.slot) {
      v += kCoupledWeights[e].weight * m[kCoupledWeights[e].motor_slot];
    }
  }
  return v;
}

// A simple joint's motor position for joint position `v`.
inline double motor_position(const Joint& j, double v) {
  const Transmission& t = kTransmissions[index_of(j)];
  return (v - t.offset) / t.scale;
}

// The motor positions (by slot) that put every joint at `joint` (by slot): simple joints through
// their ratio, each coupled group by solving matrix * motor = joint - offset (Gauss elimination
// with partial pivoting). Unmapped slots keep their value.
inline void motors_for_joints(const std::array<double, N>& joint, std::array<double, N>& motor) {
  for (const Joint& j : kJoints) {
    if (!is_coupled(j)) {
      motor[j.slot] = motor_position(j, joint[j.slot]);
    }
  }
  for (int g = 0;; ++g) {
    std::vector<size_t> slots;  // the group's joints' slots: its rows, and its motors' columns
    for (const Joint& j : kJoints) {
      if (kTransmissions[index_of(j)].group == g) slots.push_back(j.slot);
    }
    const size_t n = slots.size();
    if (n == 0) {
      return;
    }
    std::vector<double> a(n * (n + 1), 0.0);  // augmented [matrix | joint - offset]
    for (size_t r = 0; r < n; ++r) {
      for (size_t e = 0; e < kCoupledWeightCount; ++e) {
        if (kCoupledWeights[e].joint_slot != slots[r]) continue;
        for (size_t c = 0; c < n; ++c) {
          if (kCoupledWeights[e].motor_slot == slots[c]) a[r * (n + 1) + c] = kCoupledWeights[e].weight;
        }
      }
      a[r * (n + 1) + n] = joint[slots[r]] - kTransmissions[index_of(*joint_of_slot(slots[r]))].offset;
    }
    for (size_t c = 0; c < n; ++c) {
      size_t pivot = c;
      for (size_t r = c + 1; r < n; ++r) {
        if (std::fabs(a[r * (n + 1) + c]) > std::fabs(a[pivot * (n + 1) + c])) pivot = r;
      }
      for (size_t k = 0; k <= n; ++k) std::swap(a[c * (n + 1) + k], a[pivot * (n + 1) + k]);
      for (size_t r = 0; r < n; ++r) {
        if (r == c) continue;
        const double f = a[r * (n + 1) + c] / a[c * (n + 1) + c];
        for (size_t k = 0; k <= n; ++k) a[r * (n + 1) + k] -= f * a[c * (n + 1) + k];
      }
    }
    for (size_t r = 0; r < n; ++r) {
      motor[slots[r]] = a[r * (n + 1) + n] / a[r * (n + 1) + r];
    }
  }
}

}  // namespace rhi_test
