// Reference CRC of unitree_sdk2 "hg" LowCmd_ / LowState_, written independently of rhi-gen's
// templates, the way unitree_ros2 does it (example/src/src/common/motor_crc_hg.cpp):
//   1. copy every field into a plain mirror struct whose padding was zeroed first,
//   2. run the SDK's Crc32Core over all 32-bit words but the trailing crc.
// Crc32Core (crc32_core_reference.hpp) is the SDK's bitwise algorithm (SDK_FACTS.md, section A
// "CRC"): init 0xFFFFFFFF, polynomial 0x04C11DB7, 32-bit words MSB first, no reflection, no final XOR.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include <unitree/idl/hg/LowCmd_.hpp>
#include <unitree/idl/hg/LowState_.hpp>

#include "crc32_core_reference.hpp"

namespace rhi_ref {

// Mirrors of the IDL structs (natural alignment, as the SDK's on x86-64 / aarch64).
struct MotorCmdRaw {
  uint8_t mode;
  float q;
  float dq;
  float tau;
  float kp;
  float kd;
  uint32_t reserve;
};
struct LowCmdRaw {
  uint8_t mode_pr;
  uint8_t mode_machine;
  MotorCmdRaw motor_cmd[35];
  uint32_t reserve[4];
  uint32_t crc;
};
struct ImuStateRaw {
  float quaternion[4];
  float gyroscope[3];
  float accelerometer[3];
  float rpy[3];
  int16_t temperature;
};
struct MotorStateRaw {
  uint8_t mode;
  float q;
  float dq;
  float ddq;
  float tau_est;
  int16_t temperature[2];
  float vol;
  uint32_t sensor[2];
  uint32_t motorstate;
  uint32_t reserve[4];
};
struct LowStateRaw {
  uint32_t version[2];
  uint8_t mode_pr;
  uint8_t mode_machine;
  uint32_t tick;
  ImuStateRaw imu_state;
  MotorStateRaw motor_state[35];
  uint8_t wireless_remote[40];
  uint32_t reserve[4];
  uint32_t crc;
};
// SDK_FACTS.md: sizeof(LowCmd)=1004 (crc at byte 1000), sizeof(LowState)=2092 (crc at 2088).
static_assert(sizeof(MotorCmdRaw) == 28, "MotorCmd layout");
static_assert(sizeof(LowCmdRaw) == 1004 && offsetof(LowCmdRaw, crc) == 1000, "LowCmd layout");
static_assert(sizeof(ImuStateRaw) == 56 && sizeof(MotorStateRaw) == 56, "IMU/MotorState layout");
static_assert(sizeof(LowStateRaw) == 2092 && offsetof(LowStateRaw, crc) == 2088, "LowState layout");

inline uint32_t low_cmd_crc(const unitree_hg::msg::dds_::LowCmd_& msg) {
  LowCmdRaw raw;
  std::memset(&raw, 0, sizeof(raw));
  raw.mode_pr = msg.mode_pr();
  raw.mode_machine = msg.mode_machine();
  for (size_t i = 0; i < 35; ++i) {
    const auto& m = msg.motor_cmd()[i];
    raw.motor_cmd[i].mode = m.mode();
    raw.motor_cmd[i].q = m.q();
    raw.motor_cmd[i].dq = m.dq();
    raw.motor_cmd[i].tau = m.tau();
    raw.motor_cmd[i].kp = m.kp();
    raw.motor_cmd[i].kd = m.kd();
    raw.motor_cmd[i].reserve = m.reserve();
  }
  for (size_t i = 0; i < 4; ++i) {
    raw.reserve[i] = msg.reserve()[i];
  }
  raw.crc = msg.crc();
  return crc_of_raw(raw);
}

inline uint32_t low_state_crc(const unitree_hg::msg::dds_::LowState_& msg) {
  LowStateRaw raw;
  std::memset(&raw, 0, sizeof(raw));
  raw.version[0] = msg.version()[0];
  raw.version[1] = msg.version()[1];
  raw.mode_pr = msg.mode_pr();
  raw.mode_machine = msg.mode_machine();
  raw.tick = msg.tick();
  const auto& imu = msg.imu_state();
  for (size_t i = 0; i < 4; ++i) {
    raw.imu_state.quaternion[i] = imu.quaternion()[i];
  }
  for (size_t i = 0; i < 3; ++i) {
    raw.imu_state.gyroscope[i] = imu.gyroscope()[i];
    raw.imu_state.accelerometer[i] = imu.accelerometer()[i];
    raw.imu_state.rpy[i] = imu.rpy()[i];
  }
  raw.imu_state.temperature = imu.temperature();
  for (size_t i = 0; i < 35; ++i) {
    const auto& m = msg.motor_state()[i];
    MotorStateRaw& r = raw.motor_state[i];
    r.mode = m.mode();
    r.q = m.q();
    r.dq = m.dq();
    r.ddq = m.ddq();
    r.tau_est = m.tau_est();
    r.temperature[0] = m.temperature()[0];
    r.temperature[1] = m.temperature()[1];
    r.vol = m.vol();
    r.sensor[0] = m.sensor()[0];
    r.sensor[1] = m.sensor()[1];
    r.motorstate = m.motorstate();
    for (size_t k = 0; k < 4; ++k) {
      r.reserve[k] = m.reserve()[k];
    }
  }
  for (size_t i = 0; i < 40; ++i) {
    raw.wireless_remote[i] = msg.wireless_remote()[i];
  }
  for (size_t i = 0; i < 4; ++i) {
    raw.reserve[i] = msg.reserve()[i];
  }
  raw.crc = msg.crc();
  return crc_of_raw(raw);
}

}  // namespace rhi_ref
