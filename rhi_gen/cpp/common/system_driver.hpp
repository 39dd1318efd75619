// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__SYSTEM_DRIVER_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__SYSTEM_DRIVER_HPP_

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <hardware_interface/hardware_info.hpp>
#include <rclcpp/duration.hpp>
#include <rclcpp/logging.hpp>
#include <rclcpp/macros.hpp>
#include <rclcpp/node.hpp>
#include <rclcpp/publisher.hpp>
#include <rclcpp/qos.hpp>
#include <rclcpp/time.hpp>
#include <rclcpp_lifecycle/state.hpp>

#include "robot_hardware_interface/common/driver_core.hpp"
#include "robot_hardware_interface/common/driver_diagnostics.hpp"
#include "robot_hardware_interface/common/ros2_control_compat.hpp"
#include "robot_hardware_interface/common/robot_spec.hpp"
#include "robot_hardware_interface/common/types.hpp"

namespace robot_hardware_interface
{

// The SDK or topic side of a driver. Transports live in transport/<name>.hpp; a robot's source
// file picks one and passes it its options.
template<size_t N, typename T>
class DriverTransport
{
public:
  virtual ~DriverTransport() = default;
  // Name for log lines, e.g. "unitree_dds".
  virtual const char * name() const = 0;
  // on_init, after the parameters: open channels, pre-size every message, subscribe (state may
  // flow from here on). `node` is the driver's node. Return false after logging why; may throw.
  virtual bool configure(DriverCore<N, T> & core, const rclcpp::Node::SharedPtr & node) = 0;
  // on_activate: start sending (command writer thread or executor). May throw.
  virtual bool start() = 0;
  // on_deactivate: stop sending and join the transport's threads.
  virtual void stop() = 0;
  // Destruction: stop everything that could still call into the driver. Must not throw.
  virtual void shutdown() noexcept = 0;
  // Whether stiffness and damping reach the robot (otherwise no gain interfaces are exported).
  virtual bool carries_gains() const {return true;}
  // The MotorHealthField bits the robot's state carries (DriverCore::publish_motor_health()).
  virtual uint8_t motor_health() const {return 0U;}
  // Those of them the generated description cannot list because they were found in the vendor's
  // installed messages when the driver was compiled (a message package with two releases): their
  // interfaces are exported for every joint of the description that does not list them.
  virtual uint8_t detected_motor_health() const {return 0U;}
  // Why no motor error code travels, for the refusal of a motor_error_fault_mask.
  virtual const char * no_error_codes_reason() const {return "its messages carry none";}
};

// The ros2_control face of every driver: SystemInterface lifecycle and read()/write() around a
// DriverCore (the logic) and a DriverTransport (the SDK). A robot's class derives from it and
// only passes its RobotSpec (joint table, limits, defaults) and its transport.
template<size_t N, typename T>
class SystemDriver : public SystemInterfaceAdapter
{
public:
  SystemDriver(const SystemDriver &) = delete;
  SystemDriver & operator=(const SystemDriver &) = delete;

  ~SystemDriver() override
  {
    // The transport's threads would otherwise keep calling into a destroyed object.
    diagnostics_thread_.stop();
    transport_->shutdown();
  }

  // Calibration without a rebuild: the `calibration_file` hardware parameter, read here so that
  // cleanup + configure picks up a re-zeroed motor. A bad file refuses the configuration (FAILURE:
  // the component stays unconfigured, fix the file and configure again) with one error line.
  CallbackReturn on_configure(const rclcpp_lifecycle::State & /*previous_state*/) override
  {
    if (claims_lost_.exchange(false, std::memory_order_acq_rel)) {
      core_.claims().release_all();
    }
    const std::string problem = core_.calibrate(calibration_file_);
    if (!problem.empty()) {
      RCLCPP_ERROR(core_.logger(), "%s", problem.c_str());
      return CallbackReturn::FAILURE;
    }
    return CallbackReturn::SUCCESS;
  }

