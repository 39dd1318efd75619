// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_HPP_

// A fake robot: the robot's side of its transport, for trying the real driver before the robot is
// on the bench. FakeRobotRunner steps the joints (fake_joint_dynamics.hpp) at the robot's state
// rate on one wall timer and hands them to the transport's fake side (transport/*_fake_robot.hpp),
// which speaks exactly the driver's protocol. Faults are injected at run time through the node's
// string parameter `fault` (`ros2 param set /<robot>_fake_robot fault silent`; a request it cannot
// carry out is refused with the reason). Everything runs on the node's one executor thread.
// The joints move in a vacuum (fake_joint_dynamics.hpp) unless use_mujoco() hands them to MuJoCo
// (fake_physics_mujoco.hpp: gravity, a floor, the links' coupling), which a package compiled with
// RHI_FAKE_PHYSICS_MUJOCO defined can do (its CMakeLists.txt defines it where it finds MuJoCo).

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rcl_interfaces/msg/set_parameters_result.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/parameter.hpp>
#include <rclcpp/timer.hpp>

#include "robot_hardware_interface/common/fake_joint_dynamics.hpp"
#include "robot_hardware_interface/common/fake_physics.hpp"
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
#include "robot_hardware_interface/common/fake_physics_mujoco.hpp"
#endif

namespace robot_hardware_interface
{

// Whether this build can simulate the robot on MuJoCo (--physics mujoco).
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
inline constexpr bool kFakeRobotHasMujoco = true;
#else
inline constexpr bool kFakeRobotHasMujoco = false;
#endif
// Why --physics mujoco cannot be, in a build without MuJoCo.
inline constexpr const char * kFakeRobotWithoutMujoco =
  "this robot_hardware_interface was built without MuJoCo: install it (pip install mujoco-core, or "
  "a MuJoCo release and -DRHI_MUJOCO_ROOT=<its folder>) and build the package again";

// Motor temperature of a healthy fake robot [deg C].
inline constexpr double kFakeAmbientTemperature = 35.0;
// What the accelerometer of a robot at rest reads, upwards [m/s^2].
inline constexpr double kStandardGravity = 9.80665;

// What the user broke (parameter `fault`). Every field is off until a fault is injected.
struct FakeFaults
{
  bool silent{false};   // publish nothing (a dead link)
  bool corrupt{false};  // publish frames the driver must reject (bad CRC, arrays too short)
};

// The robot's body: joints, motor health and injected faults. The transport's fake side reads
// it to publish state and writes the commands it receives into it.
template<size_t N>
struct FakeRobotModel
{
  FakeRobotModel(const FakeJointSpec * joints, size_t count)
  : dynamics(joints, count)
  {
    temperature.fill(kFakeAmbientTemperature);
    imu.linear_acceleration[2] = kStandardGravity;  // at rest until a physics engine measures it
  }

  FakeJointDynamics<N> dynamics;
  FakeImuReading imu;  // what the transports publish as the robot's IMU
  std::array<double, N> temperature{};  // [deg C]
  std::array<uint32_t, N> error_code{};  // the vendor's bit field, 0 = no error
  std::array<bool, N> offline{};  // the robot reports the motor unreachable
  FakeFaults faults;
  uint64_t steps{0};  // physics steps since start: transports publish slower messages every k-th
};

// The transport's fake side: subscribes the driver's commands, publishes the robot's state.
template<size_t N>
class FakeRobotTransport
{
public:
  virtual ~FakeRobotTransport() = default;
  virtual const char * name() const = 0;
  // The network interface it uses ("" for ROS 2 topics: ROS 2 discovery settings decide), and
  // whether another one can be chosen (--network-interface).
  virtual const char * network_interface() const {return "";}
  virtual bool set_network_interface(const char * /*name*/) {return false;}
  // Whether its messages carry motor temperatures (`hot` needs them), error codes (`error`) and
  // offline motors (`offline`).
  virtual bool carries_temperatures() const {return false;}
  virtual bool carries_error_codes() const {return false;}
  virtual bool carries_offline() const {return false;}
  // Create the subscriptions and publishers and size every message (no allocation afterwards).
  virtual void configure(const rclcpp::Node::SharedPtr & node, FakeRobotModel<N> & model) = 0;
  // Before each physics step: commands received on another thread (an SDK's) into the model.
  virtual void take_commands(FakeRobotModel<N> & /*model*/) {}
  // A joint was put at rest at `q` (FakeRobot::place): a side that plays the robot's own
  // controller holds it there from now on.
  virtual void placed(size_t /*slot*/, double /*q*/) {}
  // One state (and IMU, health) publication after a physics step.
  virtual void publish(const FakeRobotModel<N> & model) = 0;
};

// Achieved loop rate and jitter, for the log and the benchmark (allocation-free).
struct FakeLoopStats
{
  uint64_t steps{0};
  int64_t first_ns{0};
  int64_t last_ns{0};
  int64_t max_late_ns{0};   // largest period minus the nominal period
  int64_t max_early_ns{0};  // largest nominal period minus the period
  double sum_abs_jitter_ns{0.0};

