"""Finding and running g++ for tests: a missing compiler fails the test, it never skips it.

The second half builds and runs the driver harness (tests/cpp/harness/README.md)."""
from __future__ import annotations

import hashlib
import importlib.util
import math
import os
import re
import shutil
import subprocess
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

import pytest
import yaml

from tests.support import shared_use, vendor_msgs
from tests.support.repo import REPO
from tests.support.ros_msgs import wheel_include_dirs, wheels_digest
from tests.support.xml_tree import attribute

T = TypeVar("T")

if TYPE_CHECKING:
    from rhi_gen.model import RobotModel
    from rhi_gen.pipeline.load import LoadedRobot

STANDINS = REPO / "tests" / "cpp" / "standins"
# Distro-independent stand-ins (rclcpp, pluginlib, unitree_sdk2, messages, rhi_fake hooks).
STANDINS_INCLUDE = STANDINS / "include"
# What every distro's code is compiled with (the flags; deprecations are errors).
WARNING_FLAGS = ("-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror")


@dataclass(frozen=True)
class Distro:
    """One ROS 2 distribution the stand-ins cover (tests/cpp/standins/README.md, "Distros")."""
    name: str
    hardware_interface: str  # version of the ros2_control branch the stand-in follows
    layers: tuple[str, ...]  # folders under tests/cpp/standins/distros/, most specific first

    @property
    def hi_major(self) -> int:
        return int(self.hardware_interface.split(".")[0])

    @property
    def include_dirs(self) -> list[Path]:
        """-I order: the distro's own headers, the shared layers, then the distro-independent ones."""
        return [STANDINS / "distros" / layer / "include" for layer in self.layers] + [STANDINS_INCLUDE]


DISTROS: dict[str, Distro] = {
    "humble": Distro("humble", "2.54.0", ("humble",)),
    "jazzy": Distro("jazzy", "4.46.0", ("jazzy", "since_jazzy")),
    "kilted": Distro("kilted", "5.16.0", ("kilted", "since_kilted", "since_jazzy")),
    # Rolling and Lyrical share ros2_control's master branch (6.x).
    "rolling": Distro("rolling", "6.8.0", ("rolling", "since_kilted", "since_jazzy")),
}
DEFAULT_DISTRO = "humble"


def standin_flags(distro: str = DEFAULT_DISTRO) -> list[str]:
    """-I flags of the stand-ins for ``distro``."""
    return [f"-I{p}" for p in DISTROS[distro].include_dirs]


def require_compiler() -> str:
    """Path of g++ (or $CXX). A test that needs it fails loudly when it is missing."""
    cxx = os.environ.get("CXX", "g++")
    path = shutil.which(cxx)
    if path is None:
        pytest.fail(f"C++ compiler {cxx!r} not found: install g++ (CI installs it in .ci/run); "
                    "C++ checks are never skipped")
    return path


def run_compiler(args: Sequence[str], *, what: str) -> subprocess.CompletedProcess:
    """Run g++ with ``args``; on failure the assertion message carries the compiler's first errors."""
    cmd = [require_compiler(), *args]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        errors = "\n".join(proc.stderr.splitlines()[:40])
        raise AssertionError(f"{what} does not compile:\n{' '.join(cmd)}\n{errors}")
    return proc


def mujoco_dir() -> Path | None:
    """The folder of the installed `mujoco-core` wheel of the test extra (libmujoco.so.* and include/mujoco/),
    found without importing it; None when it is not installed."""
    spec = importlib.util.find_spec("mujoco")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations)))


def mujoco_include_flags() -> list[str]:
    """-isystem of MuJoCo's C headers (as CMake passes an imported target's), [] when it is not installed."""
    mj = mujoco_dir()
    return ["-isystem", str(mj / "include")] if mj is not None else []


def driver_source(package_dir: Path, vendor: str, robot: str) -> Path:
    return package_dir / "src" / vendor / f"{robot}.cpp"


def fake_robot_source(package_dir: Path, vendor: str, robot: str) -> Path | None:
    """The robot's generated fake robot (src/<vendor>/<robot>_fake_robot.cpp), if its transport has one."""
    path = package_dir / "src" / vendor / f"{robot}_fake_robot.cpp"
    return path if path.is_file() else None


def _vendor_packages(transport: str | None,
                     variants: tuple[str, ...]) -> tuple[vendor_msgs.VendorPackage, ...] | None:
    if transport is None:
        if variants:
            raise ValueError("a vendor package variant is chosen for one transport's packages")
        return None
    return vendor_msgs.packages_of(transport, variants)


def message_include_dirs(transport: str | None = None, variants: tuple[str, ...] = ()) -> list[Path]:
    """The real ROS 2 message headers: the Jazzy wheels' (tests/support/ros_msgs.py) and the vendor messages
    generated by rosidl (tests/support/vendor_msgs.py): those of ``transport`` (with the releases named in
    ``variants`` instead of the default ones), or all available ones (a package whose sources are missing is
    left out: see vendor_msgs.skip_reason)."""
    return [*wheel_include_dirs(), *vendor_msgs.include_dirs(_vendor_packages(transport, variants))]


def message_include_flags(transport: str | None = None, variants: tuple[str, ...] = ()) -> list[str]:
    # -isystem, as CMake passes the include folders of imported package targets to a colcon build.
    return [flag for d in message_include_dirs(transport, variants) for flag in ("-isystem", str(d))]


def messages_digest(transport: str | None = None, variants: tuple[str, ...] = ()) -> str:
    """Content of the message headers message_include_flags(transport, variants) passes (no paths)."""
    return f"{wheels_digest()} {vendor_msgs.cache_key(_vendor_packages(transport, variants))}"


def include_flags(package_dir: Path, extra: Iterable[Path] = (), distro: str = DEFAULT_DISTRO) -> list[str]:
    return [f"-I{package_dir / 'include'}", *standin_flags(distro), *(f"-I{p}" for p in extra),
            *message_include_flags()]


def syntax_check_driver(package_dir: Path, vendor: str, robot: str, flags: Sequence[str] = (),
                        distro: str = DEFAULT_DISTRO) -> None:
    """Compile one generated driver against ``distro``'s stand-in headers with -Werror (no linking)."""
    source = driver_source(package_dir, vendor, robot)
    run_compiler([*WARNING_FLAGS, *flags, "-fsyntax-only", *include_flags(package_dir, distro=distro), str(source)],
                 what=f"{vendor}/{robot} driver ({distro})")


# =====================================================================================================
# Driver harness builds (tests/cpp/test_cpp_drivers.py, test_cpp_data_buffer.py, test_cpp_mutations.py)
#
# A test project = the repository's robots/ (every robot a user adds there is covered) plus the
# test-only robots of tests/cpp/harness/robots/ (a generic_topics robot, so that transport is
# exercised too). The package is rendered in memory (optionally from a mutated template folder) and
# written to a temporary folder; per robot, robot_data.hpp carries the expected joint -> SDK slot
# table read from the vendor YAML, the URDF limits, the transport options and the HardwareInfo of
# the ros2_control description expanded by xacro. Objects are cached by the hash of everything that
# goes into them, so each (robot, flavour) is compiled once per session and unchanged parts of a
# mutated package are not compiled again.
# =====================================================================================================
HARNESS_DIR = REPO / "tests" / "cpp" / "harness"
HARNESS_ROBOTS = HARNESS_DIR / "robots"
# The toy motor bus of the custom transport's worked example, and its filled user regions.
TOY_BUS_DIR = REPO / "tests" / "cpp" / "toy_bus"
TOY_BUS_REGIONS = TOY_BUS_DIR / "regions.cpp.in"
PACKAGE = "robot_hardware_interface"
ENV_C = {**os.environ, "LC_ALL": "C", "LANG": "C"}

# Build flavours of the harness binaries. Every flavour compiles the driver with -Werror.
FLAVOURS: dict[str, tuple[str, ...]] = {
    # -O2 is how a release build of the driver runs
    "plain": ("-O2",),
    # -O0 under ASan: every access instrumented, and the objects compile in about two thirds of -O1's time
    "asan_ubsan": ("-O0", "-g1", "-fno-omit-frame-pointer", "-fsanitize=address,undefined",
                   "-fno-sanitize-recover=all"),
    "tsan": ("-O1", "-g1", "-fsanitize=thread"),
}


