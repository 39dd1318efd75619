// Runs one generated driver against a simulated robot (the rhi_fake stand-ins).
//
// Built per robot by tests/support/cpp_build.py: this file + robot_data.hpp (tables written from the
// vendor YAML, the URDF and the expanded ros2_control xacro) + the generated driver's object file
// (+ crc_probe.cpp for unitree_dds). The driver is created through pluginlib's registry
// (PLUGINLIB_EXPORT_CLASS), exactly as ros2_control's ResourceManager does: this translation unit
// never includes the generated header. It drives the driver through rhi_fake/hw.hpp, so the same
// source runs on every distro's stand-ins (Humble: on_init(info) + export_*; 4.x+: init(params)
// with a clock, logger and executor + the framework's export order and shared handles).
//
// Sections (see tests/cpp/harness/README.md): interfaces, safety, joint_map, imu, commands,
// command_safety, crc, parameters, decimation, faults, health, diagnostics, allocations, threads; the
// feature robots' fake_robot, arm_sdk, hands, take_control (the .inc files).
// Output: "section <name>: P passed, F failed" per section and "rhi-check: P passed, F failed".
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include <hardware_interface/system_interface.hpp>
#include <rclcpp/rclcpp.hpp>
#include <lifecycle_msgs/msg/state.hpp>
#include <rclcpp_lifecycle/state.hpp>
#include <diagnostic_msgs/msg/diagnostic_array.hpp>

#include "alloc_counter.hpp"
#include "check.hpp"
#include "harness_common.hpp"
#include "rhi_fake/all.hpp"
#include "rhi_fake/plugins.hpp"

#if defined(RHI_TRANSPORT_UNITREE_DDS) && defined(RHI_UNITREE_FAMILY_GO)
#include "transport_unitree_go.hpp"
#elif defined(RHI_TRANSPORT_UNITREE_DDS)
#include "transport_unitree_dds.hpp"
#elif defined(RHI_TRANSPORT_AGIBOT_TOPICS)
#include "transport_agibot_topics.hpp"
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
#include "transport_engineai_topics.hpp"
#elif defined(RHI_TRANSPORT_GENERIC_TOPICS)
#include "transport_generic_topics.hpp"
#elif defined(RHI_TRANSPORT_CUSTOM)
#include "transport_custom.hpp"
#else
#error "robot_data.hpp names no known transport"
#endif

namespace {

using namespace rhi_test;  // NOLINT
using hardware_interface::SystemInterface;
using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;
using Severity = rhi_fake::logs::Severity;

const rclcpp::Time kTime(0, 0, RCL_ROS_TIME);
const rclcpp::Duration kPeriod(0, 2000000);
const rclcpp_lifecycle::State kInactive(lifecycle_msgs::msg::State::PRIMARY_STATE_INACTIVE, "inactive");
const rclcpp_lifecycle::State kUnconfigured(lifecycle_msgs::msg::State::PRIMARY_STATE_UNCONFIGURED, "unconfigured");
const rclcpp_lifecycle::State kActive(lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE, "active");
constexpr const char* kFloatName = sizeof(SdkFloat) == sizeof(float) ? "float" : "double";

void fresh_process() {
  rhi_fake::reset_all();
#if defined(RHI_TRANSPORT_CUSTOM)
  Transport::reset_bus();
#endif
  rclcpp::init(0, nullptr);
}

struct Rig {
  rhi_fake::hw::Framework fw;  // first: outlives the driver, as the controller manager does
  std::shared_ptr<SystemInterface> hw;
  Transport t;
  Interfaces ifs;
  bool active{false};
};

// The controller manager switching controllers: `start` claims, `stop` releases (prepare, then
// perform, as ros2_control does).
void switch_claims(Rig& rig, const std::vector<std::string>& start, const std::vector<std::string>& stop) {
  CHECK(rig.hw->prepare_command_mode_switch(start, stop) == hardware_interface::return_type::OK,
        "prepare_command_mode_switch accepts the switch");
  CHECK(rig.hw->perform_command_mode_switch(start, stop) == hardware_interface::return_type::OK,
        "perform_command_mode_switch accepts the switch");
}

// "<joint>/<interface>" of every joint for the interfaces `pick` selects among the joint's own.
template <typename Pick>
std::vector<std::string> interface_names(Pick pick) {
  std::vector<std::string> out;
  for (size_t k = 0; k < kJointCount; ++k) {
    for (const std::string& iface : joint_commands(k)) {
      if (pick(k, iface)) {
        out.push_back(std::string(kJoints[k].name) + "/" + iface);
      }
    }
  }
  return out;
}

// A controller that claims every command interface of every joint (full MIT-style control).
void claim_everything(Rig& rig) {
  switch_claims(rig, interface_names([](size_t, const std::string&) { return true; }), {});
}

std::shared_ptr<SystemInterface> create_driver() {
  try {
    return rhi_fake::plugins::create<SystemInterface>(kPluginType);
  } catch (const std::exception& e) {
    CHECK(false, "plugin class %s is not exported as a hardware_interface::SystemInterface: %s", kPluginType,
          e.what());
    return nullptr;
  }
}

// Initialisation (on_init) through a try block: a driver must report bad input with ERROR, never throw.
CallbackReturn init_driver(rhi_fake::hw::Framework& fw, SystemInterface& hw, const hardware_interface::HardwareInfo& info,
                           bool* threw) {
  *threw = false;
  try {
    return fw.init(hw, info);
  } catch (const std::exception& e) {
    *threw = true;
    std::printf("on_init threw: %s\n", e.what());
  } catch (...) {
    *threw = true;
  }
  return CallbackReturn::ERROR;
}

bool setup(Rig& rig, const hardware_interface::HardwareInfo& info) {
  rig.hw = create_driver();
  if (!rig.hw) {
    return false;
  }
  bool threw = false;
  const CallbackReturn r = init_driver(rig.fw, *rig.hw, info, &threw);
  CHECK(!threw && r == CallbackReturn::SUCCESS, "on_init with a valid description returned %d%s",
        static_cast<int>(r), threw ? " (threw)" : "");
  if (r != CallbackReturn::SUCCESS) {
    return false;
  }
  rig.ifs.exported = rhi_fake::hw::export_interfaces(*rig.hw);
  rig.ifs.index();
  CHECK(rig.ifs.complete(), "every expected interface is exported");
  if (rig.ifs.complete()) {
    claim_everything(rig);  // the sections below play a controller that commands everything
  }
  return rig.ifs.complete();
}

bool activate(Rig& rig) {
  const CallbackReturn r = rig.hw->on_activate(kInactive);
  CHECK(r == CallbackReturn::SUCCESS, "on_activate returned %d", static_cast<int>(r));
#if defined(RHI_TRANSPORT_ROS)
  CHECK(rhi_fake::ros::wait_spinning_executors(1, std::chrono::seconds(5)),
        "on_activate starts exactly one executor spinning");
#endif
  rig.active = r == CallbackReturn::SUCCESS;
  return rig.active;
}

void deactivate(Rig& rig) {
  if (!rig.active) {
    return;
  }
  const CallbackReturn r = rig.hw->on_deactivate(kActive);
  CHECK(r == CallbackReturn::SUCCESS, "on_deactivate returned %d", static_cast<int>(r));
#if defined(RHI_TRANSPORT_ROS)
  CHECK(rhi_fake::ros::wait_spinning_executors(0, std::chrono::seconds(5)),
        "on_deactivate stops the executor thread");
#endif
  rig.active = false;
}

void teardown(Rig& rig) {
  deactivate(rig);
  rig.ifs = Interfaces{};
  rig.hw.reset();
}

// Milliseconds since `t0` on the steady clock.
int64_t ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0).count();
}

// Microseconds since `t0` on the steady clock, the clock the driver stamps states with and ages them by: a
// harness reading taken before a state was delivered bounds the driver's age of it from above, one taken
// after from below.
int64_t us_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - t0).count();
}

// A command that holds `state`'s positions with zero gains, zero velocity and zero effort.
void check_hold(const CommandFrame& c, const StateFrame& state, const char* what) {
  for (const Joint& j : kJoints) {
    const size_t s = j.slot;
    CHECK(c.present[s], "%s: slot %zu (%s) is in the command", what, s, j.name);
    CHECK_EQ(c.q[s], state.q[s], "%s: %s position target = measured position", what, j.name);
    CHECK_EQ(c.dq[s], 0.0, "%s: %s velocity target", what, j.name);
    CHECK_EQ(c.tau[s], 0.0, "%s: %s feed-forward effort", what, j.name);
    if (c.has_gains) {
      CHECK_EQ(c.kp[s], 0.0, "%s: %s stiffness", what, j.name);
      CHECK_EQ(c.kd[s], 0.0, "%s: %s damping", what, j.name);
    }
  }
}

bool last_command(Transport& t, CommandFrame& c, const char* what) {
  c = CommandFrame{};
  const bool ok = t.last_command(c);
  CHECK(ok, "%s: a command was sent", what);
  return ok;
}

void check_state_interfaces(const Interfaces& ifs, const StateFrame& f, const char* what) {
  for (size_t k = 0; k < kJointCount; ++k) {
    const Joint& j = kJoints[k];
    CHECK_EQ(ifs.pos[k]->get(), f.q[j.slot], "%s: %s/position = SDK slot %zu", what, j.name, j.slot);
    CHECK_EQ(ifs.vel[k]->get(), f.dq[j.slot], "%s: %s/velocity = SDK slot %zu", what, j.name, j.slot);
    if (effort_reported(j)) {
      CHECK_EQ(ifs.eff[k]->get(), f.tau[j.slot], "%s: %s/effort = SDK slot %zu", what, j.name, j.slot);
    } else {
      CHECK_EQ(ifs.eff[k]->get(), 0.0, "%s: %s/effort stays 0 (the robot reports no torque for it)", what, j.name);
    }
  }
}

// Zero heap allocations in the hot paths after warm-up: 200 cycles of state callback, IMU
// callback, read(), write() and command writer, each counted; prints the "allocations over" line.
void check_hot_path_allocations(Transport& t, SystemInterface& hw, Interfaces& ifs, const ControllerCommand& cmd) {
  // Warm up: the fakes size their retained messages on first use.
  for (uint32_t k = 0; k < 20; ++k) {
    t.prepare_state(coded_state(k));
    t.deliver_prepared();
    t.deliver_prepared_health();
    t.deliver_prepared_imu();
    hw.read(kTime, kPeriod);
    apply_command(ifs, cmd);
    hw.write(kTime, kPeriod);
    t.tick_writer();
  }
  uint64_t in_state = 0, in_health = 0, in_imu = 0, in_read = 0, in_write = 0, in_writer = 0;
  constexpr uint32_t kCycles = 200;
  const uint64_t sent_before = t.sent_messages();
  for (uint32_t k = 0; k < kCycles; ++k) {
    t.prepare_state(coded_state(100 + k));  // harness side, not counted
    in_state += rhi_alloc::count_in([&] { t.deliver_prepared(); });
    in_health += rhi_alloc::count_in([&] { t.deliver_prepared_health(); });
    in_imu += rhi_alloc::count_in([&] { t.deliver_prepared_imu(); });
    in_read += rhi_alloc::count_in([&] { hw.read(kTime, kPeriod); });
    in_write += rhi_alloc::count_in([&] { hw.write(kTime, kPeriod); });
    in_writer += rhi_alloc::count_in([&] { t.tick_writer(); });
  }
  std::printf("allocations over %u cycles: state callback %" PRIu64 ", IMU callback %" PRIu64 ", read() %" PRIu64
              ", write() %" PRIu64 ", command writer %" PRIu64 "\n",
              kCycles, in_state, in_imu, in_read, in_write, in_writer);
  CHECK_EQ(t.sent_messages() - sent_before, kCycles * Transport::command_messages_per_cycle(),
           "the measured cycles really sent commands");
  CHECK_EQ(in_state, 0U, "heap allocations in the state callback");
  CHECK_EQ(in_health, 0U, "heap allocations in the motor health callback (a message of its own)");
  CHECK_EQ(in_imu, 0U, "heap allocations in the IMU callback");
  CHECK_EQ(in_read, 0U, "heap allocations in read()");
  CHECK_EQ(in_write, 0U, "heap allocations in write()");
  CHECK_EQ(in_writer, 0U, "heap allocations in the command writer");
}

// ================================================================ interfaces
void test_interfaces() {
  rhi_check::Section section("interfaces");
  fresh_process();

  bool exported = false;
  for (const auto& c : rhi_fake::plugins::classes()) {
    if (c.derived == kPluginType && c.base == "hardware_interface::SystemInterface") {
      exported = true;
    }
  }
  CHECK(exported, "PLUGINLIB_EXPORT_CLASS(%s, hardware_interface::SystemInterface) is registered", kPluginType);

  const hardware_interface::HardwareInfo info = make_hardware_info();
  CHECK(rhi_fake::hw::plugin_name(info) == kPluginName, "the description's <plugin> is %s", kPluginName);
  CHECK_EQ(info.joints.size(), kJointCount, "joints in the ros2_control description");

  Rig rig;
  rig.hw = create_driver();
  if (!rig.hw) {
    return;
  }
  bool threw = false;
  const CallbackReturn r = init_driver(rig.fw, *rig.hw, info, &threw);
  CHECK(!threw && r == CallbackReturn::SUCCESS, "on_init(description) = SUCCESS");
  if (r != CallbackReturn::SUCCESS) {
    return;
  }
  rhi_fake::hw::Exported interfaces = rhi_fake::hw::export_interfaces(*rig.hw);
  const auto& states = interfaces.states();
  const auto& commands = interfaces.commands();
  std::map<std::string, int> state_count;
  std::map<std::string, int> command_count;
  for (const auto& s : states) {
    ++state_count[s.name()];
  }
  for (const auto& c : commands) {
    ++command_count[c.name()];
  }
  const auto count_of = [](const std::map<std::string, int>& counts, const std::string& name) {
    const auto it = counts.find(name);
    return it == counts.end() ? 0 : it->second;
  };
  for (const Joint& j : kJoints) {
    for (const char* iface : kJointStates) {
      CHECK_EQ(count_of(state_count, std::string(j.name) + "/" + iface), 1,
               "state interface %s/%s exported exactly once", j.name, iface);
    }
    for (size_t h = 0; h < kMotorHealthNames.size(); ++h) {
      CHECK_EQ(count_of(state_count, std::string(j.name) + "/" + kMotorHealthNames[h]), kMotorHealth[h] ? 1 : 0,
               "motor health state interface %s/%s exported %s", j.name, kMotorHealthNames[h],
               kMotorHealth[h] ? "exactly once" : "never (the message does not carry it)");
    }
  }
  size_t expected_commands = 0;
  for (size_t k = 0; k < kJointCount; ++k) {
    const Joint& j = kJoints[k];
    const std::vector<std::string> wanted = joint_commands(k);
    expected_commands += wanted.size();
    for (const char* iface : kJointCommands) {
      const bool want = std::find(wanted.begin(), wanted.end(), iface) != wanted.end();
      CHECK_EQ(count_of(command_count, std::string(j.name) + "/" + iface), want ? 1 : 0,
               "command interface %s/%s exported %s (%s-commanded joint%s)", j.name, iface,
               want ? "exactly once" : "never", mode_name(j),
               kHasGains ? "" : ", transport without gains");
    }
  }
  if (kImuEnabled) {
    for (const char* iface : kImuInterfaces) {
      CHECK_EQ(count_of(state_count, std::string(kImuName) + "/" + iface), 1,
               "IMU interface %s/%s exported exactly once", kImuName, iface);
    }
  }
  if (kHasHealthGpio) {
    for (const char* iface : kHealthStates) {
      CHECK_EQ(count_of(state_count, std::string(kHealthGpio) + "/" + iface), 1,
               "health GPIO state interface %s/%s exported exactly once", kHealthGpio, iface);
    }
    CHECK_EQ(count_of(command_count, std::string(kHealthGpio) + "/estop"), 1,
             "health GPIO command interface %s/estop exported exactly once", kHealthGpio);
  }
  // Nothing else: the totals equal the expected sets.
  CHECK_EQ(states.size(), (3 + kMotorHealthCount) * kJointCount + (kImuEnabled ? kImuInterfaces.size() : 0U) +
           (kHasHealthGpio ? kHealthStates.size() : 0U),
           "number of state interfaces (3 + motor health per mapped joint + IMU + health GPIO)");
  CHECK_EQ(commands.size(), expected_commands + (kHasHealthGpio ? 1U : 0U),
           "number of command interfaces (per joint mode + the e-stop)");
  CHECK_EQ(state_count.size(), states.size(), "state interface names are unique");
  CHECK_EQ(command_count.size(), commands.size(), "command interface names are unique");
  bool readable = true;
  for (const auto& s : states) {
    try {
      (void)s.get();
    } catch (const std::exception&) {
      readable = false;
    }
  }
  CHECK(readable, "every state interface points at storage");
  interfaces = rhi_fake::hw::Exported{};
  rig.hw.reset();

  // A joint the driver does not drive: refused with ERROR and a log line, not a crash.
  hardware_interface::HardwareInfo unknown = info;
  hardware_interface::ComponentInfo extra{};
  extra.name = "rhi_test_unknown_joint";
  extra.type = "joint";
  unknown.joints.push_back(extra);
  auto hw2 = create_driver();
  if (hw2) {
    rhi_fake::logs::clear();
    const CallbackReturn r2 = init_driver(rig.fw, *hw2, unknown, &threw);
    CHECK(!threw && r2 == CallbackReturn::ERROR, "on_init with a joint the robot does not have = ERROR");
    CHECK(rhi_fake::logs::contains("rhi_test_unknown_joint", Severity::Error),
          "the error log line names the unknown joint");
  }
}

// ================================================================ main scenario
// The main scenario's state_timeout_ms: the description's, or 1 s where that is shorter. Its sections run
// sequences of sends after one state (claims switched, commands changed) that a loaded machine may stretch
// past the description's 100 ms; a stale hold there would be the driver's rule, not a fault of the checks.
// command_safety sleeps past it to see the hold.
constexpr uint64_t kMainStateTimeoutMs = kDescriptionTimeoutMs > 1000 ? kDescriptionTimeoutMs : 1000;

hardware_interface::HardwareInfo main_scenario_info() {
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["state_timeout_ms"] = std::to_string(kMainStateTimeoutMs);
  info.hardware_parameters["fault_timeout_ms"] = std::to_string(60 * kMainStateTimeoutMs);
  return info;
}

