"""Property tests: random robots and joint maps, driven through the CLI.

1. Random *valid* inputs — joint sets of every kind (revolute, continuous, prismatic, fixed, mimic),
   joint names from the whole accepted alphabet (YAML-special ones like ``yes``, ``#x``, ``[0]``
   included), link and robot names with quotes, backslashes, ``$``/``${}``, newlines and non-ASCII
   text, any motor order, spare SDK slots, every transport and float type — always generate (exit 0)
   a package whose drivers pass the C++ compile check, whose ros2_control description still lists
   exactly the mapped joints after a real xacro run, and whose controllers YAML reads back the same
   names. Several robots share one project so one `generate` and one batch of compiles cover them.
2. Random *invalid* maps — duplicate or out-of-range indices, indices that are not numbers, joints
   that are not in the URDF, missing, fixed or mimic joints, bad float types, transports, keys and
   motor counts — are always rejected with exit 2 and one line naming the YAML, its line and key,
   and a fix, before anything is written: the already generated project stays byte for byte.
"""
from __future__ import annotations

import itertools
import string
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from lxml import etree

from rhi_gen.inputs.xacro_expand import expand_xacro
from rhi_gen.model.naming import identifier_problem, pascal_case, vendor_problem
from tests.support import vendor_msgs
from tests.support.cli import ANY_LINE, assert_rejected, run_cli, snapshot
from tests.support.cpp_build import syntax_check_driver
from tests.support.repo import HOSTILE, PACKAGE

TRANSPORTS = ("generic_topics", "engineai_topics", "agibot_topics", "unitree_dds", "custom")
# The drivers that are compiled draw only from transports whose vendor messages are available here
# (without ../shared: not agibot_topics, see tests/support/vendor_msgs.py); generation is checked for all.
COMPILABLE_TRANSPORTS = tuple(t for t in TRANSPORTS if vendor_msgs.skip_reason(t) is None)
UNITREE_SLOTS = {"hg": 35, "go": 20}  # motor slots per unitree message family
# Every character rhi-gen accepts in a joint name (model/naming.py's policy, restated independently).
JOINT_ALPHABET = string.ascii_letters + string.digits + "_./-:+[]()#@"
TOP_KEYS = ("vendor", "robot", "urdf", "transport", "motor_count", "float_type", "class_prefix",
            "xacro_args", "package_paths", "imu", "parameters", "transport_options", "joint_map",
            "unmapped_joints")
# Valid names that collide with something else in the generated package or its dependencies.
TRICKY_NAMES = ("common", "transport", "msg", "detail", "rcl", "lifecycle_msgs", "class_loader", "test",
                "include", "src", "config", "description", "types", "data_buffer", "monitor",
                "motor_types", "unitree_hg_crc", "robot", "hardware", "system", "node", "executor",
                "testing", "unitree", "agibot", "engineai", "g1", "x2", "pm01", "a1", "h1_2", "arm_v2",
                "interface", "state", "command", "imu", "sensor", "joint", "main_board", "k", "x")

COMPILE_WORKERS = 2


# ---------------------------------------------------------------- strategies
def _valid_vendor(name: str) -> bool:
    return vendor_problem(name) is None


def _valid_robot(name: str) -> bool:
    return identifier_problem(name, "robot") is None


NAME_RE = r"[a-z][a-z0-9]{0,7}(_[a-z0-9]{1,5}){0,2}"
vendor_names = st.one_of(st.sampled_from(TRICKY_NAMES), st.from_regex(NAME_RE, fullmatch=True)).filter(_valid_vendor)
robot_names = st.one_of(st.sampled_from(TRICKY_NAMES), st.from_regex(NAME_RE, fullmatch=True)).filter(_valid_robot)
joint_names = st.one_of(
    st.text(alphabet=JOINT_ALPHABET, min_size=1, max_size=20),
    st.sampled_from(["yes", "no", "on", "off", "null", "true", "1e3", "0x10", "-", ".", "#x", "a:b",
                     "[0]", "@x", "x(1)", "a/b/c", "+1", "...", "-.inf", ".nan"]),
)
# Link and robot names are printed escaped, never checked: any text XML can carry.
xml_text = st.lists(
    st.one_of(
        st.characters(codec="utf-8", exclude_categories=("Cs", "Cc", "Cn")),
        st.sampled_from([*list("\"'\\$&<>{}()*/#?\n\t"), "${x}", "$(arg y)", "*/", "--", "??=", "\\n"]),
    ),
    min_size=1, max_size=10,
).map("".join).filter(lambda s: s.strip() == s and s != "")
finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
positive = st.floats(min_value=0.0, max_value=1e6, allow_nan=False)