def harness_flags(flavour: str) -> tuple[str, ...]:
    """The flavour's flags with -Og for the harness's own translation unit: test code, compiled in about half
    the time of -O2 (-O1 with a sanitizer), still instrumented alike. The driver and fake robot objects it
    links keep the flavour's optimisation (a release build's, for plain)."""
    return (*(f for f in FLAVOURS[flavour] if not f.startswith("-O")), "-Og")


SANITIZER_ENV = {
    "ASAN_OPTIONS": "abort_on_error=0:halt_on_error=1:detect_leaks=1",
    "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1",
    "TSAN_OPTIONS": "halt_on_error=1:second_deadlock_stack=1",
}
# Harness robots compiled against another release of their vendor messages (tests/support/vendor_msgs.py
# VARIANTS) than the default: the PM01 against the EngineAI native SDK's interface_protocol, whose MotorDebug
# carries voltage, error codes and offline motors. Their robot_data.hpp says so (VARIANT_MACROS).
MESSAGE_VARIANTS: dict[str, tuple[str, ...]] = {"engineai/pm01_native_sdk": (vendor_msgs.ENGINEAI_NATIVE_SDK,)}
VARIANT_MACROS = {vendor_msgs.ENGINEAI_NATIVE_SDK: "RHI_ENGINEAI_NATIVE_SDK"}


def message_variants(label: str) -> tuple[str, ...]:
    """The message releases the robot "vendor/robot" is compiled against instead of the default ones."""
    return MESSAGE_VARIANTS.get(label, ())


TRANSPORT_MACROS = {
    "unitree_dds": "RHI_TRANSPORT_UNITREE_DDS",
    "agibot_topics": "RHI_TRANSPORT_AGIBOT_TOPICS",
    "engineai_topics": "RHI_TRANSPORT_ENGINEAI_TOPICS",
    "generic_topics": "RHI_TRANSPORT_GENERIC_TOPICS",
    "custom": "RHI_TRANSPORT_CUSTOM",
}


# ------------------------------------------------------------------------------------ project
def make_test_project(dest: Path, *, extra_robots: bool = True, only: Sequence[str] | None = None) -> Path:
    """A project folder holding a copy of the repository's robots/ (+ the harness's test robots).

    ``only`` keeps just the robots named "vendor/robot"."""
    robots = dest / "robots"
    shutil.copytree(REPO / "robots", robots)
    if extra_robots and HARNESS_ROBOTS.is_dir():
        shutil.copytree(HARNESS_ROBOTS, robots, dirs_exist_ok=True)
    if only is not None:
        keep = set(only)
        for yml in robots.glob("*/*.yaml"):
            if f"{yml.parent.name}/{yml.stem}" not in keep:
                yml.unlink()
    return dest


def load_models(project_root: Path):
    """RobotModels of every robot of the project (the same loading `rhi-gen generate` does)."""
    from rhi_gen.pipeline.load import load_robots
    from rhi_gen.project import Project

    return load_robots(Project(project_root.resolve()))


def render_package_to(loaded_robots, package_dir: Path) -> dict[str, str]:
    """Render the package for ``loaded_robots`` into ``package_dir``; returns the plan."""
    from rhi_gen.render.package import render_package

    models = [r.model for r in loaded_robots]
    plan = render_package(models)
    for rel, text in plan.items():
        path = package_dir / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return plan


# ------------------------------------------------------------------------------------ robot data
def _c_string(text: str) -> str:
    """A C++ string literal (independent of rhi-gen's own cpp_string filter)."""
    out = ['"']
    for byte in str(text).encode("utf-8"):
        ch = chr(byte)
        if ch in '"\\':
            out.append("\\" + ch)
        elif 0x20 <= byte < 0x7F and ch != "?":
            out.append(ch)
        else:
            out.append(f"\\{byte:03o}")
    out.append('"')
    return "".join(out)


def _c_double(value: float | None) -> str:
    if value is None or (isinstance(value, float) and math.isinf(value) and value > 0):
        return "kInf"
    if math.isinf(value):
        return "-kInf"
    return repr(float(value))


@dataclass
class Description:
    """The <ros2_control> block of an expanded description."""
    name: str
    type: str
    plugin: str
    parameters: dict[str, str]
    joints: list[dict]
    sensors: list[dict]
    gpios: list[dict]


def expand_description(package_dir: Path, robot: str, work_dir: Path) -> Description:
    """Expand description/<robot>.ros2_control.xacro the way a user does: include it from a robot
    through $(find robot_hardware_interface) and call its macro with the defaults."""
    from lxml import etree

    from rhi_gen.inputs.xacro_expand import expand_xacro

    xacro_file = package_dir / "description" / f"{robot}.ros2_control.xacro"
    ns = {"xacro": "http://www.ros.org/wiki/xacro"}
    macros = etree.parse(str(xacro_file)).getroot().findall("xacro:macro", ns)
    assert len(macros) == 1, f"{xacro_file}: expected one xacro macro, found {len(macros)}"
    macro = macros[0].get("name")
    work_dir.mkdir(parents=True, exist_ok=True)
    wrapper = work_dir / f"{robot}_wrapper.urdf.xacro"
    wrapper.write_text(
        '<?xml version="1.0"?>\n'
        '<robot name="rhi_test_robot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        f'  <xacro:include filename="$(find {PACKAGE})/description/{robot}.ros2_control.xacro"/>\n'
        f'  <xacro:{macro}/>\n'
        '</robot>\n', encoding="utf-8")
    xml = expand_xacro(wrapper, None, {PACKAGE: package_dir})
    root = etree.fromstring(xml)
    blocks = root.findall("ros2_control")
    assert len(blocks) == 1, f"{xacro_file}: expected one <ros2_control>, found {len(blocks)}"
    block = blocks[0]
    hardware = block.find("hardware")
    assert hardware is not None, f"{xacro_file}: <ros2_control> has no <hardware>"

    def params(element) -> dict[str, str]:
        return {attribute(p, "name"): (p.text or "").strip() for p in element.findall("param")}

    def component(element) -> dict:
        return {
            "name": element.get("name"),
            "command_interfaces": [(c.get("name"), params(c)) for c in element.findall("command_interface")],
            "state_interfaces": [s.get("name") for s in element.findall("state_interface")],
            "parameters": params(element),
        }

    return Description(
        name=attribute(block, "name"), type=attribute(block, "type"),
        plugin=(hardware.findtext("plugin") or "").strip(),
        parameters=params(hardware),
        joints=[component(j) for j in block.findall("joint")],
        sensors=[component(s) for s in block.findall("sensor")],
        gpios=[component(g) for g in block.findall("gpio")],
    )


def plugin_types(package_dir: Path) -> dict[str, str]:
    """robot_hardware_interface.xml: plugin name -> C++ type."""
    from lxml import etree

    root = etree.parse(str(package_dir / f"{PACKAGE}.xml")).getroot()
    return {attribute(c, "name"): attribute(c, "type") for c in root.iter("class")}


def yaml_joint_map(yaml_path: Path) -> dict[str, int]:
    """joint_map exactly as the vendor YAML writes it (the harness's source of truth for the map)."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    return {str(name): int(index) for name, index in data["joint_map"].items()}


def yaml_modes_and_gains(yaml_path: Path) -> tuple[dict[str, str], dict[str, tuple[float, float]]]:
    """command_modes and default_gains exactly as the vendor YAML writes them."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    modes = {str(k): str(v) for k, v in (data.get("command_modes") or {}).items()}
    gains = {str(k): (float((v or {}).get("stiffness", 0.0)), float((v or {}).get("damping", 0.0)))
             for k, v in (data.get("default_gains") or {}).items()}
    return modes, gains


# Leg joints by name, the harness's own reading of "the legs" (authority upper_body leaves them to the robot).
MODE_CODES = {"position": 0, "velocity": 1, "state": 2, "position_target": 3}  # kJoints' mode
LEG_WORDS = ("hip", "thigh", "knee", "calf", "ankle", "foot")


