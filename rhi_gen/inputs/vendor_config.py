"""Load and validate a vendor YAML into a VendorConfig: the top-level schema.

Every problem is a ConfigError naming the file, the line, the key and the fix. ``transport_options``
belong to the robot's transport (transports/<name>/); checks that need the URDF (joint names
exist, every actuated joint mapped) live in assemble/robot_model.py.
"""
from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

from .. import transports
from ..errors import ConfigError
from ..model import AUTHORITIES, FLOAT_TYPES, HANDS, MAX_MOTORS, ImuConfig, Parameters, VendorConfig
from ..model.config import CONTACT_SHAPES, MAX_ARMATURE, MAX_CONTACTS, MAX_JOINT_FRICTION, ContactGeom
from ..model.naming import CLASS_PREFIX_RE, CPP_KEYWORDS, identifier_problem, suggest, vendor_problem
from ..typed_yaml.validator import Validator
from ..typed_yaml.yaml_source import Scalar, content_sha256, parse_yaml_text, read_text
from .vendor_transmissions import read_coupled_joints, read_transmissions

TOP_KEYS = ("vendor", "robot", "urdf", "transport", "motor_count", "float_type", "class_prefix",
            "xacro_args", "package_paths", "imu", "parameters", "transport_options", "joint_map",
            "unmapped_joints", "default_gains", "command_modes", "initial_positions", "armatures", "joint_damping",
            "joint_frictionloss", "contacts", "transmissions", "coupled_joints", "urdf_transmissions", "authority",
            "hands")
REQUIRED_KEYS = ("vendor", "robot", "urdf", "transport", "motor_count", "joint_map")
PARAMETER_KEYS = ("network_interface", "enable_monitor", "command_writer_period_us", "command_writer_mode",
                  "state_decimation", "state_timeout_ms", "fault_timeout_ms", "first_state_timeout_ms",
                  "diagnostics_period_ms",
                  "motor_temperature_warn_c", "motor_temperature_error_c", "motor_error_fault_mask", "is_async",
                  "rw_rate")
COMMAND_WRITER_MODES = ("timer", "on_write")  # cpp/common/robot_spec.hpp CommandWriterMode
MAX_ERROR_FAULT_MASK = 0xFFFF_FFFF  # motor error codes are at most 32 bits (hg motorstate)
MAX_RW_RATE = 100_000  # Hz; ros2_control caps rw_rate at the controller manager's update rate anyway
IMU_KEYS = ("enabled", "name", "frame_id")
GAIN_KEYS = ("stiffness", "damping")
COMMAND_MODES = ("position", "velocity")
MAX_GAIN = 1e6  # N*m/rad: far above any real motor; a typo of a few zeros still fails

FRAME_RE = re.compile(r"^[A-Za-z_][A-Za-z0-9_/.\-]*$")
NETIF_RE = re.compile(r"^[A-Za-z0-9_.:\-]{1,64}$")
SENSOR_NAME_RE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]{0,63}$")


def _check_temperatures(v: Validator, params: Parameters, *, given: bool) -> None:
    """A motor is WARN at motor_temperature_warn_c and ERROR at motor_temperature_error_c: in that order."""
    warn, error = params.motor_temperature_warn_c, params.motor_temperature_error_c
    if error > warn:
        return
    if given:
        raise v.error("parameters.motor_temperature_error_c", f"{error} must be greater than "
                      f"motor_temperature_warn_c ({warn})", fix=f"set motor_temperature_error_c above {warn}")
    raise v.error("parameters.motor_temperature_warn_c", f"{warn} must be less than motor_temperature_error_c "
                  f"({error}, the default)", fix=f"set parameters.motor_temperature_error_c above {warn}")


def _check_fault_timeout(v: Validator, params: Parameters, *, given: bool) -> None:
    """The driver holds the joints after state_timeout_ms and faults after fault_timeout_ms: in that order."""
    state, fault = params.state_timeout_ms, params.fault_timeout_ms
    if fault > state:
        return
    if given:
        raise v.error("parameters.fault_timeout_ms", f"{fault} must be greater than state_timeout_ms ({state})",
                      fix=f"set fault_timeout_ms above {state}, e.g. {state * 10}")
    raise v.error("parameters.state_timeout_ms", f"{state} must be less than fault_timeout_ms ({fault}, the default)",
                  fix=f"set parameters.fault_timeout_ms above {state}, e.g. {state * 10}")


