// rhi-gen test stand-in (not the real ROS 2 code): interface name constants of ros2_control 4.x+.
#ifndef HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_TYPE_VALUES_HPP_
#define HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_TYPE_VALUES_HPP_

namespace hardware_interface
{
constexpr char HW_IF_POSITION[] = "position";
constexpr char HW_IF_VELOCITY[] = "velocity";
constexpr char HW_IF_ACCELERATION[] = "acceleration";
constexpr char HW_IF_EFFORT[] = "effort";
constexpr char HW_IF_TORQUE[] = "torque";
constexpr char HW_IF_FORCE[] = "force";
constexpr char HW_IF_CURRENT[] = "current";
constexpr char HW_IF_TEMPERATURE[] = "temperature";
// gains
constexpr char HW_IF_PROPORTIONAL_GAIN[] = "proportional";
constexpr char HW_IF_INTEGRAL_GAIN[] = "integral";
constexpr char HW_IF_DERIVATIVE_GAIN[] = "derivative";
constexpr char HW_IF_INTEGRAL_CLAMP_MAX[] = "integral_clamp_max";
constexpr char HW_IF_INTEGRAL_CLAMP_MIN[] = "integral_clamp_min";
constexpr char HW_IF_FEEDFORWARD[] = "feedforward";
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__HARDWARE_INTERFACE_TYPE_VALUES_HPP_