def yaml_arm_sdk(yaml_path: Path) -> tuple[int, float] | None:
    """(blend weight slot, ramp seconds) of a vendor YAML with authority: upper_body, else None. The slot is
    the YAML's arm_sdk_weight_slot, else the G1's kNotUsedJoint (29, unitree_sdk2 g1_arm7_sdk_dds_example)."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    if data.get("authority") != "upper_body":
        return None
    options = data.get("transport_options") or {}
    return int(options.get("arm_sdk_weight_slot", 29)), float(options.get("arm_sdk_ramp_s", 2.0))


def yaml_dex3_topics(yaml_path: Path) -> tuple[tuple[str, str], tuple[str, str]] | None:
    """((left, right) command topics, (left, right) state topics) of a vendor YAML with hands: dex3, else None.
    The defaults are unitree_sdk2's g1_dex3_example topics (tests/support/dex3_facts.py)."""
    import yaml

    from tests.support import dex3_facts

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    if data.get("hands") != "dex3":
        return None
    options = data.get("transport_options") or {}
    command = str(options.get("hand_command_topic", dex3_facts.COMMAND_TOPIC))
    state = str(options.get("hand_state_topic", dex3_facts.STATE_TOPIC))
    sides = dex3_facts.SIDES
    return (tuple(command.replace("{side}", s) for s in sides),  # type: ignore[return-value]
            tuple(state.replace("{side}", s) for s in sides))


def yaml_aimdk_hand_topics(yaml_path: Path) -> tuple[str, str] | None:
    """(command topic, state topic) of the HandCommandArray / HandStateArray of a vendor YAML with hands: omnihand,
    else None. The defaults are AimDK's (tests/support/aimdk_facts.py)."""
    import yaml

    from tests.support import aimdk_facts

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    if data.get("hands") != "omnihand":
        return None
    options = data.get("transport_options") or {}
    return (str(options.get("hand_command_topic", aimdk_facts.HAND_COMMAND_TOPIC)),
            str(options.get("hand_state_topic", aimdk_facts.HAND_STATE_TOPIC)))


def yaml_hands(yaml_path: Path) -> str:
    """The vendor YAML's hands (none when it does not say)."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    return str(data.get("hands", "none"))


def yaml_take_control(yaml_path: Path) -> bool:
    """Whether a vendor YAML asks the driver to take control through AimDK's system-state services."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    return bool((data.get("transport_options") or {}).get("take_control", False))


def is_leg_name(name: str) -> bool:
    return any(word in name.lower().split("_") for word in LEG_WORDS)


def yaml_unitree_family(yaml_path: Path, vendor: str, robot: str) -> tuple[str, tuple[int, ...]]:
    """unitree_dds message family and go motor modes as the vendor YAML writes them; a YAML that
    omits them gets the known robot's (SDK_FACTS.md: the family follows the robot), else hg / 0x01."""
    import yaml

    from rhi_gen.transports.unitree_dds.known_robots import KNOWN_ROBOTS
    from rhi_gen.transports.unitree_dds.protocol import FAMILIES

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    opts = data.get("transport_options") or {}
    known = next((k for k in KNOWN_ROBOTS if k.vendor == vendor and k.named(robot)), None)
    family = str(opts.get("family") or (known.family if known else "hg"))
    if family != "go":
        return family, ()
    modes = tuple(int(m) for m in opts.get("motor_modes") or (known.motor_modes if known else ()))
    return family, modes or (1,) * FAMILIES["go"]


