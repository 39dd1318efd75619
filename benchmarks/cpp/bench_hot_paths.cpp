// Hot-path benchmark of one generated driver (benchmarks/bench_hot_paths.py builds it per robot).
//
// Built like the driver harness (tests/cpp/harness/README.md): this file + robot_data.hpp + the
// generated driver's object, against the C++ stand-ins; the driver is created through pluginlib's
// registry and fed through the harness's fake robot (tests/cpp/harness/transport_<transport>.hpp),
// so every path below is the driver's REAL code, entered the way the SDK / rclcpp enter it:
//   state       the state callback: one complete state frame delivered by the stand-in transport
//               (unitree_dds: one LowState_ incl. CRC check; agibot_topics: one JointStateArray per
//               joint group; engineai_topics: one JointState)
//   state_dec4  the same with state_decimation = 4 (average per delivered frame)
//   writer      one command writer cycle (the SDK recurrent thread / the executor's wall timer)
//   readwrite_pos  read() + write() of one controller cycle, with a producer thread delivering
//               state, under a position-only claim (each joint's position, velocity for a
//               velocity-commanded joint: the robot's position controller, the common case)
//   readwrite_all  the same with every command interface claimed
//   readwrite_cal  readwrite_all with a calibration_file offsetting every joint: the motors are not
//                  the joints, so read() and write() convert (what a robot with transmissions costs)
// and, in the same binary, the floors over the same arrays:
//   memcpy_*    memcpy of the arrays the path moves (state: q, dq, tau + 10 IMU values; writer:
//               q, dq, tau, kp, kd; readwrite: both)
//   shmutex_*   the seed template's DataBuffer: the writer takes a std::shared_mutex unique lock
//               and copies, the reader takes a shared lock and copies (uncontended)
//   locks_pos / locks_all  with framework-owned handles (4.x+), the handles' own locks alone: a
//               set_value() on every exported state handle but the motor health ones (written
//               only when a health frame comes, every 10 ms at most) and a get_optional() on every
//               claimed command handle and the e-stop, the least read() + write() can do through
//               upstream's API (empty on Humble, whose interfaces are the driver's own doubles)
//
// Usage: bench_hot_paths time <iterations> [path...] latency of every path, or of those (ns per call)
//        bench_hot_paths count <path> <iterations>  runs only <path>; under
//               valgrind --tool=callgrind --instr-atstart=no the measured loop alone is
//               instrumented (client requests), so Ir / iterations = instructions per call.
//        bench_hot_paths latency <seconds> <robot_hz> <update_hz> <busy_threads>  the closed loop
//               (issue 37, benchmarks/bench_latency.py): from a state on the wire to the command
//               that answers it on the wire, with the driver's own threads; see closed_loop().
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <optional>
#include <thread>
#include <tuple>
#include <vector>

#include <unistd.h>
#include <valgrind/callgrind.h>

#include <hardware_interface/system_interface.hpp>
#include <lifecycle_msgs/msg/state.hpp>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/state.hpp>

#include "harness_common.hpp"
#include "rhi_fake/all.hpp"
#include "rhi_fake/plugins.hpp"

#if defined(RHI_TRANSPORT_UNITREE_DDS)
#include "transport_unitree_dds.hpp"
#elif defined(RHI_TRANSPORT_AGIBOT_TOPICS)
#include "transport_agibot_topics.hpp"
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
#include "transport_engineai_topics.hpp"
#elif defined(RHI_TRANSPORT_GENERIC_TOPICS)
#include "transport_generic_topics.hpp"
#else
#error "robot_data.hpp names no known transport"
#endif

namespace {

using namespace rhi_test;  // NOLINT
using hardware_interface::SystemInterface;
using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

const rclcpp::Time kTime(0, 0, RCL_ROS_TIME);
const rclcpp::Duration kPeriod(0, 2000000);
const rclcpp_lifecycle::State kUnconfigured(lifecycle_msgs::msg::State::PRIMARY_STATE_UNCONFIGURED, "unconfigured");
const rclcpp_lifecycle::State kInactive(lifecycle_msgs::msg::State::PRIMARY_STATE_INACTIVE, "inactive");
const rclcpp_lifecycle::State kActive(lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE, "active");

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "bench_hot_paths: %s\n", what);
  std::exit(2);
}

// ------------------------------------------------------------------ the driver, as the harness sets it up
enum class Claim { kNone, kTargets, kAll };

