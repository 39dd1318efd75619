// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__ROS2_CONTROL_COMPAT_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__ROS2_CONTROL_COMPAT_HPP_

// Every difference between the ros2_control releases this package builds on lives in this file.
//   - Humble (hardware_interface 2.x) and Jazzy before 4.34: on_init(const HardwareInfo &) and
//     export_*_interfaces(), whose handles point at doubles the driver owns.
//   - Jazzy 4.34+, Kilted (5.x), Lyrical and Rolling (6.x): on_init(const
//     HardwareComponentInterfaceParams &); the framework creates the handles from the description
//     (on_export_*_interfaces()) and owns their values; the component gets its logger from it.
//     The old on_init and the raw-pointer handles are deprecated (4.x, 5.x) or gone (6.x).
//   - State interfaces the description does not list (unlisted_state_names(): motor health found
//     in the installed messages): exported beside the listed ones on Humble,
//     export_unlisted_state_interface_descriptions() from 4.34 on.
//   - 5.10+ (Kilted, Lyrical, Rolling): the HardwareStatus hooks
//     (ROBOT_HARDWARE_INTERFACE_HARDWARE_STATUS), which the driver overrides.
// Drivers derive from SystemInterfaceAdapter, keep their values in plain doubles, and call
// publish_state_values() / fetch_command_values() / publish_command_values() where the values
// change hands: no-ops with raw pointers, a try-lock copy per interface with framework handles
// (never blocking, never allocating). A handle another thread holds refuses the try-lock; the
// refused ones are tried again, a bounded number of passes with a yield between them (what
// ros2_control's LoanedCommandInterface does for controllers), and a command is fetched whole or
// not at all (fetch_command_values()).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <hardware_interface/handle.hpp>
#include <hardware_interface/hardware_info.hpp>
#include <hardware_interface/system_interface.hpp>
#include <rclcpp/clock.hpp>
#include <rclcpp/logger.hpp>

#include "robot_hardware_interface/common/types.hpp"

#if defined(__has_include)
#if __has_include(<hardware_interface/version.h>)
#include <hardware_interface/version.h>
#endif
#endif

#if defined(HARDWARE_INTERFACE_VERSION_GTE)
#if HARDWARE_INTERFACE_VERSION_GTE(4, 34, 0)
#define ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES 1
#endif
#endif
#ifndef ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
#define ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES 0
#endif

// From 5.10 on (Kilted, Lyrical, Rolling) the framework publishes control_msgs/HardwareStatus on
// ~/hardware_status at the <hardware> parameter status_publish_rate, filled by the component.
#if defined(HARDWARE_INTERFACE_VERSION_GTE)
#if HARDWARE_INTERFACE_VERSION_GTE(5, 10, 0)
#define ROBOT_HARDWARE_INTERFACE_HARDWARE_STATUS 1
#endif
#endif
#ifndef ROBOT_HARDWARE_INTERFACE_HARDWARE_STATUS
#define ROBOT_HARDWARE_INTERFACE_HARDWARE_STATUS 0
#endif

// From 3.1 on, a read() that returns ERROR makes the controller manager deactivate every
// controller of the component, without a mode switch the component sees (the stop switch it
// attempts from 4.x on is refused: the component's interfaces are unavailable by then). Up to 2.x
// (Humble) its controllers keep running through the error and the recovery, claims and all.
#if defined(HARDWARE_INTERFACE_VERSION_GTE)
#if HARDWARE_INTERFACE_VERSION_GTE(3, 1, 0)
#define ROBOT_HARDWARE_INTERFACE_ERROR_STOPS_CONTROLLERS 1
#endif
#endif
#ifndef ROBOT_HARDWARE_INTERFACE_ERROR_STOPS_CONTROLLERS
#define ROBOT_HARDWARE_INTERFACE_ERROR_STOPS_CONTROLLERS 0
#endif

