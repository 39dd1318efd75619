// rhi-gen test stand-in (not the real ROS 2 code). Behaves like the single-threaded fake: the fake
// runs each node's callbacks mutually exclusively (default callback group), so there is no
// observable difference for a driver with one node.
#ifndef RCLCPP__EXECUTORS__MULTI_THREADED_EXECUTOR_HPP_
#define RCLCPP__EXECUTORS__MULTI_THREADED_EXECUTOR_HPP_

#include <chrono>
#include <cstddef>
#include <thread>

#include "rclcpp/executor.hpp"
#include "rclcpp/macros.hpp"

namespace rclcpp
{
namespace executors
{

class MultiThreadedExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(MultiThreadedExecutor)

  explicit MultiThreadedExecutor(
    const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions(),
    size_t number_of_threads = 0,
    bool yield_before_execute = false,
    std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1))
  : rclcpp::Executor(options),
    number_of_threads_(number_of_threads ? number_of_threads :
      (std::thread::hardware_concurrency() ? std::thread::hardware_concurrency() : 1))
  {
    (void)yield_before_execute;
    (void)timeout;
  }

  virtual ~MultiThreadedExecutor() = default;

  /// Blocks until cancel() or rclcpp::shutdown().
  void spin() override {rhi_spin_blocking("spin()");}

  size_t get_number_of_threads() {return number_of_threads_;}

private:
  MultiThreadedExecutor(const MultiThreadedExecutor &) = delete;
  MultiThreadedExecutor & operator=(const MultiThreadedExecutor &) = delete;
  size_t number_of_threads_;
};

}  // namespace executors
}  // namespace rclcpp

#endif  // RCLCPP__EXECUTORS__MULTI_THREADED_EXECUTOR_HPP_