struct Rig {
  rhi_fake::hw::Framework fw;  // outlives the driver
  std::shared_ptr<SystemInterface> hw;
  Transport t;
  Interfaces ifs;
#if RHI_FAKE_HI_MAJOR >= 4
  // locks_*: the exported handles read() + write() must touch at the least
  std::vector<hardware_interface::StateInterface*> lock_states;
  std::vector<hardware_interface::CommandInterface*> lock_commands;
#endif
};

// A position-only claim: each joint's target (position, velocity for a velocity-commanded joint).
bool claimed(size_t k, const std::string& iface, Claim claim) {
  return claim == Claim::kAll || (claim == Claim::kTargets && iface == (kJoints[k].mode == 0 ? "position" : "velocity"));
}

void claim(Rig& rig, Claim claim_kind) {
  std::vector<std::string> names;
  for (size_t k = 0; k < kJointCount; ++k) {
    for (const std::string& iface : joint_commands(k)) {
      if (claimed(k, iface, claim_kind)) names.push_back(std::string(kJoints[k].name) + "/" + iface);
    }
  }
  if (rig.hw->prepare_command_mode_switch(names, {}) != hardware_interface::return_type::OK ||
      rig.hw->perform_command_mode_switch(names, {}) != hardware_interface::return_type::OK) {
    fail("command mode switch refused");
  }
#if RHI_FAKE_HI_MAJOR >= 4
  for (const auto& s : rig.ifs.exported.states()) {
    // Motor health changes every 10 ms at most: a driver writes those handles only then.
    const bool motor_health = std::find(kMotorHealthNames.begin(), kMotorHealthNames.end(), s.interface()) !=
                              kMotorHealthNames.end();
    if (motor_health) continue;
    // the framework's handle: const for readers, the driver writes it (set_value)
    rig.lock_states.push_back(const_cast<hardware_interface::StateInterface*>(s.handle().get()));  // NOLINT
  }
  for (const auto& c : rig.ifs.exported.commands()) {
    if (kHasHealthGpio && c.prefix() == kHealthGpio) {
      rig.lock_commands.push_back(c.handle().get());  // the e-stop: read every cycle
    }
    for (size_t k = 0; k < kJointCount; ++k) {
      if (c.prefix() == kJoints[k].name && claimed(k, c.interface(), claim_kind)) {
        rig.lock_commands.push_back(c.handle().get());
      }
    }
  }
#endif
}

// The handles' own locks alone (see the header comment).
__attribute__((noinline)) void handle_locks(Rig& rig) {
#if RHI_FAKE_HI_MAJOR >= 4
  double v = 0.25;
  for (hardware_interface::StateInterface* s : rig.lock_states) {
    std::ignore = s->set_value(v);
    v += 1.0;
  }
  for (hardware_interface::CommandInterface* c : rig.lock_commands) {
    const std::optional<double> value = c->get_optional();
    v += value.value_or(0.0);
  }
  asm volatile("" : : "r"(&v) : "memory");
#else
  static_cast<void>(rig);
#endif
}

// Created through pluginlib's registry, initialised with `info`, configured, claimed, activated.
void bring_up(Rig& rig, const hardware_interface::HardwareInfo& info, Claim claim_kind) {
  rig.hw = rhi_fake::plugins::create<SystemInterface>(kPluginType);
  if (rig.fw.init(*rig.hw, info) != CallbackReturn::SUCCESS) fail("on_init failed");
  rig.ifs.exported = rhi_fake::hw::export_interfaces(*rig.hw);
  rig.ifs.index();
  if (!rig.ifs.complete()) fail("incomplete interfaces");
  if (rig.hw->on_configure(kUnconfigured) != CallbackReturn::SUCCESS) fail("on_configure failed");
  claim(rig, claim_kind);
  if (rig.hw->on_activate(kInactive) != CallbackReturn::SUCCESS) fail("on_activate failed");
#if defined(RHI_TRANSPORT_ROS)
  if (!rhi_fake::ros::wait_spinning_executors(1, std::chrono::seconds(30))) fail("no executor");
#endif
}

