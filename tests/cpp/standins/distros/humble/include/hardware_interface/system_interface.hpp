// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::SystemInterface as in
// ROS 2 Humble (hardware_interface 2.x): on_init(const HardwareInfo &) stores info_ and returns
// SUCCESS; export_state_interfaces / export_command_interfaces / read / write are pure virtual;
// copy is deleted; there is no get_logger() / get_node() / get_clock() (those came after Humble).
// Includes exactly what the Humble header includes (not rclcpp/node.hpp, not rclcpp/logging.hpp,
// not hardware_interface_type_values.hpp).
#ifndef HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_
#define HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_

#include <memory>
#include <string>
#include <vector>

#include "hardware_interface/handle.hpp"
#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/types/hardware_interface_return_values.hpp"
#include "hardware_interface/types/lifecycle_state_names.hpp"
#include "lifecycle_msgs/msg/state.hpp"
#include "rclcpp/duration.hpp"
#include "rclcpp/time.hpp"
#include "rclcpp_lifecycle/node_interfaces/lifecycle_node_interface.hpp"
#include "rclcpp_lifecycle/state.hpp"

namespace hardware_interface
{

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class SystemInterface : public rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface
{
public:
  SystemInterface()
  : lifecycle_state_(rclcpp_lifecycle::State(
      lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN, lifecycle_state_names::UNKNOWN))
  {
  }

  /// SystemInterface copy constructor is actively deleted.
  SystemInterface(const SystemInterface & other) = delete;

  SystemInterface(SystemInterface && other) = default;

  virtual ~SystemInterface() = default;

  /// Initialization of the hardware interface from data parsed from the robot's URDF.
  virtual CallbackReturn on_init(const HardwareInfo & hardware_info)
  {
    info_ = hardware_info;
    return CallbackReturn::SUCCESS;
  };

  /// Exports all state interfaces for this hardware interface.
  virtual std::vector<StateInterface> export_state_interfaces() = 0;

  /// Exports all command interfaces for this hardware interface.
  virtual std::vector<CommandInterface> export_command_interfaces() = 0;

  /// Prepare for a new command interface switch.
  virtual return_type prepare_command_mode_switch(
    const std::vector<std::string> & /*start_interfaces*/,
    const std::vector<std::string> & /*stop_interfaces*/)
  {
    return return_type::OK;
  }

  /// Perform switching to the new command interface.
  virtual return_type perform_command_mode_switch(
    const std::vector<std::string> & /*start_interfaces*/,
    const std::vector<std::string> & /*stop_interfaces*/)
  {
    return return_type::OK;
  }

  /// Read the current state values from the hardware.
  virtual return_type read(const rclcpp::Time & time, const rclcpp::Duration & period) = 0;

  /// Write the current command values to the hardware.
  virtual return_type write(const rclcpp::Time & time, const rclcpp::Duration & period) = 0;

  /// Get name of the hardware.
  virtual std::string get_name() const {return info_.name;}

  /// Get life-cycle state of the hardware.
  const rclcpp_lifecycle::State & get_state() const {return lifecycle_state_;}

  /// Set life-cycle state of the hardware.
  void set_state(const rclcpp_lifecycle::State & new_state) {lifecycle_state_ = new_state;}

protected:
  HardwareInfo info_;
  rclcpp_lifecycle::State lifecycle_state_;
};

}  // namespace hardware_interface

#endif  // HARDWARE_INTERFACE__SYSTEM_INTERFACE_HPP_