def load_config(path: str | Path, *, display_path: str | None = None) -> VendorConfig:
    """Read and validate one vendor YAML (URDF cross-checks happen in assemble/robot_model.py)."""
    path = Path(path)
    shown = display_path or str(path)
    text = read_text(path, shown)
    data, lines = parse_yaml_text(text, shown)
    return config_from_data(data, lines, shown, path.parent)


def config_from_data(data: dict[str, Any], lines: dict[str, int], shown: str, base_dir: Path) -> VendorConfig:
    """Validate a parsed YAML tree (``base_dir``: the YAML's folder, for relative paths)."""
    v = Validator(shown, lines)
    v.mapping(data, "", TOP_KEYS)
    for key in REQUIRED_KEYS:
        if key not in data:
            raise ConfigError(f"required key {key!r} is missing", file=shown, key=key,
                              fix="see the YAML reference in docs/vendor-yaml.md")

    vendor = v.string(data["vendor"], "vendor")
    if (problem := vendor_problem(vendor)):
        raise v.error("vendor", problem, fix="use e.g. 'unitree' or 'my_company'")
    robot = v.string(data["robot"], "robot")
    if (problem := identifier_problem(robot, "robot")):
        raise v.error("robot", problem, fix="use e.g. 'g1' or 'my_arm'")
    transport = transports.get(v.choice(data["transport"], "transport", transports.NAMES))
    motor_count = v.integer(data["motor_count"], "motor_count", 1, MAX_MOTORS)
    float_type = (v.choice(data["float_type"], "float_type", FLOAT_TYPES) if "float_type" in data
                  else transport.default_float_type)

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
    package_paths: tuple[tuple[str, str], ...] = ()
    if "package_paths" in data:
        package_paths = tuple((name, str((base_dir / p) if not os.path.isabs(p) else Path(p)))
                              for name, p in v.string_map(data["package_paths"], "package_paths"))

    imu = ImuConfig()
    if "imu" in data:
        m = v.mapping(data["imu"], "imu", IMU_KEYS)
        imu = ImuConfig(
            enabled=v.boolean(m["enabled"], "imu.enabled") if "enabled" in m else True,
            name=v.string(m["name"], "imu.name", SENSOR_NAME_RE, "sensor name") if "name" in m else "base_imu",
            frame_id=v.string(m["frame_id"], "imu.frame_id", FRAME_RE, "frame id") if "frame_id" in m
            else "imu_link",
        )

    params = Parameters()
    if "parameters" in data:
        m = v.mapping(data["parameters"], "parameters", PARAMETER_KEYS)
        d, p = params, "parameters"

        def whole(key: str, low: int, high: int) -> int:
            """parameters.<key>, a whole number in [low, high]; the default when absent."""
            default: int = getattr(d, key)
            return v.optional(m, p, key, v.integer_in(low, high), default)

        params = Parameters(
            network_interface=v.optional(m, p, "network_interface",
                                         lambda x, q: v.string(x, q, NETIF_RE, "network interface name"),
                                         d.network_interface),
            enable_monitor=v.optional(m, p, "enable_monitor", v.boolean, d.enable_monitor),
            command_writer_period_us=whole("command_writer_period_us", 100, 10_000_000),
            command_writer_mode=v.optional(m, p, "command_writer_mode",
                                           lambda x, q: v.choice(x, q, COMMAND_WRITER_MODES), d.command_writer_mode),
            state_decimation=whole("state_decimation", 1, 10_000),
            state_timeout_ms=whole("state_timeout_ms", 1, 600_000),
            fault_timeout_ms=whole("fault_timeout_ms", 2, 3_600_000),
            first_state_timeout_ms=whole("first_state_timeout_ms", 2, 3_600_000),
            diagnostics_period_ms=whole("diagnostics_period_ms", 0, 60_000),
            motor_temperature_warn_c=whole("motor_temperature_warn_c", 1, 200),
            motor_temperature_error_c=whole("motor_temperature_error_c", 1, 200),
            motor_error_fault_mask=whole("motor_error_fault_mask", 0, MAX_ERROR_FAULT_MASK),
            is_async=v.optional(m, p, "is_async", v.boolean, d.is_async),
            rw_rate=whole("rw_rate", 0, MAX_RW_RATE),
        )
        _check_fault_timeout(v, params, given="fault_timeout_ms" in m)
        _check_temperatures(v, params, given="motor_temperature_error_c" in m)

    raw_options = data.get("transport_options")
    options = transport.read_options(
        v, v.mapping(raw_options, "transport_options", transport.option_keys) if raw_options is not None else {},
        motor_count)
    hands = v.optional(data, "", "hands", lambda x, q: v.choice(x, q, HANDS), "none")
    options = transport.resolve_hands(v, hands, options, vendor=vendor, robot=robot)
    options = transport.resolve_options(v, options, vendor=vendor, robot=robot, motor_count=motor_count)
    # EngineAI's error codes travel only with one release of its messages: the driver, compiled against the
    # installed one, refuses a mask when its messages have none (system_driver.hpp: error_codes_travel()).
    if params.motor_error_fault_mask and "error_code" not in (*transport.motor_health(options),
                                                              *transport.detected_motor_health(options)):
        raise v.error("parameters.motor_error_fault_mask", f"the {transport.name} state carries no motor error "
                      "codes, so no error code can fault a motor",
                      fix="remove motor_error_fault_mask (Unitree hg and AgiBot robots, and EngineAI robots with "
                          "the native SDK's interface_protocol, report error codes)")

    joint_map = _joint_map(v, data["joint_map"], motor_count)
    transport.check_hand_map(v, options, joint_map)
    unmapped: tuple[str, ...] = ()
    if "unmapped_joints" in data:
        raw = data["unmapped_joints"]
        if isinstance(raw, Scalar) and raw.value is None:
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

    mapped = dict(joint_map)
    default_gains = _default_gains(v, data.get("default_gains"), mapped) if "default_gains" in data else ()
    command_modes = _command_modes(v, data.get("command_modes"), mapped) if "command_modes" in data else ()
    initial = _initial_positions(v, data.get("initial_positions"), mapped) if "initial_positions" in data else ()
    armatures = _armatures(v, data.get("armatures"), mapped) if "armatures" in data else ()
    joint_damping = _joint_numbers(
        v, data.get("joint_damping"), mapped, "joint_damping", "{knee_joint: 0.05}",
        "write the joint's passive damping in N*m*s/rad (N*s/m for a prismatic joint), e.g. 0.05",
        MAX_JOINT_FRICTION) if "joint_damping" in data else ()
    joint_frictionloss = _joint_numbers(
        v, data.get("joint_frictionloss"), mapped, "joint_frictionloss", "{knee_joint: 0.2}",
        "write the joint's dry friction in N*m (N for a prismatic joint), e.g. 0.2",
        MAX_JOINT_FRICTION) if "joint_frictionloss" in data else ()
    contacts = _contacts(v, data["contacts"]) if "contacts" in data else ()
    coupled = read_coupled_joints(v, data["coupled_joints"], mapped) if "coupled_joints" in data else ()
    transmissions = read_transmissions(
        v, _joint_entries(v, data["transmissions"], "transmissions", mapped, "{knee_joint: {reduction: 50.0}}"),
        {joint: name for name, joints, _ in coupled for joint in joints}) if "transmissions" in data else ()
    urdf_transmissions = v.optional(data, "", "urdf_transmissions", v.boolean, True)
    authority = v.optional(data, "", "authority", lambda x, q: v.choice(x, q, AUTHORITIES), "full")
    options = transport.resolve_authority(v, authority, options, vendor=vendor, robot=robot,
                                          mapped_slots=frozenset(mapped.values()))

    return VendorConfig(
        source=shown, vendor=vendor, robot=robot, urdf=str(urdf_path), urdf_relative=urdf_rel,
        transport=transport.name, motor_count=motor_count, float_type=float_type, joint_map=joint_map,
        unmapped_joints=unmapped, imu=imu, transport_options=options, parameters=params,
        xacro_args=xacro_args, package_paths=package_paths, class_prefix=class_prefix,
        default_gains=default_gains, command_modes=command_modes, initial_positions=initial, armatures=armatures,
        joint_damping=joint_damping, joint_frictionloss=joint_frictionloss, contacts=contacts,
        transmissions=transmissions, coupled_joints=coupled, urdf_transmissions=urdf_transmissions,
        authority=authority, hands=hands,
        content_sha256=content_sha256(data), key_lines=dict(lines),
    )


