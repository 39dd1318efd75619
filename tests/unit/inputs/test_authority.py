"""authority: upper_body (Unitree's arm SDK): what the YAML may say, and what it makes of the joints.

Facts (unitree_sdk2 21d0a3b): example/g1/high_level/g1_arm7_sdk_dds_example.cpp publishes hg LowCmd_
on "rt/arm_sdk" with the blend weight in motor_cmd[kNotUsedJoint = 29].q and commands the 14 arm and 3
waist joints; h1_2_arm_sdk_dds_example.cpp uses kNotUsedJoint = 27.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.urdf_loader import load_urdf
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.render.cpp_layout import fold_cpp
from rhi_gen.render.fake_robot_views import has_fake_robot
from rhi_gen.render.views import controllers_view
from rhi_gen.transports.unitree_dds.options import UnitreeDdsOptions
from rhi_gen.transports.unitree_dds.protocol import ARM_SDK_TOPIC, ARM_SDK_WEIGHT_SLOT
from tests.support.models import model_of_yaml
from tests.support.repo import REPO

G1_YAML = (REPO / "robots/unitree/g1.yaml").read_text(encoding="utf-8")
# The 17 joints the SDK's arm example commands (arm_joints of g1_arm7_sdk_dds_example.cpp).
ARM_SDK_JOINTS = {f"{side}_{part}_joint" for side in ("left", "right") for part in (
    "shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_roll", "wrist_pitch", "wrist_yaw")} | {
    "waist_yaw_joint", "waist_roll_joint", "waist_pitch_joint"}


def g1_yaml(tmp_path: Path, *, head: str = "authority: upper_body\n", options: str = "", robot: str = "g1",
            release: bool = False) -> Path:
    text = G1_YAML.replace("urdf: g1.urdf", f"urdf: {REPO / 'robots/unitree/g1.urdf'}")
    text = text.replace("robot: g1\n", f"robot: {robot}\n{head}")
    text = text.replace("  release_motion_control: false\n", f"  release_motion_control: {str(release).lower()}\n"
                        + options)
    path = tmp_path / "g1.yaml"
    path.write_text(text, encoding="utf-8")
    return path




def test_upper_body_g1_commands_exactly_the_arm_sdk_joints(tmp_path):
    model = model_of_yaml(g1_yaml(tmp_path))
    assert model.authority == "upper_body"
    assert {j.name for j in model.commanded_joints} == ARM_SDK_JOINTS
    legs = [j for j in model.joints if j.command_mode == "state"]
    assert len(legs) == 12 and all(j.command_interfaces == () for j in legs)
    assert all(j.default_stiffness == 0.0 and j.default_damping == 0.0 for j in legs)
    options = model.transport_options
    assert isinstance(options, UnitreeDdsOptions)
    assert options.upper_body and options.arm_sdk_topic == ARM_SDK_TOPIC == "rt/arm_sdk"
    assert options.arm_sdk_weight_slot == ARM_SDK_WEIGHT_SLOT["g1"] == 29
    assert options.arm_sdk_ramp_s == 2.0
    controlled = {name for c in controllers_view(model).controllers for name in (j.name for j in c.joints)}
    assert controlled == ARM_SDK_JOINTS
    assert has_fake_robot(model)  # it plays the balance controller too


def test_full_authority_keeps_every_joint_commanded(tmp_path):
    model = model_of_yaml(g1_yaml(tmp_path, head=""))
    assert model.authority == "full" and len(model.commanded_joints) == 29
    options = model.transport_options
    assert isinstance(options, UnitreeDdsOptions) and not options.upper_body


def test_options_are_read(tmp_path):
    path = g1_yaml(tmp_path, options="  arm_sdk_topic: rt/my_arm_sdk\n  arm_sdk_ramp_s: 0.5\n")
    options = load_config(path).transport_options
    assert isinstance(options, UnitreeDdsOptions)
    assert options.arm_sdk_topic == "rt/my_arm_sdk" and options.arm_sdk_ramp_s == 0.5


@pytest.mark.parametrize(("head", "options", "robot", "release", "words"), [
    ("authority: upper_body\n", "", "my_g1", False, "does not know which LowCmd_ slot"),
    ("authority: upper_body\n", "  arm_sdk_weight_slot: 3\n", "g1", False, "joint_map drives a joint"),
    ("authority: upper_body\n", "  arm_sdk_ramp_s: 0.0\n", "g1", False, "from 0.1 to 60 seconds"),
    ("authority: upper_body\n", "  arm_sdk_weight_slot: 35\n", "g1", False, "arm_sdk_weight_slot"),
    ("", "  arm_sdk_ramp_s: 1.0\n", "g1", False, "used only with authority: upper_body"),
    ("authority: arms\n", "", "g1", False, "'arms' is not supported"),
    ("authority: upper_body\n", "", "g1", True, "would stop the robot's own controller"),
])
def test_bad_authority_is_one_line_naming_the_fix(tmp_path, head, options, robot, release, words):
    with pytest.raises(ConfigError) as info:
        load_config(g1_yaml(tmp_path, head=head, options=options, robot=robot, release=release))
    message = str(info.value)
    assert words in message and "g1.yaml:" in message and "\n" not in message and "->" in message


def test_upper_body_needs_hg_messages(tmp_path):
    text = (REPO / "tests/cpp/harness/robots/unitree/go2w.yaml").read_text(encoding="utf-8")
    path = tmp_path / "go2w.yaml"
    path.write_text(text.replace("robot: go2w\n", "robot: go2w\nauthority: upper_body\n"), encoding="utf-8")
    with pytest.raises(ConfigError, match="takes hg messages"):
        load_config(path)


@pytest.mark.parametrize(("robot", "words"), [
    ("agibot/x2", "offers no joint-level control of the arms"), ("engineai/pm01", "commands the whole robot")])
def test_other_transports_refuse_upper_body(tmp_path, robot, words):
    text = (REPO / "robots" / f"{robot}.yaml").read_text(encoding="utf-8")
    name = robot.split("/")[1]
    text = text.replace(f"robot: {name}\n", f"robot: {name}\nauthority: upper_body\n")
    path = tmp_path / f"{name}.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError, match=words) as caught:
        load_config(path)
    assert caught.value.fix


def test_a_template_argument_list_folds_at_its_bracket():
    """uncrustify indents what follows a comma between template arguments twice: break at the "<"."""
    line = "using G1UpperBodyMotorCommand = robot_hardware_interface::MotorCommand<G1_UPPER_BODY_NUM_MOTOR, float>;"
    assert fold_cpp(line).split("\n") == [
        "using G1UpperBodyMotorCommand = robot_hardware_interface::MotorCommand<",
        "  G1_UPPER_BODY_NUM_MOTOR, float>;"]


@pytest.mark.parametrize(("robot", "suggested"), [("g1", True), ("h1_2", True), ("go2", False), ("my_g1", False)])
def test_new_spells_out_authority_where_the_arm_sdk_is_known(robot, suggested):
    from rhi_gen import transports

    lines = transports.get("unitree_dds").suggest_authority(transports.known_robot("unitree", robot))
    assert ("authority: full" in lines) == suggested
    assert all(line.startswith("#") or line == "authority: full" for line in lines)


def test_new_writes_a_g1_yaml_that_loads_with_full_authority(tmp_path):
    from rhi_gen.inputs.scaffold import suggest_yaml

    text = suggest_yaml(vendor="unitree", robot="g1", urdf=load_urdf(REPO / "robots/unitree/g1.urdf"),
                        urdf_relative=str(REPO / "robots/unitree/g1.urdf"))
    path = tmp_path / "g1.yaml"
    path.write_text(text, encoding="utf-8")
    assert "authority: full" in text.splitlines() and load_config(path).authority == "full"
    path.write_text(text.replace("authority: full", "authority: upper_body"), encoding="utf-8")
    assert model_of_yaml(path).authority == "upper_body"