  void record(int64_t now_ns, int64_t nominal_ns)
  {
    if (steps > 0) {
      const int64_t late = (now_ns - last_ns) - nominal_ns;
      max_late_ns = std::max(max_late_ns, late);
      max_early_ns = std::max(max_early_ns, -late);
      sum_abs_jitter_ns += static_cast<double>(late < 0 ? -late : late);
    } else {
      first_ns = now_ns;
    }
    last_ns = now_ns;
    ++steps;
  }
  double rate_hz() const
  {
    return steps > 1 && last_ns > first_ns ?
           static_cast<double>(steps - 1) * 1e9 / static_cast<double>(last_ns - first_ns) : 0.0;
  }
  double mean_jitter_us() const
  {
    return steps > 1 ? sum_abs_jitter_ns / static_cast<double>(steps - 1) / 1e3 : 0.0;
  }
};

// Whether the loop keeps its rate, said in one line when it stops and when it is back (issue 48).
// On a busy machine the wall timer fires late: each step still advances the robot by one nominal
// period, so the robot moves in slow motion, and its driver, which counts wall time, sees stale
// state and, past fault_timeout_ms without one, a dead link. The line tells a starving fake robot
// from a dead one. Windows of kWindowNs: short below kShortFraction of the nominal rate or with a
// gap between two steps above kGapNs (a driver's default state_timeout_ms). Said when the loop
// first falls short, then again only after kRepeatWindows windows or for a gap longer than any
// said; back once kBackWindows windows in a row kept the rate (a loop that hovers around the
// bound says little). Allocation-free (the line is formatted into a fixed buffer, only when there
// is something to say).
class FakeRateWatch
{
public:
  static constexpr int64_t kWindowNs = 2000000000;  // 2 s
  static constexpr double kShortFraction = 0.9;
  static constexpr int64_t kGapNs = 100000000;  // 100 ms
  static constexpr uint32_t kRepeatWindows = 15;  // 30 s
  static constexpr uint32_t kBackWindows = 5;  // 10 s

