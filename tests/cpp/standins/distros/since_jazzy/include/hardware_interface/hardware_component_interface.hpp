// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::HardwareComponentInterface,
// the base of SystemInterface on ros2_control 4.x+ (Jazzy 4.46, Kilted 5.16, Rolling/Lyrical 6.8).
// Header-only; it does what upstream's hardware_component_interface.cpp does:
//  * init(const HardwareComponentParams &) stores the clock, logger and info_, creates the
//    component's rclcpp::Node (name: the hardware name in lower case, '/' -> '_'; namespace
//    params.node_namespace; options from define_custom_node_options()) and adds it to
//    params.executor when one is given (else warns "Skipping node creation"), then calls
//    on_init(const HardwareComponentInterfaceParams &);
//  * the default on_init(params) calls on_init(const HardwareInfo &) on 4.x/5.x, which stores
//    info_ and fills the InterfaceDescription maps (joint/sensor/gpio by component type); on 6.x
//    on_init(const HardwareInfo &) does not exist and on_init(params) does that itself;
//  * the default on_export_state_interfaces() / on_export_command_interfaces() create one handle
//    per description (NaN unless initial_value), keep them in joint_states_/joint_commands_/
//    sensor_states_/gpio_* and in the name -> handle maps behind has_/get_/set_state|command.
//    The maps are unordered_maps upstream: the export order is NOT specified;
//  * 5.x+: "status_publish_rate" > 0 and a non-empty init_hardware_status_message() make init()
//    create a "~/hardware_status" publisher and a wall timer that calls
//    update_hardware_status_message() and publishes.
// Deprecated exactly where upstream is: on_init(const HardwareInfo &) (4.x, 5.x; removed 6.x),
// export_state_interfaces() / export_command_interfaces(), init(info, logger, clock) (4.x, 5.x),
// init(info, logger, NodeClockInterface) (4.x only). GCC does not warn when a driver overrides a
// deprecated virtual; it does when a driver calls one (e.g. SystemInterface::on_init(info)).
// Not simulated: is_async components (init() throws std::logic_error), introspection
// (enable_introspection() is a no-op, no stats_registrations_), async_handler_.
#ifndef HARDWARE_INTERFACE__HARDWARE_COMPONENT_INTERFACE_HPP_
#define HARDWARE_INTERFACE__HARDWARE_COMPONENT_INTERFACE_HPP_

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hardware_interface/component_parser.hpp"
#include "hardware_interface/handle.hpp"
#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/lexical_casts.hpp"
#include "hardware_interface/types/hardware_component_interface_params.hpp"
#include "hardware_interface/types/hardware_component_params.hpp"
#include "hardware_interface/types/hardware_interface_return_values.hpp"
#include "hardware_interface/types/hardware_interface_type_values.hpp"
#include "hardware_interface/types/lifecycle_state_names.hpp"
#include "hardware_interface/types/trigger_type.hpp"
#include "lifecycle_msgs/msg/state.hpp"
#include "rclcpp/duration.hpp"
#include "rclcpp/logger.hpp"
#include "rclcpp/logging.hpp"
#include "rclcpp/node_interfaces/node_clock_interface.hpp"
#include "rclcpp/time.hpp"
#include "rclcpp_lifecycle/node_interfaces/lifecycle_node_interface.hpp"
#include "rclcpp_lifecycle/state.hpp"
#include "rhi_fake/detail/distro.hpp"
#if RHI_FAKE_HI_MAJOR >= 5
#include "control_msgs/msg/hardware_status.hpp"
#endif

