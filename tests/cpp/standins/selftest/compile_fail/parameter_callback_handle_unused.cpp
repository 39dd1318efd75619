// expect: ignoring return value|unused-result
// add_on_set_parameters_callback() is RCUTILS_WARN_UNUSED: a dropped handle removes the callback at once.
#include <memory>
#include <vector>

#include <rclcpp/node.hpp>

rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr f(const std::shared_ptr<rclcpp::Node> & node)
{
  auto callback = [](const std::vector<rclcpp::Parameter> &) {
      return rcl_interfaces::msg::SetParametersResult();
    };
#ifdef RHI_EXPECT_FAIL
  node->add_on_set_parameters_callback(callback);
  return nullptr;
#else
  return node->add_on_set_parameters_callback(callback);
#endif
}