// From 3.x on the ResourceManager takes the controller manager's clock and logger.
#if defined(HARDWARE_INTERFACE_VERSION_MAJOR) && HARDWARE_INTERFACE_VERSION_MAJOR >= 3
#define ROBOT_HARDWARE_INTERFACE_RESOURCE_MANAGER_CLOCK 1
#else
#define ROBOT_HARDWARE_INTERFACE_RESOURCE_MANAGER_CLOCK 0
#endif

namespace robot_hardware_interface
{

class SystemInterfaceAdapter : public hardware_interface::SystemInterface
{
public:
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
  CallbackReturn on_init(
    const hardware_interface::HardwareComponentInterfaceParams & params) override
  {
    if (hardware_interface::SystemInterface::on_init(params) != CallbackReturn::SUCCESS) {
      return CallbackReturn::ERROR;
    }
    return initialize(info_, get_logger());
  }

  // State interfaces of the description's joints that the description does not list
  // (unlisted_state_names()): the framework creates their handles like the listed ones'.
  std::vector<hardware_interface::InterfaceDescription>
  export_unlisted_state_interface_descriptions() override
  {
    std::vector<hardware_interface::InterfaceDescription> unlisted;
    for (const auto & joint : info_.joints) {
      for (const std::string & name : unlisted_state_names(joint)) {
        hardware_interface::InterfaceInfo interface{};
        interface.name = name;
        interface.initial_value = "0.0";
        interface.data_type = "double";
        unlisted.emplace_back(joint.name, interface);
      }
    }
    return unlisted;
  }

  std::vector<hardware_interface::StateInterface::ConstSharedPtr>
  on_export_state_interfaces() override
  {
    auto exported = hardware_interface::SystemInterface::on_export_state_interfaces();
    state_links_.clear();
    slow_state_links_.clear();
    for (const auto * handles :
      {&joint_states_, &sensor_states_, &gpio_states_, &unlisted_states_})
    {
      for (const auto & handle : *handles) {
        const double * value = state_value(handle->get_prefix_name(), handle->get_interface_name());
        if (value != nullptr) {
          (slow_state_value(value) ? slow_state_links_ : state_links_).push_back(
            StateLink{handle.get(), value});
        }
      }
    }
    state_done_.assign(state_links_.size() + slow_state_links_.size(), 0U);
    return exported;
  }

  std::vector<hardware_interface::CommandInterface::SharedPtr>
  on_export_command_interfaces() override
  {
    auto exported = hardware_interface::SystemInterface::on_export_command_interfaces();
    command_links_.clear();
    for (const auto & handle : joint_commands_) {
      double * value = command_value(handle->get_prefix_name(), handle->get_interface_name());
      if (value != nullptr) {
        command_links_.push_back(CommandLink{handle.get(), value});
      }
    }
    claimed_links_.clear();
    claimed_links_.reserve(command_links_.size());  // select_command_values() never allocates
    fetched_.assign(command_links_.size(), 0.0);
    link_done_.assign(command_links_.size(), 0U);
    // GPIO commands (the e-stop) are fetched every cycle: a controller claiming one switches no
    // joint, so the joint claims never select it.
    gpio_command_links_.clear();
    for (const auto & handle : gpio_commands_) {
      double * value = command_value(handle->get_prefix_name(), handle->get_interface_name());
      if (value != nullptr) {
        gpio_command_links_.push_back(CommandLink{handle.get(), value});
      }
    }
    return exported;
  }
#else
  CallbackReturn on_init(const hardware_interface::HardwareInfo & info) override
  {
    if (hardware_interface::SystemInterface::on_init(info) != CallbackReturn::SUCCESS) {
      return CallbackReturn::ERROR;
    }
    return initialize(info_, logger_);
  }

  std::vector<hardware_interface::StateInterface> export_state_interfaces() override
  {
    std::vector<hardware_interface::StateInterface> exported;
    for (const auto * components : {&info_.joints, &info_.sensors, &info_.gpios}) {
      for (const auto & component : *components) {
        for (const auto & interface : component.state_interfaces) {
          double * value = state_value(component.name, interface.name);
          if (value != nullptr) {
            exported.emplace_back(component.name, interface.name, value);
          }
        }
      }
    }
    // Interfaces the description does not list (unlisted_state_names()): the ResourceManager
    // takes every exported interface and checks only that the listed ones are among them.
    for (const auto & joint : info_.joints) {
      for (const std::string & name : unlisted_state_names(joint)) {
        double * value = state_value(joint.name, name);
        if (value != nullptr) {
          exported.emplace_back(joint.name, name, value);
        }
      }
    }
    return exported;
  }

