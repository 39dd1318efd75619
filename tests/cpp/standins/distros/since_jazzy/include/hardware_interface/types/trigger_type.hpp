// rhi-gen test stand-in (not the real ROS 2 code).
#ifndef HARDWARE_INTERFACE__TYPES__TRIGGER_TYPE_HPP_
#define HARDWARE_INTERFACE__TYPES__TRIGGER_TYPE_HPP_

namespace hardware_interface
{
enum class TriggerType
{
  READ,
  WRITE
};
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__TRIGGER_TYPE_HPP_
