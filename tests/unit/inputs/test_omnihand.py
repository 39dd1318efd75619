"""hands: omnihand (the X2's OmniHands): what the YAML may say, and what it makes of the hand joints.

The test robot tests/cpp/harness/robots/agibot/x2_omnihand.yaml (the reference X2 with the ten OmniHand axes per
hand added by a self-written xacro) is the valid case; every refusal below is one edit of it. The facts (topics,
axis order, hand type) are tests/support/aimdk_facts.py's, read from AgiBot's AimDK independently of rhi_gen.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.scaffold import suggest_yaml
from rhi_gen.inputs.urdf_loader import load_urdf
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.render.bringup_views import start_controllers
from rhi_gen.render.views import controllers_view, xacro_view
from rhi_gen.transports.agibot_topics import AgibotTopicsOptions
from tests.support import aimdk_facts
from tests.support.models import model_of_yaml
from tests.support.repo import REPO

HARNESS = REPO / "tests/cpp/harness/robots/agibot"
OMNIHAND_YAML = (HARNESS / "x2_omnihand.yaml").read_text(encoding="utf-8")
HAND_JOINTS = [f"{aimdk_facts.OMNIHAND_SIDE_PREFIX[side]}{axis}_joint" for side in ("left", "right")
               for axis in aimdk_facts.OMNIHAND_AXES]


def omnihand_project(tmp_path: Path) -> Path:
    """The test robot's URDF xacro beside the reference X2 it includes."""
    shutil.copy(REPO / "robots/agibot/x2.urdf", tmp_path / "x2.urdf")
    shutil.copy(HARNESS / "x2_omnihand.urdf.xacro", tmp_path / "x2_omnihand.urdf.xacro")
    return tmp_path / "x2_omnihand.urdf.xacro"


def omnihand_yaml(tmp_path: Path, edit=lambda text: text) -> Path:
    omnihand_project(tmp_path)
    path = tmp_path / "x2_omnihand.yaml"
    path.write_text(edit(OMNIHAND_YAML), encoding="utf-8")
    return path


def test_hand_axes_follow_the_body_in_aimdk_order_and_take_position_targets_only(tmp_path):
    model = model_of_yaml(omnihand_yaml(tmp_path))
    assert model.hands == "omnihand" and model.motor_count == 51
    hands = sorted(model.hand_joints, key=lambda j: j.index)
    assert [j.name for j in hands] == HAND_JOINTS and [j.index for j in hands] == list(range(31, 51))
    assert all(j.command_mode == "position_target" and j.command_interfaces == ("position",) for j in hands)
    assert all(j.default_stiffness == 0.0 and j.default_damping == 0.0 for j in hands)
    body = [j for j in model.joints if j not in hands]
    assert len(body) == 31 and all(j.command_mode == "position" and "stiffness" in j.command_interfaces for j in body)
    options = model.transport_options
    assert isinstance(options, AgibotTopicsOptions)
    assert (options.hand_command_topic, options.hand_state_topic) == (aimdk_facts.HAND_COMMAND_TOPIC,
                                                                      aimdk_facts.HAND_STATE_TOPIC)
    assert options.hand_type == aimdk_facts.HAND_TYPES["NIMBLE_HANDS"]
    assert options.hand_axes == len(aimdk_facts.OMNIHAND_AXES)


def test_the_hands_get_a_position_controller_and_no_gain_controllers(tmp_path):
    model = model_of_yaml(omnihand_yaml(tmp_path))
    controllers = {c.name: [j.name for j in c.joints] for c in controllers_view(model).controllers}
    assert sorted(controllers["hand_position_controller"]) == sorted(HAND_JOINTS)
    assert not set(HAND_JOINTS) & set(controllers["forward_position_controller"])
    for gains in ("forward_stiffness_controller", "forward_damping_controller"):
        assert len(controllers[gains]) == 31 and not set(HAND_JOINTS) & set(controllers[gains])
    assert "hand_position_controller" in start_controllers(model)[0]


