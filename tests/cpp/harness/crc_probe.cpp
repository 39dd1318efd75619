// Exposes the generated CRC header's functions to driver_harness.cpp, which checks them against
// SDK_FACTS.md's test vectors and the independent reference (hg_crc_reference.hpp).
// Compiled against the generated package; RHI_CRC_HEADER names the header (set by cpp_build.py).
#include <cstdint>

#include RHI_CRC_HEADER

uint32_t rhi_probe_low_cmd_crc(const unitree_hg::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc(const unitree_hg::msg::dds_::LowState_& msg);

uint32_t rhi_probe_low_cmd_crc(const unitree_hg::msg::dds_::LowCmd_& msg) {
  return robot_hardware_interface::unitree_hg::lowCmdCrc(msg);
}

uint32_t rhi_probe_low_state_crc(const unitree_hg::msg::dds_::LowState_& msg) {
  return robot_hardware_interface::unitree_hg::lowStateCrc(msg);
}

// The portable slicing-by-8 implementation alone (what CPUs without carry-less multiplication
// run), so that both of the header's paths are checked on any machine.
uint32_t rhi_probe_low_cmd_crc_portable(const unitree_hg::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc_portable(const unitree_hg::msg::dds_::LowState_& msg);

uint32_t rhi_probe_low_cmd_crc_portable(const unitree_hg::msg::dds_::LowCmd_& msg) {
  namespace crc = robot_hardware_interface::unitree_crc;
  return crc::maskedCrcPortable(crc::kInitialValue, reinterpret_cast<const unsigned char*>(&msg),
                                robot_hardware_interface::unitree_hg::kLowCmdMasks, 0);
}

uint32_t rhi_probe_low_state_crc_portable(const unitree_hg::msg::dds_::LowState_& msg) {
  namespace crc = robot_hardware_interface::unitree_crc;
  return crc::maskedCrcPortable(crc::kInitialValue, reinterpret_cast<const unsigned char*>(&msg),
                                robot_hardware_interface::unitree_hg::kLowStateMasks, 0);
}
