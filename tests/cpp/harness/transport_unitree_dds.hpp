// Fake robot side of the unitree_dds transport: LowState_ frames in (with a correct CRC computed
// by the independent reference, every field non-zero), LowCmd_ out.
#pragma once

#include <cstdint>
#include <string>

#include <unitree/idl/hg/LowCmd_.hpp>
#include <unitree/idl/hg/LowState_.hpp>

#include "harness_common.hpp"
#include "hg_crc_reference.hpp"
#include "rhi_fake/unitree.hpp"

namespace rhi_test {

class Transport {
public:
  using LowCmd = unitree_hg::msg::dds_::LowCmd_;
  using LowState = unitree_hg::msg::dds_::LowState_;
  static constexpr const char* kName = "unitree_dds";
  static constexpr bool kImuInState = true;
  static constexpr bool kHasGains = true;
  static constexpr size_t kSdkSlots = 35;
  static_assert(N <= kSdkSlots, "more motors than LowCmd_ slots");

  // Fill the member LowState_ (no allocation): every field non-zero, so a CRC that skips any
  // field disagrees with the reference.
  void prepare_state(const StateFrame& f, bool corrupt_crc = false) {
    LowState& m = state_msg_;
    m.version()[0] = 0x01020304U;
    m.version()[1] = 0xA0B0C0D0U;
    m.mode_pr() = kModePr;
    m.mode_machine() = f.mode_machine;
    m.tick() = 1000U + f.sequence;
    auto& imu = m.imu_state();
    for (size_t i = 0; i < 4; ++i) {
      imu.quaternion()[i] = static_cast<float>(f.quat_wxyz[i]);  // SDK order w, x, y, z
    }
    for (size_t i = 0; i < 3; ++i) {
      imu.gyroscope()[i] = static_cast<float>(f.gyro[i]);
      imu.accelerometer()[i] = static_cast<float>(f.acc[i]);
      imu.rpy()[i] = 0.0625F * static_cast<float>(i + 1);
    }
    imu.temperature() = 37;
    for (size_t i = 0; i < kSdkSlots; ++i) {
      auto& ms = m.motor_state()[i];
      ms.mode() = 1;
      if (i < N) {
        ms.q() = static_cast<float>(f.q[i]);
        ms.dq() = static_cast<float>(f.dq[i]);
        ms.tau_est() = static_cast<float>(f.tau[i]);
      } else {  // slots beyond the robot's motors: garbage the driver must ignore
        ms.q() = 777.0F + static_cast<float>(i);
        ms.dq() = -777.0F;
        ms.tau_est() = 555.0F;
      }
      ms.ddq() = 0.5F + static_cast<float>(i);
      ms.temperature()[0] = static_cast<int16_t>(30 + i);
      ms.temperature()[1] = static_cast<int16_t>(-5 - static_cast<int>(i));
      ms.vol() = 24.5F;
      ms.sensor()[0] = 0x11U + static_cast<uint32_t>(i);
      ms.sensor()[1] = 0x2200U + static_cast<uint32_t>(i);
      ms.motorstate() = 0x40000000U | static_cast<uint32_t>(i);
      for (size_t r = 0; r < 4; ++r) {
        ms.reserve()[r] = 0x9000U + static_cast<uint32_t>(i * 4 + r);
      }
    }
    for (size_t i = 0; i < 40; ++i) {
      m.wireless_remote()[i] = static_cast<uint8_t>(0x80U + i);
    }
    for (size_t i = 0; i < 4; ++i) {
      m.reserve()[i] = 0xC0DE0000U + static_cast<uint32_t>(i);
    }
    m.crc() = rhi_ref::low_state_crc(m);
    if (corrupt_crc) {
      m.crc() ^= 0x00010000U;
    }
  }

  LowState& prepared() { return state_msg_; }
  size_t deliver_prepared() { return rhi_fake::unitree::deliver<LowState>(kStateTopic, state_msg_); }
  size_t deliver_state(const StateFrame& f) {
    prepare_state(f);
    return deliver_prepared();
  }
  // The IMU travels inside LowState_.
  size_t deliver_imu(const StateFrame&) { return 1; }
  size_t deliver_prepared_imu() { return 1; }
  // A first frame that must not count as a valid state: a bad CRC.
  size_t deliver_invalid_state(const StateFrame& f) {
    prepare_state(f, true);
    return deliver_prepared();
  }

  size_t tick_writer() { return rhi_fake::unitree::tick_all_threads(); }
  uint64_t sent_messages() const { return rhi_fake::unitree::write_count(kCommandTopic); }
  static constexpr size_t command_messages_per_cycle() { return 1; }
  bool command_names_ok() const { return true; }  // slots are positions: nothing to name

  bool last_command(CommandFrame& out) {
    if (!rhi_fake::unitree::last_written<LowCmd>(kCommandTopic, cmd_msg_)) {
      return false;
    }
    out.has_gains = true;
    for (size_t i = 0; i < N; ++i) {
      const auto& mc = cmd_msg_.motor_cmd()[i];
      out.q[i] = mc.q();
      out.dq[i] = mc.dq();
      out.tau[i] = mc.tau();
      out.kp[i] = mc.kp();
      out.kd[i] = mc.kd();
      out.present[i] = true;
    }
    return true;
  }
  // The last LowCmd_ the robot received (fetched again on every call).
  const LowCmd& last_raw_command() {
    rhi_fake::unitree::last_written<LowCmd>(kCommandTopic, cmd_msg_);
    return cmd_msg_;
  }

  // The configured command period, as the transport sees it (recurrent thread interval).
  bool writer_period_us(uint64_t& out) const {
    const auto threads = rhi_fake::unitree::threads();
    if (threads.size() != 1) {
      return false;
    }
    out = threads[0].interval_us;
    return true;
  }
  std::string network_interface() const { return rhi_fake::unitree::factory_init().network_interface; }

  void use_real_threads(bool on) { rhi_fake::unitree::use_real_threads(on); }

private:
  LowState state_msg_{};
  LowCmd cmd_msg_{};
};

}  // namespace rhi_test
