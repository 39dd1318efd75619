// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::init / shutdown / ok (Humble
// signatures). init() twice without shutdown() throws rclcpp::ContextAlreadyInitialized, as in
// rclcpp. shutdown() makes ok() false and returns every spinning executor from spin().
#ifndef RCLCPP__UTILITIES_HPP_
#define RCLCPP__UTILITIES_HPP_

#include <mutex>
#include <string>

#include "rclcpp/context.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{

inline void init(
  int argc, char const * const argv[],
  const InitOptions & init_options = InitOptions(),
  SignalHandlerOptions signal_handler_options = SignalHandlerOptions::All)
{
  (void)argc;
  (void)argv;
  (void)init_options;
  (void)signal_handler_options;
  auto & reg = ::rhi_fake::detail::ros_registry();
  std::lock_guard<std::mutex> lock(reg.mutex);
  if (reg.initialized.load()) {
    throw ContextAlreadyInitialized();
  }
  reg.initialized.store(true);
  reg.init_count++;
}

inline bool ok(Context::SharedPtr context = nullptr)
{
  (void)context;
  return ::rhi_fake::detail::ros_registry().initialized.load();
}

inline bool shutdown(
  Context::SharedPtr context = nullptr,
  const std::string & reason = "user called rclcpp::shutdown()")
{
  (void)context;
  (void)reason;
  auto & reg = ::rhi_fake::detail::ros_registry();
  {
    std::lock_guard<std::mutex> lock(reg.mutex);
    if (!reg.initialized.exchange(false)) {
      return false;
    }
  }
  ::rhi_fake::detail::wake_all_executors();
  return true;
}

}  // namespace rclcpp

#endif  // RCLCPP__UTILITIES_HPP_