@dataclass
class JointSpec:
    name: str
    type: str
    parent: int          # index into links
    child: int
    limits: tuple | None = None      # (lower, upper, effort, velocity), None = no <limit>
    mimic: str | None = None

    @property
    def actuated(self) -> bool:
        return self.type in ("revolute", "continuous", "prismatic") and self.mimic is None


@dataclass
class RobotSpec:
    vendor: str
    robot: str
    robot_name: str                  # <robot name=...> (any text)
    links: list[str]
    joints: list[JointSpec]
    transport: str
    motor_count: int
    joint_map: dict[str, int]        # YAML order
    unmapped: list[str]
    float_type: str | None
    groups: list[tuple[str, int]] = field(default_factory=list)
    imu: dict | None = None
    parameters: dict | None = None
    qos: dict | None = None
    family: str = ""                # unitree_dds: hg | go

    @property
    def actuated(self) -> list[str]:
        return [j.name for j in self.joints if j.actuated]

    def urdf_bytes(self) -> bytes:
        root = etree.Element("robot", name=self.robot_name)
        for link in self.links:
            etree.SubElement(root, "link", name=link)
        for j in self.joints:
            el = etree.SubElement(root, "joint", name=j.name, type=j.type)
            etree.SubElement(el, "parent", link=self.links[j.parent])
            etree.SubElement(el, "child", link=self.links[j.child])
            etree.SubElement(el, "axis", xyz="0 0 1")
            if j.limits is not None:
                lower, upper, effort, velocity = j.limits
                attrs = {"effort": repr(effort), "velocity": repr(velocity)}
                if lower is not None:
                    attrs.update(lower=repr(lower), upper=repr(upper))
                etree.SubElement(el, "limit", attrs)
            if j.mimic is not None:
                etree.SubElement(el, "mimic", joint=j.mimic, multiplier="-1.5", offset="0.25")
        return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)

    def yaml_data(self) -> dict:
        data: dict = {"vendor": self.vendor, "robot": self.robot, "urdf": f"{self.robot}.urdf",
                      "transport": self.transport, "motor_count": self.motor_count}
        if self.float_type is not None:
            data["float_type"] = self.float_type
        if self.imu is not None:
            data["imu"] = self.imu
        if self.parameters is not None:
            data["parameters"] = self.parameters
        options: dict = {}
        if self.transport == "agibot_topics":
            options["groups"] = [{"name": n, "size": s} for n, s in self.groups]
        if self.qos is not None and self.transport not in ("unitree_dds", "custom"):
            options["qos"] = self.qos
        if self.family:
            options["family"] = self.family
        if options:
            data["transport_options"] = options
        data["joint_map"] = dict(self.joint_map)
        if self.unmapped:
            data["unmapped_joints"] = list(self.unmapped)
        return data


def dump_yaml(data: dict) -> str:
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=False, default_flow_style=False, width=1000)