def robot_data_header(loaded, package_dir: Path, work_dir: Path) -> str:
    """robot_data.hpp for one robot (namespace rhi_data, see tests/cpp/harness/harness_common.hpp)."""
    model = loaded.model
    joint_map = yaml_joint_map(loaded.yaml_path)
    yaml_modes, yaml_gains = yaml_modes_and_gains(loaded.yaml_path)
    has_gains = model.transport != "generic_topics"  # sensor_msgs/JointState carries no gains
    by_name = {j.name: j for j in model.joints}
    assert set(joint_map) == set(by_name), f"{model.robot}: YAML joint_map and model joints differ"
    assert all(by_name[n].index == i for n, i in joint_map.items()), f"{model.robot}: model moved a joint"
    description = expand_description(package_dir, model.robot, work_dir)
    health_gpio = description.gpios[0]["name"] if description.gpios else ""
    plugins = plugin_types(package_dir)
    opts = model.transport_options
    params = model.parameters

    aimdk_hands = yaml_aimdk_hand_topics(loaded.yaml_path)
    hand_first = 0
    if model.transport == "agibot_topics":
        groups = [(g.name, g.offset, g.size, g.command_topic, g.state_topic) for g in opts.groups]
        if aimdk_hands is not None:  # both hands in one message pair: consistent on its own, like a joint group
            slots = opts.hand_slots()
            hand_first = slots.start if len(slots) else model.motor_count - 20  # 10 OmniHand axes per hand
            assert not len(slots) or len(slots) == 20, f"{model.robot}: the OmniHands take 20 slots, not {len(slots)}"
            groups.append(("hands", hand_first, 20, aimdk_hands[0], aimdk_hands[1]))
    elif model.transport == "unitree_dds":
        arm_sdk = yaml_arm_sdk(loaded.yaml_path)
        hands = yaml_dex3_topics(loaded.yaml_path)
        body = model.motor_count if hands is None else model.motor_count - 14  # the Dex3-1 hands: 7 slots each
        groups = [("all", 0, body, "rt/arm_sdk" if arm_sdk else opts.lowcmd_topic, opts.lowstate_topic)]
        if hands is not None:  # each hand its own message: consistent on its own, like an AgiBot group
            groups += [(f"{side}_hand", body + 7 * i, 7, hands[0][i], hands[1][i])
                       for i, side in enumerate(("left", "right"))]
    else:
        # custom carries no topics (its options are the base TransportOptions): the fake bus needs none
        groups = [("all", 0, model.motor_count, getattr(opts, "command_topic", ""), getattr(opts, "state_topic", ""))]
    # the groups the transport's own state messages carry (AgiBot: its JointStateArrays), before any hands'
    body_group_count = len(opts.groups) if model.transport == "agibot_topics" else 1

    motor_group = {slot: group.name for group in model.motor_groups for slot in group.slots}

    def group_of(slot: int) -> int:
        for g, (_, offset, size, _, _) in enumerate(groups):
            if offset <= slot < offset + size:
                return g
        raise AssertionError(f"{model.robot}: slot {slot} is in no joint group")

    lines = [
        "// Written by tests/support/cpp_build.py for the driver harness: do not edit.",
        f"// robot {model.vendor}/{model.robot} from {loaded.yaml_path.name} (joint map read from the YAML).",
        "#pragma once",
        "#include <cstddef>",
        "#include <cstdint>",
        "#include <limits>",
        f"#define {TRANSPORT_MACROS[model.transport]} 1",
    ]
    if model.transport != "unitree_dds":
        lines.append("#define RHI_TRANSPORT_ROS 1")
    if fake_robot_source(package_dir, model.vendor, model.robot) is not None:
        lines.append("#define RHI_FAKE_ROBOT 1  // its fake robot is linked in: section fake_robot")
    for variant in message_variants(f"{model.vendor}/{model.robot}"):
        lines.append(f"#define {VARIANT_MACROS[variant]} 1  // compiled against the {variant} messages")
    family = ""
    motor_modes: tuple[int, ...] = ()
    if model.transport == "unitree_dds":
        family, motor_modes = yaml_unitree_family(loaded.yaml_path, model.vendor, model.robot)
        lines.append(f"#define RHI_UNITREE_FAMILY_{family.upper()} 1  // message family (transport_options.family)")
    arm_sdk = yaml_arm_sdk(loaded.yaml_path)
    if arm_sdk is not None:
        lines.append("#define RHI_ARM_SDK 1  // authority upper_body: section arm_sdk")
    if yaml_take_control(loaded.yaml_path):
        lines.append("#define RHI_TAKE_CONTROL 1  // transport_options.take_control: section take_control")
    dex3 = yaml_dex3_topics(loaded.yaml_path)
    if dex3 is not None:
        lines.append("#define RHI_DEX3 1  // hands: dex3 (HandCmd_ / HandState_ per hand): section hands")
    if aimdk_hands is not None:
        lines.append("#define RHI_AIMDK_HANDS 1  // hands: omnihand (HandCommandArray / HandStateArray): section hands")
    lines += [
        "namespace rhi_data {",
        f"using SdkFloat = {model.float_type};",
        "inline constexpr double kInf = std::numeric_limits<double>::infinity();",
        f"inline constexpr char kRobotLabel[] = {_c_string(model.vendor + '/' + model.robot)};",
        f"inline constexpr char kPluginName[] = {_c_string(description.plugin)};",
        f"inline constexpr char kPluginType[] = {_c_string(plugins.get(description.plugin, '?'))};",
        f"inline constexpr size_t kMotorCount = {model.motor_count};",
        f"inline constexpr bool kImuEnabled = {'true' if model.imu.enabled else 'false'};",
        f"inline constexpr char kImuName[] = {_c_string(model.imu.name)};",
        "// the <gpio> of the expanded description (the driver's health), \"\" for none",
        f"inline constexpr char kHealthGpio[] = {_c_string(health_gpio)};",
        f"inline constexpr bool kHasGains = {'true' if has_gains else 'false'};  // stiffness/damping travel",
        "// mode: 0 position-commanded, 1 velocity-commanded (a continuous joint unless command_modes says",
        "// otherwise), 2 state-only (a leg under authority upper_body), 3 position target only (an OmniHand axis:",
        "// the robot's own controller tracks it); kp/kd: the YAML's default_gains (kp is 0 for a velocity-commanded",
        "// joint, both are 0 for a state-only or position-target one)",
        ("struct Joint { const char* name; size_t slot; size_t group; double lower; double upper; double velocity;"
         " double effort; int mode; double kp; double kd; };"),
        "inline constexpr Joint kJoints[] = {",
    ]
    for name, slot in joint_map.items():
        limits = by_name[name].limits
        lower = limits.lower if limits else None
        upper = limits.upper if limits else None
        mode = yaml_modes.get(name, "velocity" if by_name[name].type == "continuous" else "position")
        kp, kd = yaml_gains.get(name, (0.0, 0.0))
        if arm_sdk is not None and is_leg_name(name):
            mode, kp, kd = "state", 0.0, 0.0
        if by_name[name].command_mode == "position_target":  # the hands section checks which joints these are
            mode, kp, kd = "position_target", 0.0, 0.0
        lines.append(
            f"    {{{_c_string(name)}, {slot}, {group_of(slot)}, "
            f"{_c_double(-math.inf if lower is None else lower)}, {_c_double(upper)}, "
            f"{_c_double(limits.velocity if limits else None)}, {_c_double(limits.effort if limits else None)}, "
            f"{MODE_CODES.get(mode, 0)}, {float(kp) if mode == 'position' else 0.0!r}, {float(kd)!r}}},")
    lines += [
        "};",
        f"inline constexpr size_t kJointCount = {len(joint_map)};",
        "// the /diagnostics motors status of each joint of kJoints (rhi_gen/model/motor_groups.py)",
        "inline constexpr const char* kJointMotorGroup[] = {",
        *(f"    {_c_string(motor_group[slot])}," for slot in joint_map.values()),
        "};",
        f"inline constexpr size_t kMotorGroupCount = {len(model.motor_groups)};",
        *transmission_lines(model, list(joint_map)),
        ("struct Group { const char* name; size_t offset; size_t size; const char* command_topic;"
         " const char* state_topic; };"),
        "inline constexpr Group kGroups[] = {",
        *(f"    {{{_c_string(n)}, {o}, {s}, {_c_string(c)}, {_c_string(st)}}}," for n, o, s, c, st in groups),
        "};",
        f"inline constexpr size_t kGroupCount = {len(groups)};",
        f"inline constexpr size_t kBodyGroupCount = {body_group_count};  // the groups before the hands'",
        f"inline constexpr char kCommandTopic[] = {_c_string(groups[0][3])};",
        f"inline constexpr char kStateTopic[] = {_c_string(groups[0][4])};",
        *([f"inline constexpr const char * kHandCommandTopics[2] = {{{', '.join(map(_c_string, dex3[0]))}}};",
           f"inline constexpr const char * kHandStateTopics[2] = {{{', '.join(map(_c_string, dex3[1]))}}};"]
          if dex3 is not None else []),
        *(["// hands: omnihand: slot kHandFirstSlot + i is left entry i, kHandFirstSlot + 10 + i right entry i",
           f"inline constexpr size_t kHandFirstSlot = {hand_first};",
           f"inline constexpr char kHandCommandTopic[] = {_c_string(aimdk_hands[0])};",
           f"inline constexpr char kHandStateTopic[] = {_c_string(aimdk_hands[1])};"]
          if aimdk_hands is not None else []),
        # each transport's options carry only its own fields (transports/<name>/): the others are unused
        f"inline constexpr char kImuTopic[] = {_c_string(getattr(opts, 'imu_topic', ''))};",
        f"inline constexpr char kMotorDebugTopic[] = {_c_string(getattr(opts, 'motor_debug_topic', ''))};",
        f"inline constexpr uint8_t kModePr = {getattr(opts, 'mode_pr', 0)};",
        "// authority upper_body: the LowCmd_ slot of the arm SDK blend weight and its ramp time (0 / 0.0: none)",
        f"inline constexpr size_t kArmSdkWeightSlot = {arm_sdk[0] if arm_sdk else 0};",
        f"inline constexpr double kArmSdkRampS = {_c_double(arm_sdk[1] if arm_sdk else 0.0)};",
        f"inline constexpr uint8_t kParallelParserType = {getattr(opts, 'parallel_parser_type', 0)};",
        "// unitree go: MotorCmd_.mode of every LowCmd_ slot (the YAML's motor_modes, else the known robot's)",
        f"inline constexpr uint8_t kMotorModes[] = {{{', '.join(str(m) for m in motor_modes) or '0'}}};",
        "// parameter defaults: the vendor YAML's parameters (spec defaults where it gives none)",
        f"inline constexpr uint64_t kDefaultPeriodUs = {params.command_writer_period_us};",
        f"inline constexpr uint32_t kDefaultDecimation = {params.state_decimation};",
        f"inline constexpr char kDefaultNetworkInterface[] = {_c_string(params.network_interface)};",
        "// what the ros2_control description passes",
        (f"inline constexpr uint64_t kDescriptionPeriodUs = "
         f"{int(description.parameters.get('command_writer_period_us', params.command_writer_period_us))};"),
        (f"inline constexpr uint64_t kDescriptionTimeoutMs = "
         f"{int(description.parameters.get('state_timeout_ms', params.state_timeout_ms))};"),
        (f"inline constexpr char kDescriptionNetworkInterface[] = "
         f"{_c_string(description.parameters.get('network_interface', params.network_interface))};"),
        "// the <ros2_control> block of the expanded description, as records (see make_hardware_info())",
        "struct InfoRecord { char kind; const char* a; const char* b; const char* c; };",
        "inline constexpr InfoRecord kInfoRecords[] = {",
        f"    {{'N', {_c_string(description.name)}, {_c_string(description.type)}, \"\"}},",
        f"    {{'L', {_c_string(description.plugin)}, \"\", \"\"}},",
    ]
    for key, value in description.parameters.items():
        lines.append(f"    {{'H', {_c_string(key)}, {_c_string(value)}, \"\"}},")
    for kind, components in (("J", description.joints), ("S", description.sensors), ("G", description.gpios)):
        for comp in components:
            lines.append(f"    {{'{kind}', {_c_string(comp['name'])}, \"\", \"\"}},")
            for iface, p in comp["command_interfaces"]:
                lines.append(f"    {{'C', {_c_string(iface)}, {_c_string(p.get('min', ''))}, "
                             f"{_c_string(p.get('max', ''))}}},")
            for iface in comp["state_interfaces"]:
                lines.append(f"    {{'T', {_c_string(iface)}, \"\", \"\"}},")
            for key, value in comp["parameters"].items():
                lines.append(f"    {{'P', {_c_string(key)}, {_c_string(value)}, \"\"}},")
    lines += ["};", "}  // namespace rhi_data", ""]
    return "\n".join(lines)


