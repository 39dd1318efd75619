"""Load and validate a vendor YAML into a VendorConfig.

Every problem is a ConfigError naming the file, the line, the key and the fix. Checks that need the
URDF (joint names exist, every actuated joint mapped) live in build.py.
"""
from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any, Callable

import yaml

from .errors import ConfigError
from .model import (FLOAT_TYPES, TRANSPORTS, ImuConfig, JointGroup, Parameters, QosConfig,
                    TransportOptions, VendorConfig)
from .naming import CLASS_PREFIX_RE, CPP_KEYWORDS, identifier_problem, suggest, vendor_problem

MAX_YAML_BYTES = 5 * 1024 * 1024
MAX_NODES = 200_000
MAX_MOTORS = 4096

TOP_KEYS = ("vendor", "robot", "urdf", "transport", "motor_count", "float_type", "class_prefix",
            "xacro_args", "package_paths", "imu", "parameters", "transport_options", "joint_map",
            "unmapped_joints")
REQUIRED_KEYS = ("vendor", "robot", "urdf", "transport", "motor_count", "joint_map")
PARAMETER_KEYS = ("network_interface", "enable_monitor", "command_writer_period_us",
                  "state_decimation", "state_timeout_ms")
IMU_KEYS = ("enabled", "name", "frame_id")
QOS_KEYS = ("reliability", "durability", "depth")
GROUP_KEYS = ("name", "size", "command_topic", "state_topic")
TRANSPORT_KEYS = {
    "unitree_dds": ("lowcmd_topic", "lowstate_topic", "sdk_slots", "domain_id", "mode_pr",
                    "release_motion_control"),
    "agibot_topics": ("groups", "imu_topic", "qos"),
    "engineai_topics": ("command_topic", "state_topic", "imu_topic", "parallel_parser_type", "qos"),
    "generic_topics": ("command_topic", "state_topic", "imu_topic", "qos"),
}
DEFAULT_FLOAT = {"unitree_dds": "float", "agibot_topics": "double", "engineai_topics": "double",
                 "generic_topics": "double"}
AGIBOT_DEFAULT_GROUPS = (("leg", 12), ("waist", 3), ("arm", 14), ("head", 2))

TOPIC_RE = re.compile(r"^/?[A-Za-z_~][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$")
FRAME_RE = re.compile(r"^[A-Za-z_][A-Za-z0-9_/.\-]*$")
NETIF_RE = re.compile(r"^[A-Za-z0-9_.:\-]{1,64}$")


