// Fake robot side of the custom transport: the toy bus of tests/cpp/toy_bus/ (an in-process
// "vendor SDK"), which the custom robot's filled user regions (tests/cpp/toy_bus/regions.cpp.in)
// talk to. State and IMU frames in through the bus's handlers, command frames (with gains) out.
// The command writer is the driver's executor wall timer, as for the topic transports.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "toy_bus.hpp"
#include "transport_ros_common.hpp"

namespace rhi_test {

class Transport : public RosTransportBase {
public:
  static constexpr const char* kName = "custom";
  static constexpr bool kHasGains = true;
  static_assert(N <= toy_bus::kMaxMotors, "more motors than the toy bus carries");

  // Every motor of the bus; the driver maps slots to joints itself.
  void prepare_state(const StateFrame& f) {
    state_.motors = N;
    for (size_t i = 0; i < N; ++i) {
      state_.position[i] = f.q[i];
      state_.velocity[i] = f.dq[i];
      state_.torque[i] = f.tau[i];
    }
    for (size_t i = N; i < toy_bus::kMaxMotors; ++i) {  // beyond the robot: garbage nobody reads
      state_.position[i] = 777.0;
      state_.velocity[i] = -777.0;
      state_.torque[i] = 555.0;
    }
    for (size_t i = 0; i < 4; ++i) {
      imu_.quaternion_wxyz[i] = f.quat_wxyz[i];
    }
    for (size_t i = 0; i < 3; ++i) {
      imu_.gyro[i] = f.gyro[i];
      imu_.accel[i] = f.acc[i];
    }
  }
  size_t deliver_prepared() { return toy_bus::Bus::instance().deliverState(state_); }
  size_t deliver_state(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared();
  }
  size_t deliver_prepared_imu() { return toy_bus::Bus::instance().deliverImu(imu_); }
  size_t deliver_imu(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared_imu();
  }
  // A frame that must not count as the first valid state: a non-finite position of a driven joint.
  size_t deliver_invalid_state(const StateFrame& f) {
    prepare_state(f);
    toy_bus::StateFrame bad = state_;
    bad.position[kJoints[0].slot] = std::numeric_limits<double>::quiet_NaN();
    return toy_bus::Bus::instance().deliverState(bad);
  }

  // One frame the driver must reject and count (health GPIO invalid_states): a non-finite position.
  size_t deliver_corrupt_state(const StateFrame& f) { return deliver_invalid_state(f); }

  uint64_t sent_messages() const { return toy_bus::Bus::instance().sentCount(); }
  static constexpr size_t command_messages_per_cycle() { return 1; }
  bool command_names_ok() const { return true; }  // slots are positions: nothing to name

  bool last_command(CommandFrame& out) {
    if (!toy_bus::Bus::instance().lastCommand(cmd_)) {
      return false;
    }
    out.has_gains = true;
    for (size_t i = 0; i < N; ++i) {
      out.q[i] = cmd_.position[i];
      out.dq[i] = cmd_.velocity[i];
      out.tau[i] = cmd_.torque[i];
      out.kp[i] = cmd_.kp[i];
      out.kd[i] = cmd_.kd[i];
      out.present[i] = cmd_.motors == N;
    }
    return true;
  }

  // The interface the connect region opened the bus on (the network_interface parameter).
  std::string network_interface() const { return toy_bus::Bus::instance().interface(); }
  static void reset_bus() { toy_bus::Bus::instance().reset(); }

private:
  toy_bus::StateFrame state_{};
  toy_bus::ImuFrame imu_{};
  toy_bus::CommandFrame cmd_{};
};

}  // namespace rhi_test