// Initialised, exported, activated (monitoring on, as the issue measures), first state delivered,
// a controller command in the command interfaces and the writer warmed up.
// `calibrated`: a calibration_file gives every joint a small offset, so read() and write() convert
// between motors and joints (the path of a robot with transmissions).
void start(Rig& rig, uint32_t decimation, Claim claim_kind, bool calibrated) {
  rhi_fake::reset_all();
  rclcpp::init(0, nullptr);
  hardware_interface::HardwareInfo info = make_hardware_info();
  if (calibrated) {
    const std::string path = "/tmp/rhi_bench_calibration_" + std::to_string(getpid()) + ".yaml";
    FILE* f = std::fopen(path.c_str(), "w");
    if (f == nullptr) fail("cannot write the calibration file");
    for (const Joint& j : kJoints) std::fprintf(f, "'%s': {offset: 0.001}\n", j.name);
    std::fclose(f);
    info.hardware_parameters["calibration_file"] = path;
  }
  info.hardware_parameters["enable_monitor"] = "true";
  info.hardware_parameters["state_decimation"] = std::to_string(decimation);
  info.hardware_parameters["state_timeout_ms"] = "100000";  // valgrind is slow: never stale
  info.hardware_parameters["fault_timeout_ms"] = "200000";  // nor faulted
  bring_up(rig, info, claim_kind);
  const ControllerCommand cmd = distinct_command(1);
  for (uint32_t k = 0; k < 50; ++k) {  // warm-up: the fakes size their retained messages
    rig.t.deliver_state(coded_state(k + 1));
    rig.t.deliver_imu(coded_state(k + 1));
    rig.hw->read(kTime, kPeriod);
    apply_command(rig.ifs, cmd);
    rig.hw->write(kTime, kPeriod);
    rig.t.tick_writer();
  }
  const uint64_t sent = rig.t.sent_messages();
  rig.t.tick_writer();
  if (rig.t.sent_messages() == sent) fail("the command writer sent nothing");
  rig.t.prepare_state(coded_state(77));
}

void stop(Rig& rig) {
  rig.hw->on_deactivate(kActive);
#if defined(RHI_TRANSPORT_ROS)
  rhi_fake::ros::wait_spinning_executors(0, std::chrono::seconds(30));
#endif
  rig.ifs = Interfaces{};
  rig.hw.reset();
}

// A producer thread delivering state frames at about 2 kHz (as the harness's threaded scenario).
struct Producer {
  std::atomic<bool> quit{false};
  std::thread thread;
  void begin() {
    thread = std::thread([this] {
      Transport t;
      for (uint32_t code = 1; !quit.load(std::memory_order_relaxed); ++code) {
        const StateFrame f = coded_state(code);
        t.deliver_state(f);
        t.deliver_imu(f);
        std::this_thread::sleep_for(std::chrono::microseconds(500));
      }
    });
  }
  void end() {
    quit.store(true);
    thread.join();
  }
};

// ------------------------------------------------------------------ floors
using Sdk = SdkFloat;
constexpr size_t kStateValues = 3 * N + 10;
constexpr size_t kCommandValues = 5 * N;

struct Floors {
  std::array<Sdk, kStateValues> state_src{}, state_dst{};
  std::array<Sdk, kCommandValues> cmd_src{}, cmd_dst{};
  // DataBuffer<T> of the seed template: one slot behind a std::shared_mutex.
  std::shared_mutex state_mutex, cmd_mutex;
  std::array<Sdk, kStateValues> state_slot{};
  std::array<Sdk, kCommandValues> cmd_slot{};
};

template <typename A>
__attribute__((noinline)) void memcpy_arrays(A& dst, const A& src) {
  std::memcpy(dst.data(), src.data(), sizeof(A));
  asm volatile("" : : "r"(dst.data()) : "memory");
}

template <typename A>
__attribute__((noinline)) void shmutex_handoff(std::shared_mutex& m, A& slot, const A& in, A& out) {
  {
    std::unique_lock<std::shared_mutex> lock(m);  // writeData(): writer takes the unique lock
    slot = in;
  }
  {
    std::shared_lock<std::shared_mutex> lock(m);  // readData(): reader takes the shared lock
    out = slot;
  }
  asm volatile("" : : "r"(out.data()) : "memory");
}

// ------------------------------------------------------------------ paths
struct Path {
  const char* name;
  uint32_t decimation;  // driver set up with this state_decimation (0: no driver needed)
  bool producer;        // a producer thread delivers state while the path runs
  std::function<void(Rig&, Floors&)> call;
  Claim claim = Claim::kAll;  // what the controllers claim while the path runs
  bool calibrated = false;    // every joint offset by a calibration file: motors are not joints
};