  std::vector<hardware_interface::CommandInterface> export_command_interfaces() override
  {
    std::vector<hardware_interface::CommandInterface> exported;
    for (const auto * components : {&info_.joints, &info_.gpios}) {
      for (const auto & component : *components) {
        for (const auto & interface : component.command_interfaces) {
          double * value = command_value(component.name, interface.name);
          if (value != nullptr) {
            exported.emplace_back(component.name, interface.name, value);
          }
        }
      }
    }
    return exported;
  }
#endif

protected:
  // `logger` is the logger ros2_control gives the component (its own one on Humble).
  explicit SystemInterfaceAdapter(const rclcpp::Logger & logger)
  : logger_(logger)
  {
  }

  // on_init, after ros2_control parsed the description into `info`.
  virtual CallbackReturn initialize(
    const hardware_interface::HardwareInfo & info, const rclcpp::Logger & logger) = 0;
  // The driver-owned double behind an interface, nullptr for one the driver does not provide.
  virtual double * state_value(const std::string & prefix, const std::string & name) = 0;
  virtual double * command_value(const std::string & prefix, const std::string & name) = 0;
  // State interfaces of joint `joint` the driver provides although the description does not list
  // them (found in the installed messages when it was compiled); none by default.
  virtual std::vector<std::string> unlisted_state_names(
    const hardware_interface::ComponentInfo & /*joint*/) const
  {
    return {};
  }
  // Whether the state double `value` changes only now and then (motor health): published by
  // publish_slow_state_values() when it changed, not by every read().
  virtual bool slow_state_value(const double * /*value*/) {return false;}

  // Controller thread, end of read(): state values out to the exported interfaces. A handle a
  // controller is reading refuses the write: it is written again once that read is over (a few
  // passes at most), so that the handles do not keep one joint of the previous frame.
  void publish_state_values()
  {
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
    publish_states(state_links_);
#endif
  }

  // Controller thread, in read() when the slow state values changed.
  void publish_slow_state_values()
  {
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
    publish_states(slow_state_links_);
#endif
  }

  // Controller thread, when the claims changed (a mode switch), before fetch_command_values():
  // from now on fetch only the command interfaces whose double `is_claimed(value)` says a
  // controller claims. A controller writes only what it claims, so an unclaimed handle holds
  // nothing to fetch, and reading it would cost its lock every cycle.
  template<typename IsClaimed>
  void select_command_values(IsClaimed is_claimed)
  {
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
    claimed_links_.clear();
    for (const CommandLink & link : command_links_) {
      if (is_claimed(static_cast<const double *>(link.value))) {
        claimed_links_.push_back(link);
      }
    }
#else
    static_cast<void>(is_claimed);  // the exported interfaces are the driver's doubles
#endif
  }

  // Controller thread, start of write(): what the controllers commanded, into the driver's doubles
  // (the claimed interfaces only, see select_command_values()). Whole or not at all: a handle a
  // controller is writing right now refuses the try-lock, and keeping the driver's previous value
  // for that joint alone would send a frame mixing two commands even when every handle holds the
  // same one. The refused handles are tried again; if one still refuses, the doubles keep the
  // previous command, whole, for this cycle, and false is returned.
  bool fetch_command_values()
  {
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
    const std::vector<CommandLink> & fetched_links = claimed_links_;
    const size_t refused = retry_refused(
      fetched_links.size(), link_done_, [this, &fetched_links](size_t i) {
        const std::optional<double> value = fetched_links[i].handle->get_optional();
        fetched_[i] = value.value_or(*fetched_links[i].value);
        return value.has_value();
      });
    for (const CommandLink & link : gpio_command_links_) {  // the e-stop: a value of its own
      const std::optional<double> value = link.handle->get_optional();
      if (value.has_value()) {
        *link.value = *value;
      }
    }
    if (refused != 0U) {
      return false;  // the previous command stays, whole
    }
    for (size_t i = 0; i < fetched_links.size(); ++i) {
      *fetched_links[i].value = fetched_[i];
    }
#endif
    return true;
  }