void test_main_scenario() {
  fresh_process();
  Rig rig;
  if (!setup(rig, main_scenario_info()) || !activate(rig)) {
    teardown(rig);
    return;
  }
  Transport& t = rig.t;
  Interfaces& ifs = rig.ifs;
  SystemInterface& hw = *rig.hw;
  const size_t per_cycle = Transport::command_messages_per_cycle();
  const StateFrame s0 = distinct_state(0);
  const ControllerCommand bogus = distinct_command(7);  // what a controller may already hold
  CommandFrame c;

  {
    rhi_check::Section section("parameters");
    uint64_t period = 0;
    CHECK(t.writer_period_us(period), "one command writer runs after on_activate");
    CHECK_EQ(period, kDescriptionPeriodUs, "command writer period [us] from the description");
#if defined(RHI_TRANSPORT_UNITREE_DDS) || defined(RHI_TRANSPORT_CUSTOM)
    CHECK(t.network_interface() == kDescriptionNetworkInterface, "SDK network interface from the description (%s)",
          kDescriptionNetworkInterface);
#endif
  }

  {
    rhi_check::Section section("safety");
    for (int i = 0; i < 5; ++i) {
      t.tick_writer();
    }
    CHECK_EQ(t.sent_messages(), 0U, "layer 1: messages sent before any state");

    apply_command(ifs, bogus);
    CHECK(hw.read(kTime, kPeriod) == hardware_interface::return_type::OK, "read() without state returns OK");
    CHECK(hw.write(kTime, kPeriod) == hardware_interface::return_type::OK, "write() without state returns OK");
    for (int i = 0; i < 3; ++i) {
      t.tick_writer();
    }
    CHECK_EQ(t.sent_messages(), 0U, "layers 1+3: write() before the first state sends nothing");
    for (size_t k = 0; k < kJointCount; ++k) {
      CHECK_EQ(ifs.pos[k]->get(), 0.0, "%s/position before any state", kJoints[k].name);
    }

    t.deliver_invalid_state(distinct_state(1));
    t.tick_writer();
    CHECK_EQ(t.sent_messages(), 0U, "an invalid first frame is not a state: nothing sent");

    // Layer 2: the first valid state makes the writer hold the measured position, zero gains.
    CHECK(t.deliver_state(s0) > 0, "the state frame reaches the driver's subscription");
    const size_t imu_reached = t.deliver_imu(s0);
    CHECK(imu_reached > 0 || !kImuEnabled, "the IMU sample reaches the driver's subscription");
    t.tick_writer();
    CHECK_EQ(t.sent_messages(), per_cycle, "one command cycle after the first state");
    if (last_command(t, c, "layer 2")) {
      check_hold(c, s0, "layer 2 (first command after the first state)");
    }

    // Layer 3: the state arrived after this cycle's read(): write() must not forward the
    // controller's stale commands.
    apply_command(ifs, bogus);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (last_command(t, c, "layer 3")) {
      check_hold(c, s0, "layer 3 (write() before read() copied a state)");
    }

    // read() copies the state; the first write() seeds the command interfaces with it.
    hw.read(kTime, kPeriod);
    apply_command(ifs, bogus);
    hw.write(kTime, kPeriod);
    for (size_t k = 0; k < kJointCount; ++k) {
      const Joint& j = kJoints[k];
      if (ifs.cpos[k]) {
        CHECK_EQ(ifs.cpos[k]->get(), s0.q[j.slot], "layer 3: first write() sets %s/position to the measured one",
                 j.name);
      }
      if (ifs.cvel[k]) {  // Interfaces::complete(): every joint but a position-target one has it
        CHECK_EQ(ifs.cvel[k]->get(), 0.0, "layer 3: first write() zeroes %s/velocity", j.name);
      }
      if (ifs.ckp[k]) {
        CHECK_EQ(ifs.ckp[k]->get(), 0.0, "layer 3: first write() zeroes %s/stiffness", j.name);
      }
      if (ifs.ckd[k]) {
        CHECK_EQ(ifs.ckd[k]->get(), 0.0, "layer 3: first write() zeroes %s/damping", j.name);
      }
      if (ifs.cff[k]) {
        CHECK_EQ(ifs.cff[k]->get(), 0.0, "layer 3: first write() zeroes %s/effort", j.name);
      }
    }
    t.tick_writer();
    if (last_command(t, c, "layer 3 first write")) {
      check_hold(c, s0, "layer 3 (first write() after read())");
    }
  }

  {
    rhi_check::Section section("joint_map");
    check_state_interfaces(ifs, s0, "state");
    // Values of slots no joint is mapped to must appear nowhere.
    std::set<double> unmapped;
    for (size_t slot = 0; slot < N; ++slot) {
      if (joint_of_slot(slot) == nullptr) {
        unmapped.insert(s0.q[slot]);
        unmapped.insert(s0.dq[slot]);
        unmapped.insert(s0.tau[slot]);
      }
    }
    int leaked = 0;
    for (const auto& s : ifs.exported.states()) {
      // Motion values are distinct per slot; motor health values repeat by design (temperatures).
      const bool motion = s.interface() == "position" || s.interface() == "velocity" || s.interface() == "effort";
      leaked += motion && unmapped.count(s.get()) > 0 ? 1 : 0;
    }
    CHECK_EQ(leaked, 0, "state interfaces showing a value of an unmapped SDK slot");
#if defined(RHI_TRANSPORT_AGIBOT_TOPICS)
    // AimDK entries are named: a publisher that changes its joint order (again and again, and
    // back) still feeds every value to the joint it names, also when the driver caches the order.
    if (kDefaultDecimation == 1) {
      uint32_t frame = 40;
      for (const size_t rotate : {1U, 1U, 3U, 0U, 2U, 0U}) {
        const StateFrame f = distinct_state(frame++);
        t.deliver_rotated(f, rotate);
        hw.read(kTime, kPeriod);
        char what[64];
        std::snprintf(what, sizeof(what), "entries rotated by %zu", rotate);
        check_state_interfaces(ifs, f, what);
      }
      t.deliver_state(s0);
      hw.read(kTime, kPeriod);
      check_state_interfaces(ifs, s0, "state in the original order again");
      // A message naming one joint twice and another not at all is dropped whole: the duplicate
      // never stands in for the missing joint (whose value would silently go stale).
      const StateFrame dup = distinct_state(frame++);
      if (t.deliver_with_duplicate(dup)) {
        hw.read(kTime, kPeriod);
        StateFrame expected = dup;
        for (size_t slot = 0; slot < N; ++slot) {
          if (t.in_first_group(slot)) {
            expected.q[slot] = s0.q[slot];
            expected.dq[slot] = s0.dq[slot];
            expected.tau[slot] = s0.tau[slot];
          }
        }
        check_state_interfaces(ifs, expected, "group 0 repeating entry 0 in place of entry 1");
        t.deliver_state(s0);
        hw.read(kTime, kPeriod);
      }
    }
#endif
  }

  {
    rhi_check::Section section("imu");
    if (kImuEnabled) {
      // ros2_control order x, y, z, w; the fake robot sent w, x, y, z = 0.5, -0.25, 0.125, 0.8125.
      CHECK_EQ(ifs.imu[0]->get(), s0.quat_wxyz[1], "%s/orientation.x", kImuName);
      CHECK_EQ(ifs.imu[1]->get(), s0.quat_wxyz[2], "%s/orientation.y", kImuName);
      CHECK_EQ(ifs.imu[2]->get(), s0.quat_wxyz[3], "%s/orientation.z", kImuName);
      CHECK_EQ(ifs.imu[3]->get(), s0.quat_wxyz[0], "%s/orientation.w", kImuName);
      for (size_t i = 0; i < 3; ++i) {
        CHECK_EQ(ifs.imu[4 + i]->get(), s0.gyro[i], "%s/angular_velocity[%zu]", kImuName, i);
        CHECK_EQ(ifs.imu[7 + i]->get(), s0.acc[i], "%s/linear_acceleration[%zu]", kImuName, i);
      }
    }
  }

  {
    rhi_check::Section section("commands");
    for (uint32_t variant = 0; variant < 2; ++variant) {
      const ControllerCommand cmd = distinct_command(variant);
      apply_command(ifs, cmd);
      const uint64_t before = t.sent_messages();
      hw.write(kTime, kPeriod);
      t.tick_writer();
      CHECK_EQ(t.sent_messages() - before, per_cycle, "one command cycle per writer tick");
      if (!last_command(t, c, "commands")) {
        continue;
      }
      CHECK(t.command_names_ok(), "command message names every slot after the joint the YAML maps to it");
      size_t rounded = 0;
      for (const Joint& j : kJoints) {
        const size_t s = j.slot;
        CHECK(c.present[s], "%s: slot %zu is in the command", j.name, s);
        if (commands_position(j)) {
          CHECK_EQ(c.q[s], sdk(cmd.q[s]), "%s/position -> SDK slot %zu as %s", j.name, s, kFloatName);
        } else {
          const size_t k = static_cast<size_t>(&j - kJoints);
          CHECK_EQ(c.q[s], sdk(ifs.pos[k]->get()), "velocity-commanded %s: position target = measured position",
                   j.name);
        }
        // a position-target joint: velocity, effort and gains are 0 (it exports none of them)
        const bool pd = takes_pd_command(j);
        CHECK_EQ(c.dq[s], pd ? sdk(cmd.dq[s]) : 0.0, "%s/velocity -> SDK slot %zu as %s (%s)", j.name, s, kFloatName,
                 mode_name(j));
        CHECK_EQ(c.tau[s], pd ? sdk(cmd.ff[s]) : 0.0, "%s/effort -> SDK slot %zu as %s (%s)", j.name, s, kFloatName,
                 mode_name(j));
        if (c.has_gains) {
          CHECK_EQ(c.kp[s], j.mode == kModePosition ? sdk(cmd.kp[s]) : 0.0, "%s/stiffness -> SDK slot %zu as %s (0 "
                   "unless position-commanded)", j.name, s, kFloatName);
          CHECK_EQ(c.kd[s], pd ? sdk(cmd.kd[s]) : 0.0, "%s/damping -> SDK slot %zu as %s (%s)", j.name, s, kFloatName,
                   mode_name(j));
        }
        rounded += static_cast<double>(static_cast<float>(cmd.q[s])) != cmd.q[s] && j.mode == kModePosition ? 1U : 0U;
      }
      // The values are chosen so that float rounding is visible: a double SDK that received
      // float-rounded values fails the exact checks above, a float SDK must show the rounding.
      CHECK(rounded > 0, "test values are not representable in float");
      // Slots no joint is mapped to stay passive.
      for (size_t slot = 0; slot < N; ++slot) {
        if (joint_of_slot(slot) == nullptr && c.present[slot] && c.has_gains) {
          CHECK_EQ(c.kp[slot], 0.0, "unmapped slot %zu stiffness", slot);
          CHECK_EQ(c.kd[slot], 0.0, "unmapped slot %zu damping", slot);
        }
      }
#if defined(RHI_TRANSPORT_UNITREE_DDS)
      // The message family's own fields (hg: mode_pr, mode_machine; go: head, level_flag, motor
      // modes), unused slots and the CRC: transport_unitree_{dds,go}.hpp.
      t.check_raw_command(s0);
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
      const auto& raw = t.last_raw_command();
      CHECK_EQ(raw.parallel_parser_type, kParallelParserType, "JointCommand.parallel_parser_type from the YAML");
      CHECK_EQ(raw.position.size(), N, "JointCommand.position has one entry per SDK slot");
#endif
    }
  }

  {
    rhi_check::Section section("command_safety");
    // A non-finite command is never forwarded: that joint holds with damping only.
    const Joint& j0 = kJoints[0];
    ControllerCommand cmd = distinct_command(3);
    apply_command(ifs, cmd);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    CommandFrame good;
    last_command(t, good, "before NaN");
    // the target the joint's mode commands: position, or velocity for a velocity-commanded joint
    (commands_position(j0) ? cmd.q : cmd.dq)[j0.slot] = std::numeric_limits<double>::quiet_NaN();
    apply_command(ifs, cmd);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (last_command(t, c, "NaN command")) {
      CHECK(std::isfinite(c.q[j0.slot]) && std::isfinite(c.dq[j0.slot]), "NaN target of %s is not sent",
            j0.name);
      CHECK_EQ(c.q[j0.slot], good.q[j0.slot], "%s keeps its last safe position target", j0.name);
      CHECK_EQ(c.dq[j0.slot], 0.0, "%s: no velocity target while held", j0.name);
      CHECK_EQ(c.tau[j0.slot], 0.0, "%s: no feed-forward while held", j0.name);
      if (c.has_gains) {
        CHECK_EQ(c.kp[j0.slot], 0.0, "%s: stiffness 0 while held", j0.name);
      }
      for (size_t k = 1; k < kJointCount; ++k) {
        if (commands_position(kJoints[k])) {
          CHECK_EQ(c.q[kJoints[k].slot], sdk(cmd.q[kJoints[k].slot]), "%s unaffected by %s's NaN", kJoints[k].name,
                   j0.name);
        }
      }
    }
    // A negative gain is never forwarded either: the last joint that takes damping (position-target
    // joints take none), with a negative damping, holds its last safe target and damping; the others
    // are unaffected.
    size_t last_damped = 0;
    for (size_t k = 0; k < kJointCount; ++k) {
      last_damped = takes_pd_command(kJoints[k]) ? k : last_damped;
    }
    if (kHasGains && last_damped > 0) {
      const Joint& jn = kJoints[last_damped];
      cmd = distinct_command(3);
      apply_command(ifs, cmd);
      hw.write(kTime, kPeriod);
      t.tick_writer();
      last_command(t, good, "before a negative damping");
      cmd.kd[jn.slot] = -0.5;
      apply_command(ifs, cmd);
      hw.write(kTime, kPeriod);
      t.tick_writer();
      if (last_command(t, c, "negative damping")) {
        CHECK_EQ(c.kd[jn.slot], good.kd[jn.slot], "%s keeps its last safe damping, not a negative one", jn.name);
        CHECK_EQ(c.q[jn.slot], good.q[jn.slot], "%s keeps its last safe position target", jn.name);
        CHECK_EQ(c.dq[jn.slot], 0.0, "%s: no velocity target while held", jn.name);
        CHECK_EQ(c.tau[jn.slot], 0.0, "%s: no feed-forward while held", jn.name);
        CHECK_EQ(c.kp[jn.slot], 0.0, "%s: stiffness 0 while held", jn.name);
        CHECK_EQ(c.kd[j0.slot], sdk(cmd.kd[j0.slot]), "%s unaffected by %s's negative damping", j0.name, jn.name);
      }
    }
    // Position targets beyond the URDF limits are clamped.
    cmd = distinct_command(4);
    size_t clamped = 0;
    for (const Joint& j : kJoints) {
      if (std::isfinite(j.upper) && commands_position(j)) {
        cmd.q[j.slot] = j.upper + 1.0;
        ++clamped;
      }
    }
    apply_command(ifs, cmd);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (clamped > 0 && last_command(t, c, "clamp")) {
      for (const Joint& j : kJoints) {
        if (std::isfinite(j.upper) && commands_position(j)) {
          CHECK_EQ(c.q[j.slot], sdk(j.upper), "%s position target clamped to its URDF upper limit", j.name);
        }
      }
    }
    // Stale state: no frame for longer than state_timeout_ms -> every joint damping only.
    std::this_thread::sleep_for(std::chrono::milliseconds(kMainStateTimeoutMs + 60));
    t.tick_writer();
    if (last_command(t, c, "stale state")) {
      for (const Joint& j : kJoints) {
        CHECK_EQ(c.dq[j.slot], 0.0, "stale state: %s velocity target", j.name);
        CHECK_EQ(c.tau[j.slot], 0.0, "stale state: %s feed-forward", j.name);
        if (c.has_gains) {
          CHECK_EQ(c.kp[j.slot], 0.0, "stale state: %s stiffness", j.name);
        }
      }
    }
    // Fresh state again: commands flow again.
    t.deliver_state(s0);
    hw.read(kTime, kPeriod);
    cmd = distinct_command(5);
    apply_command(ifs, cmd);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (last_command(t, c, "after stale")) {
      CHECK_EQ(c.dq[j0.slot], sdk(cmd.dq[j0.slot]), "commands flow again once state is back");
      if (c.has_gains) {
        CHECK_EQ(c.kd[j0.slot], sdk(cmd.kd[j0.slot]), "damping flows again once state is back");
      }
    }
  }

#if defined(RHI_TRANSPORT_UNITREE_DDS)
  {
    rhi_check::Section section("crc");
    // A LowState_ with a wrong CRC is dropped: neither its joints nor its mode_machine are used.
    StateFrame bad = distinct_state(1);
    bad.mode_machine = 9;
    t.prepare_state(bad, true);
    CHECK(t.deliver_prepared() > 0, "bad-CRC frame delivered");
    hw.read(kTime, kPeriod);
    check_state_interfaces(ifs, s0, "after a bad-CRC LowState_");
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (Transport::kEchoesModeMachine) {
      CHECK_EQ(t.echoed_mode_machine(), s0.mode_machine, "mode_machine of a bad-CRC frame is ignored");
    }
    // A field changed after the CRC was computed: dropped too (one frame per field class).
    const auto tamper = Transport::tamper_fields();
    for (const auto& [field, change] : tamper) {
      t.prepare_state(bad, false);
      change(t.prepared());
      t.deliver_prepared();
      hw.read(kTime, kPeriod);
      CHECK_EQ(ifs.vel[0]->get(), s0.dq[kJoints[0].slot], "LowState_ with %s changed after its CRC is dropped",
               field);
    }
    // A valid frame right after is used, with its mode_machine.
    t.deliver_state(bad);
    hw.read(kTime, kPeriod);
    check_state_interfaces(ifs, bad, "valid frame after bad ones");
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (Transport::kEchoesModeMachine) {
      CHECK_EQ(t.echoed_mode_machine(), 9, "mode_machine of the valid frame is echoed");
    }
    CHECK_EQ(t.last_raw_command().crc(), rhi_ref::low_cmd_crc(t.last_raw_command()),
             "LowCmd_.crc = reference after mode_machine changed");
    t.deliver_state(s0);
    hw.read(kTime, kPeriod);
  }
#endif

  {
    rhi_check::Section section("allocations");
    check_hot_path_allocations(t, hw, ifs, distinct_command(1));
  }

  {
    rhi_check::Section section("command_modes");
    t.deliver_state(s0);
    hw.read(kTime, kPeriod);
    const auto everything = interface_names([](size_t, const std::string&) { return true; });
    const auto targets = interface_names([](size_t k, const std::string& i) {
      return i == target_interface(kJoints[k]);
    });
    const auto gains = interface_names([](size_t, const std::string& i) { return i == "stiffness" || i == "damping"; });
    // After a write() and a writer cycle: the command the robot received (the same state again first: the
    // state stays fresh however long the section takes).
    const auto sent = [&](const char* what) {
      t.deliver_state(s0);
      hw.write(kTime, kPeriod);
      t.tick_writer();
      return last_command(t, c, what);
    };
    // kp / kd a joint must receive: the controller's when claimed, else the default gains while
    // its position (or velocity) is claimed, else nothing.
    const auto check_gains = [&](const char* what, bool targets_claimed, bool gains_claimed,
                                 const ControllerCommand* cmd) {
      if (!c.has_gains) {
        return;
      }
      for (const Joint& j : kJoints) {
        const size_t s = j.slot;
        const double kp = gains_claimed && cmd ? sdk(cmd->kp[s]) : targets_claimed ? sdk(j.kp) : 0.0;
        const double kd = gains_claimed && cmd ? sdk(cmd->kd[s]) : targets_claimed ? sdk(j.kd) : 0.0;
        CHECK_EQ(c.kp[s], j.mode == kModePosition ? kp : 0.0, "%s: %s stiffness", what, j.name);
        CHECK_EQ(c.kd[s], takes_pd_command(j) ? kd : 0.0, "%s: %s damping", what, j.name);
      }
    };
    const auto check_at_measured = [&](const char* what) {
      for (size_t k = 0; k < kJointCount; ++k) {
        const Joint& j = kJoints[k];
        // what read() shows (a decimated stream may not have shown s0)
        CHECK_EQ(c.q[j.slot], sdk(ifs.pos[k]->get()), "%s: %s target = measured position (no jump)", what,
                 j.name);
        CHECK_EQ(c.dq[j.slot], 0.0, "%s: %s no velocity target", what, j.name);
        CHECK_EQ(c.tau[j.slot], 0.0, "%s: %s no feed-forward", what, j.name);
      }
    };

    // No controller: nothing is claimed, so the robot is limp whatever the interfaces hold.
    switch_claims(rig, {}, everything);
    apply_command(ifs, distinct_command(6));
    if (sent("nothing claimed")) {
      check_at_measured("nothing claimed");
      check_gains("nothing claimed", false, false, nullptr);
    }

    // A position-only controller (velocity for wheels): it starts from the measured position,
    // and the default gains make it move the robot.
    switch_claims(rig, targets, {});
    if (sent("position-only switch")) {
      check_at_measured("position-only controller, first cycle");
      check_gains("position-only controller, first cycle", true, false, nullptr);
    }
    const ControllerCommand cmd7 = distinct_command(7);
    apply_command(ifs, cmd7);
    if (sent("position-only command")) {
      for (const Joint& j : kJoints) {
        const size_t s = j.slot;
        if (commands_position(j)) {
          CHECK_EQ(c.q[s], sdk(cmd7.q[s]), "position-only: %s target", j.name);
          CHECK_EQ(c.dq[s], 0.0, "position-only: %s unclaimed velocity is not sent", j.name);
        } else {
          CHECK_EQ(c.dq[s], sdk(cmd7.dq[s]), "velocity-only: %s velocity target", j.name);
        }
        CHECK_EQ(c.tau[s], 0.0, "position-only: %s unclaimed effort is not sent", j.name);
      }
      check_gains("position-only controller", true, false, &cmd7);
    }
#if RHI_FAKE_HI_MAJOR >= 4
    // Framework-owned handles (4.x+): an unclaimed command interface, written by nobody, is never
    // read. Behind the driver's back, a value lands in joint A's unclaimed effort handle; cycles
    // run; then a switch that changes only joint B's claims makes write() publish the driver's own
    // doubles to every handle. Had the driver read A's effort, the handle would still show the value.
    if (kJointCount >= 2) {
      constexpr double kNobodyWrote = 4242.25;
      const Joint& a = kJoints[0];
      const std::string b_effort = std::string(kJoints[1].name) + "/effort";
      ifs.cff[0]->set(kNobodyWrote);
      for (int cycle = 0; cycle < 3; ++cycle) {
        hw.write(kTime, kPeriod);
      }
      switch_claims(rig, {b_effort}, {});
      hw.write(kTime, kPeriod);  // the switch cycle: the safe-start target, published to every handle
      CHECK(ifs.cff[0]->get() != kNobodyWrote, "unclaimed %s/effort is never read (the driver's own value "
            "was published over it)", a.name);
      switch_claims(rig, {}, {b_effort});
      hw.write(kTime, kPeriod);
      t.tick_writer();
    }
#endif
    // The robot moves: a velocity-commanded joint goes on reporting where it is, never the
    // position it had when its controller started.
    for (int code : {9, 10}) {  // two frames: a decimated stream shows one of them
      t.deliver_state(distinct_state(code));
      hw.read(kTime, kPeriod);
    }
    if (sent("velocity joints after the robot moved")) {
      for (size_t k = 0; k < kJointCount; ++k) {
        if (kJoints[k].mode == kModeVelocity) {
          CHECK_EQ(c.q[kJoints[k].slot], sdk(ifs.pos[k]->get()), "velocity joint %s: position = measured now",
                   kJoints[k].name);
        }
      }
    }

    if (kHasGains) {
      // A controller that also claims the gains: its values apply (from the defaults on).
      switch_claims(rig, gains, {});
      if (sent("gains claimed")) {
        check_gains("gains claimed, first cycle", true, false, nullptr);
      }
      const ControllerCommand cmd8 = distinct_command(8);
      apply_command(ifs, cmd8);
      if (sent("gains commanded")) {
        check_gains("gains claimed", true, true, &cmd8);
      }
      // Back to position-only: the previous controller's gains are not left behind...
      switch_claims(rig, {}, gains);
      apply_command(ifs, cmd8);
      if (sent("gains released")) {
        check_gains("gains released", true, false, nullptr);
      }
      // ... nor picked up by the next controller that claims them.
      switch_claims(rig, gains, {});
      if (sent("gains claimed again")) {
        check_gains("gains claimed again, first cycle", true, false, nullptr);
      }
    }
    // A prepared switch that is never performed changes nothing.
    CHECK(hw.prepare_command_mode_switch({}, everything) == hardware_interface::return_type::OK,
          "prepare_command_mode_switch of an aborted switch");
    apply_command(ifs, cmd7);
    if (sent("aborted switch")) {
      for (const Joint& j : kJoints) {
        if (commands_position(j)) {
          CHECK_EQ(c.q[j.slot], sdk(cmd7.q[j.slot]), "aborted switch: %s still commanded", j.name);
        }
      }
    }
    // Interfaces of other components (the controller manager may pass them) are ignored.
    switch_claims(rig, {"rhi_test_other_robot/position", "no_separator"}, {});
    claim_everything(rig);
    hw.write(kTime, kPeriod);
  }

  {
    rhi_check::Section section("safety");
    // Re-activation re-arms all three layers: the robot may have moved meanwhile.
    deactivate(rig);
    if (!activate(rig)) {
      teardown(rig);
      return;
    }
    const uint64_t sent = t.sent_messages();
    for (int i = 0; i < 3; ++i) {
      t.tick_writer();
    }
    CHECK_EQ(t.sent_messages() - sent, 0U, "layer 1 after re-activation: old commands are not sent");
    hw.read(kTime, kPeriod);
    apply_command(ifs, bogus);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    CHECK_EQ(t.sent_messages() - sent, 0U, "layers 1+3 after re-activation: write() sends nothing before a state");
    t.deliver_invalid_state(distinct_state(1));
    t.tick_writer();
    CHECK_EQ(t.sent_messages() - sent, 0U, "after re-activation an invalid frame is not a state");
    const StateFrame s1 = distinct_state(1);
    t.deliver_state(s1);
    t.deliver_imu(s1);
    t.tick_writer();
    CHECK_EQ(t.sent_messages() - sent, per_cycle, "one command cycle after the new first state");
    if (last_command(t, c, "re-activation layer 2")) {
      check_hold(c, s1, "layer 2 after re-activation");
    }
    apply_command(ifs, bogus);
    hw.write(kTime, kPeriod);
    t.tick_writer();
    if (last_command(t, c, "re-activation layer 3")) {
      check_hold(c, s1, "layer 3 after re-activation (state not yet read)");
    }
    // The controllers kept their claims: no mode switch seeds the command, layer 3 alone must.
    hw.read(kTime, kPeriod);
    apply_command(ifs, bogus);
    hw.write(kTime, kPeriod);
    for (size_t k = 0; k < kJointCount; ++k) {
      if (ifs.cpos[k]) {
        CHECK_EQ(ifs.cpos[k]->get(), s1.q[kJoints[k].slot],
                 "layer 3 after re-activation: first write() sets %s/position to the measured one", kJoints[k].name);
      }
    }
    t.tick_writer();
    if (last_command(t, c, "re-activation first write")) {
      check_hold(c, s1, "layer 3 after re-activation (first write() after read(), claims unchanged)");
    }
  }
  teardown(rig);
}