namespace hardware_interface
{

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class HardwareComponentInterface : public rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface
{
public:
  HardwareComponentInterface()
  : lifecycle_state_(
      rclcpp_lifecycle::State(
        lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN, lifecycle_state_names::UNKNOWN)),
    logger_(rclcpp::get_logger("hardware_component_interface"))
  {
  }

  HardwareComponentInterface(const HardwareComponentInterface & other) = delete;

  HardwareComponentInterface(HardwareComponentInterface && other) = delete;

  virtual ~HardwareComponentInterface() = default;

#if RHI_FAKE_HI_MAJOR < 5
  [[deprecated("Use init(HardwareInfo, rclcpp::Logger, rclcpp::Clock::SharedPtr) instead.")]]
  CallbackReturn init(
    const HardwareInfo & hardware_info, rclcpp::Logger logger,
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface)
  {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    return this->init(hardware_info, logger, clock_interface->get_clock());
#pragma GCC diagnostic pop
  }
#endif

#if RHI_FAKE_HI_MAJOR < 6
  [[deprecated(
    "Replaced by CallbackReturn init(const hardware_interface::HardwareComponentParams & "
    "params). Initialization is handled by the Framework.")]]
  CallbackReturn init(
    const HardwareInfo & hardware_info, rclcpp::Logger logger, rclcpp::Clock::SharedPtr clock)
  {
    hardware_interface::HardwareComponentParams params;
    params.hardware_info = hardware_info;
    params.clock = clock;
    params.logger = logger;
    return init(params);
  }
#endif

  /// What the framework calls (the ResourceManager; rhi_fake::hw::init in tests).
  CallbackReturn init(const hardware_interface::HardwareComponentParams & params)
  {
    clock_ = params.clock;
    logger_ = params.logger;
    info_ = params.hardware_info;
    if (params.hardware_info.is_async) {
      throw std::logic_error(
              "rhi_fake: asynchronous hardware components (is_async) are not simulated by the "
              "stand-in");
    }
    if (auto locked_executor = params.executor.lock()) {
      std::string node_name = hardware_interface::to_lower_case(params.hardware_info.name);
      std::replace(node_name.begin(), node_name.end(), '/', '_');
      auto options = define_custom_node_options();
      options.arguments({"--ros-args", "-r", "__node:=" + node_name});
      node_ = std::make_shared<rclcpp::Node>(node_name, params.node_namespace, options);
      locked_executor->add_node(node_->get_node_base_interface());
    } else {
      RCLCPP_WARN(
        params.logger,
        "Executor is not available during hardware component initialization for '%s'. Skipping "
        "node creation!",
        params.hardware_info.name.c_str());
    }
#if RHI_FAKE_HI_MAJOR >= 5
    if (init_status_publisher() != CallbackReturn::SUCCESS) {
      return CallbackReturn::ERROR;
    }
#endif
    hardware_interface::HardwareComponentInterfaceParams interface_params;
    interface_params.hardware_info = info_;
    interface_params.executor = params.executor;
    return on_init(interface_params);
  }

#if RHI_FAKE_HI_MAJOR >= 5
  /// Override to enable status publishing: pre-fill the message (empty device list = off).
  virtual CallbackReturn init_hardware_status_message(
    control_msgs::msg::HardwareStatus & /*msg_template*/)
  {
    return CallbackReturn::SUCCESS;
  }

  /// Override to fill the pre-allocated status message (called by the status timer).
  virtual return_type update_hardware_status_message(control_msgs::msg::HardwareStatus & /*msg*/)
  {
    return return_type::OK;
  }
#endif

#if RHI_FAKE_HI_MAJOR < 6
  [[deprecated("Use on_init(const HardwareComponentInterfaceParams & params) instead.")]]
  virtual CallbackReturn on_init(const HardwareInfo & hardware_info)
  {
    info_ = hardware_info;
    parse_interface_descriptions();
    return CallbackReturn::SUCCESS;
  }
#endif

  virtual CallbackReturn on_init(const hardware_interface::HardwareComponentInterfaceParams & params)
  {
#if RHI_FAKE_HI_MAJOR < 6
    // Upstream keeps the old path for drivers that only override on_init(info).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    return on_init(params.hardware_info);
#pragma GCC diagnostic pop
#else
    info_ = params.hardware_info;
    parse_interface_descriptions();
    return CallbackReturn::SUCCESS;
#endif
  }

  /// Options of the component's node (the logger service on, as upstream with rclcpp >= 21).
  virtual rclcpp::NodeOptions define_custom_node_options() const
  {
    rclcpp::NodeOptions node_options;
    node_options.enable_logger_service(true);
    return node_options;
  }

  [[deprecated(
    "Replaced by vector<StateInterface::ConstSharedPtr> on_export_state_interfaces() method. "
    "Exporting is handled by the Framework.")]]
  virtual std::vector<StateInterface> export_state_interfaces()
  {
    return {};  // empty: the framework then calls on_export_state_interfaces()
  }

  virtual std::vector<hardware_interface::InterfaceDescription>
  export_unlisted_state_interface_descriptions()
  {
    return {};
  }

  virtual std::vector<StateInterface::ConstSharedPtr> on_export_state_interfaces()
  {
    std::vector<StateInterface::ConstSharedPtr> out;
    for (const auto & description : export_unlisted_state_interface_descriptions()) {
      unlisted_state_interfaces_.insert(std::make_pair(description.get_name(), description));
      out.push_back(add_state(description, unlisted_states_));
    }
    for (const auto & entry : joint_state_interfaces_) {
      out.push_back(add_state(entry.second, joint_states_));
    }
    for (const auto & entry : sensor_state_interfaces_) {
      out.push_back(add_state(entry.second, sensor_states_));
    }
    for (const auto & entry : gpio_state_interfaces_) {
      out.push_back(add_state(entry.second, gpio_states_));
    }
    return out;
  }

  [[deprecated(
    "Replaced by vector<CommandInterface::SharedPtr> on_export_command_interfaces() method. "
    "Exporting is handled by the Framework.")]]
  virtual std::vector<CommandInterface> export_command_interfaces()
  {
    return {};  // empty: the framework then calls on_export_command_interfaces()
  }

  virtual std::vector<hardware_interface::InterfaceDescription>
  export_unlisted_command_interface_descriptions()
  {
    return {};
  }

  virtual std::vector<CommandInterface::SharedPtr> on_export_command_interfaces()
  {
    std::vector<CommandInterface::SharedPtr> out;
    for (const auto & description : export_unlisted_command_interface_descriptions()) {
      unlisted_command_interfaces_.insert(std::make_pair(description.get_name(), description));
      out.push_back(add_command(description, unlisted_commands_));
    }
    for (const auto & entry : joint_command_interfaces_) {
      out.push_back(add_command(entry.second, joint_commands_));
    }
    for (const auto & entry : gpio_command_interfaces_) {
      out.push_back(add_command(entry.second, gpio_commands_));
    }
    return out;
  }

  virtual return_type prepare_command_mode_switch(
    const std::vector<std::string> & /*start_interfaces*/,
    const std::vector<std::string> & /*stop_interfaces*/)
  {
    return return_type::OK;
  }

  virtual return_type perform_command_mode_switch(
    const std::vector<std::string> & /*start_interfaces*/,
    const std::vector<std::string> & /*stop_interfaces*/)
  {
    return return_type::OK;
  }

  /// read() now, timed (synchronous components; the stand-in has no async ones).
  HardwareComponentCycleStatus trigger_read(const rclcpp::Time & time, const rclcpp::Duration & period)
  {
    HardwareComponentCycleStatus status;
    const auto start = std::chrono::steady_clock::now();
    status.successful = true;
    status.result = read(time, period);
    status.execution_time = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now() - start);
    return status;
  }