def _joint_entries(v: Validator, raw: Any, path: str, mapped: dict[str, int], example: str) -> dict[str, Any]:
    """A mapping keyed by joint names of joint_map (an empty or null value is an empty mapping)."""
    if isinstance(raw, Scalar) and raw.value is None:
        return {}
    if not isinstance(raw, dict):
        raise v.error(path, "must be a mapping of joint name: value", fix=f"e.g. {example}")
    for name in raw:
        if name not in mapped:
            hint = suggest(name, list(mapped))
            raise v.error(f"{path}.{name}", f"{name!r} is not a joint of joint_map",
                          fix=f"did you mean {hint!r}?" if hint else "list joints of joint_map only")
    return raw


def _default_gains(v: Validator, raw: Any, mapped: dict[str, int]) -> tuple[tuple[str, float, float], ...]:
    """default_gains: {joint: {stiffness: kp, damping: kd}}, each finite, >= 0."""
    path = "default_gains"
    entries = _joint_entries(v, raw, path, mapped, "{knee_joint: {stiffness: 60.0, damping: 1.5}}")
    out = []
    for name, item in entries.items():
        m = v.mapping(item, f"{path}.{name}", GAIN_KEYS)
        gains = []
        for key in GAIN_KEYS:
            q = f"{path}.{name}.{key}"
            what = f"a number from 0 to {MAX_GAIN:g}"
            fix = "write the gain in N*m/rad (stiffness) or N*m*s/rad (damping), e.g. 60.0"
            value = v.finite_number(m[key], q, fix, what) if key in m else 0.0
            if not 0.0 <= value <= MAX_GAIN:
                raise v.error(q, f"must be {what}, got {m[key].raw!r}", fix=fix)
            gains.append(value)
        out.append((name, gains[0], gains[1]))
    return tuple(out)