  CallbackReturn on_activate(const rclcpp_lifecycle::State & /*previous_state*/) override
  {
    // After on_error the transport still sends the hold: stop it (a no-op when it is stopped)
    // before the safe start is re-armed, which needs every transport thread stopped.
    transport_->stop();
    core_.reset_for_activation();
    link_dead_reported_ = false;
    motor_fault_reported_ = false;
    faulty_slot_ = -1;  // the next motor health frame says again
    const CallbackReturn user = on_activate_hook();
    if (user != CallbackReturn::SUCCESS) {
      return user;
    }
    try {
      if (!transport_->start()) {
        transport_->stop();
        return CallbackReturn::ERROR;
      }
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_.logger(), "starting the %s transport failed: %s", transport_->name(),
        e.what());
      transport_->stop();
      return CallbackReturn::ERROR;
    }
    active_.store(true, std::memory_order_relaxed);
    RCLCPP_INFO(core_.logger(), "activated: commands start after the first valid state");
    if (estop_pressed(core_.health().estop_command)) {
      RCLCPP_WARN(
        core_.logger(), "the e-stop is still pressed (%s/%s): every joint stays damping-only; "
        "release it and activate again", health_gpio_.c_str(), kEstopCommandInterface);
    }
    const size_t limp = core_.slots().joints_without_default_stiffness();
    if (limp > 0) {
      RCLCPP_WARN(
        core_.logger(),
        "%zu position-commanded joint(s) have no default stiffness (default_gains of "
        "the vendor YAML): a controller that claims only their position leaves them limp", limp);
    }
    return CallbackReturn::SUCCESS;
  }

  CallbackReturn on_deactivate(const rclcpp_lifecycle::State & /*previous_state*/) override
  {
    active_.store(false, std::memory_order_relaxed);
    transport_->stop();
    on_deactivate_hook();
    RCLCPP_INFO(core_.logger(), "deactivated: the %s transport stopped sending",
      transport_->name());
    return CallbackReturn::SUCCESS;
  }

  // read() returned ERROR (the link is dead) or a transition failed: ros2_control stops the
  // controllers and leaves the component unconfigured. The transport keeps running so that the
  // command writer keeps sending the damping-only hold (kp = 0, the last safe position target),
  // even if the state comes back, until on_activate restarts it through the full safe start.
  // ros2_control 3.1+ also deactivates every controller that used the component, without telling it
  // (ROBOT_HARDWARE_INTERFACE_ERROR_STOPS_CONTROLLERS): the claims go with them at the next
  // on_configure (CommandClaims::release_all()), which the recovery passes through. On Humble the
  // controllers keep running, and their claims stay.
  CallbackReturn on_error(const rclcpp_lifecycle::State & /*previous_state*/) override
  {
    active_.store(false, std::memory_order_relaxed);
    claims_lost_.store(
      ROBOT_HARDWARE_INTERFACE_ERROR_STOPS_CONTROLLERS != 0, std::memory_order_release);
    core_.hold_until_activation();
    RCLCPP_ERROR(
      core_.logger(), "in error: the %s transport keeps sending damping only (kp = 0) to every "
      "joint; once the robot answers again, configure and activate the component",
      transport_->name());
    return CallbackReturn::SUCCESS;
  }

  // The controller manager switches controllers: claimed command interfaces count, unclaimed
  // gains fall back to the joint's default (see DriverCore::write_command()).
  return_type prepare_command_mode_switch(
    const std::vector<std::string> & start_interfaces,
    const std::vector<std::string> & stop_interfaces) override
  {
    core_.claims().prepare_claims(start_interfaces, stop_interfaces);
    return return_type::OK;
  }

  return_type perform_command_mode_switch(
    const std::vector<std::string> & /*start_interfaces*/,
    const std::vector<std::string> & /*stop_interfaces*/) override
  {
    core_.claims().commit_claims();
    return return_type::OK;
  }

