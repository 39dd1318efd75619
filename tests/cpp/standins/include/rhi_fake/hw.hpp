// rhi-gen test hooks (test code only): one way to drive a hardware_interface::SystemInterface
// plugin on every distro, so one harness source compiles and runs against each distro's stand-ins.
//
//   rhi_fake::hw::Framework fw;                        // clock, logger, executor (4.x+)
//   fw.init(*hw, info);                                // Humble: on_init(info)
//                                                      // 4.x+: init(params) -> on_init(params)
//   rhi_fake::hw::Exported ifs = rhi_fake::hw::export_interfaces(*hw);
//   const rhi_fake::hw::StateRef * p = ifs.state("joint1", "position");
//   double q = p->get();                               // Humble get_value(); 4.x+ handle value
//   ifs.command("joint1", "position")->set(0.5);       // Humble set_value(); 4.x+ set_value()
//
// Exporting follows the framework: Humble calls export_*_interfaces(); 4.x+ calls the deprecated
// export_*_interfaces() first and on_export_*_interfaces() when it returns nothing (what
// upstream's HardwareComponent does). get()/set() wait for a 4.x+ handle's lock (like the
// framework's non-real-time accessors); try_get()/try_set() only try it (nullopt / false while
// another thread holds it). The export order is the driver's (upstream does not specify it).
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "hardware_interface/hardware_info.hpp"
#include "hardware_interface/system_interface.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rhi_fake/detail/distro.hpp"

namespace rhi_fake {
namespace hw {

/// hardware_interface major version of the stand-ins this was compiled against (2, 4, 5, 6).
constexpr int kMajor = RHI_FAKE_HI_MAJOR;

/// The description's <plugin>: Humble's hardware_class_type, 4.x+'s hardware_plugin_name.
inline const std::string & plugin_name(const hardware_interface::HardwareInfo & info)
{
#if RHI_FAKE_HI_MAJOR < 3
  return info.hardware_class_type;
#else
  return info.hardware_plugin_name;
#endif
}

inline void set_plugin_name(hardware_interface::HardwareInfo & info, const std::string & name)
{
#if RHI_FAKE_HI_MAJOR < 3
  info.hardware_class_type = name;
#else
  info.hardware_plugin_name = name;
#endif
}

/// What the controller manager gives a component: a clock, a logger and (4.x+) an executor the
/// component's node is added to. The executor is not spun unless the test spins it.
class Framework
{
public:
  Framework()
  : clock_(std::make_shared<rclcpp::Clock>(RCL_ROS_TIME)),
    logger_(rclcpp::get_logger("resource_manager")),
    executor_(std::make_shared<rclcpp::executors::SingleThreadedExecutor>())
  {
  }

  /// Initialise `hw` from `info` the way the distro's framework does.
  hardware_interface::CallbackReturn init(
    hardware_interface::SystemInterface & hw, const hardware_interface::HardwareInfo & info)
  {
#if RHI_FAKE_HI_MAJOR < 3
    return hw.on_init(info);
#else
    hardware_interface::HardwareComponentParams params;
    params.hardware_info = info;
    params.clock = clock_;
    params.logger = logger_.get_child("hardware_component." + info.type + "." + info.name);
    params.executor = executor_;
    return hw.init(params);
#endif
  }

  const rclcpp::Clock::SharedPtr & clock() const {return clock_;}
  const std::shared_ptr<rclcpp::Executor> & executor() const {return executor_;}

private:
  rclcpp::Clock::SharedPtr clock_;
  rclcpp::Logger logger_;
  std::shared_ptr<rclcpp::Executor> executor_;
};

#if RHI_FAKE_HI_MAJOR < 3
using StateHandle = const hardware_interface::StateInterface *;
using CommandHandle = hardware_interface::CommandInterface *;
#else
using StateHandle = hardware_interface::StateInterface::ConstSharedPtr;
using CommandHandle = hardware_interface::CommandInterface::SharedPtr;
#endif

/// One exported state interface.
class StateRef
{
public:
  explicit StateRef(StateHandle h)
  : h_(std::move(h)) {}

  const std::string & prefix() const {return h_->get_prefix_name();}
  const std::string & interface() const {return h_->get_interface_name();}
  std::string name() const {return h_->get_name();}

  /// The value (waits for a 4.x+ handle's lock). Throws if the handle has no double.
  double get() const
  {
#if RHI_FAKE_HI_MAJOR < 3
    return h_->get_value();
#else
    double v = std::numeric_limits<double>::quiet_NaN();
    std::ignore = h_->get_value(v, true);
    return v;
#endif
  }

