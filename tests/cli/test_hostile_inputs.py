"""Hostile and broken input, driven through the CLI exactly as a user would.

Every case asserts the whole contract of a rejection:
- exit code 2 (bad input), never 3 (a crash) and never a traceback;
- exactly one error line, ``error: <file>[:<line>]: [<key>: ]<what> -> <fix>``, naming the file the
  user has to edit (and its line or YAML key) and what to do about it;
- not one byte changed anywhere in the project: robots/ and generated/ are hashed before and after
  (and nothing is created outside it).

The starting point is a valid project (tests/fixtures/hostile/arm.{urdf,yaml}) that has already
been generated, so "nothing changed" also means "nothing half-overwritten".
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from lxml import etree

from rhi_gen.model.naming import vendor_problem
from tests.support.cli import (
    URDF_REL,
    YAML_REL,
    CliResult,
    assert_rejected,
    edit_yaml,
    generate_rejected,
    new_rejected,
    replace_once,
    run_cli,
    snapshot,
    write_project,
)
from tests.support.cpp_build import syntax_check_driver
from tests.support.repo import HOSTILE, PACKAGE, REPO
from tests.support.xml_tree import attribute


@pytest.fixture
def project(tmp_path: Path) -> Path:
    """A valid, already generated project at tmp_path/proj: the hostile arm (overrides tests/conftest.py's)."""
    root = write_project(tmp_path / "proj")
    result = run_cli("generate", "--project", root)
    assert result.code == 0, result.err
    assert (root / "generated" / PACKAGE / "src" / "acme" / "arm.cpp").is_file()
    return root


def fixture_text(name: str) -> str:
    return (HOSTILE / name).read_text()


# ---------------------------------------------------------------- malformed XML
def test_malformed_urdf_names_the_line(project):
    (project / URDF_REL).write_text(fixture_text("malformed.urdf"))
    generate_rejected(project, file=URDF_REL, line=10,
                      words=("malformed XML", "mismatch", "line 4", "fix the XML syntax"))


def test_unterminated_attribute_names_the_line(project):
    (project / URDF_REL).write_text(fixture_text("bad_attribute_quote.urdf"))
    # libxml2 notices the runaway attribute value at the next '<' (line 6)
    generate_rejected(project, file=URDF_REL, line=6, words=("malformed XML", "attributes values"))


def test_malformed_urdf_given_to_new(tmp_path):
    urdf = HOSTILE / "malformed.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", urdf,
                 file=str(urdf), line=10, words=("malformed XML",))


def test_malformed_xacro_names_the_line(tmp_path):
    xacro = HOSTILE / "malformed.urdf.xacro"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                 file=str(xacro), line=5, words=("malformed XML",))


# ---------------------------------------------------------------- missing files
def test_yaml_names_a_missing_urdf(project):
    edit_yaml(project, "urdf: arm.urdf", "urdf: arm_v2.urdf")
    generate_rejected(project, file=YAML_REL, line=3, key="urdf", words=("'arm_v2.urdf' does not exist",))


def test_new_with_a_missing_urdf(tmp_path):
    missing = tmp_path / "nowhere" / "robot.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", missing,
                 file=str(missing), key="--urdf", words=("not found",))


def test_missing_xacro_include(tmp_path):
    xacro = HOSTILE / "missing_include.urdf.xacro"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                 file=str(xacro), line=3, words=("cannot open", "arm_macros.xacro", "xacro:include"))


def test_generate_without_robots(tmp_path):
    root = tmp_path / "empty"
    root.mkdir()
    before = snapshot(root)
    assert_rejected(run_cli("generate", "--project", root), file="robots", words=("no robots found", "rhi-gen new"))
    assert snapshot(root) == before


def test_generate_an_unknown_robot(project):
    before = snapshot(project)
    assert_rejected(run_cli("generate", "arn", "--project", project), file="robots/",
                    words=("no robot named 'arn'", "acme/arm"))
    assert snapshot(project) == before


# ---------------------------------------------------------------- xacro errors and missing args
def test_missing_xacro_arg_through_generate(project):
    shutil.copy(HOSTILE / "needs_arg.urdf.xacro", project / "robots/acme/arm.urdf.xacro")
    edit_yaml(project, "urdf: arm.urdf", "urdf: arm.urdf.xacro")
    generate_rejected(project, file="robots/acme/arm.urdf.xacro", line=4,
                      words=("xacro arg 'prefix' is not set", "xacro_args: {prefix: <value>}"))