def transmission_lines(model, joint_order: list[str]) -> list[str]:
    """robot_data.hpp's motors-that-are-not-joints tables, per kJoints entry, written from the model's
    transmissions (direction / reduction / offset and coupled matrices, which tests/unit check against the
    YAML and the URDF) by formula: scale = direction / reduction, and every matrix entry by slot."""
    by_name = {j.name: j for j in model.joints}
    group_of = {name: g for g, group in enumerate(model.coupled_groups) for name in group.joints}
    rows = []
    for name in joint_order:
        t = by_name[name].transmission
        rows.append(f"    {{{_c_double(t.direction / t.reduction)}, {_c_double(t.offset)}, {group_of.get(name, -1)}}},")
    weights = [f"    {{{by_name[row_joint].index}, {by_name[motor_joint].index}, {_c_double(value)}}},"
               for group in model.coupled_groups
               for row_joint, row in zip(group.joints, group.matrix, strict=True)
               for motor_joint, value in zip(group.joints, row, strict=True)]
    return [
        "// motors that are not joints: joint = scale * motor + offset; a coupled joint (group >= 0):",
        "// joint = sum of weight * motor over its kCoupledWeights + offset",
        f"inline constexpr bool kHasTransmission = {'true' if model.has_transmission else 'false'};",
        "struct Transmission { double scale; double offset; int group; };",
        "inline constexpr Transmission kTransmissions[] = {", *rows, "};",
        "struct CoupledWeight { size_t joint_slot; size_t motor_slot; double weight; };",
        "inline constexpr CoupledWeight kCoupledWeights[] = {", *(weights or ["    {0, 0, 0.0},"]), "};",
        f"inline constexpr size_t kCoupledWeightCount = {len(weights)};",
    ]


# ------------------------------------------------------------------------------------ compiling
def _tree_digest(root: Path, suffixes: tuple[str, ...] = (".hpp", ".h", ".cpp")) -> str:
    h = hashlib.sha256()
    for p in sorted(root.rglob("*")):
        if p.is_file() and p.suffix in suffixes:
            h.update(p.relative_to(root).as_posix().encode())
            h.update(b"\0")
            h.update(p.read_bytes())
    return h.hexdigest()


@dataclass
class CompileResult:
    ok: bool
    path: Path
    command: list[str]
    stderr: str = ""
    seconds: float = 0.0
    cached: bool = False


class PackageDeps:
    """Which files of a generated package one object was compiled from, as a manifest beside the object:
    one line per package content seen, listing the package files g++ read (-MD), relative to the package.
    A later compile of the same source and flags is a hit when those files hash the same (ccache's
    "direct mode", for the one folder whose content varies between test packages)."""

    def __init__(self, manifest: Path, package: Path) -> None:
        self.manifest = manifest
        self.package = package

    def candidates(self) -> list[tuple[str, ...]]:
        try:
            lines = self.manifest.read_text(encoding="utf-8").splitlines()
        except FileNotFoundError:
            return []
        return list(dict.fromkeys(tuple(line.split("\t")) for line in lines if line))

    def digest(self, files: Sequence[str]) -> str | None:
        """The files' names and contents in this package; None when one of them is missing here."""
        h = hashlib.sha256()
        for rel in files:
            try:
                data = (self.package / rel).read_bytes()
            except FileNotFoundError:
                return None
            h.update(rel.encode() + b"\0" + data + b"\0")
        return h.hexdigest()

    def record(self, depfile: Path) -> tuple[str, ...]:
        """The package files a g++ depfile lists, appended to the manifest (one write: O_APPEND keeps
        lines whole across sessions sharing the cache)."""
        root = Path(os.path.normpath(self.package.resolve()))
        text = depfile.read_text(encoding="utf-8").replace("\\\n", " ")
        names = set()
        for token in text.split()[1:]:
            path = Path(os.path.normpath(Path(token).resolve()))
            if path.is_relative_to(root):
                names.add(path.relative_to(root).as_posix())
        files = tuple(sorted(names))
        with self.manifest.open("a", encoding="utf-8") as out:
            out.write("\t".join(files) + "\n")
        return files


class CppBuilder:
    """Compiles and links with a content-addressed cache (key = everything that goes in).

    Thread-safe: the same object requested twice is compiled once."""

    def __init__(self, cache_dir: Path, jobs: int | None = None) -> None:
        self.cxx = require_compiler()
        self.cache_dir = cache_dir
        cache_dir.mkdir(parents=True, exist_ok=True)
        self.jobs = jobs or max(1, os.cpu_count() or 1)
        # At most ``jobs`` compilers at once, however many threads ask: a pool can then run more workers
        # than cores, each building and then running its binary, and the runs (which mostly wait on
        # timers) overlap the next compiles instead of leaving the cores idle.
        self._slots = threading.BoundedSemaphore(self.jobs)
        version = subprocess.run([self.cxx, "--version"], capture_output=True, text=True).stdout
        self._salt = hashlib.sha256(version.encode()).hexdigest()
        self._standins = _tree_digest(STANDINS, (".hpp", ".h"))  # every distro's headers
        # Message headers per transport (None: every available vendor package). A compile for one robot
        # gets only its transport's vendor packages, so its key does not change with packages it cannot
        # include (a clone without the AimDK messages reuses the G1 objects of a session that had them).
        self._messages: dict[tuple[str | None, tuple[str, ...]], tuple[list[str], str, set[str]]] = {}
        # .inc: the sections and mutants driver_harness.cpp includes
        self._harness = _tree_digest(HARNESS_DIR, (".hpp", ".h", ".cpp", ".inc")) + \
            _tree_digest(TOY_BUS_DIR, (".hpp", ".in"))
        self._lock = threading.Lock()
        self._inflight: dict[str, threading.Event] = {}
        self._results: dict[str, CompileResult] = {}
        self.compile_seconds = 0.0
        self.compiled = 0
        self.reused = 0

    def _key(self, *parts: str) -> str:
        h = hashlib.sha256(self._salt.encode())
        for part in parts:
            h.update(part.encode())
            h.update(b"\0")
        return h.hexdigest()[:24]

    def _claim(self, key: str) -> tuple[CompileResult | None, threading.Event]:
        """(the result, when this session has it or another thread is making it: waits), else (None, the
        event to set once this thread has stored the result under ``key``)."""
        with self._lock:
            if key in self._results:
                self.reused += 1
                return self._results[key], threading.Event()
            event = self._inflight.get(key)
            if event is None:
                event = self._inflight[key] = threading.Event()
                return None, event
        event.wait()
        with self._lock:
            self.reused += 1
            return self._results[key], event

    def _run(self, key: str, out: Path, cmd: list[str]) -> CompileResult:
        done, event = self._claim(key)
        if done is not None:
            return done
        if out.exists():
            result = CompileResult(True, out, cmd, cached=True)
        else:
            start = time.monotonic()
            # per process: sessions sharing RHI_CPP_CACHE must not write one file (an exec of it fails: ETXTBSY)
            tmp = out.with_name(f"{out.name}.{os.getpid()}.tmp")
            full = [*cmd, "-o", str(tmp)]
            with self._slots:
                proc = subprocess.run(full, capture_output=True, text=True, env=ENV_C)
            seconds = time.monotonic() - start
            if proc.returncode == 0:
                os.replace(tmp, out)
            result = CompileResult(proc.returncode == 0, out, full, proc.stderr, seconds)
            with self._lock:
                self.compile_seconds += seconds
                self.compiled += 1
        with self._lock:
            self._results[key] = result
            event.set()
        return result

    def _message_parts(self, transport: str | None, variants: tuple[str, ...]) -> tuple[list[str], str]:
        """Include flags and digest of the vendor messages, once per builder; a use counts as reading what
        their generation read (the AimDK headers come from ../shared: tests/support/shared_use.py)."""
        which = (transport, variants)
        with self._lock:
            hit = self._messages.get(which)
        if hit is None:
            with shared_use.recording() as used:
                hit = (message_include_flags(transport, variants), messages_digest(transport, variants), set(used))
            with self._lock:
                hit = self._messages.setdefault(which, hit)
        shared_use.replay(hit[2])
        return hit[0], hit[1]

    def compile(self, source: Path, flags: Sequence[str], includes: Sequence[Path], *,
                digest_parts: Sequence[str] = (), name: str, distro: str = DEFAULT_DISTRO,
                transport: str | None = None, variants: tuple[str, ...] = (),
                package: Path | None = None) -> CompileResult:
        """``transport``: the robot's; only its vendor message packages are on the include path and in
        the key (None: every available one). ``variants``: other releases of those packages to compile
        against instead of the default ones (tests/support/vendor_msgs.py: VARIANTS). ``package``: a
        generated package the source includes from; only the package files the compiler actually read
        are in the key (PackageDeps), so a change to one header rebuilds only what includes it."""
        # Paths are not part of the key (the same sources in another folder give the same object),
        # so the distro, which picks the stand-in folders, is.
        message_flags, messages = self._message_parts(transport, variants)
        key = self._key("compile", source.name, source.read_text(encoding="utf-8"), *flags,
                        self._standins, messages, f"distro={distro}", *digest_parts)
        cmd = [self.cxx, *WARNING_FLAGS, "-pthread", *flags, *(f"-I{p}" for p in includes),
               *message_flags, "-c", str(source)]
        if package is None:
            return self._run(key, self.cache_dir / f"{name}-{key}.o", cmd)
        return self._run_tracked(key, name, cmd, PackageDeps(self.cache_dir / f"{name}-{key}.deps", package))

    def _run_tracked(self, base: str, name: str, cmd: list[str], deps: PackageDeps) -> CompileResult:
        """_run for a source that includes a generated package: the object's key is ``base`` plus the
        contents of the package files it read (recorded by g++ -MD in the manifest the first time)."""
        for files in deps.candidates():
            digest = deps.digest(files)
            if digest is not None:
                key = self._key(base, digest)
                out = self.cache_dir / f"{name}-{key}.o"
                if out.exists() or key in self._results:
                    return self._run(key, out, cmd)
        # Not built for this package content yet: compiled once per (base, whole package) in this session.
        whole = self._key(base, "package", package_digest(deps.package))
        done, event = self._claim(whole)
        if done is not None:
            return done
        start = time.monotonic()
        tmp = self.cache_dir / f"{name}-{whole}.{os.getpid()}.tmp"
        depfile = tmp.with_suffix(".d")
        full = [*cmd, "-MD", "-MF", str(depfile), "-o", str(tmp)]
        with self._slots:
            proc = subprocess.run(full, capture_output=True, text=True, env=ENV_C)
        seconds = time.monotonic() - start
        out, key = tmp, whole
        if proc.returncode == 0:
            key = self._key(base, deps.digest(deps.record(depfile)) or "")
            out = self.cache_dir / f"{name}-{key}.o"
            os.replace(tmp, out)
        depfile.unlink(missing_ok=True)
        result = CompileResult(proc.returncode == 0, out, full, proc.stderr, seconds)
        with self._lock:
            self.compile_seconds += seconds
            self.compiled += 1
            self._results[whole] = self._results[key] = result
            event.set()
        return result

    def link(self, objects: Sequence[CompileResult], flags: Sequence[str], name: str,
             libs: Sequence[str] = ()) -> CompileResult:
        """``libs`` come after the objects (-l options resolve what the objects before them need)."""
        key = self._key("link", *(o.path.name for o in objects), *flags, *libs)
        out = self.cache_dir / f"{name}-{key}"
        cmd = [self.cxx, "-pthread", *flags, *(str(o.path) for o in objects), *libs]
        return self._run(key, out, cmd)


