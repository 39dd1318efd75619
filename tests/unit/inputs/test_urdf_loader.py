"""urdf_loader / xacro_expand: strict URDF reading, xacro expansion, one-line errors.

Independent oracles: yourdfpy (actuated joint names, over the fixtures and the real upstream
URDFs) and hand-written expectations. Broken fixtures mark the line the error must point at with
an ``expect-error`` comment.
"""
from __future__ import annotations

import io
import os
import shutil
import subprocess
import sys
import time
import types
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rhi_gen.errors import RhiGenError, UrdfError
from rhi_gen.inputs.urdf_loader import canonical_urdf_bytes, load_urdf, parse_urdf_bytes, portable_xml
from rhi_gen.inputs.xacro_expand import expand_xacro
from rhi_gen.model import JointLimits, Mimic
from tests.support import upstream_urdf
from tests.support.repo import REPO
from tests.support.repo import URDF_FIXTURES as FIX

XACRO = FIX / "xacro"
BROKEN = FIX / "broken"
MYPKG = FIX / "mypkg"

VALID_URDFS = ["simple_arm.urdf", "mimic_gripper.urdf", "continuous_wheel.urdf", "prismatic.urdf",
               "existing_ros2_control.urdf"]


def rel(path: Path) -> str:
    return path.relative_to(REPO).as_posix()


def assert_one_line(err: RhiGenError, file: str) -> str:
    text = str(err)
    assert "\n" not in text and "\r" not in text
    assert file in text
    return text


# ---------------------------------------------------------------- valid URDFs
def test_simple_arm():
    robot = load_urdf(FIX / "simple_arm.urdf", display_path="robots/demo/simple_arm.urdf")
    assert robot.name == "simple_arm"
    assert robot.source == "robots/demo/simple_arm.urdf"
    assert robot.links == ("base_link", "shoulder_link", "upper_arm_link", "forearm_link", "tool0")
    assert [(j.name, j.type, j.parent, j.child) for j in robot.joints] == [
        ("shoulder_pan", "revolute", "base_link", "shoulder_link"),
        ("shoulder_lift", "revolute", "shoulder_link", "upper_arm_link"),
        ("elbow", "revolute", "upper_arm_link", "forearm_link"),
        ("tool_flange", "fixed", "forearm_link", "tool0"),
    ]
    pan, lift, elbow, flange = robot.joints
    assert pan.axis == (0.0, 0.0, 1.0) and lift.axis == (0.0, 1.0, 0.0)
    assert elbow.axis == (1.0, 0.0, 0.0)  # URDF default
    assert pan.limits == JointLimits(lower=-3.14, upper=3.14, velocity=2.0, effort=150.0)
    assert lift.limits == JointLimits(lower=-1.5, upper=1.5, velocity=2.0, effort=150.0)
    assert flange.limits is None and flange.mimic is None
    assert [j.line for j in robot.joints] == [10, 17, 23, 29]
    assert [j.name for j in robot.actuated_joints] == ["shoulder_pan", "shoulder_lift", "elbow"]
    assert robot.ros2_control == ()


def test_mimic_gripper():
    robot = load_urdf(FIX / "mimic_gripper.urdf")
    by = {j.name: j for j in robot.joints}
    # the mimic target is defined after the mimic joint: still fine
    assert by["right_finger_joint"].mimic == Mimic(joint="left_finger_joint", multiplier=1.0,
                                                   offset=0.0)
    assert by["thumb_joint"].mimic == Mimic(joint="left_finger_joint", multiplier=-2.5, offset=0.1)
    assert by["right_finger_joint"].axis == (0.0, -1.0, 0.0)
    assert [j.name for j in robot.actuated_joints] == ["wrist", "left_finger_joint"]
    assert [j.name for j in robot.mimic_joints] == ["right_finger_joint", "thumb_joint"]
    assert robot.links == ("base_link", "palm", "left_finger", "right_finger", "thumb")


def test_continuous_wheel():
    robot = load_urdf(FIX / "continuous_wheel.urdf")
    left, right = robot.joints
    assert (left.type, right.type) == ("continuous", "continuous")
    assert left.limits == JointLimits(lower=None, upper=None, velocity=12.0, effort=5.5)
    assert right.limits is None  # <limit> is optional for continuous joints
    assert [j.name for j in robot.actuated_joints] == ["left_wheel_joint", "right_wheel_joint"]


