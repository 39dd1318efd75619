"""The three reference robots under robots/ match their upstream facts.

Oracles are independent of rhi-gen's own code: the upstream URDFs (the repository's copies in
tests/data/upstream_urdf for G1 and PM01; AgiBot X2's from ../shared/upstream/urdf, skipped with one line
without it: tests/support/upstream_urdf.py) and joint orders hard-coded here from SDK_FACTS.md. Only lxml and
PyYAML are used.
"""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from lxml import etree

from tests.support import upstream_urdf
from tests.support.repo import REPO
from tests.support.xml_tree import attribute

ACTUATED_TYPES = ("revolute", "continuous", "prismatic")

# (vendor, robot, upstream file, robot name)
ROBOTS = [
    ("unitree", "g1", "unitree_g1.urdf", "g1_29dof_rev_1_0"),
    ("agibot", "x2", "agibot_x2.urdf", "X2-Ultra"),
    ("engineai", "pm01", "engineai_pm01.urdf", "pm_v2"),
]
IDS = [f"{v}/{r}" for v, r, _, _ in ROBOTS]

# SDK_FACTS.md A: unitree_sdk2 enum G1JointIndex, motor index 0..28.
G1_SDK_ORDER = [
    "left_hip_pitch_joint", "left_hip_roll_joint", "left_hip_yaw_joint", "left_knee_joint",
    "left_ankle_pitch_joint", "left_ankle_roll_joint",
    "right_hip_pitch_joint", "right_hip_roll_joint", "right_hip_yaw_joint", "right_knee_joint",
    "right_ankle_pitch_joint", "right_ankle_roll_joint",
    "waist_yaw_joint", "waist_roll_joint", "waist_pitch_joint",
    "left_shoulder_pitch_joint", "left_shoulder_roll_joint", "left_shoulder_yaw_joint",
    "left_elbow_joint", "left_wrist_roll_joint", "left_wrist_pitch_joint", "left_wrist_yaw_joint",
    "right_shoulder_pitch_joint", "right_shoulder_roll_joint", "right_shoulder_yaw_joint",
    "right_elbow_joint", "right_wrist_roll_joint", "right_wrist_pitch_joint", "right_wrist_yaw_joint",
]

# SDK_FACTS.md B: AimDK joint groups, in topic/group order.
_X2_LEG = ["hip_pitch", "hip_roll", "hip_yaw", "knee", "ankle_pitch", "ankle_roll"]
_X2_ARM = ["shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow", "wrist_yaw", "wrist_pitch", "wrist_roll"]
X2_GROUPS = [
    ("leg", [f"{side}_{j}_joint" for side in ("left", "right") for j in _X2_LEG]),
    ("waist", ["waist_yaw_joint", "waist_pitch_joint", "waist_roll_joint"]),
    ("arm", [f"{side}_{j}_joint" for side in ("left", "right") for j in _X2_ARM]),
    ("head", ["head_yaw_joint", "head_pitch_joint"]),
]

# SDK_FACTS.md C: PM01 motor order.
PM01_ORDER = [
    "J00_HIP_PITCH_L", "J01_HIP_ROLL_L", "J02_HIP_YAW_L", "J03_KNEE_PITCH_L", "J04_ANKLE_PITCH_L",
    "J05_ANKLE_ROLL_L", "J06_HIP_PITCH_R", "J07_HIP_ROLL_R", "J08_HIP_YAW_R", "J09_KNEE_PITCH_R",
    "J10_ANKLE_PITCH_R", "J11_ANKLE_ROLL_R", "J12_WAIST_YAW", "J13_SHOULDER_PITCH_L",
    "J14_SHOULDER_ROLL_L", "J15_SHOULDER_YAW_L", "J16_ELBOW_PITCH_L", "J17_ELBOW_YAW_L",
    "J18_SHOULDER_PITCH_R", "J19_SHOULDER_ROLL_R", "J20_SHOULDER_YAW_R", "J21_ELBOW_PITCH_R",
    "J22_ELBOW_YAW_R", "J23_HEAD_YAW",
]


