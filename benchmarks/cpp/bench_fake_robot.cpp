// Benchmark of a generated fake robot (benchmarks/bench_fake_robot.py builds it with the robot's
// src/<vendor>/<robot>_fake_robot.cpp against the C++ stand-ins): its loop on a real wall timer
// for --seconds (achieved rate and jitter, FakeLoopStats), then one loop iteration (physics and
// publication of every message) timed --steps times.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "rclcpp/executors/single_threaded_executor.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rhi_fake/ros.hpp"
#include "robot_hardware_interface/common/fake_robot.hpp"

int main(int argc, char** argv) {
  double seconds = 3.0;
  int steps = 20000;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--seconds=", 10) == 0) seconds = std::atof(argv[i] + 10);
    if (std::strncmp(argv[i], "--steps=", 8) == 0) steps = std::atoi(argv[i] + 8);
  }
  rclcpp::init(0, nullptr);
  auto robot = robot_hardware_interface::make_fake_robot();
  auto node = std::make_shared<rclcpp::Node>(robot->node_name());
  robot->configure(node);

  // The loop on its wall timer, spun by an executor thread as rclcpp::spin() does.
  robot->start(robot->rate_hz());
  rhi_fake::ros::set_realtime_timers(true);
  rclcpp::executors::SingleThreadedExecutor executor;
  executor.add_node(node);
  std::thread spinner([&executor]() { executor.spin(); });
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  executor.cancel();
  spinner.join();
  rhi_fake::ros::set_realtime_timers(false);
  robot->stop();
  const robot_hardware_interface::FakeLoopStats stats = robot->stats();
  std::printf("loop %s %.0f Hz nominal: %llu steps, %.1f Hz achieved, mean |jitter| %.1f us, late max %.1f us, "
              "early max %.1f us\n",
              robot->node_name(), robot->rate_hz(), static_cast<unsigned long long>(stats.steps), stats.rate_hz(),
              stats.mean_jitter_us(), static_cast<double>(stats.max_late_ns) / 1e3,
              static_cast<double>(stats.max_early_ns) / 1e3);

  // One iteration: physics and every message of a step.
  std::vector<int64_t> ns(static_cast<size_t>(steps));
  for (auto& v : ns) {
    const auto t0 = std::chrono::steady_clock::now();
    robot->step();
    v = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
  }
  std::sort(ns.begin(), ns.end());
  const auto at = [&ns](double q) { return ns[static_cast<size_t>(q * static_cast<double>(ns.size() - 1))]; };
  std::printf("step %s: median %lld ns, p99 %lld ns, p99.9 %lld ns over %d steps\n", robot->node_name(),
              static_cast<long long>(at(0.5)), static_cast<long long>(at(0.99)), static_cast<long long>(at(0.999)),
              steps);
  robot.reset();
  rclcpp::shutdown();
  return 0;
}