@dataclass
class RobotBuild:
    """One robot of a rendered package, ready to build harness binaries."""
    loaded: LoadedRobot
    package_dir: Path
    data_dir: Path
    data_header: str

    @property
    def model(self) -> RobotModel:
        return self.loaded.model

    @property
    def label(self) -> str:
        return f"{self.model.vendor}/{self.model.robot}"


def prepare_robot_builds(loaded_robots, package_dir: Path, work_dir: Path) -> list[RobotBuild]:
    builds = []
    for loaded in loaded_robots:
        m = loaded.model
        data_dir = work_dir / f"data_{m.vendor}_{m.robot}"
        data_dir.mkdir(parents=True, exist_ok=True)
        header = robot_data_header(loaded, package_dir, data_dir)
        (data_dir / "robot_data.hpp").write_text(header, encoding="utf-8")
        builds.append(RobotBuild(loaded, package_dir, data_dir, header))
    return builds


def crc_header(package_dir: Path, family: str = "hg") -> Path | None:
    """The generated header of one unitree message family (its CRC), wherever the templates put it."""
    found = sorted((package_dir / "include").rglob(f"unitree_{family}*.hpp"))
    return found[0] if found else None


def unitree_family(model) -> str:
    """The message family of a unitree_dds robot as the loaded model has it."""
    return getattr(model.transport_options, "family", "") or "hg"


def package_digest(package_dir: Path) -> str:
    return _tree_digest(package_dir / "include")


# The fake robot is another process on a real robot's network: in the harness binary its code (and the harness's
# fake-robot section, which includes the same headers) is moved to a namespace of its own, so that none of its
# symbols can merge with the driver's (the inline CRC tables, the templates both instantiate). A driver built
# from other sources than the fake robot (a mutation: tests/cpp/test_cpp_mutations.py) then links without an
# ODR violation, and each side runs its own code, as two processes do.
ROBOT_SIDE_FLAGS = ("-Drobot_hardware_interface=rhi_harness_robot_side",)


def compile_harness_object(builder: CppBuilder, rb: RobotBuild, flavour: str,
                           distro: str = DEFAULT_DISTRO, robot_side: RobotBuild | None = None,
                           extra_flags: Sequence[str] = (), extra_key: str = "") -> CompileResult:
    """driver_harness.cpp for one robot against ``distro``'s stand-ins (no driver needed; with a fake robot,
    its section includes the fake robot headers of ``robot_side``'s package, ``rb``'s by default). ``extra_flags``
    (the physics sections') and ``extra_key`` (what else they depend on) go into the compile and its key."""
    m = rb.model
    robot_package = (robot_side or rb).package_dir
    fake = fake_robot_source(robot_package, m.vendor, m.robot) is not None
    return builder.compile(HARNESS_DIR / "driver_harness.cpp",
                           (*harness_flags(flavour), *ROBOT_SIDE_FLAGS, *extra_flags),
                           [rb.data_dir, HARNESS_DIR, TOY_BUS_DIR, *([robot_package / "include"] if fake else []),
                            *DISTROS[distro].include_dirs],
                           digest_parts=[rb.data_header, builder._harness, extra_key],
                           package=robot_package if fake else None,
                           name=f"harness_{m.vendor}_{m.robot}_{flavour}_{distro}", distro=distro,
                           transport=m.transport, variants=message_variants(rb.label))


def build_driver_object(builder: CppBuilder, rb: RobotBuild, flavour: str,
                        distro: str = DEFAULT_DISTRO) -> tuple[CompileResult, list[CompileResult]]:
    """Only the driver object (-Werror) against ``distro``'s stand-ins: the warning-free proof for
    a distro whose runtime path another distro's harness run already covers. Same shape as
    build_harness: (the object's result, [it])."""
    obj = compile_driver(builder, rb.package_dir, rb.label, rb.model.transport, flavour, distro)
    return obj, [obj]


def compile_driver(builder: CppBuilder, package_dir: Path, label: str, transport: str, flavour: str,
                   distro: str, flags: Sequence[str] | None = None) -> CompileResult:
    """The driver source of robot ``label`` ("vendor/robot") of ``package_dir`` (-Werror) in ``flavour`` (or with
    ``flags`` instead of the flavour's) against ``distro``'s stand-ins: the object every binary that links the
    driver shares (the harness, the gtest)."""
    vendor, robot = label.split("/")
    # A custom-transport driver's filled regions include the toy bus (tests/cpp/toy_bus/).
    toy_bus = [TOY_BUS_DIR] if transport == "custom" else []
    return builder.compile(driver_source(package_dir, vendor, robot), FLAVOURS[flavour] if flags is None else flags,
                           [package_dir / "include", *toy_bus, *DISTROS[distro].include_dirs],
                           digest_parts=[builder._harness if toy_bus else ""], package=package_dir,
                           name=f"driver_{vendor}_{robot}_{flavour}_{distro}", distro=distro,
                           transport=transport, variants=message_variants(label))