# ---------------------------------------------------------------- helpers
def _root(path: Path) -> etree._Element:
    return etree.parse(str(path)).getroot()


def _joints(root: etree._Element) -> list[etree._Element]:
    return root.findall("joint")  # top-level joints only (not <ros2_control>/<transmission> children)


def _actuated(root: etree._Element) -> list[etree._Element]:
    return [j for j in _joints(root) if j.get("type") in ACTUATED_TYPES and j.find("mimic") is None]


def _limits(joint: etree._Element) -> tuple[float, float, float, float]:
    lim = joint.find("limit")
    assert lim is not None, f"{joint.get('name')}: no <limit>"
    lower, upper, effort, velocity = (float(attribute(lim, k)) for k in ("lower", "upper", "effort", "velocity"))
    return lower, upper, effort, velocity


def _axis(joint: etree._Element) -> tuple[float, ...]:
    axis = joint.find("axis")
    return tuple(float(v) for v in (attribute(axis, "xyz") if axis is not None else "1 0 0").split())


def _origin(joint: etree._Element) -> tuple[float, ...]:
    o = joint.find("origin")
    attrs = (o.get("xyz", "0 0 0"), o.get("rpy", "0 0 0")) if o is not None else ("0 0 0", "0 0 0")
    return tuple(float(v) for a in attrs for v in a.split())


def _link(joint: etree._Element, tag: str) -> str | None:
    """The link= of the joint's <parent> or <child>, which every joint has."""
    element = joint.find(tag)
    assert element is not None, f"{joint.get('name')}: no <{tag}>"
    return element.get("link")


def _ours(vendor: str, robot: str) -> etree._Element:
    return _root(REPO / "robots" / vendor / f"{robot}.urdf")


def _upstream(upstream_file: str) -> etree._Element:
    return _root(upstream_urdf.require(upstream_file))


def _yaml(vendor: str, robot: str) -> dict:
    with open(REPO / "robots" / vendor / f"{robot}.yaml", encoding="utf-8") as f:
        return yaml.safe_load(f)


def _map_order(cfg: dict) -> list[str]:
    """Joint names sorted by slot index."""
    return [name for name, _ in sorted(cfg["joint_map"].items(), key=lambda kv: kv[1])]


# ---------------------------------------------------------------- URDF vs upstream
@pytest.mark.parametrize(("vendor", "robot", "upstream_file", "robot_name"), ROBOTS, ids=IDS)
def test_actuated_joint_order_matches_upstream(vendor, robot, upstream_file, robot_name):
    ours, up = _ours(vendor, robot), _upstream(upstream_file)
    assert ours.get("name") == up.get("name") == robot_name
    assert [j.get("name") for j in _actuated(ours)] == [j.get("name") for j in _actuated(up)]


@pytest.mark.parametrize(("vendor", "robot", "upstream_file", "robot_name"), ROBOTS, ids=IDS)
def test_limits_axes_origins_tree_match_upstream(vendor, robot, upstream_file, robot_name):
    ours, up = _ours(vendor, robot), _upstream(upstream_file)
    up_by_name = {j.get("name"): j for j in _joints(up)}
    for j in _joints(ours):
        name = j.get("name")
        assert name in up_by_name, f"{name}: not an upstream joint"
        u = up_by_name[name]
        assert j.get("type") == u.get("type"), name
        assert _link(j, "parent") == _link(u, "parent"), name
        assert _link(j, "child") == _link(u, "child"), name
        assert _origin(j) == _origin(u), name
        if j.get("type") in ACTUATED_TYPES:
            assert _limits(j) == _limits(u), name
            assert _axis(j) == _axis(u), name


