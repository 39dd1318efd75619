// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::ParameterType, ParameterValue and
// ParameterTypeException, as rclcpp/parameter_value.hpp declares them (Humble through Rolling), for
// the scalar types (bool, integer, double, string); the array types are not modelled.
#ifndef RCLCPP__PARAMETER_VALUE_HPP_
#define RCLCPP__PARAMETER_VALUE_HPP_

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "rcl_interfaces/msg/parameter_type.hpp"

namespace rclcpp
{

enum ParameterType : uint8_t
{
  PARAMETER_NOT_SET = rcl_interfaces::msg::ParameterType::PARAMETER_NOT_SET,
  PARAMETER_BOOL = rcl_interfaces::msg::ParameterType::PARAMETER_BOOL,
  PARAMETER_INTEGER = rcl_interfaces::msg::ParameterType::PARAMETER_INTEGER,
  PARAMETER_DOUBLE = rcl_interfaces::msg::ParameterType::PARAMETER_DOUBLE,
  PARAMETER_STRING = rcl_interfaces::msg::ParameterType::PARAMETER_STRING,
};

inline std::string to_string(ParameterType type)
{
  switch (type) {
    case PARAMETER_NOT_SET: return "not set";
    case PARAMETER_BOOL: return "bool";
    case PARAMETER_INTEGER: return "integer";
    case PARAMETER_DOUBLE: return "double";
    case PARAMETER_STRING: return "string";
    default: return "unknown type";
  }
}

class ParameterTypeException : public std::runtime_error
{
public:
  ParameterTypeException(ParameterType expected, ParameterType actual)
  : std::runtime_error("expected [" + to_string(expected) + "] got [" + to_string(actual) + "]")
  {}
};

class ParameterValue
{
public:
  ParameterValue() = default;
  explicit ParameterValue(const bool bool_value) : type_(PARAMETER_BOOL), bool_(bool_value) {}
  explicit ParameterValue(const int int_value) : type_(PARAMETER_INTEGER), int_(int_value) {}
  explicit ParameterValue(const int64_t int_value) : type_(PARAMETER_INTEGER), int_(int_value) {}
  explicit ParameterValue(const float double_value)
  : type_(PARAMETER_DOUBLE), double_(static_cast<double>(double_value)) {}
  explicit ParameterValue(const double double_value) : type_(PARAMETER_DOUBLE), double_(double_value) {}
  explicit ParameterValue(const std::string & string_value)
  : type_(PARAMETER_STRING), string_(string_value) {}
  explicit ParameterValue(const char * string_value)
  : ParameterValue(std::string(string_value)) {}

  ParameterType get_type() const {return type_;}

  bool operator==(const ParameterValue & rhs) const
  {
    return type_ == rhs.type_ && bool_ == rhs.bool_ && int_ == rhs.int_ && double_ == rhs.double_ &&
           string_ == rhs.string_;
  }
  bool operator!=(const ParameterValue & rhs) const {return !(*this == rhs);}

  /// The value as T (bool, an integer type, float / double, std::string); throws
  /// ParameterTypeException for another type, as rclcpp does.
  template<typename T>
  decltype(auto) get() const
  {
    using U = std::decay_t<T>;
    if constexpr (std::is_same_v<U, bool>) {
      check(PARAMETER_BOOL);
      return bool_;
    } else if constexpr (std::is_integral_v<U>) {
      check(PARAMETER_INTEGER);
      return static_cast<U>(int_);
    } else if constexpr (std::is_floating_point_v<U>) {
      check(PARAMETER_DOUBLE);
      return static_cast<U>(double_);
    } else {
      static_assert(std::is_same_v<U, std::string>, "the stand-in models scalar parameters only");
      check(PARAMETER_STRING);
      return (const std::string &)string_;
    }
  }

private:
  void check(ParameterType wanted) const
  {
    if (type_ != wanted) {
      throw ParameterTypeException(wanted, type_);
    }
  }

  ParameterType type_{PARAMETER_NOT_SET};
  bool bool_{false};
  int64_t int_{0};
  double double_{0.0};
  std::string string_;
};

}  // namespace rclcpp

#endif  // RCLCPP__PARAMETER_VALUE_HPP_
