"""Finding and running g++ for tests: a missing compiler fails the test, it never skips it.

The second half builds and runs the driver harness (tests/cpp/harness/README.md)."""
from __future__ import annotations

import hashlib
import math
import os
import re
import shutil
import subprocess
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Sequence

import pytest

REPO = Path(__file__).resolve().parents[1]
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


def driver_source(package_dir: Path, vendor: str, robot: str) -> Path:
    return package_dir / "src" / vendor / f"{robot}.cpp"


def include_flags(package_dir: Path, extra: Iterable[Path] = (), distro: str = DEFAULT_DISTRO) -> list[str]:
    return [f"-I{package_dir / 'include'}", *standin_flags(distro), *(f"-I{p}" for p in extra)]


def syntax_check_driver(package_dir: Path, vendor: str, robot: str, flags: Sequence[str] = (),
                        distro: str = DEFAULT_DISTRO) -> None:
    """Compile one generated driver against ``distro``'s stand-in headers with -Werror (no linking)."""
    source = driver_source(package_dir, vendor, robot)
    run_compiler([*WARNING_FLAGS, *flags, "-fsyntax-only", *include_flags(package_dir, distro=distro), str(source)],
                 what=f"{vendor}/{robot} driver ({distro})")


# =====================================================================================================
# Driver harness builds (tests/test_cpp_drivers.py, test_cpp_data_buffer.py, test_cpp_mutations.py)
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
PACKAGE = "robot_hardware_interface"
ENV_C = {**os.environ, "LC_ALL": "C", "LANG": "C"}

