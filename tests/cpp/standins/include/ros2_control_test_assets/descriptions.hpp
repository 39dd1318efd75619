// rhi-gen test stand-in (not the real ROS 2 code): ros2_control_test_assets/descriptions.hpp of
// ros2_control Humble (2.x). Only urdf_tail (same type and value as upstream: a `const auto`
// raw string literal, i.e. `const char *`, closing the <robot> element) is provided; the URDF
// heads and the hardware_resources descriptions are deliberately absent.
#ifndef ROS2_CONTROL_TEST_ASSETS__DESCRIPTIONS_HPP_
#define ROS2_CONTROL_TEST_ASSETS__DESCRIPTIONS_HPP_

#include <string>
#include <vector>

namespace ros2_control_test_assets
{
const auto urdf_tail =
  R"(
</robot>
)";

}  // namespace ros2_control_test_assets

#endif  // ROS2_CONTROL_TEST_ASSETS__DESCRIPTIONS_HPP_
