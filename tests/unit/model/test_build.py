"""Cross-checks between the vendor YAML and the URDF, and the names the model decides."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from rhi_gen.assemble.robot_model import build_model
from rhi_gen.errors import ConfigError
from rhi_gen.inputs.urdf_loader import load_urdf, parse_urdf_bytes
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.model.config import ARMATURE_DEFAULT
from rhi_gen.model.naming import joint_name_problem
from tests.support.repo import URDF_FIXTURES as FIXTURES


def model_for(tmp_path: Path, urdf: Path, body: str, **head):
    vendor = head.get("vendor", "acme")
    robot = head.get("robot", "arm")
    yml = tmp_path / "robot.yaml"
    yml.write_text(textwrap.dedent(f"""\
        vendor: {vendor}
        robot: {robot}
        urdf: {urdf}
        transport: {head.get('transport', 'generic_topics')}
        motor_count: {head.get('motor_count', 3)}
        """) + textwrap.dedent(body), encoding="utf-8")
    cfg = load_config(yml)
    return build_model(cfg, load_urdf(cfg.urdf), yaml_path=yml, project_root=tmp_path)


ARM_MAP = """\
joint_map:
  shoulder_pan: 2
  shoulder_lift: 0
  elbow: 1
"""


def test_model_keeps_urdf_order_and_yaml_indices(tmp_path):
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP)
    assert [(j.name, j.index) for j in m.joints] == [("shoulder_pan", 2), ("shoulder_lift", 0), ("elbow", 1)]
    assert [j.name for j in m.joints_by_index] == ["shoulder_lift", "elbow", "shoulder_pan"]
    assert m.slot_names == ("shoulder_lift", "elbow", "shoulder_pan")
    assert (m.class_name, m.plugin_name, m.node_name) == ("ArmHardwareInterface",
                                                          "robot_hardware_interface/acme/ArmHardwareInterface",
                                                          "arm_hardware_interface")
    assert m.provenance.yaml_path == "robot.yaml"
    assert not Path(m.provenance.urdf_path).is_absolute()
    assert len(m.provenance.urdf_sha256) == 64


def test_pascal_names_keep_model_codes_upper(tmp_path):
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP, robot="pm01")
    assert (m.robot_pascal, m.robot_upper, m.class_name) == ("PM01", "PM01", "PM01HardwareInterface")
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP, robot="my_arm")
    assert (m.robot_pascal, m.robot_upper) == ("MyArm", "MY_ARM")


def test_joint_not_in_urdf_suggests_the_closest(tmp_path):
    with pytest.raises(ConfigError) as info:
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP.replace("elbow:", "elbw:"))
    err = info.value
    assert err.key == "joint_map.elbw" and err.line == 9
    assert "did you mean 'elbow'" in str(err)


def test_unmapped_actuated_joint_is_an_error_unless_listed(tmp_path):
    body = "joint_map:\n  shoulder_pan: 0\n  shoulder_lift: 1\n"
    with pytest.raises(ConfigError, match=r"1 actuated joint.*'elbow'.*unmapped_joints"):
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", body)
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", body + "unmapped_joints: [elbow]\n")
    assert m.unmapped_joints == ("elbow",) and len(m.joints) == 2


def test_fixed_joint_cannot_be_mapped(tmp_path):
    with pytest.raises(ConfigError, match="fixed joint"):
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP + "  tool_flange: 3\n",
                  motor_count=4)


def test_mimic_joint_cannot_be_mapped_and_is_recorded(tmp_path):
    body = "joint_map:\n  wrist: 0\n  left_finger_joint: 1\n  right_finger_joint: 2\n"
    with pytest.raises(ConfigError, match="mimics 'left_finger_joint'"):
        model_for(tmp_path, FIXTURES / "mimic_gripper.urdf", body)
    m = model_for(tmp_path, FIXTURES / "mimic_gripper.urdf",
                  "joint_map:\n  wrist: 0\n  left_finger_joint: 1\n", motor_count=2)
    assert set(m.mimic_joints) == {"right_finger_joint", "thumb_joint"}
    assert [j.name for j in m.joints] == ["wrist", "left_finger_joint"]


def test_imu_frame_must_be_a_link(tmp_path):
    with pytest.raises(ConfigError, match="not a link") as info:
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP + "imu: {frame_id: imu_lnk}\n")
    assert info.value.key == "imu.frame_id"


def test_default_imu_frame_is_a_real_link(tmp_path):
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP)
    assert m.imu.frame_id in [line.split('"')[1] for line in (FIXTURES / "simple_arm.urdf").read_text().splitlines()
                              if "<link name=" in line]


def test_no_actuated_joints(tmp_path):
    urdf = tmp_path / "fixed.urdf"
    urdf.write_text('<robot name="r"><link name="a"/><link name="b"/>'
                    '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>')
    with pytest.raises(ConfigError, match="fixed joint"):
        model_for(tmp_path, urdf, "joint_map:\n  j: 0\n", motor_count=1)


@pytest.mark.parametrize("name, ok", [
    ("left_knee_joint", True), ("J00_HIP_PITCH_L", True), ("arm/joint-1.a", True),
    ('quote"d', False), ("back\\slash", False), ("new\nline", False), ("ümlaut", False), ("sp ace", False),
    ("<tag>", False), ("amp&", False), ("", False), ("x" * 129, False),
])
def test_joint_name_policy(name, ok):
    assert (joint_name_problem(name) is None) == ok


def test_hostile_joint_name_is_rejected_with_urdf_line(tmp_path):
    urdf = tmp_path / "q.urdf"
    urdf.write_text('<robot name="r">\n<link name="a"/>\n<link name="b"/>\n'
                    '<joint name="kn&quot;ee" type="continuous"><parent link="a"/><child link="b"/></joint>\n'
                    '</robot>\n')
    with pytest.raises(ConfigError) as info:
        model_for(tmp_path, urdf, "joint_map:\n  'kn\"ee': 0\n", motor_count=1)
    assert "contains the character '\"'" in str(info.value) and "line 4" in str(info.value)


def test_parse_bytes_and_model_are_deterministic(tmp_path):
    a = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP)
    b = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP)
    assert a == b
    robot = parse_urdf_bytes((FIXTURES / "simple_arm.urdf").read_bytes(), source="x")
    assert [j.name for j in robot.actuated_joints] == ["shoulder_pan", "shoulder_lift", "elbow"]


def _urdf_with_tag(tmp_path: Path, tag_joint: str, command: bool = True) -> Path:
    urdf = tmp_path / "rc.urdf"
    cmd = '<command_interface name="position"/>' if command else ""
    urdf.write_text(textwrap.dedent(f"""\
        <robot name="r">
          <link name="a"/><link name="b"/><link name="c"/>
          <joint name="j1" type="revolute"><parent link="a"/><child link="b"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
          <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><mimic joint="j1"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
          <ros2_control name="Existing" type="system">
            <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
            <joint name="{tag_joint}">{cmd}<state_interface name="position"/></joint>
          </ros2_control>
        </robot>
        """))
    return urdf


def test_existing_ros2_control_joint_must_exist(tmp_path):
    from rhi_gen.errors import UrdfError

    with pytest.raises(UrdfError, match="'ghost', which is not a joint") as info:
        model_for(tmp_path, _urdf_with_tag(tmp_path, "ghost"), "joint_map:\n  j1: 0\n", motor_count=1)
    assert info.value.line == 9


def test_existing_ros2_control_mimic_joint_takes_no_commands(tmp_path):
    from rhi_gen.errors import UrdfError

    with pytest.raises(UrdfError, match="mimic joint 'j2' command"):
        model_for(tmp_path, _urdf_with_tag(tmp_path, "j2"), "joint_map:\n  j1: 0\n", motor_count=1)
    m = model_for(tmp_path, _urdf_with_tag(tmp_path, "j2", command=False), "joint_map:\n  j1: 0\n", motor_count=1)
    assert m.mimic_joints == ("j2",)


# ---------------------------------------------------------------- armatures
def test_armatures_default_and_are_read_joint_by_joint(tmp_path):
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP)
    assert [j.armature for j in m.joints] == [ARMATURE_DEFAULT] * 3
    m = model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP + "armatures: {elbow: 0.002, shoulder_pan: 0}\n")
    assert [(j.name, j.armature) for j in m.joints] == [("shoulder_pan", 0.0), ("shoulder_lift", ARMATURE_DEFAULT),
                                                        ("elbow", 0.002)]


@pytest.mark.parametrize(("body", "key", "message", "fix"), [
    ("armatures: {elbow: -0.1}\n", "armatures.elbow", "must be a number from 0 to 100, got '-0.1'", "kg*m^2"),
    ("armatures: {elbow: 1000}\n", "armatures.elbow", "must be a number from 0 to 100", "e.g. 0.01"),
    ("armatures: {elbow: heavy}\n", "armatures.elbow", "must be a number from 0 to 100, got 'heavy'", "kg*m^2"),
    ("armatures: {elbw: 0.01}\n", "armatures.elbw", "'elbw' is not a joint of joint_map", "did you mean 'elbow'?"),
    ("armatures: 0.01\n", "armatures", "must be a mapping", "{knee_joint: 0.02}"),
])
def test_bad_armatures_are_one_line_with_the_yaml_line_and_a_fix(tmp_path, body, key, message, fix):
    with pytest.raises(ConfigError) as info:
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP + body)
    err = info.value
    assert err.key == key and err.line == 10, (err.key, err.line)
    assert message in err.message and fix in (err.fix or ""), str(err)
    assert "\n" not in str(err)


# ---------------------------------------------------------------- initial_positions
def test_initial_positions_default_to_zero_clamped_into_the_limits(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text((FIXTURES / "simple_arm.urdf").read_text().replace('lower="-2.5" upper="2.5"',
                                                                       'lower="0.2" upper="2.5"'))
    m = model_for(tmp_path, urdf, ARM_MAP)
    assert [(j.name, j.initial_position) for j in m.joints] == [("shoulder_pan", 0.0), ("shoulder_lift", 0.0),
                                                                ("elbow", 0.2)]
    m = model_for(tmp_path, urdf, ARM_MAP + "initial_positions: {elbow: 1.25, shoulder_pan: -3}\n")
    assert [j.initial_position for j in m.joints] == [-3.0, 0.0, 1.25]


@pytest.mark.parametrize(("body", "key", "message", "fix"), [
    ("initial_positions: {elbow: 2.6}\n", "initial_positions.elbow",
     "'elbow': 2.6 is outside the URDF limits [-2.5, 2.5]", "inside the limits, e.g. 0"),
    ("initial_positions: {elbw: 0.0}\n", "initial_positions.elbw", "'elbw' is not a joint of joint_map",
     "did you mean 'elbow'?"),
    ("initial_positions: {elbow: .nan}\n", "initial_positions.elbow", "must be a finite number", "e.g. 0.0"),
    ("initial_positions: {elbow: .inf}\n", "initial_positions.elbow", "must be a finite number", "in rad"),
    ("initial_positions: {elbow: up}\n", "initial_positions.elbow", "must be a finite number, got 'up'", "in rad"),
    ("initial_positions: [0.0]\n", "initial_positions", "must be a mapping", "{knee_joint: 0.3}"),
])
def test_bad_initial_positions_are_one_line_with_the_yaml_line_and_a_fix(tmp_path, body, key, message, fix):
    with pytest.raises(ConfigError) as info:
        model_for(tmp_path, FIXTURES / "simple_arm.urdf", ARM_MAP + body)
    err = info.value
    assert err.key == key and err.line == 10, (err.key, err.line)  # line 10: initial_positions
    assert message in err.message and fix in (err.fix or ""), str(err)
    assert "\n" not in str(err)
