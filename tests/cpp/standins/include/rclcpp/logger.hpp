// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Logger as in ROS 2 Humble.
// Like the real class it has no public default constructor: obtain one with
// rclcpp::get_logger(name) or node->get_logger(). Copying a Logger never allocates.
#ifndef RCLCPP__LOGGER_HPP_
#define RCLCPP__LOGGER_HPP_

#include <memory>
#include <string>

#include "rclcpp/visibility_control.hpp"

namespace rclcpp
{

class Logger;

/// Return a named logger (allocates its name once).
RCLCPP_PUBLIC
inline Logger get_logger(const std::string & name);

class Logger
{
public:
  enum class Level
  {
    Unset = 0,
    Debug = 10,
    Info = 20,
    Warn = 30,
    Error = 40,
    Fatal = 50,
  };

private:
  friend Logger rclcpp::get_logger(const std::string & name);

  Logger()
  : name_(nullptr) {}

  explicit Logger(const std::string & name)
  : name_(std::make_shared<const std::string>(name)) {}

  std::shared_ptr<const std::string> name_;

public:
  Logger(const Logger &) = default;
  Logger(Logger &&) = default;
  Logger & operator=(const Logger &) = default;
  Logger & operator=(Logger &&) = default;

  /// Name of the logger, or nullptr for a dummy logger.
  const char * get_name() const
  {
    if (!name_) {
      return nullptr;
    }
    return name_->c_str();
  }

  /// Child logger "<name>.<suffix>".
  Logger get_child(const std::string & suffix)
  {
    if (!name_) {
      return Logger();
    }
    return Logger(*name_ + "." + suffix);
  }

  /// Accepted and ignored by the stand-in (every line is captured whatever the level).
  void set_level(Level level) {(void)level;}
};

inline Logger get_logger(const std::string & name)
{
  return Logger(name);
}

}  // namespace rclcpp

#endif  // RCLCPP__LOGGER_HPP_
