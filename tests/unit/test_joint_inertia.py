"""The fake robot's per-joint rotor: inertia about the axis, damping, from the URDF (assemble/joint_inertia.py).

Expected values are worked out by hand in the comments: I = sum over the subtree of a^T R I_c R^T a + m d^2."""
from __future__ import annotations

import math

import pytest

from rhi_gen.assemble.joint_inertia import DEFAULT_DAMPING, MIN_INERTIA, JointDynamics, joint_dynamics
from tests.support.repo import REPO

QUARTER_TURN = "1.5707963267948966"  # pi/2


def _inertial(mass: str, xyz: str = "0 0 0", diag: tuple[str, str, str] = ("0", "0", "0"), rpy: str = "0 0 0",
              off: tuple[str, str, str] = ("0", "0", "0")) -> str:
    ixx, iyy, izz = diag
    ixy, ixz, iyz = off
    return (f'<inertial><origin xyz="{xyz}" rpy="{rpy}"/><mass value="{mass}"/>'
            f'<inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="{izz}"/></inertial>')


def _joint(name: str, parent: str, child: str, *, kind: str = "revolute", axis: str | None = "0 0 1",
           xyz: str = "0 0 0", rpy: str = "0 0 0", extra: str = "") -> str:
    axis_el = f'<axis xyz="{axis}"/>' if axis is not None else ""
    return (f'<joint name="{name}" type="{kind}"><origin xyz="{xyz}" rpy="{rpy}"/><parent link="{parent}"/>'
            f'<child link="{child}"/>{axis_el}<limit lower="-1" upper="1" effort="1" velocity="1"/>{extra}</joint>')


def _robot(*parts: str) -> str:
    return '<?xml version="1.0"?>\n<robot name="r"><link name="base"/>' + "".join(parts) + "</robot>"


def _one_link(inertial: str, **joint: str) -> str:
    """base -j-> arm, the arm carrying ``inertial``."""
    return _robot(f'<link name="arm">{inertial}</link>', _joint("j", "base", "arm", **joint))


def _inertia(urdf: str, joint: str = "j") -> float:
    return joint_dynamics(urdf)[joint].inertia


# ---------------------------------------------------------------- one link
def test_point_mass_off_the_axis_is_m_d_squared():
    # 2 kg at 0.5 m from the z axis: 2 * 0.5^2 = 0.5
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0"))) == 0.5


def test_tensor_term_adds_the_component_about_the_axis():
    # izz = 0.3 about z, plus 2 * 0.5^2 = 0.5: 0.8 (ixx, iyy do not count)
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")))) == 0.8
    # COM offset along y instead of x: same distance, same 0.8
    assert _inertia(_one_link(_inertial("2", xyz="0 -0.5 0", diag=("0.1", "0.2", "0.3")))) == 0.8
    # an offset along the axis itself adds nothing: 0.3 + 2 * 0.5^2 (the x part only) = 0.8
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 7", diag=("0.1", "0.2", "0.3")))) == 0.8


def test_axis_along_the_com_offset_leaves_only_the_tensor_term():
    # axis x through a COM at (0.5, 0, 0): d = 0, so ixx = 0.1 alone
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), axis="1 0 0")) == 0.1
    # the axis is normalised: (3, 0, 0) is x
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), axis="3 0 0")) == 0.1


def test_a_tiny_link_gets_the_floor():
    # 1 g at 1 cm, ixx 1e-6 about x: 1e-6 + 0.001 * 0.01^2 = 1.1e-6, far below MIN_INERTIA
    assert _inertia(_one_link(_inertial("0.001", xyz="0 0.01 0", diag=("1e-6", "1e-6", "1e-6")), axis="1 0 0")) \
        == MIN_INERTIA
    # no inertial at all: 0 -> floor
    assert _inertia(_robot('<link name="arm"/>', _joint("j", "base", "arm"))) == MIN_INERTIA


def test_inertial_origin_rpy_rotates_the_tensor():
    # tensor diag(0.1, 0.2, 0.3) in a frame turned 90 deg about z: its y axis lies along the link's -x,
    # so about x the rotated tensor gives iyy = 0.2 (not ixx = 0.1); COM at the origin
    urdf = _one_link(_inertial("2", diag=("0.1", "0.2", "0.3"), rpy=f"0 0 {QUARTER_TURN}"), axis="1 0 0")
    assert _inertia(urdf) == 0.2


def test_diagonal_axis_counts_the_products_of_inertia():
    # a = (1, 1, 0)/sqrt(2): a^T I a = (ixx + 2 ixy + iyy) / 2 = (0.1 + 2*0.05 + 0.2) / 2 = 0.2; COM at origin
    urdf = _one_link(_inertial("2", diag=("0.1", "0.2", "0.3"), off=("0.05", "0", "0")), axis="1 1 0")
    assert _inertia(urdf) == 0.2
    # the product of inertia's sign matters: ixy = -0.05 -> (0.1 - 0.1 + 0.2) / 2 = 0.1
    urdf = _one_link(_inertial("2", diag=("0.1", "0.2", "0.3"), off=("-0.05", "0", "0")), axis="1 1 0")
    assert _inertia(urdf) == 0.1


