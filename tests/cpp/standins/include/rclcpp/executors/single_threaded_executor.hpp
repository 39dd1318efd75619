// rhi-gen test stand-in (not the real ROS 2 code). See rclcpp/executor.hpp for the fake semantics.
#ifndef RCLCPP__EXECUTORS__SINGLE_THREADED_EXECUTOR_HPP_
#define RCLCPP__EXECUTORS__SINGLE_THREADED_EXECUTOR_HPP_

#include "rclcpp/executor.hpp"
#include "rclcpp/macros.hpp"

namespace rclcpp
{
namespace executors
{

class SingleThreadedExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SingleThreadedExecutor)

  explicit SingleThreadedExecutor(const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions())
  : rclcpp::Executor(options) {}

  virtual ~SingleThreadedExecutor() = default;

  /// Blocks until cancel() or rclcpp::shutdown().
  void spin() override {rhi_spin_blocking("spin()");}

private:
  SingleThreadedExecutor(const SingleThreadedExecutor &) = delete;
  SingleThreadedExecutor & operator=(const SingleThreadedExecutor &) = delete;
};

}  // namespace executors
}  // namespace rclcpp

#endif  // RCLCPP__EXECUTORS__SINGLE_THREADED_EXECUTOR_HPP_
