"""A description that already drives its joints with its own <ros2_control> tag.

`new` and `generate` accept it (exit 0, everything written) and print one warning per robot on
stderr: the tag's name and plugin, how many joints it covers with a few names, how many of them the
generated driver drives, and the choice (replace the tag with the generated macro, or keep it and do
not include the generated one). `check` and `diff` stay quiet and keep their exit codes. Real
descriptions from example-robot-data (xArm7: one tag; TIAGo Pro: three) and hostile variants.
"""
from __future__ import annotations

import importlib.metadata
import shutil
from pathlib import Path

import pytest

from tests.support import upstream_urdf
from tests.support.cli import assert_rejected, run_cli, snapshot
from tests.support.repo import HOSTILE
from tests.support.repo import URDF_FIXTURES as FIX

UPSTREAM_G1 = upstream_urdf.find("unitree_g1.urdf")  # the repository's copy (tests/data/upstream_urdf)
ANY = -1  # assert_rejected(line=ANY): some line number


def erd(path: str) -> Path:
    """A file of the example-robot-data package (robots/<path>); skip when it is not installed."""
    try:
        files = importlib.metadata.files("example-robot-data") or []
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("example-robot-data is not installed")
    hits = [f for f in files if str(f).endswith(f"example-robot-data/robots/{path}")]
    if not hits:
        pytest.skip(f"example-robot-data has no {path}")
    return Path(str(hits[0].locate()))


def warnings(err: str) -> list[str]:
    return [line for line in err.splitlines() if line.startswith("warning: ")]


def new(root: Path, vendor: str, robot: str, urdf: Path, *extra: str):
    root.mkdir(parents=True, exist_ok=True)
    result = run_cli("new", "--vendor", vendor, "--robot", robot, "--urdf", urdf, *extra, "--project", root)
    assert result.code == 0, result.err
    return result


XARM_WARNING = (
    'already has <ros2_control name="uf_robot_hardware/UFRobotSystemHardware"> with plugin '
    "uf_robot_hardware/UFRobotSystemHardware for 7 joints (joint1, joint2, joint3 and 4 more); the generated "
    "description/xarm7.ros2_control.xacro drives the same joints with plugin "
    "robot_hardware_interface/uf/XARM7HardwareInterface -> "
    "replace that tag with the generated macro, or keep the tag and do not include the generated macro; never "
    "both (two plugins would claim the same joint interfaces)")


def test_new_on_xarm7_warns_once_and_writes_everything(tmp_path):
    urdf = erd("xarm_description/urdf/xarm7.urdf")
    result = new(tmp_path / "proj", "uf", "xarm7", urdf)
    assert result.err.splitlines() == [f"warning: {urdf}:26: {XARM_WARNING}"]
    assert "warning" not in result.out
    package = tmp_path / "proj/generated/robot_hardware_interface"
    assert (package / "description/xarm7.ros2_control.xacro").is_file()
    assert (package / "src/uf/xarm7.cpp").is_file()
    assert (tmp_path / "proj/robots/uf/xarm7.yaml").is_file()


def test_new_on_tiago_pro_sums_up_three_tags_in_one_line(tmp_path):
    urdf = erd("tiago_pro_description/robots/tiago_pro.urdf")
    result = new(tmp_path / "proj", "pal", "tiago_pro", urdf)
    (line,) = result.err.splitlines()
    assert line.startswith(f"warning: {urdf}:2366: already has 3 <ros2_control> tags "
                           '("ros2_control_tiago_pro_system_can", "ros2_control_tiago_pro_system_dynamixel", '
                           '"ros2_control_tiago_pro_system_ethercat") with plugin robot_control/RobotControl for 33 '
                           "joints (wheel_front_right_joint, wheel_front_left_joint, wheel_rear_right_joint and 30 "
                           "more)")
    assert "drives 23 of them (" in line and " -> replace that tag" in line


