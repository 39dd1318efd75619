// rhi-gen test stand-in (not the real ROS 2 code): rclcpp_lifecycle::State (Humble API subset).
#ifndef RCLCPP_LIFECYCLE__STATE_HPP_
#define RCLCPP_LIFECYCLE__STATE_HPP_

#include <cstdint>
#include <stdexcept>
#include <string>

#include "lifecycle_msgs/msg/state.hpp"

namespace rclcpp_lifecycle
{

class State
{
public:
  /// Default: PRIMARY_STATE_UNKNOWN, label "unknown".
  State()
  : id_(lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN), label_("unknown") {}

  State(uint8_t id, const std::string & label)
  : id_(id), label_(label)
  {
    if (label.empty()) {
      throw std::runtime_error("Lifecycle State cannot have an empty label.");
    }
  }

  State(const State & rhs) = default;
  virtual ~State() = default;
  State & operator=(const State & rhs) = default;

  uint8_t id() const {return id_;}
  std::string label() const {return label_;}

private:
  uint8_t id_;
  std::string label_;
};

}  // namespace rclcpp_lifecycle

#endif  // RCLCPP_LIFECYCLE__STATE_HPP_