@pytest.mark.parametrize(("vendor", "robot", "upstream_file", "robot_name"), ROBOTS, ids=IDS)
def test_urdf_is_the_vendors_own_file_with_its_licence_and_provenance(vendor, robot, upstream_file, robot_name):
    """Issue 49: the vendor's URDF byte for byte (the upstream copy where one is at hand), its licence beside it
    and a row in robots/PROVENANCE.md; a real body: inertials everywhere a link moves, collision geometry."""
    path = REPO / "robots" / vendor / f"{robot}.urdf"
    root = _root(path)
    assert root.tag == "robot" and root.get("name") == robot_name
    assert list(root.iter("collision")) and list(root.iter("inertial"))
    upstream = upstream_urdf.find(upstream_file)
    if upstream is not None:
        assert path.read_bytes() == upstream.read_bytes()
    assert list((REPO / "robots" / vendor).glob("LICENSE*")), f"robots/{vendor}/: no licence text"
    assert f"`{vendor}/{robot}.urdf`" in (REPO / "robots" / "PROVENANCE.md").read_text(encoding="utf-8")


def test_imu_frames_present():
    g1 = {j.get("name"): _link(j, "child") for j in _joints(_ours("unitree", "g1"))}
    assert g1["imu_in_pelvis_joint"] == "imu_in_pelvis"
    assert g1["imu_in_torso_joint"] == "imu_in_torso"
    x2 = {j.get("name"): j for j in _joints(_ours("agibot", "x2"))}
    for name in ("imu_in_pelvis_joint", "imu_in_torso_joint"):
        assert x2[name].get("type") == "fixed"
    pm = {j.get("name"): j.get("type") for j in _joints(_ours("engineai", "pm01"))}
    for name in ("J_FIXED_FOOT_L", "J_FIXED_FOOT_R", "J_FIXED_ELBOW_END_L", "J_FIXED_ELBOW_END_R"):
        assert pm[name] == "fixed"


# ---------------------------------------------------------------- vendor YAML
@pytest.mark.parametrize(("vendor", "robot", "upstream_file", "robot_name"), ROBOTS, ids=IDS)
def test_yaml_joint_map_covers_actuated_joints(vendor, robot, upstream_file, robot_name):
    cfg = _yaml(vendor, robot)
    assert cfg["vendor"] == vendor and cfg["robot"] == robot
    assert (REPO / "robots" / vendor / cfg["urdf"]).is_file()
    actuated = [j.get("name") for j in _actuated(_ours(vendor, robot))]
    assert set(cfg["joint_map"]) == set(actuated)
    assert len(actuated) == cfg["motor_count"]
    assert sorted(cfg["joint_map"].values()) == list(range(cfg["motor_count"]))
    assert not cfg.get("unmapped_joints")
    frame = cfg["imu"]["frame_id"]
    assert frame in {link.get("name") for link in _ours(vendor, robot).findall("link")}


def test_g1_yaml_matches_sdk_order():
    cfg = _yaml("unitree", "g1")
    assert cfg["transport"] == "unitree_dds" and cfg["float_type"] == "float"
    assert cfg["motor_count"] == 29 == len(G1_SDK_ORDER)
    assert cfg["joint_map"] == {name: i for i, name in enumerate(G1_SDK_ORDER)}
    assert cfg["transport_options"] == {
        "family": "hg", "lowcmd_topic": "rt/lowcmd", "lowstate_topic": "rt/lowstate", "sdk_slots": 35,
        "domain_id": 0, "mode_pr": 0, "release_motion_control": False,
    }
    assert cfg["imu"] == {"enabled": True, "frame_id": "imu_in_pelvis"}
    # the upstream URDF order is the SDK order (SDK_FACTS.md)
    assert [j.get("name") for j in _actuated(_ours("unitree", "g1"))] == G1_SDK_ORDER