# Build flavours of the harness binaries. Every flavour compiles the driver with -Werror.
FLAVOURS: dict[str, tuple[str, ...]] = {
    # -O2 is how a release build of the driver runs
    "plain": ("-O2",),
    "asan_ubsan": ("-O1", "-g1", "-fno-omit-frame-pointer", "-fsanitize=address,undefined",
                   "-fno-sanitize-recover=all"),
    "tsan": ("-O1", "-g1", "-fsanitize=thread"),
}
SANITIZER_ENV = {
    "ASAN_OPTIONS": "abort_on_error=0:halt_on_error=1:detect_leaks=1",
    "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1",
    "TSAN_OPTIONS": "halt_on_error=1:second_deadlock_stack=1",
}
TRANSPORT_MACROS = {
    "unitree_dds": "RHI_TRANSPORT_UNITREE_DDS",
    "agibot_topics": "RHI_TRANSPORT_AGIBOT_TOPICS",
    "engineai_topics": "RHI_TRANSPORT_ENGINEAI_TOPICS",
    "generic_topics": "RHI_TRANSPORT_GENERIC_TOPICS",
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
    from rhi_gen.pipeline import load_robots
    from rhi_gen.project import Project

    return load_robots(Project(project_root.resolve()))


def template_env_factory(template_dir: Path):
    """An env_factory for render_package: make_environment()'s settings, templates from a folder."""
    import jinja2
    from rhi_gen.render import make_environment

    def factory():
        env = make_environment()
        env.loader = jinja2.FileSystemLoader(str(template_dir))
        return env

    return factory


def render_package_to(loaded_robots, package_dir: Path, env_factory=None) -> dict[str, str]:
    """Render the package for ``loaded_robots`` into ``package_dir``; returns the plan."""
    from rhi_gen.render import render_package

    models = [r.model for r in loaded_robots]
    plan = render_package(models) if env_factory is None else render_package(models, env_factory=env_factory)
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


def expand_description(package_dir: Path, robot: str, work_dir: Path) -> Description:
    """Expand description/<robot>.ros2_control.xacro the way a user does: include it from a robot
    through $(find robot_hardware_interface) and call its macro with the defaults."""
    from lxml import etree
    from rhi_gen.xacro_expand import expand_xacro

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

    def params(element) -> dict[str, str]:
        return {p.get("name"): (p.text or "").strip() for p in element.findall("param")}

    def component(element) -> dict:
        return {
            "name": element.get("name"),
            "command_interfaces": [(c.get("name"), params(c)) for c in element.findall("command_interface")],
            "state_interfaces": [s.get("name") for s in element.findall("state_interface")],
            "parameters": params(element),
        }

    return Description(
        name=block.get("name"), type=block.get("type"),
        plugin=(hardware.findtext("plugin") or "").strip(),
        parameters=params(hardware),
        joints=[component(j) for j in block.findall("joint")],
        sensors=[component(s) for s in block.findall("sensor")],
    )


def plugin_types(package_dir: Path) -> dict[str, str]:
    """robot_hardware_interface.xml: plugin name -> C++ type."""
    from lxml import etree

    root = etree.parse(str(package_dir / f"{PACKAGE}.xml")).getroot()
    return {c.get("name"): c.get("type") for c in root.iter("class")}


def yaml_joint_map(yaml_path: Path) -> dict[str, int]:
    """joint_map exactly as the vendor YAML writes it (the harness's source of truth for the map)."""
    import yaml

    data = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    return {str(name): int(index) for name, index in data["joint_map"].items()}


def robot_data_header(loaded, package_dir: Path, work_dir: Path) -> str:
    """robot_data.hpp for one robot (namespace rhi_data, see tests/cpp/harness/harness_common.hpp)."""
    model = loaded.model
    joint_map = yaml_joint_map(loaded.yaml_path)
    by_name = {j.name: j for j in model.joints}
    assert set(joint_map) == set(by_name), f"{model.robot}: YAML joint_map and model joints differ"
    assert all(by_name[n].index == i for n, i in joint_map.items()), f"{model.robot}: model moved a joint"
    description = expand_description(package_dir, model.robot, work_dir)
    plugins = plugin_types(package_dir)
    opts = model.transport_options
    params = model.parameters

    if model.transport == "agibot_topics":
        groups = [(g.name, g.offset, g.size, g.command_topic, g.state_topic) for g in opts.groups]
    elif model.transport == "unitree_dds":
        groups = [("all", 0, model.motor_count, opts.lowcmd_topic, opts.lowstate_topic)]
    else:
        groups = [("all", 0, model.motor_count, opts.command_topic, opts.state_topic)]

    def group_of(slot: int) -> int:
        for g, (_, offset, size, _, _) in enumerate(groups):
            if offset <= slot < offset + size:
                return g
        raise AssertionError(f"{model.robot}: slot {slot} is in no joint group")

    lines = [
        "// Written by tests/cpp_build.py for the driver harness: do not edit.",
        f"// robot {model.vendor}/{model.robot} from {loaded.yaml_path.name} (joint map read from the YAML).",
        "#pragma once",
        "#include <cstddef>",
        "#include <cstdint>",
        "#include <limits>",
        f"#define {TRANSPORT_MACROS[model.transport]} 1",
    ]
    if model.transport != "unitree_dds":
        lines.append("#define RHI_TRANSPORT_ROS 1")
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
        "struct Joint { const char* name; size_t slot; size_t group; double lower; double upper; double velocity;"
        " double effort; };",
        "inline constexpr Joint kJoints[] = {",
    ]
    for name, slot in joint_map.items():
        limits = by_name[name].limits
        lower = limits.lower if limits else None
        upper = limits.upper if limits else None
        lines.append(
            f"    {{{_c_string(name)}, {slot}, {group_of(slot)}, "
            f"{_c_double(-math.inf if lower is None else lower)}, {_c_double(upper)}, "
            f"{_c_double(limits.velocity if limits else None)}, {_c_double(limits.effort if limits else None)}}},")
    lines += [
        "};",
        f"inline constexpr size_t kJointCount = {len(joint_map)};",
        "struct Group { const char* name; size_t offset; size_t size; const char* command_topic;"
        " const char* state_topic; };",
        "inline constexpr Group kGroups[] = {",
        *(f"    {{{_c_string(n)}, {o}, {s}, {_c_string(c)}, {_c_string(st)}}}," for n, o, s, c, st in groups),
        "};",
        f"inline constexpr size_t kGroupCount = {len(groups)};",
        f"inline constexpr char kCommandTopic[] = {_c_string(groups[0][3])};",
        f"inline constexpr char kStateTopic[] = {_c_string(groups[0][4])};",
        f"inline constexpr char kImuTopic[] = {_c_string(opts.imu_topic)};",
        f"inline constexpr uint8_t kModePr = {opts.mode_pr};",
        f"inline constexpr uint8_t kParallelParserType = {opts.parallel_parser_type};",
        "// parameter defaults: the vendor YAML's parameters (spec defaults where it gives none)",
        f"inline constexpr uint64_t kDefaultPeriodUs = {params.command_writer_period_us};",
        f"inline constexpr uint32_t kDefaultDecimation = {params.state_decimation};",
        f"inline constexpr char kDefaultNetworkInterface[] = {_c_string(params.network_interface)};",
        "// what the ros2_control description passes",
        f"inline constexpr uint64_t kDescriptionPeriodUs = "
        f"{int(description.parameters.get('command_writer_period_us', params.command_writer_period_us))};",
        f"inline constexpr uint64_t kDescriptionTimeoutMs = "
        f"{int(description.parameters.get('state_timeout_ms', params.state_timeout_ms))};",
        f"inline constexpr char kDescriptionNetworkInterface[] = "
        f"{_c_string(description.parameters.get('network_interface', params.network_interface))};",
        "// the <ros2_control> block of the expanded description, as records (see make_hardware_info())",
        "struct InfoRecord { char kind; const char* a; const char* b; const char* c; };",
        "inline constexpr InfoRecord kInfoRecords[] = {",
        f"    {{'N', {_c_string(description.name)}, {_c_string(description.type)}, \"\"}},",
        f"    {{'L', {_c_string(description.plugin)}, \"\", \"\"}},",
    ]
    for key, value in description.parameters.items():
        lines.append(f"    {{'H', {_c_string(key)}, {_c_string(value)}, \"\"}},")
    for kind, components in (("J", description.joints), ("S", description.sensors)):
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