@st.composite
def robot_specs(draw, vendor: str, robot: str, transports: tuple[str, ...] = TRANSPORTS) -> RobotSpec:
    kinds = draw(st.lists(st.sampled_from(["revolute", "continuous", "prismatic", "fixed", "mimic"]),
                          min_size=1, max_size=14))
    if not any(k in ("revolute", "continuous", "prismatic") for k in kinds):
        kinds.append(draw(st.sampled_from(["revolute", "continuous", "prismatic"])))
    names = draw(st.lists(joint_names, min_size=len(kinds), max_size=len(kinds), unique=True))
    links = draw(st.lists(xml_text, min_size=len(kinds) + 1, max_size=len(kinds) + 1, unique=True))
    if draw(st.booleans()):  # a link that looks like an IMU (the default IMU frame), hostile text and all
        links[draw(st.integers(0, len(links) - 1))] = draw(xml_text.map(lambda s: f"imu{s}"))
        assume(len(set(links)) == len(links))
    joints: list[JointSpec] = []
    for i, (kind, name) in enumerate(zip(kinds, names, strict=False)):
        parent = draw(st.integers(0, i))  # links[0] is the root; joint i connects to links[i + 1]
        jtype = kind if kind != "mimic" else draw(st.sampled_from(["revolute", "prismatic", "continuous"]))
        limits = None
        if jtype in ("revolute", "prismatic"):
            a, b = sorted((draw(finite), draw(finite)))
            limits = (a, b, draw(positive), draw(positive))
        elif jtype == "continuous" and draw(st.booleans()):
            limits = (None, None, draw(positive), draw(positive))
        joints.append(JointSpec(name, jtype, parent, i + 1, limits, mimic="?" if kind == "mimic" else None))
    leaders = [j.name for j in joints if j.actuated]
    for j in joints:
        if j.mimic == "?":
            j.mimic = draw(st.sampled_from(leaders))

    actuated = [j.name for j in joints if j.actuated]
    mapped = draw(st.lists(st.sampled_from(actuated), min_size=1, max_size=len(actuated), unique=True))
    unmapped = [n for n in actuated if n not in mapped]
    transport = draw(st.sampled_from(transports if len(mapped) <= UNITREE_SLOTS["go"]
                                     else tuple(t for t in transports if t != "unitree_dds")))
    family = draw(st.sampled_from(sorted(UNITREE_SLOTS))) if transport == "unitree_dds" else ""
    spare = draw(st.integers(0, 4))
    motor_count = len(mapped) + spare
    if transport == "unitree_dds":
        motor_count = min(motor_count, UNITREE_SLOTS[family])
    indices = draw(st.permutations(range(motor_count)))[:len(mapped)]
    joint_map = dict(zip(mapped, indices, strict=False))

    groups: list[tuple[str, int]] = []
    if transport == "agibot_topics":
        cuts = sorted(draw(st.sets(st.integers(1, motor_count - 1), max_size=3))) if motor_count > 1 else []
        bounds = [0, *cuts, motor_count]
        groups = [(f"group{k}", hi - lo) for k, (lo, hi) in enumerate(itertools.pairwise(bounds))]

    imu = None
    if draw(st.booleans()):
        imu = {"enabled": draw(st.booleans())}
        framable = [link for link in links if link.isascii() and link.replace("_", "a").isalnum()
                    and not link[0].isdigit()]
        if imu["enabled"] and framable and draw(st.booleans()):
            imu["frame_id"] = draw(st.sampled_from(framable))
    parameters = None
    if draw(st.booleans()):
        state_timeout_ms = draw(st.integers(1, 600_000))
        parameters = {
            "network_interface": draw(st.from_regex(r"[A-Za-z0-9_.:\-]{1,15}", fullmatch=True)),
            "enable_monitor": draw(st.booleans()),
            "command_writer_period_us": draw(st.integers(100, 10_000_000)),
            "state_decimation": draw(st.integers(1, 10_000)),
            "state_timeout_ms": state_timeout_ms,
            "fault_timeout_ms": draw(st.integers(state_timeout_ms + 1, 3_600_000)),
        }
    qos = None
    if draw(st.booleans()):
        qos = {"reliability": draw(st.sampled_from(["best_effort", "reliable"])),
               "durability": draw(st.sampled_from(["volatile", "transient_local"])),
               "depth": draw(st.integers(1, 1000))}
    return RobotSpec(vendor=vendor, robot=robot, robot_name=draw(xml_text), links=links, joints=joints,
                     transport=transport, motor_count=motor_count, joint_map=joint_map, unmapped=unmapped,
                     float_type=draw(st.sampled_from([None, "float", "double"])), groups=groups, imu=imu,
                     parameters=parameters, qos=qos, family=family)


@st.composite
def projects(draw, max_robots: int = 3, transports: tuple[str, ...] = TRANSPORTS) -> list[RobotSpec]:
    count = draw(st.integers(1, max_robots))
    robots = draw(st.lists(robot_names, min_size=count, max_size=count, unique=True)
                  .filter(lambda rs: len({pascal_case(r) for r in rs}) == len(rs)))
    vendors = draw(st.lists(vendor_names, min_size=count, max_size=count))
    return [draw(robot_specs(v, r, transports)) for v, r in zip(vendors, robots, strict=True)]


def write_robot(root: Path, spec: RobotSpec, data: dict | None = None) -> Path:
    folder = root / "robots" / spec.vendor
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{spec.robot}.urdf").write_bytes(spec.urdf_bytes())
    path = folder / f"{spec.robot}.yaml"
    path.write_text(dump_yaml(data if data is not None else spec.yaml_data()))
    return path