@pytest.fixture
def tagged_project(tmp_path: Path) -> Path:
    """xArm7 (tag), the rrbot fixture (two tags, two plugins) and a plain arm (no tag), all generated."""
    root = tmp_path / "proj"
    robots = root / "robots" / "acme"
    robots.mkdir(parents=True)
    shutil.copy(erd("xarm_description/urdf/xarm7.urdf"), robots / "xarm7.urdf")
    shutil.copy(FIX / "existing_ros2_control.urdf", robots / "rrbot.urdf")
    shutil.copy(FIX / "simple_arm.urdf", robots / "arm.urdf")
    for robot in ("xarm7", "rrbot", "arm"):
        new(root, "acme", robot, robots / f"{robot}.urdf")
    return root


def test_generate_warns_once_per_robot_with_a_tag(tagged_project):
    result = run_cli("generate", "--project", tagged_project)
    assert result.code == 0, result.err
    lines = result.err.splitlines()
    assert lines == warnings(result.err) and len(lines) == 2, result.err  # xarm7 and rrbot, once each
    assert lines[0].startswith("warning: robots/acme/rrbot.urdf:22: already has 2 <ros2_control> tags "
                               '("RRBotSystem" with plugin ros2_control_demo_hardware/RRBotSystemPositionOnlyHardware, '
                               '"GazeboSystem" with plugin gazebo_ros2_control/GazeboSystem) for 2 joints (joint1, '
                               "joint2); the generated description/rrbot.ros2_control.xacro drives the same joints "
                               "with plugin robot_hardware_interface/acme/RrbotHardwareInterface -> ")
    assert lines[1].startswith("warning: robots/acme/xarm7.urdf:26: already has <ros2_control name=")
    assert "summary:" in result.out and "warning" not in result.out


def test_generate_one_robot_warns_for_that_robot_only(tagged_project):
    assert warnings(run_cli("generate", "arm", "--project", tagged_project).err) == []
    only = warnings(run_cli("generate", "xarm7", "--project", tagged_project).err)
    assert len(only) == 1 and only[0].startswith("warning: robots/acme/xarm7.urdf:26:")


def test_generate_dry_run_warns_too(tagged_project):
    result = run_cli("generate", "--dry-run", "--project", tagged_project)
    assert result.code == 0 and len(warnings(result.err)) == 2


def test_check_and_diff_stay_quiet(tagged_project):
    result = run_cli("check", "--project", tagged_project)
    assert result.code == 0 and result.err == "" and "warning" not in result.out
    result = run_cli("diff", "--project", tagged_project)
    assert result.code == 0 and "warning" not in result.err + result.out
    # a stale robot: check still exits 1 with its usual lines, and no warning
    yml = tagged_project / "robots/acme/xarm7.yaml"
    yml.write_text(yml.read_text().replace("state_decimation: 1", "state_decimation: 2"))
    result = run_cli("check", "--project", tagged_project)
    assert result.code == 1 and "warning" not in result.err + result.out
    result = run_cli("diff", "--project", tagged_project)
    assert result.code == 1 and "warning" not in result.err + result.out


def test_bad_input_is_one_error_line_without_the_warning(tagged_project):
    yml = tagged_project / "robots/acme/xarm7.yaml"
    text = yml.read_text()
    assert text.count('"joint2": 1') == 1
    yml.write_text(text.replace('"joint2": 1', '"joint2": 0'))
    before = snapshot(tagged_project)
    assert_rejected(run_cli("generate", "--project", tagged_project), file="robots/acme/xarm7.yaml", line=ANY,
                    key="joint_map.joint2", words=("already used by",))
    assert snapshot(tagged_project) == before



def test_new_refused_for_a_clash_says_nothing_about_the_tag(tagged_project):
    result = run_cli("new", "--vendor", "other", "--robot", "xarm7", "--urdf",
                     tagged_project / "robots/acme/xarm7.urdf", "--project", tagged_project)
    assert_rejected(result, file="--robot", words=("already used by robots/acme/xarm7.yaml",))


# ---------------------------------------------------------------- when there is nothing to choose: no warning
def _with_tag(plugin: str, joints: list[str]) -> str:
    tag = (f'  <ros2_control name="Mine" type="system">\n    <hardware><plugin>{plugin}</plugin></hardware>\n'
           + "".join(f'    <joint name="{j}"><command_interface name="position"/>'
                     '<state_interface name="position"/></joint>\n' for j in joints)
           + "  </ros2_control>\n</robot>")
    return (FIX / "simple_arm.urdf").read_text().replace("</robot>", tag)