def _command_modes(v: Validator, raw: Any, mapped: dict[str, int]) -> tuple[tuple[str, str], ...]:
    """command_modes: {joint: position | velocity}."""
    path = "command_modes"
    entries = _joint_entries(v, raw, path, mapped, "{wheel_joint: velocity}")
    return tuple((name, v.choice(item, f"{path}.{name}", COMMAND_MODES)) for name, item in entries.items())


def _initial_positions(v: Validator, raw: Any, mapped: dict[str, int]) -> tuple[tuple[str, float], ...]:
    """initial_positions: {joint: rad (m for a prismatic joint)}, finite; URDF limits are checked in assemble."""
    return _joint_numbers(v, raw, mapped, "initial_positions", "{knee_joint: 0.3}",
                          "write the joint's start position in rad (m for a prismatic joint), e.g. 0.0")


def _joint_numbers(v: Validator, raw: Any, mapped: dict[str, int], path: str, example: str, fix: str,
                   most: float | None = None) -> tuple[tuple[str, float], ...]:
    """{joint: finite number} (from 0 to ``most`` when given), each error naming its joint's line."""
    entries = _joint_entries(v, raw, path, mapped, example)
    what = f"a number from 0 to {most:g}" if most is not None else "a finite number"
    out = []
    for name, item in entries.items():
        q = f"{path}.{name}"
        value = v.finite_number(item, q, fix, what)
        if most is not None and not 0.0 <= value <= most:
            raise v.error(q, f"must be {what}, got {item.raw!r}", fix=fix)
        out.append((name, value))
    return tuple(out)


def _armatures(v: Validator, raw: Any, mapped: dict[str, int]) -> tuple[tuple[str, float], ...]:
    """armatures: {joint: kg m^2 (kg for a prismatic joint)}, finite, from 0 to MAX_ARMATURE."""
    return _joint_numbers(v, raw, mapped, "armatures", "{knee_joint: 0.02}",
                          "write the rotor inertia reflected to the joint in kg*m^2 (kg for a prismatic joint), "
                          "e.g. 0.01", MAX_ARMATURE)