std::vector<Path> paths() {
  std::vector<Path> all = {
      {"noop", 0, false, [](Rig&, Floors&) {}},  // the measuring loop itself (subtracted)
      {"state", 1, false, [](Rig& r, Floors&) { r.t.deliver_prepared(); }},
      {"state_dec4", 4, false, [](Rig& r, Floors&) { r.t.deliver_prepared(); }},
      {"writer", 1, false, [](Rig& r, Floors&) { r.t.tick_writer(); }},
      {"readwrite_pos", 1, true,
       [](Rig& r, Floors&) {
         r.hw->read(kTime, kPeriod);
         r.hw->write(kTime, kPeriod);
       },
       Claim::kTargets},
      {"readwrite_all", 1, true,
       [](Rig& r, Floors&) {
         r.hw->read(kTime, kPeriod);
         r.hw->write(kTime, kPeriod);
       },
       Claim::kAll},
      {"readwrite_cal", 1, true,
       [](Rig& r, Floors&) {
         r.hw->read(kTime, kPeriod);
         r.hw->write(kTime, kPeriod);
       },
       Claim::kAll, true},
      {"locks_pos", 1, false, [](Rig& r, Floors&) { handle_locks(r); }, Claim::kTargets},
      {"locks_all", 1, false, [](Rig& r, Floors&) { handle_locks(r); }, Claim::kAll},
      {"memcpy_state", 0, false, [](Rig&, Floors& f) { memcpy_arrays(f.state_dst, f.state_src); }},
      {"memcpy_writer", 0, false, [](Rig&, Floors& f) { memcpy_arrays(f.cmd_dst, f.cmd_src); }},
      {"memcpy_readwrite", 0, false,
       [](Rig&, Floors& f) {
         memcpy_arrays(f.state_dst, f.state_src);
         memcpy_arrays(f.cmd_dst, f.cmd_src);
       }},
      {"shmutex_state", 0, false,
       [](Rig&, Floors& f) { shmutex_handoff(f.state_mutex, f.state_slot, f.state_src, f.state_dst); }},
      {"shmutex_writer", 0, false,
       [](Rig&, Floors& f) { shmutex_handoff(f.cmd_mutex, f.cmd_slot, f.cmd_src, f.cmd_dst); }},
      {"shmutex_readwrite", 0, false,
       [](Rig&, Floors& f) {
         shmutex_handoff(f.state_mutex, f.state_slot, f.state_src, f.state_dst);
         shmutex_handoff(f.cmd_mutex, f.cmd_slot, f.cmd_src, f.cmd_dst);
       }},
  };
  if (Transport::kHealthMessage) {  // motor health in a message of its own (EngineAI MotorDebug): its callback
    all.push_back({"health_msg", 1, false, [](Rig& r, Floors&) { r.t.deliver_prepared_health(); }});
  }
  return all;
}

// Latency of `iterations` calls (steady_clock around each call: its own cost is reported as
// "clock" and included in every figure).
void time_path(const Path& p, Rig* rig, Floors& floors, uint32_t iterations) {
  std::vector<int64_t> ns(iterations);
  Producer producer;
  if (p.producer) producer.begin();
  for (uint32_t i = 0; i < std::min<uint32_t>(iterations / 10 + 10, 2000); ++i) p.call(*rig, floors);  // warm caches
  for (uint32_t i = 0; i < iterations; ++i) {
    const auto a = std::chrono::steady_clock::now();
    p.call(*rig, floors);
    const auto b = std::chrono::steady_clock::now();
    ns[i] = std::chrono::duration_cast<std::chrono::nanoseconds>(b - a).count();
  }
  if (p.producer) producer.end();
  std::sort(ns.begin(), ns.end());
  auto at = [&](double q) { return ns[std::min<size_t>(ns.size() - 1, static_cast<size_t>(q * ns.size()))]; };
  std::printf("time %s median %" PRId64 " p99 %" PRId64 " p99.9 %" PRId64 " max %" PRId64 "\n", p.name, at(0.5),
              at(0.99), at(0.999), ns.back());
}

void clock_overhead(uint32_t iterations) {
  std::vector<int64_t> ns(iterations);
  for (uint32_t i = 0; i < iterations; ++i) {
    const auto a = std::chrono::steady_clock::now();
    const auto b = std::chrono::steady_clock::now();
    ns[i] = std::chrono::duration_cast<std::chrono::nanoseconds>(b - a).count();
  }
  std::sort(ns.begin(), ns.end());
  std::printf("time clock median %" PRId64 " p99 %" PRId64 " p99.9 %" PRId64 " max %" PRId64 "\n", ns[ns.size() / 2],
              ns[ns.size() * 99 / 100], ns[ns.size() * 999 / 1000], ns.back());
}