  // Controller thread: the driver rewrote its command doubles itself (safe start), so the
  // exported command interfaces must show the same values.
  void publish_command_values()
  {
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
    static_cast<void>(retry_refused(
      command_links_.size(), link_done_, [this](size_t i) {
        return command_links_[i].handle->set_value(*command_links_[i].value);
      }));
#endif
  }

private:
  rclcpp::Logger logger_;  // Humble only: later releases pass get_logger() to initialize()
#if ROBOT_HARDWARE_INTERFACE_FRAMEWORK_HANDLES
  struct StateLink
  {
    hardware_interface::StateInterface * handle;
    const double * value;
  };
  struct CommandLink
  {
    hardware_interface::CommandInterface * handle;
    double * value;
  };
  std::vector<StateLink> state_links_;
  std::vector<StateLink> slow_state_links_;  // published when they change (motor health)
  std::vector<CommandLink> command_links_;
  std::vector<CommandLink> claimed_links_;  // the command_links_ controllers claim
  std::vector<CommandLink> gpio_command_links_;  // fetched every cycle (the e-stop)
  std::vector<double> fetched_;     // fetch_command_values(): the claimed values, before they count
  std::vector<uint8_t> link_done_;  // retry_refused() over the command links
  std::vector<uint8_t> state_done_;  // retry_refused() over the state links

  // Passes over the handles that refused their try-lock (the first pass included).
  static constexpr unsigned kHandlePasses = 10U;

  // `attempt(i)` for every i < count, then again for those it returned false for, up to
  // kHandlePasses passes with a yield between them (`done`, sized at export, is the scratch).
  // Returns how many never succeeded.
  template<typename Attempt>
  static size_t retry_refused(size_t count, std::vector<uint8_t> & done, Attempt attempt)
  {
    size_t refused = count;
    for (unsigned pass = 0; pass < kHandlePasses && refused > 0U; ++pass) {
      if (pass > 0U) {
        std::this_thread::yield();
      }
      refused = 0U;
      for (size_t i = 0; i < count; ++i) {
        if (pass == 0U || done[i] == 0U) {
          done[i] = attempt(i) ? 1U : 0U;
        }
        refused += done[i] == 0U ? 1U : 0U;
      }
    }
    return refused;
  }

  void publish_states(const std::vector<StateLink> & links)
  {
    static_cast<void>(retry_refused(
      links.size(), state_done_, [&links](size_t i) {
        return links[i].handle->set_value(*links[i].value);
      }));
  }
#endif
};

// Tests: a ResourceManager loading `urdf` the way this release's controller manager does. A
// template, so that drivers including this header do not pull in the ResourceManager.
template<typename ResourceManager>
std::unique_ptr<ResourceManager> make_resource_manager(const std::string & urdf)
{
#if ROBOT_HARDWARE_INTERFACE_RESOURCE_MANAGER_CLOCK
  return std::make_unique<ResourceManager>(
    urdf, std::make_shared<rclcpp::Clock>(RCL_STEADY_TIME),
    rclcpp::get_logger("robot_hardware_interface_test"));
#else
  return std::make_unique<ResourceManager>(urdf);  // validate_interfaces = true
#endif
}

// Tests: whether every component of `resource_manager` initialised (Humble's constructor throws
// instead).
template<typename ResourceManager>
bool components_initialized(const ResourceManager & resource_manager)
{
#if ROBOT_HARDWARE_INTERFACE_RESOURCE_MANAGER_CLOCK
  return resource_manager.are_components_initialized();
#else
  static_cast<void>(resource_manager);
  return true;
#endif
}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__ROS2_CONTROL_COMPAT_HPP_