class _Loader:
    """YAML -> plain Python, remembering the line of every key path ("a.b[2].c")."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.lines: dict[str, int] = {}
        self._count = 0
        self._active: set[int] = set()  # nodes being converted: an alias back to one is a cycle

    def error(self, message: str, path: str = "", fix: str | None = None, line: int | None = None) -> ConfigError:
        return ConfigError(message, file=self.source, line=line or self.lines.get(path), key=path or None, fix=fix)

    def convert(self, node: yaml.Node, path: str) -> Any:
        self._count += 1
        if self._count > MAX_NODES:
            raise self.error("the YAML is too large or expands too many aliases", fix="write a plain vendor YAML")
        self.lines.setdefault(path, node.start_mark.line + 1)
        if id(node) in self._active or len(self._active) > 64:
            raise self.error("the YAML refers to itself through an alias or nests too deeply", path,
                             fix="write the values out instead of using recursive anchors")
        if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
            self._active.add(id(node))
            try:
                return self._convert_collection(node, path)
            finally:
                self._active.discard(id(node))
        try:
            return _Scalar(node)
        except yaml.YAMLError as exc:
            raise self.error(f"cannot read this value: {getattr(exc, 'problem', None) or exc}", path,
                             fix="use plain strings, numbers and true/false") from exc

    def _convert_collection(self, node: yaml.Node, path: str) -> Any:
        if isinstance(node, yaml.MappingNode):
            out: dict[str, Any] = {}
            for key_node, value_node in node.value:
                if not isinstance(key_node, yaml.ScalarNode):
                    raise self.error("keys must be plain strings", path, line=key_node.start_mark.line + 1,
                                     fix="write each key as plain text (no '?', lists or mappings as keys)")
                key = key_node.value  # raw text: 'on'/'yes' stay names, not booleans
                sub = f"{path}.{key}" if path else key
                if key in out:
                    raise self.error(f"duplicate key {key!r}", sub, fix="keep one entry per key",
                                     line=key_node.start_mark.line + 1)
                self.lines[sub] = key_node.start_mark.line + 1
                out[key] = self.convert(value_node, sub)
            return out
        return [self.convert(item, f"{path}[{i}]") for i, item in enumerate(node.value)]


class _Scalar:
    """A scalar with both its raw text and its YAML 1.1 meaning."""
    __slots__ = ("raw", "value")

    def __init__(self, node: yaml.ScalarNode) -> None:
        self.raw = node.value
        loader = yaml.SafeLoader("")
        try:
            self.value = loader.construct_object(node, deep=True)
        finally:
            loader.dispose()


def _read_text(path: Path, shown: str) -> str:
    if not path.exists():
        raise ConfigError("file not found", file=shown, fix="check the path (rhi-gen list shows the robots)")
    if path.is_dir():
        raise ConfigError("is a directory, not a vendor YAML", file=shown, fix="give the path of the .yaml file")
    try:
        size = path.stat().st_size
        if size > MAX_YAML_BYTES:
            raise ConfigError(f"file is {size} bytes; a vendor YAML is a few kB", file=shown,
                              fix="start from `rhi-gen new` or the README's YAML reference")
        data = path.read_bytes()
    except OSError as exc:
        raise ConfigError(f"cannot read: {exc.strerror}", file=shown,
                          fix="check the file's permissions (chmod a+r)") from exc
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ConfigError("is not UTF-8 text", file=shown, fix="save the YAML as UTF-8") from exc


def parse_yaml_text(text: str, shown: str) -> tuple[dict[str, Any], dict[str, int]]:
    """Parse YAML text to a mapping of plain values (scalars as _Scalar) plus key -> line."""
    if not text.strip():
        raise ConfigError("file is empty", file=shown, fix="start from `rhi-gen new` or the README's YAML reference")
    try:
        docs = list(yaml.compose_all(text, Loader=yaml.SafeLoader))
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else None
        problem = f"{exc.problem or exc.context}"
        fix = ("indent with spaces, not tabs" if "\\t" in problem or "\t" in problem else
               "fix the YAML syntax at that line (quote values that contain ': ' or ' #')")
        raise ConfigError(f"invalid YAML: {problem}", file=shown, line=line, fix=fix) from exc
    except yaml.YAMLError as exc:
        raise ConfigError(f"invalid YAML: {exc}", file=shown, fix="fix the YAML syntax") from exc
    docs = [d for d in docs if d is not None]
    if not docs:
        raise ConfigError("file is empty (only comments)", file=shown,
                          fix="start from `rhi-gen new` or the README's YAML reference")
    if len(docs) > 1:
        raise ConfigError("holds several YAML documents; a vendor YAML is one mapping", file=shown,
                          line=docs[1].start_mark.line + 1, fix="remove the '---' and everything after it")
    root = docs[0]
    if not isinstance(root, yaml.MappingNode):
        kind = "a list" if isinstance(root, yaml.SequenceNode) else "a single value"
        raise ConfigError(f"top level is {kind}, not a mapping of keys", file=shown,
                          line=root.start_mark.line + 1, fix="write `vendor: ...`, `robot: ...` etc. as keys")
    loader = _Loader(shown)
    data = loader.convert(root, "")
    return data, loader.lines


class _Validator:
    def __init__(self, source: str, lines: dict[str, int]) -> None:
        self.source = source
        self.lines = lines

    def error(self, path: str, message: str, fix: str | None = None) -> ConfigError:
        return ConfigError(message, file=self.source, line=self.lines.get(path), key=path, fix=fix)

    def mapping(self, value: Any, path: str, allowed: tuple[str, ...]) -> dict[str, Any]:
        if isinstance(value, _Scalar) and value.raw in ("", "~", "null") and value.value is None:
            return {}
        if not isinstance(value, dict):
            raise self.error(path, "must be a mapping of keys", fix=f"allowed keys: {', '.join(allowed)}")
        for key in value:
            if key not in allowed:
                sub = f"{path}.{key}" if path else key
                hint = suggest(key, allowed)
                fix = f"did you mean {hint!r}?" if hint else f"allowed keys: {', '.join(allowed)}"
                raise self.error(sub, "unknown key", fix=fix)
        return value

    def scalar(self, value: Any, path: str) -> Any:
        if not isinstance(value, _Scalar):
            raise self.error(path, "must be a single value, not a list or mapping",
                             fix="write one value after the colon")
        return value.value

    def string(self, value: Any, path: str, pattern: re.Pattern[str] | None = None, what: str = "") -> str:
        v = self.scalar(value, path)
        if not isinstance(v, str) or not v:
            raise self.error(path, f"must be a non-empty string, got {value.raw!r}",
                             fix="write the text in quotes, e.g. \"name\"")
        if pattern is not None and not pattern.match(v):
            raise self.error(path, f"{v!r} is not a valid {what}", fix=f"write a valid {what}")
        return v

    def integer(self, value: Any, path: str, low: int, high: int) -> int:
        v = self.scalar(value, path)
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.error(path, f"must be a whole number, got {value.raw!r}",
                             fix=f"write a whole number from {low} to {high}, without quotes")
        if not low <= v <= high:
            raise self.error(path, f"{v} is out of range {low}..{high}",
                             fix=f"write a whole number from {low} to {high}")
        return v

    def boolean(self, value: Any, path: str) -> bool:
        v = self.scalar(value, path)
        if not isinstance(v, bool):
            raise self.error(path, f"must be true or false, got {value.raw!r}", fix="write true or false")
        return v

    def choice(self, value: Any, path: str, choices: tuple[str, ...]) -> str:
        v = self.scalar(value, path)
        if not isinstance(v, str) or v not in choices:
            raw = value.raw if isinstance(value, _Scalar) else str(v)
            hint = suggest(str(raw), choices)
            fix = (f"did you mean {hint!r}? " if hint else "") + f"use one of: {', '.join(choices)}"
            raise self.error(path, f"{raw!r} is not supported", fix=fix)
        return v

    def string_map(self, value: Any, path: str) -> tuple[tuple[str, str], ...]:
        if isinstance(value, _Scalar) and value.value is None:
            return ()
        if not isinstance(value, dict):
            raise self.error(path, "must be a mapping of name: value", fix="write one `name: value` per line")
        out = []
        for key, item in value.items():
            if not isinstance(item, _Scalar) or item.value is None:
                raise self.error(f"{path}.{key}", "must be a single value", fix="write one value after the colon")
            out.append((key, item.raw))
        return tuple(out)

    def topic(self, value: Any, path: str) -> str:
        return self.string(value, path, TOPIC_RE, "ROS topic name (letters, digits, _ and / separators)")


def load_config(path: str | Path, *, display_path: str | None = None) -> VendorConfig:
    """Read and validate one vendor YAML (URDF cross-checks happen in build.py)."""
    path = Path(path)
    shown = display_path or str(path)
    text = _read_text(path, shown)
    data, lines = parse_yaml_text(text, shown)
    return config_from_data(data, lines, shown, path.parent)


def config_from_data(data: dict[str, Any], lines: dict[str, int], shown: str, base_dir: Path) -> VendorConfig:
    v = _Validator(shown, lines)
    v.mapping(data, "", TOP_KEYS)
    for key in REQUIRED_KEYS:
        if key not in data:
            raise ConfigError(f"required key {key!r} is missing", file=shown, key=key,
                              fix="see the YAML reference in README.md")

    vendor = v.string(data["vendor"], "vendor")
    if (problem := vendor_problem(vendor)):
        raise v.error("vendor", problem, fix="use e.g. 'unitree' or 'my_company'")
    robot = v.string(data["robot"], "robot")
    if (problem := identifier_problem(robot, "robot")):
        raise v.error("robot", problem, fix="use e.g. 'g1' or 'my_arm'")
    transport = v.choice(data["transport"], "transport", TRANSPORTS)
    motor_count = v.integer(data["motor_count"], "motor_count", 1, MAX_MOTORS)
    float_type = (v.choice(data["float_type"], "float_type", FLOAT_TYPES) if "float_type" in data
                  else DEFAULT_FLOAT[transport])

    urdf_rel = v.string(data["urdf"], "urdf")
    if "\x00" in urdf_rel:
        raise v.error("urdf", "path contains a NUL character", fix="write the plain path of the URDF or xacro file")
    urdf_path = (base_dir / urdf_rel) if not os.path.isabs(urdf_rel) else Path(urdf_rel)

    class_prefix = None
    if "class_prefix" in data:
        class_prefix = v.string(data["class_prefix"], "class_prefix")
        if not CLASS_PREFIX_RE.match(class_prefix) or class_prefix.lower() in CPP_KEYWORDS:
            raise v.error("class_prefix", f"{class_prefix!r} must be a C++ identifier starting with an "
                          "uppercase letter (letters and digits only)", fix="e.g. G1 or MyArm")

    xacro_args = v.string_map(data.get("xacro_args"), "xacro_args") if "xacro_args" in data else ()
    package_paths = ()
    if "package_paths" in data:
        package_paths = tuple((name, str((base_dir / p) if not os.path.isabs(p) else Path(p)))
                              for name, p in v.string_map(data["package_paths"], "package_paths"))

    imu = ImuConfig()
    if "imu" in data:
        m = v.mapping(data["imu"], "imu", IMU_KEYS)
        imu = ImuConfig(
            enabled=v.boolean(m["enabled"], "imu.enabled") if "enabled" in m else True,
            name=v.string(m["name"], "imu.name", re.compile(r"^[A-Za-z_][A-Za-z0-9_]{0,63}$"),
                          "sensor name") if "name" in m else "base_imu",
            frame_id=v.string(m["frame_id"], "imu.frame_id", FRAME_RE, "frame id") if "frame_id" in m
            else "imu_link",
        )

    params = Parameters()
    if "parameters" in data:
        m = v.mapping(data["parameters"], "parameters", PARAMETER_KEYS)
        params = Parameters(
            network_interface=v.string(m["network_interface"], "parameters.network_interface", NETIF_RE,
                                       "network interface name") if "network_interface" in m
            else params.network_interface,
            enable_monitor=v.boolean(m["enable_monitor"], "parameters.enable_monitor")
            if "enable_monitor" in m else params.enable_monitor,
            command_writer_period_us=v.integer(m["command_writer_period_us"],
                                               "parameters.command_writer_period_us", 100, 10_000_000)
            if "command_writer_period_us" in m else params.command_writer_period_us,
            state_decimation=v.integer(m["state_decimation"], "parameters.state_decimation", 1, 10_000)
            if "state_decimation" in m else params.state_decimation,
            state_timeout_ms=v.integer(m["state_timeout_ms"], "parameters.state_timeout_ms", 1, 600_000)
            if "state_timeout_ms" in m else params.state_timeout_ms,
        )

    options = _transport_options(v, data.get("transport_options"), transport, motor_count)

    joint_map = _joint_map(v, data["joint_map"], motor_count)
    unmapped: tuple[str, ...] = ()
    if "unmapped_joints" in data:
        raw = data["unmapped_joints"]
        if isinstance(raw, _Scalar) and raw.value is None:
            raw = []
        if not isinstance(raw, list):
            raise v.error("unmapped_joints", "must be a list of URDF joint names", fix="e.g. [left_wheel, right_wheel]")
        names = []
        for i, item in enumerate(raw):
            name = v.string(item, f"unmapped_joints[{i}]")
            if name in names:
                raise v.error(f"unmapped_joints[{i}]", f"{name!r} is listed twice", fix="remove the duplicate")
            if name in dict(joint_map):
                raise v.error(f"unmapped_joints[{i}]", f"{name!r} is also in joint_map",
                              fix="a joint is either mapped to a motor or intentionally unmapped")
            names.append(name)
        unmapped = tuple(names)

    return VendorConfig(
        source=shown, vendor=vendor, robot=robot, urdf=str(urdf_path), urdf_relative=urdf_rel,
        transport=transport, motor_count=motor_count, float_type=float_type, joint_map=joint_map,
        unmapped_joints=unmapped, imu=imu, transport_options=options, parameters=params,
        xacro_args=xacro_args, package_paths=package_paths, class_prefix=class_prefix,
        key_lines=dict(lines),
    )


def _joint_map(v: _Validator, raw: Any, motor_count: int) -> tuple[tuple[str, int], ...]:
    if not isinstance(raw, dict) or not raw:
        raise v.error("joint_map", "must be a non-empty mapping of URDF joint name: motor index",
                      fix="run `rhi-gen inspect --urdf <file>` for a suggested map")
    seen: dict[int, str] = {}
    out = []
    for name, item in raw.items():
        path = f"joint_map.{name}"
        if not name:
            raise v.error(path, "joint name is empty", fix="write the URDF joint name before the colon")
        if not isinstance(item, _Scalar):
            raise v.error(path, "must be a motor index (a whole number)",
                          fix=f"write a whole number from 0 to {motor_count - 1}")
        value = item.value
        if isinstance(value, bool) or not isinstance(value, int):
            raise v.error(path, f"motor index must be a whole number, got {item.raw!r}",
                          fix=f"write a whole number from 0 to {motor_count - 1}, without quotes")
        if not 0 <= value < motor_count:
            raise v.error(path, f"motor index {value} is out of range 0..{motor_count - 1} "
                          f"(motor_count is {motor_count})",
                          fix=f"use an index below {motor_count} or raise motor_count")
        if value in seen:
            raise v.error(path, f"motor index {value} is already used by {seen[value]!r}",
                          fix="every motor index may appear once")
        seen[value] = name
        out.append((name, value))
    return tuple(out)


def _qos(v: _Validator, raw: Any, path: str, default: QosConfig) -> QosConfig:
    if raw is None:
        return default
    m = v.mapping(raw, path, QOS_KEYS)
    return QosConfig(
        reliability=v.choice(m["reliability"], f"{path}.reliability", ("best_effort", "reliable"))
        if "reliability" in m else default.reliability,
        durability=v.choice(m["durability"], f"{path}.durability", ("volatile", "transient_local"))
        if "durability" in m else default.durability,
        depth=v.integer(m["depth"], f"{path}.depth", 1, 1000) if "depth" in m else default.depth,
    )


def _transport_options(v: _Validator, raw: Any, transport: str, motor_count: int) -> TransportOptions:
    allowed = TRANSPORT_KEYS[transport]
    m = v.mapping(raw, "transport_options", allowed) if raw is not None else {}
    p = "transport_options"
    get: Callable[[str, Callable[[Any, str], Any], Any], Any] = (
        lambda key, conv, default: conv(m[key], f"{p}.{key}") if key in m else default)

    if transport == "unitree_dds":
        sdk_slots = get("sdk_slots", lambda x, q: v.integer(x, q, 1, 1024), 35)
        if motor_count > sdk_slots:
            raise ConfigError(f"motor_count {motor_count} exceeds the {sdk_slots} motor slots of the "
                              "unitree hg LowCmd_", file=v.source, line=v.lines.get("motor_count"),
                              key="motor_count", fix=f"use at most {sdk_slots} motors")
        if sdk_slots != 35:
            raise v.error(f"{p}.sdk_slots", f"unitree hg messages have exactly 35 motor slots, not {sdk_slots}",
                          fix="remove sdk_slots or set it to 35")
        return TransportOptions(
            lowcmd_topic=get("lowcmd_topic", v.topic, "rt/lowcmd"),
            lowstate_topic=get("lowstate_topic", v.topic, "rt/lowstate"),
            sdk_slots=sdk_slots,
            domain_id=get("domain_id", lambda x, q: v.integer(x, q, 0, 232), 0),
            mode_pr=get("mode_pr", lambda x, q: v.integer(x, q, 0, 1), 0),
            release_motion_control=get("release_motion_control", v.boolean, False),
        )

    if transport == "agibot_topics":
        groups = _groups(v, m.get("groups"), motor_count)
        return TransportOptions(
            groups=groups,
            imu_topic=get("imu_topic", v.topic, "/aima/hal/imu/torso/state"),
            qos=_qos(v, m.get("qos"), f"{p}.qos", QosConfig(depth=1)),
            sdk_slots=motor_count,
        )

    if transport == "engineai_topics":
        return TransportOptions(
            command_topic=get("command_topic", v.topic, "/hardware/joint_command"),
            state_topic=get("state_topic", v.topic, "/hardware/joint_state"),
            imu_topic=get("imu_topic", v.topic, "/hardware/imu_info"),
            parallel_parser_type=get("parallel_parser_type", lambda x, q: v.integer(x, q, 0, 1), 0),
            qos=_qos(v, m.get("qos"), f"{p}.qos", QosConfig(depth=3)),
            sdk_slots=motor_count,
        )

    options = TransportOptions(
        command_topic=get("command_topic", v.topic, "/hardware/joint_commands"),
        state_topic=get("state_topic", v.topic, "/hardware/joint_states"),
        imu_topic=get("imu_topic", v.topic, "/hardware/imu"),
        qos=_qos(v, m.get("qos"), f"{p}.qos", QosConfig(depth=1)),
        sdk_slots=motor_count,
    )
    if options.command_topic == options.state_topic:
        raise v.error(f"{p}.command_topic", "command and state topics must differ",
                      fix="give command_topic and state_topic different names")
    return options


def _groups(v: _Validator, raw: Any, motor_count: int) -> tuple[JointGroup, ...]:
    path = "transport_options.groups"
    if raw is None:
        specs = [(name, size, f"/aima/hal/joint/{name}/command", f"/aima/hal/joint/{name}/state")
                 for name, size in AGIBOT_DEFAULT_GROUPS]
    else:
        if not isinstance(raw, list) or not raw:
            raise v.error(path, "must be a non-empty list of {name, size, command_topic, state_topic}",
                          fix="e.g. [{name: leg, size: 12}] or remove groups for the AgiBot defaults")
        specs = []
        for i, item in enumerate(raw):
            q = f"{path}[{i}]"
            m = v.mapping(item, q, GROUP_KEYS)
            for key in ("name", "size"):
                if key not in m:
                    raise v.error(q, f"group needs {key!r}", fix=f"add {key}: to the group")
            name = v.string(m["name"], f"{q}.name", re.compile(r"^[a-z][a-z0-9_]*$"), "group name")
            size = v.integer(m["size"], f"{q}.size", 1, MAX_MOTORS)
            cmd = v.topic(m["command_topic"], f"{q}.command_topic") if "command_topic" in m \
                else f"/aima/hal/joint/{name}/command"
            state = v.topic(m["state_topic"], f"{q}.state_topic") if "state_topic" in m \
                else f"/aima/hal/joint/{name}/state"
            if any(s[0] == name for s in specs):
                raise v.error(f"{q}.name", f"group {name!r} is defined twice", fix="give every group its own name")
            specs.append((name, size, cmd, state))
    total = sum(s[1] for s in specs)
    if total != motor_count:
        raise ConfigError(f"motor_count is {motor_count} but the groups hold {total} slots",
                          file=v.source, line=v.lines.get("motor_count"), key="motor_count",
                          fix="make motor_count equal the sum of the group sizes")
    groups, offset = [], 0
    for name, size, cmd, state in specs:
        groups.append(JointGroup(name=name, size=size, command_topic=cmd, state_topic=state, offset=offset))
        offset += size
    return tuple(groups)