def test_missing_xacro_arg_through_new(tmp_path):
    xacro = HOSTILE / "needs_arg.urdf.xacro"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                 file=str(xacro), line=4, words=("xacro arg 'prefix' is not set", "--xacro-arg prefix=<value>"))
    # the fix works: given the arg, the same file generates (expanded into the project: it lies outside)
    result = run_cli("new", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                     "--xacro-arg", "prefix=left_", "--project", tmp_path / "proj")
    assert result.code == 0, result.err
    written = yaml.safe_load((tmp_path / "proj" / YAML_REL).read_text())
    assert written["urdf"] == "arm.urdf" and "xacro_args" not in written
    assert "prefix:=left_" in (tmp_path / "proj" / YAML_REL).read_text()  # in the provenance comment
    assert list(written["joint_map"]) == ["left_shoulder_pan"]
    # inside the project the xacro stays a xacro, and the arg is recorded
    inside = tmp_path / "proj2" / "robots" / "acme" / "arm.urdf.xacro"
    inside.parent.mkdir(parents=True)
    shutil.copy(xacro, inside)
    result = run_cli("new", "--vendor", "acme", "--robot", "arm", "--urdf", inside,
                     "--xacro-arg", "prefix=left_", "--project", tmp_path / "proj2")
    assert result.code == 0, result.err
    written = yaml.safe_load((tmp_path / "proj2" / YAML_REL).read_text())
    assert written["urdf"] == "arm.urdf.xacro" and written["xacro_args"] == {"prefix": "left_"}


def test_xacro_undefined_property(tmp_path):
    xacro = HOSTILE / "undefined_property.urdf.xacro"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                 file=str(xacro), words=("xacro", "raech"))


def test_xacro_unknown_macro(tmp_path):
    xacro = HOSTILE / "unknown_macro.urdf.xacro"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", xacro,
                 file=str(xacro), words=("unknown macro", "lge"))


def test_bad_xacro_arg_syntax(tmp_path):
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", HOSTILE / "arm.urdf",
                 "--xacro-arg", "prefix", file="--xacro-arg", words=("NAME=VALUE",))


# ---------------------------------------------------------------- nothing to drive
def test_urdf_without_actuated_joints_through_new(tmp_path):
    urdf = HOSTILE / "no_actuated_joints.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "head", "--urdf", urdf,
                 file=str(urdf), words=("has no actuated joints",))


def test_urdf_whose_movable_joints_all_mimic_through_new(tmp_path):
    """Movable joints that all mimic one another: none is driven, and the chain never ends."""
    urdf = HOSTILE / "mimic_loop.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "loop", "--urdf", urdf,
                 file=str(urdf), line=16, words=("mimic joints follow each other in a loop",))


def test_yaml_maps_a_fixed_joint(project):
    (project / URDF_REL).write_text(fixture_text("no_actuated_joints.urdf"))
    edit_yaml(project, "  shoulder_pan: 0\n  shoulder_lift: 1\n  elbow: 2\n", "  camera_joint: 0\n")
    edit_yaml(project, "motor_count: 3", "motor_count: 1")
    generate_rejected(project, file=YAML_REL, line=8, key="joint_map.camera_joint",
                      words=("fixed joint", "remove it from joint_map"))


# ---------------------------------------------------------------- joint names that are not C++/XML-safe text
HOSTILE_JOINT_NAMES = {
    "double quote": ('el"bow', "the character '\"'"),
    "backslash": ("el\\bow", "the character '\\\\'"),
    "newline": ("el\nbow", "control character (U+000A)"),
    "tab": ("el\tbow", "control character (U+0009)"),
    "non-ASCII": ("ellbögen", "non-ASCII character 'ö'"),
    "emoji": ("elbow_\U0001F916", "non-ASCII character"),
    "space": ("left elbow", "whitespace"),
    "angle bracket": ("elbow<1>", "the character '<'"),
    "ampersand": ("elbow&wrist", "the character '&'"),
    "xacro dollar": ("${elbow}", "the character '$'"),
    "C++ comment": ("elbow*/", "the character '*'"),
    "too long": ("j" * 200, "200 characters long"),
}