def test_six_significant_digits():
    # 1 kg at 1/3 m: 1/9 = 0.111111...
    value = _inertia(_one_link(_inertial("1", xyz="0.3333333333 0 0")))
    assert value == 0.111111
    assert repr(value) == "0.111111"


# ---------------------------------------------------------------- chains
def _two_link_chain(rpy: str) -> str:
    # base -j1 (axis y, at the base origin)-> l1 -j2 (at x = 0.4, turned by rpy, axis x)-> l2
    return _robot(
        f'<link name="l1">{_inertial("1", xyz="0.2 0 0", diag=("0.01", "0.02", "0.03"))}</link>',
        f'<link name="l2">{_inertial("2", xyz="0.1 0 0", diag=("0.04", "0.05", "0.06"))}</link>',
        _joint("j1", "base", "l1", axis="0 1 0"),
        _joint("j2", "l1", "l2", axis="1 0 0", xyz="0.4 0 0", rpy=rpy))


def test_upstream_joint_carries_the_downstream_link():
    dyn = joint_dynamics(_two_link_chain(f"0 0 {QUARTER_TURN}"))
    # j1 about y. l1: iyy 0.02 + 1 * 0.2^2 = 0.06.
    # l2: its frame is turned 90 deg about z, so its x axis lies along j1's y: its ixx = 0.04 counts.
    #     its COM is at (0.4, 0, 0) + Rz(90)(0.1, 0, 0) = (0.4, 0.1, 0); distance from the y axis 0.4:
    #     2 * 0.16 = 0.32. l2 gives 0.36. j1 = 0.06 + 0.36 = 0.42
    assert dyn["j1"].inertia == 0.42
    # j2 about l2's own x: ixx 0.04, COM on the axis: 0.04
    assert dyn["j2"].inertia == 0.04


def test_without_the_rotation_another_component_counts():
    dyn = joint_dynamics(_two_link_chain("0 0 0"))
    # l2 unturned: its iyy = 0.05 counts, COM at (0.5, 0, 0): 2 * 0.25 = 0.5; j1 = 0.06 + 0.55 = 0.61
    assert dyn["j1"].inertia == 0.61


def test_fixed_joints_carry_their_links_into_the_subtree():
    # j -> arm (1 kg at origin) -fixed at x=0.3-> tool (1 kg, COM at its origin): about z, 1 * 0.09 = 0.09
    urdf = _robot(f'<link name="arm">{_inertial("1")}</link>', f'<link name="tool">{_inertial("1")}</link>',
                  _joint("j", "base", "arm"), _joint("f", "arm", "tool", kind="fixed", axis=None, xyz="0.3 0 0"))
    assert _inertia(urdf) == 0.09


def test_the_joint_origin_is_the_reference_not_the_parent_frame():
    # the joint sits at (5, 5, 0) in base; the link's COM is 0.5 m from it: 2 * 0.25 = 0.5 (not 2 * 50.x)
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0"), xyz="5 5 0")) == 0.5
    # the joint's own rpy turns its axis: z in a frame rolled 90 deg about x is base -y, but the axis and the
    # COM are both in the joint frame, so nothing changes: 0.5
    assert _inertia(_one_link(_inertial("2", xyz="0.5 0 0"), rpy=f"{QUARTER_TURN} 0 0")) == 0.5


# ---------------------------------------------------------------- prismatic
def test_prismatic_joint_carries_the_subtree_mass():
    # slider (2 kg, far off any axis) + tool through a fixed joint (0.5 kg): 2.5 kg
    urdf = _robot(f'<link name="slider">{_inertial("2", xyz="3 0 0", diag=("1", "1", "1"))}</link>',
                  f'<link name="tool">{_inertial("0.5")}</link>',
                  _joint("p", "base", "slider", kind="prismatic", axis="0 0 1"),
                  _joint("f", "slider", "tool", kind="fixed", axis=None, xyz="0 1 0"))
    assert _inertia(urdf, "p") == 2.5


def test_light_prismatic_joint_gets_the_floor():
    assert _inertia(_one_link(_inertial("0.002"), kind="prismatic")) == MIN_INERTIA


# ---------------------------------------------------------------- damping
@pytest.mark.parametrize(("dynamics", "damping"), [
    ('<dynamics damping="0.7" friction="0.2"/>', 0.7),
    ('<dynamics damping="0"/>', 0.0),
    ('<dynamics damping="1.23456789"/>', 1.23457),   # six significant digits
    ("", DEFAULT_DAMPING),                             # no <dynamics>
    ('<dynamics friction="0.2"/>', DEFAULT_DAMPING),   # <dynamics> without damping
    ('<dynamics damping="lots"/>', DEFAULT_DAMPING),
    ('<dynamics damping="nan"/>', DEFAULT_DAMPING),
    ('<dynamics damping="inf"/>', DEFAULT_DAMPING),
    ('<dynamics damping=""/>', DEFAULT_DAMPING),
    ('<dynamics damping="-0.5"/>', DEFAULT_DAMPING),
])
def test_damping_from_dynamics(dynamics, damping):
    assert joint_dynamics(_one_link(_inertial("2", xyz="0.5 0 0"), extra=dynamics))["j"].damping == damping