def test_x2_yaml_groups_match_aimdk_order():
    cfg = _yaml("agibot", "x2")
    assert cfg["transport"] == "agibot_topics" and cfg["float_type"] == "double"
    opts = cfg["transport_options"]
    groups = opts["groups"]
    assert [(g["name"], g["size"]) for g in groups] == [(n, len(js)) for n, js in X2_GROUPS]
    for g in groups:
        assert g["command_topic"] == f"/aima/hal/joint/{g['name']}/command"
        assert g["state_topic"] == f"/aima/hal/joint/{g['name']}/state"
    assert opts["imu_topic"] == "/aima/hal/imu/torso/state"
    assert opts["qos"] == {"reliability": "best_effort", "durability": "volatile", "depth": 1}
    assert cfg["motor_count"] == sum(len(js) for _, js in X2_GROUPS) == 31
    order = _map_order(cfg)
    offset = 0
    for name, joints in X2_GROUPS:
        assert order[offset:offset + len(joints)] == joints, name
        offset += len(joints)
    x2 = {j.get("name"): _link(j, "child") for j in _joints(_ours("agibot", "x2"))}
    assert cfg["imu"]["frame_id"] == x2["imu_in_torso_joint"]


def test_x2_yaml_slot_comments():
    """Each joint_map line carries a '# group[i]' comment consistent with its slot."""
    text = (REPO / "robots" / "agibot" / "x2.yaml").read_text(encoding="utf-8")
    after = text.split("joint_map:", 1)[1].splitlines()[1:]
    lines = after[:next((i for i, ln in enumerate(after) if ln and not ln[0].isspace()), len(after))]
    expected = [f"{g}[{i}]" for g, js in X2_GROUPS for i in range(len(js))]
    comments = [ln.split("#", 1)[1].strip() for ln in lines if ln.strip() and ":" in ln]
    assert comments == expected


@pytest.mark.parametrize("vendor,robot", [("unitree", "g1"), ("agibot", "x2"), ("engineai", "pm01")])
def test_reference_robot_has_default_gains_for_every_joint(vendor, robot):
    """A position-only controller on a reference robot is never limp, and the driver's start-up line
    about joints without default stiffness (a warning on every launch) never comes."""
    cfg = _yaml(vendor, robot)
    gains = cfg["default_gains"]
    assert set(gains) == set(cfg["joint_map"])
    assert all(g["stiffness"] > 0 and g["damping"] > 0 for g in gains.values())


def test_x2_and_pm01_default_gains_are_the_vendor_examples():
    """X2: AimDK motocontrol.cpp (hip 40/4, yaw 30/3, knee 80/8, ankle 40/4 and 20/2, waist 20/4, arms
    and head 20/2); PM01: the native SDK's pd_stand task in motor order."""
    x2 = _yaml("agibot", "x2")["default_gains"]
    assert x2["left_hip_yaw_joint"] == {"stiffness": 30.0, "damping": 3.0}
    assert x2["right_knee_joint"] == {"stiffness": 80.0, "damping": 8.0}
    assert x2["left_ankle_roll_joint"] == {"stiffness": 20.0, "damping": 2.0}
    assert x2["waist_pitch_joint"] == {"stiffness": 20.0, "damping": 4.0}
    assert x2["head_pitch_joint"] == {"stiffness": 20.0, "damping": 2.0}
    pm01 = _yaml("engineai", "pm01")["default_gains"]
    stiffness = [pm01[name]["stiffness"] for name in PM01_ORDER]
    damping = [pm01[name]["damping"] for name in PM01_ORDER]
    assert stiffness == [200, 200, 380, 450, 400, 200] * 2 + [200] + [250] * 10 + [100]
    assert damping == [5, 5, 5, 5, 2, 2] * 2 + [1] * 12


def test_pm01_yaml_is_identity():
    cfg = _yaml("engineai", "pm01")
    assert cfg["transport"] == "engineai_topics" and cfg["float_type"] == "double"
    assert cfg["motor_count"] == 24
    assert cfg["joint_map"] == {name: i for i, name in enumerate(PM01_ORDER)}
    for name, i in cfg["joint_map"].items():
        assert int(name[1:3]) == i
    opts = cfg["transport_options"]
    assert opts["command_topic"] == "/hardware/joint_command"
    assert opts["state_topic"] == "/hardware/joint_state"
    assert opts["imu_topic"] == "/hardware/imu_info"
    assert opts["parallel_parser_type"] == 0
    assert opts["qos"] == {"reliability": "best_effort", "durability": "volatile", "depth": 3}
