// rhi-gen test stand-in (not the real ROS 2 code): hardware_interface::ResourceManager of
// ros2_control 4.x+ for the generated colcon gtest (never a driver). Like upstream:
//  * every constructor needs a clock and a logger (ResourceManager(urdf) does not compile):
//    (clock_interface, logger_interface), (clock, logger), (urdf, clock_interface,
//    logger_interface, activate_all = false, update_rate = 100), (urdf, clock, logger,
//    activate_all = false, update_rate = 100), (const ResourceManagerParams &, bool load);
//    a null clock throws std::invalid_argument;
//  * loading parses the URDF with parse_control_resources_from_urdf(), which THROWS
//    std::runtime_error (out of the constructor) for a <ros2_control> joint that is not a joint of
//    the URDF, a fixed joint, a malformed URDF, ...;
//  * each component's plugin is created through the plugin registry (rhi_fake::plugins::resolve:
//    the <plugin> lookup name -> class type, as pluginlib does from the plugin description XML),
//    then init(params) (clock, logger "<rm logger>.hardware_component.<type>.<name>", executor and
//    namespace from the params) -> on_init -> export: the deprecated export_*_interfaces() first,
//    on_export_*_interfaces() when that returns nothing. A component that fails to load or to
//    initialise (or exports fewer interfaces than its description lists) makes loading fail:
//    nothing is kept, are_components_initialized() is false, nothing is thrown;
//  * components start 'unconfigured'; activate_all configures and activates them;
//    set_component_state() runs the lifecycle transitions; interfaces become available when a
//    component is configured; read() reads inactive and active components, write() active ones.
// Not here: claim_*_interface / Loaned*Interface, controller-exported interfaces, joint limiters,
// import_component, async components, statistics, on_component_state_switch callbacks.
#ifndef HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_
#define HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hardware_interface/component_parser.hpp"
#include "hardware_interface/hardware_component_info.hpp"
#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/system_interface.hpp"
#include "hardware_interface/types/hardware_interface_return_values.hpp"
#include "hardware_interface/types/lifecycle_state_names.hpp"
#include "hardware_interface/types/resource_manager_params.hpp"
#include "rclcpp/duration.hpp"
#include "rclcpp/executor.hpp"
#include "rclcpp/node_interfaces/node_clock_interface.hpp"
#include "rclcpp/node_interfaces/node_logging_interface.hpp"
#include "rclcpp/time.hpp"
#include "rhi_fake/detail/distro.hpp"
#include "rhi_fake/plugins.hpp"

namespace hardware_interface
{
struct HardwareReadWriteStatus
{
  return_type result;
  std::vector<std::string> failed_hardware_names;
};

class ResourceManager
{
public:
  explicit ResourceManager(
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface,
    rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logger_interface)
  : ResourceManager(make_params(clock_interface->get_clock(), logger_interface->get_logger()), false)
  {
  }

  explicit ResourceManager(rclcpp::Clock::SharedPtr clock, rclcpp::Logger logger)
  : ResourceManager(make_params(clock, logger), false)
  {
  }

  explicit ResourceManager(
    const std::string & urdf,
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock_interface,
    rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logger_interface,
    bool activate_all = false, const unsigned int update_rate = 100)
  : ResourceManager(
      make_params(
        clock_interface->get_clock(), logger_interface->get_logger(), urdf, activate_all,
        update_rate),
      true)
  {
  }

  explicit ResourceManager(
    const std::string & urdf, rclcpp::Clock::SharedPtr clock, rclcpp::Logger logger,
    bool activate_all = false, const unsigned int update_rate = 100)
  : ResourceManager(make_params(clock, logger, urdf, activate_all, update_rate), true)
  {
  }

  explicit ResourceManager(const hardware_interface::ResourceManagerParams & params, bool load)
  : params_(params)
  {
    if (!params_.clock) {
      throw std::invalid_argument("Clock is nullptr. ResourceManager needs a valid clock.");
    }
    if (load) {
      load_and_initialize_components(params);
      if (params.activate_all) {
        for (const auto & name : component_names()) {
          rclcpp_lifecycle::State active(
            lifecycle_msgs::msg::State::PRIMARY_STATE_ACTIVE, lifecycle_state_names::ACTIVE);
          set_component_state(name, active);
        }
      }
    }
  }

  ResourceManager(const ResourceManager &) = delete;

  virtual ~ResourceManager() = default;

