// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__ROS_TOPICS_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__ROS_TOPICS_HPP_

// What the ROS 2 topic transports (agibot_topics, engineai_topics, generic_topics) share: their
// QoS, the executor thread that spins the driver's node while it is active, and IMU parsing.

#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <thread>
#include <utility>

#include <rclcpp/executors/single_threaded_executor.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/qos.hpp>
#include <rclcpp/timer.hpp>

#include "robot_hardware_interface/common/command_writer.hpp"
#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/monitor.hpp"

namespace robot_hardware_interface
{

// transport_options.qos of the vendor YAML.
struct TopicQos
{
  bool reliable;         // false: best effort
  bool transient_local;  // false: volatile
  size_t depth;          // keep last
};

inline rclcpp::QoS make_qos(const TopicQos & options)
{
  rclcpp::QoS qos(rclcpp::KeepLast(options.depth));
  if (options.reliable) {
    qos.reliable();
  } else {
    qos.best_effort();
  }
  if (options.transient_local) {
    qos.transient_local();
  } else {
    qos.durability_volatile();
  }
  return qos;
}

// Spins the driver's node on its own thread from start() (on_activate) to stop()
// (on_deactivate), with the command writer as a wall timer on it (topic callbacks and the writer
// never run concurrently), or in the on_write mode on the OnWriteCommandWriter's thread.
class TopicExecutor
{
public:
  TopicExecutor() = default;
  TopicExecutor(const TopicExecutor &) = delete;
  TopicExecutor & operator=(const TopicExecutor &) = delete;
  ~TopicExecutor() {stop();}

  void configure(const rclcpp::Node::SharedPtr & node)
  {
    node_ = node;
    executor_ = std::make_shared<rclcpp::executors::SingleThreadedExecutor>();
    executor_->add_node(node_);
  }

  // Starts spinning, with `writer` called every `period_us` on the executor (a wall timer), or,
  // given `on_write` (command_writer_mode on_write), on that writer's thread as write() wakes it
  // (then topic callbacks and the writer may run at the same time). May throw (then call stop()).
  template<typename Writer>
  void start(
    uint64_t period_us, const rclcpp::Logger & logger, OnWriteCommandWriter * on_write,
    Writer && writer)
  {
    if (on_write == nullptr) {
      command_timer_ = node_->create_wall_timer(
        std::chrono::microseconds(period_us), std::forward<Writer>(writer));
    }
    stopped_.store(false, std::memory_order_release);
    thread_ = std::thread(
      [this, logger]() {
        try {
          executor_->spin();
        } catch (const std::exception & e) {
          RCLCPP_ERROR(logger, "executor thread stopped: %s", e.what());
        }
        stopped_.store(true, std::memory_order_release);
      });
    if (on_write != nullptr) {
      on_write_ = on_write;
      on_write->start(period_us, std::forward<Writer>(writer));
    }
  }

  // While the executor does not spin (before start(), after stop()): spins it on the caller's
  // thread until `future` is ready or `timeout` has passed; true when it is ready.
  template<typename Future>
  bool spin_until(const Future & future, std::chrono::nanoseconds timeout)
  {
    return executor_->spin_until_future_complete(future, timeout) ==
           rclcpp::FutureReturnCode::SUCCESS;
  }

  void stop()
  {
    if (on_write_ != nullptr) {
      on_write_->stop();
      on_write_ = nullptr;
    }
    if (thread_.joinable()) {
      // A cancel() issued before spin() has started is lost (rclcpp behaviour) and join() would
      // then wait forever: repeat it until the thread has really left spin().
      while (!stopped_.load(std::memory_order_acquire)) {
        executor_->cancel();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      thread_.join();
    }
    if (command_timer_) {
      command_timer_->cancel();
      command_timer_.reset();
    }
  }

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::executors::SingleThreadedExecutor::SharedPtr executor_;
  std::thread thread_;
  std::atomic<bool> stopped_{true};  // set by the executor thread when it leaves spin()
  rclcpp::TimerBase::SharedPtr command_timer_;  // the timer mode's writer
  OnWriteCommandWriter * on_write_{nullptr};  // the on_write mode's writer, while started
};

// An IMU sample from ROS message fields (quaternion x, y, z, w; vectors x, y, z) into the core,
// which stores it w, x, y, z. A sample with a non-finite value is dropped and counted.
template<size_t N, typename T, typename Quaternion, typename Vector3>
void publish_ros_imu(
  DriverCore<N, T> & core, const Quaternion & q, const Vector3 & w, const Vector3 & a)
{
  if (!all_finite(q.x, q.y, q.z, q.w) || !all_finite(w.x, w.y, w.z) ||
    !all_finite(a.x, a.y, a.z))
  {
    const uint64_t dropped = core.reject_imu();
    RCLCPP_WARN_THROTTLE(
      core.logger(), core.throttle_clock(), MonitorThresholds::WARN_THROTTLE_MS,
      "dropped IMU sample with non-finite values (%" PRIu64 " dropped so far)", dropped);
    return;
  }
  auto & imu = core.imu_frame();
  imu.quat = {static_cast<T>(q.w), static_cast<T>(q.x), static_cast<T>(q.y), static_cast<T>(q.z)};
  imu.omega = {static_cast<T>(w.x), static_cast<T>(w.y), static_cast<T>(w.z)};
  imu.acc = {static_cast<T>(a.x), static_cast<T>(a.y), static_cast<T>(a.z)};
  core.publish_imu();
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__ROS_TOPICS_HPP_
