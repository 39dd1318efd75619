// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>

namespace robot_hardware_interface
{

// A count of events one thread detects and read() reports (state, writer or controller thread).
// A relaxed atomic: the count hands over no other data, and its only writer needs no
// read-modify-write (so no locked instruction on the hot path).
class HealthCounter
{
public:
  // The detecting thread only.
  uint64_t add()
  {
    const uint64_t next = value_.load(std::memory_order_relaxed) + 1;
    value_.store(next, std::memory_order_relaxed);
    return next;
  }
  uint64_t get() const {return value_.load(std::memory_order_relaxed);}
  // As an interface value, through int64_t: one conversion instruction (a count stays < 2^63).
  double value() const {return static_cast<double>(static_cast<int64_t>(get()));}

private:
  std::atomic<uint64_t> value_{0};
};

// The driver's health as any thread may read it (atomics only, never the controller thread's
// storage): what /diagnostics and ros2_control's hardware status report, and the one place that
// says when a silence is stale or dead.
struct HealthFacts
{
  bool active{false};           // between on_activate and on_deactivate / on_error
  int64_t now_ns{0};            // steady time the facts were taken at, 0: never taken
  int64_t silence_ns{-1};       // without a valid state (since the newest, or the activation)
  uint64_t valid_messages{0};   // valid state messages (each part, where the state comes in parts)
  uint64_t invalid_states{0};
  uint64_t stale_holds{0};
  uint64_t rejected_commands{0};
  uint64_t writer_overruns{0};
  bool error_hold{false};       // on_error latched the damping-only hold
  bool estop{false};            // the e-stop latched it
  bool awaiting_first_state{false};  // no valid state yet in this activation (DDS discovery)

