// rhi-gen test stand-in (not the real ROS 2 code): what Node::get_node_logging_interface()
// returns (abstract, as in rclcpp). ros2_control 4.x+ ResourceManager takes one.
#ifndef RCLCPP__NODE_INTERFACES__NODE_LOGGING_INTERFACE_HPP_
#define RCLCPP__NODE_INTERFACES__NODE_LOGGING_INTERFACE_HPP_

#include "rclcpp/logger.hpp"
#include "rclcpp/macros.hpp"

namespace rclcpp
{
namespace node_interfaces
{
class NodeLoggingInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeLoggingInterface)

  virtual ~NodeLoggingInterface() = default;

  /// The logger of the node.
  virtual rclcpp::Logger get_logger() const = 0;

  /// Its name.
  virtual const char * get_logger_name() const = 0;
};
}  // namespace node_interfaces
}  // namespace rclcpp

#endif  // RCLCPP__NODE_INTERFACES__NODE_LOGGING_INTERFACE_HPP_