  // One loop step at steady time `now_ns`, the loop meant to run at `nominal_hz`. Returns the line
  // to log (*warning: it says the loop falls behind), nullptr when there is nothing to say.
  const char * record(int64_t now_ns, double nominal_hz, bool * warning)
  {
    if (steps_ == 0) {
      window_start_ns_ = now_ns;
    } else {
      longest_gap_ns_ = std::max(longest_gap_ns_, now_ns - last_ns_);
    }
    last_ns_ = now_ns;
    ++steps_;
    const int64_t elapsed = now_ns - window_start_ns_;
    if (elapsed < kWindowNs) {
      return nullptr;
    }
    const double rate = static_cast<double>(steps_ - 1) * 1e9 / static_cast<double>(elapsed);
    const int64_t gap = longest_gap_ns_;
    steps_ = 1;  // this step opens the next window
    window_start_ns_ = now_ns;
    longest_gap_ns_ = 0;
    ++windows_since_said_;
    const bool slow = rate < kShortFraction * nominal_hz;
    const bool stalled = gap > kGapNs;
    if (slow || stalled) {
      good_windows_ = 0;
      const bool say = !short_ || windows_since_said_ >= kRepeatWindows || gap > said_gap_ns_;
      short_ = true;
      if (!say) {
        return nullptr;
      }
      windows_since_said_ = 0;
      said_gap_ns_ = std::max(said_gap_ns_, gap);
      *warning = true;
      std::snprintf(
        line_.data(), line_.size(),
        "the loop falls behind: %.0f steps/s of its %.0f Hz over the last %.1f s, longest gap "
        "%.0f ms (the machine is too busy: the robot moves at %.2fx real time and its driver may "
        "see stale state or a dead link; a lighter load or --rate helps)",
        rate, nominal_hz, static_cast<double>(elapsed) / 1e9, static_cast<double>(gap) / 1e6,
        rate / nominal_hz);
      return line_.data();
    }
    if (!short_ || ++good_windows_ < kBackWindows) {
      return nullptr;
    }
    short_ = false;
    good_windows_ = 0;
    said_gap_ns_ = 0;
    *warning = false;
    std::snprintf(
      line_.data(), line_.size(), "the loop keeps its rate again: %.0f steps/s of its %.0f Hz",
      rate, nominal_hz);
    return line_.data();
  }

private:
  uint64_t steps_{0};
  int64_t window_start_ns_{0};
  int64_t last_ns_{0};
  int64_t longest_gap_ns_{0};
  bool short_{false};
  uint32_t windows_since_said_{0};
  uint32_t good_windows_{0};
  int64_t said_gap_ns_{0};
  std::array<char, 320> line_{};
};

// What every fake robot offers its executable and the tests, whatever its motor count.
class FakeRobot
{
public:
  virtual ~FakeRobot() = default;
  virtual const char * node_name() const = 0;
  virtual const char * transport() const = 0;
  virtual const char * network_interface() const = 0;
  virtual bool set_network_interface(const char * name) = 0;
  virtual double rate_hz() const = 0;
  // Subscriptions, publishers and the `fault` parameter; then start() runs the loop at `rate_hz`.
  virtual void configure(const rclcpp::Node::SharedPtr & node) = 0;
  virtual void start(double rate_hz) = 0;
  virtual void stop() = 0;
  // One loop iteration now (the wall timer's callback): physics, then publication.
  virtual void step() = 0;
  virtual size_t joint_count() const = 0;
  virtual const FakeJointSpec & joint(size_t k) const = 0;
  virtual double position(size_t slot) const = 0;
  virtual double velocity(size_t slot) const = 0;
  virtual void place(size_t slot, double q) = 0;
  virtual const FakeMotorCommand & last_command(size_t slot) const = 0;
  virtual const FakeLoopStats & stats() const = 0;
  // What the robot's source tells a physics engine: its URDF, its IMU link, its transmissions.
  virtual const FakePhysicsSpec & physics_spec() const = 0;
  // Before configure(): hand the joints to MuJoCo, the robot compiled from options.urdf_path
  // (imu_link and transmissions from physics_spec() where options leave them empty). False with
  // one line in *error: the package was built without MuJoCo, or MuJoCo cannot load the robot;
  // *warnings gets a line per thing the simulation leaves out. Not real-time.
  virtual bool use_mujoco(
    const FakePhysicsOptions & options, std::string * error,
    std::vector<std::string> * warnings) = 0;
  // "vacuum", or "mujoco" once use_mujoco() succeeded.
  virtual const char * physics() const = 0;
  // Where the robot's root link is in the world [m]: the simulation's, the origin in a vacuum
  // (where nothing carries the robot anywhere).
  virtual std::array<double, 3> base_position() const = 0;
  // The robot's mass as the simulation has it [kg] (0 in a vacuum), and the links that touched the
  // floor since the last call (none in a vacuum): what a test of a robot standing reads. Not
  // real-time.
  virtual double total_mass() const = 0;
  // The root link's orientation in the world (w, x, y, z): level in a vacuum.
  virtual std::array<double, 4> base_orientation() const = 0;
  virtual std::vector<std::string> floor_touches() = 0;
};

// The robot-independent fake robot: its loop, its faults, its body; the transport speaks.
template<size_t N>
class FakeRobotRunner final : public FakeRobot
{
public:
  FakeRobotRunner(
    const char * node_name, const FakeJointSpec * joints, size_t count, double rate_hz,
    std::unique_ptr<FakeRobotTransport<N>> transport, const FakePhysicsSpec & physics_spec)
  : node_name_(node_name), rate_hz_(rate_hz), model_(joints, count),
    transport_(std::move(transport)), physics_spec_(physics_spec)
  {
  }