// ------------------------------------------------------------------ closed-loop latency (issue 37)
// A robot thread sends a state every 1 / robot_hz s, each joint's position carrying the state's sequence
// (coded_state: kCodes positions inside the joint's range), and notes when it put it on the wire; the
// stand-in hands it to the driver's state callback on that thread, as a DDS listener thread would. The
// controller manager's loop, played as ros2_control runs it (one thread, every 1 / update_hz s: read(), a
// controller holding each joint's measured position, write()), echoes the sequence into the position
// commands; the command leaves on the driver's own writer: its SDK thread or executor timer, every
// command_writer_period_us ("timer"), or its OnWriteCommandWriter woken by write() ("on_write"). An observer of the command topic decodes the first joint's position target and
// notes, per state, the first command that carries its sequence: latency = command on the wire - state on
// the wire. The floor, same binary: a state answered directly from its callback (read(), the controller,
// write() and the writer's send on the robot thread, nothing waiting), the least the driver's code takes.
// busy_threads spin beside it all (the machine loaded).
#if defined(RHI_TRANSPORT_UNITREE_DDS)
bool observe_commands(std::function<void(const void*)> fn) {
  return rhi_fake::unitree::observe_writes(kCommandTopic, std::move(fn));
}
double commanded_position(const void* msg, const Joint& j) {
  return static_cast<const Transport::LowCmd*>(msg)->motor_cmd()[j.slot].q();
}
#elif defined(RHI_TRANSPORT_AGIBOT_TOPICS)
bool observe_commands(std::function<void(const void*)> fn) {
  return rhi_fake::ros::observe_publishes(kGroups[kJoints[0].group].command_topic, std::move(fn));
}
double commanded_position(const void* msg, const Joint& j) {
  const auto& m = *static_cast<const Transport::CommandMsg*>(msg);
  const size_t p = j.slot - kGroups[j.group].offset;
  return p < m.joints.size() ? m.joints[p].position : -1e9;
}
#elif defined(RHI_TRANSPORT_ENGINEAI_TOPICS)
bool observe_commands(std::function<void(const void*)> fn) {
  return rhi_fake::ros::observe_publishes(kCommandTopic, std::move(fn));
}
double commanded_position(const void* msg, const Joint& j) {
  const auto& m = *static_cast<const Transport::CommandMsg*>(msg);
  return j.slot < m.position.size() ? m.position[j.slot] : -1e9;
}
#else
bool observe_commands(std::function<void(const void*)>) { return false; }
double commanded_position(const void*, const Joint&) { return -1e9; }
#endif

struct LatencyProbe {
  static constexpr size_t kRing = 4096;  // states remembered (8 s at 500 Hz): far more than a command lags
  std::array<std::atomic<int64_t>, kRing> sent_ns{};
  std::atomic<uint32_t> last_sent{0};
  uint32_t answered = 0;          // the newest sequence answered (observer thread only)
  uint64_t commands = 0;          // commands observed while recording (observer thread only)
  uint64_t undecoded = 0;         // of those, carrying no sequence of a state sent
  std::vector<int64_t> samples;   // [ns], reserved up front (observer thread only)
  std::atomic<bool> recording{false};

  static int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  void sent(uint32_t seq) {
    sent_ns[seq % kRing].store(now_ns(), std::memory_order_relaxed);
    last_sent.store(seq, std::memory_order_release);
  }
  // A command on the wire: the newest state sent whose code it carries, if no earlier command answered it.
  void command(const void* msg) {
    const int64_t t = now_ns();
    const int code = decode_position(kJoints[0], commanded_position(msg, kJoints[0]));
    const uint32_t last = last_sent.load(std::memory_order_acquire);
    const bool counting = recording.load(std::memory_order_relaxed);
    commands += counting ? 1U : 0U;
    const uint32_t back = (last % kCodes + kCodes - static_cast<uint32_t>(code)) % kCodes;
    if (code < 0 || code >= kCodes || last == 0 || back >= last) {
      undecoded += counting ? 1U : 0U;
      return;
    }
    const uint32_t seq = last - back;
    if (seq <= answered) return;  // the writer sending the same command again, or an older state's
    answered = seq;
    if (counting && samples.size() < samples.capacity()) {
      samples.push_back(t - sent_ns[seq % kRing].load(std::memory_order_relaxed));
    }
  }
};