// ================================================================ parameters and decimation
// Deliver `frames` frames, read() after each; returns the indices whose values read() showed.
std::vector<uint32_t> processed_frames(Rig& rig, uint32_t frames) {
  std::vector<uint32_t> processed;
  int shown = -1;  // code read() showed last
  for (uint32_t k = 0; k < frames; ++k) {
    const uint32_t code = 200 + 7 * k;
    StateFrame f = coded_state(code);
    f.mode_machine = static_cast<uint8_t>(20 + k);
    rig.t.deliver_state(f);
    rig.hw->read(kTime, kPeriod);
    int same = 0, previous = 0;
    for (size_t j = 0; j < kJointCount; ++j) {
      const int d = decode_position(kJoints[j], rig.ifs.pos[j]->get());
      same += d == static_cast<int>(code % kCodes) ? 1 : 0;
      previous += d == shown ? 1 : 0;
    }
    if (same == static_cast<int>(kJointCount)) {
      processed.push_back(k);
      shown = static_cast<int>(code % kCodes);
    } else {
      CHECK(previous == static_cast<int>(kJointCount), "frame %u: read() shows a mix of frames", k);
    }
#if defined(RHI_TRANSPORT_UNITREE_DDS)
    // mode_machine is safety-critical: copied from every valid frame, decimated or not.
    rig.t.tick_writer();
    if (Transport::kEchoesModeMachine) {
      CHECK_EQ(rig.t.echoed_mode_machine(), f.mode_machine, "mode_machine of frame %u (decimated or not)", k);
    }
#endif
  }
  return processed;
}

void check_decimation(Rig& rig, uint32_t decimation, uint32_t frames) {
  rhi_check::Section section("decimation");
  const std::vector<uint32_t> processed = processed_frames(rig, frames);
  std::vector<uint32_t> expected;
  for (uint32_t k = 0; k < frames; k += decimation) {
    expected.push_back(k);
  }
  CHECK_EQ(processed.size(), expected.size(), "state_decimation %u: frames processed out of %u", decimation, frames);
  CHECK(processed == expected, "state_decimation %u: the first frame and every %u-th after it are processed",
        decimation, decimation);
  std::printf("decimation %u: %zu of %u frames processed\n", decimation, processed.size(), frames);
}

void test_parameters() {
  // Defaults: a description without <param>s gets the vendor YAML's values (spec defaults).
  {
    rhi_check::Section section("parameters");
    fresh_process();
    Rig rig;
    hardware_interface::HardwareInfo info = make_hardware_info();
    info.hardware_parameters.clear();
    if (setup(rig, info) && activate(rig)) {
      uint64_t period = 0;
      CHECK(rig.t.writer_period_us(period), "one command writer");
      CHECK_EQ(period, kDefaultPeriodUs, "default command_writer_period_us");
#if defined(RHI_TRANSPORT_UNITREE_DDS) || defined(RHI_TRANSPORT_CUSTOM)
      CHECK(rig.t.network_interface() == kDefaultNetworkInterface, "default network_interface %s",
            kDefaultNetworkInterface);
#endif
      check_decimation(rig, kDefaultDecimation, 12);
    }
    teardown(rig);
  }
  // Overrides.
  for (const uint32_t decimation : {3U, 4U}) {
    rhi_check::Section section("parameters");
    fresh_process();
    Rig rig;
    hardware_interface::HardwareInfo info = make_hardware_info();
    info.hardware_parameters["command_writer_period_us"] = "5000";
    info.hardware_parameters["state_decimation"] = std::to_string(decimation);
    info.hardware_parameters["state_timeout_ms"] = "250";
    info.hardware_parameters["enable_monitor"] = "false";
    info.hardware_parameters["network_interface"] = "rhi_test0";
    if (setup(rig, info) && activate(rig)) {
      uint64_t period = 0;
      CHECK(rig.t.writer_period_us(period), "one command writer");
      CHECK_EQ(period, 5000U, "command_writer_period_us override");
#if defined(RHI_TRANSPORT_UNITREE_DDS) || defined(RHI_TRANSPORT_CUSTOM)
      CHECK(rig.t.network_interface() == "rhi_test0", "network_interface override");
#endif
      check_decimation(rig, decimation, 10);
    }
    teardown(rig);
  }
  // Invalid values: CallbackReturn::ERROR and an error line naming the parameter; no exception.
  {
    rhi_check::Section section("parameters");
    const std::string description_timeout = std::to_string(kDescriptionTimeoutMs);
    std::vector<std::pair<const char*, const char*>> invalid = {
        {"command_writer_period_us", "abc"}, {"command_writer_period_us", ""},
        {"command_writer_period_us", "-1"},  {"command_writer_period_us", "0"},
        {"command_writer_period_us", "12x"}, {"command_writer_period_us", "99999999999999999999999"},
        {"command_writer_mode", "onwrite"},  {"command_writer_mode", ""},
        {"command_writer_mode", "Timer"},
        {"state_decimation", "0"},           {"state_decimation", "-3"},
        {"state_decimation", "two"},         {"state_decimation", "4.5"},
        {"state_timeout_ms", "0"},           {"state_timeout_ms", "soon"},
        {"enable_monitor", "maybe"},
        {"fault_timeout_ms", "1"},           {"fault_timeout_ms", "later"},
        // not more than the description's state_timeout_ms: the driver would fault before it holds
        {"fault_timeout_ms", description_timeout.c_str()},
        {"diagnostics_period_ms", "60001"},  {"diagnostics_period_ms", "often"},
        {"motor_temperature_warn_c", "0"},   {"motor_temperature_error_c", "201"},
        // not above the default motor_temperature_warn_c (70)
        {"motor_temperature_error_c", "70"},
    };
    if (!kMotorHealth[2]) {  // a mask where no error code travels: refused, not silently idle
      invalid.emplace_back("motor_error_fault_mask", "12");
    }
    fresh_process();
    rhi_fake::hw::Framework fw;
    for (const auto& [name, value] : invalid) {
      hardware_interface::HardwareInfo info = make_hardware_info();
      info.hardware_parameters[name] = value;
      auto hw = create_driver();
      if (!hw) {
        return;
      }
      rhi_fake::logs::clear();
      bool threw = false;
      const CallbackReturn r = init_driver(fw, *hw, info, &threw);
      CHECK(!threw, "%s='%s': on_init does not throw", name, value);
      CHECK(r == CallbackReturn::ERROR, "%s='%s': on_init returns ERROR (got %d)", name, value, static_cast<int>(r));
      CHECK(rhi_fake::logs::contains(name, Severity::Error), "%s='%s': an error line names the parameter", name,
            value);
    }
  }
}

// Decimated frames still prove that state arrives: with state_decimation x frame period longer
// than state_timeout_ms, frames arriving every period must not make the writer hold the robot.
void test_decimation_keeps_state_fresh() {
  rhi_check::Section section("decimation");
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  constexpr int kDecimation = 8;
  constexpr int kTimeoutMs = 60;
  constexpr int kFramePeriodMs = 12;  // 8 x 12 ms = 96 ms between processed frames > 60 ms timeout
  info.hardware_parameters["state_decimation"] = std::to_string(kDecimation);
  info.hardware_parameters["state_timeout_ms"] = std::to_string(kTimeoutMs);
  if (!setup(rig, info) || !activate(rig)) {
    teardown(rig);
    return;
  }
  const ControllerCommand cmd = distinct_command(6);
  // Each cycle timed on the driver's clock from before its frame to after its send: in a cycle that took less
  // than state_timeout_ms the frame it brought (decimated or not) is younger than that at the send, so the
  // writer must not hold. A cycle the machine stalled longer is not judged (a hold there is the driver's
  // rule); a driver that ignores decimated frames holds about a third of the cycles it ran in time.
  int ticks = 0, held = 0, in_time = 0;
  CommandFrame c;
  for (uint32_t k = 0; k < 40; ++k) {
    const auto cycle_start = std::chrono::steady_clock::now();
    rig.t.deliver_state(coded_state(300 + k));
    rig.hw->read(kTime, kPeriod);
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    rig.t.tick_writer();
    const bool judged = us_since(cycle_start) < 1000 * kTimeoutMs;
    if (k >= 2 && judged && rig.t.last_command(c)) {  // frame 0 seeds, frame 1's write() is the layer-3 hold
      const Joint& j = kJoints[0];
      const bool holding = c.has_gains ? c.kp[j.slot] == 0.0 : (c.dq[j.slot] == 0.0 && c.tau[j.slot] == 0.0);
      ++in_time;
      held += holding ? 1 : 0;
    }
    ticks += k >= 2 ? 1 : 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(kFramePeriodMs));
  }
  std::printf("decimation %d, state_timeout_ms %d, a frame every %d ms: held in %d of %d writer cycles run in time "
              "(%d of %d; the others not judged)\n", kDecimation, kTimeoutMs, kFramePeriodMs, held, in_time, in_time,
              ticks);
  CHECK(in_time * 2 >= ticks, "at least half the cycles ran in less than state_timeout_ms (%d of %d): the machine "
        "did not stall the harness throughout", in_time, ticks);
  CHECK_EQ(held, 0, "frames keep arriving (decimated): in a cycle shorter than state_timeout_ms the writer never "
           "holds as if state were stale (held %d of %d)", held, in_time);

  // But decimated frames must not hide a bad stream: after a processed frame is rejected (NaN),
  // the skipped frames that follow do not keep the state fresh. Frame 40 is processed (40 % 8 == 0).
  auto hold_after = [&](const StateFrame& f) {
    rig.t.deliver_state(f);
    rig.hw->read(kTime, kPeriod);
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    rig.t.tick_writer();
    rig.t.last_command(c);
    const Joint& j = kJoints[0];
    return c.has_gains ? c.kp[j.slot] == 0.0 : (c.dq[j.slot] == 0.0 && c.tau[j.slot] == 0.0);
  };
  StateFrame bad = coded_state(340);
  bad.q[kJoints[0].slot] = std::numeric_limits<double>::quiet_NaN();
  hold_after(bad);
  std::this_thread::sleep_for(std::chrono::milliseconds(kFramePeriodMs));
  bool last_held = false;
  for (uint32_t k = 41; k < 48; ++k) {  // skipped frames, 7 x 12 ms > 60 ms
    last_held = hold_after(coded_state(300 + k));
    std::this_thread::sleep_for(std::chrono::milliseconds(kFramePeriodMs));
  }
  CHECK(last_held, "after a rejected frame, decimated frames alone do not keep the state fresh (writer holds)");
  const auto fresh_start = std::chrono::steady_clock::now();
  const bool fresh_held = hold_after(coded_state(348));
  CHECK(!fresh_held || us_since(fresh_start) >= 1000 * kTimeoutMs,
        "the next processed valid frame makes the state fresh again");
  teardown(rig);
}