  // Milliseconds without a valid state, -1 before any state or activation.
  static double age_ms_of(int64_t silence_ns)
  {
    return silence_ns < 0 ? -1.0 : static_cast<double>(silence_ns) * 1e-6;
  }
  double age_ms() const {return age_ms_of(silence_ns);}
  // Valid state messages per second since `earlier` facts, -1 without earlier ones.
  double message_rate_since(const HealthFacts & earlier) const
  {
    if (earlier.now_ns == 0 || now_ns <= earlier.now_ns) {
      return -1.0;
    }
    return static_cast<double>(valid_messages - earlier.valid_messages) * 1e9 /
           static_cast<double>(now_ns - earlier.now_ns);
  }
  bool no_state() const {return silence_ns < 0;}
  // No valid state for more than `timeout_ms`: stale after state_timeout_ms, dead after
  // fault_timeout_ms (an active component only: an inactive one may be silent).
  static bool silent_for(int64_t silence_ns, uint64_t timeout_ms)
  {
    return silence_ns > static_cast<int64_t>(timeout_ms) * 1000000;
  }
  bool stale(uint64_t state_timeout_ms) const {return silent_for(silence_ns, state_timeout_ms);}
  // The silence after which an active link is dead: fault_timeout_ms since the newest state;
  // before the first state of an activation the longer first_state_timeout_ms, since DDS discovery
  // of a robot that already runs may take seconds (the safe start sends nothing meanwhile).
  static uint64_t dead_after_ms(
    bool awaiting_first_state, uint64_t fault_timeout_ms, uint64_t first_state_timeout_ms)
  {
    return awaiting_first_state && first_state_timeout_ms > fault_timeout_ms ?
           first_state_timeout_ms : fault_timeout_ms;
  }
  bool link_dead(uint64_t fault_timeout_ms, uint64_t first_state_timeout_ms) const
  {
    return active && silent_for(
      silence_ns, dead_after_ms(awaiting_first_state, fault_timeout_ms, first_state_timeout_ms));
  }
};

// The driver's health as ros2_control interfaces of the robot's health GPIO
// (<gpio name="<hardware>_health"> of the description): what an operator or a controller needs to
// see a dying link or a stopped robot. Controller thread only: read() fills the states, write()
// takes the e-stop command.
struct DriverHealthData
{
  double state_age_ms{-1.0};      // since the newest valid state (or the activation); -1: none
  double invalid_states{0.0};     // rejected state frames (CRC, size, names, non-finite)
  double stale_holds{0.0};        // times the writer held damping-only for a stale state
  double rejected_commands{0.0};  // writer cycles holding a joint for a NaN / negative gain
  double writer_overruns{0.0};    // sends later than command_writer_period_us + 500 us
  double fault{0.0};              // 1: the driver holds damping-only (dead link, error or e-stop)
  double estop{0.0};              // 1: the e-stop is latched until the next activation
  double estop_command{0.0};      // command: >= 0.5 latches the e-stop
};

// The health GPIO's interfaces, in the order of the description (rhi_gen/render/views.py holds the
// same names for the generated xacro and controllers YAML).
struct HealthStateInterface
{
  const char * name;
  double DriverHealthData::* value;
};

inline constexpr HealthStateInterface kHealthStateInterfaces[] = {
  {"state_age_ms", &DriverHealthData::state_age_ms},
  {"invalid_states", &DriverHealthData::invalid_states},
  {"stale_holds", &DriverHealthData::stale_holds},
  {"rejected_commands", &DriverHealthData::rejected_commands},
  {"writer_overruns", &DriverHealthData::writer_overruns},
  {"fault", &DriverHealthData::fault},
  {"estop", &DriverHealthData::estop},
};
inline constexpr const char * kEstopCommandInterface = "estop";

// The state double of the health GPIO interface `name`, nullptr for an unknown one.
inline double * health_state_value(DriverHealthData & health, const std::string & name)
{
  for (const HealthStateInterface & interface : kHealthStateInterfaces) {
    if (name == interface.name) {
      return &(health.*interface.value);
    }
  }
  return nullptr;
}

// Motor health a robot's state message may carry per motor slot: the transport says which
// (DriverTransport::motor_health()), the description lists them after position, velocity and
// effort, and a robot without a field simply lacks that interface.
enum MotorHealthField : uint8_t
{
  kMotorTemperature = 1U << 0,  // "temperature": winding temperature [deg C]
  kMotorVoltage = 1U << 1,      // "voltage": supply voltage [V]
  kMotorErrorCode = 1U << 2,    // "error_code": the motor's error bits (vendor), 0: none
  kMotorOffline = 1U << 3,      // the robot reports the motor unreachable (no interface: a fault)
};

// The bits of an error_code value (a motor health double holds the vendor's unsigned code).
inline uint64_t motor_error_bits(double code)
{
  return code > 0.0 && code < 18446744073709551616.0 ? static_cast<uint64_t>(code) : 0U;
}

struct MotorHealthInterface
{
  const char * name;
  MotorHealthField field;
};

inline constexpr MotorHealthInterface kMotorHealthInterfaces[] = {
  {"temperature", kMotorTemperature}, {"voltage", kMotorVoltage}, {"error_code", kMotorErrorCode}};

// Motor health by SDK motor slot, as the state message said it. The state thread publishes one at
// most every kMotorHealthPeriodNs (temperatures change slowly; read() copies a frame only when a
// new one came, and the framework handles are written only then).
template<size_t N>
struct MotorHealthFrame
{
  std::array<double, N> temperature{};
  std::array<double, N> voltage{};
  std::array<double, N> error_code{};
  std::array<bool, N> offline{};  // kMotorOffline: not an interface, it faults an active robot
  uint64_t sequence{0};  // 0: never published

  // The double of field `name` of `slot`, nullptr for an unknown name or a field not in `fields`.
  double * value(size_t slot, const std::string & name, uint8_t fields)
  {
    for (const MotorHealthInterface & interface : kMotorHealthInterfaces) {
      if (name == interface.name && (fields & interface.field) != 0U) {
        return interface.field == kMotorTemperature ? &temperature[slot] :
               interface.field == kMotorVoltage ? &voltage[slot] : &error_code[slot];
      }
    }
    return nullptr;
  }

  // Whether `value` is one of this frame's doubles (std::less: a total order on any pointers).
  bool holds(const double * value) const
  {
    for (const std::array<double, N> * values : {&temperature, &voltage, &error_code}) {
      if (!std::less<const double *>()(value, values->data()) &&
        std::less<const double *>()(value, values->data() + N))
      {
        return true;
      }
    }
    return false;
  }
};

inline constexpr int64_t kMotorHealthPeriodNs = 10000000;  // 100 Hz

// An e-stop command value presses the e-stop: NaN (a framework handle nobody wrote) never does.
inline bool estop_pressed(double command) {return command >= 0.5;}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_
