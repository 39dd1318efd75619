// Exposes the generated CRC header's functions to driver_harness.cpp, which checks them against
// SDK_FACTS.md's test vectors and the independent references (hg_crc_reference.hpp,
// go_crc_reference.hpp). Compiled against the generated package; RHI_CRC_HEADER names the header
// of the robot's message family and RHI_UNITREE_FAMILY_GO / _HG the family (set by cpp_build.py).
#include <cstdint>

#include RHI_CRC_HEADER

#if defined(RHI_UNITREE_FAMILY_GO)
#define RHI_PROBE_NS unitree_go
#else
#define RHI_PROBE_NS unitree_hg
#endif

uint32_t rhi_probe_low_cmd_crc(const ::RHI_PROBE_NS::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc(const ::RHI_PROBE_NS::msg::dds_::LowState_& msg);

uint32_t rhi_probe_low_cmd_crc(const ::RHI_PROBE_NS::msg::dds_::LowCmd_& msg) {
  return robot_hardware_interface::RHI_PROBE_NS::low_cmd_crc(msg);
}

uint32_t rhi_probe_low_state_crc(const ::RHI_PROBE_NS::msg::dds_::LowState_& msg) {
  return robot_hardware_interface::RHI_PROBE_NS::low_state_crc(msg);
}

// The portable slicing-by-8 implementation alone (what CPUs without carry-less multiplication
// run), so that both of the header's paths are checked on any machine.
uint32_t rhi_probe_low_cmd_crc_portable(const ::RHI_PROBE_NS::msg::dds_::LowCmd_& msg);
uint32_t rhi_probe_low_state_crc_portable(const ::RHI_PROBE_NS::msg::dds_::LowState_& msg);

uint32_t rhi_probe_low_cmd_crc_portable(const ::RHI_PROBE_NS::msg::dds_::LowCmd_& msg) {
  namespace crc = robot_hardware_interface::unitree_crc;
  return crc::masked_crc_portable(crc::kInitialValue, reinterpret_cast<const unsigned char*>(&msg),
                                robot_hardware_interface::RHI_PROBE_NS::kLowCmdMasks, 0);
}

uint32_t rhi_probe_low_state_crc_portable(const ::RHI_PROBE_NS::msg::dds_::LowState_& msg) {
  namespace crc = robot_hardware_interface::unitree_crc;
  return crc::masked_crc_portable(crc::kInitialValue, reinterpret_cast<const unsigned char*>(&msg),
                                robot_hardware_interface::RHI_PROBE_NS::kLowStateMasks, 0);
}