def test_prismatic():
    robot = load_urdf(FIX / "prismatic.urdf")
    (slide,) = robot.joints
    assert slide.type == "prismatic" and slide.actuated
    assert slide.limits == JointLimits(lower=-0.25, upper=0.75, velocity=0.5, effort=300.0)
    assert slide.line == 5


def test_existing_ros2_control():
    robot = load_urdf(FIX / "existing_ros2_control.urdf")
    # <joint> inside <transmission>, <ros2_control> and <gazebo> are not URDF joints
    assert [j.name for j in robot.joints] == ["joint1", "joint2"]
    system, gazebo = robot.ros2_control
    assert (system.name, system.type, system.line) == ("RRBotSystem", "system", 22)
    assert system.plugin == "ros2_control_demo_hardware/RRBotSystemPositionOnlyHardware"
    assert [(j.name, j.command_interfaces, j.state_interfaces, j.line) for j in system.joints] == [
        ("joint1", ("position",), ("position", "velocity"), 29),
        ("joint2", ("position", "velocity"), ("position",), 36),
    ]
    # anywhere under <robot>, e.g. inside <gazebo>
    assert (gazebo.name, gazebo.plugin, gazebo.line) == ("GazeboSystem", "gazebo_ros2_control/GazeboSystem",
                                                 46)
    assert [(j.name, j.command_interfaces, j.state_interfaces) for j in gazebo.joints] == [
        ("joint2", (), ("effort",))]


def test_latin1_declared_encoding_is_honoured(tmp_path):
    doc = ('<?xml version="1.0" encoding="ISO-8859-1"?>\n<robot name="r\u00e9">\n'
           '<link name="a"/><link name="b"/>\n'
           '<joint name="gel\u00e9nk" type="continuous"><parent link="a"/><child link="b"/></joint>'
           '\n</robot>\n').encode("latin-1")
    path = tmp_path / "latin1.urdf"
    path.write_bytes(doc)
    robot = load_urdf(path)
    assert robot.name == "r\u00e9" and robot.joints[0].name == "gel\u00e9nk"


def test_plain_urdf_is_never_run_through_xacro(tmp_path):
    # A URDF generated by xacro (banner) whose names contain xacro syntax: taken literally.
    doc = (b'<?xml version="1.0" ?>\n'
           b'<!-- |    This document was autogenerated by xacro from /x/y.xacro | -->\n'
           b'<robot name="$(arg name)">\n  <link name="a"/>\n  <link name="b"/>\n'
           b'  <joint name="${pi}" type="fixed"><parent link="a"/><child link="b"/></joint>\n'
           b'</robot>\n')
    path = tmp_path / "generated.urdf"
    path.write_bytes(doc)
    robot = load_urdf(path)
    assert robot.name == "$(arg name)" and robot.joints[0].name == "${pi}"


def test_parse_urdf_bytes_matches_load_urdf():
    data = (FIX / "simple_arm.urdf").read_bytes()
    assert parse_urdf_bytes(data, source="x.urdf") == load_urdf(FIX / "simple_arm.urdf",
                                                                display_path="x.urdf")


# ---------------------------------------------------------------- xacro
def test_xacro_macro_arg_and_find():
    robot = load_urdf(XACRO / "robot.urdf.xacro", package_paths={"mypkg": MYPKG},
                      display_path="robots/x/robot.urdf.xacro")
    assert robot.name == "xacro_bot"
    assert robot.source == "robots/x/robot.urdf.xacro"
    assert [(j.name, j.type) for j in robot.joints] == [("joint_a", "revolute"),
                                                        ("left_hip", "continuous")]
    assert robot.links == ("base_link", "link_a", "left_thigh")
    joint_a = robot.joints[0]
    assert joint_a.limits is not None
    assert joint_a.limits.upper == pytest.approx(1.5707963267948966)
    assert joint_a.limits.lower == pytest.approx(-1.5707963267948966)
    assert b"autogenerated by xacro" not in robot.canonical_xml
    assert str(REPO).encode() not in robot.canonical_xml

    prefixed = load_urdf(XACRO / "robot.urdf.xacro", xacro_args={"prefix": "r1_"},
                         package_paths={"mypkg": str(MYPKG)})
    assert [j.name for j in prefixed.joints] == ["r1_joint_a", "r1_left_hip"]
    # args never leak into the next expansion (xacro keeps them in a module global)
    again = load_urdf(XACRO / "robot.urdf.xacro", package_paths={"mypkg": MYPKG})
    assert [j.name for j in again.joints] == ["joint_a", "left_hip"]