# ---------------------------------------------------------------- checks of a generated robot
def expanded_description(pkg: Path, spec: RobotSpec) -> etree._Element:
    """The generated ros2_control xacro, included and called the way a user's URDF does, through xacro."""
    wrapper = pkg / "description" / f"_check_{spec.robot}.urdf.xacro"
    wrapper.write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="check">\n'
        f'  <xacro:include filename="{spec.robot}.ros2_control.xacro"/>\n'
        f'  <xacro:{spec.robot}_ros2_control/>\n</robot>\n')
    try:
        return etree.fromstring(expand_xacro(wrapper, {}, {}))
    finally:
        wrapper.unlink()


def check_robot_outputs(root: Path, spec: RobotSpec) -> None:
    pkg = root / "generated" / PACKAGE
    mapped_in_urdf_order = [n for n in spec.actuated if n in spec.joint_map]
    rc = expanded_description(pkg, spec).find("ros2_control")
    assert rc is not None
    assert [j.get("name") for j in rc.iter("joint")] == mapped_in_urdf_order
    sensors = rc.findall("sensor")
    imu_on = spec.imu is None or spec.imu.get("enabled", True)
    assert len(sensors) == (1 if imu_on else 0)
    frame = None
    if imu_on:
        frame = sensors[0].findtext("param[@name='frame_id']")
        assert frame in spec.links, f"IMU frame {frame!r} is not a link of the URDF"
        if spec.imu is not None and "frame_id" in spec.imu:
            assert frame == spec.imu["frame_id"]
    controllers = yaml.safe_load((pkg / "config" / f"{spec.robot}_controllers.yaml").read_text())
    wheels = {j.name for j in spec.joints if j.type == "continuous"}  # velocity-commanded
    for name, expected in (("forward_position_controller", [n for n in mapped_in_urdf_order if n not in wheels]),
                           ("forward_velocity_controller", [n for n in mapped_in_urdf_order if n in wheels])):
        if expected:
            assert controllers[name]["ros__parameters"]["joints"] == expected
        else:
            assert name not in controllers
    if imu_on:
        assert controllers["imu_sensor_broadcaster"]["ros__parameters"]["frame_id"] == frame


def compile_all(root: Path, specs: list[RobotSpec]) -> None:
    pkg = root / "generated" / PACKAGE
    errors: list[str] = []

    def one(spec: RobotSpec) -> None:
        try:
            syntax_check_driver(pkg, spec.vendor, spec.robot)
        except AssertionError as exc:
            errors.append(f"{spec.vendor}/{spec.robot} ({spec.transport}, {spec.float_type}): {exc}")

    with ThreadPoolExecutor(max_workers=COMPILE_WORKERS) as pool:
        list(pool.map(one, specs))
    assert not errors, "\n\n".join(errors)


# ---------------------------------------------------------------- 1. valid inputs always compile
@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(specs=projects(transports=COMPILABLE_TRANSPORTS))
def test_random_valid_robots_generate_drivers_that_compile(specs):
    with tempfile.TemporaryDirectory(prefix="rhi-prop-") as tmp:
        root = Path(tmp)
        for spec in specs:
            write_robot(root, spec)
        result = run_cli("generate", "--project", root)
        assert result.code == 0, f"valid input rejected:\n{result.err}\n" + "\n---\n".join(
            (root / "robots" / s.vendor / f"{s.robot}.yaml").read_text() for s in specs)
        for spec in specs:
            check_robot_outputs(root, spec)
        compile_all(root, specs)
        # generating again changes nothing
        before = snapshot(root)
        again = run_cli("generate", "--project", root)
        assert again.code == 0, again.err
        assert snapshot(root) == before


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
@pytest.mark.parametrize("vendor", ["system", "time", "index"])
def test_vendor_named_like_a_c_library_global_compiles_or_is_rejected(tmp_path, vendor):
    """Found by the property above: the vendor becomes a namespace at global scope (the spec's layout),
    where the C library (through <cstdlib>, <ctime>, <cstring>, ...) already declares system(), time(),
    index(), y0(), struct tm, errno, ... (about 2300 names with glibc). Such a name must be rejected
    with one clear line (rhi_gen/model/c_library_names.py), or the driver must compile."""
    root = tmp_path / "proj"
    root.mkdir()
    result = run_cli("new", "--vendor", vendor, "--robot", "arm", "--urdf", HOSTILE / "arm.urdf", "--project", root)
    if result.code == 2:
        assert_rejected(result, file="--vendor", words=(vendor,))
        assert snapshot(root) == {}
        return
    assert result.code == 0, result.err
    syntax_check_driver(root / "generated" / PACKAGE, vendor, "arm")