def _urdf_with_elbow_named(name: str) -> str:
    attr = etree.tostring(etree.Element("x", name=name)).decode()[2:-2]  # ' name="..."', XML-escaped
    return replace_once(fixture_text("arm.urdf"), ' name="elbow"', attr)


@pytest.mark.parametrize("label", sorted(HOSTILE_JOINT_NAMES))
def test_hostile_joint_name_through_new(tmp_path, label):
    name, words = HOSTILE_JOINT_NAMES[label]
    urdf = tmp_path / "input" / "arm.urdf"
    urdf.parent.mkdir()
    urdf.write_text(_urdf_with_elbow_named(name), encoding="utf-8")
    message = new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", urdf,
                           file=str(urdf), line=21, words=(words, "rename the joint"))
    assert "\n" not in message and "\r" not in message


@pytest.mark.parametrize("label", ["double quote", "backslash", "newline", "non-ASCII"])
def test_hostile_joint_name_through_generate(project, label):
    name, words = HOSTILE_JOINT_NAMES[label]
    (project / URDF_REL).write_text(_urdf_with_elbow_named(name), encoding="utf-8")
    key = yaml.safe_dump(name, allow_unicode=False, default_style='"').strip()
    edit_yaml(project, "  elbow: 2", f"  {key}: 2")
    generate_rejected(project, file=YAML_REL, line=10, words=(words, "rename the joint in arm.urdf (line 21)"))


@pytest.mark.parametrize("option, value, words", [
    ("--vendor", "class", "C++ keyword"),
    ("--vendor", "namespace", "C++ keyword"),
    ("--vendor", "std", "clash with the C++ namespace"),
    ("--vendor", "rclcpp", "clash with the C++ namespace"),
    ("--robot", "int", "C++ keyword"),
    ("--robot", "delete", "C++ keyword"),
    ("--robot", "my__arm", "must not contain '__'"),
    ("--robot", "Arm", "lowercase letters"),
    ("--vendor", "acme corp", "lowercase letters"),
    ("--robot", "arm\"; system(\"rm -rf /", "lowercase letters"),
    ("--vendor", "common", "shared headers"),
    ("--vendor", "transport", "shared headers"),
    ("--vendor", "unitree_hg", "clash with the C++ namespace"),
    ("--vendor", "unitree_go", "robot_hardware_interface::unitree_go of rhi-gen's shared headers"),
    ("--vendor", "bounded", "robot_hardware_interface::bounded of rhi-gen's shared headers"),
    ("--vendor", "system", "the C library declares at global scope"),
    ("--vendor", "errno", "the C library declares at global scope"),
])
def test_vendor_or_robot_name_that_breaks_cpp_through_new(tmp_path, option, value, words):
    names = {"--vendor": "acme", "--robot": "arm", option: value}
    new_rejected(tmp_path / "proj", "--vendor", names["--vendor"], "--robot", names["--robot"],
                 "--urdf", HOSTILE / "arm.urdf", file=option, words=(words,))


def test_names_the_shared_headers_declare_in_the_package_namespace_are_refused_as_vendor():
    """robot_hardware_interface::<vendor> must not be one of the package namespace's own names: a
    nested namespace (the vendor's driver would land in it) or a function (a redeclaration error).
    The shared headers declare namespace-scope names at column 0 (ROS 2 style): collect them."""
    root = REPO / "rhi_gen"
    decl = re.compile(r"^(?!using |class |struct |enum |namespace |template|typedef |return |#|//|\}|\{)"
                      r"[A-Za-z_][\w:<>, ]*?[ *&]([a-z][a-z0-9_]*)\s*(?:\(|=|\[|\{|;)")
    names = set()
    for header in [*root.glob("cpp/common/*.hpp"), *root.glob("transports/*/*.hpp")]:
        for line in header.read_text(encoding="utf-8").splitlines():
            found = decl.match(line) or re.match(r"^namespace (\w+)$", line)
            if found and found.group(1) != "robot_hardware_interface":
                names.add(found.group(1))
    assert {"unitree_hg", "bounded"} <= names
    assert {n for n in names if vendor_problem(n) is None} == set()


