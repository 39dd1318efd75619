// rhi-gen test stand-in (not the real ROS 2 code).
#ifndef HARDWARE_INTERFACE__TYPES__LIFECYCLE_STATE_NAMES_HPP_
#define HARDWARE_INTERFACE__TYPES__LIFECYCLE_STATE_NAMES_HPP_

namespace hardware_interface
{
namespace lifecycle_state_names
{
constexpr char UNKNOWN[] = "unknown";
constexpr char UNCONFIGURED[] = "unconfigured";
constexpr char INACTIVE[] = "inactive";
constexpr char ACTIVE[] = "active";
constexpr char FINALIZED[] = "finalized";
}  // namespace lifecycle_state_names
}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__TYPES__LIFECYCLE_STATE_NAMES_HPP_
