#!/usr/bin/env python3
"""Writes the unitree_sdk2 IDL stand-ins under ../include: the "hg" family (unitree/idl/hg/*_.hpp,
namespace unitree_hg) and the "go" family (unitree/idl/go2/*_.hpp, namespace unitree_go).

Shape of the Cyclone DDS idlcxx output used by unitree_sdk2 (checked against the SDK's
include/unitree/idl/hg/{HandCmd_,PressSensorState_,AgvBmsState_}.hpp): namespace
unitree_hg::msg::dds_, a class with private members `name_` (primitives `= 0`, arrays `= { }`),
`Name_() = default`, an explicit all-members constructor, and per member
  primitive: `T name() const`, `T& name()`, `void name(T)`
  other:     `const T& name() const`, `T& name()`, `void name(const T&)`, `void name(T&&)`
plus operator== / operator!=. Member order/types from SDK_FACTS.md sections A and D (= unitree_ros2
unitree_hg / unitree_go msgs; the go IDL uses uint8_t where the .msg files say int8).
The DDS type-support parts of the real headers are omitted.
"""
from __future__ import annotations

from pathlib import Path

INCLUDE = Path(__file__).resolve().parent.parent / "include"
NS = "::unitree_hg::msg::dds_::"
GO = "::unitree_go::msg::dds_::"
PRIMITIVES = {"uint8_t", "int16_t", "uint16_t", "int32_t", "uint32_t", "float"}

HG_TYPES = {
    "MotorCmd_": ([("uint8_t", "mode"), ("float", "q"), ("float", "dq"), ("float", "tau"),
                   ("float", "kp"), ("float", "kd"), ("uint32_t", "reserve")], [], 28),
    "MotorState_": ([("uint8_t", "mode"), ("float", "q"), ("float", "dq"), ("float", "ddq"),
                     ("float", "tau_est"), ("std::array<int16_t, 2>", "temperature"), ("float", "vol"),
                     ("std::array<uint32_t, 2>", "sensor"), ("uint32_t", "motorstate"),
                     ("std::array<uint32_t, 4>", "reserve")], [], 56),
    "IMUState_": ([("std::array<float, 4>", "quaternion"), ("std::array<float, 3>", "gyroscope"),
                   ("std::array<float, 3>", "accelerometer"), ("std::array<float, 3>", "rpy"),
                   ("int16_t", "temperature")], [], 56),
    "LowCmd_": ([("uint8_t", "mode_pr"), ("uint8_t", "mode_machine"),
                 (f"std::array<{NS}MotorCmd_, 35>", "motor_cmd"), ("std::array<uint32_t, 4>", "reserve"),
                 ("uint32_t", "crc")], ["MotorCmd_"], 1004),
    "LowState_": ([("std::array<uint32_t, 2>", "version"), ("uint8_t", "mode_pr"),
                   ("uint8_t", "mode_machine"), ("uint32_t", "tick"), (f"{NS}IMUState_", "imu_state"),
                   (f"std::array<{NS}MotorState_, 35>", "motor_state"),
                   ("std::array<uint8_t, 40>", "wireless_remote"), ("std::array<uint32_t, 4>", "reserve"),
                   ("uint32_t", "crc")], ["IMUState_", "MotorState_"], 2092),
    # Dex3-1 hands (unitree_sdk2 include/unitree/idl/hg/HandCmd_.hpp, HandState_.hpp, PressSensorState_.hpp):
    # IDL sequences (std::vector), no crc; size None = no fixed layout.
    "PressSensorState_": ([("std::array<float, 12>", "pressure"), ("std::array<float, 12>", "temperature"),
                           ("uint32_t", "lost"), ("uint32_t", "reserve")], [], 104),
    "HandCmd_": ([(f"std::vector<{NS}MotorCmd_>", "motor_cmd"), ("std::array<uint32_t, 4>", "reserve")],
                 ["MotorCmd_"], None),
    "HandState_": ([(f"std::vector<{NS}MotorState_>", "motor_state"),
                    (f"std::vector<{NS}PressSensorState_>", "press_sensor_state"), (f"{NS}IMUState_", "imu_state"),
                    ("float", "power_v"), ("float", "power_a"), ("float", "system_v"), ("float", "device_v"),
                    ("std::array<uint32_t, 2>", "error"), ("std::array<uint32_t, 2>", "reserve")],
                   ["MotorState_", "PressSensorState_", "IMUState_"], None),
}

