// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Parameter, a name and a ParameterValue,
// with the accessors of rclcpp/parameter.hpp (Humble through Rolling) for the scalar types.
#ifndef RCLCPP__PARAMETER_HPP_
#define RCLCPP__PARAMETER_HPP_

#include <cstdint>
#include <string>
#include <utility>

#include "rclcpp/parameter_value.hpp"

namespace rclcpp
{

class Parameter
{
public:
  Parameter() = default;
  explicit Parameter(const std::string & name) : name_(name) {}
  Parameter(const std::string & name, const ParameterValue & value) : name_(name), value_(value) {}
  template<typename ValueTypeT>
  Parameter(const std::string & name, ValueTypeT value)
  : Parameter(name, ParameterValue(value)) {}

  bool operator==(const Parameter & rhs) const {return name_ == rhs.name_ && value_ == rhs.value_;}
  bool operator!=(const Parameter & rhs) const {return !(*this == rhs);}

  ParameterType get_type() const {return value_.get_type();}
  std::string get_type_name() const {return rclcpp::to_string(get_type());}
  const std::string & get_name() const {return name_;}
  const ParameterValue & get_parameter_value() const {return value_;}

  template<typename T>
  decltype(auto) get_value() const {return value_.get<T>();}

  bool as_bool() const {return value_.get<bool>();}
  int64_t as_int() const {return value_.get<int64_t>();}
  double as_double() const {return value_.get<double>();}
  const std::string & as_string() const {return value_.get<std::string>();}

private:
  std::string name_;
  ParameterValue value_;
};

}  // namespace rclcpp

#endif  // RCLCPP__PARAMETER_HPP_