  virtual return_type read(const rclcpp::Time & time, const rclcpp::Duration & period) = 0;

  HardwareComponentCycleStatus trigger_write(const rclcpp::Time & time, const rclcpp::Duration & period)
  {
    HardwareComponentCycleStatus status;
    const auto start = std::chrono::steady_clock::now();
    status.successful = true;
    status.result = write(time, period);
    status.execution_time = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now() - start);
    return status;
  }

  virtual return_type write(const rclcpp::Time & /*time*/, const rclcpp::Duration & /*period*/)
  {
    return return_type::OK;
  }

  const std::string & get_name() const {return info_.name;}

  const std::string & get_group_name() const {return info_.group;}

  const rclcpp_lifecycle::State & get_lifecycle_state() const {return lifecycle_state_;}

  void set_lifecycle_state(const rclcpp_lifecycle::State & new_state)
  {
    lifecycle_state_ = new_state;
    lifecycle_id_cache_.store(new_state.id(), std::memory_order_release);
  }

  uint8_t get_lifecycle_id() const {return lifecycle_id_cache_.load(std::memory_order_acquire);}

  virtual bool has_state(const std::string & interface_name) const
  {
    return hardware_states_.find(interface_name) != hardware_states_.end();
  }

  /// Throws std::runtime_error for an interface this component did not export.
  virtual const StateInterface::SharedPtr & get_state_interface_handle(
    const std::string & interface_name) const
  {
    const auto it = hardware_states_.find(interface_name);
    if (it == hardware_states_.end()) {
      throw std::runtime_error(
              "The requested state interface not found: '" + interface_name +
              "' in hardware component: '" + info_.name + "'.");
    }
    return it->second;
  }

  template<typename T>
  bool set_state(
    const StateInterface::SharedPtr & interface_handle, const T & value, bool wait_until_set)
  {
    if (!interface_handle) {
      throw std::runtime_error(
              "State interface handle is null in hardware component: " + info_.name +
              ", while calling set_state method. This should not happen.");
    }
    return interface_handle->set_value(value, wait_until_set);
  }

  /// Not real-time safe (waits for the lock).
  template<typename T>
  void set_state(const std::string & interface_name, const T & value)
  {
    std::ignore = set_state(get_state_interface_handle(interface_name), value, true);
  }

  template<typename T>
  bool get_state(
    const StateInterface::SharedPtr & interface_handle, T & state, bool wait_until_get) const
  {
    if (!interface_handle) {
      throw std::runtime_error(
              "State interface handle is null in hardware component: " + info_.name +
              ", while calling get_state method. This should not happen.");
    }
    const bool success = interface_handle->get_value(state, wait_until_get);
    if (!success && wait_until_get) {
      throw std::runtime_error(
              "Failed to get state value from interface: " + interface_handle->get_name() +
              " in hardware component: " + info_.name + ". This should not happen.");
    }
    return success;
  }

  template<typename T = double>
  T get_state(const std::string & interface_name) const
  {
    T state;
    get_state<T>(get_state_interface_handle(interface_name), state, true);
    return state;
  }

  virtual bool has_command(const std::string & interface_name) const
  {
    return hardware_commands_.find(interface_name) != hardware_commands_.end();
  }

  virtual const CommandInterface::SharedPtr & get_command_interface_handle(
    const std::string & interface_name) const
  {
    const auto it = hardware_commands_.find(interface_name);
    if (it == hardware_commands_.end()) {
      throw std::runtime_error(
              "The requested command interface not found: '" + interface_name +
              "' in hardware component: '" + info_.name + "'.");
    }
    return it->second;
  }

  template<typename T>
  bool set_command(
    const CommandInterface::SharedPtr & interface_handle, const T & value, bool wait_until_set)
  {
    if (!interface_handle) {
      throw std::runtime_error(
              "Command interface handle is null in hardware component: " + info_.name +
              ", while calling set_command method. This should not happen.");
    }
    return interface_handle->set_value(value, wait_until_set);
  }

  template<typename T>
  void set_command(const std::string & interface_name, const T & value)
  {
    std::ignore = set_command(get_command_interface_handle(interface_name), value, true);
  }

  template<typename T>
  bool get_command(
    const CommandInterface::SharedPtr & interface_handle, T & command, bool wait_until_get) const
  {
    if (!interface_handle) {
      throw std::runtime_error(
              "Command interface handle is null in hardware component: " + info_.name +
              ", while calling get_command method. This should not happen.");
    }
    const bool success = interface_handle->get_value(command, wait_until_get);
    if (!success && wait_until_get) {
      throw std::runtime_error(
              "Failed to get command value from interface: " + interface_handle->get_name() +
              " in hardware component: " + info_.name + ". This should not happen.");
    }
    return success;
  }

  template<typename T = double>
  T get_command(const std::string & interface_name) const
  {
    T command;
    get_command<T>(get_command_interface_handle(interface_name), command, true);
    return command;
  }

  /// The logger given by the framework ("hardware_component_interface" before init()).
  virtual rclcpp::Logger get_logger() const {return logger_;}

  /// The controller manager's clock (nullptr before init()).
  virtual rclcpp::Clock::SharedPtr get_clock() const {return clock_;}

  /// The component's node, in the framework's executor (nullptr without an executor).
  virtual rclcpp::Node::SharedPtr get_node() const {return node_;}

  const HardwareInfo & get_hardware_info() const {return info_;}

  void pause_async_operations() {}

  void stop_async_handler() {}

  void prepare_for_activation() {}

  void enable_introspection(bool /*enable*/) {}

