// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Time as in ROS 2 Humble.
// Like the real class, comparing or subtracting Times of different clock types throws
// std::runtime_error (e.g. node->now() is RCL_ROS_TIME, rclcpp::Time(0) is RCL_SYSTEM_TIME).
#ifndef RCLCPP__TIME_HPP_
#define RCLCPP__TIME_HPP_

#include <cstdint>
#include <limits>
#include <stdexcept>

#include "builtin_interfaces/msg/time.hpp"
#include "rcl/time.h"
#include "rclcpp/duration.hpp"
#include "rclcpp/visibility_control.hpp"

namespace rclcpp
{

class RCLCPP_PUBLIC Time
{
public:
  Time(int32_t seconds, uint32_t nanoseconds, rcl_clock_type_t clock_type = RCL_SYSTEM_TIME)
  {
    if (seconds < 0) {
      throw std::runtime_error("cannot store a negative time point in rclcpp::Time");
    }
    rcl_time_.nanoseconds = static_cast<int64_t>(seconds) * 1000000000LL + nanoseconds;
    rcl_time_.clock_type = clock_type;
  }

  explicit Time(int64_t nanoseconds = 0, rcl_clock_type_t clock_type = RCL_SYSTEM_TIME)
  {
    rcl_time_.nanoseconds = nanoseconds;
    rcl_time_.clock_type = clock_type;
  }

  Time(const Time & rhs) = default;
  Time(Time && rhs) noexcept = default;

  Time(const builtin_interfaces::msg::Time & time_msg, rcl_clock_type_t clock_type = RCL_ROS_TIME)  // NOLINT
  {
    if (time_msg.sec < 0) {
      throw std::runtime_error("cannot store a negative time point in rclcpp::Time");
    }
    rcl_time_.nanoseconds = static_cast<int64_t>(time_msg.sec) * 1000000000LL + time_msg.nanosec;
    rcl_time_.clock_type = clock_type;
  }

  explicit Time(const rcl_time_point_t & time_point)
  : rcl_time_(time_point)
  {}

  virtual ~Time() = default;

  operator builtin_interfaces::msg::Time() const
  {
    builtin_interfaces::msg::Time msg;
    msg.sec = static_cast<int32_t>(rcl_time_.nanoseconds / 1000000000LL);
    msg.nanosec = static_cast<uint32_t>(rcl_time_.nanoseconds % 1000000000LL);
    return msg;
  }

  Time & operator=(const Time & rhs) = default;
  Time & operator=(Time && rhs) noexcept = default;

  Time & operator=(const builtin_interfaces::msg::Time & time_msg)
  {
    *this = Time(time_msg);
    return *this;
  }

  bool operator==(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't compare times with different time sources");
    return rcl_time_.nanoseconds == rhs.rcl_time_.nanoseconds;
  }
  bool operator!=(const rclcpp::Time & rhs) const {return !(*this == rhs);}
  bool operator<(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't compare times with different time sources");
    return rcl_time_.nanoseconds < rhs.rcl_time_.nanoseconds;
  }
  bool operator<=(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't compare times with different time sources");
    return rcl_time_.nanoseconds <= rhs.rcl_time_.nanoseconds;
  }
  bool operator>=(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't compare times with different time sources");
    return rcl_time_.nanoseconds >= rhs.rcl_time_.nanoseconds;
  }
  bool operator>(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't compare times with different time sources");
    return rcl_time_.nanoseconds > rhs.rcl_time_.nanoseconds;
  }

  Time operator+(const rclcpp::Duration & rhs) const
  {
    return Time(rcl_time_.nanoseconds + rhs.nanoseconds(), rcl_time_.clock_type);
  }

  Duration operator-(const rclcpp::Time & rhs) const
  {
    check_same(rhs, "can't subtract times with different time sources");
    return Duration::from_nanoseconds(rcl_time_.nanoseconds - rhs.rcl_time_.nanoseconds);
  }

  Time operator-(const rclcpp::Duration & rhs) const
  {
    return Time(rcl_time_.nanoseconds - rhs.nanoseconds(), rcl_time_.clock_type);
  }

  Time & operator+=(const rclcpp::Duration & rhs)
  {
    *this = *this + rhs;
    return *this;
  }

  Time & operator-=(const rclcpp::Duration & rhs)
  {
    *this = *this - rhs;
    return *this;
  }

  rcl_time_point_value_t nanoseconds() const {return rcl_time_.nanoseconds;}

  static Time max() {return Time(std::numeric_limits<int32_t>::max(), 999999999);}

  double seconds() const {return static_cast<double>(rcl_time_.nanoseconds) * 1e-9;}

  rcl_clock_type_t get_clock_type() const {return rcl_time_.clock_type;}

private:
  void check_same(const Time & rhs, const char * what) const
  {
    if (rcl_time_.clock_type != rhs.rcl_time_.clock_type) {
      throw std::runtime_error(what);
    }
  }

  rcl_time_point_t rcl_time_;
};

inline Time operator+(const rclcpp::Duration & lhs, const rclcpp::Time & rhs)
{
  return rhs + lhs;
}

}  // namespace rclcpp

#endif  // RCLCPP__TIME_HPP_