@pytest.mark.parametrize("key, value, line, words", [
    ("vendor", "class", 1, "C++ keyword"),
    ("vendor", "std", 1, "clash with the C++ namespace"),
    ("robot", "struct", 2, "C++ keyword"),
    ("robot", "'2arm'", 2, "starting with a letter"),
    ("vendor", "common", 1, "shared headers"),
    ("vendor", "time", 1, "the C library declares at global scope"),
])
def test_vendor_or_robot_name_that_breaks_cpp_in_yaml(project, key, value, line, words):
    edit_yaml(project, f"{key}: {'acme' if key == 'vendor' else 'arm'}", f"{key}: {value}")
    generate_rejected(project, file=YAML_REL, line=line, key=key, words=(words,))


# ---------------------------------------------------------------- names that would escape the output folder
@pytest.mark.parametrize("option, value", [
    ("--vendor", "../x"), ("--vendor", "../../etc"), ("--vendor", "a/b"), ("--vendor", ".."),
    ("--robot", "../x"), ("--robot", "/ABS"), ("--robot", "x/../../y"), ("--robot", "~"),
])
def test_names_escaping_the_project_through_new(tmp_path, option, value):
    value = value.replace("/ABS", str(tmp_path / "evil"))
    names = {"--vendor": "acme", "--robot": "arm", option: value}
    new_rejected(tmp_path / "proj", "--vendor", names["--vendor"], "--robot", names["--robot"],
                 "--urdf", HOSTILE / "arm.urdf", file=option, words=("lowercase letters",))
    assert not (tmp_path / "evil").exists() and not (tmp_path / "evil.yaml").exists()
    assert not (tmp_path / "x").exists() and not (tmp_path / "x.yaml").exists()


@pytest.mark.parametrize("key, value", [
    ("vendor", "../../outside"), ("vendor", "/tmp"), ("robot", "../../../outside"), ("robot", "'/ABS'"),
])
def test_names_escaping_the_project_in_yaml(project, key, value):
    value = value.replace("/ABS", str(project.parent / "evil"))
    edit_yaml(project, f"{key}: {'acme' if key == 'vendor' else 'arm'}", f"{key}: {value}")
    generate_rejected(project, file=YAML_REL, line=1 if key == "vendor" else 2, key=key,
                      words=("lowercase letters",))
    assert not (project.parent / "evil").exists() and not (project.parent / "outside").exists()


# ---------------------------------------------------------------- motor indices
def test_duplicate_motor_index(project):
    edit_yaml(project, "elbow: 2", "elbow: 1")
    generate_rejected(project, file=YAML_REL, line=10, key="joint_map.elbow",
                      words=("motor index 1 is already used by 'shoulder_lift'",))


def test_motor_index_equal_to_motor_count(project):
    edit_yaml(project, "elbow: 2", "elbow: 3")
    generate_rejected(project, file=YAML_REL, line=10, key="joint_map.elbow",
                      words=("motor index 3 is out of range 0..2", "raise motor_count"))


def test_motor_index_far_beyond_motor_count(project):
    edit_yaml(project, "shoulder_pan: 0", "shoulder_pan: 99999999999999999999")
    generate_rejected(project, file=YAML_REL, line=8, key="joint_map.shoulder_pan", words=("out of range",))


def test_negative_motor_index(project):
    edit_yaml(project, "elbow: 2", "elbow: -1")
    generate_rejected(project, file=YAML_REL, line=10, key="joint_map.elbow", words=("out of range",))


def test_motor_index_that_is_not_a_number(project):
    edit_yaml(project, "elbow: 2", "elbow: '2'")
    generate_rejected(project, file=YAML_REL, line=10, key="joint_map.elbow", words=("whole number",))


def test_actuated_joint_left_out_of_the_map(project):
    edit_yaml(project, "  elbow: 2\n", "")
    generate_rejected(project, file=YAML_REL, line=7, key="joint_map", words=("'elbow'", "unmapped_joints"))


# ---------------------------------------------------------------- float type, transport
@pytest.mark.parametrize("value, words", [
    ("half", ("'half' is not supported", "float, double")),
    ("long double", ("'long double' is not supported",)),
    ("doubel", ("did you mean 'double'?",)),
    ("float32", ("did you mean 'float'?",)),
    ("64", ("'64' is not supported",)),
])
def test_float_type_other_than_float_or_double(project, value, words):
    edit_yaml(project, "float_type: double", f"float_type: {value}")
    generate_rejected(project, file=YAML_REL, line=6, key="float_type", words=words)