def test_a_tag_with_the_generated_plugin_is_the_generated_macro(tmp_path):
    """The description already includes the generated macro (docs/adding-a-robot.md, step 4): nothing to warn about."""
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(_with_tag("robot_hardware_interface/acme/ArmHardwareInterface", ["shoulder_pan", "elbow"]))
    assert new(tmp_path / "proj", "acme", "arm", urdf).err == ""


def test_a_tag_with_the_plugin_name_before_the_package_namespace_says_what_to_write(tmp_path):
    """Migration: acme/ArmHardwareInterface became robot_hardware_interface/acme/ArmHardwareInterface."""
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(_with_tag("acme/ArmHardwareInterface", ["shoulder_pan", "elbow"]))
    err = new(tmp_path / "proj", "acme", "arm", urdf).err
    assert err.count("warning:") == 1, err
    assert ('names plugin acme/ArmHardwareInterface, which rhi-gen now generates as '
            'robot_hardware_interface/acme/ArmHardwareInterface') in err, err
    assert "write <plugin>robot_hardware_interface/acme/ArmHardwareInterface</plugin> in that tag" in err, err


def test_a_tag_on_joints_the_driver_leaves_alone(tmp_path):
    """Another hardware component for a joint listed under unmapped_joints: two components, no overlap."""
    root = tmp_path / "proj"
    robots = root / "robots" / "acme"
    robots.mkdir(parents=True)
    shutil.copy(HOSTILE / "kinematics.urdf", robots / "mobile.urdf")
    (robots / "mobile.yaml").write_text(
        "vendor: acme\nrobot: mobile\nurdf: mobile.urdf\ntransport: generic_topics\nmotor_count: 4\njoint_map:\n"
        "  left_wheel_joint: 0\n  right_wheel_joint: 1\n  wrist_joint: 2\n  finger_left_joint: 3\n"
        "unmapped_joints: [lift_joint]\n")
    result = run_cli("generate", "--project", root)
    assert result.code == 0 and result.err == "", result.err
    # mapping lift_joint as well makes the tag and the generated macro overlap on it
    yml = robots / "mobile.yaml"
    yml.write_text(yml.read_text().replace("unmapped_joints: [lift_joint]\n", "  lift_joint: 4\n")
                   .replace("motor_count: 4", "motor_count: 5"))
    (line,) = run_cli("generate", "--project", root).err.splitlines()
    assert line.startswith('warning: robots/acme/mobile.urdf:55: already has <ros2_control name="SimSystem"> with '
                           "plugin mock_components/GenericSystem for 2 joints (lift_joint, finger_right_joint); the "
                           "generated description/mobile.ros2_control.xacro drives 1 of them (lift_joint) with")


def test_a_description_without_a_tag_gives_no_warning(tmp_path):
    urdf = UPSTREAM_G1 if UPSTREAM_G1 is not None else FIX / "simple_arm.urdf"
    assert new(tmp_path / "proj", "unitree", "g1", urdf).err == ""


def test_a_tag_in_a_xacro_is_named_without_a_misleading_line(tmp_path):
    xacro = tmp_path / "arm.urdf.xacro"
    text = _with_tag("fake_components/GenericSystem", ["shoulder_pan"])
    xacro.write_text(text.replace('<robot name="', '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="', 1))
    (line,) = new(tmp_path / "proj", "acme", "arm", xacro).err.splitlines()
    assert line.startswith(f'warning: {xacro}: already has <ros2_control name="Mine"> with plugin '
                           "fake_components/GenericSystem in the xacro-expanded description for 1 joint "
                           "(shoulder_pan); the generated description/arm.ros2_control.xacro drives the same joints")


def test_inspect_lists_the_tag_and_the_choice():
    result = run_cli("inspect", "--urdf", FIX / "existing_ros2_control.urdf")
    assert result.code == 0 and result.err == ""
    assert ("existing <ros2_control name='RRBotSystem'> plugin ros2_control_demo_hardware/"
            "RRBotSystemPositionOnlyHardware: 2 joints (joint1, joint2)") in result.out
    assert "replace the existing tag with it, or keep the tag and do not include the macro" in result.out