// ================================================================ faults
// A dead link. The checks only rely on ordering on the driver's own clock (the steady clock): a
// read() that returned ERROR must have started more than fault_timeout_ms after the last state was
// delivered, and a read() that ended within fault_timeout_ms of it must have returned OK. The
// timeouts are far above any scheduling delay of a loaded machine (a cycle of a healthy robot is
// never late enough to be held), so that only the silences the checks make on purpose count; a
// check whose premise the machine broke anyway (a stall longer than a timeout) says so instead of
// judging (docs/testing.md, "Timing").
constexpr int kFaultStateTimeoutMs = 250;
constexpr int kFaultTimeoutMs = 1000;
constexpr int kFirstStateTimeoutMs = 2000;  // the wait for the first state (DDS discovery)

// Every joint damping only: kp = 0 (when the robot takes gains), no velocity target or effort.
void check_damping_only(const CommandFrame& c, const char* what) {
  for (const Joint& j : kJoints) {
    CHECK_EQ(c.dq[j.slot], 0.0, "%s: %s velocity target", what, j.name);
    CHECK_EQ(c.tau[j.slot], 0.0, "%s: %s feed-forward effort", what, j.name);
    if (c.has_gains) {
      CHECK_EQ(c.kp[j.slot], 0.0, "%s: %s stiffness", what, j.name);
    }
  }
}

// Controller cycles without any new state since `t0` (taken before the last state was delivered, or
// before on_activate) until read() returns ERROR (or 10 s past the fault timeout: a hang). Returns the
// milliseconds after t0 at which the ERROR read() ended, -1 for none. `stale_ok`: a read() returned
// OK while the writer held damping only, at a send more than state_timeout_ms after `since` (taken
// once the last state was delivered: the driver's age of it was past state_timeout_ms then, however
// slow the machine). `dead_after_ms`: the bound ERROR may not come before (fault_timeout_ms, or
// first_state_timeout_ms while the first state of the activation is awaited).
int64_t cycle_until_error(Rig& rig, std::chrono::steady_clock::time_point t0, std::chrono::steady_clock::time_point since,
                          const ControllerCommand& cmd, bool* stale_ok, uint64_t* allocations,
                          int dead_after_ms = kFaultTimeoutMs) {
  CommandFrame c;
  while (ms_since(t0) < dead_after_ms + 10000) {
    hardware_interface::return_type r = hardware_interface::return_type::OK;
    const uint64_t in_read = rhi_alloc::count_in([&] { r = rig.hw->read(kTime, kPeriod); });
    const int64_t after = ms_since(t0);
    if (r == hardware_interface::return_type::ERROR) {  // its error line may allocate, once
      CHECK(after >= dead_after_ms, "read() returned ERROR %" PRId64 " ms after the last state (or activation), "
            "not after more than %d ms", after, dead_after_ms);
      return after;
    }
    CHECK(r == hardware_interface::return_type::OK, "read() returns OK or ERROR");
    *allocations += in_read;
    apply_command(rig.ifs, cmd);
    *allocations += rhi_alloc::count_in([&] { rig.hw->write(kTime, kPeriod); });
    const uint64_t sent = rig.t.sent_messages();
    const bool held = us_since(since) > 1000 * kFaultStateTimeoutMs;  // before the send: its age is past it
    rig.t.tick_writer();
    if (held && rig.t.sent_messages() > sent && rig.t.last_command(c)) {
      check_damping_only(c, "stale state, read() still OK");
      *stale_ok = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK(false, "read() never returned ERROR within %d ms + 10 s without state", dead_after_ms);
  return -1;
}

// on_error after read() said ERROR: SUCCESS (the component can be configured again). As ros2_control
// (jazzy resource_manager.cpp / controller_manager.cpp) does, no mode switch: it deactivates the
// controllers that used the component, and the stop switch it attempts is refused before it reaches the
// component, whose interfaces are unavailable by then.
void enter_error(Rig& rig) {
  const CallbackReturn r = rig.hw->on_error(kActive);
  CHECK(r == CallbackReturn::SUCCESS, "on_error returned %d", static_cast<int>(r));
  rig.active = false;  // ros2_control calls no on_deactivate: the component is unconfigured now
}

// Configure and activate again (ros2 control set_hardware_component_state <name> active).
bool configure_and_activate(Rig& rig) {
  const CallbackReturn r = rig.hw->on_configure(kUnconfigured);
  CHECK(r == CallbackReturn::SUCCESS, "on_configure after on_error returned %d", static_cast<int>(r));
  return r == CallbackReturn::SUCCESS && activate(rig);
}

// The recovery the README gives: configure and activate, then the controllers again (ros2 control
// switch_controllers --activate ...), here the one that commands everything.
bool recover(Rig& rig) {
  if (!configure_and_activate(rig)) {
    return false;
  }
  claim_everything(rig);
  return true;
}

void test_faults() {
  rhi_check::Section section("faults");
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["state_timeout_ms"] = std::to_string(kFaultStateTimeoutMs);
  info.hardware_parameters["fault_timeout_ms"] = std::to_string(kFaultTimeoutMs);
  info.hardware_parameters["first_state_timeout_ms"] = std::to_string(kFirstStateTimeoutMs);
  if (!setup(rig, info)) {
    teardown(rig);
    return;
  }
  // ros2_control also reads an inactive component: configured but not started, a silent robot is
  // no fault, however long it stays silent.
  std::this_thread::sleep_for(std::chrono::milliseconds(kFaultTimeoutMs + 50));
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK,
        "read() of an inactive component, silent for longer than fault_timeout_ms, returns OK");
  auto t0 = std::chrono::steady_clock::now();  // before on_activate: the wait for a first state
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  Transport& t = rig.t;
  const ControllerCommand cmd = distinct_command(5);
  CommandFrame c;
  uint64_t allocations = 0;
  bool stale_ok = false;

  // A robot that never answers is a dead link too: ERROR first_state_timeout_ms after on_activate
  // (not fault_timeout_ms: DDS discovery of a running robot may take longer), said in one line.
  rhi_fake::logs::clear();
  const hardware_interface::return_type first_read = rig.hw->read(kTime, kPeriod);
  CHECK(first_read == hardware_interface::return_type::OK || ms_since(t0) >= kFaultTimeoutMs,
        "read() right after on_activate, before any state, returns OK");
  CHECK(cycle_until_error(rig, t0, t0, cmd, &stale_ok, &allocations, kFirstStateTimeoutMs) > 0,
        "no state at all after on_activate: read() returns ERROR after first_state_timeout_ms");
  CHECK_EQ(rhi_fake::logs::count(Severity::Error), 1U, "exactly one error line for a robot that never answered");
  CHECK_EQ(rhi_fake::logs::count_containing("never answered", Severity::Error), 1U,
           "the error line says the robot never answered");
  CHECK_EQ(rhi_fake::logs::count_containing("first_state_timeout_ms", Severity::Error), 1U,
           "the error line names first_state_timeout_ms");
  CHECK_EQ(rhi_fake::logs::count_containing("set_hardware_component_state", Severity::Error), 1U,
           "the error line says how to recover");
  enter_error(rig);
  t.tick_writer();
  CHECK_EQ(t.sent_messages(), 0U, "no state ever came: nothing is sent after on_error either (layer 1)");

  // A first state that comes late (DDS discovery past fault_timeout_ms, within
  // first_state_timeout_ms) is no fault: read() stays OK, and the link's rule is fault_timeout_ms
  // from then on (below).
  // Each read() is judged on the driver's clock: OK is due where it ended less than
  // first_state_timeout_ms after the harness asked for the activation (a machine that stalled past it
  // makes ERROR right, said as such); the wait goes on until the driver's wait is past fault_timeout_ms.
  const auto before_activation = std::chrono::steady_clock::now();
  if (!recover(rig)) {
    teardown(rig);
    return;
  }
  const auto late_t0 = std::chrono::steady_clock::now();
  bool late_ok = true;
  bool in_time = true;
  while (ms_since(late_t0) <= kFaultTimeoutMs + 10) {
    const bool ok = rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK;
    in_time = in_time && ms_since(before_activation) < kFirstStateTimeoutMs;
    late_ok = late_ok && (ok || !in_time);
    rig.hw->write(kTime, kPeriod);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK(late_ok, "read() returns OK while the first state is awaited past fault_timeout_ms (within "
        "first_state_timeout_ms)");
  t.deliver_state(coded_state(1));
  const bool late_read_ok = rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK;
  in_time = in_time && ms_since(before_activation) < kFirstStateTimeoutMs;
  if (!in_time) {
    std::printf("faults: the machine stalled the harness past first_state_timeout_ms (%d ms) while the late "
                "first state was awaited: an ERROR there is the driver's rule, not judged\n", kFirstStateTimeoutMs);
  }
  CHECK(late_read_ok || !in_time, "read() returns OK once the late first state came");
  t.tick_writer();
  if (last_command(t, c, "after a late first state")) {
    check_hold(c, coded_state(1), "first command after a late first state (layer 2)");
  }
  if (kHasHealthGpio) {
    CHECK_EQ(rig.ifs.health[kFault]->get(), 0.0, "no fault on the health GPIO after a late first state");
  }

  // A link that dies while the robot runs. Cycles with a fresh state until the controller's command
  // reaches the robot (the safe start takes three; a cycle the machine stalled past state_timeout_ms is
  // held, rightly, and the next one tries again).
  bool gains_sent = false;
  for (uint32_t k = 0; k < 50 && !gains_sent; ++k) {
    t.deliver_state(coded_state(k));
    rig.hw->read(kTime, kPeriod);
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    t.tick_writer();
    if (k >= 2 && last_command(t, c, "before the link dies")) {
      for (const Joint& j : kJoints) {
        gains_sent = gains_sent || c.kp[j.slot] != 0.0 || !c.has_gains;
      }
    }
  }
  CHECK(gains_sent, "the controller's command reaches the robot before the link dies");
  rhi_fake::logs::clear();
  stale_ok = false;
  allocations = 0;
  t0 = std::chrono::steady_clock::now();
  t.deliver_state(coded_state(3));  // the last state: the link dies after it
  const int64_t error_ms = cycle_until_error(rig, t0, std::chrono::steady_clock::now(), cmd, &stale_ok, &allocations);
  CHECK(stale_ok, "read() returned OK while the writer already held the joints damping-only (between "
        "state_timeout_ms and fault_timeout_ms)");
  if (kHasHealthGpio) {
    CHECK_EQ(rig.ifs.health[kFault]->get(), 1.0, "the health GPIO's fault after read() said ERROR");
    CHECK(rig.ifs.health[kStateAge]->get() > kFaultTimeoutMs, "state_age_ms of a dead link: %g",
          rig.ifs.health[kStateAge]->get());
  }
  hardware_interface::return_type again = hardware_interface::return_type::ERROR;
  for (int i = 0; i < 200; ++i) {  // read() runs at the control rate: ERROR each time, said once
    allocations += rhi_alloc::count_in([&] { again = rig.hw->read(kTime, kPeriod); });
    CHECK(again == hardware_interface::return_type::ERROR, "read() keeps returning ERROR on a dead link");
    allocations += rhi_alloc::count_in([&] { rig.hw->write(kTime, kPeriod); });
  }
  std::printf("faults: read() ERROR %" PRId64 " ms after the last state (state_timeout_ms %d, fault_timeout_ms "
              "%d); heap allocations in read()/write() on the way: %" PRIu64 "\n",
              error_ms, kFaultStateTimeoutMs, kFaultTimeoutMs, allocations);
  CHECK_EQ(allocations, 0U, "heap allocations in read()/write() while the link dies (but the one error line)");
  CHECK_EQ(rhi_fake::logs::count(Severity::Error), 1U, "exactly one error line for a dead link");
  CHECK_EQ(rhi_fake::logs::count_containing("fault_timeout_ms", Severity::Error), 1U,
           "the error line names fault_timeout_ms");
  CHECK_EQ(rhi_fake::logs::count_containing("set_hardware_component_state", Severity::Error), 1U,
           "the error line says what the operator runs next");

  // on_error: the writer keeps sending the hold, even once the state is back.
  enter_error(rig);
  const uint64_t sent = t.sent_messages();
  t.tick_writer();
  CHECK(t.sent_messages() > sent, "after on_error the writer still sends");
  if (last_command(t, c, "after on_error")) {
    check_damping_only(c, "after on_error");
  }
  t.deliver_state(coded_state(4));
  rig.hw->write(kTime, kPeriod);
  t.tick_writer();
  if (last_command(t, c, "state back, still in error")) {
    check_damping_only(c, "state back while in error (no controller runs): still damping only");
  }

  // Recovery: configure + activate go through the full three-layer safe start.
  if (!recover(rig)) {
    teardown(rig);
    return;
  }
  const uint64_t sent_at_activation = t.sent_messages();
  t.tick_writer();
  CHECK_EQ(t.sent_messages(), sent_at_activation, "after recovery, layer 1: nothing sent before the first state");
  const StateFrame back = coded_state(7);
  t.deliver_state(back);
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK, "read() returns OK after recovery");
  t.tick_writer();
  if (last_command(t, c, "recovery, layer 2")) {
    check_hold(c, back, "first command after recovery (layer 2)");
  }
  apply_command(rig.ifs, cmd);
  rig.hw->write(kTime, kPeriod);
  t.tick_writer();
  if (last_command(t, c, "recovery, layer 3")) {
    if (kHasTransmission) {
      check_damping_only(c, "first write() after recovery (layer 3)");
    } else {
      check_hold(c, back, "first write() after recovery (layer 3)");
    }
  }
  // Deactivated, the robot may go silent for good (powered down for the night): no fault either.
  deactivate(rig);
  std::this_thread::sleep_for(std::chrono::milliseconds(kFaultTimeoutMs + 50));
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK,
        "read() of a deactivated component, silent for longer than fault_timeout_ms, returns OK");
  teardown(rig);
}

// ================================================================ health
// The health GPIO: counters and the link age as the transport and the writer see them, and the
// e-stop: a latched damping-only hold that outlives its release until the next activation.
double health(const Rig& rig, HealthState which) {
  const auto* ref = rig.ifs.health[which];
  return ref ? ref->get() : std::numeric_limits<double>::quiet_NaN();
}

// One controller cycle with a new state: state callback, read(), `cmd` written, write(), a send.
void cycle(Rig& rig, uint32_t code, const ControllerCommand& cmd) {
  rig.t.deliver_state(coded_state(code));
  rig.hw->read(kTime, kPeriod);
  apply_command(rig.ifs, cmd);
  rig.hw->write(kTime, kPeriod);
  rig.t.tick_writer();
}

bool commands_reach_robot(Rig& rig, const char* what) {
  CommandFrame c;
  if (!last_command(rig.t, c, what)) {
    return false;
  }
  bool gains = !c.has_gains;
  bool moving = false;
  for (const Joint& j : kJoints) {
    gains = gains || c.kp[j.slot] != 0.0;
    moving = moving || c.tau[j.slot] != 0.0;
  }
  return gains && moving;
}

// Every joint's motor health interfaces show `f`'s values at its SDK slot.
void check_motor_health(const Rig& rig, const StateFrame& f, const char* what) {
  for (size_t k = 0; k < kJointCount; ++k) {
    const Joint& j = kJoints[k];
    const std::array<double, 3> expected = {f.temperature[j.slot], f.voltage[j.slot], f.error_code[j.slot]};
    for (size_t h = 0; h < kMotorHealthNames.size(); ++h) {
      if (kMotorHealth[h] && rig.ifs.motor_health[k][h] != nullptr) {
        CHECK_EQ(rig.ifs.motor_health[k][h]->get(), expected[h], "%s: %s/%s = SDK slot %zu", what, j.name,
                 kMotorHealthNames[h], j.slot);
      }
    }
  }
}

// Motor health from the robot's messages, at most every 10 ms (a health frame is due only then).
void check_motor_health_updates(Rig& rig) {
  using Clock = std::chrono::steady_clock;
  std::this_thread::sleep_for(std::chrono::milliseconds(12));  // the next health frame is due
  const StateFrame first = distinct_state(50);
  rig.t.deliver_state(first);
  const auto before_first_read = Clock::now();
  rig.hw->read(kTime, kPeriod);
  check_motor_health(rig, first, "a state 10 ms after the last health frame");
  const StateFrame soon = distinct_state(51);
  rig.t.deliver_state(soon);
  rig.hw->read(kTime, kPeriod);
  // Both read()s within 10 ms on the driver's clock (bounded from above by the harness's readings around
  // them): the second one takes no health frame. On a machine that stalled between them it is due: then
  // nothing to say.
  const bool within_period = Clock::now() - before_first_read < std::chrono::milliseconds(10);
  if (within_period) {
    check_motor_health(rig, first, "a state within 10 ms of the last health frame (health at 100 Hz)");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(12));
  const StateFrame later = distinct_state(52);
  rig.t.deliver_state(later);
  rig.hw->read(kTime, kPeriod);
  check_motor_health(rig, later, "the next health frame");
#if defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
  // MotorDebug is its own message: a short or non-finite one is dropped, the last temperatures stay.
  for (const bool short_array : {true, false}) {
    std::this_thread::sleep_for(std::chrono::milliseconds(12));
    CHECK(rig.t.deliver_bad_motor_debug(short_array) > 0, "the driver subscribes the motor debug topic");
    rig.hw->read(kTime, kPeriod);
    check_motor_health(rig, later, short_array ? "after a MotorDebug one motor short" : "after a NaN temperature");
  }
#endif
}