GO_HEADER = [("std::array<uint8_t, 2>", "head"), ("uint8_t", "level_flag"), ("uint8_t", "frame_reserve"),
             ("std::array<uint32_t, 2>", "sn"), ("std::array<uint32_t, 2>", "version"), ("uint16_t", "bandwidth")]
GO_TYPES = {
    "MotorCmd_": ([("uint8_t", "mode"), ("float", "q"), ("float", "dq"), ("float", "tau"),
                   ("float", "kp"), ("float", "kd"), ("std::array<uint32_t, 3>", "reserve")], [], 36),
    "BmsCmd_": ([("uint8_t", "off"), ("std::array<uint8_t, 3>", "reserve")], [], 4),
    "MotorState_": ([("uint8_t", "mode"), ("float", "q"), ("float", "dq"), ("float", "ddq"),
                     ("float", "tau_est"), ("float", "q_raw"), ("float", "dq_raw"), ("float", "ddq_raw"),
                     ("uint8_t", "temperature"), ("uint32_t", "lost"), ("std::array<uint32_t, 2>", "reserve")],
                    [], 48),
    "IMUState_": ([("std::array<float, 4>", "quaternion"), ("std::array<float, 3>", "gyroscope"),
                   ("std::array<float, 3>", "accelerometer"), ("std::array<float, 3>", "rpy"),
                   ("uint8_t", "temperature")], [], 56),
    "BmsState_": ([("uint8_t", "version_high"), ("uint8_t", "version_low"), ("uint8_t", "status"),
                   ("uint8_t", "soc"), ("int32_t", "current"), ("uint16_t", "cycle"),
                   ("std::array<uint8_t, 2>", "bq_ntc"), ("std::array<uint8_t, 2>", "mcu_ntc"),
                   ("std::array<uint16_t, 15>", "cell_vol")], [], 44),
    "LowCmd_": ([*GO_HEADER, (f"std::array<{GO}MotorCmd_, 20>", "motor_cmd"), (f"{GO}BmsCmd_", "bms_cmd"),
                             ("std::array<uint8_t, 40>", "wireless_remote"), ("std::array<uint8_t, 12>", "led"),
                             ("std::array<uint8_t, 2>", "fan"), ("uint8_t", "gpio"), ("uint32_t", "reserve"),
                             ("uint32_t", "crc")], ["MotorCmd_", "BmsCmd_"], 812),
    "LowState_": ([*GO_HEADER, (f"{GO}IMUState_", "imu_state"), (f"std::array<{GO}MotorState_, 20>", "motor_state"),
                               (f"{GO}BmsState_", "bms_state"), ("std::array<int16_t, 4>", "foot_force"),
                               ("std::array<int16_t, 4>", "foot_force_est"), ("uint32_t", "tick"),
                               ("std::array<uint8_t, 40>", "wireless_remote"), ("uint8_t", "bit_flag"),
                               ("float", "adc_reel"), ("uint8_t", "temperature_ntc1"),
                               ("uint8_t", "temperature_ntc2"), ("float", "power_v"), ("float", "power_a"),
                               ("std::array<uint16_t, 4>", "fan_frequency"), ("uint32_t", "reserve"),
                               ("uint32_t", "crc")], ["IMUState_", "MotorState_", "BmsState_"], 1180),
}
FAMILIES = (("hg", "unitree_hg", "hg", HG_TYPES), ("go", "unitree_go", "go2", GO_TYPES))


