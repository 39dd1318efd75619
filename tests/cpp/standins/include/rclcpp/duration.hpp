// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Duration as in ROS 2 Humble.
// As in Humble there is no default constructor (it is private) and no constructor from a bare
// integer count; use Duration(sec, nsec), a std::chrono duration, or from_seconds/from_nanoseconds.
#ifndef RCLCPP__DURATION_HPP_
#define RCLCPP__DURATION_HPP_

#include <chrono>
#include <cstdint>
#include <limits>

#include "builtin_interfaces/msg/duration.hpp"
#include "rcl/time.h"
#include "rmw/types.h"
#include "rclcpp/visibility_control.hpp"

namespace rclcpp
{
class Time;

class RCLCPP_PUBLIC Duration
{
public:
  Duration(int32_t seconds, uint32_t nanoseconds)
  {
    rcl_duration_.nanoseconds = static_cast<int64_t>(seconds) * 1000000000LL + nanoseconds;
  }

  explicit Duration(std::chrono::nanoseconds nanoseconds)
  {
    rcl_duration_.nanoseconds = nanoseconds.count();
  }

  // intentionally not explicit (as in rclcpp): converts from any std::chrono duration
  template<class Rep, class Period>
  Duration(const std::chrono::duration<Rep, Period> & duration)  // NOLINT
  : Duration(std::chrono::duration_cast<std::chrono::nanoseconds>(duration))
  {}

  Duration(const builtin_interfaces::msg::Duration & duration_msg)  // NOLINT
  {
    rcl_duration_.nanoseconds =
      static_cast<int64_t>(duration_msg.sec) * 1000000000LL + duration_msg.nanosec;
  }

  explicit Duration(const rcl_duration_t & duration)
  : rcl_duration_(duration)
  {}

  Duration(const Duration & rhs) = default;

  virtual ~Duration() = default;

  operator builtin_interfaces::msg::Duration() const
  {
    builtin_interfaces::msg::Duration msg;
    int64_t ns = rcl_duration_.nanoseconds;
    int64_t sec = ns / 1000000000LL;
    int64_t rem = ns % 1000000000LL;
    if (rem < 0) {
      rem += 1000000000LL;
      sec -= 1;
    }
    msg.sec = static_cast<int32_t>(sec);
    msg.nanosec = static_cast<uint32_t>(rem);
    return msg;
  }

  Duration & operator=(const Duration & rhs) = default;

  Duration & operator=(const builtin_interfaces::msg::Duration & duration_msg)
  {
    *this = Duration(duration_msg);
    return *this;
  }

  bool operator==(const rclcpp::Duration & rhs) const {return nanoseconds() == rhs.nanoseconds();}
  bool operator!=(const rclcpp::Duration & rhs) const {return nanoseconds() != rhs.nanoseconds();}
  bool operator<(const rclcpp::Duration & rhs) const {return nanoseconds() < rhs.nanoseconds();}
  bool operator<=(const rclcpp::Duration & rhs) const {return nanoseconds() <= rhs.nanoseconds();}
  bool operator>=(const rclcpp::Duration & rhs) const {return nanoseconds() >= rhs.nanoseconds();}
  bool operator>(const rclcpp::Duration & rhs) const {return nanoseconds() > rhs.nanoseconds();}

  Duration operator+(const rclcpp::Duration & rhs) const
  {
    return from_nanoseconds(nanoseconds() + rhs.nanoseconds());
  }
  Duration & operator+=(const rclcpp::Duration & rhs)
  {
    rcl_duration_.nanoseconds += rhs.nanoseconds();
    return *this;
  }
  Duration operator-(const rclcpp::Duration & rhs) const
  {
    return from_nanoseconds(nanoseconds() - rhs.nanoseconds());
  }
  Duration & operator-=(const rclcpp::Duration & rhs)
  {
    rcl_duration_.nanoseconds -= rhs.nanoseconds();
    return *this;
  }
  Duration operator-() const {return from_nanoseconds(-nanoseconds());}
  Duration operator*(double scale) const
  {
    return from_nanoseconds(static_cast<rcl_duration_value_t>(static_cast<double>(nanoseconds()) * scale));
  }
  Duration & operator*=(double scale)
  {
    *this = *this * scale;
    return *this;
  }

  static Duration max() {return Duration(std::numeric_limits<int32_t>::max(), 999999999);}

  rcl_duration_value_t nanoseconds() const {return rcl_duration_.nanoseconds;}

  double seconds() const {return static_cast<double>(rcl_duration_.nanoseconds) * 1e-9;}

  static Duration from_seconds(double seconds)
  {
    return from_nanoseconds(static_cast<rcl_duration_value_t>(seconds * 1e9));
  }

  static Duration from_nanoseconds(rcl_duration_value_t nanoseconds)
  {
    Duration d;
    d.rcl_duration_.nanoseconds = nanoseconds;
    return d;
  }

  static Duration from_rmw_time(rmw_time_t duration)
  {
    return from_nanoseconds(
      static_cast<rcl_duration_value_t>(duration.sec * 1000000000ULL + duration.nsec));
  }

  template<class DurationT>
  DurationT to_chrono() const
  {
    return std::chrono::duration_cast<DurationT>(std::chrono::nanoseconds(this->nanoseconds()));
  }

  rmw_time_t to_rmw_time() const
  {
    rmw_time_t t;
    int64_t ns = rcl_duration_.nanoseconds < 0 ? 0 : rcl_duration_.nanoseconds;
    t.sec = static_cast<uint64_t>(ns / 1000000000LL);
    t.nsec = static_cast<uint64_t>(ns % 1000000000LL);
    return t;
  }

private:
  friend class Time;
  Duration()
  {
    rcl_duration_.nanoseconds = 0;
  }

  rcl_duration_t rcl_duration_;
};

}  // namespace rclcpp

#endif  // RCLCPP__DURATION_HPP_