def test_unknown_transport_in_yaml(project):
    edit_yaml(project, "transport: generic_topics", "transport: generic_topic")
    generate_rejected(project, file=YAML_REL, line=4, key="transport",
                      words=("'generic_topic' is not supported", "did you mean 'generic_topics'?"))


def test_unknown_transport_through_new(tmp_path):
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", HOSTILE / "arm.urdf",
                 "--transport", "unitree_ddss", file="--transport",
                 words=("unknown transport 'unitree_ddss'", "did you mean 'unitree_dds'?"))


def test_transport_option_of_another_transport(project):
    (project / YAML_REL).write_text((project / YAML_REL).read_text() + "transport_options:\n  lowcmd_topic: rt/x\n")
    generate_rejected(project, file=YAML_REL, line=12, key="transport_options.lowcmd_topic", words=("unknown key",))


# ---------------------------------------------------------------- unknown keys, did you mean
@pytest.mark.parametrize("addition, line, key, hint", [
    ("motor_cont: 3\n", 11, "motor_cont", "did you mean 'motor_count'?"),
    ("jointmap: {}\n", 11, "jointmap", "did you mean 'joint_map'?"),
    ("parameters:\n  state_decimaton: 2\n", 12, "parameters.state_decimaton", "did you mean 'state_decimation'?"),
    ("imu:\n  frame: imu_link\n", 12, "imu.frame", "did you mean 'frame_id'?"),
    ("transport_options:\n  comand_topic: /cmd\n", 12, "transport_options.comand_topic",
     "did you mean 'command_topic'?"),
    ("colour: blue\n", 11, "colour", "allowed keys: vendor, robot"),
])
def test_unknown_yaml_key_suggests_the_closest(project, addition, line, key, hint):
    path = project / YAML_REL
    path.write_text(path.read_text() + addition)
    generate_rejected(project, file=YAML_REL, line=line, key=key, words=("unknown key", hint))


@pytest.mark.parametrize("value, words", [
    ("onwrite", ("'onwrite' is not supported", "did you mean 'on_write'?")),
    ("true", ("is not supported", "use one of: timer, on_write")),
    ("[timer]", ("must be a single value",)),
])
def test_command_writer_mode_is_timer_or_on_write(project, value, words):
    path = project / YAML_REL
    path.write_text(path.read_text() + f"parameters:\n  command_writer_mode: {value}\n")
    generate_rejected(project, file=YAML_REL, line=12, key="parameters.command_writer_mode", words=words)


def test_command_writer_mode_reaches_the_driver_and_the_description(project):
    """The YAML's mode becomes the driver's compiled-in default and the description's argument default."""
    path = project / YAML_REL
    path.write_text(path.read_text() + "parameters:\n  command_writer_mode: on_write\n")
    assert run_cli("generate", "--project", project).code == 0
    package = project / "generated" / PACKAGE
    source = (package / "src" / "acme" / "arm.cpp").read_text()
    assert source.count("CommandWriterMode::kOnWrite") == 1 and "kTimer" not in source
    xacro = (package / "description" / "arm.ros2_control.xacro").read_text()
    assert "command_writer_mode:='on_write'" in xacro
    assert '<param name="command_writer_mode">${command_writer_mode}</param>' in xacro


# ---------------------------------------------------------------- YAML that is not a mapping, empty files
@pytest.mark.parametrize("text, line, words", [
    ("- vendor: acme\n- robot: arm\n", 1, "top level is a list"),
    ("just a sentence\n", 1, "top level is a single value"),
    ("42\n", 1, "top level is a single value"),
    ("vendor: acme\n---\nrobot: arm\n", 3, "several YAML documents"),
    ("vendor: [acme\n", 2, "invalid YAML"),
    ("vendor: acme\n\trobot: arm\n", 2, "invalid YAML"),
])
def test_yaml_that_is_not_a_mapping(project, text, line, words):
    (project / YAML_REL).write_text(text)
    generate_rejected(project, file=YAML_REL, line=line, words=(words,))


@pytest.mark.parametrize("text", ["", "\n\n", "# only a comment\n"])
def test_empty_yaml(project, text):
    (project / YAML_REL).write_text(text)
    generate_rejected(project, file=YAML_REL, words=("file is empty",))


@pytest.mark.parametrize("text", ["", "   \n\n"])
def test_empty_urdf_through_generate(project, text):
    (project / URDF_REL).write_text(text)
    generate_rejected(project, file=URDF_REL, words=("file is empty",))