class CppBuilder:
    """Compiles and links with a content-addressed cache (key = everything that goes in).

    Thread-safe: the same object requested twice is compiled once."""

    def __init__(self, cache_dir: Path, jobs: int | None = None) -> None:
        self.cxx = require_compiler()
        self.cache_dir = cache_dir
        cache_dir.mkdir(parents=True, exist_ok=True)
        self.jobs = jobs or max(1, os.cpu_count() or 1)
        version = subprocess.run([self.cxx, "--version"], capture_output=True, text=True).stdout
        self._salt = hashlib.sha256(version.encode()).hexdigest()
        self._standins = _tree_digest(STANDINS, (".hpp", ".h"))  # every distro's headers
        self._harness = _tree_digest(HARNESS_DIR)
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

    def _run(self, key: str, out: Path, cmd: list[str]) -> CompileResult:
        with self._lock:
            if key in self._results:
                self.reused += 1
                return self._results[key]
            event = self._inflight.get(key)
            owner = event is None
            if owner:
                event = self._inflight[key] = threading.Event()
        if not owner:
            event.wait()
            with self._lock:
                self.reused += 1
                return self._results[key]
        if out.exists():
            result = CompileResult(True, out, cmd, cached=True)
        else:
            start = time.monotonic()
            tmp = out.with_name(out.name + ".tmp")
            full = [*cmd, "-o", str(tmp)]
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

    def compile(self, source: Path, flags: Sequence[str], includes: Sequence[Path], *,
                digest_parts: Sequence[str], name: str, distro: str = DEFAULT_DISTRO) -> CompileResult:
        # Paths are not part of the key (the same sources in another folder give the same object),
        # so the distro, which picks the stand-in folders, is.
        key = self._key("compile", source.name, source.read_text(encoding="utf-8"), *flags,
                        self._standins, f"distro={distro}", *digest_parts)
        out = self.cache_dir / f"{name}-{key}.o"
        cmd = [self.cxx, *WARNING_FLAGS, "-pthread", *flags, *(f"-I{p}" for p in includes), "-c", str(source)]
        return self._run(key, out, cmd)

    def link(self, objects: Sequence[CompileResult], flags: Sequence[str], name: str) -> CompileResult:
        key = self._key("link", *(o.path.name for o in objects), *flags)
        out = self.cache_dir / f"{name}-{key}"
        cmd = [self.cxx, "-pthread", *flags, *(str(o.path) for o in objects)]
        return self._run(key, out, cmd)


@dataclass
class RobotBuild:
    """One robot of a rendered package, ready to build harness binaries."""
    loaded: object
    package_dir: Path
    data_dir: Path
    data_header: str

    @property
    def model(self):
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


def crc_header(package_dir: Path) -> Path | None:
    """The generated unitree hg CRC header, wherever the templates put it."""
    found = sorted((package_dir / "include").rglob("*crc*.hpp"))
    return found[0] if found else None


def package_digest(package_dir: Path) -> str:
    return _tree_digest(package_dir / "include")


def compile_harness_object(builder: CppBuilder, rb: RobotBuild, flavour: str,
                           distro: str = DEFAULT_DISTRO) -> CompileResult:
    """driver_harness.cpp for one robot against ``distro``'s stand-ins (no driver needed)."""
    m = rb.model
    return builder.compile(HARNESS_DIR / "driver_harness.cpp", FLAVOURS[flavour],
                           [rb.data_dir, HARNESS_DIR, *DISTROS[distro].include_dirs],
                           digest_parts=[rb.data_header, builder._harness],
                           name=f"harness_{m.vendor}_{m.robot}_{flavour}_{distro}", distro=distro)


