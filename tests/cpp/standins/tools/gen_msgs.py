#!/usr/bin/env python3
"""Writes the rosidl-style message stand-in headers under ../include.

Run from anywhere: `python3 tests/cpp/standins/tools/gen_msgs.py`. The generated headers are
checked in; rerun after editing MESSAGES. Field lists come from the .msg files (ROS 2 Humble
common_interfaces for std/geometry/sensor/builtin/lifecycle msgs; /work/shared/upstream/msgs for
aimdk_msgs and interface_protocol).

Generated shape (as rosidl_generator_cpp does for Humble):
  namespace pkg { namespace msg {
    template<class ContainerAllocator> struct Name_ { explicit Name_(MessageInitialization = ALL); ... };
    using Name = Name_<std::allocator<void>>;
  }}
with SharedPtr/ConstSharedPtr/UniquePtr/WeakPtr aliases, `static constexpr` constants, ==/!=, and
rosidl_generator_traits::is_message/name/data_type specializations. The default constructor is
explicit (so `Msg m = {};` is rejected as with real rosidl code; `Msg m{};` and `Msg m;` work).
"""
from __future__ import annotations

import re
from pathlib import Path

INCLUDE = Path(__file__).resolve().parent.parent / "include"

# (package, MessageName, [fields], [constants], [message includes])
# field: (cpp_type, name, initializer)   constant: (cpp_type, name, value)
T = "builtin_interfaces::msg::Time"
MESSAGES = [
    ("builtin_interfaces", "Time", [("int32_t", "sec", "0"), ("uint32_t", "nanosec", "0")], [], []),
    ("builtin_interfaces", "Duration", [("int32_t", "sec", "0"), ("uint32_t", "nanosec", "0")], [], []),
    ("std_msgs", "Header", [(T, "stamp", None), ("std::string", "frame_id", None)], [],
     ["builtin_interfaces/msg/time.hpp"]),
    ("geometry_msgs", "Quaternion",
     [("double", "x", "0.0"), ("double", "y", "0.0"), ("double", "z", "0.0"), ("double", "w", "1.0")],
     [], []),
    ("geometry_msgs", "Vector3",
     [("double", "x", "0.0"), ("double", "y", "0.0"), ("double", "z", "0.0")], [], []),
    ("sensor_msgs", "Imu",
     [("std_msgs::msg::Header", "header", None),
      ("geometry_msgs::msg::Quaternion", "orientation", None),
      ("std::array<double, 9>", "orientation_covariance", "{}"),
      ("geometry_msgs::msg::Vector3", "angular_velocity", None),
      ("std::array<double, 9>", "angular_velocity_covariance", "{}"),
      ("geometry_msgs::msg::Vector3", "linear_acceleration", None),
      ("std::array<double, 9>", "linear_acceleration_covariance", "{}")],
     [], ["std_msgs/msg/header.hpp", "geometry_msgs/msg/quaternion.hpp", "geometry_msgs/msg/vector3.hpp"]),
    ("sensor_msgs", "JointState",
     [("std_msgs::msg::Header", "header", None),
      ("std::vector<std::string>", "name", None),
      ("std::vector<double>", "position", None),
      ("std::vector<double>", "velocity", None),
      ("std::vector<double>", "effort", None)],
     [], ["std_msgs/msg/header.hpp"]),
    ("lifecycle_msgs", "State", [("uint8_t", "id", "0"), ("std::string", "label", None)],
     [("uint8_t", "PRIMARY_STATE_UNKNOWN", "0"), ("uint8_t", "PRIMARY_STATE_UNCONFIGURED", "1"),
      ("uint8_t", "PRIMARY_STATE_INACTIVE", "2"), ("uint8_t", "PRIMARY_STATE_ACTIVE", "3"),
      ("uint8_t", "PRIMARY_STATE_FINALIZED", "4"), ("uint8_t", "TRANSITION_STATE_CONFIGURING", "10"),
      ("uint8_t", "TRANSITION_STATE_CLEANINGUP", "11"), ("uint8_t", "TRANSITION_STATE_SHUTTINGDOWN", "12"),
      ("uint8_t", "TRANSITION_STATE_ACTIVATING", "13"), ("uint8_t", "TRANSITION_STATE_DEACTIVATING", "14"),
      ("uint8_t", "TRANSITION_STATE_ERRORPROCESSING", "15")], []),
    ("lifecycle_msgs", "Transition", [("uint8_t", "id", "0"), ("std::string", "label", None)],
     [("uint8_t", "TRANSITION_CREATE", "0"), ("uint8_t", "TRANSITION_CONFIGURE", "1"),
      ("uint8_t", "TRANSITION_CLEANUP", "2"), ("uint8_t", "TRANSITION_ACTIVATE", "3"),
      ("uint8_t", "TRANSITION_DEACTIVATE", "4"), ("uint8_t", "TRANSITION_UNCONFIGURED_SHUTDOWN", "5"),
      ("uint8_t", "TRANSITION_INACTIVE_SHUTDOWN", "6"), ("uint8_t", "TRANSITION_ACTIVE_SHUTDOWN", "7"),
      ("uint8_t", "TRANSITION_DESTROY", "8"), ("uint8_t", "TRANSITION_CALLBACK_SUCCESS", "97"),
      ("uint8_t", "TRANSITION_CALLBACK_FAILURE", "98"), ("uint8_t", "TRANSITION_CALLBACK_ERROR", "99")],
     []),
    # aimdk_msgs (interface/robot/common/msg/MessageHeader.msg, interface/robot/hal/msg/*.msg)
    ("aimdk_msgs", "MessageHeader",
     [(T, "stamp", None), ("std::string", "frame_id", None), ("uint32_t", "sequence", "0"),
      (T, "meas_stamp", None)],
     [], ["builtin_interfaces/msg/time.hpp"]),
    ("aimdk_msgs", "DomainErrorState", [("uint8_t", "value", "0")],
     [("uint8_t", "NONE", "0"), ("uint8_t", "DAMPING", "1"), ("uint8_t", "POWERDOWN", "2"),
      ("uint8_t", "DISABLE", "3"), ("uint8_t", "DISCONNECT", "4")], []),
    ("aimdk_msgs", "JointCommand",
     [("std::string", "name", None), ("double", "position", "0.0"), ("double", "velocity", "0.0"),
      ("double", "effort", "0.0"), ("double", "stiffness", "0.0"), ("double", "damping", "0.0")],
     [], []),
    ("aimdk_msgs", "JointCommandArray",
     [("aimdk_msgs::msg::MessageHeader", "header", None),
      ("std::vector<aimdk_msgs::msg::JointCommand>", "joints", None)],
     [], ["aimdk_msgs/msg/message_header.hpp", "aimdk_msgs/msg/joint_command.hpp"]),
    ("aimdk_msgs", "JointState",
     [("std::string", "name", None), ("double", "position", "0.0"), ("double", "velocity", "0.0"),
      ("double", "effort", "0.0"), ("uint16_t", "error_code", "0")],
     [], []),
    ("aimdk_msgs", "JointStateArray",
     [("aimdk_msgs::msg::MessageHeader", "header", None),
      ("aimdk_msgs::msg::DomainErrorState", "state", None),
      ("std::vector<aimdk_msgs::msg::JointState>", "joints", None)],
     [], ["aimdk_msgs/msg/message_header.hpp", "aimdk_msgs/msg/domain_error_state.hpp",
          "aimdk_msgs/msg/joint_state.hpp"]),
    # interface_protocol (engineai_ros2_workspace/msg/*.msg)
    ("interface_protocol", "JointCommand",
     [("std_msgs::msg::Header", "header", None),
      ("std::vector<double>", "position", None), ("std::vector<double>", "velocity", None),
      ("std::vector<double>", "feed_forward_torque", None), ("std::vector<double>", "torque", None),
      ("std::vector<double>", "stiffness", None), ("std::vector<double>", "damping", None),
      ("uint8_t", "parallel_parser_type", "0")],
     [], ["std_msgs/msg/header.hpp"]),
    ("interface_protocol", "JointState",
     [("std_msgs::msg::Header", "header", None),
      ("std::vector<double>", "position", None), ("std::vector<double>", "velocity", None),
      ("std::vector<double>", "torque", None)],
     [], ["std_msgs/msg/header.hpp"]),
    ("interface_protocol", "ImuInfo",
     [("std_msgs::msg::Header", "header", None),
      ("geometry_msgs::msg::Quaternion", "quaternion", None),
      ("geometry_msgs::msg::Vector3", "rpy", None),
      ("geometry_msgs::msg::Vector3", "linear_acceleration", None),
      ("geometry_msgs::msg::Vector3", "angular_velocity", None)],
     [], ["std_msgs/msg/header.hpp", "geometry_msgs/msg/quaternion.hpp", "geometry_msgs/msg/vector3.hpp"]),
    # A message with only constants: rosidl adds a dummy byte member.
    ("interface_protocol", "ParallelParserType",
     [("uint8_t", "structure_needs_at_least_one_member", "0")],
     [("uint8_t", "CLASSIC_PARSER", "0"), ("uint8_t", "RL_PARSER", "1")], []),
]