protected:
  HardwareInfo info_;
  // interface names to InterfaceDescription
  std::unordered_map<std::string, InterfaceDescription> joint_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> joint_command_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> sensor_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> gpio_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> gpio_command_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> unlisted_state_interfaces_;
  std::unordered_map<std::string, InterfaceDescription> unlisted_command_interfaces_;

  rclcpp_lifecycle::State lifecycle_state_;

  // Handles created by the default on_export_*_interfaces().
  std::vector<StateInterface::SharedPtr> joint_states_;
  std::vector<CommandInterface::SharedPtr> joint_commands_;
  std::vector<StateInterface::SharedPtr> sensor_states_;
  std::vector<StateInterface::SharedPtr> gpio_states_;
  std::vector<CommandInterface::SharedPtr> gpio_commands_;
  std::vector<StateInterface::SharedPtr> unlisted_states_;
  std::vector<CommandInterface::SharedPtr> unlisted_commands_;

private:
  // What upstream's on_init(info) parses, by component type.
  void parse_interface_descriptions()
  {
    if (info_.type == "actuator") {
      parse_state_interface_descriptions(info_.joints, joint_state_interfaces_);
      parse_command_interface_descriptions(info_.joints, joint_command_interfaces_);
    } else if (info_.type == "sensor") {
      parse_state_interface_descriptions(info_.joints, joint_state_interfaces_);
      parse_state_interface_descriptions(info_.sensors, sensor_state_interfaces_);
    } else if (info_.type == "system") {
      parse_state_interface_descriptions(info_.joints, joint_state_interfaces_);
      parse_state_interface_descriptions(info_.sensors, sensor_state_interfaces_);
      parse_state_interface_descriptions(info_.gpios, gpio_state_interfaces_);
      parse_command_interface_descriptions(info_.joints, joint_command_interfaces_);
      parse_command_interface_descriptions(info_.gpios, gpio_command_interfaces_);
    }
  }

  StateInterface::ConstSharedPtr add_state(
    const InterfaceDescription & description, std::vector<StateInterface::SharedPtr> & list)
  {
    auto handle = std::make_shared<StateInterface>(description);
    hardware_states_.insert(std::make_pair(description.get_name(), handle));
    list.push_back(handle);
    return std::const_pointer_cast<const StateInterface>(handle);
  }

  CommandInterface::SharedPtr add_command(
    const InterfaceDescription & description, std::vector<CommandInterface::SharedPtr> & list)
  {
    auto handle = std::make_shared<CommandInterface>(description);
    hardware_commands_.insert(std::make_pair(description.get_name(), handle));
    list.push_back(handle);
    return handle;
  }

