// Copyright the rhi-gen authors
// SPDX-License-Identifier: Apache-2.0
//
// rhi-gen copies this file into every generated package that needs it, below the package's banner.

#ifndef ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_HG_HPP_
#define ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_HG_HPP_

// unitree_sdk2's "hg" low-level messages (G1, H1-2, H2, R1): 35 motor slots, mode_pr and
// mode_machine, CRC-protected LowCmd_ / LowState_.

#include <array>
#include <cstddef>
#include <cstdint>

#include <unitree/idl/hg/LowCmd_.hpp>
#include <unitree/idl/hg/LowState_.hpp>

#include "robot_hardware_interface/common/driver_health.hpp"
#include "robot_hardware_interface/transport/unitree_crc.hpp"

namespace robot_hardware_interface
{
namespace unitree_hg
{

using LowCmd = ::unitree_hg::msg::dds_::LowCmd_;
using LowState = ::unitree_hg::msg::dds_::LowState_;
using unitree_crc::FieldBytes;

constexpr size_t kMotorSlots = 35;
constexpr uint8_t kMotorEnable = 1;  // MotorCmd_.mode: 1 enable, 0 disable

// LowCmd_ (1004 bytes, CRC over 250 words): mode_pr u8 @0, mode_machine u8 @1,
// motor_cmd[35] @4 (28 bytes: mode u8 @0, q dq tau kp kd f32 @4..20, reserve u32 @24),
// reserve u32[4] @984, crc @1000.
constexpr size_t kLowCmdWords = 250;
constexpr std::array<FieldBytes, 5> kLowCmdFields = {{
  {0, 2, 1, 0},           // mode_pr, mode_machine
  {4, 1, kMotorSlots, 28},    // motor_cmd[i].mode
  {8, 24, kMotorSlots, 28},   // motor_cmd[i].q .. reserve
  {984, 16, 1, 0},        // reserve[4]
  {1000, 0, 0, 0},        // crc (not covered)
}};
constexpr auto kLowCmdMasks = unitree_crc::word_masks<kLowCmdWords>(kLowCmdFields);

// LowState_ (2092 bytes, CRC over 522 words): version u32[2] @0, mode_pr u8 @8, mode_machine u8
// @9, tick u32 @12, imu_state @16 (quaternion, gyroscope, accelerometer, rpy f32 @0..51,
// temperature i16 @52), motor_state[35] @72 (56 bytes: mode u8 @0, q dq ddq tau_est f32 @4..19,
// temperature i16[2] @20, vol f32 @24, sensor u32[2] @28, motorstate u32 @36, reserve u32[4] @40),
// wireless_remote u8[40] @2032, reserve u32[4] @2072, crc @2088.
constexpr size_t kLowStateWords = 522;
constexpr std::array<FieldBytes, 8> kLowStateFields = {{
  {0, 8, 1, 0},           // version[2]
  {8, 2, 1, 0},           // mode_pr, mode_machine
  {12, 4, 1, 0},          // tick
  {16, 54, 1, 0},         // imu_state
  {72, 1, kMotorSlots, 56},   // motor_state[i].mode
  {76, 52, kMotorSlots, 56},  // motor_state[i].q .. reserve
  {2032, 56, 1, 0},       // wireless_remote[40], reserve[4]
  {2088, 0, 0, 0},        // crc (not covered)
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

// What the Unitree DDS transport needs to know about the hg messages.
struct Family
{
  using LowCmd = unitree_hg::LowCmd;
  using LowState = unitree_hg::LowState;
  static constexpr size_t kMotorSlots = unitree_hg::kMotorSlots;
  static constexpr const char * kName = "unitree_hg";

  // The constant parts of every command: mode_pr, and the enable bit of each driven slot (the
  // other slots stay disabled with all-zero targets).
  template<typename Slots>
  static void init_command(
    LowCmd & cmd, const Slots & driven_slots, uint8_t mode_pr, const uint8_t * /*motor_modes*/)
  {
    cmd = LowCmd{};
    cmd.mode_pr() = mode_pr;
    for (const size_t slot : driven_slots) {
      cmd.motor_cmd()[slot].mode() = kMotorEnable;
    }
  }

  // mode_machine of a valid LowState_, echoed in every LowCmd_ (0 until the first state).
  static uint8_t state_tag(const LowState & state) {return state.mode_machine();}
  static void apply_state_tag(LowCmd & cmd, uint8_t tag) {cmd.mode_machine() = tag;}

  static uint32_t command_crc(const LowCmd & cmd) {return low_cmd_crc(cmd);}
  static uint32_t state_crc(const LowState & state) {return low_state_crc(state);}

  // Motor health of MotorState_ (SDK_FACTS.md): temperature[0], vol and motorstate.
  static constexpr uint8_t kMotorHealth = kMotorTemperature | kMotorVoltage | kMotorErrorCode;
  template<typename Motor, typename Frame>
  static void read_motor_health(const Motor & motor, Frame & frame, size_t slot)
  {
    frame.temperature[slot] = static_cast<double>(motor.temperature()[0]);
    frame.voltage[slot] = static_cast<double>(motor.vol());
    frame.error_code[slot] = static_cast<double>(motor.motorstate());
  }
};

}  // namespace unitree_hg
}  // namespace robot_hardware_interface

#endif  // ROBOT_HARDWARE_INTERFACE__TRANSPORT__UNITREE_HG_HPP_