# ---------------------------------------------------------------- 2. invalid maps are always rejected first
MUTATIONS = ("duplicate_index", "index_too_large", "negative_index", "index_not_a_number", "unknown_joint",
             "missing_joint", "fixed_joint", "mimic_joint", "float_type", "transport", "unknown_key",
             "motor_count", "mapped_and_unmapped", "empty_map")


def _rename_entry(joint_map: dict[str, object], old: str, new: str) -> dict[str, object]:
    return {(new if k == old else k): v for k, v in joint_map.items()}


@st.composite
def invalid_inputs(draw):
    """(valid spec, broken YAML data, expected key or None, words in the message)."""
    vendor, robot = draw(vendor_names), draw(robot_names)
    spec = draw(robot_specs(vendor, robot))
    data = spec.yaml_data()
    jm: dict[str, object] = dict(data["joint_map"])
    names = list(jm)
    kind = draw(st.sampled_from(MUTATIONS))
    fixed = [j.name for j in spec.joints if j.type == "fixed"]
    mimic = [j.name for j in spec.joints if j.mimic is not None]
    key: str | None = None
    words: tuple[str, ...] = ()
    if kind == "duplicate_index":
        assume(len(names) >= 2)
        a, b = sorted(draw(st.lists(st.integers(0, len(names) - 1), min_size=2, max_size=2, unique=True)))
        jm[names[b]] = jm[names[a]]
        key, words = f"joint_map.{names[b]}", ("already used",)
    elif kind in ("index_too_large", "negative_index", "index_not_a_number"):
        victim = draw(st.sampled_from(names))
        if kind == "index_too_large":
            jm[victim] = spec.motor_count + draw(st.integers(0, 10**12))
        elif kind == "negative_index":
            jm[victim] = -draw(st.integers(1, 10**12))
        else:
            jm[victim] = draw(st.sampled_from([1.5, "3", True, None, [1], {"a": 1}, "", "0x1", 1e3]))
        key = f"joint_map.{victim}"
    elif kind == "unknown_joint":
        ghost = draw(joint_names.filter(lambda n: n not in {j.name for j in spec.joints}))
        jm = _rename_entry(jm, draw(st.sampled_from(names)), ghost)
        key, words = f"joint_map.{ghost}", ("is not in",)
    elif kind == "missing_joint":
        assume(len(names) >= 2)
        del jm[draw(st.sampled_from(names))]
        key, words = "joint_map", ("no motor index",)
    elif kind == "fixed_joint":
        assume(fixed)
        target = draw(st.sampled_from(fixed))
        jm = _rename_entry(jm, draw(st.sampled_from(names)), target)
        key, words = f"joint_map.{target}", ("fixed joint",)
    elif kind == "mimic_joint":
        assume(mimic)
        target = draw(st.sampled_from(mimic))
        jm = _rename_entry(jm, draw(st.sampled_from(names)), target)
        key, words = f"joint_map.{target}", ("mimics",)
    elif kind == "float_type":
        data["float_type"] = draw(st.one_of(st.text(max_size=12), st.integers(), st.just(["double"])).filter(
            lambda v: v not in ("float", "double")))
        key = "float_type"
    elif kind == "transport":
        data["transport"] = draw(st.one_of(st.text(max_size=16), st.integers(), st.just(None)).filter(
            lambda v: v not in TRANSPORTS))
        key = "transport"
    elif kind == "unknown_key":
        extra = draw(st.from_regex(r"[a-z][a-z_]{0,14}", fullmatch=True).filter(lambda k: k not in TOP_KEYS))
        data[extra] = draw(st.sampled_from([1, "x", None, [1]]))
        key, words = extra, ("unknown key",)
    elif kind == "motor_count":
        data["motor_count"] = draw(st.one_of(st.integers(max_value=0), st.integers(min_value=4097),
                                             st.sampled_from(["3", 2.5, None, True, [3]])))
        key = "motor_count"
    elif kind == "mapped_and_unmapped":
        again = draw(st.sampled_from(names))
        data["unmapped_joints"] = [*spec.unmapped, again]
        key, words = f"unmapped_joints[{len(spec.unmapped)}]", ("also in joint_map",)
    elif kind == "empty_map":
        jm = draw(st.sampled_from([{}, [], None, "all"]))
        key = "joint_map"
    data["joint_map"] = jm
    return spec, data, key, words


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                                 HealthCheck.filter_too_much])
@given(case=invalid_inputs())
def test_random_invalid_maps_are_rejected_before_anything_is_written(case):
    spec, data, key, words = case
    with tempfile.TemporaryDirectory(prefix="rhi-prop-") as tmp:
        root = Path(tmp)
        yaml_path = write_robot(root, spec)
        first = run_cli("generate", "--project", root)
        assert first.code == 0, first.err
        yaml_path.write_text(dump_yaml(data))
        before = snapshot(root)
        result = run_cli("generate", "--project", root)
        assert_rejected(result, file=f"robots/{spec.vendor}/{spec.robot}.yaml", line=ANY_LINE, key=key,
                        words=words)
        assert snapshot(root) == before, "a rejected generate changed the project"