#if RHI_FAKE_HI_MAJOR >= 5
  // Upstream's status publisher setup in init() (RealtimeThreadSafeBox -> a mutex here).
  CallbackReturn init_status_publisher()
  {
    double publish_rate = 0.0;
    const auto it = info_.hardware_parameters.find("status_publish_rate");
    if (it != info_.hardware_parameters.end()) {
      try {
        publish_rate = hardware_interface::stod(it->second);
      } catch (const std::invalid_argument &) {
        RCLCPP_WARN(
          get_logger(), "Invalid 'status_publish_rate' parameter. Using default %.1f Hz.",
          publish_rate);
      }
    }
    if (publish_rate <= 0.0) {
      return CallbackReturn::SUCCESS;
    }
    control_msgs::msg::HardwareStatus status_template;
    if (init_hardware_status_message(status_template) != CallbackReturn::SUCCESS) {
      RCLCPP_ERROR(get_logger(), "User-defined 'init_hardware_status_message' failed.");
      return CallbackReturn::ERROR;
    }
    if (status_template.hardware_device_states.empty()) {
      RCLCPP_WARN(
        get_logger(),
        "`status_publish_rate` was set to a non-zero value, but no hardware status message was "
        "configured. Publisher will not be created. Are you sure "
        "init_hardware_status_message() is set up properly?");
      return CallbackReturn::SUCCESS;
    }
    if (!node_) {
      RCLCPP_WARN(
        get_logger(),
        "Hardware status message was configured, but no node is available for the publisher. "
        "Publisher will not be created.");
      return CallbackReturn::SUCCESS;
    }
    try {
      status_publisher_ = node_->create_publisher<control_msgs::msg::HardwareStatus>(
        "~/hardware_status", rclcpp::SystemDefaultsQoS());
      status_timer_ = node_->create_wall_timer(
        std::chrono::duration<double>(1.0 / publish_rate), [this]() {publish_status();});
      std::lock_guard<std::mutex> lock(status_mutex_);
      status_message_ = status_template;
    } catch (const std::exception & e) {
      RCLCPP_ERROR(
        get_logger(), "Exception during publisher/timer setup for hardware status: %s", e.what());
      return CallbackReturn::ERROR;
    }
    return CallbackReturn::SUCCESS;
  }

  void publish_status()
  {
    std::lock_guard<std::mutex> lock(status_mutex_);
    if (!status_message_.has_value() || !status_publisher_) {
      return;
    }
    control_msgs::msg::HardwareStatus & msg = status_message_.value();
    if (update_hardware_status_message(msg) != return_type::OK) {
      RCLCPP_WARN_THROTTLE(
        get_logger(), *clock_, 1000, "User's update_hardware_status_message() failed for '%s'.",
        info_.name.c_str());
      return;
    }
    msg.header.stamp = clock_->now();
    status_publisher_->publish(msg);
  }

  rclcpp::Publisher<control_msgs::msg::HardwareStatus>::SharedPtr status_publisher_;
  rclcpp::TimerBase::SharedPtr status_timer_;
  std::mutex status_mutex_;
  std::optional<control_msgs::msg::HardwareStatus> status_message_;
#endif

  rclcpp::Clock::SharedPtr clock_;
  rclcpp::Logger logger_;
  rclcpp::Node::SharedPtr node_;
  std::unordered_map<std::string, StateInterface::SharedPtr> hardware_states_;
  std::unordered_map<std::string, CommandInterface::SharedPtr> hardware_commands_;
  std::atomic<uint8_t> lifecycle_id_cache_{lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN};
};

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__HARDWARE_COMPONENT_INTERFACE_HPP_