  return_type read(const rclcpp::Time & /*time*/, const rclcpp::Duration & /*period*/) override
  {
    const auto start = std::chrono::steady_clock::now();
    const int64_t now_ns = steady_ns(start);
    core_.read_state();
    if (motor_health_ != 0U && core_.read_motor_health()) {
      faulty_slot_ = faulty_motor_slot();
      publish_slow_state_values();
    }
    // Only an active component faults: ros2_control also reads an inactive one, and a robot that
    // is configured but not yet started may well be silent (or cooling down).
    const int64_t silence_ns = core_.silence_ns(now_ns);  // once: the fault and the GPIO
    const bool active = active_.load(std::memory_order_relaxed);
    const bool link_dead = active && core_.link_dead(silence_ns);
    const bool motor_fault = active && faulty_slot_ >= 0;
    core_.read_health(silence_ns, link_dead || motor_fault);
    publish_state_values();
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(link_dead)) {
      return report_dead_link();
    }
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(motor_fault)) {
      return report_motor_fault();
    }
    core_.monitor().check_read_latency(start);
    return return_type::OK;
  }

  return_type write(const rclcpp::Time & /*time*/, const rclcpp::Duration & /*period*/) override
  {
    const auto start = std::chrono::steady_clock::now();
    // Claims a mode switch committed: write_command() resets the joints whose claims changed (the
    // switch cycle sends the safe-start target), and from now on only the claimed interfaces are
    // fetched (once per switch, never in the steady cycle; a no-op on Humble).
    CommandClaims<N, T> & claims = core_.claims();
    if (claims.take_committed()) {
      const JointStorage<N> & joints = core_.joints();
      select_command_values(
        [&claims, &joints](const double * value) {return claims.claims_value(joints, value);});
    }
    fetch_command_values();
    if (ROBOT_HARDWARE_INTERFACE_UNLIKELY(estop_pressed(core_.health().estop_command))) {
      press_estop();
    }
    if (core_.write_command()) {
      publish_command_values();
    }
    core_.command_written();
    core_.monitor().check_write_latency(start);
    return return_type::OK;
  }

protected:
  // `transmission`: the robot's motors that are not joints (nullptr: every motor is its joint).
  SystemDriver(
    const RobotSpec & spec, std::unique_ptr<DriverTransport<N, T>> transport,
    const TransmissionSpec * transmission = nullptr)
  : SystemInterfaceAdapter(rclcpp::get_logger(spec.node_name)),
    core_(spec, transmission), transport_(std::move(transport))
  {
  }

  // Customisation points for hand-written code: declare the override in the robot header's
  // `members` user region and define it in the source's `callbacks` region.
  // After the parameters, before the transport is set up; `info` is the parsed description.
  virtual CallbackReturn on_init_hook(const hardware_interface::HardwareInfo & /*info*/)
  {
    return CallbackReturn::SUCCESS;
  }
  // Before the transport starts sending; anything but SUCCESS refuses the activation.
  virtual CallbackReturn on_activate_hook() {return CallbackReturn::SUCCESS;}
  // After the transport stopped sending.
  virtual void on_deactivate_hook() {}

  // The SDK motor slot of a URDF joint, -1 for a joint this driver does not drive.
  int get_joint_index(const std::string & name) const {return core_.slots().slot_of(name);}
  DriverCore<N, T> & core() {return core_;}
  const rclcpp::Logger & logger() const {return core_.logger();}

  // <robot>_hardware_interface: spun by topic transports, free for hand-written code.
  rclcpp::Node::SharedPtr node_;

private:
  // write() with the e-stop pressed: the hold latches until the next activation, said once.
  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE void press_estop()
  {
    if (core_.press_estop()) {
      RCLCPP_ERROR(
        core_.logger(), "e-stop (%s/%s): every joint held damping-only (kp = 0, the last safe "
        "target, no feed-forward) until the e-stop is released and the component is activated "
        "again (ros2 control set_hardware_component_state %s inactive, then active)",
        health_gpio_.c_str(), kEstopCommandInterface, hardware_name_.c_str());
    }
  }