def test_xacro_raw_output_has_the_volatile_banner_and_canonical_strips_it():
    raw = expand_xacro(XACRO / "robot.urdf.xacro", {}, {"mypkg": MYPKG})
    assert b"autogenerated by xacro from " + str(XACRO / "robot.urdf.xacro").encode() in raw
    canon = canonical_urdf_bytes(raw)
    assert b"autogenerated" not in canon and b"EDITING THIS FILE" not in canon
    assert b"A small xacro" in canon  # the user's own comment stays
    assert canonical_urdf_bytes(canon) == canon


def test_xacro_hash_input_is_machine_independent(tmp_path):
    results = []
    for where in ("a", "deeper/b"):
        root = tmp_path / where
        shutil.copytree(FIX, root / "fixtures")
        robot = load_urdf(root / "fixtures" / "xacro" / "robot.urdf.xacro",
                          package_paths={"mypkg": root / "fixtures" / "mypkg"})
        results.append(robot.canonical_xml)
    assert results[0] == results[1]


def test_file_declaring_xacro_namespace_is_expanded():
    robot = load_urdf(XACRO / "plain_name_with_ns.urdf")
    limits = robot.joints[0].limits
    assert limits is not None
    assert limits.upper == pytest.approx(1.5707963267948966)


def test_xacro_warnings_do_not_reach_stderr(capfd):
    robot = load_urdf(XACRO / "warns.urdf.xacro")
    limits = robot.joints[0].limits
    assert limits is not None
    assert limits.upper == 0.5
    out, err = capfd.readouterr()
    assert out == "" and err == ""


def test_xacro_leaves_no_global_state_behind():
    import xacro

    before_modules = {k: sys.modules.get(k) for k in ("ament_index_python",
                                                      "ament_index_python.packages")}
    before_yaml = dict(yaml.SafeLoader.yaml_constructors)
    stdout, stderr = sys.stdout, sys.stderr
    load_urdf(XACRO / "robot.urdf.xacro", xacro_args={"prefix": "p_"},
              package_paths={"mypkg": MYPKG})
    load_urdf(XACRO / "yaml_limits.urdf.xacro")  # xacro registers !degrees on yaml.SafeLoader
    with pytest.raises(UrdfError):
        load_urdf(XACRO / "needs_arg.urdf.xacro")
    assert {k: sys.modules.get(k) for k in before_modules} == before_modules
    assert dict(yaml.SafeLoader.yaml_constructors) == before_yaml
    assert sys.stdout is stdout and sys.stderr is stderr
    assert xacro.substitution_args_context == {}
    assert xacro.all_includes == []
    assert xacro.filestack is None and xacro.macrostack is None
    assert "open" not in vars(xacro)
    with pytest.raises(yaml.constructor.ConstructorError):
        yaml.safe_load("a: !degrees 90")  # our own YAML loading is not widened by xacro


def test_xacro_load_yaml():
    (elbow,) = load_urdf(XACRO / "yaml_limits.urdf.xacro").joints
    assert elbow.limits is not None
    assert elbow.limits.lower == pytest.approx(-1.5707963267948966)
    assert elbow.limits.upper == pytest.approx(1.5707963267948966)
    assert (elbow.limits.effort, elbow.limits.velocity) == (12.5, 3.0)


