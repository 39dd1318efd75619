// Pieces shared by the ROS 2 topic transports' fake robot sides.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include <sensor_msgs/msg/imu.hpp>

#include "harness_common.hpp"
#include "rhi_fake/ros.hpp"

namespace rhi_test {

class RosTransportBase {
public:
  static constexpr bool kImuInState = false;
  // Motor health in a message of its own (EngineAI MotorDebug): none here, it travels with the state.
  static constexpr bool kHealthMessage = false;
  size_t deliver_prepared_health() { return 0; }

  // The command period as the transport sees it: the driver's one wall timer.
  bool writer_period_us(uint64_t& out) const {
    const auto periods = rhi_fake::ros::timer_periods();
    if (periods.size() != 1) {
      return false;
    }
    out = static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(periods[0]).count());
    return true;
  }
  std::string network_interface() const { return ""; }
  size_t tick_writer() { return rhi_fake::ros::fire_timers(); }
  void use_real_threads(bool on) { rhi_fake::ros::set_realtime_timers(on); }

protected:
  // sensor_msgs/Imu: orientation x, y, z, w.
  void prepare_ros_imu(const StateFrame& f) {
    imu_msg_.orientation.w = f.quat_wxyz[0];
    imu_msg_.orientation.x = f.quat_wxyz[1];
    imu_msg_.orientation.y = f.quat_wxyz[2];
    imu_msg_.orientation.z = f.quat_wxyz[3];
    imu_msg_.angular_velocity.x = f.gyro[0];
    imu_msg_.angular_velocity.y = f.gyro[1];
    imu_msg_.angular_velocity.z = f.gyro[2];
    imu_msg_.linear_acceleration.x = f.acc[0];
    imu_msg_.linear_acceleration.y = f.acc[1];
    imu_msg_.linear_acceleration.z = f.acc[2];
  }
  size_t deliver_ros_imu() { return rhi_fake::ros::deliver<sensor_msgs::msg::Imu>(kImuTopic, imu_msg_); }

  sensor_msgs::msg::Imu imu_msg_;
};

}  // namespace rhi_test