def test_empty_urdf_through_new(tmp_path):
    urdf = tmp_path / "empty.urdf"
    urdf.write_text("")
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", urdf,
                 file=str(urdf), words=("file is empty",))


def test_binary_file_as_urdf(project):
    (project / URDF_REL).write_bytes(bytes(range(256)) * 4)
    generate_rejected(project, file=URDF_REL, words=("not a text file",))


def test_yaml_that_is_not_utf8(project):
    (project / YAML_REL).write_bytes("vendor: acme\nrobot: \xe4rm\n".encode("latin-1"))
    generate_rejected(project, file=YAML_REL, words=("not UTF-8",))


# ---------------------------------------------------------------- very large URDFs
def chain_urdf(joints: int, *, name: str = "big", broken_at: int | None = None) -> str:
    """A serial chain of ``joints`` revolute joints, one element per line (3 lines per joint)."""
    out = ['<?xml version="1.0"?>', f'<robot name="{name}">', '  <link name="l0"/>']
    for i in range(1, joints + 1):
        out.append(f'  <link name="l{i}"/>')
        limit = 'lower="-1" upper="1"' if i != broken_at else 'lower="-1" upper="one"'
        out.append(f'  <joint name="j{i}" type="revolute"><parent link="l{i - 1}"/><child link="l{i}"/>')
        out.append(f'    <limit {limit} effort="10" velocity="2"/></joint>')
    out.append("</robot>")
    return "\n".join(out) + "\n"


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
def test_large_urdf_generates_and_compiles(tmp_path):
    """1200 joints: ``new`` generates every joint and the driver compiles. How long it takes is the
    benchmark's figure (benchmarks/bench_generate.py, `new` on a 1200-joint chain), never a verdict here."""
    urdf = tmp_path / "big.urdf"
    urdf.write_text(chain_urdf(1200))
    root = tmp_path / "proj"
    root.mkdir()
    result = run_cli("new", "--vendor", "acme", "--robot", "big", "--urdf", urdf, "--project", root)
    assert result.code == 0, result.err
    written = yaml.safe_load((root / "robots/acme/big.yaml").read_text())
    assert written["motor_count"] == 1200 and len(written["joint_map"]) == 1200
    syntax_check_driver(root / "generated" / PACKAGE, "acme", "big")


def test_large_urdf_error_past_line_65535_names_the_exact_line(tmp_path):
    urdf = tmp_path / "big.urdf"
    urdf.write_text(chain_urdf(25_000, broken_at=24_000))
    line = 3 + 3 * 24_000  # the <limit> line of joint 24000
    assert urdf.read_text().splitlines()[line - 1].strip().startswith('<limit lower="-1" upper="one"')
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "big", "--urdf", urdf,
                 file=str(urdf), line=line, words=("'j24000'", "is not a number"))


def test_large_urdf_too_many_joints_for_unitree(tmp_path):
    urdf = tmp_path / "big.urdf"
    urdf.write_text(chain_urdf(1200))
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "big", "--urdf", urdf,
                 "--transport", "unitree_dds", file=str(urdf), words=("1200 actuated joints", "35 motor slots"))


def test_urdf_with_more_joints_than_rhi_gen_drives(tmp_path):
    urdf = tmp_path / "huge.urdf"
    urdf.write_text(chain_urdf(4200))
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "huge", "--urdf", urdf,
                 file=str(urdf), words=("4200 actuated joints", "at most 4096"))


def test_yaml_motor_count_above_the_limit(project):
    edit_yaml(project, "motor_count: 3", "motor_count: 100000")
    generate_rejected(project, file=YAML_REL, line=5, key="motor_count", words=("out of range 1..4096",))