#if ROBOT_HARDWARE_INTERFACE_HARDWARE_STATUS
  // ros2_control's ~/hardware_status (5.10+, when status_publish_rate is set): one device, the
  // robot, whose one state is the driver's health. init() calls this before on_init, with info_
  // already parsed. Filled from HealthFacts (atomics) into strings reserved here, so the update
  // allocates nothing, whichever thread the framework calls it from.
  CallbackReturn init_hardware_status_message(control_msgs::msg::HardwareStatus & msg) override
  {
    const std::string & hardware_name = info_.name;
    msg.hardware_id = hardware_name;
    msg.hardware_device_states.resize(1);
    control_msgs::msg::HardwareDeviceStatus & device = msg.hardware_device_states.front();
    device.device_id = hardware_name;
    device.hardware_status.resize(1);
    control_msgs::msg::GenericHardwareState & state = device.hardware_status.front();
    state.error_domain.reserve(2);
    state.state_details.resize(kStatusDetails.size());
    for (size_t i = 0; i < kStatusDetails.size(); ++i) {
      state.state_details[i].key = kStatusDetails[i];
      state.state_details[i].value.reserve(32);
    }
    return CallbackReturn::SUCCESS;
  }

  return_type update_hardware_status_message(control_msgs::msg::HardwareStatus & msg) override
  {
    using State = control_msgs::msg::GenericHardwareState;
    if (msg.hardware_device_states.size() != 1 ||
      msg.hardware_device_states.front().hardware_status.size() != 1)
    {
      return return_type::ERROR;
    }
    State & state = msg.hardware_device_states.front().hardware_status.front();
    const HealthFacts facts = core_.health_facts(
      steady_now_ns(), active_.load(std::memory_order_relaxed));
    const DriverParameters & p = core_.parameters();
    const bool dead = facts.link_dead(p.fault_timeout_ms, p.first_state_timeout_ms);
    const bool stale = facts.no_state() || facts.stale(p.state_timeout_ms);
    state.health_status = facts.estop || facts.error_hold || dead ? State::HEALTH_ERROR :
      stale ? State::HEALTH_WARNING : State::HEALTH_OK;
    state.error_domain.clear();
    if (facts.estop) {
      state.error_domain.push_back(State::EMERGENCY_STOP_SW);
    }
    if (dead) {
      state.error_domain.push_back(State::ERROR_HW);
    }
    const double values[] = {
      facts.age_ms(), static_cast<double>(facts.invalid_states),
      static_cast<double>(facts.stale_holds), static_cast<double>(facts.rejected_commands),
      static_cast<double>(facts.writer_overruns), facts.estop ? 1.0 : 0.0};
    for (size_t i = 0; i < kStatusDetails.size() && i < state.state_details.size(); ++i) {
      char text[32];
      std::snprintf(text, sizeof(text), "%.1f", values[i]);
      state.state_details[i].value.assign(text);
    }
    return return_type::OK;
  }

  static constexpr std::array<const char *, 6> kStatusDetails = {
    "state_age_ms", "invalid_states", "stale_holds", "rejected_commands", "writer_overruns",
    "estop"};
