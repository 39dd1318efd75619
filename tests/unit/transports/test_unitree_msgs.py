"""The unitree_sdk2 stand-in structs (tests/cpp/standins/include/unitree/idl/{hg,go2}/*_.hpp) against
Unitree's own message definitions (tests/data/vendor_msgs/unitree_{hg,go}, BSD-3-Clause, copied from
unitreerobotics/unitree_ros2; provenance beside them).

The oracle is the .msg file, read by rosidl's own parser (rosidl_adapter, from the ROS 2 wheels of the
`test` extra), not SDK_FACTS.md: every member of the stand-in class, in order, has the field's name, its
C++ type (float32 -> float, uint32 -> uint32_t, ...; a nested message -> that family's `Name_` class) and,
for a fixed-size array, its length (the motor slots: 35 for hg, 20 for go). The only allowed differences
are those unitree_sdk2's generated headers have (SDK_FACTS.md §D: `uint8_t` where the go .msg files say
`int8`); the test lists them and fails if one disappears, so the list cannot go stale.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from rosidl_adapter.parser import parse_message_string

from tests.support.cpp_build import STANDINS_INCLUDE
from tests.support.vendor_msgs import IN_REPO_MSGS

FAMILIES = {  # .msg package -> (stand-in folder, C++ namespace)
    "unitree_hg": ("hg", "::unitree_hg::msg::dds_::"),
    "unitree_go": ("go2", "::unitree_go::msg::dds_::"),
}
STANDIN_TYPES = {
    "unitree_hg": ("LowCmd", "LowState", "MotorCmd", "MotorState", "IMUState"),
    "unitree_go": ("LowCmd", "LowState", "MotorCmd", "MotorState", "IMUState", "BmsCmd", "BmsState"),
}
SCALARS = {"bool": "bool", "int8": "int8_t", "uint8": "uint8_t", "int16": "int16_t", "uint16": "uint16_t",
           "int32": "int32_t", "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t",
           "float32": "float", "float64": "double", "byte": "uint8_t", "char": "uint8_t"}
# unitree_sdk2's generated go headers (include/unitree/idl/go2) say uint8_t where the .msg says int8.
SDK_DIFFERENCES = {
    ("unitree_go", "IMUState", "temperature"): ("int8_t", "uint8_t"),
    ("unitree_go", "MotorState", "temperature"): ("int8_t", "uint8_t"),
    ("unitree_go", "LowState", "temperature_ntc1"): ("int8_t", "uint8_t"),
    ("unitree_go", "LowState", "temperature_ntc2"): ("int8_t", "uint8_t"),
    ("unitree_go", "BmsState", "bq_ntc"): ("std::array<int8_t, 2>", "std::array<uint8_t, 2>"),
    ("unitree_go", "BmsState", "mcu_ntc"): ("std::array<int8_t, 2>", "std::array<uint8_t, 2>"),
}
CASES = [(pkg, name) for pkg, names in STANDIN_TYPES.items() for name in names]
_MEMBER = re.compile(r"^ (?P<type>[^;=]+?) (?P<name>\w+)_(?: = [^;]*)?;$", re.M)


def msg_members(package: str, name: str) -> list[tuple[str, str]]:
    """(field name, expected C++ type) of one .msg file, parsed by rosidl."""
    path = IN_REPO_MSGS / package / "msg" / f"{name}.msg"
    spec = parse_message_string(package, name, path.read_text(encoding="utf-8"))
    ns = FAMILIES[package][1]
    out = []
    for field in spec.fields:
        t = field.type
        cpp = SCALARS[t.type] if t.is_primitive_type() else f"{ns}{t.type}_"
        assert t.pkg_name in (None, package) or t.is_primitive_type(), f"{name}.{field.name}: {t.pkg_name}"
        if t.is_array:
            assert t.array_size and not t.is_upper_bound, f"{name}.{field.name}: only fixed arrays expected"
            cpp = f"std::array<{cpp}, {t.array_size}>"
        out.append((field.name, cpp))
    return out


def standin_members(package: str, name: str) -> list[tuple[str, str]]:
    """(member name, C++ type) of the stand-in class, in declaration order (its private members)."""
    folder, _ = FAMILIES[package]
    text = (STANDINS_INCLUDE / "unitree" / "idl" / folder / f"{name}_.hpp").read_text(encoding="utf-8")
    body = text.split("private:", 1)[1].split("public:", 1)[0]
    return [(m["name"], " ".join(m["type"].split())) for m in _MEMBER.finditer(body)]


@pytest.mark.parametrize(("package", "name"), CASES, ids=[f"{p}/{n}" for p, n in CASES])
def test_standin_struct_is_the_msg_definition(package, name):
    expected = msg_members(package, name)
    got = standin_members(package, name)
    assert [n for n, _ in got] == [n for n, _ in expected], f"{name}_: member names or order differ"
    for (field, want), (_, have) in zip(expected, got, strict=True):
        allowed = SDK_DIFFERENCES.get((package, name, field))
        if allowed is not None:
            assert (want, have) == allowed, f"{name}_.{field}: expected the SDK's {allowed[1]}, got {have}"
        else:
            assert have == want, f"{name}_.{field}: stand-in {have}, {package}/msg/{name}.msg says {want}"


def test_motor_slots_are_those_of_the_messages():
    """The array lengths the generated drivers rely on (35 hg, 20 go), read from the .msg files."""
    for package, slots in (("unitree_hg", 35), ("unitree_go", 20)):
        cmd = dict(msg_members(package, "LowCmd"))
        state = dict(msg_members(package, "LowState"))
        ns = FAMILIES[package][1]
        assert cmd["motor_cmd"] == f"std::array<{ns}MotorCmd_, {slots}>"
        assert state["motor_state"] == f"std::array<{ns}MotorState_, {slots}>"


def test_every_sdk_difference_is_still_one():
    """The allowed differences all exist (a stand-in fixed to the .msg type must update this list)."""
    for (package, name, field), (want, have) in SDK_DIFFERENCES.items():
        assert dict(msg_members(package, name))[field] == want, (name, field)
        assert dict(standin_members(package, name))[field] == have, (name, field)


def test_the_copies_hold_every_standin_type():
    for package, names in STANDIN_TYPES.items():
        present = {p.stem for p in (IN_REPO_MSGS / package / "msg").glob("*.msg")}
        assert set(names) <= present, sorted(set(names) - present)
        assert Path(IN_REPO_MSGS / package / "LICENSE").is_file()
