// Fake robot side of the unitree_dds transport, "hg" message family (G1, H1-2; SDK_FACTS.md section
// A): LowState_ frames in (every field non-zero, padding bytes garbage, a correct CRC computed by
// the independent reference over the zero-padded image), LowCmd_ out. The go family has its own
// fake (transport_unitree_go.hpp, selected by RHI_UNITREE_FAMILY_GO) with the same interface.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <unitree/idl/hg/LowCmd_.hpp>
#include <unitree/idl/hg/LowState_.hpp>
#if defined(RHI_DEX3)
#include <unitree/idl/hg/HandCmd_.hpp>
#include <unitree/idl/hg/HandState_.hpp>
#endif

#include "check.hpp"
#include "crc_checks.hpp"
#include "harness_common.hpp"
#include "hg_crc_reference.hpp"
#include "rhi_fake/unitree.hpp"

// crc_probe.cpp: the generated CRC header's functions (compiled against the generated package).
uint32_t rhi_probe_low_cmd_crc(const unitree_hg::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc(const unitree_hg::msg::dds_::LowState_& msg);
uint32_t rhi_probe_low_cmd_crc_portable(const unitree_hg::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc_portable(const unitree_hg::msg::dds_::LowState_& msg);

namespace rhi_test {

class Transport {
public:
  // Motor health in a message of its own (EngineAI MotorDebug): none here, it travels with the state.
  static constexpr bool kHealthMessage = false;
  size_t deliver_prepared_health() { return 0; }
  using LowCmd = unitree_hg::msg::dds_::LowCmd_;
  using LowState = unitree_hg::msg::dds_::LowState_;
  static constexpr const char* kName = "unitree_dds";
  static constexpr bool kImuInState = true;
  static constexpr bool kHasGains = true;
  static constexpr bool kEchoesModeMachine = true;  // LowCmd_.mode_machine echoes LowState_'s
  static constexpr size_t kSdkSlots = 35;
#if defined(RHI_DEX3)
  // hands: dex3, each hand's 7 motors on its own HandCmd_ / HandState_ after the LowCmd_ slots
  // (the harness's own reading of unitree_sdk2's g1_dex3_example: left 35..41, right 42..48)
  using HandCmd = unitree_hg::msg::dds_::HandCmd_;
  using HandState = unitree_hg::msg::dds_::HandState_;
  static constexpr size_t kHandMotors = 7;
  static constexpr size_t kHandSlots = 2 * kHandMotors;
  static constexpr size_t hand_slot(size_t side, size_t id) { return kSdkSlots + side * kHandMotors + id; }
  // MotorCmd_.mode of hand motor `id`: id | status 1 << 4, timeout bit 0
  static constexpr uint8_t hand_mode(size_t id) { return static_cast<uint8_t>(id | (1U << 4)); }
#else
  static constexpr size_t kHandSlots = 0;
#endif
  static constexpr size_t kBodySlots = N < kSdkSlots ? N : kSdkSlots;
  static_assert(N <= kSdkSlots + kHandSlots, "more motors than LowCmd_ slots");

  // Fill the member LowState_ (no allocation): padding bytes garbage, every field non-zero, so a
  // CRC that skips any field, or hashes the padding, disagrees with the reference.
  void prepare_state(const StateFrame& f, bool corrupt_crc = false) {
    LowState& m = state_msg_;
    rhi_ref::fill_garbage(m);  // every field is set below: only the padding keeps it
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
#if defined(RHI_DEX3)
    prepare_hands(f);
#endif
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
      // motor health: the frame's for the robot's slots, garbage beyond
      ms.temperature()[0] = static_cast<int16_t>(i < N ? f.temperature[i] : 300.0 + static_cast<double>(i));
      ms.temperature()[1] = static_cast<int16_t>(-5 - static_cast<int>(i));
      ms.vol() = i < N ? static_cast<float>(f.voltage[i]) : 99.5F;
      ms.sensor()[0] = 0x11U + static_cast<uint32_t>(i);
      ms.sensor()[1] = 0x2200U + static_cast<uint32_t>(i);
      ms.motorstate() = i < N ? static_cast<uint32_t>(f.error_code[i]) : 0x40000000U | static_cast<uint32_t>(i);
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
  // The hands' states first (when the robot has hands), then the body's, which carries them to read().
  size_t deliver_prepared() {
#if defined(RHI_DEX3)
    for (size_t side = 0; side < 2; ++side) {
      rhi_fake::unitree::deliver<HandState>(rhi_data::kHandStateTopics[side], hand_state_msgs_[side]);
    }
#endif
    return rhi_fake::unitree::deliver<LowState>(kStateTopic, state_msg_);
  }
#if defined(RHI_DEX3)
  // Each hand's HandState_ from the frame's hand slots: 7 motors, 9 pressure sensors (SENSOR_MAX of
  // the SDK example), every other field non-zero.
  void prepare_hands(const StateFrame& f) {
    for (size_t side = 0; side < 2; ++side) {
      HandState& h = hand_state_msgs_[side];
      h.motor_state().resize(kHandMotors);
      h.press_sensor_state().resize(9);
      for (size_t id = 0; id < kHandMotors; ++id) {
        const size_t slot = hand_slot(side, id);
        auto& ms = h.motor_state()[id];
        ms.mode() = hand_mode(id);
        ms.q() = static_cast<float>(f.q[slot]);
        ms.dq() = static_cast<float>(f.dq[slot]);
        ms.tau_est() = static_cast<float>(f.tau[slot]);
        ms.ddq() = 0.25F;
        ms.temperature()[0] = static_cast<int16_t>(f.temperature[slot]);
        ms.temperature()[1] = 21;
        ms.vol() = static_cast<float>(f.voltage[slot]);
        ms.motorstate() = static_cast<uint32_t>(f.error_code[slot]);
      }
      for (auto& sensor : h.press_sensor_state()) {
        sensor.pressure().fill(1.5F);
        sensor.temperature().fill(30.0F);
      }
      h.imu_state().quaternion()[0] = 1.0F;
      h.power_v() = 24.0F;
      h.power_a() = 0.5F;
      h.system_v() = 24.0F;
      h.device_v() = 5.0F;
    }
  }
  HandState& prepared_hand(size_t side) { return hand_state_msgs_[side]; }
  size_t deliver_prepared_hand(size_t side) {
    return rhi_fake::unitree::deliver<HandState>(rhi_data::kHandStateTopics[side], hand_state_msgs_[side]);
  }
  // The last HandCmd_ hand `side` received (false before the first).
  bool last_hand_command(size_t side, HandCmd& out) const {
    return rhi_fake::unitree::last_written<HandCmd>(rhi_data::kHandCommandTopics[side], out);
  }
  uint64_t sent_hand_messages(size_t side) const {
    return rhi_fake::unitree::write_count(rhi_data::kHandCommandTopics[side]);
  }
#endif
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

  // One frame the driver must reject and count (health GPIO invalid_states): a bad CRC.
  size_t deliver_corrupt_state(const StateFrame& f) { return deliver_invalid_state(f); }

  size_t tick_writer() { return rhi_fake::unitree::tick_all_threads(); }
  uint64_t sent_messages() const { return rhi_fake::unitree::write_count(kCommandTopic); }
  static constexpr size_t command_messages_per_cycle() { return 1; }
  bool command_names_ok() const { return true; }  // slots are positions: nothing to name

  bool last_command(CommandFrame& out) {
    if (!rhi_fake::unitree::last_written<LowCmd>(kCommandTopic, cmd_msg_)) {
      return false;
    }
    out.has_gains = true;
    for (size_t i = 0; i < kBodySlots; ++i) {
      const auto& mc = cmd_msg_.motor_cmd()[i];
      out.q[i] = mc.q();
      out.dq[i] = mc.dq();
      out.tau[i] = mc.tau();
      out.kp[i] = mc.kp();
      out.kd[i] = mc.kd();
      out.present[i] = true;
    }
#if defined(RHI_DEX3)
    for (size_t side = 0; side < 2; ++side) {
      if (!last_hand_command(side, hand_cmd_msgs_[side]) || hand_cmd_msgs_[side].motor_cmd().size() != kHandMotors) {
        return false;
      }
      for (size_t id = 0; id < kHandMotors; ++id) {
        const auto& mc = hand_cmd_msgs_[side].motor_cmd()[id];
        const size_t slot = hand_slot(side, id);
        out.q[slot] = mc.q();
        out.dq[slot] = mc.dq();
        out.tau[slot] = mc.tau();
        out.kp[slot] = mc.kp();
        out.kd[slot] = mc.kd();
        out.present[slot] = true;
      }
    }
#endif
    return true;
  }
  // The last LowCmd_ the robot received (fetched again on every call).
  const LowCmd& last_raw_command() {
    rhi_fake::unitree::last_written<LowCmd>(kCommandTopic, cmd_msg_);
    return cmd_msg_;
  }
  int echoed_mode_machine() { return last_raw_command().mode_machine(); }

  // The hg-specific fields of the last LowCmd_: mode_pr from the YAML, mode_machine echoed from
  // the state, CRC = reference, driven slots enabled (mode 1), unused slots all zero.
  void check_raw_command(const StateFrame& state) {
    const LowCmd& raw = last_raw_command();
    CHECK_EQ(raw.mode_pr(), kModePr, "LowCmd_.mode_pr from the YAML");
    CHECK_EQ(raw.mode_machine(), state.mode_machine, "LowCmd_.mode_machine copied from LowState_");
    CHECK_EQ(raw.crc(), rhi_ref::low_cmd_crc(raw), "LowCmd_.crc = reference Crc32Core over the message");
    for (size_t slot = 0; slot < kSdkSlots; ++slot) {
      const bool mapped = slot < N && joint_of_slot(slot) != nullptr;
      const auto& mc = raw.motor_cmd()[slot];
      CHECK_EQ(mc.mode(), mapped ? 1 : 0, "LowCmd_.motor_cmd[%zu].mode (1 = enabled)", slot);
      if (!mapped) {
        const bool zero = mc.q() == 0.0F && mc.dq() == 0.0F && mc.tau() == 0.0F && mc.kp() == 0.0F && mc.kd() == 0.0F;
        CHECK(zero, "LowCmd_.motor_cmd[%zu] of an unused slot is all zero", slot);
      }
    }
#if defined(RHI_DEX3)
    // Each HandCmd_: 7 motors, motor i's mode = i | status 1 << 4 (timeout bit clear), reserve 0.
    for (size_t side = 0; side < 2; ++side) {
      CHECK(last_hand_command(side, hand_cmd_msgs_[side]), "hand %zu received a HandCmd_", side);
      const HandCmd& hand = hand_cmd_msgs_[side];
      CHECK_EQ(hand.motor_cmd().size(), kHandMotors, "HandCmd_ %zu carries the hand's 7 motors", side);
      for (size_t id = 0; id < hand.motor_cmd().size() && id < kHandMotors; ++id) {
        CHECK_EQ(hand.motor_cmd()[id].mode(), hand_mode(id), "HandCmd_ %zu motor %zu mode byte", side, id);
        CHECK_EQ(hand.motor_cmd()[id].reserve(), 0U, "HandCmd_ %zu motor %zu reserve", side, id);
      }
      CHECK(hand.reserve()[0] == 0U && hand.reserve()[3] == 0U, "HandCmd_ %zu reserve is zero", side);
    }
#endif
  }

  // Fields changed after the CRC was computed (one per field class): the driver must drop the frame.
  static std::vector<std::pair<const char*, std::function<void(LowState&)>>> tamper_fields() {
    return {
        {"tick", [](LowState& m) { m.tick() += 1; }},
        {"motor_state[0].q", [](LowState& m) { m.motor_state()[0].q() += 0.25F; }},
        {"motor_state[N-1].tau_est", [](LowState& m) { m.motor_state()[kBodySlots - 1].tau_est() += 1.0F; }},
        {"motor_state[34].reserve[3]", [](LowState& m) { m.motor_state()[34].reserve()[3] ^= 1U; }},
        {"imu_state.quaternion[0]", [](LowState& m) { m.imu_state().quaternion()[0] = 0.0F; }},
        {"wireless_remote[39]", [](LowState& m) { m.wireless_remote()[39] ^= 1U; }},
        {"reserve[3]", [](LowState& m) { m.reserve()[3] ^= 1U; }},
    };
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
#if defined(RHI_DEX3)
  std::array<HandState, 2> hand_state_msgs_{};
  std::array<HandCmd, 2> hand_cmd_msgs_{};
#endif
};

// Section crc (no driver): the reference reproduces SDK_FACTS.md's hg vectors, the generated
// low_cmd_crc / low_state_crc (crc_probe.cpp) agree with it on those, on every field, on frames with
// garbage padding and on random frames.
inline void check_crc_functions() {
  using LowCmd = Transport::LowCmd;
  using LowState = Transport::LowState;
  const auto gen_cmd = [](const LowCmd& m) { return rhi_probe_low_cmd_crc(m); };
  const auto portable_cmd = [](const LowCmd& m) { return rhi_probe_low_cmd_crc_portable(m); };
  const auto ref_cmd = [](const LowCmd& m) { return rhi_ref::low_cmd_crc(m); };
  const auto gen_state = [](const LowState& m) { return rhi_probe_low_state_crc(m); };
  const auto portable_state = [](const LowState& m) { return rhi_probe_low_state_crc_portable(m); };
  const auto ref_state = [](const LowState& m) { return rhi_ref::low_state_crc(m); };
  // The reference reproduces the test vectors of SDK_FACTS.md.
  static const uint32_t zeros[522] = {};
  CHECK_EQ(rhi_ref::Crc32Core(zeros, 250), 0xFE172F9FU, "reference: 250 zero words");
  CHECK_EQ(rhi_ref::Crc32Core(zeros, 522), 0xD64BB04AU, "reference: 522 zero words");
  LowCmd vector_cmd{};
  vector_cmd.mode_machine() = 5;
  for (auto& m : vector_cmd.motor_cmd()) {
    m.mode() = 1;
  }
  CHECK_EQ(rhi_ref::low_cmd_crc(vector_cmd), 0x77176F39U, "reference: LowCmd mode_machine=5, every mode=1");
  // The generated CRC agrees with them.
  CHECK_EQ(rhi_probe_low_cmd_crc(LowCmd{}), 0xFE172F9FU, "generated: zero LowCmd_");
  CHECK_EQ(rhi_probe_low_state_crc(LowState{}), 0xD64BB04AU, "generated: zero LowState_");
  CHECK_EQ(rhi_probe_low_cmd_crc(vector_cmd), 0x77176F39U, "generated: LowCmd mode_machine=5, every mode=1");

  // Every field counts: changing any one changes the CRC, and generated = reference.
  LowCmd base;
  rhi_ref::fill_garbage(base);  // padding garbage; every field is set below
  base.mode_pr() = 0;
  base.mode_machine() = 5;
  base.crc() = 0;
  for (size_t i = 0; i < 35; ++i) {
    auto& m = base.motor_cmd()[i];
    m.mode() = 1;
    m.q() = 0.1F * i;
    m.dq() = -0.2F * i;
    m.tau() = 0.3F;
    m.kp() = 40.0F + i;
    m.kd() = 1.5F;
    m.reserve() = 7U + i;
  }
  base.reserve() = {1U, 2U, 3U, 4U};
  const FieldChanges<LowCmd> cmd_fields = {
      {"mode_pr", [](LowCmd& m) { m.mode_pr() = 1; }},
      {"mode_machine", [](LowCmd& m) { m.mode_machine() = 6; }},
      {"motor_cmd[0].mode", [](LowCmd& m) { m.motor_cmd()[0].mode() = 0; }},
      {"motor_cmd[0].q", [](LowCmd& m) { m.motor_cmd()[0].q() += 1.0F; }},
      {"motor_cmd[17].dq", [](LowCmd& m) { m.motor_cmd()[17].dq() += 1.0F; }},
      {"motor_cmd[28].tau", [](LowCmd& m) { m.motor_cmd()[28].tau() += 1.0F; }},
      {"motor_cmd[5].kp", [](LowCmd& m) { m.motor_cmd()[5].kp() += 1.0F; }},
      {"motor_cmd[6].kd", [](LowCmd& m) { m.motor_cmd()[6].kd() += 1.0F; }},
      {"motor_cmd[34].q", [](LowCmd& m) { m.motor_cmd()[34].q() = 3.0F; }},
      {"motor_cmd[9].reserve", [](LowCmd& m) { m.motor_cmd()[9].reserve() ^= 0x80000000U; }},
      {"reserve[0]", [](LowCmd& m) { m.reserve()[0] ^= 1U; }},
      {"reserve[3]", [](LowCmd& m) { m.reserve()[3] ^= 0x100U; }},
  };
  const uint32_t base_crc = rhi_probe_low_cmd_crc(base);
  CHECK(rhi_ref::raw_image_crc(base) != rhi_ref::low_cmd_crc(base), "the LowCmd_ under test carries garbage padding");
  CHECK_EQ(base_crc, rhi_ref::low_cmd_crc(base), "generated = reference for a LowCmd_ with every field set");
  check_every_field_counts("LowCmd_", base, cmd_fields, gen_cmd, portable_cmd, ref_cmd);
  LowCmd with_crc = base;
  with_crc.crc() = 0xDEADBEEFU;
  CHECK_EQ(rhi_probe_low_cmd_crc(with_crc), base_crc, "the crc field itself is not part of the CRC");

  Transport filler;
  filler.prepare_state(distinct_state(0));
  const LowState& state_base = filler.prepared();  // the fake's frame itself: its padding is garbage
  CHECK(rhi_ref::raw_image_crc(state_base) != rhi_ref::low_state_crc(state_base),
        "the fake robot's LowState_ carries garbage padding");
  const FieldChanges<LowState> state_fields = {
      {"version[1]", [](LowState& m) { m.version()[1] ^= 1U; }},
      {"mode_pr", [](LowState& m) { m.mode_pr() ^= 1U; }},
      {"mode_machine", [](LowState& m) { m.mode_machine() ^= 1U; }},
      {"tick", [](LowState& m) { m.tick() += 1U; }},
      {"imu_state.quaternion[3]", [](LowState& m) { m.imu_state().quaternion()[3] += 1.0F; }},
      {"imu_state.gyroscope[0]", [](LowState& m) { m.imu_state().gyroscope()[0] += 1.0F; }},
      {"imu_state.accelerometer[2]", [](LowState& m) { m.imu_state().accelerometer()[2] += 1.0F; }},
      {"imu_state.rpy[1]", [](LowState& m) { m.imu_state().rpy()[1] += 1.0F; }},
      {"imu_state.temperature", [](LowState& m) { m.imu_state().temperature() += 1; }},
      {"motor_state[0].mode", [](LowState& m) { m.motor_state()[0].mode() ^= 1U; }},
      {"motor_state[1].q", [](LowState& m) { m.motor_state()[1].q() += 1.0F; }},
      {"motor_state[2].dq", [](LowState& m) { m.motor_state()[2].dq() += 1.0F; }},
      {"motor_state[3].ddq", [](LowState& m) { m.motor_state()[3].ddq() += 1.0F; }},
      {"motor_state[4].tau_est", [](LowState& m) { m.motor_state()[4].tau_est() += 1.0F; }},
      {"motor_state[5].temperature[1]", [](LowState& m) { m.motor_state()[5].temperature()[1] += 1; }},
      {"motor_state[6].vol", [](LowState& m) { m.motor_state()[6].vol() += 1.0F; }},
      {"motor_state[7].sensor[1]", [](LowState& m) { m.motor_state()[7].sensor()[1] ^= 1U; }},
      {"motor_state[8].motorstate", [](LowState& m) { m.motor_state()[8].motorstate() ^= 1U; }},
      {"motor_state[34].reserve[3]", [](LowState& m) { m.motor_state()[34].reserve()[3] ^= 1U; }},
      {"wireless_remote[39]", [](LowState& m) { m.wireless_remote()[39] ^= 1U; }},
      {"reserve[3]", [](LowState& m) { m.reserve()[3] ^= 1U; }},
  };
  const uint32_t state_crc = rhi_probe_low_state_crc(state_base);
  CHECK_EQ(state_crc, rhi_ref::low_state_crc(state_base), "generated = reference for a LowState_ with every field set");
  check_every_field_counts("LowState_", state_base, state_fields, gen_state, portable_state, ref_state);

  // Random frames, padding included: generated = reference on every one.
  std::mt19937 rng(0x4860F00DU);
  constexpr int kRandomFrames = 100;
  check_random_frames<LowCmd>("LowCmd_", rng, kRandomFrames, gen_cmd, portable_cmd, ref_cmd);
  check_random_frames<LowState>("LowState_", rng, kRandomFrames, gen_state, portable_state, ref_state);
}

}  // namespace rhi_test
