// Fake robot side of the unitree_dds transport, "go" message family (Go2, Go2-W, B2, B2-W, the
// original H1; SDK_FACTS.md section D): LowState_ frames in (every field non-zero, padding bytes
// garbage, a correct CRC computed by the independent reference over the zero-padded image), LowCmd_
// out. Selected by RHI_UNITREE_FAMILY_GO (robot_data.hpp); same interface as the hg fake
// (transport_unitree_dds.hpp), plus the family's own checks of the sent LowCmd_ and of the CRC.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <unitree/idl/go2/LowCmd_.hpp>
#include <unitree/idl/go2/LowState_.hpp>

#include "check.hpp"
#include "crc_checks.hpp"
#include "go_crc_reference.hpp"
#include "harness_common.hpp"
#include "rhi_fake/unitree.hpp"

// crc_probe.cpp: the generated CRC header's functions (compiled against the generated package).
uint32_t rhi_probe_low_cmd_crc(const unitree_go::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc(const unitree_go::msg::dds_::LowState_& msg);
uint32_t rhi_probe_low_cmd_crc_portable(const unitree_go::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc_portable(const unitree_go::msg::dds_::LowState_& msg);

namespace rhi_test {

class Transport {
public:
  // Motor health in a message of its own (EngineAI MotorDebug): none here, it travels with the state.
  static constexpr bool kHealthMessage = false;
  size_t deliver_prepared_health() { return 0; }
  using LowCmd = unitree_go::msg::dds_::LowCmd_;
  using LowState = unitree_go::msg::dds_::LowState_;
  static constexpr const char* kName = "unitree_dds";
  static constexpr bool kImuInState = true;
  static constexpr bool kHasGains = true;
  static constexpr bool kEchoesModeMachine = false;  // go messages have no mode_machine
  static constexpr size_t kSdkSlots = 20;
  static_assert(N <= kSdkSlots, "more motors than LowCmd_ slots");
  static_assert(sizeof(kMotorModes) == kSdkSlots, "robot_data.hpp: one go motor mode per LowCmd_ slot");

  // Fill the member LowState_ (no allocation): padding bytes garbage, every field non-zero, so a
  // CRC that skips any field, or hashes the padding, disagrees with the reference.
  void prepare_state(const StateFrame& f, bool corrupt_crc = false) {
    LowState& m = state_msg_;
    rhi_ref::fill_garbage(m);
    m.head()[0] = rhi_ref::go::kHead0;
    m.head()[1] = rhi_ref::go::kHead1;
    m.level_flag() = rhi_ref::go::kLowLevel;
    m.frame_reserve() = 0x5A;
    m.sn()[0] = 0x01020304U;
    m.sn()[1] = 0x05060708U;
    m.version()[0] = 0xA0B0C0D0U;
    m.version()[1] = 0x0E0F1011U;
    m.bandwidth() = 0x1234;
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
      ms.q_raw() = 1.25F + static_cast<float>(i);
      ms.dq_raw() = -1.5F - static_cast<float>(i);
      ms.ddq_raw() = 2.75F;
      ms.temperature() = static_cast<uint8_t>(i < N ? f.temperature[i] : 200.0 + static_cast<double>(i));
      ms.lost() = 0x40000000U | static_cast<uint32_t>(i);
      ms.reserve()[0] = 0x9000U + static_cast<uint32_t>(i);
      ms.reserve()[1] = 0x9100U + static_cast<uint32_t>(i);
    }
    auto& bms = m.bms_state();
    bms.version_high() = 1;
    bms.version_low() = 2;
    bms.status() = 3;
    bms.soc() = 87;
    bms.current() = -1234;
    bms.cycle() = 42;
    bms.bq_ntc() = {25, 26};
    bms.mcu_ntc() = {27, 28};
    for (size_t i = 0; i < 15; ++i) {
      bms.cell_vol()[i] = static_cast<uint16_t>(3700 + i);
    }
    for (size_t i = 0; i < 4; ++i) {
      m.foot_force()[i] = static_cast<int16_t>(100 + i);
      m.foot_force_est()[i] = static_cast<int16_t>(-100 - static_cast<int>(i));
      m.fan_frequency()[i] = static_cast<uint16_t>(2000 + i);
    }
    m.tick() = 1000U + f.sequence;
    for (size_t i = 0; i < 40; ++i) {
      m.wireless_remote()[i] = static_cast<uint8_t>(0x80U + i);
    }
    m.bit_flag() = 0x3C;
    m.adc_reel() = 3.5F;
    m.temperature_ntc1() = 41;
    m.temperature_ntc2() = 42;
    m.power_v() = 28.5F;
    m.power_a() = -2.25F;
    m.reserve() = 0xC0DE0001U;
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
  int echoed_mode_machine() { return -1; }  // nothing is echoed

  // The go-specific fields of the last LowCmd_ (SDK_FACTS.md section D "Filling LowCmd_"): the
  // low-level header in every command, the YAML's motor mode in every slot, unused slots idle
  // (the SDK examples' stop values with zero gains and torque), everything else zero, CRC = reference.
  void check_raw_command(const StateFrame& /*state*/) {
    const LowCmd& raw = last_raw_command();
    CHECK_EQ(raw.head()[0], rhi_ref::go::kHead0, "LowCmd_.head[0] = 0xFE");
    CHECK_EQ(raw.head()[1], rhi_ref::go::kHead1, "LowCmd_.head[1] = 0xEF");
    CHECK_EQ(raw.level_flag(), rhi_ref::go::kLowLevel, "LowCmd_.level_flag = 0xFF (LOWLEVEL)");
    const bool header_zero = raw.frame_reserve() == 0 && raw.sn()[0] == 0 && raw.sn()[1] == 0 &&
                             raw.version()[0] == 0 && raw.version()[1] == 0 && raw.bandwidth() == 0;
    CHECK(header_zero, "LowCmd_.frame_reserve, sn, version, bandwidth left 0");
    bool tail_zero = raw.bms_cmd().off() == 0 && raw.gpio() == 0 && raw.reserve() == 0 && raw.fan()[0] == 0 &&
                     raw.fan()[1] == 0;
    for (uint8_t b : raw.bms_cmd().reserve()) tail_zero = tail_zero && b == 0;
    for (uint8_t b : raw.wireless_remote()) tail_zero = tail_zero && b == 0;
    for (uint8_t b : raw.led()) tail_zero = tail_zero && b == 0;
    CHECK(tail_zero, "LowCmd_.bms_cmd, wireless_remote, led, fan, gpio, reserve left 0");
    CHECK_EQ(raw.crc(), rhi_ref::low_cmd_crc(raw), "LowCmd_.crc = reference Crc32Core over the zero-padded message");
    for (size_t slot = 0; slot < kSdkSlots; ++slot) {
      const auto& mc = raw.motor_cmd()[slot];
      CHECK_EQ(mc.mode(), kMotorModes[slot], "LowCmd_.motor_cmd[%zu].mode = the YAML's motor_modes[%zu]", slot, slot);
      CHECK(mc.reserve()[0] == 0 && mc.reserve()[1] == 0 && mc.reserve()[2] == 0,
            "LowCmd_.motor_cmd[%zu].reserve left 0", slot);
      const bool mapped = slot < N && joint_of_slot(slot) != nullptr;
      if (!mapped) {
        CHECK(mc.kp() == 0.0F && mc.kd() == 0.0F && mc.tau() == 0.0F,
              "LowCmd_.motor_cmd[%zu] of an unused slot: zero gains and torque", slot);
        CHECK(mc.q() == rhi_ref::go::kPosStopF && mc.dq() == rhi_ref::go::kVelStopF,
              "LowCmd_.motor_cmd[%zu] of an unused slot: the SDK's PosStopF / VelStopF", slot);
      }
    }
  }

  // Fields changed after the CRC was computed (one per field class): the driver must drop the frame.
  static std::vector<std::pair<const char*, std::function<void(LowState&)>>> tamper_fields() {
    return {
        {"head[1]", [](LowState& m) { m.head()[1] ^= 1U; }},
        {"bandwidth", [](LowState& m) { m.bandwidth() ^= 1U; }},
        {"tick", [](LowState& m) { m.tick() += 1; }},
        {"motor_state[0].q", [](LowState& m) { m.motor_state()[0].q() += 0.25F; }},
        {"motor_state[N-1].tau_est", [](LowState& m) { m.motor_state()[N - 1].tau_est() += 1.0F; }},
        {"motor_state[19].reserve[1]", [](LowState& m) { m.motor_state()[19].reserve()[1] ^= 1U; }},
        {"imu_state.quaternion[0]", [](LowState& m) { m.imu_state().quaternion()[0] = 0.0F; }},
        {"bms_state.cell_vol[14]", [](LowState& m) { m.bms_state().cell_vol()[14] ^= 1U; }},
        {"temperature_ntc2", [](LowState& m) { m.temperature_ntc2() ^= 1U; }},
        {"reserve", [](LowState& m) { m.reserve() ^= 1U; }},
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
};

// Section crc (no driver): the reference reproduces SDK_FACTS.md's go vectors, the generated
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
  namespace go = rhi_ref::go;
  static const uint32_t zeros[294] = {};
  CHECK_EQ(rhi_ref::Crc32Core(zeros, 202), 0x4B5A4880U, "reference: 202 zero words");
  CHECK_EQ(rhi_ref::Crc32Core(zeros, 294), 0x85F11EA6U, "reference: 294 zero words");
  LowCmd vector_cmd{};
  vector_cmd.head()[0] = go::kHead0;
  vector_cmd.head()[1] = go::kHead1;
  vector_cmd.level_flag() = go::kLowLevel;
  for (auto& m : vector_cmd.motor_cmd()) {
    m.mode() = 1;
  }
  const go::LowCmdRaw image = go::mirror(vector_cmd);
  uint32_t word0 = 0;
  std::memcpy(&word0, &image, sizeof(word0));
  CHECK_EQ(word0, 0x00FFEFFEU, "reference: word 0 with head FE EF, level_flag FF");
  CHECK_EQ(rhi_ref::low_cmd_crc(vector_cmd), 0x57ECF19DU, "reference: LowCmd_ head, level_flag, every mode=1");
  LowCmd stop_cmd = vector_cmd;
  for (auto& m : stop_cmd.motor_cmd()) {
    m.q() = go::kPosStopF;
    m.dq() = go::kVelStopF;
  }
  uint32_t stop_bits = 0;
  std::memcpy(&stop_bits, &go::kPosStopF, sizeof(stop_bits));
  CHECK_EQ(stop_bits, 0x4EFFD2B9U, "PosStopF bits");
  CHECK_EQ(rhi_ref::low_cmd_crc(stop_cmd), 0x06E577CDU, "reference: + every q=PosStopF, dq=VelStopF");
  // The generated CRC agrees with them.
  CHECK_EQ(rhi_probe_low_cmd_crc(LowCmd{}), 0x4B5A4880U, "generated: zero LowCmd_");
  CHECK_EQ(rhi_probe_low_state_crc(LowState{}), 0x85F11EA6U, "generated: zero LowState_");
  CHECK_EQ(rhi_probe_low_cmd_crc(vector_cmd), 0x57ECF19DU, "generated: LowCmd_ head, level_flag, every mode=1");
  CHECK_EQ(rhi_probe_low_cmd_crc(stop_cmd), 0x06E577CDU, "generated: + every q=PosStopF, dq=VelStopF");

  // Every field counts: changing any one changes the CRC, and generated = reference.
  LowCmd base;
  rhi_ref::fill_garbage(base);  // padding garbage; every field is set below
  base.head() = {go::kHead0, go::kHead1};
  base.level_flag() = go::kLowLevel;
  base.frame_reserve() = 3;
  base.sn() = {11U, 12U};
  base.version() = {13U, 14U};
  base.bandwidth() = 15;
  for (size_t i = 0; i < 20; ++i) {
    auto& m = base.motor_cmd()[i];
    m.mode() = static_cast<uint8_t>(i % 2 == 0 ? 0x01 : 0x0A);
    m.q() = 0.1F * static_cast<float>(i);
    m.dq() = -0.2F * static_cast<float>(i);
    m.tau() = 0.3F;
    m.kp() = 40.0F + static_cast<float>(i);
    m.kd() = 1.5F;
    m.reserve() = {7U + static_cast<uint32_t>(i), 8U, 9U};
  }
  base.bms_cmd().off() = 0xA5;
  base.bms_cmd().reserve() = {1, 2, 3};
  for (size_t i = 0; i < 40; ++i) base.wireless_remote()[i] = static_cast<uint8_t>(i + 1);
  for (size_t i = 0; i < 12; ++i) base.led()[i] = static_cast<uint8_t>(0x40 + i);
  base.fan() = {5, 6};
  base.gpio() = 7;
  base.reserve() = 0x11223344U;
  base.crc() = 0;
  const FieldChanges<LowCmd> cmd_fields = {
      {"head[0]", [](LowCmd& m) { m.head()[0] ^= 1U; }},
      {"head[1]", [](LowCmd& m) { m.head()[1] ^= 1U; }},
      {"level_flag", [](LowCmd& m) { m.level_flag() = 0xEE; }},
      {"frame_reserve", [](LowCmd& m) { m.frame_reserve() ^= 1U; }},
      {"sn[1]", [](LowCmd& m) { m.sn()[1] ^= 1U; }},
      {"version[0]", [](LowCmd& m) { m.version()[0] ^= 1U; }},
      {"bandwidth", [](LowCmd& m) { m.bandwidth() ^= 0x100U; }},
      {"motor_cmd[0].mode", [](LowCmd& m) { m.motor_cmd()[0].mode() = 0; }},
      {"motor_cmd[0].q", [](LowCmd& m) { m.motor_cmd()[0].q() += 1.0F; }},
      {"motor_cmd[12].dq", [](LowCmd& m) { m.motor_cmd()[12].dq() += 1.0F; }},
      {"motor_cmd[15].tau", [](LowCmd& m) { m.motor_cmd()[15].tau() += 1.0F; }},
      {"motor_cmd[5].kp", [](LowCmd& m) { m.motor_cmd()[5].kp() += 1.0F; }},
      {"motor_cmd[6].kd", [](LowCmd& m) { m.motor_cmd()[6].kd() += 1.0F; }},
      {"motor_cmd[19].q", [](LowCmd& m) { m.motor_cmd()[19].q() = 3.0F; }},
      {"motor_cmd[9].reserve[0]", [](LowCmd& m) { m.motor_cmd()[9].reserve()[0] ^= 0x80000000U; }},
      {"motor_cmd[19].reserve[2]", [](LowCmd& m) { m.motor_cmd()[19].reserve()[2] ^= 1U; }},
      {"bms_cmd.off", [](LowCmd& m) { m.bms_cmd().off() ^= 1U; }},
      {"bms_cmd.reserve[2]", [](LowCmd& m) { m.bms_cmd().reserve()[2] ^= 1U; }},
      {"wireless_remote[39]", [](LowCmd& m) { m.wireless_remote()[39] ^= 1U; }},
      {"led[11]", [](LowCmd& m) { m.led()[11] ^= 1U; }},
      {"fan[1]", [](LowCmd& m) { m.fan()[1] ^= 1U; }},
      {"gpio", [](LowCmd& m) { m.gpio() ^= 1U; }},
      {"reserve", [](LowCmd& m) { m.reserve() ^= 0x100U; }},
  };
  const uint32_t base_crc = rhi_probe_low_cmd_crc(base);
  CHECK(rhi_ref::raw_image_crc(base) != rhi_ref::low_cmd_crc(base), "the LowCmd_ under test carries garbage padding");
  CHECK_EQ(base_crc, rhi_ref::low_cmd_crc(base), "generated = reference for a LowCmd_ with every field set, "
           "garbage padding (the padding is not hashed as it is)");
  check_every_field_counts("LowCmd_", base, cmd_fields, gen_cmd, portable_cmd, ref_cmd);
  LowCmd with_crc = base;
  with_crc.crc() = 0xDEADBEEFU;
  CHECK_EQ(rhi_probe_low_cmd_crc(with_crc), base_crc, "the crc field itself is not part of the CRC");

  Transport filler;
  filler.prepare_state(distinct_state(0));
  const LowState& state_base = filler.prepared();  // the fake's frame itself: its padding is garbage
  CHECK(rhi_ref::raw_image_crc(state_base) != rhi_ref::low_state_crc(state_base),
        "the fake robot's LowState_ carries garbage padding");
  const uint32_t state_crc = rhi_probe_low_state_crc(state_base);
  CHECK_EQ(state_crc, rhi_ref::low_state_crc(state_base), "generated = reference for a LowState_ with every field "
           "set, garbage padding");
  const FieldChanges<LowState> state_fields = {
      {"head[0]", [](LowState& m) { m.head()[0] ^= 1U; }},
      {"level_flag", [](LowState& m) { m.level_flag() ^= 1U; }},
      {"frame_reserve", [](LowState& m) { m.frame_reserve() ^= 1U; }},
      {"sn[0]", [](LowState& m) { m.sn()[0] ^= 1U; }},
      {"version[1]", [](LowState& m) { m.version()[1] ^= 1U; }},
      {"bandwidth", [](LowState& m) { m.bandwidth() ^= 1U; }},
      {"imu_state.quaternion[3]", [](LowState& m) { m.imu_state().quaternion()[3] += 1.0F; }},
      {"imu_state.gyroscope[0]", [](LowState& m) { m.imu_state().gyroscope()[0] += 1.0F; }},
      {"imu_state.accelerometer[2]", [](LowState& m) { m.imu_state().accelerometer()[2] += 1.0F; }},
      {"imu_state.rpy[1]", [](LowState& m) { m.imu_state().rpy()[1] += 1.0F; }},
      {"imu_state.temperature", [](LowState& m) { m.imu_state().temperature() ^= 1U; }},
      {"motor_state[0].mode", [](LowState& m) { m.motor_state()[0].mode() ^= 1U; }},
      {"motor_state[1].q", [](LowState& m) { m.motor_state()[1].q() += 1.0F; }},
      {"motor_state[2].dq", [](LowState& m) { m.motor_state()[2].dq() += 1.0F; }},
      {"motor_state[3].ddq", [](LowState& m) { m.motor_state()[3].ddq() += 1.0F; }},
      {"motor_state[4].tau_est", [](LowState& m) { m.motor_state()[4].tau_est() += 1.0F; }},
      {"motor_state[5].q_raw", [](LowState& m) { m.motor_state()[5].q_raw() += 1.0F; }},
      {"motor_state[6].dq_raw", [](LowState& m) { m.motor_state()[6].dq_raw() += 1.0F; }},
      {"motor_state[7].ddq_raw", [](LowState& m) { m.motor_state()[7].ddq_raw() += 1.0F; }},
      {"motor_state[8].temperature", [](LowState& m) { m.motor_state()[8].temperature() ^= 1U; }},
      {"motor_state[9].lost", [](LowState& m) { m.motor_state()[9].lost() ^= 1U; }},
      {"motor_state[19].reserve[1]", [](LowState& m) { m.motor_state()[19].reserve()[1] ^= 1U; }},
      {"bms_state.version_high", [](LowState& m) { m.bms_state().version_high() ^= 1U; }},
      {"bms_state.soc", [](LowState& m) { m.bms_state().soc() ^= 1U; }},
      {"bms_state.current", [](LowState& m) { m.bms_state().current() ^= 1; }},
      {"bms_state.cycle", [](LowState& m) { m.bms_state().cycle() ^= 1U; }},
      {"bms_state.bq_ntc[1]", [](LowState& m) { m.bms_state().bq_ntc()[1] ^= 1U; }},
      {"bms_state.mcu_ntc[0]", [](LowState& m) { m.bms_state().mcu_ntc()[0] ^= 1U; }},
      {"bms_state.cell_vol[14]", [](LowState& m) { m.bms_state().cell_vol()[14] ^= 1U; }},
      {"foot_force[0]", [](LowState& m) { m.foot_force()[0] ^= 1; }},
      {"foot_force_est[3]", [](LowState& m) { m.foot_force_est()[3] ^= 1; }},
      {"tick", [](LowState& m) { m.tick() += 1U; }},
      {"wireless_remote[39]", [](LowState& m) { m.wireless_remote()[39] ^= 1U; }},
      {"bit_flag", [](LowState& m) { m.bit_flag() ^= 1U; }},
      {"adc_reel", [](LowState& m) { m.adc_reel() += 1.0F; }},
      {"temperature_ntc1", [](LowState& m) { m.temperature_ntc1() ^= 1U; }},
      {"temperature_ntc2", [](LowState& m) { m.temperature_ntc2() ^= 1U; }},
      {"power_v", [](LowState& m) { m.power_v() += 1.0F; }},
      {"power_a", [](LowState& m) { m.power_a() += 1.0F; }},
      {"fan_frequency[3]", [](LowState& m) { m.fan_frequency()[3] ^= 1U; }},
      {"reserve", [](LowState& m) { m.reserve() ^= 1U; }},
  };
  check_every_field_counts("LowState_", state_base, state_fields, gen_state, portable_state, ref_state);

  // Random frames, padding included: generated = reference on every one.
  std::mt19937 rng(0x60F00DU);
  constexpr int kRandomFrames = 200;
  CHECK_EQ(check_random_frames<LowCmd>("LowCmd_", rng, kRandomFrames, gen_cmd, portable_cmd, ref_cmd), 0,
           "random LowCmd_ frames have non-zero padding (the test can see a padding bug)");
  check_random_frames<LowState>("LowState_", rng, kRandomFrames, gen_state, portable_state, ref_state);
}

}  // namespace rhi_test