def test_xacro_reads_utf8_whatever_the_locale(tmp_path):
    # xacro itself opens files in the locale's encoding (ASCII under a bare C locale).
    path = tmp_path / "u.urdf.xacro"
    path.write_bytes(
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">\n'
        '<xacro:property name="n" value="gel\u00e9nk\u2713"/>\n'
        '<link name="a"/><link name="b"/>\n'
        '<joint name="${n}" type="continuous"><parent link="a"/><child link="b"/></joint>\n'
        '</robot>\n'.encode("utf-8"))
    assert load_urdf(path).joints[0].name == "gel\u00e9nk\u2713"
    env = dict(os.environ, LC_ALL="C", LANG="C", PYTHONUTF8="0", PYTHONCOERCECLOCALE="0")
    code = ("import sys; from rhi_gen.inputs.urdf_loader import load_urdf; "
            f"sys.stdout.write(ascii(load_urdf({str(path)!r}).joints[0].name))")
    done = subprocess.run([sys.executable, "-c", code], env=env, cwd=REPO, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert done.stdout == ascii("gel\u00e9nk\u2713")


def test_real_ament_index_is_shadowed_and_restored(monkeypatch):
    real_top = types.ModuleType("ament_index_python")
    real_pkgs = types.ModuleType("ament_index_python.packages")

    def boom(name):  # a sourced ROS workspace must not decide what $(find) means
        raise AssertionError("the real ament index was consulted")

    monkeypatch.setattr(real_pkgs, "get_package_share_directory", boom, raising=False)
    monkeypatch.setitem(sys.modules, "ament_index_python", real_top)
    monkeypatch.setitem(sys.modules, "ament_index_python.packages", real_pkgs)
    robot = load_urdf(XACRO / "robot.urdf.xacro", package_paths={"mypkg": MYPKG})
    assert len(robot.joints) == 2
    assert sys.modules["ament_index_python.packages"] is real_pkgs
    assert sys.modules["ament_index_python"] is real_top


def test_xacro_expansions_in_parallel_threads_do_not_mix():
    prefixes = [f"t{i}_" for i in range(12)]

    def run(prefix):
        robot = load_urdf(XACRO / "robot.urdf.xacro", xacro_args={"prefix": prefix},
                          package_paths={"mypkg": MYPKG})
        return [j.name for j in robot.joints]

    with ThreadPoolExecutor(max_workers=6) as pool:
        results = list(pool.map(run, prefixes))
    assert results == [[f"{p}joint_a", f"{p}left_hip"] for p in prefixes]


XACRO_ERRORS: list[tuple[str, dict[str, Path], dict[str, str], str, int | None, list[str]]] = [
    # (fixture, package_paths, args, shown file, line, substrings)
    ("unknown_pkg.urdf.xacro", {"mypkg": MYPKG}, {}, "robots/unknown_pkg.urdf.xacro", 3,  # the $(find) line
     ["unknown package 'nosuchpkg'", "add package_paths: {nosuchpkg: <dir>} to the vendor YAML"]),
    ("needs_arg.urdf.xacro", {}, {}, "robots/needs_arg.urdf.xacro", 3,  # the $(arg) line
     ["xacro arg 'base_name' is not set", "xacro_args: {base_name: <value>}"]),
    ("broken_include.urdf.xacro", {}, {}, "robots/parts/broken_part.xacro", 4,
     ["malformed XML: mismatched tag"]),
    ("missing_include.urdf.xacro", {}, {}, "robots/missing_include.urdf.xacro", 3,  # the <xacro:include> line
     ["cannot open robots/parts/does_not_exist.xacro", "No such file"]),
    ("package_url.urdf.xacro", {}, {}, "robots/package_url.urdf.xacro", 3,
     ["package://mypkg/urdf/leg.xacro", "write $(find mypkg)/urdf/leg.xacro instead",
      "package_paths: {mypkg: <dir>}"]),
    ("unknown_macro.urdf.xacro", {}, {}, "robots/unknown_macro.urdf.xacro", None,
     ["unknown macro name: xacro:no_such_macro"]),
    ("malformed_top.urdf.xacro", {}, {}, "robots/malformed_top.urdf.xacro", 4,
     ["malformed XML: Opening and ending tag mismatch"]),
    ("duplicate_after_expansion.urdf.xacro", {}, {}, "robots/duplicate_after_expansion.urdf.xacro",
     13, ["duplicate link name 'left_wheel'", "xacro-expanded"]),
    ("robot.urdf.xacro", {}, {}, "robots/robot.urdf.xacro", 7,
     ["unknown package 'mypkg'", "package_paths: {mypkg: <dir>}"]),
    ("robot.urdf.xacro", {"mypkg": MYPKG / "nope"}, {}, "robots/robot.urdf.xacro", 7,
     ["not a directory", "package_paths: {mypkg: <dir>}"]),
]


@pytest.mark.parametrize("name,pkgs,args,shown,line,parts", XACRO_ERRORS,
                         ids=[f"{e[0]}-{i}" for i, e in enumerate(XACRO_ERRORS)])
def test_xacro_errors(name, pkgs, args, shown, line, parts, capfd):
    with pytest.raises(UrdfError) as info:
        load_urdf(XACRO / name, xacro_args=args, package_paths=pkgs,
                  display_path=f"robots/{name}")
    err = info.value
    text = assert_one_line(err, shown)
    assert err.file == shown and err.line == line
    for part in parts:
        assert part in text
    assert err.fix
    if "not a directory" not in text:  # there the user's own (absolute) path is the point
        assert str(REPO) not in text  # display paths, not absolute ones
    out, errout = capfd.readouterr()
    assert out == "" and errout == ""


def test_xacro_arg_values_must_be_strings():
    not_strings: dict[str, Any] = {"prefix": 3}  # what an untyped caller (a YAML value) can pass
    with pytest.raises(UrdfError) as info:
        load_urdf(XACRO / "robot.urdf.xacro", xacro_args=not_strings,
                  package_paths={"mypkg": MYPKG}, display_path="r.xacro")
    assert info.value.key == "xacro_args" and "must be a string" in str(info.value)


def test_xacro_unexpandable_prefix_is_reported():
    with pytest.raises(UrdfError) as info:
        load_urdf(BROKEN / "unexpanded_xacro.urdf", display_path="u.urdf")
    assert "<x:property> was not expanded" in str(info.value)


# ---------------------------------------------------------------- broken URDFs
def _marked_line(path: Path) -> int:
    lines = path.read_text(encoding="utf-8").splitlines()
    marked = [i + 1 for i, text in enumerate(lines) if "expect-error" in text]
    assert len(marked) == 1, path
    return marked[0]


BROKEN_CASES = [
    ("malformed.urdf", "malformed XML: Opening and ending tag mismatch"),
    ("root_not_robot.urdf", "root element is <model>, not <robot>"),
    ("robot_no_name.urdf", "<robot> has no name attribute"),
    ("joint_no_name.urdf", "<joint> has no name attribute"),
    ("joint_no_type.urdf", "joint 'j' has no type attribute"),
    ("joint_no_parent.urdf", "joint 'j' has no <parent"),
    ("joint_no_child.urdf", "joint 'j' has no <child"),
    ("joint_unknown_type.urdf", "unknown type 'hinge'"),
    ("duplicate_joint.urdf", "duplicate joint name 'j' (first defined on line 6)"),
    ("duplicate_link.urdf", "duplicate link name 'a' (first defined on line 3)"),
    ("undefined_link.urdf", "child link 'upper_ram' is not defined (did you mean 'upper_arm'?)"),
    ("two_parents.urdf", "link 'c' is the child of two joints: 'j1' (line 6) and 'j2'"),
    ("cycle.urdf", "cycle: 'j_xy' -> 'j_yz' -> 'j_zx' -> 'j_xy'"),
    ("multiple_roots.urdf", "2 root links ('camera_link', 'base_link'); link 'camera_link'"),
    ("limit_not_number.urdf", "<limit upper=\"1.5rad\"> is not a number"),
    ("limit_xacro_expression.urdf", "unexpanded xacro expression"),
    ("limit_nan.urdf", "<limit effort=\"nan\"> is not a number"),
    ("limit_no_effort.urdf", "<limit> has no effort attribute"),
    ("lower_above_upper.urdf", "lower 0.5 is greater than upper -0.5"),
    ("revolute_no_limit.urdf", "revolute joint 'j' has no <limit>"),
    ("prismatic_no_limit.urdf", "prismatic joint 'slide' has no <limit>"),
    ("mimic_missing_joint.urdf", "mimics 'finger_lef', which is not a joint"),
    ("mimic_self.urdf", "joint 'j' mimics itself"),
    ("mimic_loop.urdf", "loop: 'j1' -> 'j2' -> 'j1'"),
    ("mimic_bad_multiplier.urdf", "<mimic multiplier=\"minus one\"> is not a number"),
    ("axis_bad.urdf", "<axis xyz=\"0 1\"> is not three numbers"),
    ("entity.urdf", "<!ENTITY> declarations are not supported"),
    ("no_links.urdf", "the robot has no <link>"),
    ("xacro_prefix_undeclared.urdf", "Namespace prefix xacro on property is not defined"),
]


def test_every_broken_fixture_is_covered():
    covered = {name for name, _ in BROKEN_CASES} | {"unexpanded_xacro.urdf"}
    assert {p.name for p in BROKEN.glob("*.urdf")} == covered


@pytest.mark.parametrize("name,expected", BROKEN_CASES, ids=[c[0] for c in BROKEN_CASES])
def test_broken_urdf(name, expected):
    path = BROKEN / name
    shown = rel(path)
    with pytest.raises(UrdfError) as info:
        load_urdf(path, display_path=shown)
    err = info.value
    line = _marked_line(path)
    assert (err.file, err.line) == (shown, line)
    text = assert_one_line(err, shown)
    assert text.startswith(f"{shown}:{line}: ")
    assert expected in text
    assert err.fix and f" -> {err.fix}" in text
    # the same through parse_urdf_bytes (already-expanded input)
    with pytest.raises(UrdfError) as again:
        parse_urdf_bytes(path.read_bytes(), source=shown)
    assert (again.value.line, again.value.message) == (err.line, err.message)


def test_unexpanded_xacro_given_as_plain_bytes():
    path = BROKEN / "unexpanded_xacro.urdf"
    with pytest.raises(UrdfError) as info:
        parse_urdf_bytes(path.read_bytes(), source="u.urdf")
    assert info.value.line == _marked_line(path)
    assert "not run through xacro" in str(info.value)


# ---------------------------------------------------------------- unreadable inputs
def _load_error(path, shown="robots/bad.urdf") -> UrdfError:
    with pytest.raises(UrdfError) as info:
        load_urdf(path, display_path=shown)
    assert_one_line(info.value, shown)
    assert info.value.fix
    return info.value


@pytest.mark.parametrize("content", [b"", b"  \n\t\n"], ids=["zero-bytes", "whitespace"])
def test_empty_file(tmp_path, content):
    path = tmp_path / "empty.urdf"
    path.write_bytes(content)
    assert "file is empty" in _load_error(path).message


def test_missing_file(tmp_path):
    assert "file not found" in _load_error(tmp_path / "nope.urdf").message
    assert "file not found" in _load_error(tmp_path / "nope.urdf.xacro").message


def test_directory_instead_of_file(tmp_path):
    assert "is a directory" in _load_error(tmp_path).message
    (tmp_path / "d.urdf.xacro").mkdir()
    assert "is a directory" in _load_error(tmp_path / "d.urdf.xacro").message


def test_unreadable_file(tmp_path, monkeypatch):
    path = tmp_path / "secret.urdf"
    path.write_bytes((FIX / "prismatic.urdf").read_bytes())

    def denied(self):
        raise PermissionError(13, "Permission denied", str(self))

    monkeypatch.setattr(Path, "read_bytes", denied)
    assert "permission denied" in _load_error(path).message


def test_binary_junk(tmp_path):
    path = tmp_path / "mesh.urdf"
    path.write_bytes(bytes(range(256)) * 4)
    assert "binary" in _load_error(path).message


def test_non_utf8_bytes(tmp_path):
    path = tmp_path / "bad.urdf"
    path.write_bytes(b'<?xml version="1.0"?>\n<robot name="r">\n  <link name="caf\xe9"/>\n'
                     b'</robot>\n')
    err = _load_error(path)
    assert err.fix is not None
    assert err.line == 3 and "malformed XML" in err.message and "UTF-8" in err.fix


# ---------------------------------------------------------------- canonical bytes
def test_canonical_bytes_normalises_line_endings_and_strips_only_the_banner():
    banner = (b"<?xml version=\"1.0\" ?>\r\n"
              b"<!-- ==================== -->\r\n"
              b"<!-- |    This document was autogenerated by xacro from /home/me/r.xacro  | -->\r\n"
              b"<!-- |    EDITING THIS FILE BY HAND IS NOT RECOMMENDED                   | -->\r\n"
              b"<!-- ==================== -->\r\n"
              b"<!-- my comment -->\r<robot name=\"r\"><!-- ===== --></robot>\r\n")
    assert canonical_urdf_bytes(banner) == (
        b"<?xml version=\"1.0\" ?>\n<!-- my comment -->\n<robot name=\"r\"><!-- ===== --></robot>\n")
    plain = b"<!-- ===== -->\n<robot name=\"r\"/>\n"
    assert canonical_urdf_bytes(plain) == plain  # no xacro banner: nothing removed
    other_machine = banner.replace(b"/home/me/r.xacro", b"/opt/ws/src/robot/urdf/r.xacro")
    assert canonical_urdf_bytes(other_machine) == canonical_urdf_bytes(banner)


# ---------------------------------------------------------------- size and line numbers
def _chain_urdf(n: int, prefix: bytes = b"") -> bytes:
    parts = [b'<?xml version="1.0"?>', prefix + b'<robot name="big">', b'  <link name="link_0"/>']
    for i in range(1, n + 1):
        parts.append(
            b'  <link name="link_%d">\n    <visual><geometry><box size="0.1 0.1 0.1"/></geometry>'
            b'</visual>\n  </link>' % i)
        parts.append(
            b'  <joint name="joint_%d" type="revolute">\n    <parent link="link_%d"/>\n'
            b'    <child link="link_%d"/>\n    <origin xyz="0 0 0.1" rpy="0 0 0"/>\n'
            b'    <axis xyz="0 0 1"/>\n'
            b'    <limit lower="-1" upper="1" effort="10" velocity="1"/>\n  </joint>'
            % (i, i - 1, i))
    parts.append(b"</robot>\n")
    return b"\n".join(parts)


def test_2000_joints_load(tmp_path, report):
    path = tmp_path / "big.urdf"
    path.write_bytes(_chain_urdf(2000))
    start = time.perf_counter()
    robot = load_urdf(path)
    elapsed = time.perf_counter() - start
    assert len(robot.joints) == 2000 and len(robot.actuated_joints) == 2000
    assert robot.joints[-1].name == "joint_2000" and robot.joints[-1].child == "link_2000"
    report(f"test_2000_joints_load: 2000 joints loaded in {elapsed * 1000:.1f} ms")  # a figure, not a limit


def test_line_numbers_past_65535_are_exact(tmp_path):
    # libxml2 keeps element lines in 16 bits; comments and CDATA that look like tags must not
    # confuse the exact recount.
    pad = (b"<!-- <joint name=\"commented\"> <link name='c'/> -->\n" * 69990
           + b"<![CDATA[ <link name=\"x\"> ]]>\n" * 5 + b"<?pi <link?>\n" * 5)
    doc = (b'<?xml version="1.0"?>\n<robot name="tall">\n' + pad
           + b'  <link name="a"/>\n  <link name="b"/>\n'
           + b'  <joint name="ok" type="fixed">\n    <parent link="a"/>\n    <child link="b"/>\n'
           + b'  </joint>\n'
           + b'  <joint name="bad" type="hinge">\n    <parent link="a"/>\n    <child link="b"/>\n'
           + b'  </joint>\n</robot>\n')
    first_line = 2 + 70000 + 1
    with pytest.raises(UrdfError) as info:
        parse_urdf_bytes(doc, source="tall.urdf")
    assert info.value.line == first_line + 6
    good = doc.replace(b'type="hinge"', b'type="fixed"').replace(
        b'<child link="b"/>\n  </joint>\n</robot>',
        b'<child link="c"/>\n  </joint>\n  <link name="c"/>\n</robot>')
    robot = parse_urdf_bytes(good, source="tall.urdf")
    assert [j.line for j in robot.joints] == [first_line + 2, first_line + 6]
    crlf = parse_urdf_bytes(good.replace(b"\n", b"\r\n"), source="tall.urdf")
    assert [j.line for j in crlf.joints] == [first_line + 2, first_line + 6]


# ---------------------------------------------------------------- names round-trip exactly
def _xml_attr(text: str) -> str:
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;").replace("'", "&apos;").replace("\t", "&#9;")
            .replace("\n", "&#10;").replace("\r", "&#13;"))