  const char * node_name() const override {return node_name_;}
  const char * transport() const override {return transport_->name();}
  const char * network_interface() const override {return transport_->network_interface();}
  bool set_network_interface(const char * name) override
  {
    return transport_->set_network_interface(name);
  }
  double rate_hz() const override {return rate_hz_;}

  void configure(const rclcpp::Node::SharedPtr & node) override
  {
    node_ = node;
    transport_->configure(node, model_);
    // Declared before the callback exists (declaring runs the callbacks): a request given at
    // start-up (--ros-args -p fault:=silent) is applied here, from the first step.
    const std::string initial = node->declare_parameter<std::string>(kFaultParameter, "");
    const bool release = node->declare_parameter<bool>(kReleaseBandParameter, false);
    fault_callback_ = node->add_on_set_parameters_callback(
      [this](const std::vector<rclcpp::Parameter> & parameters) {
        return on_parameters(parameters);
      });
    std::string why;
    if (!initial.empty() && !apply_fault(initial.c_str(), &why)) {
      throw std::invalid_argument(std::string("parameter fault: ") + why);
    }
    if (release && !release_band(rclcpp::Parameter(kReleaseBandParameter, true), &why)) {
      throw std::invalid_argument(std::string("parameter release_band: ") + why);
    }
  }

  void start(double rate_hz) override
  {
    rate_hz_ = rate_hz;
    period_ns_ = static_cast<int64_t>(1e9 / rate_hz);
    timer_ = node_->create_wall_timer(
      std::chrono::nanoseconds(period_ns_), [this]() {
        step();
        watch_rate();
        watch_base();
      });
  }

  void stop() override
  {
    if (timer_) {
      timer_->cancel();
      timer_.reset();
    }
  }

  void step() override
  {
    const int64_t now_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now().time_since_epoch()).count();
    stats_.record(now_ns, period_ns_);
    transport_->take_commands(model_);
    // The nominal period, not the measured one: the same commands give the same motion.
    model_.dynamics.step(1.0 / rate_hz_);
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_) {
      model_.imu = physics_->imu();
    }
#endif
    ++model_.steps;
    if (!model_.faults.silent) {
      transport_->publish(model_);
    }
  }

  size_t joint_count() const override {return model_.dynamics.joint_count();}
  const FakeJointSpec & joint(size_t k) const override {return model_.dynamics.joints()[k];}
  double position(size_t slot) const override {return model_.dynamics.position(slot);}
  double velocity(size_t slot) const override {return model_.dynamics.velocity(slot);}
  void place(size_t slot, double q) override
  {
    model_.dynamics.place(slot, q);
    transport_->placed(slot, model_.dynamics.position(slot));
  }
  const FakeMotorCommand & last_command(size_t slot) const override
  {
    return model_.dynamics.last_command(slot);
  }
  const FakeLoopStats & stats() const override {return stats_;}
  const FakePhysicsSpec & physics_spec() const override {return physics_spec_;}

  bool use_mujoco(
    const FakePhysicsOptions & options, std::string * error,
    std::vector<std::string> * warnings) override
  {
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    FakePhysicsOptions o = options;
    if (o.imu_link.empty() && physics_spec_.imu_link != nullptr) {
      o.imu_link = physics_spec_.imu_link;
    }
    if (o.transmissions.empty() && physics_spec_.transmissions != nullptr) {
      o.transmissions.assign(
        physics_spec_.transmissions, physics_spec_.transmissions + model_.dynamics.joint_count());
    }
    if (o.contacts.empty() && physics_spec_.contacts != nullptr) {
      o.contacts.assign(
        physics_spec_.contacts, physics_spec_.contacts + physics_spec_.contact_count);
    }
    auto physics = std::make_unique<FakeMujocoPhysics<N>>(
      model_.dynamics.joints(), model_.dynamics.joint_count());
    if (!physics->load(o, error, warnings)) {
      return false;
    }
    model_.dynamics.use_engine(nullptr);
    physics_ = std::move(physics);
    band_ = o.base == FakeBase::kBand;
    model_.dynamics.use_engine(physics_.get());
    return true;
#else
    (void)options;
    (void)warnings;
    *error = kFakeRobotWithoutMujoco;
    return false;
#endif
  }

  const char * physics() const override
  {
    return model_.dynamics.has_engine() ? "mujoco" : "vacuum";
  }

  std::array<double, 3> base_position() const override
  {
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_) {
      return physics_->base_position();
    }
