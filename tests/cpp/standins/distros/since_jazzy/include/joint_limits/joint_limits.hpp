// rhi-gen test stand-in (not the real ROS 2 code): joint_limits::JointLimits / SoftJointLimits
// of ros2_control 4.x+ (HardwareInfo::limits / soft_limits). Same members; every value starts NaN
// and every has_* flag false, as upstream's constructors do.
#ifndef JOINT_LIMITS__JOINT_LIMITS_HPP_
#define JOINT_LIMITS__JOINT_LIMITS_HPP_

#include <limits>
#include <sstream>
#include <string>

namespace joint_limits
{
struct JointLimits
{
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  double min_position = kNaN;
  double max_position = kNaN;
  double max_velocity = kNaN;
  double max_acceleration = kNaN;
  double max_deceleration = kNaN;
  double max_jerk = kNaN;
  double max_effort = kNaN;

  bool has_position_limits = false;
  bool has_velocity_limits = false;
  bool has_acceleration_limits = false;
  bool has_deceleration_limits = false;
  bool has_jerk_limits = false;
  bool has_effort_limits = false;
  bool angle_wraparound = false;

  JointLimits() {}

  /// Every flag off, every bound +-max (upstream's "limits disabled").
  void disable_all_limits()
  {
    has_position_limits = has_velocity_limits = has_acceleration_limits = false;
    has_deceleration_limits = has_jerk_limits = has_effort_limits = false;
    constexpr double big = std::numeric_limits<double>::max();
    min_position = -big;
    max_position = max_velocity = max_acceleration = max_deceleration = max_jerk = max_effort = big;
  }

  std::string to_string() const
  {
    std::ostringstream out;
    out << "  has position limits: " << (has_position_limits ? "true" : "false") << " [" <<
      min_position << ", " << max_position << "]\n";
    out << "  has velocity limits: " << (has_velocity_limits ? "true" : "false") << " [" <<
      max_velocity << "]\n";
    out << "  has effort limits: " << (has_effort_limits ? "true" : "false") << " [" <<
      max_effort << "]\n";
    out << "  angle wraparound: " << (angle_wraparound ? "true" : "false");
    return out.str();
  }
};

struct SoftJointLimits
{
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  double min_position = kNaN;
  double max_position = kNaN;
  double k_position = kNaN;
  double k_velocity = kNaN;

  SoftJointLimits() {}

  std::string to_string() const
  {
    std::ostringstream out;
    out << "  soft position limits: [" << min_position << ", " << max_position << "]\n";
    out << "  k-position: [" << k_position << "]\n";
    out << "  k-velocity: [" << k_velocity << "]\n";
    return out.str();
  }
};
}  // namespace joint_limits

#endif  // JOINT_LIMITS__JOINT_LIMITS_HPP_