CONTACT_EXAMPLE = "{left_foot_link: [{box: [0.2, 0.1, 0.02], xyz: [0.03, 0.0, -0.04]}]}"
CONTACT_SIZES = {"sphere": (1, "the radius [m]"), "box": (3, "[x, y, z] lengths [m]"),
                 "cylinder": (2, "[radius, length] [m]")}


def _contacts(v: Validator, raw: Any) -> tuple[ContactGeom, ...]:
    """contacts: {link: [{<shape>: size, xyz: [..], rpy: [..]}]}; the links are checked against the URDF in
    assemble."""
    if isinstance(raw, Scalar) and raw.value is None:
        return ()
    if not isinstance(raw, dict):
        raise v.error("contacts", "must be a mapping of URDF link name: list of shapes", fix=f"e.g. {CONTACT_EXAMPLE}")
    out: list[ContactGeom] = []
    for link, shapes in raw.items():
        path = f"contacts.{link}"
        if not isinstance(shapes, list) or not shapes:
            raise v.error(path, "must be a non-empty list of shapes", fix=f"e.g. {CONTACT_EXAMPLE}")
        for i, item in enumerate(shapes):
            out.append(_contact(v, link, item, f"{path}[{i}]"))
            if len(out) > MAX_CONTACTS:
                raise v.error(path, f"more than {MAX_CONTACTS} contacts",
                              fix="give each foot a few primitives (the vendor's MuJoCo model's)")
    return tuple(out)


def _contact(v: Validator, link: str, item: Any, path: str) -> ContactGeom:
    m = v.mapping(item, path, (*CONTACT_SHAPES, "xyz", "rpy"))
    shapes = [s for s in CONTACT_SHAPES if s in m]
    if len(shapes) != 1:
        raise v.error(path, "must name exactly one shape: " + ", ".join(CONTACT_SHAPES),
                      fix="e.g. {sphere: 0.005, xyz: [0.1, 0.03, -0.03]}")
    shape = shapes[0]
    count, what = CONTACT_SIZES[shape]
    fix = f"write {shape}: {what}, each more than 0"
    sizes = _numbers(v, m[shape], f"{path}.{shape}", count, fix)
    if not all(0.0 < x <= 100.0 for x in sizes):
        raise v.error(f"{path}.{shape}", f"a {shape}'s sizes must be more than 0 m (and at most 100 m)", fix=fix)
    xyz = _numbers(v, m["xyz"], f"{path}.xyz", 3, "write xyz: [x, y, z] in m") if "xyz" in m else (0.0,) * 3
    rpy = _numbers(v, m["rpy"], f"{path}.rpy", 3, "write rpy: [roll, pitch, yaw] in rad") if "rpy" in m else (0.0,) * 3
    padded = (*sizes, *(0.0,) * (3 - len(sizes)))
    return ContactGeom(link, shape, (padded[0], padded[1], padded[2]), (xyz[0], xyz[1], xyz[2]),
                       (rpy[0], rpy[1], rpy[2]))


def _numbers(v: Validator, raw: Any, path: str, count: int, fix: str) -> tuple[float, ...]:
    """``count`` finite numbers: a list of them, or one number alone when ``count`` is 1."""
    items = raw if isinstance(raw, list) else [raw] if count == 1 else None
    if items is None or len(items) != count:
        raise v.error(path, f"must be {'a number' if count == 1 else f'a list of {count} numbers'}", fix=fix)
    return tuple(v.finite_number(x, f"{path}[{i}]" if isinstance(raw, list) else path, fix)
                 for i, x in enumerate(items))


def _joint_map(v: Validator, raw: Any, motor_count: int) -> tuple[tuple[str, int], ...]:
    if not isinstance(raw, dict) or not raw:
        raise v.error("joint_map", "must be a non-empty mapping of URDF joint name: motor index",
                      fix="run `rhi-gen inspect --urdf <file>` for a suggested map")
    seen: dict[int, str] = {}
    out = []
    for name, item in raw.items():
        path = f"joint_map.{name}"
        if not name:
            raise v.error(path, "joint name is empty", fix="write the URDF joint name before the colon")
        if not isinstance(item, Scalar):
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