#endif

  // /diagnostics (diagnostic_msgs/DiagnosticArray) every diagnostics_period_ms from its own
  // thread: "<hardware>: link", "<hardware>: safety" and, where the state carries motor health,
  // one per motor group ("<hardware>: left leg motors", RobotSpec::motor_groups). Reads only
  // atomics and its own buffer (HealthFacts): the hot paths never wait for it, and it may allocate.
  bool start_diagnostics()
  {
    const DriverParameters & p = core_.parameters();
    if (p.diagnostics_period_ms == 0) {
      return true;
    }
    try {
      diagnostics_publisher_ = node_->create_publisher<diagnostic_msgs::msg::DiagnosticArray>(
        "/diagnostics", rclcpp::QoS(10));
    } catch (const std::exception & e) {
      RCLCPP_ERROR(core_.logger(), "creating the /diagnostics publisher failed: %s", e.what());
      return false;
    }
    const std::string prefix = hardware_name_ + ": ";
    const RobotSpec & spec = core_.spec();
    size_t groups = 0;
    const bool motors = motor_health_ != 0U;
    while (motors && groups < kMaxMotorGroups && spec.motor_groups[groups] != nullptr) {
      ++groups;
    }
    diagnostics_message_.status.resize(2 + groups);
    diagnostics_message_.status[0].name = prefix + "link";
    diagnostics_message_.status[1].name = prefix + "safety";
    for (size_t g = 0; g < groups; ++g) {
      diagnostics_message_.status[2 + g].name = prefix + spec.motor_groups[g];
    }
    for (auto & status : diagnostics_message_.status) {
      status.hardware_id = hardware_name_;
    }
    diagnostics_limits_ = DiagnosticsLimits{
      p.state_timeout_ms, p.fault_timeout_ms, p.first_state_timeout_ms,
      static_cast<double>(p.motor_temperature_warn_c),
      static_cast<double>(p.motor_temperature_error_c), p.motor_error_fault_mask};
    diagnostics_thread_.start(
      std::chrono::milliseconds(p.diagnostics_period_ms), [this]() {publish_diagnostics();});
    return true;
  }

  void publish_diagnostics()
  {
    const HealthFacts facts = core_.health_facts(
      steady_now_ns(), active_.load(std::memory_order_relaxed));
    for (auto & status : diagnostics_message_.status) {
      status.values.clear();
    }
    DriverDiagnostics::describe_link(
      diagnostics_message_.status[0], facts, previous_facts_, diagnostics_limits_);
    DriverDiagnostics::describe_safety(diagnostics_message_.status[1], facts, previous_facts_);
    previous_facts_ = facts;
    const MotorHealthFrame<N> * frame =
      motor_health_ != 0U ? core_.diagnostics_motor_health() : nullptr;
    for (size_t i = 2; i < diagnostics_message_.status.size(); ++i) {
      if (frame != nullptr) {
        DriverDiagnostics::describe_motors(
          diagnostics_message_.status[i], *frame, core_.spec(), i - 2, motor_health_,
          diagnostics_limits_);
      } else {
        DriverDiagnostics::set(
          diagnostics_message_.status[i], diagnostic_msgs::msg::DiagnosticStatus::WARN,
          "no motor health from the robot yet");
      }
    }
    diagnostics_message_.header.stamp = node_->now();
    diagnostics_publisher_->publish(diagnostics_message_);
  }

  // Whether the motor of `slot` is at or above motor_temperature_error_c (where the state carries
  // temperatures).
  bool motor_too_hot(size_t slot) const
  {
    return (motor_health_ & kMotorTemperature) != 0U &&
           core_.motor_health().temperature[slot] >=
           static_cast<double>(core_.parameters().motor_temperature_error_c);
  }

  // Whether the motor of `slot` reports an error code with a bit of motor_error_fault_mask (where
  // the state carries error codes; the mask is 0, nothing faults, unless the vendor YAML sets it).
  bool motor_in_error(size_t slot) const
  {
    return (motor_health_ & kMotorErrorCode) != 0U &&
           (motor_error_bits(core_.motor_health().error_code[slot]) &
           core_.parameters().motor_error_fault_mask) != 0U;
  }

  // Whether the robot reports the motor of `slot` offline (where the state says so).
  bool motor_offline(size_t slot) const
  {
    return (motor_health_ & kMotorOffline) != 0U && core_.motor_health().offline[slot];
  }

  // read(), on a new motor health frame: the first driven slot offline, too hot or in error, -1
  // for none.
  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE int faulty_motor_slot()
  {
    for (const size_t slot : core_.slots().mapped_slots()) {
      if (motor_offline(slot) || motor_too_hot(slot) || motor_in_error(slot)) {
        return static_cast<int>(slot);
      }
    }
    return -1;
  }

  // read() of an active robot with a motor offline, too hot or in error: ERROR (ros2_control
  // stops the controllers and on_error holds every joint damping-only), said once per activation.
  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE return_type report_motor_fault()
  {
    if (motor_fault_reported_) {
      return return_type::ERROR;
    }
    motor_fault_reported_ = true;
    const auto slot = static_cast<size_t>(faulty_slot_);
    const char * joint = core_.slots().slot_joint_names()[slot];
    if (motor_offline(slot)) {
      RCLCPP_ERROR(
        core_.logger(), "motor offline: the robot reports %s (SDK slot %zu) offline: read() "
        "returns ERROR, ros2_control stops the controllers and the joints are held damping-only. "
        "Check the motor's power and cable, then %s", joint, slot, recovery_hint().c_str());
      return return_type::ERROR;
    }
    if (!motor_too_hot(slot)) {
      RCLCPP_ERROR(
        core_.logger(), "motor error: %s (SDK slot %zu) reports error code 0x%" PRIX64 ", a bit of "
        "motor_error_fault_mask 0x%" PRIX64 ": read() returns ERROR, ros2_control stops the "
        "controllers and the joints are held damping-only. Clear the motor's error (the vendor's "
        "tools), then %s", joint, slot, motor_error_bits(core_.motor_health().error_code[slot]),
        core_.parameters().motor_error_fault_mask, recovery_hint().c_str());
      return return_type::ERROR;
    }
    RCLCPP_ERROR(
      core_.logger(), "motor too hot: %s (SDK slot %zu) at %.1f C, motor_temperature_error_c is "
      "%" PRIu64 ": read() returns ERROR, ros2_control stops the controllers and the joints are "
      "held damping-only. Let the motor cool, then %s", joint, slot,
      core_.motor_health().temperature[slot], core_.parameters().motor_temperature_error_c,
      recovery_hint().c_str());
    return return_type::ERROR;
  }

  // read() of a dead link: ERROR, said once per activation (read() runs at the control rate).
  // A robot that never answered since the activation is told apart from a link that died.
  ROBOT_HARDWARE_INTERFACE_OUT_OF_LINE return_type report_dead_link()
  {
    if (link_dead_reported_) {
      return return_type::ERROR;
    }
    link_dead_reported_ = true;
    const DriverParameters & p = core_.parameters();
    const std::string recovery = recovery_hint();
    if (!core_.first_state_received()) {
      RCLCPP_ERROR(
        core_.logger(), "the robot never answered: no valid state in the %" PRIu64 " ms since "
        "activation (first_state_timeout_ms; %" PRIu64 " invalid state frames): read() returns "
        "ERROR, ros2_control stops the controllers; nothing was sent to the robot. Check that the "
        "robot runs and is reachable (network_interface '%s', ROS_DOMAIN_ID), then %s",
        std::max(p.first_state_timeout_ms, p.fault_timeout_ms),
        core_.health_facts(steady_now_ns(), true).invalid_states, p.network_interface.c_str(),
        recovery.c_str());
      return return_type::ERROR;
    }
    RCLCPP_ERROR(
      core_.logger(), "link lost: no valid state from the robot for more than %" PRIu64 " ms "
      "(fault_timeout_ms; held damping-only since state_timeout_ms = %" PRIu64 " ms): read() "
      "returns ERROR, ros2_control stops the controllers. Check the robot's power and network, "
      "then %s", p.fault_timeout_ms, p.state_timeout_ms, recovery.c_str());
    return return_type::ERROR;
  }

  // What the operator runs after a fault: the component active again (configure + activate, the
  // full safe start), then the controllers ros2_control stopped with it, broadcasters included.
  std::string recovery_hint() const
  {
    std::string hint = "set the component active again (ros2 control "
      "set_hardware_component_state " + hardware_name_ + " active)";
    const char * controllers = core_.spec().launch_controllers;
    if (controllers != nullptr && controllers[0] != '\0') {
      hint += " and activate its controllers again (ros2 control switch_controllers --activate ";
      hint += controllers;
      hint += ": those the package's launch file starts, or the ones you ran)";
    }
    return hint;
  }

  CallbackReturn initialize(
    const hardware_interface::HardwareInfo & info, const rclcpp::Logger & logger) override
  {
    core_.monitor().set_logger(logger);
    const rclcpp::Logger & log = core_.logger();
    hardware_name_ = info.name;
    motor_health_ = transport_->motor_health();
    health_gpio_ = info.gpios.empty() ? info.name + "_health" : info.gpios.front().name;
    if (!read_driver_parameters(log, info.hardware_parameters, core_.parameters()) ||
      !error_codes_travel() || !description_is_driven(info))
    {
      return CallbackReturn::ERROR;
    }
    if (!core_.transmissions().error().empty()) {
      RCLCPP_ERROR(log, "%s", core_.transmissions().error().c_str());
      return CallbackReturn::ERROR;
    }
    const auto calibration = info.hardware_parameters.find("calibration_file");
    calibration_file_ = calibration == info.hardware_parameters.end() ?
      std::string() : std::string(trimmed(calibration->second));
    const CallbackReturn user = on_init_hook(info);
    if (user != CallbackReturn::SUCCESS) {
      return user;
    }
    // SDK and rclcpp calls may throw (bad topic name, network interface, ...): report, never
    // propagate.
    try {
      node_ = std::make_shared<rclcpp::Node>(core_.spec().node_name);
      if (!transport_->configure(core_, node_)) {
        return CallbackReturn::ERROR;
      }
    } catch (const std::exception & e) {
      RCLCPP_ERROR(log, "setting up the %s transport failed: %s", transport_->name(), e.what());
      return CallbackReturn::ERROR;
    }
    if (!start_diagnostics()) {
      return CallbackReturn::ERROR;
    }
    const DriverParameters & p = core_.parameters();
    RCLCPP_INFO(
      log, "initialized: %zu joints, command period %" PRIu64 " us (%s), state decimation %u, "
      "state timeout %" PRIu64 " ms, fault timeout %" PRIu64 " ms, monitor %s",
      core_.spec().joint_count, p.command_writer_period_us,
      p.command_writer_mode == CommandWriterMode::kOnWrite ? "sent on write()" : "timer",
      p.state_decimation, p.state_timeout_ms, p.fault_timeout_ms, p.enable_monitor ? "on" : "off");
    return CallbackReturn::SUCCESS;
  }

  // A motor_error_fault_mask needs error codes: refused (one line) where the messages this driver
  // was compiled against carry none, rather than never faulting.
  bool error_codes_travel() const
  {
    const uint64_t mask = core_.parameters().motor_error_fault_mask;
    if (mask == 0U || (motor_health_ & kMotorErrorCode) != 0U) {
      return true;
    }
    RCLCPP_ERROR(
      core_.logger(), "parameter motor_error_fault_mask 0x%" PRIX64 ": the %s state this driver "
      "was built with carries no motor error codes (%s), so no code can fault a motor; set it to "
      "0 (vendor YAML parameters.motor_error_fault_mask, or the <param> of the description)", mask,
      transport_->name(), transport_->no_error_codes_reason());
    return false;
  }

  // Interfaces of the motor health the transport found in the installed messages
  // (detected_motor_health()) that joint `joint` of the description does not list: exported
  // beyond the description, so the same description serves either release of the messages.
  std::vector<std::string> unlisted_state_names(
    const hardware_interface::ComponentInfo & joint) const override
  {
    std::vector<std::string> names;
    const uint8_t detected = transport_->detected_motor_health();
    if (detected == 0U || core_.slots().slot_of(joint.name) < 0) {
      return names;
    }
    for (const MotorHealthInterface & interface : kMotorHealthInterfaces) {
      if ((detected & interface.field) == 0U) {
        continue;
      }
      bool listed = false;
      for (const auto & described : joint.state_interfaces) {
        listed = listed || described.name == interface.name;
      }
      if (!listed) {
        names.emplace_back(interface.name);
      }
    }
    return names;
  }

  // Every joint, interface and sensor of the description must be one this driver drives: a typo
  // would otherwise only surface later, as an interface nobody updates. A driven joint missing
  // from the description gets no interfaces and keeps zero gains (passive).
  bool description_is_driven(const hardware_interface::HardwareInfo & info)
  {
    const rclcpp::Logger & log = core_.logger();
    for (const auto & joint : info.joints) {
      if (core_.slots().slot_of(joint.name) < 0) {
        RCLCPP_ERROR(
          log, "joint '%s' of the ros2_control description is not driven by %s",
          joint.name.c_str(), core_.spec().plugin_name);
        return false;
      }
      for (const auto & interface : joint.state_interfaces) {
        if (!supported(state_value(joint.name, interface.name), interface, joint.name)) {
          return false;
        }
      }
      for (const auto & interface : joint.command_interfaces) {
        if (!supported(command_value(joint.name, interface.name), interface, joint.name)) {
          return false;
        }
      }
    }
    for (const auto & sensor : info.sensors) {
      for (const auto & interface : sensor.state_interfaces) {
        if (!supported(state_value(sensor.name, interface.name), interface, sensor.name)) {
          return false;
        }
      }
    }
    // One <gpio>: the driver's health (state interfaces) and its e-stop (command interface).
    if (info.gpios.size() > 1) {
      RCLCPP_ERROR(
        log, "<gpio> '%s' of the ros2_control description: %s has one GPIO, its health ('%s')",
        info.gpios[1].name.c_str(), core_.spec().plugin_name, info.gpios.front().name.c_str());
      return false;
    }
    for (const auto & gpio : info.gpios) {
      for (const auto & interface : gpio.state_interfaces) {
        if (!supported(state_value(gpio.name, interface.name), interface, gpio.name)) {
          return false;
        }
      }
      for (const auto & interface : gpio.command_interfaces) {
        if (!supported(command_value(gpio.name, interface.name), interface, gpio.name)) {
          return false;
        }
      }
    }
    for (size_t i = 0; i < core_.spec().joint_count; ++i) {
      const JointSpec & joint = core_.spec().joints[i];
      bool described = false;
      for (const auto & component : info.joints) {
        described = described || component.name == joint.name;
      }
      if (!described) {
        RCLCPP_WARN(
          log, "joint '%s' (motor slot %zu) is not in the ros2_control description: it gets no "
          "interfaces and stays passive", joint.name, joint.slot);
      }
    }
    return true;
  }

  bool supported(
    const double * value, const hardware_interface::InterfaceInfo & interface,
    const std::string & component)
  {
    if (value == nullptr) {
      RCLCPP_ERROR(
        core_.logger(), "interface '%s/%s' of the ros2_control description is not provided by %s",
        component.c_str(), interface.name.c_str(), core_.spec().plugin_name);
      return false;
    }
    if (!interface.data_type.empty() && interface.data_type != "double") {
      RCLCPP_ERROR(
        core_.logger(), "interface '%s/%s' has data_type '%s': %s provides double values",
        component.c_str(), interface.name.c_str(), interface.data_type.c_str(),
        core_.spec().plugin_name);
      return false;
    }
    return true;
  }

  double * state_value(const std::string & prefix, const std::string & name) override
  {
    const int slot = core_.slots().slot_of(prefix);
    if (slot >= 0) {
      JointStorage<N> & joints = core_.joints();
      const auto s = static_cast<size_t>(slot);
      double * value = name == "position" ? &joints.pos[s] : name == "velocity" ? &joints.vel[s] :
        name == "effort" ? &joints.tau[s] : nullptr;
      return value != nullptr ? value : core_.motor_health().value(s, name, motor_health_);
    }
    if (prefix == health_gpio_) {
      return health_state_value(core_.health(), name);
    }
    if (!core_.has_imu() || prefix != core_.spec().imu_name) {
      return nullptr;
    }
    ImuData & imu = core_.imu_data();
    static constexpr const char * kImuInterfaces[] = {
      "orientation.x", "orientation.y", "orientation.z", "orientation.w",
      "angular_velocity.x", "angular_velocity.y", "angular_velocity.z",
      "linear_acceleration.x", "linear_acceleration.y", "linear_acceleration.z"};
    double * const values[] = {
      &imu.orientation[0], &imu.orientation[1], &imu.orientation[2], &imu.orientation[3],
      &imu.angular_velocity[0], &imu.angular_velocity[1], &imu.angular_velocity[2],
      &imu.linear_acceleration[0], &imu.linear_acceleration[1], &imu.linear_acceleration[2]};
    for (size_t i = 0; i < 10; ++i) {
      if (name == kImuInterfaces[i]) {
        return values[i];
      }
    }
    return nullptr;
  }

  bool slow_state_value(const double * value) override {return core_.motor_health().holds(value);}

  double * command_value(const std::string & prefix, const std::string & name) override
  {
    const int slot = core_.slots().slot_of(prefix);
    if (slot < 0) {
      return prefix == health_gpio_ && name == kEstopCommandInterface ?
             &core_.health().estop_command : nullptr;
    }
    const CommandMode mode = core_.slots().mode_of(static_cast<size_t>(slot));
    if (mode == CommandMode::kStateOnly) {
      return nullptr;  // the robot's own controller keeps this joint
    }
    if (mode == CommandMode::kVelocity && (name == "position" || name == "stiffness")) {
      return nullptr;  // a velocity-commanded joint has no position target and no stiffness
    }
    if (mode == CommandMode::kPositionTarget && name != "position") {
      return nullptr;  // the robot's own controller tracks the target: nothing else travels
    }
    if (!transport_->carries_gains() && (name == "stiffness" || name == "damping")) {
      return nullptr;  // the robot applies its own gains
    }
    JointStorage<N> & joints = core_.joints();
    const auto s = static_cast<size_t>(slot);
    return name == "position" ? &joints.pos_des[s] : name == "velocity" ? &joints.vel_des[s] :
           name == "stiffness" ? &joints.kp[s] : name == "damping" ? &joints.kd[s] :
           name == "effort" ? &joints.ff[s] : nullptr;
  }

  DriverCore<N, T> core_;
  std::unique_ptr<DriverTransport<N, T>> transport_;
  std::string calibration_file_;  // the `calibration_file` hardware parameter, "" for none
  std::string hardware_name_;     // the <ros2_control name>, for the operator's command line
  std::string health_gpio_;       // the <gpio> name of the health interfaces and the e-stop
  uint8_t motor_health_{0};       // the transport's MotorHealthField bits
  // /diagnostics: its thread only (but start and stop)
  typename rclcpp::Publisher<diagnostic_msgs::msg::DiagnosticArray>::SharedPtr
    diagnostics_publisher_;
  diagnostic_msgs::msg::DiagnosticArray diagnostics_message_;
  DiagnosticsLimits diagnostics_limits_{};
  HealthFacts previous_facts_;
  PeriodicThread diagnostics_thread_;  // last: stopped first when destroyed
  bool link_dead_reported_{false};  // controller thread: read() said ERROR in this activation
  bool motor_fault_reported_{false};  // controller thread: read() said a motor is faulty
  int faulty_slot_{-1};  // controller thread: a motor too hot or in error, faulty_motor_slot()
  std::atomic<bool> active_{false};  // between on_activate and on_deactivate / on_error
  std::atomic<bool> claims_lost_{false};  // on_error -> on_configure: the controllers are gone
};

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__SYSTEM_DRIVER_HPP_