def render(name: str, members, deps, size: int | None, namespace: str = "unitree_hg", folder: str = "hg") -> str:
    guard = f"DDSCXX_UNITREE_IDL_{folder.upper()}_{name.upper()}_HPP"
    out = [
        "// rhi-gen test stand-in (not the real unitree_sdk2): Cyclone-DDS-style C++ class of the",
        f"// {namespace} {name} IDL type. Generated by tests/cpp/standins/tools/gen_unitree_idl.py.",
        f"#ifndef {guard}",
        f"#define {guard}",
        "",
        "#include <array>",
        "#include <cstddef>",
        "#include <cstdint>",
        "#include <type_traits>",
        "#include <utility>",
    ]
    if any(t.startswith("std::vector") for t, _ in members):
        out.append("#include <vector>")
    out += [f'#include "unitree/idl/{folder}/{d}.hpp"' for d in deps]
    out += ["", f"namespace {namespace}", "{", "namespace msg", "{", "namespace dds_", "{",
            f"class {name}", "{", "private:"]
    for t, m in members:
        if t in PRIMITIVES:
            out.append(f" {t} {m}_ = 0;")
        elif t.startswith("std::array"):
            out.append(f" {t} {m}_ = {{ }};")
        else:
            out.append(f" {t} {m}_;")
    out += ["", "public:", f"  {name}() = default;", "", f"  explicit {name}("]
    params = []
    for t, m in members:
        params.append(f"    {t} {m}" if t in PRIMITIVES else f"    const {t}& {m}")
    out.append(",\n".join(params) + ") :")
    out.append(",\n".join(f"    {m}_({m})" for _, m in members) + " { }")
    out.append("")
    for t, m in members:
        if t in PRIMITIVES:
            out += [
                f"  {t} {m}() const {{ return this->{m}_; }}",
                f"  {t}& {m}() {{ return this->{m}_; }}",
                f"  void {m}({t} _val_) {{ this->{m}_ = _val_; }}",
            ]
        else:
            out += [
                f"  const {t}& {m}() const {{ return this->{m}_; }}",
                f"  {t}& {m}() {{ return this->{m}_; }}",
                f"  void {m}(const {t}& _val_) {{ this->{m}_ = _val_; }}",
                f"  void {m}({t}&& _val_) {{ this->{m}_ = _val_; }}",
            ]
    out += ["", f"  bool operator==(const {name}& _other) const", "  {", "    (void) _other;"]
    out.append("    return " + " &&\n      ".join(f"{m}_ == _other.{m}_" for _, m in members) + ";")
    out += ["  }", "", f"  bool operator!=(const {name}& _other) const", "  {",
            "    return !(*this == _other);", "  }", "", "};", "", "}", "", "}", "", "}", ""]
    if size is None:  # holds a sequence: no fixed layout, no CRC
        out += [f"#endif  // {guard}", ""]
        return "\n".join(out)
    out += [
        "// Layout checks (x86-64 g++): the CRC of the SDK is computed over the raw bytes.",
        (f"static_assert(sizeof(::{namespace}::msg::dds_::{name}) == {size}, "
         f"\"{namespace} {name} must be {size} bytes\");"),
        (f"static_assert(std::is_standard_layout<::{namespace}::msg::dds_::{name}>::value, "
         f"\"{namespace} {name} must be standard layout\");"),
        (f"static_assert(std::is_trivially_copyable<::{namespace}::msg::dds_::{name}>::value, "
         f"\"{namespace} {name} must be trivially copyable\");"),
    ]
    if any(m == "crc" for _, m in members):
        out.append(
            f"static_assert(sizeof(::{namespace}::msg::dds_::{name}) % 4 == 0, "
            f"\"{name}: whole 32-bit words\");")
    out += ["", f"#endif  // {guard}", ""]
    return "\n".join(out)


def main() -> None:
    for _, namespace, folder, types in FAMILIES:
        for name, (members, deps, size) in types.items():
            path = INCLUDE / "unitree" / "idl" / folder / f"{name}.hpp"
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(render(name, members, deps, size, namespace, folder))
            print("wrote", path.relative_to(INCLUDE))


if __name__ == "__main__":
    main()
