// rhi-gen test stand-in (not the real ROS 2 code): the parameter callback handle of
// rclcpp/node_interfaces/node_parameters_interface.hpp. Humble names the callback type
// OnParametersSetCallbackType; Jazzy renames it OnSetParametersCallbackType and keeps the old name
// deprecated; Kilted and Rolling have only the new one.
#ifndef RCLCPP__NODE_INTERFACES__NODE_PARAMETERS_INTERFACE_HPP_
#define RCLCPP__NODE_INTERFACES__NODE_PARAMETERS_INTERFACE_HPP_

#include <functional>
#include <vector>

#include "rcl_interfaces/msg/set_parameters_result.hpp"
#include "rclcpp/macros.hpp"
#include "rclcpp/parameter.hpp"
#include "rhi_fake/detail/distro.hpp"

namespace rclcpp
{
namespace node_interfaces
{

struct OnSetParametersCallbackHandle
{
  RCLCPP_SMART_PTR_DEFINITIONS(OnSetParametersCallbackHandle)

#if RHI_FAKE_RCLCPP_MAJOR < 28
  using OnParametersSetCallbackType =
    std::function<rcl_interfaces::msg::SetParametersResult(const std::vector<rclcpp::Parameter> &)>;
  OnParametersSetCallbackType callback;
#else
  using OnSetParametersCallbackType =
    std::function<rcl_interfaces::msg::SetParametersResult(const std::vector<rclcpp::Parameter> &)>;
#if RHI_FAKE_RCLCPP_MAJOR < 29
  using OnParametersSetCallbackType [[deprecated("use OnSetParametersCallbackType instead")]] =
    OnSetParametersCallbackType;
#endif
  OnSetParametersCallbackType callback;
#endif
};

}  // namespace node_interfaces
}  // namespace rclcpp

#endif  // RCLCPP__NODE_INTERFACES__NODE_PARAMETERS_INTERFACE_HPP_