def _xml_char(c: str) -> bool:
    o = ord(c)
    return o in (9, 10, 13) or 0x20 <= o <= 0xD7FF or 0xE000 <= o <= 0xFFFD or o >= 0x10000


_NAME = st.text(
    alphabet=st.one_of(st.sampled_from("\"'\\&<>;$(){} \t\n\r\u00e9\u96ea\U0001F916"),
                       st.characters(min_codepoint=9).filter(_xml_char)),
    min_size=1, max_size=24)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(names=st.lists(_NAME, min_size=2, max_size=2, unique=True), robot_name=_NAME)
def test_names_round_trip_exactly(names, robot_name):
    a, b = names
    doc = f"""<?xml version="1.0" encoding="UTF-8"?>
<robot name="{_xml_attr(robot_name)}">
  <link name="base"/><link name="l1"/><link name="l2"/>
  <joint name="{_xml_attr(a)}" type="revolute">
    <parent link="base"/><child link="l1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name='{_xml_attr(b)}' type="revolute">
    <parent link="base"/><child link="l2"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="{_xml_attr(a)}"/>
  </joint>
  <ros2_control name="s" type="system">
    <joint name="{_xml_attr(a)}"><command_interface name="position"/></joint>
  </ros2_control>
</robot>
""".encode()
    robot = parse_urdf_bytes(doc, source="names.urdf")
    assert robot.name == robot_name
    assert [j.name for j in robot.joints] == [a, b]
    assert robot.joints[1].mimic is not None
    assert robot.joints[1].mimic.joint == a
    assert robot.ros2_control[0].joints[0].name == a


