// Reference CRC of unitree_sdk2 "go" LowCmd_ / LowState_ (Go2, Go2-W, B2, B2-W, original H1),
// written independently of rhi-gen's templates from SDK_FACTS.md section D, the way unitree_ros2
// does it (example/src/src/common/motor_crc.cpp):
//   1. copy every field into a plain, non-packed mirror struct whose padding was zeroed first,
//   2. run the SDK's Crc32Core (crc32_core_reference.hpp) over all 32-bit words but the trailing
//      crc: 202 words of LowCmd_ (812 bytes), 294 words of LowState_ (1180 bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include <unitree/idl/go2/LowCmd_.hpp>
#include <unitree/idl/go2/LowState_.hpp>

#include "crc32_core_reference.hpp"

namespace rhi_ref {
namespace go {

// Mirrors of the go IDL structs in declaration order (natural alignment, never packed).
struct MotorCmdRaw {
  uint8_t mode;
  float q;
  float dq;
  float tau;
  float kp;
  float kd;
  uint32_t reserve[3];
};
struct BmsCmdRaw {
  uint8_t off;
  uint8_t reserve[3];
};
struct LowCmdRaw {
  uint8_t head[2];
  uint8_t level_flag;
  uint8_t frame_reserve;
  uint32_t sn[2];
  uint32_t version[2];
  uint16_t bandwidth;
  MotorCmdRaw motor_cmd[20];
  BmsCmdRaw bms_cmd;
  uint8_t wireless_remote[40];
  uint8_t led[12];
  uint8_t fan[2];
  uint8_t gpio;
  uint32_t reserve;
  uint32_t crc;
};
struct ImuStateRaw {
  float quaternion[4];
  float gyroscope[3];
  float accelerometer[3];
  float rpy[3];
  uint8_t temperature;
};
struct MotorStateRaw {
  uint8_t mode;
  float q;
  float dq;
  float ddq;
  float tau_est;
  float q_raw;
  float dq_raw;
  float ddq_raw;
  uint8_t temperature;
  uint32_t lost;
  uint32_t reserve[2];
};
struct BmsStateRaw {
  uint8_t version_high;
  uint8_t version_low;
  uint8_t status;
  uint8_t soc;
  int32_t current;
  uint16_t cycle;
  uint8_t bq_ntc[2];
  uint8_t mcu_ntc[2];
  uint16_t cell_vol[15];
};
struct LowStateRaw {
  uint8_t head[2];
  uint8_t level_flag;
  uint8_t frame_reserve;
  uint32_t sn[2];
  uint32_t version[2];
  uint16_t bandwidth;
  ImuStateRaw imu_state;
  MotorStateRaw motor_state[20];
  BmsStateRaw bms_state;
  int16_t foot_force[4];
  int16_t foot_force_est[4];
  uint32_t tick;
  uint8_t wireless_remote[40];
  uint8_t bit_flag;
  float adc_reel;
  uint8_t temperature_ntc1;
  uint8_t temperature_ntc2;
  float power_v;
  float power_a;
  uint16_t fan_frequency[4];
  uint32_t reserve;
  uint32_t crc;
};
// SDK_FACTS.md section D "sizeof and CRC coverage".
static_assert(sizeof(MotorCmdRaw) == 36 && sizeof(BmsCmdRaw) == 4, "MotorCmd_/BmsCmd_ layout");
static_assert(offsetof(LowCmdRaw, bandwidth) == 20 && offsetof(LowCmdRaw, motor_cmd) == 24, "LowCmd_ header");
static_assert(offsetof(LowCmdRaw, bms_cmd) == 744 && offsetof(LowCmdRaw, wireless_remote) == 748, "LowCmd_ tail");
static_assert(offsetof(LowCmdRaw, led) == 788 && offsetof(LowCmdRaw, fan) == 800, "LowCmd_ tail");
static_assert(offsetof(LowCmdRaw, gpio) == 802 && offsetof(LowCmdRaw, reserve) == 804, "LowCmd_ tail");
static_assert(sizeof(LowCmdRaw) == 812 && offsetof(LowCmdRaw, crc) == 808, "LowCmd_: 812 bytes, crc at 808");
static_assert(sizeof(ImuStateRaw) == 56 && sizeof(MotorStateRaw) == 48 && sizeof(BmsStateRaw) == 44, "parts");
static_assert(offsetof(MotorStateRaw, temperature) == 32 && offsetof(MotorStateRaw, lost) == 36, "MotorState_");
static_assert(offsetof(BmsStateRaw, current) == 4 && offsetof(BmsStateRaw, cell_vol) == 14, "BmsState_");
static_assert(offsetof(LowStateRaw, imu_state) == 24 && offsetof(LowStateRaw, motor_state) == 80, "LowState_");
static_assert(offsetof(LowStateRaw, bms_state) == 1040 && offsetof(LowStateRaw, foot_force) == 1084, "LowState_");
static_assert(offsetof(LowStateRaw, foot_force_est) == 1092 && offsetof(LowStateRaw, tick) == 1100, "LowState_");
static_assert(offsetof(LowStateRaw, wireless_remote) == 1104 && offsetof(LowStateRaw, bit_flag) == 1144, "LowState_");
static_assert(offsetof(LowStateRaw, adc_reel) == 1148 && offsetof(LowStateRaw, temperature_ntc1) == 1152, "LowState_");
static_assert(offsetof(LowStateRaw, temperature_ntc2) == 1153 && offsetof(LowStateRaw, power_v) == 1156, "LowState_");
static_assert(offsetof(LowStateRaw, power_a) == 1160 && offsetof(LowStateRaw, fan_frequency) == 1164, "LowState_");
static_assert(offsetof(LowStateRaw, reserve) == 1172 && offsetof(LowStateRaw, crc) == 1176, "LowState_");
static_assert(sizeof(LowStateRaw) == 1180, "LowState_: 1180 bytes");
// The stand-in IDL classes have the same size (their own static_asserts check 812 / 1180).
static_assert(sizeof(LowCmdRaw) == sizeof(unitree_go::msg::dds_::LowCmd_), "stand-in LowCmd_ size");
static_assert(sizeof(LowStateRaw) == sizeof(unitree_go::msg::dds_::LowState_), "stand-in LowState_ size");

// The SDK examples' constants (SDK_FACTS.md section D "Filling LowCmd_").
constexpr uint8_t kHead0 = 0xFE;
constexpr uint8_t kHead1 = 0xEF;
constexpr uint8_t kLowLevel = 0xFF;
constexpr float kPosStopF = 2.146E+9F;
constexpr float kVelStopF = 16000.0F;

template <size_t K, typename T, typename Src>
inline void copy_array(T (&dst)[K], const Src& src) {
  for (size_t i = 0; i < K; ++i) dst[i] = src[i];
}

inline LowCmdRaw mirror(const unitree_go::msg::dds_::LowCmd_& msg) {
  LowCmdRaw raw;
  std::memset(&raw, 0, sizeof(raw));
  copy_array(raw.head, msg.head());
  raw.level_flag = msg.level_flag();
  raw.frame_reserve = msg.frame_reserve();
  copy_array(raw.sn, msg.sn());
  copy_array(raw.version, msg.version());
  raw.bandwidth = msg.bandwidth();
  for (size_t i = 0; i < 20; ++i) {
    const auto& m = msg.motor_cmd()[i];
    MotorCmdRaw& r = raw.motor_cmd[i];
    r.mode = m.mode();
    r.q = m.q();
    r.dq = m.dq();
    r.tau = m.tau();
    r.kp = m.kp();
    r.kd = m.kd();
    copy_array(r.reserve, m.reserve());
  }
  raw.bms_cmd.off = msg.bms_cmd().off();
  copy_array(raw.bms_cmd.reserve, msg.bms_cmd().reserve());
  copy_array(raw.wireless_remote, msg.wireless_remote());
  copy_array(raw.led, msg.led());
  copy_array(raw.fan, msg.fan());
  raw.gpio = msg.gpio();
  raw.reserve = msg.reserve();
  raw.crc = msg.crc();
  return raw;
}

inline LowStateRaw mirror(const unitree_go::msg::dds_::LowState_& msg) {
  LowStateRaw raw;
  std::memset(&raw, 0, sizeof(raw));
  copy_array(raw.head, msg.head());
  raw.level_flag = msg.level_flag();
  raw.frame_reserve = msg.frame_reserve();
  copy_array(raw.sn, msg.sn());
  copy_array(raw.version, msg.version());
  raw.bandwidth = msg.bandwidth();
  const auto& imu = msg.imu_state();
  copy_array(raw.imu_state.quaternion, imu.quaternion());
  copy_array(raw.imu_state.gyroscope, imu.gyroscope());
  copy_array(raw.imu_state.accelerometer, imu.accelerometer());
  copy_array(raw.imu_state.rpy, imu.rpy());
  raw.imu_state.temperature = imu.temperature();
  for (size_t i = 0; i < 20; ++i) {
    const auto& m = msg.motor_state()[i];
    MotorStateRaw& r = raw.motor_state[i];
    r.mode = m.mode();
    r.q = m.q();
    r.dq = m.dq();
    r.ddq = m.ddq();
    r.tau_est = m.tau_est();
    r.q_raw = m.q_raw();
    r.dq_raw = m.dq_raw();
    r.ddq_raw = m.ddq_raw();
    r.temperature = m.temperature();
    r.lost = m.lost();
    copy_array(r.reserve, m.reserve());
  }
  const auto& bms = msg.bms_state();
  raw.bms_state.version_high = bms.version_high();
  raw.bms_state.version_low = bms.version_low();
  raw.bms_state.status = bms.status();
  raw.bms_state.soc = bms.soc();
  raw.bms_state.current = bms.current();
  raw.bms_state.cycle = bms.cycle();
  copy_array(raw.bms_state.bq_ntc, bms.bq_ntc());
  copy_array(raw.bms_state.mcu_ntc, bms.mcu_ntc());
  copy_array(raw.bms_state.cell_vol, bms.cell_vol());
  copy_array(raw.foot_force, msg.foot_force());
  copy_array(raw.foot_force_est, msg.foot_force_est());
  raw.tick = msg.tick();
  copy_array(raw.wireless_remote, msg.wireless_remote());
  raw.bit_flag = msg.bit_flag();
  raw.adc_reel = msg.adc_reel();
  raw.temperature_ntc1 = msg.temperature_ntc1();
  raw.temperature_ntc2 = msg.temperature_ntc2();
  raw.power_v = msg.power_v();
  raw.power_a = msg.power_a();
  copy_array(raw.fan_frequency, msg.fan_frequency());
  raw.reserve = msg.reserve();
  raw.crc = msg.crc();
  return raw;
}

}  // namespace go

// Overloads next to the hg ones (hg_crc_reference.hpp): the harness calls rhi_ref::low_cmd_crc(raw)
// whatever the family.
inline uint32_t low_cmd_crc(const unitree_go::msg::dds_::LowCmd_& msg) { return crc_of_raw(go::mirror(msg)); }
inline uint32_t low_state_crc(const unitree_go::msg::dds_::LowState_& msg) {
  return crc_of_raw(go::mirror(msg));
}

}  // namespace rhi_ref
