// rhi-gen test stand-in (not the real ROS 2 code): a minimal rclcpp::Context (only the default,
// process-wide context exists in the fake).
#ifndef RCLCPP__CONTEXT_HPP_
#define RCLCPP__CONTEXT_HPP_

#include <memory>
#include <stdexcept>
#include <string>

#include "rclcpp/macros.hpp"

namespace rclcpp
{

class ContextAlreadyInitialized : public std::runtime_error
{
public:
  ContextAlreadyInitialized()
  : std::runtime_error("context is already initialized") {}
};

class Context
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Context)
  Context() = default;
  virtual ~Context() = default;
};

class InitOptions
{
public:
  InitOptions() = default;
  bool shutdown_on_signal = true;
  bool auto_initialize_logging() const {return true;}
  InitOptions & auto_initialize_logging(bool) {return *this;}
};

enum class SignalHandlerOptions
{
  All,
  SigInt,
  SigTerm,
  None,
};

}  // namespace rclcpp

#endif  // RCLCPP__CONTEXT_HPP_
