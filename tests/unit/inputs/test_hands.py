"""hands: dex3 (the G1's Dex3-1 hands): what the YAML may say, and what it makes of the hand joints.

The test robot tests/cpp/harness/robots/unitree/g1_dex3.yaml (Unitree's G1 URDF with hands) is the valid case;
every refusal below is one edit of it. The facts (topics, motor order) are tests/support/dex3_facts.py's,
read from unitree_sdk2 independently of rhi_gen.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.scaffold import suggest_yaml
from rhi_gen.inputs.urdf_loader import load_urdf
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.model import TransportOptions
from rhi_gen.render.bringup_views import start_controllers
from rhi_gen.render.views import controllers_view
from rhi_gen.transports import HandSuggestion, get
from rhi_gen.transports.unitree_dds.options import UnitreeDdsOptions
from rhi_gen.typed_yaml.validator import Validator
from tests.support import dex3_facts
from tests.support.models import model_of_yaml
from tests.support.repo import REPO

HARNESS = REPO / "tests/cpp/harness/robots/unitree"
DEX3_YAML = (HARNESS / "g1_dex3.yaml").read_text(encoding="utf-8")
HAND_JOINTS = [dex3_facts.joint_name(side, m) for side in dex3_facts.SIDES
               for m in range(dex3_facts.MOTORS_PER_HAND)]


def dex3_yaml(tmp_path: Path, edit=lambda text: text) -> Path:
    text = DEX3_YAML.replace("urdf: g1_dex3.urdf", f"urdf: {(HARNESS / 'g1_dex3.urdf').resolve()}")
    path = tmp_path / "g1_dex3.yaml"
    path.write_text(edit(text), encoding="utf-8")
    return path




def test_dex3_hand_motors_follow_the_body_in_the_sdk_order(tmp_path):
    model = model_of_yaml(dex3_yaml(tmp_path))
    assert model.hands == "dex3" and model.motor_count == 49
    slots = {j.name: j.index for j in model.hand_joints}
    assert list(slots) and sorted(slots, key=lambda name: slots[name]) == HAND_JOINTS
    assert sorted(slots.values()) == list(range(35, 49))
    options = model.transport_options
    assert isinstance(options, UnitreeDdsOptions)
    for side in dex3_facts.SIDES:
        assert options.hand_topics(side) == (dex3_facts.COMMAND_TOPIC.format(side=side),
                                             dex3_facts.STATE_TOPIC.format(side=side))
    # Every hand joint is position-commanded with the full PD command, like the body's.
    assert all(j.command_mode == "position" and "stiffness" in j.command_interfaces for j in model.hand_joints)


def test_the_hands_get_their_own_position_controller(tmp_path):
    model = model_of_yaml(dex3_yaml(tmp_path))
    controllers = {c.name: [j.name for j in c.joints] for c in controllers_view(model).controllers}
    assert controllers["hand_position_controller"] == [j.name for j in model.joints if j.name in HAND_JOINTS]
    assert not set(controllers["forward_position_controller"]) & set(HAND_JOINTS)
    assert len(controllers["forward_position_controller"]) == 29
    active, inactive = start_controllers(model)
    assert {"forward_position_controller", "hand_position_controller"} <= set(active)
    assert "hand_position_controller" not in inactive


def test_hand_topics_can_be_moved(tmp_path):
    path = dex3_yaml(tmp_path, lambda t: t.replace(
        "  release_motion_control: false\n",
        "  release_motion_control: false\n  hand_state_topic: rt/dex3/{side}/state\n"))
    options = load_config(path).transport_options
    assert isinstance(options, UnitreeDdsOptions)
    assert options.hand_topics("right") == ("rt/dex3/right/cmd", "rt/dex3/right/state")


def _drop_hand_joint(text: str) -> str:
    return text.replace("  right_hand_index_1_joint: 48\n", "", 1)


@pytest.mark.parametrize(("edit", "key", "words"), [
    (lambda t: t.replace("motor_count: 49", "motor_count: 35"), "motor_count", "motor_count is 49"),
    (_drop_hand_joint, "joint_map", "right_hand_index_1_joint: 48"),
    (lambda t: t.replace("hands: dex3", "hands: inspire"), "hands", "is not supported"),
    (lambda t: t.replace("hands: dex3", "hands: none"), "motor_count", "exceeds the 35 motor slots"),
    (lambda t: t.replace("  release_motion_control: false\n",
                         "  release_motion_control: false\n  hand_command_topic: rt/dex3/cmd\n"),
     "transport_options.hand_command_topic", "{side}"),
    (lambda t: t.replace("family: hg", "family: go").replace("  sdk_slots: 35", "").replace("  mode_pr: 0", ""),
     "hands", "speak hg messages"),
])
def test_refusals_name_the_line_and_the_fix(tmp_path, edit, key, words):
    path = dex3_yaml(tmp_path, edit)
    with pytest.raises(ConfigError) as caught:
        model_of_yaml(path)
    error = caught.value
    assert words in str(error), str(error)
    assert error.fix, str(error)
    lines = path.read_text(encoding="utf-8").splitlines()
    top = key.split(".")[-1]
    if error.line is not None:
        assert re.match(rf"\s*{re.escape(top)}\s*:", lines[error.line - 1]) or top == "joint_map", (error.line, key)


def test_hand_options_without_hands_are_refused(tmp_path):
    g1 = (REPO / "robots/unitree/g1.yaml").read_text(encoding="utf-8")
    text = g1.replace("urdf: g1.urdf", f"urdf: {REPO / 'robots/unitree/g1.urdf'}").replace(
        "  release_motion_control: false\n", "  release_motion_control: false\n  hand_state_topic: x/{side}\n")
    path = tmp_path / "g1.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError, match="used only with hands: dex3"):
        load_config(path)


@pytest.mark.parametrize("transport", ["generic_topics", "engineai_topics"])
def test_other_transports_drive_no_hands(tmp_path, transport):
    v = Validator("x.yaml", {"hands": 3})
    with pytest.raises(ConfigError, match="drives no hands") as caught:
        get(transport).resolve_hands(v, "dex3", TransportOptions(), vendor="v", robot="r")
    assert caught.value.line == 3 and caught.value.fix


def _new_yaml(tmp_path: Path, urdf: Path) -> Path:
    text = suggest_yaml(vendor="unitree", robot="g1", urdf=load_urdf(urdf), urdf_relative=str(urdf))
    path = tmp_path / "g1.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_new_drives_the_hands_of_a_g1_urdf_with_hands(tmp_path):
    """`rhi-gen new` on Unitree's G1 URDF with hands writes hands: dex3 and the Dex3-1 motor order."""
    model = model_of_yaml(_new_yaml(tmp_path, (HARNESS / "g1_dex3.urdf").resolve()))
    assert model.hands == "dex3" and model.motor_count == 49
    assert [j.name for j in sorted(model.hand_joints, key=lambda j: j.index)] == HAND_JOINTS
    assert [j.index for j in sorted(model.hand_joints, key=lambda j: j.index)] == list(range(35, 49))
    assert all((j.default_stiffness, j.default_damping) == dex3_facts.GRIP_GAINS for j in model.hand_joints)
    assert len(model.joints) == 43


def test_new_tells_a_g1_without_hands_how_to_add_them(tmp_path):
    path = _new_yaml(tmp_path, REPO / "robots/unitree/g1.urdf")
    text = path.read_text(encoding="utf-8")
    assert "hands: none" in text.splitlines() and ", ".join(dex3_facts.MOTOR_ORDER) in text
    assert load_config(path).hands == "none"
    assert get("unitree_dds").suggest_hands(None, HandSuggestion()) == []