// A motor at motor_temperature_error_c (80 here) faults an active robot like a dead link: read()
// ERROR with one line naming the joint, on_error holds damping-only, and once the motor cooled,
// configure + activate bring it back.
void check_hot_motor_faults(Rig& rig) {
  const auto hot_state = [](uint32_t code, double hot_c) {
    StateFrame f = coded_state(code);
    f.temperature.fill(40.0);
    f.temperature[kJoints[0].slot] = hot_c;
    return f;
  };
  const ControllerCommand cmd = distinct_command(2);
  std::this_thread::sleep_for(std::chrono::milliseconds(12));  // a motor health frame is due
  cycle(rig, 700, cmd);
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK, "read() with every motor at 40 C");
  rhi_fake::logs::clear();
  std::this_thread::sleep_for(std::chrono::milliseconds(12));
  rig.t.deliver_state(hot_state(701, 80.0));
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::ERROR,
        "read() with %s at motor_temperature_error_c (80 C) returns ERROR", kJoints[0].name);
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::ERROR, "and keeps returning ERROR");
  CHECK_EQ(rig.ifs.health[kFault]->get(), 1.0, "the health GPIO's fault while a motor is too hot");
  CHECK_EQ(rhi_fake::logs::count_containing("too hot", Severity::Error), 1U, "one error line for the hot motor");
  CHECK(rhi_fake::logs::contains(kJoints[0].name, Severity::Error), "the error line names the joint");
  enter_error(rig);
  rig.t.tick_writer();
  CommandFrame c;
  if (last_command(rig.t, c, "hot motor, after on_error")) {
    check_damping_only(c, "hot motor, after on_error");
  }
  if (!recover(rig)) {
    return;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(12));
  rig.t.deliver_state(hot_state(702, 79.0));  // cooled below the limit
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK,
        "after the motor cooled, configure + activate: read() returns OK");
}

void check_health_description_refusals() {
  // A GPIO interface the driver does not have, or a second GPIO: ERROR naming it, never a throw.
  const hardware_interface::HardwareInfo info = make_hardware_info();
  Rig rig;
  bool threw = false;
  hardware_interface::HardwareInfo unknown = info;
  hardware_interface::InterfaceInfo bogus{};
  bogus.name = "rhi_test_bogus";
  bogus.size = 1;
  unknown.gpios.front().state_interfaces.push_back(bogus);
  rig.hw = create_driver();
  if (rig.hw) {
    rhi_fake::logs::clear();
    const CallbackReturn r = init_driver(rig.fw, *rig.hw, unknown, &threw);
    CHECK(!threw && r == CallbackReturn::ERROR, "on_init with an unknown health GPIO state interface = ERROR");
    CHECK(rhi_fake::logs::contains("rhi_test_bogus", Severity::Error), "the error line names the interface");
  }
  hardware_interface::HardwareInfo two = info;
  two.gpios.push_back(info.gpios.front());
  two.gpios.back().name = "rhi_test_second_gpio";
  rig.hw = create_driver();
  if (rig.hw) {
    rhi_fake::logs::clear();
    const CallbackReturn r = init_driver(rig.fw, *rig.hw, two, &threw);
    CHECK(!threw && r == CallbackReturn::ERROR, "on_init with a second <gpio> = ERROR");
    CHECK(rhi_fake::logs::contains("rhi_test_second_gpio", Severity::Error), "the error line names the GPIO");
  }
  // Without the GPIO the driver runs as before (a hand-written description may leave it out).
  hardware_interface::HardwareInfo without = info;
  without.gpios.clear();
  rig.hw = create_driver();
  if (rig.hw) {
    const CallbackReturn r = init_driver(rig.fw, *rig.hw, without, &threw);
    CHECK(!threw && r == CallbackReturn::SUCCESS, "on_init without the health GPIO = SUCCESS");
  }
  rig.hw.reset();
}

void test_health() {
  rhi_check::Section section("health");
  CHECK(kHasHealthGpio, "the generated description has the health GPIO");
  if (!kHasHealthGpio) {
    return;
  }
  fresh_process();
  check_health_description_refusals();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  // Far above any scheduling delay between a state and the next send (a healthy robot is never held);
  // the stale episodes below sleep past it, a lower bound on the driver's clock however slow the machine.
  constexpr int kStateTimeoutMs = kFaultStateTimeoutMs;
  info.hardware_parameters["state_timeout_ms"] = std::to_string(kStateTimeoutMs);
  info.hardware_parameters["fault_timeout_ms"] = "60000";
  info.hardware_parameters["state_decimation"] = "1";  // every frame parsed: every invalid one counted
  info.hardware_parameters["motor_temperature_warn_c"] = "60";
  info.hardware_parameters["motor_temperature_error_c"] = "80";
  if (!setup(rig, info)) {
    teardown(rig);
    return;
  }
  Transport& t = rig.t;
  CHECK(rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK, "read() before any state");
  CHECK_EQ(health(rig, kStateAge), -1.0, "state_age_ms before any state and activation");
  CHECK_EQ(health(rig, kFault), 0.0, "fault of an inactive component");
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  const ControllerCommand cmd = distinct_command(9);
  // Each cycle timed on the driver's clock, from before its state to after its send: while every one took
  // less than state_timeout_ms, no send can have been a stale hold.
  int64_t slowest_cycle_us = 0;
  for (uint32_t k = 0; k < 3; ++k) {
    const auto cycle_start = std::chrono::steady_clock::now();
    cycle(rig, k, cmd);
    slowest_cycle_us = std::max(slowest_cycle_us, us_since(cycle_start));
  }
  const bool cycles_in_time = slowest_cycle_us < 1000 * kStateTimeoutMs;
  if (!cycles_in_time) {
    std::printf("health: a cycle took %" PRId64 " us, past state_timeout_ms (%d ms): the machine stalled it, "
                "its stale hold is the driver's rule, not judged\n", slowest_cycle_us, kStateTimeoutMs);
  }
  CHECK(commands_reach_robot(rig, "healthy robot") || !cycles_in_time, "the controller's command reaches the robot");
  // A state half state_timeout_ms old is still fresh: the controller's command is sent, not a hold.
  {
    const auto delivered = std::chrono::steady_clock::now();
    t.deliver_state(coded_state(8));
    rig.hw->read(kTime, kPeriod);
    std::this_thread::sleep_for(std::chrono::milliseconds(kStateTimeoutMs / 2));
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    t.tick_writer();
    const bool fresh = us_since(delivered) < 1000 * kStateTimeoutMs;
    CHECK(commands_reach_robot(rig, "a state half state_timeout_ms old") || !fresh,
          "a state %d ms old (state_timeout_ms %d) is fresh: the controller's command is sent, not a hold",
          kStateTimeoutMs / 2, kStateTimeoutMs);
    slowest_cycle_us = std::max(slowest_cycle_us, fresh ? 0 : us_since(delivered));
  }
  const bool no_stall = slowest_cycle_us < 1000 * kStateTimeoutMs;
  const auto before_read = std::chrono::steady_clock::now();
  t.deliver_state(coded_state(3));
  rig.hw->read(kTime, kPeriod);
  const double bound_ms = static_cast<double>(ms_since(before_read)) + 1.0;
  CHECK(health(rig, kStateAge) >= 0.0 && health(rig, kStateAge) <= bound_ms,
        "state_age_ms right after a state: %g (<= %g)", health(rig, kStateAge), bound_ms);
  for (const HealthState h : {kInvalidStates, kStaleHolds, kRejectedCommands, kFault, kEstopState}) {
    if (h == kStaleHolds && !no_stall) {
      continue;  // said above: a cycle the machine stalled past state_timeout_ms is held, rightly
    }
    CHECK_EQ(health(rig, h), 0.0, "%s of a healthy robot", kHealthStates[h]);
  }

  if (kMotorHealthCount > 0) {
    check_motor_health_updates(rig);
  }

  // An invalid state frame (bad CRC, wrong size or names, non-finite value): counted once.
  t.deliver_corrupt_state(distinct_state(4));
  rig.hw->read(kTime, kPeriod);
  CHECK_EQ(health(rig, kInvalidStates), 1.0, "invalid_states after one invalid frame");
  cycle(rig, 5, cmd);

  // A non-finite command: one rejected writer cycle per send.
  ControllerCommand bad = cmd;
  const Joint& j0 = kJoints[0];
  (commands_position(j0) ? bad.q : bad.dq)[j0.slot] = std::numeric_limits<double>::quiet_NaN();
  cycle(rig, 6, bad);
  rig.hw->read(kTime, kPeriod);
  CHECK_EQ(health(rig, kRejectedCommands), 1.0, "rejected_commands after one send of a NaN command");
  cycle(rig, 7, cmd);
  rig.hw->read(kTime, kPeriod);
  CHECK_EQ(health(rig, kRejectedCommands), 1.0, "a valid command is not counted");

  // The state goes stale twice: two stale holds, however many sends each lasts. Counted from the
  // counter before each episode, after a send of the controller's command (no hold in progress).
  for (uint32_t episode = 1; episode <= 2; ++episode) {
    for (uint32_t k = 0; k < 50 && !commands_reach_robot(rig, "before a stale episode"); ++k) {
      cycle(rig, 60 + k, cmd);  // a cycle the machine stalled is held: the next one sends the command
    }
    const double holds_before = health(rig, kStaleHolds);
    const auto silent_since = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(kStateTimeoutMs + 5));  // past it on any clock
    for (int i = 0; i < 3; ++i) {
      rig.hw->write(kTime, kPeriod);
      t.tick_writer();
    }
    const int64_t lower_ms = ms_since(silent_since);
    rig.hw->read(kTime, kPeriod);
    CHECK_EQ(health(rig, kStaleHolds) - holds_before, 1.0, "stale_holds counts stale episode %u once (%g -> %g)",
             episode, holds_before, health(rig, kStaleHolds));
    CHECK(health(rig, kStateAge) >= static_cast<double>(lower_ms) - 1.0,
          "state_age_ms of a silent link: %g (>= %" PRId64 ")", health(rig, kStateAge), lower_ms);
    CHECK_EQ(health(rig, kFault), 0.0, "a stale hold is no fault (before fault_timeout_ms)");
    cycle(rig, 10 + episode, cmd);
    cycle(rig, 20 + episode, cmd);
  }

  // A send later than the period allows: a writer overrun.
  rig.hw->read(kTime, kPeriod);
  const double overruns = health(rig, kWriterOverruns);
  t.tick_writer();
  std::this_thread::sleep_for(std::chrono::microseconds(kDescriptionPeriodUs + 500 + 10000));
  t.tick_writer();
  rig.hw->read(kTime, kPeriod);
  CHECK(health(rig, kWriterOverruns) >= overruns + 1.0, "writer_overruns after a late send: %g (before %g)",
        health(rig, kWriterOverruns), overruns);

  // A framework handle nobody wrote holds NaN: no e-stop.
  rig.ifs.estop->set(std::numeric_limits<double>::quiet_NaN());
  cycle(rig, 30, cmd);
  cycle(rig, 31, cmd);
  CHECK(commands_reach_robot(rig, "estop NaN"), "estop = NaN does not stop the robot");

  // The e-stop: damping-only at the next send, said once, latched after its release.
  rhi_fake::logs::clear();
  rig.ifs.estop->set(1.0);
  uint64_t allocations = 0;
  CommandFrame c;
  for (uint32_t k = 0; k < 200; ++k) {
    t.deliver_state(coded_state(40 + k));
    hardware_interface::return_type r = hardware_interface::return_type::ERROR;
    const uint64_t in_read = rhi_alloc::count_in([&] { r = rig.hw->read(kTime, kPeriod); });
    CHECK(r == hardware_interface::return_type::OK, "read() with the e-stop pressed returns OK");
    apply_command(rig.ifs, cmd);
    const uint64_t in_write = rhi_alloc::count_in([&] { rig.hw->write(kTime, kPeriod); });
    allocations += in_read + (k == 0 ? 0 : in_write);  // the first write() says it, once
    t.tick_writer();
    if (k == 0 && last_command(t, c, "e-stop")) {
      check_damping_only(c, "first send after the e-stop");
    }
  }
  CHECK_EQ(allocations, 0U, "heap allocations in read()/write() with the e-stop pressed");
  CHECK_EQ(rhi_fake::logs::count_containing("e-stop", Severity::Error), 1U, "one error line for the e-stop");
  CHECK_EQ(health(rig, kEstopState), 1.0, "estop state while pressed");
  CHECK_EQ(health(rig, kFault), 1.0, "fault while the e-stop holds the robot");
  rig.ifs.estop->set(0.0);
  cycle(rig, 300, cmd);
  cycle(rig, 301, cmd);
  if (last_command(t, c, "e-stop released")) {
    check_damping_only(c, "e-stop released, not re-activated: still damping only");
  }
  CHECK_EQ(health(rig, kEstopState), 1.0, "estop state stays latched after the release");

  // Re-activation: the full safe start, then the controller's commands again.
  deactivate(rig);
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  const uint64_t sent_at_activation = t.sent_messages();
  t.tick_writer();
  CHECK_EQ(t.sent_messages(), sent_at_activation, "after the e-stop, layer 1: nothing before the first state");
  const StateFrame back = coded_state(400);
  t.deliver_state(back);
  rig.hw->read(kTime, kPeriod);
  CHECK_EQ(health(rig, kEstopState), 0.0, "estop state after re-activation");
  CHECK_EQ(health(rig, kFault), 0.0, "fault after re-activation");
  t.tick_writer();
  if (last_command(t, c, "after the e-stop, layer 2")) {
    check_hold(c, back, "first command after the e-stop (layer 2)");
  }
  for (uint32_t k = 0; k < 3; ++k) {
    cycle(rig, 401 + k, cmd);
  }
  CHECK(commands_reach_robot(rig, "after the e-stop"), "the controller's command reaches the robot again");

  // Activated with the e-stop still pressed: warned at activation, held from the first write().
  rig.ifs.estop->set(1.0);
  cycle(rig, 500, cmd);
  deactivate(rig);
  rhi_fake::logs::clear();
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  CHECK(rhi_fake::logs::contains("still pressed", Severity::Warn), "activation warns of a pressed e-stop");
  for (uint32_t k = 0; k < 3; ++k) {
    cycle(rig, 600 + k, cmd);
  }
  if (last_command(t, c, "activated with the e-stop pressed")) {
    check_damping_only(c, "activated with the e-stop pressed");
  }
  if (kMotorHealth[0]) {
    rig.ifs.estop->set(0.0);
    deactivate(rig);
    if (activate(rig)) {
      check_hot_motor_faults(rig);
    }
  }
  teardown(rig);
}

// ================================================================ diagnostics
// /diagnostics (diagnostic_msgs/DiagnosticArray, the real message): the driver's own thread publishes
// "<hardware>: link", "<hardware>: safety" and, where the state carries motor health, one status per
// motor group ("<hardware>: left leg motors", kJointMotorGroup) every diagnostics_period_ms. Waits poll with generous timeouts; a change counts once two
// more messages came (the one being built may predate it).
using DiagnosticArray = diagnostic_msgs::msg::DiagnosticArray;
using DiagnosticStatus = diagnostic_msgs::msg::DiagnosticStatus;
constexpr char kDiagnosticsTopic[] = "/diagnostics";

