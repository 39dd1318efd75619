// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_GO_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_GO_HPP_

// unitree_sdk2's "go" low-level messages (Go2, Go2-W, B2, B2-W, the original H1): 20 motor slots,
// head/level_flag framing, CRC-protected LowCmd_ / LowState_ (IDL folder go2, namespace
// unitree_go).

#include <array>
#include <cstddef>
#include <cstdint>

#include <unitree/idl/go2/LowCmd_.hpp>
#include <unitree/idl/go2/LowState_.hpp>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/transport/unitree_crc.hpp"

namespace robot_hardware_interface
{
namespace unitree_go
{

using LowCmd = ::unitree_go::msg::dds_::LowCmd_;
using LowState = ::unitree_go::msg::dds_::LowState_;
using unitree_crc::FieldBytes;

constexpr size_t kMotorSlots = 20;
constexpr uint8_t kHead0 = 0xFE;
constexpr uint8_t kHead1 = 0xEF;
constexpr uint8_t kLowLevel = 0xFF;  // level_flag of a low-level command
// A slot nobody drives: the SDK examples' stop values with zero gains (a pure-torque idle slot).
constexpr float kPosStop = 2.146E+9F;
constexpr float kVelStop = 16000.0F;

// LowCmd_ (812 bytes, CRC over 202 words): head u8[2] @0, level_flag u8 @2, frame_reserve u8 @3,
// sn u32[2] @4, version u32[2] @12, bandwidth u16 @20, motor_cmd[20] @24 (36 bytes: mode u8 @0,
// q dq tau kp kd f32 @4..20, reserve u32[3] @24), bms_cmd @744 (off u8, reserve u8[3]),
// wireless_remote u8[40] @748, led u8[12] @788, fan u8[2] @800, gpio u8 @802, reserve u32 @804,
// crc @808.
constexpr size_t kLowCmdWords = 202;
constexpr std::array<FieldBytes, 5> kLowCmdFields = {{
  {0, 22, 1, 0},           // head .. bandwidth
  {24, 1, kMotorSlots, 36},    // motor_cmd[i].mode
  {28, 32, kMotorSlots, 36},   // motor_cmd[i].q .. reserve
  {744, 59, 1, 0},         // bms_cmd, wireless_remote, led, fan, gpio
  {804, 4, 1, 0},          // reserve
}};
constexpr auto kLowCmdMasks = unitree_crc::word_masks<kLowCmdWords>(kLowCmdFields);

// LowState_ (1180 bytes, CRC over 294 words): head .. bandwidth as LowCmd_ (@0..21), imu_state
// @24 (quaternion, gyroscope, accelerometer, rpy f32 @0..51, temperature u8 @52), motor_state[20]
// @80 (48 bytes: mode u8 @0, q dq ddq tau_est q_raw dq_raw ddq_raw f32 @4..31, temperature u8
// @32, lost u32 @36, reserve u32[2] @40), bms_state @1040 (44 bytes, no padding), foot_force
// i16[4] @1084, foot_force_est i16[4] @1092, tick u32 @1100, wireless_remote u8[40] @1104,
// bit_flag u8 @1144, adc_reel f32 @1148, temperature_ntc1/2 u8 @1152, power_v f32 @1156,
// power_a f32 @1160, fan_frequency u16[4] @1164, reserve u32 @1172, crc @1176.
constexpr size_t kLowStateWords = 294;
constexpr std::array<FieldBytes, 9> kLowStateFields = {{
  {0, 22, 1, 0},            // head .. bandwidth
  {24, 53, 1, 0},           // imu_state
  {80, 1, kMotorSlots, 48},     // motor_state[i].mode
  {84, 29, kMotorSlots, 48},    // motor_state[i].q .. temperature
  {116, 12, kMotorSlots, 48},   // motor_state[i].lost, reserve
  {1040, 105, 1, 0},        // bms_state .. bit_flag
  {1148, 6, 1, 0},          // adc_reel, temperature_ntc1, temperature_ntc2
  {1156, 20, 1, 0},         // power_v, power_a, fan_frequency, reserve
  {1176, 0, 0, 0},          // crc (not covered)
}};
constexpr auto kLowStateMasks = unitree_crc::word_masks<kLowStateWords>(kLowStateFields);

// The value the `crc` field of `cmd` must hold.
inline uint32_t low_cmd_crc(const LowCmd & cmd)
{
  return unitree_crc::message_crc(cmd, kLowCmdMasks);
}

// The value the `crc` field of `state` must hold to be valid.
inline uint32_t low_state_crc(const LowState & state)
{
  return unitree_crc::message_crc(state, kLowStateMasks);
}

// What the Unitree DDS transport needs to know about the go messages.
struct Family
{
  using LowCmd = unitree_go::LowCmd;
  using LowState = unitree_go::LowState;
  static constexpr size_t kMotorSlots = unitree_go::kMotorSlots;
  static constexpr const char * kName = "unitree_go";

  // The constant parts of every command, as the SDK's low-level examples fill them: the low-level
  // header, and every slot in its motor mode with the stop values and zero gains (driven slots
  // are overwritten every cycle). `motor_modes` holds one MotorCmd_.mode per slot.
  template<typename Slots>
  static void init_command(
    LowCmd & cmd, const Slots & /*driven_slots*/, uint8_t /*mode_pr*/, const uint8_t * motor_modes)
  {
    cmd = LowCmd{};
    cmd.head()[0] = kHead0;
    cmd.head()[1] = kHead1;
    cmd.level_flag() = kLowLevel;
    cmd.gpio() = 0;
    for (size_t slot = 0; slot < kMotorSlots; ++slot) {
      auto & motor = cmd.motor_cmd()[slot];
      motor.mode() = motor_modes[slot];
      motor.q() = kPosStop;
      motor.dq() = kVelStop;
      motor.kp() = 0.0F;
      motor.kd() = 0.0F;
      motor.tau() = 0.0F;
    }
  }

  // The go messages carry nothing to echo.
  static uint8_t state_tag(const LowState & /*state*/) {return 0;}
  static void apply_state_tag(LowCmd & /*cmd*/, uint8_t /*tag*/) {}

  static uint32_t command_crc(const LowCmd & cmd) {return low_cmd_crc(cmd);}
  static uint32_t state_crc(const LowState & state) {return low_state_crc(state);}

  // Motor health of MotorState_ (SDK_FACTS.md): one temperature (no voltage, no error code).
  static constexpr uint8_t kMotorHealth = kMotorTemperature;
  template<typename Motor, typename Frame>
  static void read_motor_health(const Motor & motor, Frame & frame, size_t slot)
  {
    frame.temperature[slot] = static_cast<double>(motor.temperature());
  }
};

}  // namespace unitree_go
}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_GO_HPP_