#endif
    return {0.0, 0.0, 0.0};
  }

  std::array<double, 4> base_orientation() const override
  {
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_) {
      return physics_->base_orientation();
    }
#endif
    return {1.0, 0.0, 0.0, 0.0};
  }

  double total_mass() const override
  {
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_) {
      return physics_->total_mass();
    }
#endif
    return 0.0;
  }

  std::vector<std::string> floor_touches() override
  {
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_) {
      return physics_->floor_touches();
    }
#endif
    return {};
  }

private:
  static constexpr const char * kFaultParameter = "fault";

  // After each step of the wall timer's loop (not in step(), which tests call at their own pace).
  void watch_rate()
  {
    bool warning = false;
    const char * line = rate_watch_.record(stats_.last_ns, rate_hz_, &warning);
    if (line == nullptr) {
      return;
    }
    if (warning) {
      RCLCPP_WARN(node_->get_logger(), "%s", line);
    } else {
      RCLCPP_INFO(node_->get_logger(), "%s", line);
    }
  }

  // After each step of the wall timer's loop, on MuJoCo: one line when the robot's root link tips
  // past kFallenTilt (it fell, or hangs tipped over in the band), one when it is upright again.
  void watch_base()
  {
    if (!model_.dynamics.has_engine()) {
      return;
    }
    const std::array<double, 4> q = base_orientation();
    const double tilt = std::acos(std::clamp(1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]), -1.0, 1.0)) *
      180.0 / 3.14159265358979323846;
    if (!fallen_ && tilt > kFallenTilt) {
      fallen_ = true;
      RCLCPP_WARN(
        node_->get_logger(), "the robot fell: its root link tilts %.0f degrees, at %.2f m above "
        "the floor", tilt, base_position()[2]);
    } else if (fallen_ && tilt < kUprightTilt) {
      fallen_ = false;
      RCLCPP_INFO(node_->get_logger(), "the robot is upright again (%.1f degrees)", tilt);
    }
  }

  static constexpr double kFallenTilt = 45.0;   // [degrees]
  static constexpr double kUprightTilt = 10.0;  // [degrees]
  static constexpr const char * kReleaseBandParameter = "release_band";

  // `ros2 param set <node> fault <request>`: carried out, or refused with the reason.
  rcl_interfaces::msg::SetParametersResult on_parameters(
    const std::vector<rclcpp::Parameter> & parameters)
  {
    rcl_interfaces::msg::SetParametersResult result;
    result.successful = true;
    for (const rclcpp::Parameter & parameter : parameters) {
      if (parameter.get_name() == kReleaseBandParameter) {
        std::string why;
        if (!release_band(parameter, &why)) {
          RCLCPP_ERROR(node_->get_logger(), "release_band refused: %s", why.c_str());
          result.successful = false;
          result.reason = why;
        }
        continue;
      }
      if (parameter.get_name() != kFaultParameter) {
        continue;
      }
      const std::string & request = parameter.as_string();
      if (request.empty()) {
        continue;
      }
      std::string why;
      if (apply_fault(request.c_str(), &why)) {
        RCLCPP_WARN(node_->get_logger(), "fault injected: %s", request.c_str());
      } else {
        RCLCPP_ERROR(
          node_->get_logger(), "fault request '%s' refused: %s", request.c_str(), why.c_str());
        result.successful = false;
        result.reason = why;
      }
    }
    return result;
  }

  // `ros2 param set <node> release_band true`: the elastic band lets go of the robot (for good).
  bool release_band(const rclcpp::Parameter & parameter, std::string * why)
  {
    if (parameter.get_type() != rclcpp::ParameterType::PARAMETER_BOOL) {
      *why = "expected true or false";
      return false;
    }
    if (!parameter.as_bool()) {
      return true;  // a released band stays released
    }
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
    if (physics_ && band_) {
      if (physics_->band_holding()) {
        physics_->release_band();
        RCLCPP_WARN(node_->get_logger(), "band released: the robot stands on its own from now on");
      }
      return true;
    }
#endif
    *why = "no elastic band holds this robot (it has one with --physics mujoco --base band)";
    return false;
  }

  // silent | corrupt | hot <joint> <deg C> | error <joint> <code> | offline <joint> | clear
  bool apply_fault(const char * request, std::string * why)
  {
    char verb[16] = {0};
    char joint[128] = {0};
    char value[32] = {0};
    const int n = std::sscanf(request, "%15s %127s %31s", verb, joint, value);
    if (n == 1 && std::strcmp(verb, "silent") == 0) {
      model_.faults.silent = true;
      return true;
    }
    if (n == 1 && std::strcmp(verb, "corrupt") == 0) {
      model_.faults.corrupt = true;
      return true;
    }
    if (n == 1 && std::strcmp(verb, "clear") == 0) {
      model_.faults = FakeFaults{};
      model_.temperature.fill(kFakeAmbientTemperature);
      model_.error_code.fill(0U);
      model_.offline.fill(false);
      return true;
    }
    const bool hot = std::strcmp(verb, "hot") == 0;
    const bool error = std::strcmp(verb, "error") == 0;
    const bool offline = n == 2 && std::strcmp(verb, "offline") == 0;
    if (!offline && (n != 3 || (!hot && !error))) {
      *why = "expected one of: silent, corrupt, hot <joint> <deg C>, error <joint> <code>, "
        "offline <joint>, clear";
      return false;
    }
    const FakeJointSpec * spec = find_joint(joint);
    if (spec == nullptr) {
      *why = std::string("no joint named '") + joint + "' on this robot";
      return false;
    }
    if (offline) {
      if (!transport_->carries_offline()) {
        *why = std::string("the ") + transport_->name() + " messages carry no offline motors";
        return false;
      }
      model_.offline[spec->slot] = true;
      return true;
    }
    char * end = nullptr;
    if (hot && !transport_->carries_temperatures()) {
      *why = std::string("the ") + transport_->name() + " messages carry no motor temperatures";
      return false;
    }
    if (hot) {
      const double celsius = std::strtod(value, &end);
      if (end == value || *end != '\0' || !std::isfinite(celsius)) {
        *why = std::string("'") + value + "' is not a temperature in deg C";
        return false;
      }
      model_.temperature[spec->slot] = celsius;
      return true;
    }
    if (!transport_->carries_error_codes()) {
      *why = std::string("the ") + transport_->name() + " messages carry no motor error codes";
      return false;
    }
    const unsigned long long code = std::strtoull(value, &end, 0);  // NOLINT(runtime/int)
    if (end == value || *end != '\0' || value[0] == '-' || code > 0xFFFFFFFFULL) {
      *why = std::string("'") + value + "' is not an error code (0 to 0xFFFFFFFF)";
      return false;
    }
    model_.error_code[spec->slot] = static_cast<uint32_t>(code);
    return true;
  }

  const FakeJointSpec * find_joint(const char * name) const
  {
    for (size_t k = 0; k < model_.dynamics.joint_count(); ++k) {
      if (std::strcmp(model_.dynamics.joints()[k].name, name) == 0) {
        return &model_.dynamics.joints()[k];
      }
    }
    return nullptr;
  }

  const char * node_name_;
  double rate_hz_;
  int64_t period_ns_{0};
  FakeRobotModel<N> model_;
  std::unique_ptr<FakeRobotTransport<N>> transport_;
  rclcpp::Node::SharedPtr node_;
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr fault_callback_;
  rclcpp::TimerBase::SharedPtr timer_;
  FakeLoopStats stats_;
  FakeRateWatch rate_watch_;
  bool fallen_{false};  // watch_base()
  FakePhysicsSpec physics_spec_;
#if defined(RHI_FAKE_PHYSICS_MUJOCO)
  std::unique_ptr<FakeMujocoPhysics<N>> physics_;
  bool band_{false};  // --base band
#endif
};

// Defined by each robot's src/<vendor>/<robot>_fake_robot.cpp: the robot's fake robot, for the
// executable's main() (src/fake_robot_main.cpp) and for tests.
std::unique_ptr<FakeRobot> make_fake_robot();

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__FAKE_ROBOT_HPP_
