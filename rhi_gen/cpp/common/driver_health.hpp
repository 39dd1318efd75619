// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_
#define ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_

#include <atomic>
#include <cstddef>
#include <cstdint>
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

private:
  std::atomic<uint64_t> value_{0};
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

// An e-stop command value presses the e-stop: NaN (a framework handle nobody wrote) never does.
inline bool estop_pressed(double command) {return command >= 0.5;}

}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__COMMON__DRIVER_HEALTH_HPP_