  /// Every component to 'finalized'.
  bool shutdown_components()
  {
    bool ok = true;
    for (const auto & name : component_names()) {
      rclcpp_lifecycle::State finalized(
        lifecycle_msgs::msg::State::PRIMARY_STATE_FINALIZED, lifecycle_state_names::FINALIZED);
      ok = set_component_state(name, finalized) == return_type::OK && ok;
    }
    return ok;
  }

#if RHI_FAKE_HI_MAJOR < 5
  [[deprecated(
    "Use load_and_initialize_components(const ResourceManagerParams & params) "
    "instead")]]
  virtual bool load_and_initialize_components(
    const std::string & urdf, const unsigned int update_rate = 100)
  {
    ResourceManagerParams params = params_;
    params.robot_description = urdf;
    params.update_rate = update_rate;
    return load_and_initialize_components(params);
  }
#endif

  virtual bool load_and_initialize_components(const hardware_interface::ResourceManagerParams & params)
  {
    params_.clock = params.clock;
    params_.logger = params.logger;
    params_.robot_description = params.robot_description;
    params_.update_rate = params.update_rate;
    params_.executor = params.executor;
    params_.node_namespace = params.node_namespace;
    params_.handle_exceptions = params.handle_exceptions;
    initialized_ = false;
    auto hardware_info = parse_control_resources_from_urdf(params.robot_description);
    for (auto & hw : hardware_info) {
      hw.rw_rate = (hw.rw_rate == 0 || hw.rw_rate > params.update_rate) ? params.update_rate : hw.rw_rate;
    }
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    bool ok = true;
    for (const auto & hw : hardware_info) {
      if (components_.count(hw.name) != 0) {
        RCLCPP_ERROR(
          get_logger(), "Hardware name %s is duplicated. Please provide a unique 'name' in the URDF.",
          hw.name.c_str());
        ok = false;
        break;
      }
      if (!load_component(hw)) {
        ok = false;
        break;
      }
    }
    if (ok && validate_storage(hardware_info)) {
      initialized_ = true;
    } else {
      components_.clear();
      order_.clear();
      state_map_.clear();
      command_map_.clear();
      available_states_.clear();
      available_commands_.clear();
    }
    return initialized_;
  }

  bool are_components_initialized() const {return initialized_;}

  std::vector<std::string> state_interface_keys() const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    std::vector<std::string> keys;
    for (const auto & entry : state_map_) {keys.push_back(entry.first);}
    return keys;
  }

  std::vector<std::string> available_state_interfaces() const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return available_states_;
  }

  bool state_interface_is_available(const std::string & name) const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return contains(available_states_, name);
  }

  /// The stand-in never claims interfaces (no claim_command_interface()).
  bool command_interface_is_claimed(const std::string & /*key*/) const {return false;}

  std::vector<std::string> command_interface_keys() const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    std::vector<std::string> keys;
    for (const auto & entry : command_map_) {keys.push_back(entry.first);}
    return keys;
  }

  std::vector<std::string> available_command_interfaces() const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return available_commands_;
  }

  bool command_interface_is_available(const std::string & interface) const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return contains(available_commands_, interface);
  }

  size_t actuator_components_size() const {return count_type("actuator");}
  size_t sensor_components_size() const {return count_type("sensor");}
  size_t system_components_size() const {return count_type("system");}

  const std::unordered_map<std::string, HardwareComponentInfo> & get_components_status()
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    status_.clear();
    for (const auto & entry : components_) {
      status_[entry.first] = entry.second.info;
      status_[entry.first].state = entry.second.hw->get_lifecycle_state();
    }
    return status_;
  }

  bool prepare_command_mode_switch(
    const std::vector<std::string> & start_interfaces,
    const std::vector<std::string> & stop_interfaces)
  {
    return mode_switch(start_interfaces, stop_interfaces, true);
  }

  bool perform_command_mode_switch(
    const std::vector<std::string> & start_interfaces,
    const std::vector<std::string> & stop_interfaces)
  {
    return mode_switch(start_interfaces, stop_interfaces, false);
  }

  /// Runs the lifecycle transitions from the component's state to target_state.
  return_type set_component_state(
    const std::string & component_name, rclcpp_lifecycle::State & target_state)
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    const auto it = components_.find(component_name);
    if (it == components_.end()) {
      RCLCPP_WARN(
        get_logger(), "Hardware component '%s' does not exist, so its state cannot be changed.",
        component_name.c_str());
      return return_type::ERROR;
    }
    return transition(it->second, target_state.id()) ? return_type::OK : return_type::ERROR;
  }

  HardwareReadWriteStatus read(const rclcpp::Time & time, const rclcpp::Duration & period)
  {
    return cycle(time, period, true);
  }

  HardwareReadWriteStatus write(const rclcpp::Time & time, const rclcpp::Duration & period)
  {
    return cycle(time, period, false);
  }

  bool command_interface_exists(const std::string & key) const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return command_map_.count(key) != 0;
  }

  bool state_interface_exists(const std::string & key) const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return state_map_.count(key) != 0;
  }

  const std::string & get_robot_description() const {return params_.robot_description;}