def snake(name: str) -> str:
    s = re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name)
    s = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1_\2", s)
    return s.lower()


def render(pkg: str, name: str, fields, constants, includes) -> str:
    rel = f"{pkg}/msg/{snake(name)}.hpp"
    guard = rel.upper().replace("/", "__").replace(".", "_") + "_"
    std_includes = {"<memory>", "<cstdint>"}
    for ctype, _, _ in fields:
        if "std::string" in ctype:
            std_includes.add("<string>")
        if "std::vector" in ctype:
            std_includes.add("<vector>")
        if "std::array" in ctype:
            std_includes.add("<array>")
    out = [
        f"// rhi-gen test stand-in (not the real ROS 2 code): {pkg}/msg/{name}.",
        "// Generated by tests/cpp/standins/tools/gen_msgs.py -- edit that script, not this file.",
        f"#ifndef {guard}",
        f"#define {guard}",
        "",
    ]
    out += [f"#include {i}" for i in sorted(std_includes)]
    out += ["", '#include "rosidl_runtime_cpp/message_initialization.hpp"',
            '#include "rosidl_runtime_cpp/traits.hpp"']
    out += [f'#include "{i}"' for i in includes]
    s = f"{name}_"
    out += [
        "",
        f"namespace {pkg}",
        "{",
        "namespace msg",
        "{",
        "",
        "template<class ContainerAllocator>",
        f"struct {s}",
        "{",
        f"  using Type = {s}<ContainerAllocator>;",
        "",
        f"  explicit {s}(",
        "    rosidl_runtime_cpp::MessageInitialization _init = rosidl_runtime_cpp::MessageInitialization::ALL)",
        "  {",
        "    (void)_init;",
        "  }",
        "",
        f"  explicit {s}(",
        "    const ContainerAllocator & _alloc,",
        "    rosidl_runtime_cpp::MessageInitialization _init = rosidl_runtime_cpp::MessageInitialization::ALL)",
        "  {",
        "    (void)_alloc;",
        "    (void)_init;",
        "  }",
        "",
    ]
    for ctype, fname, init in fields:
        out.append(f"  using _{fname}_type = {ctype};")
        if init is None:
            out.append(f"  _{fname}_type {fname};")
        else:
            out.append(f"  _{fname}_type {fname}{{{init if init != '{}' else ''}}};")
    if fields:
        out.append("")
    for ctype, fname, _ in fields:
        out += [
            f"  Type & set__{fname}(const {ctype} & _arg)",
            "  {",
            f"    this->{fname} = _arg;",
            "    return *this;",
            "  }",
        ]
    if constants:
        out.append("")
        out.append("  // constant declarations")
    for ctype, cname, value in constants:
        out.append(f"  static constexpr {ctype} {cname} = {value}u;")
    out += [
        "",
        "  using RawPtr = Type *;",
        "  using ConstRawPtr = const Type *;",
        "  using SharedPtr = std::shared_ptr<Type>;",
        "  using ConstSharedPtr = std::shared_ptr<Type const>;",
        "  template<typename Deleter = std::default_delete<Type>>",
        "  using UniquePtrWithDeleter = std::unique_ptr<Type, Deleter>;",
        "  using UniquePtr = UniquePtrWithDeleter<>;",
        "  template<typename Deleter = std::default_delete<Type>>",
        "  using ConstUniquePtrWithDeleter = std::unique_ptr<Type const, Deleter>;",
        "  using ConstUniquePtr = ConstUniquePtrWithDeleter<>;",
        "  using WeakPtr = std::weak_ptr<Type>;",
        "  using ConstWeakPtr = std::weak_ptr<Type const>;",
        "",
        f"  bool operator==(const {s} & other) const",
        "  {",
    ]
    for _, fname, _ in fields:
        out += [f"    if (this->{fname} != other.{fname}) {{", "      return false;", "    }"]
    out += [
        "    return true;",
        "  }",
        f"  bool operator!=(const {s} & other) const",
        "  {",
        "    return !this->operator==(other);",
        "  }",
        "};",
        "",
        f"using {name} = {pkg}::msg::{s}<std::allocator<void>>;",
        "",
        "}  // namespace msg",
        f"}}  // namespace {pkg}",
        "",
        f'RHI_ROSIDL_MESSAGE_TRAITS({pkg}::msg::{name}, "{pkg}::msg::{name}", "{pkg}/msg/{name}")',
        "",
        f"#endif  // {guard}",
        "",
    ]
    return "\n".join(out), rel


def main() -> None:
    for spec in MESSAGES:
        text, rel = render(*spec)
        path = INCLUDE / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        print("wrote", path.relative_to(INCLUDE))


if __name__ == "__main__":
    main()