# ---------------------------------------------------------------- independent oracle: yourdfpy
def _oracle_cases():
    cases = [pytest.param(FIX / name, id=name) for name in VALID_URDFS]
    cases.append(pytest.param(XACRO / "robot.urdf.xacro", id="xacro/robot.urdf.xacro"))
    cases.append(pytest.param(XACRO / "plain_name_with_ns.urdf", id="xacro/plain_name_with_ns"))
    # the repository's upstream copies always; the shared folder's others when it is there
    cases += [pytest.param(p, id=f"upstream/{p.name}") for p in upstream_urdf.in_repo()]
    if upstream_urdf.SHARED.is_dir():
        cases += [pytest.param(p, id=f"upstream/{p.name}") for p in upstream_urdf.shared_only()]
    else:
        cases.append(pytest.param(None, id="upstream/not-carried", marks=pytest.mark.skip(
            reason=upstream_urdf.missing_reason("agibot_x2.urdf, engineai_pm01_edu.urdf"))))
    return cases


@pytest.mark.parametrize("path", _oracle_cases())
def test_actuated_joints_match_yourdfpy(path):
    yourdfpy = pytest.importorskip("yourdfpy")
    robot = load_urdf(path, package_paths={"mypkg": MYPKG})
    xml = robot.canonical_xml if path.name.endswith(".xacro") or "xacro" in path.parts else \
        path.read_bytes()
    theirs = yourdfpy.URDF.load(io.BytesIO(xml), build_scene_graph=False, load_meshes=False,
                                build_collision_scene_graph=False, load_collision_meshes=False)
    types_by_name = {j.name: j.type for j in theirs.robot.joints}
    expected = [n for n in theirs.actuated_joint_names
                if types_by_name[n] not in ("floating", "planar")]
    assert [j.name for j in robot.actuated_joints] == expected
    assert [j.name for j in robot.joints] == [j.name for j in theirs.robot.joints]
    assert list(robot.links) == [link.name for link in theirs.robot.links]