protected:
  rclcpp::Logger get_logger() const {return params_.logger;}

  rclcpp::Clock::SharedPtr get_clock() const {return params_.clock;}

private:
  struct Component
  {
    std::shared_ptr<SystemInterface> hw;
    HardwareComponentInfo info;
  };

  static ResourceManagerParams make_params(
    rclcpp::Clock::SharedPtr clock, rclcpp::Logger logger, const std::string & urdf = "",
    bool activate_all = false, unsigned int update_rate = 100)
  {
    ResourceManagerParams params;
    params.clock = clock;
    params.logger = logger;
    params.robot_description = urdf;
    params.activate_all = activate_all;
    params.update_rate = update_rate;
    return params;
  }

  static bool contains(const std::vector<std::string> & list, const std::string & item)
  {
    return std::find(list.begin(), list.end(), item) != list.end();
  }

  std::vector<std::string> component_names() const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    return order_;
  }

  size_t count_type(const std::string & type) const
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    size_t n = 0;
    for (const auto & entry : components_) {n += entry.second.info.type == type ? 1U : 0U;}
    return n;
  }

  // Upstream: load_hardware() + initialize_hardware() + import_*_interfaces(). Only "system"
  // components have a stand-in interface class.
  bool load_component(const HardwareInfo & hw_info)
  {
    Component c;
    c.info.name = hw_info.name;
    c.info.type = hw_info.type;
    c.info.group = hw_info.group;
    c.info.plugin_name = hw_info.hardware_plugin_name;
    c.info.is_async = hw_info.is_async;
    c.info.rw_rate = hw_info.rw_rate;
    if (hw_info.type != "system") {
      RCLCPP_ERROR(
        get_logger(), "rhi_fake: the stand-in loads only 'system' components, not '%s' ('%s')",
        hw_info.type.c_str(), hw_info.name.c_str());
      return false;
    }
    try {
      const std::string type = ::rhi_fake::plugins::resolve(
        hw_info.hardware_plugin_name, "hardware_interface::SystemInterface");
      c.hw = ::rhi_fake::plugins::create<SystemInterface>(type);
    } catch (const std::exception & ex) {
      RCLCPP_ERROR(
        get_logger(), "Caught exception while loading hardware: %s", ex.what());
      if (!params_.handle_exceptions) {throw;}
      return false;
    }
    HardwareComponentParams component_params;
    component_params.hardware_info = hw_info;
    component_params.clock = params_.clock;
    component_params.logger = params_.logger.get_child(
      "hardware_component." + hw_info.type + "." + hw_info.name);
    component_params.executor = params_.executor;
    component_params.node_namespace = params_.node_namespace;
    try {
      const CallbackReturn r = c.hw->init(component_params);
      c.hw->set_lifecycle_state(
        r == CallbackReturn::SUCCESS ?
        rclcpp_lifecycle::State(
          lifecycle_msgs::msg::State::PRIMARY_STATE_UNCONFIGURED, lifecycle_state_names::UNCONFIGURED) :
        rclcpp_lifecycle::State(
          lifecycle_msgs::msg::State::PRIMARY_STATE_FINALIZED, lifecycle_state_names::FINALIZED));
      if (r != CallbackReturn::SUCCESS) {
        RCLCPP_ERROR(get_logger(), "Failed to initialize hardware '%s'", hw_info.name.c_str());
        return false;
      }
      import_interfaces(c);
    } catch (const std::exception & ex) {
      RCLCPP_ERROR(
        get_logger(), "Exception occurred while initializing hardware '%s': %s",
        hw_info.name.c_str(), ex.what());
      if (!params_.handle_exceptions) {throw;}
      return false;
    }
    order_.push_back(hw_info.name);
    components_.emplace(hw_info.name, std::move(c));
    return true;
  }

  // Upstream's HardwareComponent::export_*_interfaces(): the deprecated path first.
  void import_interfaces(Component & c)
  {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    std::vector<StateInterface> old_states = c.hw->export_state_interfaces();
    std::vector<CommandInterface> old_commands = c.hw->export_command_interfaces();
#pragma GCC diagnostic pop
    std::vector<StateInterface::ConstSharedPtr> states;
    if (old_states.empty()) {
      states = c.hw->on_export_state_interfaces();
    } else {
      for (const auto & s : old_states) {states.push_back(std::make_shared<const StateInterface>(s));}
    }
    for (const auto & s : states) {
      if (!state_map_.emplace(s->get_name(), s).second) {
        throw std::runtime_error(
                "ResourceStorage: Tried to insert StateInterface with already existing key. Insert[" +
                s->get_name() + "]");
      }
      c.info.state_interfaces.push_back(s->get_name());
    }
    std::vector<CommandInterface::SharedPtr> commands;
    if (old_commands.empty()) {
      commands = c.hw->on_export_command_interfaces();
    } else {
      for (auto & cmd : old_commands) {commands.push_back(std::make_shared<CommandInterface>(std::move(cmd)));}
    }
    for (const auto & cmd : commands) {
      if (!command_map_.emplace(cmd->get_name(), cmd).second) {
        throw std::runtime_error(
                "ResourceStorage: Tried to insert CommandInterface with already existing key. "
                "Insert[" + cmd->get_name() + "]");
      }
      c.info.command_interfaces.push_back(cmd->get_name());
    }
  }

  // Upstream: every interface the description lists must have been exported.
  bool validate_storage(const std::vector<HardwareInfo> & hardware_info) const
  {
    std::string missing;
    const auto need = [&](const std::vector<ComponentInfo> & list, bool commands) {
        for (const auto & component : list) {
          for (const auto & itf : component.state_interfaces) {
            const std::string key = component.name + "/" + itf.name;
            if (!state_interface_exists(key)) {missing += " state " + key;}
          }
          if (!commands) {continue;}
          for (const auto & itf : component.command_interfaces) {
            const std::string key = component.name + "/" + itf.name;
            if (!command_interface_exists(key)) {missing += " command " + key;}
          }
        }
      };
    for (const auto & hw : hardware_info) {
      need(hw.joints, true);
      need(hw.sensors, false);
      need(hw.gpios, true);
    }
    if (!missing.empty()) {
      RCLCPP_ERROR(
        get_logger(),
        "Discrepancy between robot description file (urdf) and actually exported HW interfaces. "
        "Missing:%s", missing.c_str());
      return false;
    }
    return true;
  }

  // One lifecycle callback; SUCCESS -> `to`, FAILURE -> stays, ERROR -> on_error().
  bool step(Component & c, uint8_t to, const char * label, CallbackReturn r)
  {
    using S = lifecycle_msgs::msg::State;
    if (r == CallbackReturn::SUCCESS) {
      c.hw->set_lifecycle_state(rclcpp_lifecycle::State(to, label));
      return true;
    }
    if (r == CallbackReturn::ERROR) {
      const CallbackReturn e = c.hw->on_error(c.hw->get_lifecycle_state());
      c.hw->set_lifecycle_state(
        e == CallbackReturn::SUCCESS ?
        rclcpp_lifecycle::State(S::PRIMARY_STATE_UNCONFIGURED, lifecycle_state_names::UNCONFIGURED) :
        rclcpp_lifecycle::State(S::PRIMARY_STATE_FINALIZED, lifecycle_state_names::FINALIZED));
      make_unavailable(c);
    }
    return false;
  }

  void make_available(const Component & c)
  {
    for (const auto & k : c.info.state_interfaces) {
      if (!contains(available_states_, k)) {available_states_.push_back(k);}
    }
    for (const auto & k : c.info.command_interfaces) {
      if (!contains(available_commands_, k)) {available_commands_.push_back(k);}
    }
  }

  void make_unavailable(const Component & c)
  {
    const auto drop = [](std::vector<std::string> & list, const std::vector<std::string> & keys) {
        list.erase(
          std::remove_if(
            list.begin(), list.end(), [&](const std::string & k) {return contains(keys, k);}),
          list.end());
      };
    drop(available_states_, c.info.state_interfaces);
    drop(available_commands_, c.info.command_interfaces);
  }

  bool transition(Component & c, uint8_t target)
  {
    using S = lifecycle_msgs::msg::State;
    namespace names = lifecycle_state_names;
    for (int guard = 0; guard < 4; ++guard) {
      const uint8_t id = c.hw->get_lifecycle_id();
      if (id == target) {return true;}
      const rclcpp_lifecycle::State current = c.hw->get_lifecycle_state();
      if (target == S::PRIMARY_STATE_FINALIZED) {
        if (id == S::PRIMARY_STATE_ACTIVE) {
          if (!step(c, S::PRIMARY_STATE_INACTIVE, names::INACTIVE, c.hw->on_deactivate(current))) {return false;}
          continue;
        }
        const bool ok = step(c, S::PRIMARY_STATE_FINALIZED, names::FINALIZED, c.hw->on_shutdown(current));
        make_unavailable(c);
        return ok;
      }
      if (id == S::PRIMARY_STATE_UNCONFIGURED) {
        if (!step(c, S::PRIMARY_STATE_INACTIVE, names::INACTIVE, c.hw->on_configure(current))) {return false;}
        make_available(c);
      } else if (id == S::PRIMARY_STATE_INACTIVE && target == S::PRIMARY_STATE_ACTIVE) {
        c.hw->prepare_for_activation();
        if (!step(c, S::PRIMARY_STATE_ACTIVE, names::ACTIVE, c.hw->on_activate(current))) {return false;}
      } else if (id == S::PRIMARY_STATE_INACTIVE && target == S::PRIMARY_STATE_UNCONFIGURED) {
        if (!step(c, S::PRIMARY_STATE_UNCONFIGURED, names::UNCONFIGURED, c.hw->on_cleanup(current))) {
          return false;
        }
        make_unavailable(c);
      } else if (id == S::PRIMARY_STATE_ACTIVE) {
        if (!step(c, S::PRIMARY_STATE_INACTIVE, names::INACTIVE, c.hw->on_deactivate(current))) {return false;}
      } else {
        return false;  // finalized / unknown: no way back
      }
    }
    return c.hw->get_lifecycle_id() == target;
  }

  bool mode_switch(
    const std::vector<std::string> & start, const std::vector<std::string> & stop, bool prepare)
  {
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    for (const auto & key : start) {
      if (!command_interface_exists(key) || !contains(available_commands_, key)) {return false;}
    }
    bool ok = true;
    for (const auto & name : order_) {
      Component & c = components_.at(name);
      std::vector<std::string> own_start, own_stop;
      for (const auto & k : start) {if (contains(c.info.command_interfaces, k)) {own_start.push_back(k);}}
      for (const auto & k : stop) {if (contains(c.info.command_interfaces, k)) {own_stop.push_back(k);}}
      if (own_start.empty() && own_stop.empty()) {continue;}
      const return_type r = prepare ? c.hw->prepare_command_mode_switch(own_start, own_stop) :
        c.hw->perform_command_mode_switch(own_start, own_stop);
      ok = ok && r == return_type::OK;
    }
    return ok;
  }

  HardwareReadWriteStatus cycle(const rclcpp::Time & time, const rclcpp::Duration & period, bool reading)
  {
    using S = lifecycle_msgs::msg::State;
    std::lock_guard<std::recursive_mutex> guard(mutex_);
    HardwareReadWriteStatus status{return_type::OK, {}};
    for (const auto & name : order_) {
      Component & c = components_.at(name);
      const uint8_t id = c.hw->get_lifecycle_id();
      const bool runs = id == S::PRIMARY_STATE_ACTIVE || (reading && id == S::PRIMARY_STATE_INACTIVE);
      if (!runs) {continue;}
      const HardwareComponentCycleStatus r = reading ? c.hw->trigger_read(time, period) :
        c.hw->trigger_write(time, period);
      if (r.result != return_type::OK) {
        status.result = r.result;
        status.failed_hardware_names.push_back(name);
      }
    }
    return status;
  }

  ResourceManagerParams params_;
  bool initialized_ = false;
  mutable std::recursive_mutex mutex_;
  std::vector<std::string> order_;  // component names in description order
  std::unordered_map<std::string, Component> components_;
  std::unordered_map<std::string, HardwareComponentInfo> status_;
  std::map<std::string, StateInterface::ConstSharedPtr> state_map_;
  std::map<std::string, CommandInterface::SharedPtr> command_map_;
  std::vector<std::string> available_states_;
  std::vector<std::string> available_commands_;
};

}  // namespace hardware_interface
#endif  // HARDWARE_INTERFACE__RESOURCE_MANAGER_HPP_