bool next_diagnostics(DiagnosticArray& out, const char* what) {
  const uint64_t before = rhi_fake::ros::publish_count(kDiagnosticsTopic);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (rhi_fake::ros::publish_count(kDiagnosticsTopic) < before + 2) {
    if (std::chrono::steady_clock::now() > deadline) {
      CHECK(false, "%s: no /diagnostics message within 5 s", what);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const bool got = rhi_fake::ros::last_published<DiagnosticArray>(kDiagnosticsTopic, out);
  CHECK(got, "%s: a /diagnostics message", what);
  return got;
}

const DiagnosticStatus* status_named(const DiagnosticArray& a, const std::string& name) {
  for (const DiagnosticStatus& s : a.status) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

std::string value_of(const DiagnosticStatus& s, const std::string& key) {
  for (const auto& kv : s.values) {
    if (kv.key == key) return kv.value;
  }
  return "<missing>";
}

// The status `part` of the latest message has `level` and a message containing `words`.
void check_status(const DiagnosticArray& a, const std::string& hardware, const char* part, uint8_t level,
                  const char* words, const char* what) {
  const DiagnosticStatus* s = status_named(a, hardware + ": " + part);
  CHECK(s != nullptr, "%s: status '%s: %s' in /diagnostics", what, hardware.c_str(), part);
  if (s == nullptr) return;
  CHECK_EQ(static_cast<int>(s->level), static_cast<int>(level), "%s: level of '%s' (message '%s')", what, part,
           s->message.c_str());
  CHECK(s->message.find(words) != std::string::npos, "%s: '%s' says '%s' (got '%s')", what, part, words,
        s->message.c_str());
  CHECK(s->hardware_id == hardware, "%s: hardware_id of '%s' is '%s'", what, part, s->hardware_id.c_str());
}

// A state whose motors are all at `celsius` with no error code, but `hot` (a joint index) at `hot_c`.
StateFrame health_state(uint32_t code, double celsius, size_t hot, double hot_c, double error_code) {
  StateFrame f = coded_state(code);
  f.temperature.fill(celsius);
  f.error_code.fill(0.0);
  f.temperature[kJoints[hot].slot] = hot_c;
  f.error_code[kJoints[hot].slot] = error_code;
  return f;
}

void deliver_health(Rig& rig, const StateFrame& f) {
  std::this_thread::sleep_for(std::chrono::milliseconds(12));  // a motor health frame is due
  rig.t.deliver_state(f);
  rig.hw->read(kTime, kPeriod);
}

#if RHI_FAKE_HI_MAJOR >= 5
// ros2_control 5.10+ publishes control_msgs/HardwareStatus on ~/hardware_status when the
// description sets status_publish_rate; the driver fills it with its health.
bool next_hardware_status(control_msgs::msg::HardwareStatus& out, const char* what) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  std::string topic;
  uint64_t before = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    rhi_fake::ros::fire_timers();  // the controller manager's executor runs the status timer
    for (const auto& t : rhi_fake::ros::topics()) {
      const std::string suffix = "/hardware_status";
      if (t.name.size() > suffix.size() && t.name.compare(t.name.size() - suffix.size(), suffix.size(), suffix) == 0) {
        if (topic.empty()) {
          topic = t.name;
          before = t.publish_count;
        } else if (t.name == topic && t.publish_count >= before + 2) {
          return rhi_fake::ros::last_published<control_msgs::msg::HardwareStatus>(topic, out);
        }
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  CHECK(false, "%s: no ~/hardware_status message within 5 s", what);
  return false;
}

void check_hardware_status() {
  using State = control_msgs::msg::GenericHardwareState;
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["status_publish_rate"] = "50";
  if (!setup(rig, info) || !activate(rig)) {
    teardown(rig);
    return;
  }
  const ControllerCommand cmd = distinct_command(3);
  cycle(rig, 1, cmd);
  control_msgs::msg::HardwareStatus status;
  if (next_hardware_status(status, "healthy robot")) {
    CHECK(status.hardware_id == info.name, "hardware_status.hardware_id is the component ('%s')",
          status.hardware_id.c_str());
    CHECK_EQ(status.hardware_device_states.size(), 1U, "one device: the robot");
    if (status.hardware_device_states.size() == 1 && status.hardware_device_states[0].hardware_status.size() == 1) {
      const State& state = status.hardware_device_states[0].hardware_status[0];
      CHECK_EQ(static_cast<int>(state.health_status), static_cast<int>(State::HEALTH_OK), "health of a fresh robot");
      CHECK(!state.state_details.empty() && state.state_details[0].key == "state_age_ms",
            "the details start with state_age_ms");
    }
  }
  rig.ifs.estop->set(1.0);
  cycle(rig, 2, cmd);
  if (next_hardware_status(status, "e-stop") && status.hardware_device_states.size() == 1 &&
      status.hardware_device_states[0].hardware_status.size() == 1) {
    const State& state = status.hardware_device_states[0].hardware_status[0];
    CHECK_EQ(static_cast<int>(state.health_status), static_cast<int>(State::HEALTH_ERROR), "health with the e-stop");
    CHECK(std::find(state.error_domain.begin(), state.error_domain.end(), State::EMERGENCY_STOP_SW) !=
              state.error_domain.end(),
          "error_domain names the software e-stop");
  }
  teardown(rig);
}
#endif

// The link status counts the valid state messages (every group's, where the state comes in parts, AgiBot's
// hands' too) and shows their rate: 5 states between two messages add 5 per part.
void check_link_message_count(Rig& rig, const std::string& hw, DiagnosticArray& a) {
#if defined(RHI_TRANSPORT_AGIBOT_TOPICS)
  constexpr uint64_t kMessagesPerState = kGroupCount;
#else
  constexpr uint64_t kMessagesPerState = 1;
#endif
  const auto count = [&hw](const DiagnosticArray& m) {
    const DiagnosticStatus* l = status_named(m, hw + ": link");
    return l == nullptr ? std::string("<no link status>") : value_of(*l, "valid state messages");
  };
  const std::string before = count(a);
  for (uint32_t k = 0; k < 5; ++k) {
    rig.t.deliver_state(coded_state(20 + k));
  }
  if (!next_diagnostics(a, "after 5 more states")) return;
  const std::string after = count(a);
  const uint64_t added = std::strtoull(after.c_str(), nullptr, 10) - std::strtoull(before.c_str(), nullptr, 10);
  CHECK_EQ(added, 5 * kMessagesPerState, "valid state messages went from %s to %s over 5 states", before.c_str(),
           after.c_str());
  const DiagnosticStatus* l = status_named(a, hw + ": link");
  const std::string rate = l != nullptr ? value_of(*l, "valid state messages [1/s]") : "<no link status>";
  char* end = nullptr;
  const double hz = std::strtod(rate.c_str(), &end);
  CHECK(end != rate.c_str() && *end == '\0' && hz >= 0.0, "the link status shows a message rate (got '%s')",
        rate.c_str());
}

// Every motor group has its status, OK on a healthy robot, and lists exactly its own joints (each joint in one
// status); the joint `hot` (at 41 C) shows its temperature.
void check_motor_groups(const DiagnosticArray& a, const std::string& hw, size_t hot) {
  const char* field = kMotorHealth[0] ? " temperature [C]" : kMotorHealth[1] ? " voltage [V]" : " error code";
  for (size_t k = 0; k < kJointCount; ++k) {
    check_status(a, hw, kJointMotorGroup[k], DiagnosticStatus::OK, "", "healthy robot");
    size_t listed = 0;
    for (size_t s = 2; s < a.status.size(); ++s) {
      listed += value_of(a.status[s], std::string(kJoints[k].name) + field) != "<missing>" ? 1U : 0U;
    }
    const DiagnosticStatus* own = status_named(a, hw + ": " + kJointMotorGroup[k]);
    CHECK(listed == 1 && own != nullptr && value_of(*own, std::string(kJoints[k].name) + field) != "<missing>",
          "%s is listed once, in '%s' (in %zu statuses)", kJoints[k].name, kJointMotorGroup[k], listed);
  }
  const DiagnosticStatus* m = status_named(a, hw + ": " + kJointMotorGroup[hot]);
  if (m != nullptr && kMotorHealth[0]) {
    const std::string shown = value_of(*m, std::string(kJoints[hot].name) + " temperature [C]");
    CHECK(shown == "41.0", "the motors status lists every joint's temperature (got '%s')", shown.c_str());
  }
}

// The description of the motor fault checks: every frame processed, no dead link meanwhile, /diagnostics
// every 20 ms.
hardware_interface::HardwareInfo motor_fault_info() {
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["state_decimation"] = "1";
  info.hardware_parameters["fault_timeout_ms"] = "60000";
  info.hardware_parameters["diagnostics_period_ms"] = "20";
  return info;
}

// One cycle of the motor fault checks: a state with its motor health (due after 10 ms), read(); while active
// also the controller's `cmd`, write() and a send. Returns what read() said.
hardware_interface::return_type motor_fault_step(Rig& rig, const StateFrame& f, const ControllerCommand& cmd) {
  std::this_thread::sleep_for(std::chrono::milliseconds(12));  // a motor health frame is due
  rig.t.deliver_state(f);
  const hardware_interface::return_type r = rig.hw->read(kTime, kPeriod);
  if (rig.active) {
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    rig.t.tick_writer();
  }
  return r;
}

// motor_error_fault_mask (0xc here): an error code with one of its bits faults an active robot like a hot
// motor: read() ERROR with one line naming the joint and the code, its group's /diagnostics status ERROR,
// damping-only after on_error. A code without those bits only shows (WARN); once the code cleared,
// configure + activate bring the robot back.
void check_motor_error_faults() {
  using hardware_interface::return_type;
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = motor_fault_info();
  info.hardware_parameters["motor_error_fault_mask"] = "12";
  if (!setup(rig, info) || !activate(rig)) {
    teardown(rig);
    return;
  }
  const auto coded = [](uint32_t code, double error_code) {
    StateFrame f = coded_state(code);
    f.temperature.fill(40.0);
    f.error_code.fill(0.0);
    f.error_code[kJoints[0].slot] = error_code;
    return f;
  };
  const ControllerCommand cmd = distinct_command(6);
  const auto step = [&rig, &cmd](const StateFrame& f) { return motor_fault_step(rig, f, cmd); };
  const std::string hw = info.name;
  const std::string joint = kJoints[0].name;
  CHECK(step(coded(801, 0.0)) == return_type::OK, "read() without motor error codes");
  rhi_fake::logs::clear();
  CHECK(step(coded(802, 3.0)) == return_type::OK, "read() with error code 0x3 (no bit of the mask 0xc)");
  DiagnosticArray a;
  if (next_diagnostics(a, "an error code outside the mask")) {
    check_status(a, hw, kJointMotorGroup[0], DiagnosticStatus::WARN, (joint + " (0x3)").c_str(), "code 0x3, mask 0xc");
  }
  CHECK(step(coded(803, 20.0)) == return_type::ERROR, "read() with %s at error code 0x14 (bit 0x4 of the mask 0xc)",
        joint.c_str());
  CHECK(rig.hw->read(kTime, kPeriod) == return_type::ERROR, "and keeps returning ERROR");
  CHECK_EQ(health(rig, kFault), 1.0, "the health GPIO's fault while a motor is in error");
  CHECK_EQ(rhi_fake::logs::count_containing("motor error", Severity::Error), 1U, "one error line for the motor");
  CHECK(rhi_fake::logs::contains(joint + " (SDK slot", Severity::Error) && rhi_fake::logs::contains("0x14", Severity::Error),
        "the error line names the joint and its code");
  if (next_diagnostics(a, "an error code in the mask")) {
    check_status(a, hw, kJointMotorGroup[0], DiagnosticStatus::ERROR, (joint + " (0x14)").c_str(), "code 0x14, mask 0xc");
  }
  enter_error(rig);
  rig.t.tick_writer();
  CommandFrame c;
  if (last_command(rig.t, c, "motor error, after on_error")) {
    check_damping_only(c, "motor error, after on_error");
  }
  if (recover(rig)) {
    CHECK(step(coded(804, 0.0)) == return_type::OK, "after the code cleared, configure + activate: read() returns OK");
  }
  teardown(rig);
}

void test_diagnostics() {
  rhi_check::Section section("diagnostics");
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["diagnostics_period_ms"] = "20";
  info.hardware_parameters["motor_temperature_warn_c"] = "60";
  info.hardware_parameters["motor_temperature_error_c"] = "80";
  // The healthy robot's statuses need its state fresh when the /diagnostics thread builds them: timeouts far
  // above any scheduling delay; the silent link sleeps past them (a lower bound on the driver's clock).
  info.hardware_parameters["state_timeout_ms"] = std::to_string(kFaultStateTimeoutMs);
  info.hardware_parameters["fault_timeout_ms"] = std::to_string(kFaultTimeoutMs);
  info.hardware_parameters["state_decimation"] = "1";
  if (!setup(rig, info)) {
    teardown(rig);
    return;
  }
  const std::string hw = info.name;
  const bool motors = kMotorHealthCount > 0;
  DiagnosticArray a;
  if (!next_diagnostics(a, "after on_init")) {
    teardown(rig);
    return;
  }
  CHECK_EQ(a.status.size(), motors ? 2U + kMotorGroupCount : 2U, "statuses: link, safety%s",
           motors ? " and one per motor group" : "");
  check_status(a, hw, "link", DiagnosticStatus::WARN, "no state", "before any state");
  check_status(a, hw, "safety", DiagnosticStatus::OK, "", "before any state");
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  const ControllerCommand cmd = distinct_command(4);
  const size_t hot = kJointCount - 1;
  const char* hot_group = kJointMotorGroup[hot];
  deliver_health(rig, health_state(1, 40.0, hot, 41.0, 0.0));
  apply_command(rig.ifs, cmd);
  rig.hw->write(kTime, kPeriod);
  rig.t.tick_writer();
  if (next_diagnostics(a, "healthy robot")) {
    check_status(a, hw, "link", DiagnosticStatus::OK, "state fresh", "healthy robot");
    check_status(a, hw, "safety", DiagnosticStatus::OK, "commands forwarded", "healthy robot");
    if (motors) {
      check_motor_groups(a, hw, hot);
    }
  }
  check_link_message_count(rig, hw, a);
  if (motors && kMotorHealth[0]) {
    deliver_health(rig, health_state(2, 40.0, hot, 65.0, 0.0));
    if (next_diagnostics(a, "a hot motor")) {
      check_status(a, hw, hot_group, DiagnosticStatus::WARN, kJoints[hot].name, "65 C (warn 60)");
    }
    deliver_health(rig, health_state(3, 40.0, hot, 85.0, 0.0));
    if (next_diagnostics(a, "a motor too hot")) {
      check_status(a, hw, hot_group, DiagnosticStatus::ERROR, "too hot", "85 C (error 80)");
    }
  }
  if (motors && kMotorHealth[2]) {
    deliver_health(rig, health_state(4, 40.0, hot, 40.0, 6.0));
    if (next_diagnostics(a, "a motor error code")) {
      check_status(a, hw, hot_group, DiagnosticStatus::WARN, (std::string(kJoints[hot].name) + " (0x6)").c_str(),
                   "error code 6");
    }
  }
  deliver_health(rig, health_state(5, 40.0, hot, 40.0, 0.0));
  rig.t.deliver_corrupt_state(distinct_state(6));
  if (next_diagnostics(a, "one invalid frame")) {
    const DiagnosticStatus* l = status_named(a, hw + ": link");
    CHECK(l != nullptr && value_of(*l, "invalid state frames") == "1", "the link status counts the invalid frame");
  }
  // The e-stop.
  rig.ifs.estop->set(1.0);
  deliver_health(rig, health_state(7, 40.0, hot, 40.0, 0.0));
  apply_command(rig.ifs, cmd);
  rig.hw->write(kTime, kPeriod);
  if (next_diagnostics(a, "e-stop")) {
    check_status(a, hw, "safety", DiagnosticStatus::ERROR, "e-stop", "e-stop pressed");
  }
  rig.ifs.estop->set(0.0);
  // The link goes stale, then dies.
  std::this_thread::sleep_for(std::chrono::milliseconds(kFaultStateTimeoutMs + 10));
  if (next_diagnostics(a, "stale state")) {
    const DiagnosticStatus* l = status_named(a, hw + ": link");
    CHECK(l != nullptr && l->level >= DiagnosticStatus::WARN, "a silent link is WARN or worse: '%s'",
          l != nullptr ? l->message.c_str() : "");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(kFaultTimeoutMs - kFaultStateTimeoutMs + 10));
  if (next_diagnostics(a, "dead link")) {
    check_status(a, hw, "link", DiagnosticStatus::ERROR, "link lost", "no state for fault_timeout_ms");
  }
  // Zero allocations in the hot paths while /diagnostics runs (its own thread may allocate).
  uint64_t allocations = 0;
  deactivate(rig);
  activate(rig);
  for (uint32_t k = 0; k < 200; ++k) {
    rig.t.prepare_state(coded_state(10 + k));
    allocations += rhi_alloc::count_in([&] { rig.t.deliver_prepared(); });
    allocations += rhi_alloc::count_in([&] { rig.hw->read(kTime, kPeriod); });
    apply_command(rig.ifs, cmd);
    allocations += rhi_alloc::count_in([&] { rig.hw->write(kTime, kPeriod); });
    allocations += rhi_alloc::count_in([&] { rig.t.tick_writer(); });
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  CHECK_EQ(allocations, 0U, "heap allocations in the state callback, read(), write() and the writer over 200 "
           "cycles while /diagnostics publishes");
  teardown(rig);
  // diagnostics_period_ms 0: no /diagnostics at all.
  fresh_process();
  Rig quiet;
  hardware_interface::HardwareInfo off = make_hardware_info();
  off.hardware_parameters["diagnostics_period_ms"] = "0";
  if (setup(quiet, off)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    CHECK_EQ(rhi_fake::ros::publish_count(kDiagnosticsTopic), 0U, "diagnostics_period_ms 0 publishes nothing");
  }
  teardown(quiet);
#if RHI_FAKE_HI_MAJOR >= 5
  check_hardware_status();
#endif
  if (kMotorHealth[2]) {
    check_motor_error_faults();
  }
}

// ================================================================ offline (EngineAI native SDK)
// A motor the robot reports offline (the native SDK's MotorDebug.offline): its group's /diagnostics
// status ERROR naming the joint, also while inactive, where read() stays OK; once active, read() ERROR
// and ERROR again, the health GPIO's fault, exactly one error line naming the joint, "offline" and
// set_hardware_component_state; on_error holds damping only; configure + activate with the motor back:
// OK, and the status OK again.
void test_motor_offline() {
  using hardware_interface::return_type;
  rhi_check::Section section("offline");
  fresh_process();
  Rig rig;
  const hardware_interface::HardwareInfo info = motor_fault_info();
  if (!setup(rig, info)) {
    teardown(rig);
    return;
  }
  const size_t k = kJointCount - 1;  // the last joint: another group than the first one's
  const std::string joint = kJoints[k].name;
  const std::string hw = info.name;
  const auto frame = [k](uint32_t code, bool offline) {
    StateFrame f = coded_state(code);
    f.temperature.fill(40.0);
    f.error_code.fill(0.0);
    f.offline.fill(false);
    f.offline[kJoints[k].slot] = offline;
    return f;
  };
  const ControllerCommand cmd = distinct_command(7);
  const auto step = [&rig, &cmd](const StateFrame& f) { return motor_fault_step(rig, f, cmd); };
  DiagnosticArray a;
  CHECK(step(frame(901, true)) == return_type::OK, "read() of an inactive component with %s offline", joint.c_str());
  if (next_diagnostics(a, "an offline motor, inactive")) {
    check_status(a, hw, kJointMotorGroup[k], DiagnosticStatus::ERROR, ("motor offline: " + joint).c_str(),
                 "a motor offline");
    const DiagnosticStatus* m = status_named(a, hw + ": " + kJointMotorGroup[k]);
    if (m != nullptr) {
      CHECK(value_of(*m, joint + " offline") == "true", "the status lists %s offline", joint.c_str());
      if (std::string(kJointMotorGroup[k - 1]) == kJointMotorGroup[k]) {
        CHECK(value_of(*m, std::string(kJoints[k - 1].name) + " offline") == "false",
              "and %s of its group online", kJoints[k - 1].name);
      }
    }
    const DiagnosticStatus* first = status_named(a, hw + ": " + kJointMotorGroup[0]);
    if (first != nullptr && std::string(kJointMotorGroup[0]) != kJointMotorGroup[k]) {
      CHECK_EQ(static_cast<int>(first->level), static_cast<int>(DiagnosticStatus::OK),
               "another group's status stays OK (%s)", first->message.c_str());
    }
  }
  if (!activate(rig)) {
    teardown(rig);
    return;
  }
  CHECK(step(frame(902, false)) == return_type::OK, "read() of the active robot with every motor online");
  rhi_fake::logs::clear();
  CHECK(step(frame(903, true)) == return_type::ERROR, "read() of the active robot with %s offline", joint.c_str());
  CHECK(rig.hw->read(kTime, kPeriod) == return_type::ERROR, "and keeps returning ERROR");
  CHECK_EQ(health(rig, kFault), 1.0, "the health GPIO's fault while a motor is offline");
  CHECK_EQ(rhi_fake::logs::count(Severity::Error), 1U, "one error line for the offline motor");
  CHECK(rhi_fake::logs::contains("motor offline", Severity::Error) &&
            rhi_fake::logs::contains(joint + " (SDK slot", Severity::Error) &&
            rhi_fake::logs::contains("set_hardware_component_state", Severity::Error),
        "the error line names the joint, says offline and how to recover");
  enter_error(rig);
  rig.t.tick_writer();
  CommandFrame c;
  if (last_command(rig.t, c, "motor offline, after on_error")) {
    check_damping_only(c, "motor offline, after on_error");
  }
  if (recover(rig)) {
    CHECK(step(frame(904, false)) == return_type::OK, "with the motor back online, configure + activate: read() OK");
    if (next_diagnostics(a, "every motor back online")) {
      const DiagnosticStatus* m = status_named(a, hw + ": " + kJointMotorGroup[k]);
      CHECK(m != nullptr && m->level == DiagnosticStatus::OK, "the group's status is OK again (%s)",
            m != nullptr ? m->message.c_str() : "missing");
    }
  }
  teardown(rig);
}

#if defined(RHI_TRANSPORT_UNITREE_DDS)
// ================================================================ CRC (reference and generated)
void test_crc_functions() {
  rhi_check::Section section("crc");
  check_crc_functions();  // the family's fake robot header (transport_unitree_*.hpp)
}
#endif

// ================================================================ threads
// Real threads: the SDK's recurrent writer thread / the driver's executor thread with real-time
// timers, a producer thread delivering state frames, the controller loop on this thread and a
// monitor thread reading what the robot received. Every frame encodes one code in every joint's
// position; a frame mixing codes within one consistency group is torn.
// In a command (`present` given) a velocity-commanded joint carries its measured position, not a
// code: it is left out (a position-target joint carries the code like a position-commanded one). A state's `q` holds the joint positions read(); a command's the motor
// positions, whose joints (joint_value: the robot's transmissions) carry the code.
bool consistent_group(const std::array<double, N>& q, const std::array<bool, N>* present, size_t group, int* code) {
  int first = -1;
  for (const Joint& j : kJoints) {
    if (j.group != group || !position_range(j).usable() || (present != nullptr && !commands_position(j))) {
      continue;
    }
    if (present != nullptr && !(*present)[j.slot]) {
      return false;
    }
    const int d = decode_position(j, present != nullptr ? joint_value(j, q, true) : q[j.slot]);
    if (first < 0) {
      first = d;
    } else if (d != first) {
      return false;
    }
  }
  if (code != nullptr) {
    *code = first;
  }
  return true;
}

// Did any joint of group g arrive in the command the robot received?
bool group_published(const std::array<bool, N>& present, size_t group) {
  for (const Joint& j : kJoints) {
    if (j.group == group && present[j.slot]) {
      return true;
    }
  }
  return false;
}

// What a command the robot received carries: `torn` groups that mix codes (a group whose first
// message is still on its way is not torn: the writer publishes the groups one after another), of
// them `torn_with_hold` where some joint carries a code below `hold_below` (a hold at the measured
// position: the state codes count up from 1), and the code every group carries (`whole`, -1 when
// the groups differ, one is missing or torn).
struct CommandCodes {
  uint32_t torn{0};
  uint32_t torn_with_hold{0};
  int whole{-1};
};

CommandCodes command_codes(const CommandFrame& c, uint32_t hold_below) {
  CommandCodes out;
  int whole = -1;  // the code every group carries; -2 once two groups differ or one is missing
  for (size_t g = 0; g < kGroupCount; ++g) {
    int code = -1;
    const bool published = group_published(c.present, g);
    const bool consistent = published && consistent_group(c.q, &c.present, g, &code);
    if (published && !consistent) {
      ++out.torn;
      bool hold = false;
      for (const Joint& j : kJoints) {
        if (j.group == g && c.present[j.slot] && position_range(j).usable() && commands_position(j)) {
          hold = hold || decode_position(j, joint_value(j, c.q, true)) < static_cast<int>(hold_below);
        }
      }
      out.torn_with_hold += hold ? 1U : 0U;
    }
    if (!consistent) {
      whole = -2;
    } else if (code >= 0 && whole != -2) {  // a group without a position joint carries no code
      whole = (whole == -1 || whole == code) ? code : -2;
    }
  }
  out.whole = whole >= 0 ? whole : -1;
  return out;
}

// The robot's side of the threaded scenarios, each on a thread of its own until `stop`: a state
// (and IMU) frame every 500 us, and every command received checked for torn groups (and, on
// Unitree, its CRC).
struct RobotThreads {
  // `hold_below_code` (0: none): the state codes cycle below it, so that a command holding the
  // measured pose carries a code below it however long the scenario runs (command_codes()).
  explicit RobotThreads(uint32_t hold_below_code = 0) : hold_below(hold_below_code) {}
  const uint32_t hold_below;
  std::atomic<bool> stop{false};
  std::atomic<uint64_t> produced{0}, commands_seen{0}, torn_commands{0}, torn_with_hold{0}, crc_errors{0};
  // The codes of the commands that arrived whole (every group published and carrying that code).
  std::array<std::atomic<bool>, kCodes> arrived_whole{};
  std::thread producer, monitor;

  void start() {
    producer = std::thread([this] {
      Transport t;
      for (uint32_t n = 0; !stop.load(); ++n) {
        const StateFrame f = coded_state(hold_below > 1 ? 1 + n % (hold_below - 1) : 1 + n);
        t.deliver_state(f);
        t.deliver_imu(f);
        produced.fetch_add(1);
        std::this_thread::sleep_for(std::chrono::microseconds(500));
      }
    });
    monitor = std::thread([this] {
      Transport t;
      CommandFrame c;
      while (!stop.load()) {
        if (t.last_command(c)) {
          commands_seen.fetch_add(1);
          const CommandCodes codes = command_codes(c, hold_below);
          torn_commands.fetch_add(codes.torn);
          torn_with_hold.fetch_add(codes.torn_with_hold);
          if (codes.whole >= 0) {
            arrived_whole[static_cast<size_t>(codes.whole)].store(true);
          }
#if defined(RHI_TRANSPORT_UNITREE_DDS)
          // One snapshot: every last_raw_command() call refreshes the buffer, so comparing the CRC
          // of one call with the checksum of another raced with the writer thread.
          const auto raw = t.last_raw_command();
          if (raw.crc() != rhi_ref::low_cmd_crc(raw)) {
            crc_errors.fetch_add(1);
          }
#endif
        }
        std::this_thread::sleep_for(std::chrono::microseconds(700));
      }
    });
  }
  void join() {
    stop.store(true);
    producer.join();
    monitor.join();
  }
};

// A rig whose transport runs real threads, with timeouts long enough for the sanitizers; false (and
// torn down) when it did not set up and activate.
bool start_threaded(Rig& rig) {
  rig.t.use_real_threads(true);
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["state_timeout_ms"] = "2000";  // sanitizers slow everything down
  info.hardware_parameters["fault_timeout_ms"] = "20000";
  if (!setup(rig, info) || !activate(rig)) {
    teardown(rig);
    rig.t.use_real_threads(false);
    return false;
  }
  return true;
}

// A controller reading every joint's position interface: true when a state is there; each group
// that mixes two frames adds one to `torn`.
bool controller_reads_state(const Rig& rig, uint64_t* torn) {
  std::array<double, N> q{};
  bool any = false;
  for (size_t k = 0; k < kJointCount; ++k) {
    q[kJoints[k].slot] = rig.ifs.pos[k]->get();
    any = any || q[kJoints[k].slot] != 0.0;
  }
  if (any) {
    for (size_t g = 0; g < kGroupCount; ++g) {
      *torn += consistent_group(q, nullptr, g, nullptr) ? 0U : 1U;
    }
  }
  return any;
}

// A controller command carrying `code` in every joint's position target (and its stiffness).
ControllerCommand coded_command(uint32_t code) {
  ControllerCommand cmd;
  for (const Joint& j : kJoints) {
    cmd.q[j.slot] = encode_position(j, code);
    cmd.dq[j.slot] = 0.0;
    cmd.kp[j.slot] = 1.0 + (code % 7);
    cmd.kd[j.slot] = 0.5;
    cmd.ff[j.slot] = 0.0;
  }
  return cmd;
}

void test_threads(int duration_ms) {
  rhi_check::Section section("threads");
  fresh_process();
  Rig rig;
  if (!start_threaded(rig)) {
    return;
  }
  RobotThreads robot;
  robot.start();
  uint64_t cycles = 0, states_seen = 0, torn_states = 0;
  uint32_t code = 500;
  // duration_ms of cycles, and on until the counts below were reached (a machine that starves the threads
  // takes longer, up to a hang's bound)
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(duration_ms);
  const auto hang = end + std::chrono::seconds(10);
  const auto enough = [&] { return robot.produced.load() > 10 && states_seen > 5 && robot.commands_seen.load() > 5; };
  while (std::chrono::steady_clock::now() < end || (!enough() && std::chrono::steady_clock::now() < hang)) {
    rig.hw->read(kTime, kPeriod);
    if (controller_reads_state(rig, &torn_states)) {
      ++states_seen;
    }
    apply_command(rig.ifs, coded_command(code));
    rig.hw->write(kTime, kPeriod);
    ++code;
    ++cycles;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  deactivate(rig);  // stops the writer thread while the producer still delivers
  robot.join();
  teardown(rig);
  rig.t.use_real_threads(false);
  std::printf("threads: %d ms, %" PRIu64 " state frames produced, %" PRIu64 " controller cycles (%" PRIu64
              " with state), %" PRIu64 " commands observed; torn states %" PRIu64 ", torn commands %" PRIu64
              ", bad CRCs %" PRIu64 "\n",
              duration_ms, robot.produced.load(), cycles, states_seen, robot.commands_seen.load(), torn_states,
              robot.torn_commands.load(), robot.crc_errors.load());
  CHECK(robot.produced.load() > 10, "the producer delivered state frames");
  CHECK(states_seen > 5, "read() saw state while threads ran");
  CHECK(robot.commands_seen.load() > 5, "the robot received commands while threads ran");
  CHECK_EQ(torn_states, 0U, "torn state frames seen by read()");
  CHECK_EQ(robot.torn_commands.load(), 0U, "torn command frames received by the robot");
  CHECK_EQ(robot.crc_errors.load(), 0U, "commands with a wrong CRC");
}

// ================================================================ async
// An asynchronous component (<ros2_control is_async="true">, Jazzy and later): ros2_control's
// AsyncFunctionHandler calls read() and then write() from a thread of its own, triggered by each
// controller manager cycle, while the controller manager's thread runs the controllers on the
// framework's handles and switches their claims, the transport's threads deliver state and send
// commands, and the handler is paused (the current cycle finished) before on_deactivate.
//
// ros2_control's handles lock one at a time, and write() only TRIES each lock (get_optional()): a
// handle a controller is writing at that moment refuses it. The driver tries the refused ones
// again and, if one still refuses, fetches nothing of that cycle rather than one joint less
// (fetch_command_values()), so a frame never mixes the command every handle holds with an older one. What per-handle locks do allow, and the driver
// cannot prevent, is a frame mixing two sets of handle values when the handles change while
// write() reads them: two controller cycles, or right after a claim switch the hold write()
// publishes into the handles (the measured position) and the controller's next command.
#if RHI_FAKE_HI_MAJOR >= 4
// The controller's commands carry the codes from here to kCodes (cycling), the state frames those
// below (RobotThreads' hold_below): a command holding the measured pose is never taken for one.
constexpr uint32_t kAsyncCodes = static_cast<uint32_t>(kCodes);
constexpr uint32_t kAsyncFirstCode = kAsyncCodes / 2;

// The controller's n-th command.
uint32_t async_code(uint32_t n) { return kAsyncFirstCode + n % (kAsyncCodes - kAsyncFirstCode); }

// write() while a controller is in the middle of writing a handle, made deterministic: the handle's
// lock is held (what a controller's set_value() holds while it writes) across write(). The command
// that reaches the robot is whole: the one before (write() fetched nothing) or the new one.
void check_write_during_a_controller_write() {
  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["state_timeout_ms"] = "2000";  // never stale, however slow the machine
  info.hardware_parameters["fault_timeout_ms"] = "20000";
  if (!setup(rig, info) || !activate(rig)) {
    teardown(rig);
    return;
  }
  size_t locked = kJointCount;  // a joint whose position command carries the code
  for (size_t k = 0; k < kJointCount && locked == kJointCount; ++k) {
    const Joint& j = kJoints[k];
    locked = rig.ifs.cpos[k] && commands_position(j) && position_range(j).usable() ? k : kJointCount;
  }
  if (locked == kJointCount) {
    teardown(rig);
    return;  // no joint carries a code (not a robot of this harness)
  }
  const auto sent = [&](const char* what) {
    rig.t.tick_writer();
    CommandFrame c;
    return last_command(rig.t, c, what) ? command_codes(c, 0) : CommandCodes{};
  };
  const auto read_state = [&](uint32_t frame) {
    rig.t.deliver_state(distinct_state(frame));
    rig.t.deliver_imu(distinct_state(frame));
    rig.hw->read(kTime, kPeriod);
  };
  constexpr uint32_t kOld = kAsyncCodes - 2, kNew = kAsyncCodes - 1;
  read_state(0);
  rig.hw->write(kTime, kPeriod);  // the safe start's hold
  apply_command(rig.ifs, coded_command(kOld));
  read_state(1);
  rig.hw->write(kTime, kPeriod);
  CHECK_EQ(sent("the command before the contended write()").whole, static_cast<int>(kOld),
           "the controller's command reached the robot whole");
  apply_command(rig.ifs, coded_command(kNew));
  read_state(2);
  {
    std::unique_lock<std::shared_mutex> writing(rig.ifs.cpos[locked]->handle()->get_mutex());
    CHECK(rig.hw->write(kTime, kPeriod) == hardware_interface::return_type::OK,
          "write() while a controller writes %s/position returns OK", kJoints[locked].name);
  }
  const CommandCodes contended = sent("the command of the contended write()");
  CHECK_EQ(contended.torn, 0U, "a write() that found %s/position locked sent no torn group (every handle held %u)",
           kJoints[locked].name, kNew);
  CHECK(contended.whole == static_cast<int>(kOld) || contended.whole == static_cast<int>(kNew),
        "a write() that found a handle locked sent one controller command whole (got %d)", contended.whole);
  read_state(3);
  rig.hw->write(kTime, kPeriod);
  CHECK_EQ(sent("the command once the handle is free").whole, static_cast<int>(kNew),
           "the next write() sends the controller's command whole");
  teardown(rig);
}

void test_async(int duration_ms) {
  rhi_check::Section section("async");
  check_write_during_a_controller_write();
  fresh_process();
  Rig rig;
  if (!start_threaded(rig)) {
    return;
  }
  RobotThreads robot(kAsyncFirstCode);
  robot.start();
  // The asynchronous handler: one read() + write() per trigger, as AsyncFunctionHandler runs them.
  std::mutex m;
  std::condition_variable cv;
  uint64_t triggered = 0, done = 0;
  bool quit = false;
  std::atomic<uint64_t> read_errors{0}, write_errors{0};
  std::thread handler([&] {
    std::unique_lock<std::mutex> lock(m);
    while (true) {
      cv.wait(lock, [&] { return quit || triggered > done; });
      if (quit) {
        return;
      }
      lock.unlock();
      const bool read_ok = rig.hw->read(kTime, kPeriod) == hardware_interface::return_type::OK;
      const bool write_ok = read_ok && rig.hw->write(kTime, kPeriod) == hardware_interface::return_type::OK;
      read_errors.fetch_add(read_ok ? 0U : 1U);
      write_errors.fetch_add(read_ok && !write_ok ? 1U : 0U);
      lock.lock();
      done = triggered;
      cv.notify_all();
    }
  });
  // pause_async_operations(): the current cycle ends before a transition.
  const auto pause = [&] {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return done == triggered; });
  };
  const std::vector<std::string> all = interface_names([](size_t, const std::string&) { return true; });
  uint64_t cycles = 0, states_seen = 0, torn_states = 0, switches = 0;
  uint32_t checked_commands = 0;
  const auto whole_commands = [&] {  // the controller's commands the robot received whole
    uint32_t n = 0;
    for (uint32_t c = kAsyncFirstCode; c < kAsyncCodes; ++c) {
      n += robot.arrived_whole[c].load() ? 1U : 0U;
    }
    return n;
  };
  // At least duration_ms, and on until every count checked below has something to count (a slow or
  // loaded machine runs longer instead of failing), within a minute.
  const auto started = std::chrono::steady_clock::now();
  const auto enough = [&] {
    return std::chrono::steady_clock::now() >= started + std::chrono::milliseconds(duration_ms) &&
           robot.produced.load() > 10 && states_seen > 5 && robot.commands_seen.load() > 5 && switches > 0 &&
           whole_commands() > 0;
  };
  // The controllers run while read()/write() may. The controller changes its command only every
  // 4th cycle, after waiting for the handler's cycle to end (the state it then reads must be one
  // frame); in between it writes the same command again, while write() may be reading the handles.
  // So the handles never hold two controller commands at once, and a frame mixing two of them is
  // the driver's own tear.
  while (!enough() && std::chrono::steady_clock::now() < started + std::chrono::minutes(1)) {
    const bool checked = cycles % 4 == 0;
    if (checked) {
      pause();
    }
    uint64_t torn = 0;
    if (controller_reads_state(rig, &torn) && checked) {
      ++states_seen;
      torn_states += torn;
    }
    if (checked) {
      ++checked_commands;
    }
    apply_command(rig.ifs, coded_command(async_code(checked_commands)));
    if (cycles % 40 == 5) {  // a controller switch while write() may run: release, then claim again
      switch_claims(rig, {}, all);
      switch_claims(rig, all, {});
      ++switches;
    }
    {  // the controller manager's next cycle triggers the component
      std::lock_guard<std::mutex> lock(m);
      ++triggered;
      cv.notify_all();
    }
    ++cycles;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  pause();
  deactivate(rig);  // stops the writer thread while the producer still delivers
  {
    std::lock_guard<std::mutex> lock(m);
    quit = true;
    cv.notify_all();
  }
  handler.join();
  robot.join();
  teardown(rig);
  rig.t.use_real_threads(false);
  const auto elapsed_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                              std::chrono::steady_clock::now() - started).count();
  const uint32_t whole_checked = whole_commands();
  const uint64_t torn_with_hold = robot.torn_with_hold.load();
  const uint64_t torn_commands = robot.torn_commands.load() - torn_with_hold;
  std::printf("async: %lld ms, %" PRIu64 " state frames produced, %" PRIu64 " controller cycles (%" PRIu64
              " with state), %" PRIu64 " claim switches, %" PRIu64 " commands observed; torn states %" PRIu64
              ", torn commands %" PRIu64 " (two controller commands), %" PRIu64
              " (a switch's hold and a command); %u of %u checked commands seen whole\n",
              static_cast<long long>(elapsed_ms), robot.produced.load(), cycles, states_seen, switches,
              robot.commands_seen.load(), torn_states, torn_commands, torn_with_hold, whole_checked,
              checked_commands);
  CHECK(robot.produced.load() > 10, "the producer delivered state frames");
  CHECK(states_seen > 5, "the controllers saw state that read() wrote from the asynchronous thread");
  CHECK(robot.commands_seen.load() > 5, "the robot received commands while read()/write() ran asynchronously");
  CHECK(switches > 0, "claims were switched while the asynchronous thread ran");
  CHECK(whole_checked > 0, "the checked commands reached the robot (the torn count below counts something)");
  CHECK_EQ(torn_states, 0U, "torn state frames seen by the controllers");
  // What the driver guarantees: every command it sends is one the handles held, whole. A checked
  // command the writer never sent (the next replaced it first) is not torn, and a group mixing a
  // switch's hold with the controller's command is the framework's (the handles changed while
  // write() read them: counted above, documented in docs/generated-package.md).
  CHECK_EQ(torn_commands, 0U, "command groups mixing two controller commands received by the robot");
  CHECK_EQ(robot.crc_errors.load(), 0U, "commands with a wrong CRC");
  CHECK_EQ(read_errors.load(), 0U, "read() errors on the asynchronous thread (the link stayed up)");
  CHECK_EQ(write_errors.load(), 0U, "write() errors on the asynchronous thread");
}
#endif

// ================================================================ transmission
// Motors that are not joints, through the whole transport: the robot's generated transmissions
// (robot_data.hpp's kTransmissions / kCoupledWeights; the identity for most robots) with a
// calibration_file on top, read at on_configure. The state interfaces show the joints the motors
// make, the safe start holds the measured pose, the motors receive what puts the joints where the
// controller commanded (velocities, efforts and gains through the ratios), and a broken
// calibration file refuses on_configure with one error line.

bool near(double got, double want, double tolerance) {
  return std::fabs(got - want) <= tolerance * (1.0 + std::fabs(want));
}

std::string write_calibration(const char* name, const std::string& text) {
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir != nullptr ? dir : "/tmp") + "/rhi_harness_" + std::to_string(getpid()) +
                           "_" + name + ".yaml";
  FILE* f = std::fopen(path.c_str(), "w");
  if (f != nullptr) {
    std::fputs(text.c_str(), f);
    std::fclose(f);
  }
  return path;
}

void test_transmission() {
  rhi_check::Section section("transmission");
  // The calibration: the first simple position joint reversed and offset, the second offset, the
  // first coupled joint offset (a coupled joint takes no direction).
  std::array<double, kJointCount> direction{};
  std::array<double, kJointCount> offset{};
  direction.fill(1.0);
  std::string text = "# harness calibration\n";
  int simple_seen = 0;
  bool coupled_seen = false;
  for (size_t k = 0; k < kJointCount; ++k) {
    const Joint& j = kJoints[k];
    if (is_coupled(j) && !coupled_seen) {
      coupled_seen = true;
      offset[k] = 0.0625;
      text += std::string("'") + j.name + "':\n  offset: 0.0625\n";
    } else if (!is_coupled(j) && j.mode == kModePosition && simple_seen == 0) {
      ++simple_seen;
      direction[k] = -1.0;
      offset[k] = 0.25;
      text += std::string(j.name) + ": {offset: 0.25, direction: -1}  # remounted\n";
    } else if (!is_coupled(j) && j.mode == kModePosition && simple_seen == 1) {
      ++simple_seen;
      offset[k] = -0.125;
      text += std::string("\"") + j.name + "\": {offset: -0.125}\n";
    }
  }
  const std::string path = write_calibration("good", text);
  // Joint value of kJoints[k] from motor values, with the calibration.
  auto joint = [&](size_t k, const std::array<double, N>& m, bool with_offset) {
    const Joint& j = kJoints[k];
    return direction[k] * joint_value(j, m, false) + (with_offset ? kTransmissions[k].offset + offset[k] : 0.0);
  };

  fresh_process();
  Rig rig;
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["calibration_file"] = path;
  bool ready = setup(rig, info);
  if (ready) {
    const CallbackReturn r = rig.hw->on_configure(kUnconfigured);
    CHECK(r == CallbackReturn::SUCCESS, "on_configure with a valid calibration file returned %d", static_cast<int>(r));
    ready = r == CallbackReturn::SUCCESS && activate(rig);
  }
  if (!ready) {
    teardown(rig);
    std::remove(path.c_str());
    return;
  }
  Transport& t = rig.t;
  SystemInterface& hw = *rig.hw;
  const StateFrame s0 = distinct_state(0);
  t.deliver_state(s0);
  hw.read(kTime, kPeriod);
  for (size_t k = 0; k < kJointCount; ++k) {
    const Joint& j = kJoints[k];
    CHECK(near(rig.ifs.pos[k]->get(), joint(k, s0.q, true), 1e-9), "%s/position %.9g: the joint its motors make (%.9g)",
          j.name, rig.ifs.pos[k]->get(), joint(k, s0.q, true));
    CHECK(near(rig.ifs.vel[k]->get(), joint(k, s0.dq, false), 1e-9), "%s/velocity %.9g, expected %.9g", j.name,
          rig.ifs.vel[k]->get(), joint(k, s0.dq, false));
    if (!is_coupled(j)) {
      const double want = effort_reported(j) ? s0.tau[j.slot] / (direction[k] * kTransmissions[k].scale) : 0.0;
      CHECK(near(rig.ifs.eff[k]->get(), want, 1e-9), "%s/effort %.9g, expected %.9g", j.name, rig.ifs.eff[k]->get(),
            want);
    }
  }
  // A coupled group's joint efforts, taken back through the matrix's transpose, are its motors'.
  for (size_t e = 0; e < kCoupledWeightCount; ++e) {
    const size_t motor = kCoupledWeights[e].motor_slot;
    double back = 0.0;
    for (size_t f = 0; f < kCoupledWeightCount; ++f) {
      if (kCoupledWeights[f].motor_slot == motor) {
        const Joint* j = joint_of_slot(kCoupledWeights[f].joint_slot);
        back += kCoupledWeights[f].weight * rig.ifs.eff[index_of(*j)]->get();
      }
    }
    CHECK(near(back, s0.tau[motor], 1e-9), "coupled motor %zu effort %.9g from its joints, measured %.9g", motor, back,
          s0.tau[motor]);
  }
  // The safe start holds the measured pose (within the joint's limits: a calibration may put a
  // joint outside them), no gains.
  CommandFrame c;
  hw.write(kTime, kPeriod);
  t.tick_writer();
  if (last_command(t, c, "transmission safe start")) {
    for (const Joint& j : kJoints) {
      const size_t k = index_of(j);
      const double measured = joint(k, s0.q, true);
      const double held = commands_position(j) ? std::min(std::max(measured, j.lower), j.upper) : measured;
      CHECK(near(joint(k, c.q, true), held, 1e-6), "safe start: the motors hold %s at %.9g, measured %.9g", j.name,
            joint(k, c.q, true), measured);
      if (c.has_gains) {
        CHECK_EQ(c.kp[j.slot], 0.0, "safe start: motor of %s stiffness", j.name);
        CHECK_EQ(c.kd[j.slot], 0.0, "safe start: motor of %s damping", j.name);
      }
    }
  }
  // A controller's command: the motors receive what puts the joints there.
  const ControllerCommand cmd = distinct_command(0);
  apply_command(rig.ifs, cmd);
  hw.write(kTime, kPeriod);
  t.tick_writer();
  if (last_command(t, c, "transmission commands")) {
    for (size_t k = 0; k < kJointCount; ++k) {
      const Joint& j = kJoints[k];
      const size_t s = j.slot;
      if (commands_position(j)) {
        CHECK(near(joint(k, c.q, true), cmd.q[s], 1e-6), "%s: the motors put the joint at %.9g, commanded %.9g", j.name,
              joint(k, c.q, true), cmd.q[s]);
      } else {
        CHECK(near(c.q[s], s0.q[s], 1e-6), "velocity-commanded %s: motor target = its measured position", j.name);
      }
      // a position-target joint: no velocity, effort or gains travel
      const bool pd = takes_pd_command(j);
      const double dq = pd ? cmd.dq[s] : 0.0;
      CHECK(near(joint(k, c.dq, false), dq, 1e-6), "%s: joint velocity %.9g from the motors, commanded %.9g", j.name,
            joint(k, c.dq, false), dq);
      if (is_coupled(j)) {
        continue;
      }
      const double scale = direction[k] * kTransmissions[k].scale;
      const double ff = pd ? cmd.ff[s] : 0.0;
      CHECK(near(c.tau[s], ff * scale, 1e-6), "%s: motor feed-forward %.9g, expected %.9g", j.name, c.tau[s],
            ff * scale);
      if (c.has_gains) {
        const double kp = j.mode == kModePosition ? cmd.kp[s] : 0.0;
        const double kd = pd ? cmd.kd[s] : 0.0;
        CHECK(near(c.kp[s], kp * scale * scale, 1e-6), "%s: motor stiffness %.9g, expected %.9g", j.name, c.kp[s],
              kp * scale * scale);
        CHECK(near(c.kd[s], kd * scale * scale, 1e-6), "%s: motor damping %.9g, expected %.9g", j.name, c.kd[s],
              kd * scale * scale);
      }
    }
    // Coupled motors: effort by the transpose, gains the diagonal of transpose * diag(k) * matrix.
    for (size_t e = 0; e < kCoupledWeightCount; ++e) {
      const size_t motor = kCoupledWeights[e].motor_slot;
      double ff = 0.0, kp = 0.0, kd = 0.0;
      for (size_t f = 0; f < kCoupledWeightCount; ++f) {
        if (kCoupledWeights[f].motor_slot == motor) {
          const double w = kCoupledWeights[f].weight;
          const size_t js = kCoupledWeights[f].joint_slot;
          ff += w * cmd.ff[js];
          kp += w * w * (joint_of_slot(js)->mode == kModePosition ? cmd.kp[js] : 0.0);
          kd += w * w * (takes_pd_command(*joint_of_slot(js)) ? cmd.kd[js] : 0.0);
        }
      }
      CHECK(near(c.tau[motor], ff, 1e-6), "coupled motor %zu feed-forward %.9g, expected %.9g", motor, c.tau[motor], ff);
      if (c.has_gains) {
        CHECK(near(c.kp[motor], kp, 1e-6), "coupled motor %zu stiffness %.9g, expected %.9g", motor, c.kp[motor], kp);
        CHECK(near(c.kd[motor], kd, 1e-6), "coupled motor %zu damping %.9g, expected %.9g", motor, c.kd[motor], kd);
      }
    }
  }
  if (kHasTransmission) {
    // The main scenario's allocation count assumes motors that are their joints: measured here.
    check_hot_path_allocations(t, hw, rig.ifs, cmd);
  }
  teardown(rig);
  std::remove(path.c_str());

  // A broken calibration file: on_configure refuses (FAILURE: fix it and configure again) with
  // exactly one error line naming the file, the line and the fix.
  struct Broken {
    const char* name;
    std::string text;
    std::string says;
  };
  const std::string first = kJoints[0].name;
  const Broken broken[] = {
      {"unknown", "rhi_no_such_joint: {offset: 0.1}\n", "line 1: 'rhi_no_such_joint' is not a joint of"},
      {"degrees", "\n'" + first + "': {offset: 90}\n", "line 2: joint '" + first + "': offset 90 is beyond one turn"},
      {"nan", "'" + first + "':\n  offset: .nan\n", "is not a finite number"},
  };
  for (const Broken& b : broken) {
    fresh_process();
    Rig bad;
    const std::string bad_path = write_calibration(b.name, b.text);
    hardware_interface::HardwareInfo bad_info = make_hardware_info();
    bad_info.hardware_parameters["calibration_file"] = bad_path;
    if (setup(bad, bad_info)) {
      rhi_fake::logs::clear();
      const CallbackReturn r = bad.hw->on_configure(kUnconfigured);
      CHECK(r == CallbackReturn::FAILURE, "%s calibration file: on_configure returned %d, not FAILURE", b.name,
            static_cast<int>(r));
      CHECK_EQ(rhi_fake::logs::count(Severity::Error), 1U, "%s calibration file: error lines", b.name);
      CHECK_EQ(rhi_fake::logs::count_containing(("calibration_file '" + bad_path + "' ").c_str(), Severity::Error), 1U,
               "%s calibration file: the error names the file", b.name);
      CHECK_EQ(rhi_fake::logs::count_containing(b.says, Severity::Error), 1U, "%s calibration file: the error says '%s'",
               b.name, b.says.c_str());
    }
    teardown(bad);
    std::remove(bad_path.c_str());
  }
}

#if defined(RHI_CUSTOM_EXPECT_UNFILLED)
// The custom transport as generated, before anyone fills its regions: it initialises and exports
// its interfaces, then refuses to activate with exactly one error line naming the first unfilled
// region and its file; no writer runs and nothing is sent.
void test_unfilled_refuses_activation() {
  rhi_check::Section section("unfilled");
  fresh_process();
  Rig rig;
  if (!setup(rig, make_hardware_info())) {
    teardown(rig);
    return;
  }
  rhi_fake::logs::clear();
  const CallbackReturn r = rig.hw->on_activate(kInactive);
  CHECK(r == CallbackReturn::ERROR, "on_activate of the unfilled custom transport returned %d, not ERROR",
        static_cast<int>(r));
  CHECK_EQ(rhi_fake::logs::count(Severity::Error), 1U, "error lines logged by the refused activation");
  CHECK_EQ(rhi_fake::logs::count(Severity::Fatal), 0U, "fatal lines logged by the refused activation");
  CHECK_EQ(rhi_fake::logs::count_containing("custom transport: region 'transport_connect' of src/", Severity::Error),
           1U, "the error line names the unfilled region and its source file");
  for (const auto& line : rhi_fake::logs::lines()) {
    if (line.severity == Severity::Error) {
      std::printf("refused: %s\n", line.text.c_str());
    }
  }
  CHECK(rhi_fake::ros::wait_spinning_executors(0, std::chrono::seconds(1)), "no executor thread runs");
  for (int i = 0; i < 5; ++i) {
    rig.t.tick_writer();
  }
  CHECK_EQ(rig.t.sent_messages(), 0U, "messages sent by the refused driver");
  CHECK(!toy_bus::Bus::instance().isOpen(), "the bus was never opened");
  rig.ifs = Interfaces{};
  rig.hw.reset();
}
#endif

}  // namespace

// --only=threads (or a comma list of interfaces,main,parameters,decimation,faults,health,diagnostics,crc,threads)
// runs just those scenarios, e.g. to repeat the threaded one many times.
#include "on_write_checks.inc"
#if defined(RHI_FAKE_ROBOT)
#include "fake_robot_checks.inc"
#endif
#if defined(RHI_HARNESS_PHYSICS)
#include "physics_checks.inc"
#endif
#if defined(RHI_ARM_SDK)
#include "arm_sdk_checks.inc"
#endif
#if defined(RHI_DEX3)
#include "hands_checks.inc"
#endif
#if defined(RHI_AIMDK_HANDS)
#include "aimdk_hands_checks.inc"
#endif
#if defined(RHI_TAKE_CONTROL)
#include "take_control_checks.inc"
#endif

static bool selected(const std::string& only, const char* name) { return only.empty() || in_list(only, name); }

// A mutation schema's switch (tests/support/cpp_mutate.py): a driver built from a schema asks it whether its
// mutant N is on; --mutant=N turns that one on, none is by default. Set before any driver thread starts.
static int g_mutant = 0;
extern "C" bool rhi_mutant_on(int mutant) noexcept;
extern "C" bool rhi_mutant_on(int mutant) noexcept { return mutant == g_mutant; }

int main(int argc, char** argv) {
  int threads_ms = 300;
  std::string only;
#if defined(RHI_HARNESS_PHYSICS)
  PhysicsSetup physics;  // the fake robot on MuJoCo: --physics-urdf, -base, -package-path, --physics, --physics-arm
#endif
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--threads-ms=", 13) == 0) {
      threads_ms = std::atoi(argv[i] + 13);
    } else if (std::strncmp(argv[i], "--only=", 7) == 0) {
      only = argv[i] + 7;
    } else if (std::strncmp(argv[i], "--mutant=", 9) == 0) {
      g_mutant = std::atoi(argv[i] + 9);
      std::printf("mutant %d switched on\n", g_mutant);
#if defined(RHI_HARNESS_PHYSICS)
    } else if (std::strncmp(argv[i], "--physics-urdf=", 15) == 0) {
      physics.urdf = argv[i] + 15;
    } else if (std::strncmp(argv[i], "--physics-base=", 15) == 0) {
      CHECK(FakePhysicsOptions::parse_base(argv[i] + 15, &physics.base), "%s names a base", argv[i]);
    } else if (std::strncmp(argv[i], "--physics=", 10) == 0) {
      physics.scenarios = argv[i] + 10;
    } else if (std::strncmp(argv[i], "--physics-arm=", 14) == 0) {
      physics.arm = argv[i] + 14;
    } else if (std::strncmp(argv[i], "--physics-package-path=", 23) == 0) {
      physics.package_path = argv[i] + 23;
#endif
    }
  }
  std::printf("robot %s: transport %s, %zu SDK slots, %zu mapped joints, SDK float type %s, plugin %s\n",
              kRobotLabel, Transport::kName, N, kJointCount, kFloatName, kPluginType);
  try {
#if defined(RHI_CUSTOM_EXPECT_UNFILLED)
    test_unfilled_refuses_activation();
    only = "none";  // the other scenarios need a filled transport
#endif
#if defined(RHI_ARM_SDK)
    if (only.empty()) {
      // The legs are state-only: the scenarios that command every joint do not apply.
      std::printf("authority upper_body (arm SDK): sections interfaces, crc, arm_sdk, fake_robot\n");
      only = "interfaces,crc,arm_sdk,fake_robot";
    }
#endif
    if (kHasTransmission && only.empty()) {
      // The main scenario, decimation and parameters compare exact motor values with joint values.
      std::printf("motors that are not joints: sections interfaces, transmission, faults, health, diagnostics, "
                  "fake_robot, threads, async\n");
      only = "interfaces,transmission,faults,health,diagnostics,fake_robot,threads,async";
    }
    if (selected(only, "interfaces")) test_interfaces();
    if (selected(only, "transmission")) test_transmission();
    if (selected(only, "main")) test_main_scenario();
    if (selected(only, "parameters")) test_parameters();
    if (selected(only, "decimation")) test_decimation_keeps_state_fresh();
    if (selected(only, "faults")) test_faults();
    if (selected(only, "health")) test_health();
    if (selected(only, "diagnostics")) test_diagnostics();
    if (kMotorOffline && selected(only, "offline")) test_motor_offline();
#if defined(RHI_TRANSPORT_UNITREE_DDS)
    if (selected(only, "crc")) test_crc_functions();
#endif
#if defined(RHI_FAKE_ROBOT)
    if (selected(only, "fake_robot")) test_fake_robot();
#endif
#if defined(RHI_HARNESS_PHYSICS)
    if (selected(only, "physics")) test_physics(physics);
#endif
#if defined(RHI_ARM_SDK)
    if (selected(only, "arm_sdk")) test_arm_sdk();
#endif
#if defined(RHI_DEX3) || defined(RHI_AIMDK_HANDS)
    if (selected(only, "hands")) test_hands();
#endif
#if defined(RHI_TAKE_CONTROL)
    if (selected(only, "take_control")) test_take_control();
#endif
    if (selected(only, "threads")) test_threads(threads_ms);
    if (selected(only, "on_write")) test_on_write();
#if RHI_FAKE_HI_MAJOR >= 4
    if (selected(only, "async")) test_async(threads_ms);
#endif
  } catch (const std::exception& e) {
    CHECK(false, "uncaught exception: %s", e.what());
  }
  rhi_fake::reset_all();
  return rhi_check::summary();
}