MESH_XACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="meshy">
  <link name="base_link"><visual><geometry><mesh filename="file://$(find mypkg)/meshes/base.stl"/></geometry></visual></link>
  <link name="l1"><visual><geometry><mesh filename="${xacro.abs_filename('meshes/l1.stl')}"/></geometry></visual></link>
  <joint name="j1" type="continuous"><parent link="base_link"/><child link="l1"/></joint>
</robot>
"""  # noqa: E501 (one element a line: the tests read line numbers)


def test_xacro_hash_is_machine_independent_with_find_and_dirname_in_meshes(tmp_path):
    """$(find pkg) or xacro.abs_filename() in a mesh expand to this machine's folders: the fingerprint
    must not see them (else no clone of the project at another path passes `rhi-gen check`)."""
    results = []
    for where in ("a", "deeper/b b&c"):
        root = tmp_path / where
        (root / "desc").mkdir(parents=True)
        (root / "mypkg").mkdir()
        (root / "desc" / "robot.urdf.xacro").write_text(MESH_XACRO)
        robot = load_urdf(root / "desc" / "robot.urdf.xacro", package_paths={"mypkg": root / "mypkg"})
        assert [j.name for j in robot.joints] == ["j1"]
        results.append(robot.canonical_xml)
    assert results[0] == results[1]
    xml = results[0]
    assert b'filename="file://$(find mypkg)/meshes/base.stl"' in xml
    assert b'filename="$(dirname)/meshes/l1.stl"' in xml
    assert str(tmp_path).encode() not in xml


def test_portable_xml_replaces_whole_folders_only(tmp_path):
    pkg, other = tmp_path / "ws" / "mypkg", tmp_path / "ws" / "mypkg2"
    xml = (f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{pkg}/a.stl"/></geometry></visual>'
           f'</link><link name="b"><visual><geometry><mesh filename="{other}/b.stl"/></geometry></visual></link>'
           f'<!-- {pkg} --></robot>').encode()
    out = portable_xml(xml, tmp_path / "top" / "r.urdf.xacro", {"mypkg": pkg})
    assert b'filename="$(find mypkg)/a.stl"' in out and f'filename="{other}/b.stl"'.encode() in out
    assert b"<!-- $(find mypkg) -->" in out