def test_the_description_gives_a_hand_axis_its_position_command_alone(tmp_path):
    view = xacro_view(model_of_yaml(omnihand_yaml(tmp_path)))
    by_name = {j.name: j for j in view.joints}
    for name in HAND_JOINTS:
        assert [i.name for i in by_name[name].command_interfaces] == ["position"], name
        assert "position target only" in by_name[name].comment
    assert [i.name for i in by_name["left_knee_joint"].command_interfaces] == [
        "position", "velocity", "stiffness", "damping", "effort"]


def _refused(tmp_path: Path, edit, key: str, *words: str) -> ConfigError:
    with pytest.raises(ConfigError) as caught:
        model_of_yaml(omnihand_yaml(tmp_path, edit))
    err = caught.value
    assert err.key == key and err.fix, (err.key, str(err))
    assert all(w in str(err) for w in words), str(err)
    return err


def test_motor_count_must_hold_the_groups_and_the_hands(tmp_path):
    err = _refused(tmp_path, lambda t: t.replace("motor_count: 51", "motor_count: 31"), "motor_count",
                   "groups hold 31 slots and the OmniHands 20")
    assert "motor_count: 51" in str(err.fix)


def test_every_hand_axis_must_be_mapped(tmp_path):
    err = _refused(tmp_path, lambda t: t.replace("  R_thumb_mcp_joint:", "  # R_thumb_mcp_joint:"), "joint_map",
                   "slot 43", "right hand's thumb_mcp axis")
    assert "R_thumb_mcp_joint: 43" in str(err.fix)


def test_a_hand_axis_takes_no_gains_or_command_mode(tmp_path):
    _refused(tmp_path, lambda t: t + "default_gains:\n  L_index_pip_joint: {stiffness: 1.0, damping: 0.1}\n",
             "default_gains.L_index_pip_joint", "position targets only")
    _refused(tmp_path, lambda t: t + "command_modes:\n  R_pinky_pip_joint: velocity\n",
             "command_modes.R_pinky_pip_joint", "position targets only")


def test_other_hands_and_hand_options_without_hands_are_refused(tmp_path):
    err = _refused(tmp_path, lambda t: t.replace("hands: omnihand", "hands: dex3"), "hands", "dex3")
    assert "omnihand" in str(err.fix)
    _refused(tmp_path, lambda t: t.replace("hands: omnihand", "hands: none").replace(
        "  take_control: true", "  hand_state_topic: /x/state\n  take_control: true"),
        "transport_options.hand_state_topic", "used only with hands: omnihand")


def test_an_omnihand_is_not_a_unitree_hand(tmp_path):
    g1 = (REPO / "robots/unitree/g1.yaml").read_text(encoding="utf-8")
    path = tmp_path / "g1.yaml"
    path.write_text(g1.replace("urdf: g1.urdf", f"urdf: {REPO / 'robots/unitree/g1.urdf'}") + "hands: omnihand\n",
                    encoding="utf-8")
    with pytest.raises(ConfigError, match="not the G1 Dex3-1's hand") as caught:
        load_config(path)
    assert caught.value.key == "hands"


def _new_yaml(tmp_path: Path, urdf: Path) -> Path:
    text = suggest_yaml(vendor="agibot", robot="x2", urdf=load_urdf(urdf), urdf_relative=str(urdf))
    path = tmp_path / "x2.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_new_drives_the_hands_of_an_x2_urdf_with_omnihands(tmp_path):
    """`rhi-gen new` on an X2 URDF with both OmniHands writes hands: omnihand, the body's groups and the hand axes
    after them."""
    model = model_of_yaml(_new_yaml(tmp_path, omnihand_project(tmp_path)))
    assert model.hands == "omnihand" and model.motor_count == 51
    assert [j.name for j in sorted(model.hand_joints, key=lambda j: j.index)] == HAND_JOINTS
    options = model.transport_options
    assert isinstance(options, AgibotTopicsOptions)
    assert [(g.name, g.size) for g in options.groups] == [("leg", 12), ("waist", 3), ("arm", 14), ("head", 2)]


def test_new_tells_an_x2_without_hands_how_to_add_them(tmp_path):
    path = _new_yaml(tmp_path, REPO / "robots/agibot/x2.urdf")
    text = path.read_text(encoding="utf-8")
    assert "hands: none" in text.splitlines() and "motor_count 51" in text
    assert all(len(line) <= 120 for line in text.splitlines())
    assert load_config(path).hands == "none"