# ---------------------------------------------------------------- 3. any edit of the inputs: a result or a clear line
SNIPPETS = ("<", ">", "/>", "</joint>", "<joint name=\"x\" type=\"revolute\">", "\"", "'", "&", "&amp;", "&#0;",
            "<!--", "-->", "<![CDATA[", "]]>", "<?xml version=\"1.0\"?>", "<!DOCTYPE r [<!ENTITY e \"x\">]>", "&e;",
            "xmlns:xacro=\"http://www.ros.org/wiki/xacro\"", "<xacro:foo/>", "${", "$(arg a)", "\n", "\t", "\x00",
            "\ufeff", "é", "\U0001F916", ":", ": ", "- ", "#", "{", "}", "[", "]", "*a", "&a ", "!!python/object:x",
            "? ", "---\n", "...\n", "%YAML 1.1\n", "~", "null", "yes", "1e9999", "-1", "0x10", "2.5", "\\")


@st.composite
def edited(draw, text: str) -> str:
    """``text`` with a few random deletions, insertions and duplications."""
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(text)))
        action = draw(st.sampled_from(["delete", "insert", "duplicate"]))
        if action == "delete":
            text = text[:at] + text[at + draw(st.integers(1, 40)):]
        elif action == "insert":
            text = text[:at] + draw(st.one_of(st.sampled_from(SNIPPETS), st.text(max_size=6))) + text[at:]
        else:
            end = min(len(text), at + draw(st.integers(1, 80)))
            text = text[:end] + text[at:end] + text[end:]
    return text


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(yaml_text=edited((HOSTILE / "arm.yaml").read_text()), urdf_text=edited((HOSTILE / "arm.urdf").read_text()),
       which=st.sampled_from(["yaml", "urdf", "both"]))
def test_edited_inputs_generate_or_are_rejected_cleanly(yaml_text, urdf_text, which):
    """Whatever a user (or a bad merge) does to the inputs, rhi-gen never crashes (exit 3) and a
    rejection leaves the previously generated package untouched."""
    with tempfile.TemporaryDirectory(prefix="rhi-prop-") as tmp:
        root = Path(tmp)
        folder = root / "robots" / "acme"
        folder.mkdir(parents=True)
        (folder / "arm.urdf").write_text((HOSTILE / "arm.urdf").read_text())
        (folder / "arm.yaml").write_text((HOSTILE / "arm.yaml").read_text())
        assert run_cli("generate", "--project", root).code == 0
        if which in ("yaml", "both"):
            (folder / "arm.yaml").write_bytes(yaml_text.encode("utf-8", "surrogatepass"))
        if which in ("urdf", "both"):
            (folder / "arm.urdf").write_bytes(urdf_text.encode("utf-8", "surrogatepass"))
        before = snapshot(root)
        result = run_cli("generate", "--project", root)
        assert result.code in (0, 2), f"exit {result.code}:\n{result.err}"
        assert "Traceback" not in result.err
        if result.code == 2:
            lines = result.error_lines
            assert len(lines) == 1 and lines[0].startswith("error: robots/acme/arm."), lines
            assert " -> " in lines[0], f"no fix in {lines[0]!r}"
            assert snapshot(root) == before
