// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::Clock (ROS 2 Humble API subset).
// now() reads the system clock (steady clock for RCL_STEADY_TIME) unless a test set a fake time
// with rhi_fake::ros::set_time(). It never allocates. now() is non-const here (the stricter of
// the signatures rclcpp has had), so call it through a non-const Clock (node->get_clock()).
#ifndef RCLCPP__CLOCK_HPP_
#define RCLCPP__CLOCK_HPP_

#include <memory>

#include "rcl/time.h"
#include "rclcpp/macros.hpp"
#include "rclcpp/time.hpp"
#include "rclcpp/visibility_control.hpp"
#include "rhi_fake/detail/time_core.hpp"

namespace rclcpp
{

class RCLCPP_PUBLIC Clock
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Clock)

  explicit Clock(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME)
  : clock_type_(clock_type)
  {}

  ~Clock() = default;

  Time now()
  {
    return Time(::rhi_fake::detail::clock_now_ns(clock_type_), clock_type_);
  }

  bool ros_time_is_active() {return false;}

  rcl_clock_type_t get_clock_type() {return clock_type_;}

private:
  rcl_clock_type_t clock_type_;
};

}  // namespace rclcpp

#endif  // RCLCPP__CLOCK_HPP_