# The fake robot on MuJoCo in the harness (tests/cpp/harness/physics_checks.inc, issue 36): in PHYSICS_CELL the
# harness and fake robot objects of these robots are built with MuJoCo (the test extra's mujoco-core) and the binary
# runs the physics sections on the package's URDF: the faults on every one (its robot held as the base says), and
# the scenarios named. No other cell changes: the physics adds no compile to the suite.
PHYSICS_CELL = ("jazzy", "plain")


@dataclass(frozen=True)
class PhysicsRobot:
    base: str                         # how the faults section holds it: band (a floating base) or fixed
    scenarios: tuple[str, ...] = ()   # band, arm (the joints ARM_JOINTS names, base fixed), roll
    arm: str = ""                     # a regular expression of the arm's joints, for "arm"


PHYSICS_ROBOTS = {
    "unitree/g1": PhysicsRobot("band", ("band", "arm", "stand", "stand_stiff"), r"left_(shoulder|elbow|wrist)"),
    "engineai/pm01": PhysicsRobot("band", ("band", "stand")),
    "engineai/pm01_native_sdk": PhysicsRobot("band"),
    "agibot/x2": PhysicsRobot("band", ("band", "stand", "stand_stiff")),
    "unitree/go2w": PhysicsRobot("band", ("roll",)),
}


def physics_robot(label: str, distro: str, flavour: str) -> PhysicsRobot | None:
    """How robot ``label`` runs on MuJoCo in the harness cell (distro, flavour); None: in a vacuum only."""
    return PHYSICS_ROBOTS.get(label) if (distro, flavour) == PHYSICS_CELL else None


def physics_arguments(rb: RobotBuild, physics: PhysicsRobot) -> list[str]:
    """The harness binary's options for its physics sections (driver_harness.cpp main)."""
    arm = [j for j in yaml_joint_map(rb.loaded.yaml_path) if physics.arm and re.search(physics.arm, j)]
    return [f"--physics-urdf={rb.package_dir / 'urdf' / f'{rb.model.robot}.urdf'}", f"--physics-base={physics.base}",
            f"--physics={','.join(physics.scenarios)}", f"--physics-arm={','.join(arm)}"]


def _mujoco_parts() -> tuple[list[str], list[str], str] | None:
    """(compile flags, link arguments, the library's name: part of the object keys), None without MuJoCo."""
    mj = mujoco_dir()
    libs = sorted(mj.glob("libmujoco.so*")) if mj is not None else []
    if not libs:
        return None
    return ["-DRHI_FAKE_PHYSICS_MUJOCO", *mujoco_include_flags()], \
        ["-Wl,--no-as-needed", str(libs[-1]), f"-Wl,-rpath,{mj}"], libs[-1].name


def build_harness(builder: CppBuilder, rb: RobotBuild, flavour: str, distro: str = DEFAULT_DISTRO,
                  robot_side: RobotBuild | None = None, physics: bool = False
                  ) -> tuple[CompileResult, list[CompileResult]]:
    """Driver object (-Werror), harness object, fake robot object (where the package has one), CRC probe
    (unitree) and the linked binary, all against ``distro``'s stand-ins. ``robot_side``: the same robot in
    another rendered package to build the fake robot from (the robot as it really is, when ``rb``'s driver
    is broken on purpose); ``rb`` by default. ``physics``: the fake robot and the harness with MuJoCo (the
    physics sections; a failed step when MuJoCo is not installed).

    Returns (link result, [object results]); the objects are compiled at once, the link only when all are."""
    m = rb.model
    flags = FLAVOURS[flavour]
    pkg_include = rb.package_dir / "include"
    standins = DISTROS[distro].include_dirs
    tag = f"{m.vendor}_{m.robot}_{flavour}_{distro}"
    variants = message_variants(rb.label)
    mujoco = _mujoco_parts() if physics else None
    if physics and mujoco is None:
        return CompileResult(False, Path("mujoco"), [], "MuJoCo is not installed: pip install -e '.[test]' "
                             "installs mujoco-core (the harness's physics sections need it)"), []
    physics_flags, link_libs, mujoco_key = mujoco if mujoco is not None else ([], [], "")
    tasks: list[Callable[[], CompileResult]] = [
        lambda: compile_driver(builder, rb.package_dir, rb.label, m.transport, flavour, distro),
        lambda: compile_harness_object(builder, rb, flavour, distro, robot_side,
                                       [*physics_flags, "-DRHI_HARNESS_PHYSICS"] if mujoco else [], mujoco_key)]
    robot_package = (robot_side or rb).package_dir
    fake = fake_robot_source(robot_package, m.vendor, m.robot)
    if fake is not None:
        tasks.append(lambda: builder.compile(fake, (*flags, *ROBOT_SIDE_FLAGS, *physics_flags),
                                             [robot_package / "include", *standins], digest_parts=[mujoco_key],
                                             package=robot_package, name=f"fake_{tag}", distro=distro,
                                             transport=m.transport, variants=variants))
    if m.transport == "unitree_dds":
        family = unitree_family(m)
        header = crc_header(rb.package_dir, family)
        if header is None:
            missing = CompileResult(False, Path("crc_probe"), [], f"no unitree_{family}*.hpp in the generated package")
            tasks.append(lambda: missing)
        else:
            rel = header.relative_to(pkg_include).as_posix()
            probe_flags = (*flags, f'-DRHI_CRC_HEADER="{rel}"', f"-DRHI_UNITREE_FAMILY_{family.upper()}=1")
            tasks.append(lambda: builder.compile(HARNESS_DIR / "crc_probe.cpp", probe_flags,
                                                 [pkg_include, *standins], package=rb.package_dir,
                                                 name=f"crcprobe_{tag}", distro=distro, transport=m.transport))
    # at once: the builder runs one compiler per core however many ask, so the last cells of a fixture keep
    # both cores busy instead of compiling their objects one after another
    steps = run_concurrently(tasks)
    failed = [s for s in steps if not s.ok]
    if failed:
        return failed[0], steps
    return builder.link(steps, flags, f"harness_{tag}", link_libs), steps


@dataclass
class HarnessRun:
    returncode: int
    stdout: str
    stderr: str
    seconds: float
    passed: int = 0
    failed: int = 0
    sections: dict[str, tuple[int, int]] = field(default_factory=dict)

    @property
    def failures(self) -> list[str]:
        return [line for line in self.stdout.splitlines() if line.startswith("FAIL ")]

    def sanitizer_reports(self) -> list[str]:
        marks = ("WARNING: ThreadSanitizer", "ERROR: AddressSanitizer", "runtime error:",
                 "ERROR: LeakSanitizer", "SUMMARY: UndefinedBehaviorSanitizer")
        return [line for line in self.stderr.splitlines() if any(m in line for m in marks)]

    def describe(self) -> str:
        tail = "\n".join(self.stdout.splitlines()[-60:])
        return (f"exit {self.returncode}; {self.passed} passed, {self.failed} failed\n"
                f"{chr(10).join(self.failures[:40])}\n--- stdout (tail)\n{tail}\n--- stderr (tail)\n"
                f"{self.stderr[-6000:]}")


def _parse_run(proc_returncode: int, stdout: str, stderr: str, seconds: float) -> HarnessRun:
    run = HarnessRun(proc_returncode, stdout, stderr, seconds)
    for name, p, f in re.findall(r"^section (\S+): (\d+) passed, (\d+) failed$", stdout, re.M):
        run.sections[name] = (int(p), int(f))
    total = re.search(r"^rhi-check: (\d+) passed, (\d+) failed$", stdout, re.M)
    if total:
        run.passed, run.failed = int(total.group(1)), int(total.group(2))
    return run


def run_binary(binary: Path, args: Sequence[str] = (), timeout: float = 300,
               prefix: Sequence[str] = (), env: dict[str, str] | None = None) -> HarnessRun:
    """Run a harness binary with the sanitizer options; a time-out is a failed run (exit -9)."""
    start = time.monotonic()
    try:
        proc = subprocess.run([*prefix, str(binary), *args], capture_output=True, text=True, timeout=timeout,
                              env={**ENV_C, **SANITIZER_ENV, **(env or {})})
    except subprocess.TimeoutExpired as exc:
        out = exc.stdout.decode(errors="replace") if isinstance(exc.stdout, bytes) else (exc.stdout or "")
        err = exc.stderr.decode(errors="replace") if isinstance(exc.stderr, bytes) else (exc.stderr or "")
        return _parse_run(-9, out, err + f"\n(time-out after {timeout:.0f} s)", time.monotonic() - start)
    return _parse_run(proc.returncode, proc.stdout, proc.stderr, time.monotonic() - start)