void report_latency(const char* mode, LatencyProbe& probe, uint64_t states) {
  std::vector<int64_t>& ns = probe.samples;
  std::printf("latency %s samples %zu states %" PRIu64 " commands %" PRIu64 " undecoded %" PRIu64, mode, ns.size(),
              states, probe.commands, probe.undecoded);
  if (!ns.empty()) {
    std::sort(ns.begin(), ns.end());
    auto at = [&](double q) { return ns[std::min<size_t>(ns.size() - 1, static_cast<size_t>(q * ns.size()))]; };
    std::printf(" median_us %.1f p99_us %.1f p99.9_us %.1f max_us %.1f", at(0.5) / 1e3, at(0.99) / 1e3,
                at(0.999) / 1e3, ns.back() / 1e3);
  }
  std::printf("\n");
}

// The driver set up as ros2_control runs it with a forward position controller: a position claim, the
// transport's real threads (SDK threads / wall timers) when `threaded`; `writer_mode`: the hardware
// parameter command_writer_mode (timer, on_write).
void start_closed_loop(Rig& rig, bool threaded, const char* writer_mode = "timer") {
  rhi_fake::reset_all();
  rclcpp::init(0, nullptr);
  rig.t.use_real_threads(threaded);
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["enable_monitor"] = "true";
  info.hardware_parameters["command_writer_mode"] = writer_mode;
  bring_up(rig, info, Claim::kTargets);
}

// The controller: every claimed position target at the joint's measured position.
void hold_measured(Rig& rig) {
  for (size_t k = 0; k < kJointCount; ++k) {
    if (rig.ifs.cpos[k] != nullptr && rig.ifs.pos[k] != nullptr) rig.ifs.cpos[k]->set(rig.ifs.pos[k]->get());
  }
}

void stop_closed_loop(Rig& rig, LatencyProbe& probe, const char* mode, uint64_t states) {
  observe_commands({});
  stop(rig);
  rig.t.use_real_threads(false);
  report_latency(mode, probe, states);
}

