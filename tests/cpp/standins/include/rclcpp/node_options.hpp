// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::NodeOptions (accepted, mostly ignored).
#ifndef RCLCPP__NODE_OPTIONS_HPP_
#define RCLCPP__NODE_OPTIONS_HPP_

#include <string>
#include <vector>

#include "rhi_fake/detail/distro.hpp"

namespace rclcpp
{
class NodeOptions
{
public:
  NodeOptions() = default;

  bool use_intra_process_comms() const {return use_intra_process_comms_;}
  NodeOptions & use_intra_process_comms(bool v)
  {
    use_intra_process_comms_ = v;
    return *this;
  }
  bool start_parameter_services() const {return start_parameter_services_;}
  NodeOptions & start_parameter_services(bool v)
  {
    start_parameter_services_ = v;
    return *this;
  }
  bool start_parameter_event_publisher() const {return start_parameter_event_publisher_;}
  NodeOptions & start_parameter_event_publisher(bool v)
  {
    start_parameter_event_publisher_ = v;
    return *this;
  }
#if RHI_FAKE_RCLCPP_MAJOR >= 21
  // Iron (rclcpp 21) and later; hardware_interface 4.x+ sets it in define_custom_node_options().
  bool enable_logger_service() const {return enable_logger_service_;}
  NodeOptions & enable_logger_service(bool v)
  {
    enable_logger_service_ = v;
    return *this;
  }
#endif
  const std::vector<std::string> & arguments() const {return arguments_;}
  NodeOptions & arguments(const std::vector<std::string> & a)
  {
    arguments_ = a;
    return *this;
  }

private:
  bool use_intra_process_comms_ = false;
  bool start_parameter_services_ = true;
  bool start_parameter_event_publisher_ = true;
  bool enable_logger_service_ = false;
  std::vector<std::string> arguments_;
};
}  // namespace rclcpp

#endif  // RCLCPP__NODE_OPTIONS_HPP_
