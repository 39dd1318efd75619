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
//   readwrite   read() + write() of one controller cycle, with a producer thread delivering state
// and, in the same binary, the floors over the same arrays:
//   memcpy_*    memcpy of the arrays the path moves (state: q, dq, tau + 10 IMU values; writer:
//               q, dq, tau, kp, kd; readwrite: both)
//   shmutex_*   the seed template's DataBuffer: the writer takes a std::shared_mutex unique lock
//               and copies, the reader takes a shared lock and copies (uncontended)
//
// Usage: bench_hot_paths time <iterations>          latency of every path (ns per call)
//        bench_hot_paths count <path> <iterations>  runs only <path>; under
//               valgrind --tool=callgrind --instr-atstart=no the measured loop alone is
//               instrumented (client requests), so Ir / iterations = instructions per call.
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
#include <thread>
#include <vector>

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
const rclcpp_lifecycle::State kInactive(lifecycle_msgs::msg::State::PRIMARY_STATE_INACTIVE, "inactive");
const rclcpp_lifecycle::State kActive(lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE, "active");

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "bench_hot_paths: %s\n", what);
  std::exit(2);
}

// ------------------------------------------------------------------ the driver, as the harness sets it up
struct Rig {
  rhi_fake::hw::Framework fw;  // outlives the driver
  std::shared_ptr<SystemInterface> hw;
  Transport t;
  Interfaces ifs;
};

void claim_everything(Rig& rig) {
  std::vector<std::string> all;
  for (size_t k = 0; k < kJointCount; ++k) {
    for (const std::string& iface : joint_commands(k)) {
      all.push_back(std::string(kJoints[k].name) + "/" + iface);
    }
  }
  if (rig.hw->prepare_command_mode_switch(all, {}) != hardware_interface::return_type::OK ||
      rig.hw->perform_command_mode_switch(all, {}) != hardware_interface::return_type::OK) {
    fail("command mode switch refused");
  }
}

// Initialised, exported, activated (monitoring on, as the issue measures), first state delivered,
// a controller command in the command interfaces and the writer warmed up.
void start(Rig& rig, uint32_t decimation) {
  rhi_fake::reset_all();
  rclcpp::init(0, nullptr);
  hardware_interface::HardwareInfo info = make_hardware_info();
  info.hardware_parameters["enable_monitor"] = "true";
  info.hardware_parameters["state_decimation"] = std::to_string(decimation);
  info.hardware_parameters["state_timeout_ms"] = "100000";  // valgrind is slow: never stale
  rig.hw = rhi_fake::plugins::create<SystemInterface>(kPluginType);
  if (rig.fw.init(*rig.hw, info) != CallbackReturn::SUCCESS) fail("on_init failed");
  rig.ifs.exported = rhi_fake::hw::export_interfaces(*rig.hw);
  rig.ifs.index();
  if (!rig.ifs.complete()) fail("incomplete interfaces");
  claim_everything(rig);
  if (rig.hw->on_activate(kInactive) != CallbackReturn::SUCCESS) fail("on_activate failed");
#if defined(RHI_TRANSPORT_ROS)
  if (!rhi_fake::ros::wait_spinning_executors(1, std::chrono::seconds(30))) fail("no executor");
#endif
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
};

std::vector<Path> paths() {
  return {
      {"noop", 0, false, [](Rig&, Floors&) {}},  // the measuring loop itself (subtracted)
      {"state", 1, false, [](Rig& r, Floors&) { r.t.deliver_prepared(); }},
      {"state_dec4", 4, false, [](Rig& r, Floors&) { r.t.deliver_prepared(); }},
      {"writer", 1, false, [](Rig& r, Floors&) { r.t.tick_writer(); }},
      {"readwrite", 1, true,
       [](Rig& r, Floors&) {
         r.hw->read(kTime, kPeriod);
         r.hw->write(kTime, kPeriod);
       }},
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) fail("usage: bench_hot_paths time <iterations> | count <path> <iterations>");
  const std::string mode = argv[1];
  Floors floors;
  for (size_t i = 0; i < kStateValues; ++i) floors.state_src[i] = static_cast<Sdk>(0.25 * i);
  for (size_t i = 0; i < kCommandValues; ++i) floors.cmd_src[i] = static_cast<Sdk>(0.5 * i);
  std::printf("robot %s motors %zu joints %zu groups %zu sdk_float %s\n", kRobotLabel, N, kJointCount, kGroupCount,
              sizeof(Sdk) == sizeof(float) ? "float" : "double");
  if (mode == "time") {
    const auto iterations = static_cast<uint32_t>(std::strtoul(argv[2], nullptr, 10));
    clock_overhead(iterations);
    for (const Path& p : paths()) {
      if (p.decimation == 0) {
        time_path(p, nullptr, floors, iterations);
        continue;
      }
      Rig rig;
      start(rig, p.decimation);
      time_path(p, &rig, floors, iterations);
      stop(rig);
    }
    return 0;
  }
  if (mode == "count" && argc >= 4) {
    const std::string name = argv[2];
    const auto iterations = static_cast<uint32_t>(std::strtoul(argv[3], nullptr, 10));
    for (const Path& p : paths()) {
      if (name != p.name) continue;
      Rig rig;
      if (p.decimation != 0) start(rig, p.decimation);
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
