// rhi-gen test stand-in (not the real ROS 2 code): the rclcpp exception types the stand-ins throw.
#ifndef RCLCPP__EXCEPTIONS_HPP_
#define RCLCPP__EXCEPTIONS_HPP_

#include <stdexcept>
#include <string>

namespace rclcpp
{
namespace exceptions
{

class RCLError : public std::runtime_error
{
public:
  explicit RCLError(const std::string & message)
  : std::runtime_error(message) {}
};

class NameValidationError : public std::invalid_argument
{
public:
  NameValidationError(
    const char * name_type_, const char * name_, const char * error_msg_, size_t invalid_index_)
  : std::invalid_argument(format_error(name_type_, name_, error_msg_, invalid_index_)),
    name_type(name_type_), name(name_), error_msg(error_msg_), invalid_index(invalid_index_)
  {}

  static std::string format_error(
    const char * type_, const char * value_, const char * why_, size_t at_)
  {
    std::string msg;
    msg += "Invalid "; msg += type_; msg += ": "; msg += why_; msg += ":\n  '";
    msg += value_; msg += "'\n   "; msg += std::string(at_, ' '); msg += "^\n";
    return msg;
  }

  const std::string name_type;
  const std::string name;
  const std::string error_msg;
  const size_t invalid_index;
};

class InvalidNodeNameError : public NameValidationError
{
public:
  InvalidNodeNameError(const char * node_name, const char * error_msg_, size_t invalid_index_)
  : NameValidationError("node name", node_name, error_msg_, invalid_index_) {}
};

class InvalidNamespaceError : public NameValidationError
{
public:
  InvalidNamespaceError(const char * namespace_, const char * error_msg_, size_t invalid_index_)
  : NameValidationError("namespace", namespace_, error_msg_, invalid_index_) {}
};

class InvalidTopicNameError : public NameValidationError
{
public:
  InvalidTopicNameError(const char * topic_name, const char * error_msg_, size_t invalid_index_)
  : NameValidationError("topic name", topic_name, error_msg_, invalid_index_) {}
};

class InvalidServiceNameError : public NameValidationError
{
public:
  InvalidServiceNameError(const char * service_name, const char * error_msg_, size_t invalid_index_)
  : NameValidationError("service name", service_name, error_msg_, invalid_index_) {}
};

class ParameterAlreadyDeclaredException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};

class ParameterNotDeclaredException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};

class InvalidParameterValueException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};

class InvalidParameterTypeException : public std::runtime_error
{
public:
  InvalidParameterTypeException(const std::string & name, const std::string message)
  : std::runtime_error("parameter '" + name + "' has invalid type: " + message) {}
};

}  // namespace exceptions
}  // namespace rclcpp

#endif  // RCLCPP__EXCEPTIONS_HPP_