def build_harness(builder: CppBuilder, rb: RobotBuild, flavour: str,
                  distro: str = DEFAULT_DISTRO) -> tuple[CompileResult, list[CompileResult]]:
    """Driver object (-Werror), harness object, CRC probe (unitree) and the linked binary, all
    against ``distro``'s stand-ins.

    Returns (link result, [object results]); a failed step leaves later ones out."""
    m = rb.model
    flags = FLAVOURS[flavour]
    pkg_include = rb.package_dir / "include"
    standins = DISTROS[distro].include_dirs
    pkg = package_digest(rb.package_dir)
    tag = f"{m.vendor}_{m.robot}_{flavour}_{distro}"
    driver_src = driver_source(rb.package_dir, m.vendor, m.robot)
    steps = [builder.compile(driver_src, flags, [pkg_include, *standins], digest_parts=[pkg],
                             name=f"driver_{tag}", distro=distro)]
    steps.append(compile_harness_object(builder, rb, flavour, distro))
    if m.transport == "unitree_dds":
        header = crc_header(rb.package_dir)
        if header is None:
            steps.append(CompileResult(False, Path("crc_probe"), [], "no *crc*.hpp in the generated package"))
        else:
            rel = header.relative_to(pkg_include).as_posix()
            steps.append(builder.compile(HARNESS_DIR / "crc_probe.cpp", (*flags, f'-DRHI_CRC_HEADER="{rel}"'),
                                         [pkg_include, *standins], digest_parts=[pkg],
                                         name=f"crcprobe_{tag}", distro=distro))
    failed = [s for s in steps if not s.ok]
    if failed:
        return failed[0], steps
    return builder.link(steps, flags, f"harness_{tag}"), steps


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


def run_parallel(jobs, fn, workers: int | None = None) -> list:
    """fn over jobs on a thread pool (compilers and test binaries are separate processes)."""
    with ThreadPoolExecutor(max_workers=workers or max(1, os.cpu_count() or 1)) as pool:
        return list(pool.map(fn, jobs))


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


@dataclass
class RenderedPackage:
    project: Path
    package_dir: Path
    loaded: list
    builds: list[RobotBuild]

    def build(self, label: str) -> RobotBuild:
        return next(b for b in self.builds if b.label == label)


def render_test_package(root: Path, *, only: Sequence[str] | None = None, template_dir: Path | None = None,
                        extra_robots: bool = True) -> RenderedPackage:
    """Project (robots/ + test robots) -> rendered package -> robot_data.hpp per robot, under root."""
    project = make_test_project(root / "project", extra_robots=extra_robots, only=only)
    loaded = load_models(project)
    package_dir = root / "generated" / PACKAGE
    factory = template_env_factory(template_dir) if template_dir is not None else None
    render_package_to(loaded, package_dir, factory)
    builds = prepare_robot_builds(loaded, package_dir, root / "work")
    return RenderedPackage(project, package_dir, loaded, builds)


def session_reference_package(tmp_path_factory) -> RenderedPackage:
    """The package of every robot of robots/ (+ test robots), rendered from the shipped templates."""
    with _SESSION_LOCK:
        if "reference" not in _SESSION:
            _SESSION["reference"] = render_test_package(tmp_path_factory.mktemp("reference"))
        return _SESSION["reference"]  # type: ignore[return-value]


def project_robot_labels(extra_robots: bool = True) -> list[str]:
    """vendor/robot of every vendor YAML (known at collection time, before anything is generated)."""
    folders = [REPO / "robots"] + ([HARNESS_ROBOTS] if extra_robots and HARNESS_ROBOTS.is_dir() else [])
    return sorted(f"{y.parent.name}/{y.stem}" for folder in folders for y in folder.glob("*/*.yaml"))


def compile_data_buffer_stress(builder: CppBuilder, package_dir: Path, flavour: str) -> CompileResult:
    src = HARNESS_DIR / "data_buffer_stress.cpp"
    obj = builder.compile(src, FLAVOURS[flavour], [package_dir / "include", HARNESS_DIR],
                          digest_parts=[package_digest(package_dir), builder._harness],
                          name=f"data_buffer_{flavour}")
    if not obj.ok:
        return obj
    return builder.link([obj], FLAVOURS[flavour], f"data_buffer_{flavour}")
