"""Names that end up as C++ identifiers, folder names and ROS names.

Vendor and robot names become a C++ namespace, a class name prefix and path components, so they
are checked strictly here rather than escaped: a name that is not a plain identifier is an error
the user fixes once, not something to mangle silently. URDF joint names are untrusted text that is
escaped, not mangled, but only characters every output format carries safely are accepted.
"""
from __future__ import annotations

import difflib
import re

from .c_library_names import C_LIBRARY_NAMES

# The package's C++ namespace: a robot's driver is robot_hardware_interface::<vendor>::<Class>, its
# pluginlib name robot_hardware_interface/<vendor>/<Class> (the namespace path with '/').
PACKAGE_NAMESPACE = "robot_hardware_interface"

# At most 26 characters: vendor, robot and class prefix become C++ names that generated lines
# combine (Vendor::RobotHardwareInterface::RobotHardwareInterface(), the header guard
# ROBOT_HARDWARE_INTERFACE__VENDOR__ROBOT_HPP_), and ROS 2 code stays within
# 100 columns.
MAX_NAME = 26
IDENTIFIER_RE = re.compile(rf"^[a-z][a-z0-9_]{{0,{MAX_NAME - 1}}}$")
CLASS_PREFIX_RE = re.compile(rf"^[A-Z][A-Za-z0-9]{{0,{MAX_NAME - 1}}}$")