# -------------------------------------------------------- ros2_control's own rules (mimic, continuous, prismatic, tags)
def _description_joints(root: Path, robot: str) -> dict[str, etree._Element]:
    path = root / "generated" / PACKAGE / "description" / f"{robot}.ros2_control.xacro"
    tree = etree.parse(str(path))
    return {attribute(j, "name"): j for j in tree.iter("joint")}


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
def test_mimic_continuous_prismatic_and_an_existing_tag_follow_ros2_control(tmp_path):
    urdf = HOSTILE / "kinematics.urdf"
    root = tmp_path / "proj"
    root.mkdir()
    result = run_cli("new", "--vendor", "acme", "--robot", "mobile", "--urdf", urdf, "--project", root)
    assert result.code == 0, result.err
    written = yaml.safe_load((root / "robots/acme/mobile.yaml").read_text())
    # the mimic finger has no motor; every other movable joint has one, in URDF order
    assert list(written["joint_map"]) == ["left_wheel_joint", "right_wheel_joint", "lift_joint", "wrist_joint",
                                          "finger_left_joint"]
    joints = _description_joints(root, "mobile")
    assert set(joints) == set(written["joint_map"])  # no mimic, no fixed joint; all exist in the URDF

    def position_limits(name: str) -> tuple[float, float]:
        cmd = joints[name].find("command_interface[@name='position']")
        assert cmd is not None, name
        low, high = cmd.findtext("param[@name='min']"), cmd.findtext("param[@name='max']")
        assert low is not None and high is not None, name
        return float(low), float(high)

    for wheel in ("left_wheel_joint", "right_wheel_joint"):  # continuous: velocity-commanded, no position target
        assert joints[wheel].find("command_interface[@name='position']") is None, wheel
        assert joints[wheel].find("command_interface[@name='velocity']") is not None, wheel
        assert joints[wheel].find("state_interface[@name='position']") is not None, wheel
    assert position_limits("lift_joint") == (0.0, 0.6)  # prismatic: metres
    assert position_limits("wrist_joint") == (-2.9, 2.9)
    syntax_check_driver(root / "generated" / PACKAGE, "acme", "mobile")


def test_yaml_maps_a_mimic_joint(tmp_path):
    root = write_project(tmp_path / "proj", urdf_text=fixture_text("kinematics.urdf"), yaml_text=(
        "vendor: acme\nrobot: arm\nurdf: arm.urdf\ntransport: generic_topics\nmotor_count: 6\njoint_map:\n"
        "  left_wheel_joint: 0\n  right_wheel_joint: 1\n  lift_joint: 2\n  wrist_joint: 3\n"
        "  finger_left_joint: 4\n  finger_right_joint: 5\n"))
    generate_rejected(root, file=YAML_REL, line=12, key="joint_map.finger_right_joint",
                      words=("mimics 'finger_left_joint'", "no command interfaces", "remove it from joint_map"))


def test_existing_ros2_control_tag_names_a_joint_not_in_the_urdf(tmp_path):
    urdf = HOSTILE / "ros2_control_unknown_joint.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "mobile", "--urdf", urdf,
                 file=str(urdf), line=57, words=("'lift_jiont', which is not a joint of the URDF",))


def test_existing_ros2_control_tag_commands_a_mimic_joint(tmp_path):
    urdf = HOSTILE / "ros2_control_mimic_command.urdf"
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "mobile", "--urdf", urdf,
                 file=str(urdf), line=61, words=("mimic joint 'finger_right_joint'", "<command_interface>"))


def test_existing_ros2_control_tag_errors_name_the_urdf_in_generate(tmp_path):
    root = write_project(tmp_path / "proj", urdf_text=fixture_text("ros2_control_unknown_joint.urdf"), yaml_text=(
        "vendor: acme\nrobot: arm\nurdf: arm.urdf\ntransport: generic_topics\nmotor_count: 5\njoint_map:\n"
        "  left_wheel_joint: 0\n  right_wheel_joint: 1\n  lift_joint: 2\n  wrist_joint: 3\n"
        "  finger_left_joint: 4\n"))
    generate_rejected(root, file=URDF_REL, line=57, words=("'lift_jiont'",))


# ---------------------------------------------------------------- the installed command
def test_installed_command_exits_2_with_one_line(project):
    """The console script, in its own process: exit status 2, one line, no traceback, nothing written."""
    exe = Path(sys.executable).with_name("rhi-gen")
    assert exe.is_file(), f"{exe} missing: install rhi-gen into the test environment (pip install -e '.[test]')"
    edit_yaml(project, "elbow: 2", "elbow: 1")
    before = snapshot(project)
    proc = subprocess.run([str(exe), "generate", "--project", str(project)], capture_output=True, text=True,
                          env={k: v for k, v in os.environ.items() if k != "RHI_GEN_DEBUG"})
    result = CliResult(proc.returncode, proc.stdout, proc.stderr)
    assert_rejected(result, file=YAML_REL, line=10, key="joint_map.elbow", words=("already used",))
    assert snapshot(project) == before
