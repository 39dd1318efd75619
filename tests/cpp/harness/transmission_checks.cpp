// Motors that are not joints: the generated DriverCore with a robot whose motors are geared,
// reversed, offset and coupled, checked against the formulas written out here (independently of
// joint_transmissions.hpp), and the calibration file with every way it can be wrong.
//
// Built by tests/cpp/test_cpp_transmissions.py against a generated package's common headers and
// one distro's stand-ins, plain / ASan+UBSan / TSan. Output: "rhi-check: P passed, F failed".
//
// The robot: 6 motor slots, float frames.
//   slot 0  "reversed_geared": direction -1, reduction 50, offset 0.1, limits [-1, 1]
//   slot 1  "plain": the motor is the joint
//   slot 2  unmapped
//   slots 3, 4  "wrist_pitch", "wrist_roll": a differential, joint = A * motor + offset
//   slot 5  "wheel": velocity-commanded, direction -1, reduction 2
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <rclcpp/rclcpp.hpp>

#include "alloc_counter.hpp"
#include "check.hpp"
#include "rhi_fake/all.hpp"
#include "robot_hardware_interface/common/driver_core.hpp"

namespace {

using robot_hardware_interface::CommandMode;
using robot_hardware_interface::CoupledJointsSpec;
using robot_hardware_interface::DriverCore;
using robot_hardware_interface::JointSpec;
using robot_hardware_interface::JointTransmissionSpec;
using robot_hardware_interface::kNoLimit;
using robot_hardware_interface::RobotSpec;
using robot_hardware_interface::TransmissionSpec;

constexpr size_t N = 6;
using Core = DriverCore<N, float>;

constexpr std::array<JointSpec, 5> kJoints = {{
    {"reversed_geared", 0, CommandMode::kPosition, -1.0, 1.0, 3.0, 40.0, 20.0, 1.0, 0},
    {"plain", 1, CommandMode::kPosition, -2.0, 2.0, kNoLimit, kNoLimit, 10.0, 0.5, 0},
    {"wrist_pitch", 3, CommandMode::kPosition, -1.5, 1.5, kNoLimit, kNoLimit, 8.0, 0.4, 0},
    {"wrist_roll", 4, CommandMode::kPosition, -1.5, 1.5, kNoLimit, kNoLimit, 8.0, 0.4, 0},
    {"wheel", 5, CommandMode::kVelocity, -kNoLimit, kNoLimit, 30.0, 10.0, 0.0, 2.0, 0},
}};
constexpr RobotSpec kRobot{"test/TransmissionRobot", "transmission_robot", kJoints.data(), kJoints.size(),
                           nullptr, {{"motors"}},
                           {"lo", false, 2000, robot_hardware_interface::CommandWriterMode::kTimer, 1, 100, 1000, 10000, 0,
                            70, 85, 0}};

constexpr double kWristOffset[2] = {0.2, -0.3};
constexpr std::array<JointTransmissionSpec, 4> kTransmissions = {{
    {0, -1.0, 50.0, 0.1},
    {3, 1.0, 1.0, kWristOffset[0]},
    {4, 1.0, 1.0, kWristOffset[1]},
    {5, -1.0, 2.0, 0.0},
}};
constexpr std::array<size_t, 2> kWristSlots = {{3, 4}};
constexpr double kA[2][2] = {{0.5, 0.5}, {0.5, -0.5}};  // joint per motor
constexpr std::array<double, 4> kWristMatrix = {{kA[0][0], kA[0][1], kA[1][0], kA[1][1]}};
constexpr std::array<CoupledJointsSpec, 1> kGroups = {{{"wrist", 2, kWristSlots.data(), kWristMatrix.data()}}};
constexpr TransmissionSpec kTransmission{kTransmissions.data(), kTransmissions.size(), kGroups.data(), 1};

constexpr std::array<double, 4> kSingular = {{1.0, 2.0, 2.0, 4.0}};
constexpr std::array<CoupledJointsSpec, 1> kSingularGroups = {{{"wrist", 2, kWristSlots.data(), kSingular.data()}}};
constexpr TransmissionSpec kSingularTransmission{kTransmissions.data(), kTransmissions.size(),
                                                 kSingularGroups.data(), 1};

// ----------------------------------------------------------------- the formulas, written out
// Simple joints: joint = s * motor + o, s = direction / reduction; effort = motor / s.
struct Simple {
  double s;
  double o;
};
Simple simple(size_t slot, double calibration_direction = 1.0, double calibration_offset = 0.0) {
  switch (slot) {
    case 0: return {calibration_direction * -1.0 / 50.0, 0.1 + calibration_offset};
    case 5: return {calibration_direction * -1.0 / 2.0, calibration_offset};
    default: return {calibration_direction, calibration_offset};
  }
}

bool near(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance * (1.0 + std::fabs(b)); }

#define CHECK_NEAR(actual, expected, tolerance, ...)                                                     \
  do {                                                                                                  \
    const double rhi_got_ = (actual);                                                                   \
    const double rhi_want_ = (expected);                                                                \
    CHECK(near(rhi_got_, rhi_want_, tolerance), "%s: got %.9g, expected %.9g", (std::string(__VA_ARGS__)).c_str(), \
          rhi_got_, rhi_want_);                                                                         \
  } while (0)

int64_t now_ns() { return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A motor frame with distinct values in every slot.
void deliver(Core& core, const std::array<float, N>& q, const std::array<float, N>& dq, const std::array<float, N>& tau) {
  core.start_state_frame();
  core.state_frame().q = q;
  core.state_frame().dq = dq;
  core.state_frame().tau = tau;
  core.publish_state(now_ns());
}

void claim_all(Core& core) {
  std::vector<std::string> start;
  for (const JointSpec& j : kJoints) {
    for (const char* iface : {"position", "velocity", "effort", "stiffness", "damping"}) {
      if (j.mode == CommandMode::kVelocity && (std::string(iface) == "position" || std::string(iface) == "stiffness")) {
        continue;
      }
      start.push_back(std::string(j.name) + "/" + iface);
    }
  }
  core.claims().prepare_claims(start, std::vector<std::string>{});
  core.claims().commit_claims();
  core.claims().take_committed();
}

const std::array<float, N> kQ = {{2.5f, 0.75f, 9.0f, 0.4f, -0.2f, 3.0f}};
const std::array<float, N> kDq = {{10.0f, -0.5f, 8.0f, 0.3f, 0.1f, -4.0f}};
const std::array<float, N> kTau = {{0.25f, 1.5f, 7.0f, 2.0f, -1.0f, 0.5f}};

// ----------------------------------------------------------------- state
// `path` ("" for none) is accepted.
void calibrates(Core& core, const std::string& path, const char* what) {
  const std::string error = core.calibrate(path);
  CHECK(error.empty(), "%s: %s", what, error.c_str());
}

void check_state(Core& core, double cal_dir0, double cal_off0, double cal_off_pitch, const char* what) {
  const auto& joints = core.joints();
  for (size_t slot : {size_t{0}, size_t{1}, size_t{5}}) {
    const Simple t = simple(slot, slot == 0 ? cal_dir0 : 1.0, slot == 0 ? cal_off0 : 0.0);
    CHECK_NEAR(joints.pos[slot], t.s * kQ[slot] + t.o, 1e-12, std::string(what) + ": position of slot " + std::to_string(slot));
    CHECK_NEAR(joints.vel[slot], t.s * kDq[slot], 1e-12, std::string(what) + ": velocity of slot " + std::to_string(slot));
    CHECK_NEAR(joints.tau[slot], kTau[slot] / t.s, 1e-12, std::string(what) + ": effort of slot " + std::to_string(slot));
  }
  // Differential: joint = A * motor + offset; effort = A^-T * motor effort. For this A, A^-1 = 2 A^T... A^-T = 2A.
  const double offsets[2] = {kWristOffset[0] + cal_off_pitch, kWristOffset[1]};
  for (size_t j = 0; j < 2; ++j) {
    const size_t slot = kWristSlots[j];
    const double pos = kA[j][0] * kQ[3] + kA[j][1] * kQ[4] + offsets[j];
    const double vel = kA[j][0] * kDq[3] + kA[j][1] * kDq[4];
    const double tau = 2.0 * (kA[j][0] * kTau[3] + kA[j][1] * kTau[4]);
    CHECK_NEAR(joints.pos[slot], pos, 1e-12, std::string(what) + ": coupled position of " + kJoints[2 + j].name);
    CHECK_NEAR(joints.vel[slot], vel, 1e-12, std::string(what) + ": coupled velocity of " + kJoints[2 + j].name);
    CHECK_NEAR(joints.tau[slot], tau, 1e-12, std::string(what) + ": coupled effort of " + kJoints[2 + j].name);
  }
}

// Joint values back from a motor command, by the state formulas (what the robot will measure).
struct JointCommand {
  std::array<double, N> q{}, dq{}, kp{}, kd{}, ff{};
};
JointCommand joint_side(const robot_hardware_interface::MotorCommand<N, float>& m) {
  JointCommand j;
  for (size_t slot : {size_t{0}, size_t{1}, size_t{5}}) {
    const Simple t = simple(slot);
    j.q[slot] = t.s * m.q_target[slot] + t.o;
    j.dq[slot] = t.s * m.dq_target[slot];
    j.kp[slot] = m.kp[slot] / (t.s * t.s);
    j.kd[slot] = m.kd[slot] / (t.s * t.s);
    j.ff[slot] = m.tau_ff[slot] / t.s;
  }
  for (size_t r = 0; r < 2; ++r) {
    const size_t slot = kWristSlots[r];
    j.q[slot] = kA[r][0] * m.q_target[3] + kA[r][1] * m.q_target[4] + kWristOffset[r];
    j.dq[slot] = kA[r][0] * m.dq_target[3] + kA[r][1] * m.dq_target[4];
    j.ff[slot] = 2.0 * (kA[r][0] * m.tau_ff[3] + kA[r][1] * m.tau_ff[4]);  // A^-T
  }
  return j;
}

void test_state_and_safe_start() {
  rhi_check::Section section("transmission_state");
  Core core(kRobot, &kTransmission);
  CHECK(core.transmissions().error().empty(), "the generated transmissions are usable: %s", core.transmissions().error().c_str());
  CHECK(core.transmissions().active(), "a robot with transmissions converts");
  calibrates(core, "", "no calibration file");
  core.reset_for_activation();
  deliver(core, kQ, kDq, kTau);
  // Layer 2: the first command holds the measured motor positions, in motor space.
  const auto* first = core.next_command();
  CHECK(first != nullptr, "a command after the first state");
  if (first != nullptr) {
    for (size_t slot = 0; slot < N; ++slot) {
      CHECK_EQ(first->q_target[slot], kQ[slot], "layer 2 holds motor %zu where it is", slot);
      CHECK_EQ(first->kp[slot], 0.0f, "layer 2: motor %zu kp", slot);
    }
  }
  core.read_state();
  check_state(core, 1.0, 0.0, 0.0, "state");
  // Layer 3: the first write() holds the measured pose (in joint space): motor targets = measured.
  claim_all(core);
  core.write_command();
  const auto* held = core.next_command();
  CHECK(held != nullptr, "a command after write()");
  if (held != nullptr) {
    for (size_t slot : {size_t{0}, size_t{1}, size_t{3}, size_t{4}, size_t{5}}) {
      CHECK_NEAR(held->q_target[slot], kQ[slot], 1e-6, "safe start holds motor " + std::to_string(slot) + " where it is");
      CHECK_EQ(held->kp[slot], 0.0f, "safe start: motor %zu kp", slot);
      CHECK_EQ(held->kd[slot], 0.0f, "safe start: motor %zu kd", slot);
    }
  }
}

void test_command_round_trip() {
  rhi_check::Section section("transmission_commands");
  Core core(kRobot, &kTransmission);
  core.reset_for_activation();
  deliver(core, kQ, kDq, kTau);
  core.read_state();
  claim_all(core);
  core.write_command();  // safe start
  auto& j = core.joints();
  const std::array<double, N> q = {{0.3, -1.25, 0.0, 0.7, -0.4, 0.0}};
  const std::array<double, N> dq = {{1.5, 0.5, 0.0, -0.25, 0.75, 6.0}};
  const std::array<double, N> kp = {{30.0, 12.0, 0.0, 9.0, 9.0, 0.0}};
  const std::array<double, N> kd = {{1.5, 0.25, 0.0, 0.5, 0.5, 3.0}};
  const std::array<double, N> ff = {{5.0, -2.0, 0.0, 1.25, -0.75, 2.5}};
  j.pos_des = q;
  j.vel_des = dq;
  j.kp = kp;
  j.kd = kd;
  j.ff = ff;
  core.write_command();
  const auto* m = core.next_command();
  CHECK(m != nullptr, "a command is sent");
  if (m == nullptr) {
    return;
  }
  const JointCommand back = joint_side(*m);
  for (size_t slot : {size_t{0}, size_t{1}, size_t{3}, size_t{4}}) {
    CHECK_NEAR(back.q[slot], q[slot], 1e-6, "joint -> motor -> joint position of slot " + std::to_string(slot));
  }
  for (size_t slot : {size_t{0}, size_t{1}, size_t{3}, size_t{4}, size_t{5}}) {
    CHECK_NEAR(back.dq[slot], dq[slot], 1e-6, "joint -> motor -> joint velocity of slot " + std::to_string(slot));
    CHECK_NEAR(back.ff[slot], ff[slot], 1e-6, "joint -> motor -> joint effort of slot " + std::to_string(slot));
  }
  for (size_t slot : {size_t{0}, size_t{1}, size_t{5}}) {
    if (slot != 5) {
      CHECK_NEAR(back.kp[slot], kp[slot], 1e-6, "stiffness through the reduction, slot " + std::to_string(slot));
    }
    CHECK_NEAR(back.kd[slot], kd[slot], 1e-6, "damping through the reduction, slot " + std::to_string(slot));
  }
  // Coupled gains: the diagonal of A^T diag(k) A; equal joint gains and a differential: exact.
  for (size_t i = 0; i < 2; ++i) {
    const double want_kp = kA[0][i] * kA[0][i] * kp[3] + kA[1][i] * kA[1][i] * kp[4];
    const double want_kd = kA[0][i] * kA[0][i] * kd[3] + kA[1][i] * kA[1][i] * kd[4];
    CHECK_NEAR(m->kp[kWristSlots[i]], want_kp, 1e-6, "coupled motor stiffness " + std::to_string(i));
    CHECK_NEAR(m->kd[kWristSlots[i]], want_kd, 1e-6, "coupled motor damping " + std::to_string(i));
  }
  // The wheel has no position target: its motor's measured position.
  CHECK_NEAR(m->q_target[5], kQ[5], 1e-6, "velocity joint: motor target = measured motor position");
  CHECK_EQ(m->kp[5], 0.0f, "velocity joint: no stiffness");

  // Limits hold in joint space: beyond the upper limit, the motor goes where the joint is at 1.0.
  j.pos_des[0] = 5.0;
  j.pos_des[3] = -9.0;
  core.write_command();
  const auto* limited = core.next_command();
  if (limited != nullptr) {
    const JointCommand l = joint_side(*limited);
    CHECK_NEAR(l.q[0], 1.0, 1e-6, "joint position limit applies before the reduction");
    CHECK_NEAR(limited->q_target[0], (1.0 - 0.1) * -50.0, 1e-5, "motor target of the limited joint");
    CHECK_NEAR(l.q[3], -1.5, 1e-6, "coupled joint limited in joint space");
  }

  // A NaN on one coupled joint spoils both of its motors: both held with damping only.
  j.pos_des[0] = q[0];
  j.pos_des[3] = std::nan("");
  core.write_command();
  const auto* nan_held = core.next_command();
  if (nan_held != nullptr) {
    CHECK_EQ(nan_held->kp[3], 0.0f, "NaN on a coupled joint: motor 3 held with kp 0");
    CHECK_EQ(nan_held->kp[4], 0.0f, "NaN on a coupled joint: motor 4 held with kp 0");
    CHECK(std::isfinite(nan_held->q_target[3]) && std::isfinite(nan_held->q_target[4]), "no NaN reaches a motor");
    CHECK_NEAR(nan_held->kp[0], kp[0] / 2500.0, 1e-6, "the other joints keep their command");
  }
  // A negative gain on one coupled joint cannot hide behind the other's positive one.
  j.pos_des[3] = q[3];
  j.kp[3] = -1.0;
  j.kp[4] = 100.0;
  core.write_command();
  const auto* negative = core.next_command();
  if (negative != nullptr) {
    CHECK_EQ(negative->kp[3], 0.0f, "negative gain on a coupled joint: motor 3 held");
    CHECK_EQ(negative->kp[4], 0.0f, "negative gain on a coupled joint: motor 4 held");
  }
  j.kp = kp;
  j.kd[3] = 10.0;
  j.kd[4] = -1.0;
  core.write_command();
  const auto* negative_kd = core.next_command();
  if (negative_kd != nullptr) {
    CHECK_EQ(negative_kd->kp[3], 0.0f, "negative damping on a coupled joint: motor 3 held");
    CHECK_EQ(negative_kd->kp[4], 0.0f, "negative damping on a coupled joint: motor 4 held");
  }
  j.kd = kd;
  // Hot paths allocate nothing with transmissions on.
  const uint64_t allocations = rhi_alloc::count_in([&] {
    for (int i = 0; i < 200; ++i) {
      deliver(core, kQ, kDq, kTau);
      core.read_state();
      core.write_command();
      core.next_command();
    }
  });
  CHECK_EQ(allocations, uint64_t{0}, "heap allocations in 200 cycles of state, read, write and writer");
}

// ----------------------------------------------------------------- calibration file
std::string write_file(const std::string& name, const std::string& text) {
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir != nullptr ? dir : "/tmp") + "/rhi_calibration_" +
                           std::to_string(static_cast<long long>(::getpid())) + "_" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

void test_calibration() {
  rhi_check::Section section("calibration");
  {
    Core core(kRobot, &kTransmission);
    const std::string path = write_file("good",
                                        "# zero offsets, read in the zero pose\n"
                                        "reversed_geared: {offset: 0.05, direction: -1}  # remounted\n"
                                        "'wrist_pitch':\n"
                                        "  offset: -0.125\n");
    calibrates(core, path, "a valid calibration file is accepted");
    core.reset_for_activation();
    deliver(core, kQ, kDq, kTau);
    core.read_state();
    check_state(core, -1.0, 0.05, -0.125, "calibrated state");
    // Calibrating again starts from the generated values (not on top of the last calibration).
    calibrates(core, path, "calibrating twice");
    core.read_state();
    check_state(core, -1.0, 0.05, -0.125, "calibrated twice");
    calibrates(core, "", "no calibration file");
    core.read_state();
    check_state(core, 1.0, 0.0, 0.0, "calibration removed");
    std::remove(path.c_str());
  }
  {
    // A robot whose motors are its joints: no conversion at all, until a calibration asks for one.
    Core core(kRobot, nullptr);
    CHECK(!core.transmissions().active(), "no transmissions: read() and write() copy");
    const std::string path = write_file("plain", "plain: {offset: 0.5}\n");
    calibrates(core, path, "calibration of a robot without transmissions");
    CHECK(core.transmissions().active(), "a calibration turns the conversion on");
    core.reset_for_activation();
    deliver(core, kQ, kDq, kTau);
    core.read_state();
    CHECK_NEAR(core.joints().pos[1], kQ[1] + 0.5, 1e-12, "calibrated offset of a plain joint");
    CHECK_NEAR(core.joints().pos[0], kQ[0], 1e-12, "an uncalibrated joint of that robot");
    std::remove(path.c_str());
  }
  struct Bad {
    const char* name;
    const char* text;
    const char* says;  // words the one-line error must contain
  };
  const Bad bad[] = {
      {"unknown_joint", "elbow: {offset: 0.1}\n", "line 1: 'elbow' is not a joint"},
      {"not_a_number", "plain: {offset: abc}\n", "line 1: joint 'plain': offset 'abc' is not a finite number"},
      {"nan", "plain:\n  offset: .nan\n", "line 2: joint 'plain': offset '.nan' is not a finite number"},
      {"inf", "plain: {offset: inf}\n", "is not a finite number"},
      {"beyond_a_turn", "plain: {offset: 10}\n", "offset 10 is beyond one turn"},
      {"degrees", "\n\nplain: {offset: 90}\n", "line 3:"},
      {"direction_2", "plain: {direction: 2}\n", "direction 2 is not 1 or -1"},
      {"coupled_direction", "wrist_roll: {direction: -1}\n", "joint 'wrist_roll' is coupled"},
      {"duplicate", "plain: {offset: 0.1}\nplain: {offset: 0.2}\n", "line 2: joint 'plain' is given twice"},
      {"unknown_key", "plain: {ofset: 0.1}\n", "unknown key 'ofset'"},
      {"tab", "plain:\n\toffset: 0.1\n", "a tab character"},
      {"empty_joint", "plain:\nwheel: {offset: 0.1}\n", "line 1: joint 'plain' has no offset or direction"},
      {"scalar", "plain: 0.1\n", "expected a mapping"},
      {"garbage", "this is not yaml at all\n", "expected '<joint>: {offset"},
      {"orphan", "  offset: 0.1\n", "belongs to no joint"},
  };
  for (const Bad& b : bad) {
    Core core(kRobot, &kTransmission);
    const std::string path = write_file(b.name, b.text);
    const std::string error = core.calibrate(path);
    CHECK(error.find(b.says) != std::string::npos, "%s: '%s' does not say '%s'", b.name, error.c_str(), b.says);
    CHECK(error.rfind("calibration_file '" + path + "'", 0) == 0, "%s: the error names the file: %s", b.name,
          error.c_str());
    CHECK(error.find(" -> ") != std::string::npos && error.find('\n') == std::string::npos,
          "%s: one line with a fix: %s", b.name, error.c_str());
    // Refused: the generated transmissions stay as they are.
    core.reset_for_activation();
    deliver(core, kQ, kDq, kTau);
    core.read_state();
    check_state(core, 1.0, 0.0, 0.0, b.name);
    std::remove(path.c_str());
  }
  Core core(kRobot, &kTransmission);
  const std::string missing = core.calibrate("/nonexistent/rhi/calibration.yaml");
  CHECK(missing.find("cannot be read") != std::string::npos, "a missing file: %s", missing.c_str());
}

void test_singular_matrix() {
  rhi_check::Section section("transmission_spec");
  Core core(kRobot, &kSingularTransmission);
  CHECK(core.transmissions().error().find("coupled joints 'wrist': the matrix is singular") != std::string::npos,
        "a singular coupling matrix is named: '%s'", core.transmissions().error().c_str());
  CHECK(!core.calibrate("").empty(), "and refuses the configuration");
}

}  // namespace

int main() {
  rclcpp::init(0, nullptr);
  test_state_and_safe_start();
  test_command_round_trip();
  test_calibration();
  test_singular_matrix();
  return rhi_check::summary();
}