# C++20 keywords and alternative tokens, plus names that would clash inside the generated code.
CPP_KEYWORDS = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
char32_t class compl concept const consteval constexpr constinit const_cast continue co_await
co_return co_yield decltype default delete do double dynamic_cast else enum explicit export extern
false float for friend goto if inline int long mutable namespace new noexcept not not_eq nullptr
operator or or_eq private protected public register reinterpret_cast requires return short signed
sizeof static static_assert static_cast struct switch template this thread_local throw true try
typedef typeid typename union unsigned using virtual void volatile wchar_t while xor xor_eq
final override import module
""".split())
RESERVED_NAMESPACES = frozenset({
    "std", "rclcpp", "rclcpp_lifecycle", "hardware_interface", "pluginlib", "robot_hardware_interface",
    "unitree", "unitree_hg", "aimdk_msgs", "interface_protocol", "sensor_msgs", "std_msgs",
    "geometry_msgs", "builtin_interfaces", "rcutils", "rmw", "posix", "main",
})
# Folders of include/robot_hardware_interface/ that hold rhi-gen's shared headers: a vendor of that
# name would put its robot headers there (vendor "common", robot "types" would overwrite types.hpp).
RESERVED_VENDOR_FOLDERS = frozenset({"common", "transport"})
# Names the shared headers declare in namespace robot_hardware_interface (nested namespaces, free
# functions and variables spelt like a vendor): the vendor namespace robot_hardware_interface::<vendor>
# would be that namespace (its names mixed with the driver's) or clash with that function.
# tests/cli/test_hostile_inputs.py checks that every such name of rhi_gen/cpp and rhi_gen/transports is here.
PACKAGE_SCOPE_NAMES = frozenset({
    "unitree_crc", "unitree_dex3", "unitree_go", "unitree_hg",     # namespaces
    # functions (snake_case, ROS 2 style, so a vendor name could redeclare one)
    "all_finite", "bound_command_block", "bound_command_slots", "bounded", "components_initialized",
    "copy_state_block", "copy_state_slots",
    "takes_position", "cpu_has_clmul", "elapsed_us", "estop_pressed", "first_slot", "motor_mode",
    "for_each_slot_block", "health_state_value", "load_word",
    "low_cmd_crc", "low_state_crc",
    "make_joint_index_map", "make_qos", "make_resource_manager", "make_tables", "masked_crc",
    "masked_crc_clmul", "masked_crc_portable", "message_crc", "parse_bool", "parse_unsigned",
    "power_of_x_mod", "publish_ros_imu", "read_bool_parameter", "read_driver_parameters",
    "read_unsigned_parameter", "read_writer_mode_parameter", "slots_are_valid", "motor_error_bits",
    "steady_now_ns", "steady_now_us", "steady_ns",
    "transmit_command_block", "transmit_command_slots", "transmit_state_block", "transmit_state_slots",
    "trimmed",
    "word_masks",
    "make_fake_robot", "network_exposure", "parse_fake_robot_arguments", "run_fake_robot",  # the fake robot's
    "fake_robot_share_file", "use_fake_robot_physics",
})
# Vendor namespaces that are ours to use (the reference vendors) even though SDKs use some of them.
ALLOWED_VENDOR_NAMESPACES = frozenset({"unitree", "agibot", "engineai"})


def identifier_problem(name: object, what: str) -> str | None:
    """Why ``name`` cannot be a vendor/robot identifier, or None if it can."""
    if not isinstance(name, str) or not name:
        return f"{what} must be a non-empty string"
    if not IDENTIFIER_RE.match(name):
        return (f"{what} {name!r} must be lowercase letters, digits and underscores, starting with a "
                f"letter, at most {MAX_NAME} characters (it becomes a C++ namespace, class and folder name)")
    if "__" in name or name.endswith("_"):
        return f"{what} {name!r} must not contain '__' or end with '_' (reserved in C++)"
    if name in CPP_KEYWORDS:
        return f"{what} {name!r} is a C++ keyword"
    return None


def vendor_problem(name: object) -> str | None:
    problem = identifier_problem(name, "vendor")
    if problem is None and name in RESERVED_NAMESPACES and name not in ALLOWED_VENDOR_NAMESPACES:
        return f"vendor {name!r} would clash with the C++ namespace of a library the driver uses"
    if problem is None and name in C_LIBRARY_NAMES:
        return (f"vendor {name!r} is a function, type or macro the C library declares at global scope, so it "
                "cannot be the driver's C++ namespace")
    if problem is None and name in PACKAGE_SCOPE_NAMES:
        return (f"vendor {name!r} would clash with {PACKAGE_NAMESPACE}::{name} of rhi-gen's shared headers "
                f"(the driver's namespace is {PACKAGE_NAMESPACE}::<vendor>)")
    if problem is None and name in RESERVED_VENDOR_FOLDERS:
        return (f"vendor {name!r} is the folder of rhi-gen's shared headers "
                f"(include/robot_hardware_interface/{name}/)")
    return problem


def plugin_name(vendor: str, class_name: str) -> str:
    """The pluginlib lookup name of robot_hardware_interface::<vendor>::<Class>, as <plugin> names it."""
    return f"{PACKAGE_NAMESPACE}/{vendor}/{class_name}"


def legacy_plugin_name(vendor: str, class_name: str) -> str:
    """The plugin name of rhi-gen before the package namespace (<vendor>/<Class>, C++ <vendor>::<Class>):
    a description that still names it gets a warning saying what to write instead."""
    return f"{vendor}/{class_name}"


def pascal_case(name: str) -> str:
    """g1 -> G1, pm01 -> PM01, my_arm -> MyArm: parts with digits are model codes, kept upper."""
    parts = [p for p in name.split("_") if p]
    return "".join(p.upper() if any(c.isdigit() for c in p) else p[:1].upper() + p[1:] for p in parts)


def upper_snake(name: str) -> str:
    return name.upper()


def suggest(word: str, choices: list[str] | tuple[str, ...]) -> str | None:
    """The closest known word, for 'did you mean' hints."""
    match = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return match[0] if match else None


# Joint names become C++ string literals, XML attribute values, YAML list items and ROS 2
# interface names ("<joint>/position"). We accept what every one of those handles without
# surprises and reject the rest with a clear message rather than emitting fragile code.
SAFE_JOINT_NAME_RE = re.compile(r"^[A-Za-z0-9_./\-:+\[\]()#@]+$")
MAX_JOINT_NAME = 128


def joint_name_problem(name: str) -> str | None:
    """Why a URDF joint name cannot travel safely through C++, XML and ROS names, or None."""
    if not name:
        return "joint name is empty"
    if len(name) > MAX_JOINT_NAME:
        return f"joint name is {len(name)} characters long (at most {MAX_JOINT_NAME})"
    if SAFE_JOINT_NAME_RE.match(name):
        return None
    bad = next(ch for ch in name if not SAFE_JOINT_NAME_RE.match(ch))
    if ch_is_control(bad):
        what = f"a control character (U+{ord(bad):04X})"
    elif bad.isspace():
        what = "whitespace"
    elif ord(bad) > 127:
        what = f"the non-ASCII character {bad!r}"
    else:
        what = f"the character {bad!r}"
    return (f"joint name {name!r} contains {what}; joint names become C++ string literals, XML "
            "attributes and ROS 2 interface names")


def ch_is_control(ch: str) -> bool:
    return ord(ch) < 0x20 or 0x7F <= ord(ch) < 0xA0