# ---------------------------------------------------------------- which joints
def test_only_actuated_joints_without_mimic():
    urdf = _robot(*(f'<link name="l{i}">{_inertial("1", xyz="1 0 0")}</link>' for i in range(6)),
                  _joint("rev", "base", "l0"),
                  _joint("cont", "l0", "l1", kind="continuous"),
                  _joint("slide", "l1", "l2", kind="prismatic"),
                  _joint("glued", "l2", "l3", kind="fixed", axis=None),
                  _joint("follower", "l3", "l4", extra='<mimic joint="rev" multiplier="1"/>'),
                  _joint("free", "l4", "l5", kind="floating", axis=None))
    assert sorted(joint_dynamics(urdf)) == ["cont", "rev", "slide"]


# ---------------------------------------------------------------- robustness
@pytest.mark.parametrize(("inertial", "joint", "expected"), [
    # a garbled COM vector counts as absent (at the origin): izz 0.3 alone
    (_inertial("2", xyz="0.5 nan 0", diag=("0.1", "0.2", "0.3")), {}, 0.3),
    (_inertial("2", xyz="0.5 0", diag=("0.1", "0.2", "0.3")), {}, 0.3),
    (_inertial("2", xyz="a b c", diag=("0.1", "0.2", "0.3")), {}, 0.3),
    # a garbled inertial rpy counts as none: izz 0.3 + 0.5
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3"), rpy="0 x 0"), {}, 0.8),
    # garbled tensor entries are zero: 0 + 0.5
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "inf")), {}, 0.5),
    # a garbled or negative mass is no mass: izz 0.3 alone
    (_inertial("heavy", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {}, 0.3),
    (_inertial("-2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {}, 0.3),
    # missing, garbled or zero axis: URDF's default x, so ixx 0.1 + 2 * 0 (COM on x) = 0.1
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {"axis": None}, 0.1),
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {"axis": "0 0 one"}, 0.1),
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {"axis": "0 0 0"}, 0.1),
    # a garbled joint origin is the identity: 0.3 + 0.5
    (_inertial("2", xyz="0.5 0 0", diag=("0.1", "0.2", "0.3")), {"xyz": "1 2", "rpy": "nan 0 0"}, 0.8),
])
def test_garbled_numbers_count_as_absent(inertial, joint, expected):
    assert _inertia(_one_link(inertial, **joint)) == expected


def test_missing_elements_do_not_raise():
    urdf = _robot('<link name="a"><inertial/></link>',
                  '<link name="b"><inertial><mass value="2"/></inertial></link>',
                  '<link name="c"><inertial><inertia ixx="0.5"/></inertial></link>',
                  '<joint name="ja" type="revolute"><parent link="base"/><child link="a"/></joint>',
                  '<joint name="jb" type="revolute"><parent link="a"/><child link="b"/></joint>',
                  '<joint name="jc" type="revolute"><parent link="b"/><child link="c"/></joint>')
    dyn = joint_dynamics(urdf)
    # no origins, default axis x: b's 2 kg sits on the axis, only c's ixx = 0.5 counts, for all three
    assert dyn == {name: JointDynamics(0.5, DEFAULT_DAMPING) for name in ("ja", "jb", "jc")}


def test_same_input_same_result():
    urdf = _two_link_chain(f"0.3 -0.2 {QUARTER_TURN}")
    assert joint_dynamics(urdf) == joint_dynamics(urdf)
    assert list(joint_dynamics(urdf)) == ["j1", "j2"]  # document order


# ---------------------------------------------------------------- a real robot
def test_unitree_g1_every_joint_and_the_leg_below_the_hip():
    urdf = (REPO / "robots/unitree/g1.urdf").read_text(encoding="utf-8")
    dyn = joint_dynamics(urdf)
    assert len(dyn) == 29  # the G1's 29 revolute joints, its fixed ones absent
    assert all(math.isfinite(d.inertia) and d.inertia >= MIN_INERTIA for d in dyn.values())
    assert all(d.damping == DEFAULT_DAMPING for d in dyn.values())  # the skeleton has no <dynamics>
    # the whole leg hangs below the hip: pitching it swings six links, rolling the foot swings one
    assert dyn["left_hip_pitch_joint"].inertia > dyn["left_knee_joint"].inertia > dyn["left_ankle_roll_joint"].inertia
    # the legs mirror each other
    assert dyn["left_hip_pitch_joint"] == dyn["right_hip_pitch_joint"]
