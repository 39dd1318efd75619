// rhi-gen test stand-in (not the real ROS 2 code): what Node::get_node_base_interface() returns;
// an Executor accepts it in add_node/remove_node like the real one.
#ifndef RCLCPP__NODE_INTERFACES__NODE_BASE_INTERFACE_HPP_
#define RCLCPP__NODE_INTERFACES__NODE_BASE_INTERFACE_HPP_

#include <memory>
#include <utility>

#include "rclcpp/macros.hpp"
#include "rhi_fake/detail/ros_core.hpp"

namespace rclcpp
{
namespace node_interfaces
{

class NodeBaseInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeBaseInterface)

  explicit NodeBaseInterface(std::shared_ptr<::rhi_fake::detail::NodeCore> core)
  : core_(std::move(core)) {}
  virtual ~NodeBaseInterface() = default;

  const char * get_name() const {return core_->name.c_str();}
  const char * get_namespace() const {return core_->ns.c_str();}
  const char * get_fully_qualified_name() const {return core_->fqn.c_str();}

  /// Stand-in internal.
  const std::shared_ptr<::rhi_fake::detail::NodeCore> & rhi_core() const {return core_;}

private:
  std::shared_ptr<::rhi_fake::detail::NodeCore> core_;
};

}  // namespace node_interfaces
}  // namespace rclcpp

#endif  // RCLCPP__NODE_INTERFACES__NODE_BASE_INTERFACE_HPP_