void closed_loop(double seconds, double robot_hz, double update_hz, int busy_threads) {
  std::atomic<bool> quit{false};
  std::vector<std::thread> busy;
  for (int i = 0; i < busy_threads; ++i) {
    busy.emplace_back([&quit] {
      volatile double x = 1.0;
      while (!quit.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
    });
  }
  // The robot's clock runs 0.1 % fast against the controller's: two free-running clocks, whose phase offset
  // sweeps through a whole period every 1000 periods (2 s at 500 Hz), so the run sees every offset.
  const auto robot_period = std::chrono::nanoseconds(static_cast<int64_t>(1e9 / (robot_hz * 1.001)));
  const auto update_period = std::chrono::nanoseconds(static_cast<int64_t>(1e9 / update_hz));
  const auto samples_wanted = static_cast<size_t>((seconds + 1.0) * robot_hz * 1.01) + 16;  // every state sent
  // The controller manager's loop on its own clock, the driver's writer on the writer's (timer) or woken by
  // write() (on_write).
  for (const char* writer_mode : {"timer", "on_write"}) {
    Rig rig;
    start_closed_loop(rig, true, writer_mode);
    LatencyProbe probe;
    probe.samples.reserve(samples_wanted);
    if (!observe_commands([&probe](const void* msg) { probe.command(msg); })) fail("no command topic to observe");
    std::atomic<bool> stop{false};
    std::atomic<uint64_t> states{0};
    std::thread robot([&] {
      Transport t;
      auto next = std::chrono::steady_clock::now();
      for (uint32_t seq = 1; !stop.load(std::memory_order_relaxed); ++seq) {
        const StateFrame f = coded_state(seq);
        t.prepare_state(f);  // the frame (and its CRC) made before it goes on the wire
        probe.sent(seq);
        t.deliver_prepared();
        t.deliver_imu(f);
        states.fetch_add(1, std::memory_order_relaxed);
        next += robot_period;
        std::this_thread::sleep_until(next);
      }
    });
    const auto begin = std::chrono::steady_clock::now();
    auto next = begin;
    while (next - begin < std::chrono::duration<double>(seconds + 0.3)) {
      if (!probe.recording.load() && next - begin > std::chrono::milliseconds(300)) {
        probe.recording.store(true);  // after the safe start's first state and the writer's first cycles
        states.store(0);
      }
      rig.hw->read(kTime, kPeriod);
      hold_measured(rig);
      rig.hw->write(kTime, kPeriod);
      next += update_period;
      std::this_thread::sleep_until(next);
    }
    probe.recording.store(false);
    stop.store(true);
    robot.join();
    stop_closed_loop(rig, probe, writer_mode, states.load());
  }
  {  // the floor: each state answered from its callback on the robot's thread, nothing waiting
    Rig rig;
    start_closed_loop(rig, false);
    LatencyProbe probe;
    probe.samples.reserve(samples_wanted);
    if (!observe_commands([&probe](const void* msg) { probe.command(msg); })) fail("no command topic to observe");
    Transport t;
    uint64_t states = 0;
    auto next = std::chrono::steady_clock::now();
    const auto end = next + std::chrono::duration<double>(seconds + 0.3);
    for (uint32_t seq = 1; next < end; ++seq) {
      probe.recording.store(seq > 50);
      const StateFrame f = coded_state(seq);
      t.prepare_state(f);  // the frame (and its CRC) made before it goes on the wire
      probe.sent(seq);
      t.deliver_prepared();
      t.deliver_imu(f);
      rig.hw->read(kTime, kPeriod);
      hold_measured(rig);
      rig.hw->write(kTime, kPeriod);
      rig.t.tick_writer();
      states += seq > 50 ? 1U : 0U;
      next += robot_period;
      std::this_thread::sleep_until(next);
    }
    stop_closed_loop(rig, probe, "floor", states);
  }
  quit.store(true);
  for (std::thread& b : busy) b.join();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) fail("usage: bench_hot_paths time <iterations> [<path>...] | count <path> <iterations>");
  const std::string mode = argv[1];
  Floors floors;
  for (size_t i = 0; i < kStateValues; ++i) floors.state_src[i] = static_cast<Sdk>(0.25 * i);
  for (size_t i = 0; i < kCommandValues; ++i) floors.cmd_src[i] = static_cast<Sdk>(0.5 * i);
  std::printf("robot %s motors %zu joints %zu groups %zu sdk_float %s\n", kRobotLabel, N, kJointCount, kGroupCount,
              sizeof(Sdk) == sizeof(float) ? "float" : "double");
  if (mode == "time") {
    const auto iterations = static_cast<uint32_t>(std::strtoul(argv[2], nullptr, 10));
    const std::vector<std::string> only(argv + 3, argv + argc);  // these paths only (none: all)
    clock_overhead(iterations);
    for (const Path& p : paths()) {
      if (!only.empty() && std::find(only.begin(), only.end(), p.name) == only.end()) continue;
      if (p.decimation == 0) {
        time_path(p, nullptr, floors, iterations);
        continue;
      }
      Rig rig;
      start(rig, p.decimation, p.claim, p.calibrated);
      time_path(p, &rig, floors, iterations);
      stop(rig);
    }
    return 0;
  }
  if (mode == "latency" && argc >= 6) {
    closed_loop(std::strtod(argv[2], nullptr), std::strtod(argv[3], nullptr), std::strtod(argv[4], nullptr),
                std::atoi(argv[5]));
    return 0;
  }
  if (mode == "count" && argc >= 4) {
    const std::string name = argv[2];
    const auto iterations = static_cast<uint32_t>(std::strtoul(argv[3], nullptr, 10));
    for (const Path& p : paths()) {
      if (name != p.name) continue;
      Rig rig;
      if (p.decimation != 0) start(rig, p.decimation, p.claim, p.calibrated);
      Producer producer;
      if (p.producer) producer.begin();
      for (uint32_t i = 0; i < 100; ++i) p.call(rig, floors);  // warm-up, not counted
      CALLGRIND_START_INSTRUMENTATION;
      CALLGRIND_ZERO_STATS;
      for (uint32_t i = 0; i < iterations; ++i) p.call(rig, floors);
      CALLGRIND_DUMP_STATS_AT(p.name);
      CALLGRIND_STOP_INSTRUMENTATION;
      if (p.producer) producer.end();
      if (p.decimation != 0) stop(rig);
      std::printf("count %s %u\n", p.name, iterations);
      return 0;
    }
    fail("unknown path");
  }
  fail("unknown mode");
}