# Threads for a pool whose jobs build (the builder allows one compiler per core) and then run a binary that
# mostly sleeps: the runs overlap the compiles.
OVERLAP_WORKERS = (os.cpu_count() or 1) + 3
# Threads for runs of binaries that mostly wait on their timers: the mutants' harness runs take 7 to 67 s each and
# at most 6 % of one core (measured), most of them sleeping until a check's deadline. Many run at once, next to
# the builds (the builder keeps one compiler per core): with twelve per core the mutations module on cached objects
# took 88 s instead of 119 s with six, its runs' total time unchanged (1198 s against 1193 s).
WAITING_WORKERS = 12 * (os.cpu_count() or 1)


def run_parallel(jobs, fn, workers: int | None = None) -> list:
    """fn over jobs on a thread pool (compilers and test binaries are separate processes)."""
    with ThreadPoolExecutor(max_workers=workers or max(1, os.cpu_count() or 1)) as pool:
        return list(pool.map(fn, jobs))


def run_concurrently(tasks: Sequence[Callable[[], T]]) -> list[T]:
    """Each task on a thread of its own, in order; what each read of ../shared counts for this thread, as if it
    had run here (tests/support/shared_use.py: a worker thread's reads go to its own recording)."""
    def one(task: Callable[[], T]) -> tuple[T, set[str]]:
        with shared_use.recording() as used:
            return task(), set(used)

    results = run_parallel(tasks, one, len(tasks))
    for _, used in results:
        shared_use.replay(used)
    return [result for result, _ in results]


def run_binary_retrying(binary: Path, args: Sequence[str] = (), timeout: float = 300) -> HarnessRun:
    """run_binary, run again when the sanitizer runtime cannot work in this environment (not a
    finding): TSan that cannot map its shadow memory (GCC 12 on kernels with vm.mmap_rnd_bits > 28)
    reruns without address-space randomisation, still under TSan."""
    run = run_binary(binary, args, timeout)
    if "unexpected memory mapping" in run.stderr and shutil.which("setarch"):
        return run_binary(binary, args, timeout, prefix=("setarch", os.uname().machine, "-R"))
    if "LeakSanitizer has encountered a fatal error" in run.stderr:
        # LeakSanitizer cannot stop the world under some container seccomp profiles: run ASan and
        # UBSan again without leak detection rather than fail on the environment.
        no_leaks = {"ASAN_OPTIONS": SANITIZER_ENV["ASAN_OPTIONS"].replace("detect_leaks=1", "detect_leaks=0")}
        return run_binary(binary, args, timeout, env=no_leaks)
    return run


# ------------------------------------------------------------------------------------ session state
# Shared by the C++ test modules of one pytest session (a conftest-free stand-in for session
# fixtures): one object cache, one rendered reference package.
_SESSION: dict[str, object] = {}
_SESSION_LOCK = threading.Lock()


def session_builder(tmp_path_factory) -> CppBuilder:
    """The session's CppBuilder. RHI_CPP_CACHE=<dir> keeps objects across sessions (development);
    keys hash every input, so a stale object cannot be picked up."""
    with _SESSION_LOCK:
        if "builder" not in _SESSION:
            cache = os.environ.get("RHI_CPP_CACHE")
            cache_dir = Path(cache) if cache else tmp_path_factory.mktemp("cpp_cache")
            _SESSION["builder"] = CppBuilder(cache_dir)
        return _SESSION["builder"]  # type: ignore[return-value]


def session_cache_dir() -> Path | None:
    """The session's object cache, once its CppBuilder exists (None before)."""
    with _SESSION_LOCK:
        builder = _SESSION.get("builder")
    return builder.cache_dir if isinstance(builder, CppBuilder) else None


@dataclass
class RenderedPackage:
    project: Path
    package_dir: Path
    loaded: list
    builds: list[RobotBuild]

    def build(self, label: str) -> RobotBuild:
        return next(b for b in self.builds if b.label == label)


def fill_custom_regions(loaded_robots, package_dir: Path, regions: Path = TOY_BUS_REGIONS) -> list[Path]:
    """Fill the user regions of every custom-transport robot's source with ``regions`` (the toy bus),
    through rhi-gen's own splice, as a regeneration over a filled file does. Returns the files filled."""
    from rhi_gen.write.regions import splice

    filled = []
    for loaded in loaded_robots:
        m = loaded.model
        if m.transport != "custom":
            continue
        path = driver_source(package_dir, m.vendor, m.robot)
        text, orphans = splice(path.read_text(encoding="utf-8"), regions.read_text(encoding="utf-8"), str(path))
        assert not orphans, f"{regions.name} has regions the generated {path.name} lacks: {orphans}"
        path.write_text(text, encoding="utf-8")
        filled.append(path)
    return filled


def render_test_package(root: Path, *, only: Sequence[str] | None = None, extra_robots: bool = True,
                        fill_custom: bool = True) -> RenderedPackage:
    """Project (robots/ + test robots) -> rendered package -> robot_data.hpp per robot, under root.

    ``fill_custom``: custom-transport robots get the toy bus filled into their user regions (without
    it they are as generated: they compile, and refuse to activate)."""
    project = make_test_project(root / "project", extra_robots=extra_robots, only=only)
    loaded = load_models(project)
    package_dir = root / "generated" / PACKAGE
    render_package_to(loaded, package_dir)
    if fill_custom:
        fill_custom_regions(loaded, package_dir)
    builds = prepare_robot_builds(loaded, package_dir, root / "work")
    return RenderedPackage(project, package_dir, loaded, builds)


def session_reference_package(tmp_path_factory) -> RenderedPackage:
    """The package of every robot of robots/ (+ test robots), rendered from the shipped templates."""
    with _SESSION_LOCK:
        if "reference" not in _SESSION:
            _SESSION["reference"] = render_test_package(tmp_path_factory.mktemp("reference"))
        return _SESSION["reference"]  # type: ignore[return-value]


def label_yaml(label: str) -> Path:
    """The vendor YAML of "vendor/robot": robots/, else the harness's test robots."""
    path = REPO / "robots" / f"{label}.yaml"
    return path if path.is_file() else HARNESS_ROBOTS / f"{label}.yaml"


def label_transport(label: str) -> str:
    """The transport "vendor/robot"'s YAML names, known before anything is rendered."""
    return str(yaml.safe_load(label_yaml(label).read_text(encoding="utf-8"))["transport"])


def project_robot_labels(extra_robots: bool = True) -> list[str]:
    """vendor/robot of every vendor YAML (known at collection time, before anything is generated)."""
    folders = [REPO / "robots"] + ([HARNESS_ROBOTS] if extra_robots and HARNESS_ROBOTS.is_dir() else [])
    return sorted(f"{y.parent.name}/{y.stem}" for folder in folders for y in folder.glob("*/*.yaml"))


def compile_data_buffer_stress(builder: CppBuilder, package_dir: Path, flavour: str) -> CompileResult:
    src = HARNESS_DIR / "data_buffer_stress.cpp"
    obj = builder.compile(src, FLAVOURS[flavour], [package_dir / "include", HARNESS_DIR],
                          digest_parts=[builder._harness], package=package_dir,
                          name=f"data_buffer_{flavour}", transport="")
    if not obj.ok:
        return obj
    return builder.link([obj], FLAVOURS[flavour], f"data_buffer_{flavour}")


def compile_transmission_checks(builder: CppBuilder, package_dir: Path, flavour: str, distro: str) -> CompileResult:
    """tests/cpp/harness/transmission_checks.cpp against the package's common headers and ``distro``'s stand-ins."""
    src = HARNESS_DIR / "transmission_checks.cpp"
    includes = [package_dir / "include", HARNESS_DIR, *DISTROS[distro].include_dirs]
    name = f"transmission_checks_{distro}_{flavour}"
    obj = builder.compile(src, FLAVOURS[flavour], includes, name=name, distro=distro, transport="",
                          digest_parts=[builder._harness], package=package_dir)
    if not obj.ok:
        return obj
    return builder.link([obj], FLAVOURS[flavour], name)