  /// The value, or nullopt while another thread holds the handle's lock (Humble: always a value).
  std::optional<double> try_get() const
  {
#if RHI_FAKE_HI_MAJOR < 3
    return h_->get_value();
#else
    return h_->get_optional();
#endif
  }

  const StateHandle & handle() const {return h_;}

private:
  StateHandle h_;
};

/// One exported command interface.
class CommandRef
{
public:
  explicit CommandRef(CommandHandle h)
  : h_(std::move(h)) {}

  const std::string & prefix() const {return h_->get_prefix_name();}
  const std::string & interface() const {return h_->get_interface_name();}
  std::string name() const {return h_->get_name();}

  double get() const
  {
#if RHI_FAKE_HI_MAJOR < 3
    return h_->get_value();
#else
    double v = std::numeric_limits<double>::quiet_NaN();
    std::ignore = h_->get_value(v, true);
    return v;
#endif
  }

  std::optional<double> try_get() const
  {
#if RHI_FAKE_HI_MAJOR < 3
    return h_->get_value();
#else
    return h_->get_optional();
#endif
  }

  /// Writes `value` (waits for a 4.x+ handle's lock).
  void set(double value) const
  {
#if RHI_FAKE_HI_MAJOR < 3
    h_->set_value(value);
#else
    std::ignore = h_->set_value(value, true);
#endif
  }

  /// Writes `value` unless another thread holds the lock (then false; Humble: always true).
  bool try_set(double value) const
  {
#if RHI_FAKE_HI_MAJOR < 3
    h_->set_value(value);
    return true;
#else
    return h_->set_value(value);
#endif
  }

  const CommandHandle & handle() const {return h_;}

private:
  CommandHandle h_;
};

/// Everything a component exported; owns the interfaces (Humble) or shares them (4.x+).
/// Movable, not copyable: refs stay valid when it moves.
class Exported
{
public:
  Exported() = default;
  Exported(const Exported &) = delete;
  Exported & operator=(const Exported &) = delete;
  Exported(Exported &&) = default;
  Exported & operator=(Exported &&) = default;

  const std::vector<StateRef> & states() const {return state_refs_;}
  const std::vector<CommandRef> & commands() const {return command_refs_;}

  /// The state interface "<prefix>/<interface>", or nullptr.
  const StateRef * state(const std::string & prefix, const std::string & interface) const
  {
    for (const auto & s : state_refs_) {
      if (s.prefix() == prefix && s.interface() == interface) {return &s;}
    }
    return nullptr;
  }

  const CommandRef * command(const std::string & prefix, const std::string & interface) const
  {
    for (const auto & c : command_refs_) {
      if (c.prefix() == prefix && c.interface() == interface) {return &c;}
    }
    return nullptr;
  }

private:
  friend Exported export_interfaces(hardware_interface::SystemInterface & hw);

#if RHI_FAKE_HI_MAJOR < 3
  std::vector<hardware_interface::StateInterface> states_;
  std::vector<hardware_interface::CommandInterface> commands_;
#endif
  std::vector<StateRef> state_refs_;
  std::vector<CommandRef> command_refs_;
};

/// Exports the component's interfaces the way the distro's framework does.
inline Exported export_interfaces(hardware_interface::SystemInterface & hw)
{
  Exported out;
#if RHI_FAKE_HI_MAJOR < 3
  out.states_ = hw.export_state_interfaces();
  out.commands_ = hw.export_command_interfaces();
  for (const auto & s : out.states_) {out.state_refs_.emplace_back(&s);}
  for (auto & c : out.commands_) {out.command_refs_.emplace_back(&c);}
#else
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  std::vector<hardware_interface::StateInterface> old_states = hw.export_state_interfaces();
  std::vector<hardware_interface::CommandInterface> old_commands = hw.export_command_interfaces();
#pragma GCC diagnostic pop
  if (old_states.empty()) {
    for (auto & s : hw.on_export_state_interfaces()) {out.state_refs_.emplace_back(s);}
  } else {
    for (const auto & s : old_states) {
      out.state_refs_.emplace_back(std::make_shared<const hardware_interface::StateInterface>(s));
    }
  }
  if (old_commands.empty()) {
    for (auto & c : hw.on_export_command_interfaces()) {out.command_refs_.emplace_back(c);}
  } else {
    for (auto & c : old_commands) {
      out.command_refs_.emplace_back(std::make_shared<hardware_interface::CommandInterface>(std::move(c)));
    }
  }
#endif
  return out;
}

}  // namespace hw
}  // namespace rhi_fake
