"""<transmission> in real and hostile URDFs: ros2_control's convention, never an error."""
from __future__ import annotations

import math

import pytest

from rhi_gen.inputs.urdf_loader import load_urdf, parse_urdf_bytes
from rhi_gen.inputs.urdf_transmissions import describe
from tests.support.corpus import example_robot


def by_name(urdf):
    return {t.name: t for t in urdf.transmissions}


def test_talos_simple_and_differential_transmissions():
    urdf = load_urdf(example_robot("talos_data/robots/talos_reduced.urdf"))
    ts = by_name(urdf)
    assert len(ts) == 28
    # actuator1 -1, actuator2 1, joint1 -1, joint2 1:
    # A = [[1/(2*jr0*ar0), 1/(2*jr0*ar1)], [1/(2*jr1*ar0), -1/(2*jr1*ar1)]]
    wrist = ts["wrist_left_trans"]
    assert wrist.short_kind == "DifferentialTransmission" and not wrist.problem
    assert wrist.joints == ("arm_left_6_joint", "arm_left_7_joint")
    assert wrist.matrix == ((0.5, -0.5), (0.5, 0.5)) and wrist.offsets == (0.0, 0.0)
    assert ts["talos_torso_trans"].matrix == ((0.5, 0.5), (0.5, -0.5))
    # joint and actuator reductions of -1 multiply into the identity
    simple = ts["arm_left_5_trans"]
    assert (simple.joints, simple.reduction, simple.offsets, simple.problem) == (("arm_left_5_joint",), 1.0, (0.0,), "")
    assert describe(simple) == "arm_left_5_joint: SimpleTransmission 'arm_left_5_trans': identity (changes nothing)"
    half = ts["talos_trans"]
    assert half.short_kind == "HalfDifferentialTransmission"
    assert "applies only SimpleTransmission and DifferentialTransmission" in half.problem


def test_pr2_signed_reductions_old_forms_and_unsupported_kinds():
    urdf = load_urdf(example_robot("pr2_description/urdf/pr2.urdf"))
    ts = by_name(urdf)
    # <mechanicalReduction> straight under <transmission>, and type="" as an attribute
    assert ts["torso_lift_trans"].reduction == -52143.33 and not ts["torso_lift_trans"].problem
    assert describe(ts["torso_lift_trans"]) == ("torso_lift_joint: SimpleTransmission 'torso_lift_trans': "
                                                "reduction 52143.3, direction -1")
    assert ts["r_shoulder_pan_trans"].reduction == pytest.approx(63.1552452977)
    assert "a fixed joint" in ts["fl_caster_rotation_trans"].problem
    assert ts["r_wrist_trans"].short_kind == "WristTransmission" and ts["r_wrist_trans"].problem


def test_tiago_hey5_reducer_is_not_applied_and_its_wrist_is():
    ts = by_name(load_urdf(example_robot("tiago_description/robots/tiago.urdf")))
    hey5 = [t for t in ts.values() if t.short_kind == "Hey5Reducer"]
    assert len(hey5) == 33 and all(t.problem for t in hey5)
    assert ts["wrist_trans"].matrix == ((-0.5, 0.5), (0.5, 0.5))


def test_tiago_pro_ros2_control_plugin_form():
    urdf = load_urdf(example_robot("tiago_pro_description/robots/tiago_pro.urdf"))
    plugin_form = [t for t in urdf.transmissions if t.name == "wheel_front_right_trans"]
    assert len(plugin_form) == 1
    t = plugin_form[0]
    assert (t.kind, t.joints, t.reduction, t.problem) == ("transmission_interface/SimpleTransmission",
                                                          ("wheel_front_right_joint",), 1.0, "")


ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j3" type="continuous"><parent link="b"/><child link="c"/></joint>
  {body}
</robot>
"""


def urdf_with(body: str):
    return parse_urdf_bytes(ARM.format(body=body).encode(), source="arm.urdf")


def test_ros2_control_form_roles_reductions_and_offsets():
    urdf = urdf_with("""
  <ros2_control name="hw" type="system">
    <hardware><plugin>x/Y</plugin></hardware>
    <transmission name="knee">
      <plugin>transmission_interface/SimpleTransmission</plugin>
      <actuator name="m3" role="actuator1"><mechanical_reduction>2</mechanical_reduction></actuator>
      <joint name="j3" role="joint1"><mechanical_reduction>-25</mechanical_reduction><offset>0.5</offset></joint>
    </transmission>
    <transmission name="wrist">
      <plugin>transmission_interface/DifferentialTransmission</plugin>
      <actuator name="m2" role="actuator2"><mechanical_reduction>4</mechanical_reduction></actuator>
      <actuator name="m1" role="actuator1"><mechanical_reduction>2</mechanical_reduction></actuator>
      <joint name="j2" role="joint2"><mechanical_reduction>1</mechanical_reduction><offset>-0.1</offset></joint>
      <joint name="j1" role="joint1"><mechanical_reduction>0.5</mechanical_reduction></joint>
    </transmission>
  </ros2_control>""")
    knee, wrist = urdf.transmissions
    assert (knee.reduction, knee.offsets, knee.problem) == (-50.0, (0.5,), "")
    assert describe(knee) == "j3: SimpleTransmission 'knee': reduction 50, direction -1, offset 0.5"
    assert wrist.joints == ("j1", "j2") and wrist.offsets == (0.0, -0.1)
    # jr = (0.5, 1), ar = (2, 4) in role order
    assert wrist.matrix == ((1 / (2 * 0.5 * 2), 1 / (2 * 0.5 * 4)), (1 / (2 * 1 * 2), -1 / (2 * 1 * 4)))
    assert (knee.line, wrist.line) == (12, 17)


SIMPLE = "<transmission name='t'><type>transmission_interface/SimpleTransmission</type>{}</transmission>"


@pytest.mark.parametrize("body, words", [
    (SIMPLE.format("<joint name='j1'/><actuator name='m'><mechanicalReduction>fifty</mechanicalReduction></actuator>"),
     "'fifty', not a number"),
    (SIMPLE.format("<joint name='j1'/><actuator name='m'><mechanicalReduction>0</mechanicalReduction></actuator>"),
     "is 0"),
    (SIMPLE.format("<joint name='j1'><offset>nan</offset></joint><actuator name='m'/>"), "not a number"),
    (SIMPLE.format("<joint name='j1'><offset>1e999</offset></joint><actuator name='m'/>"), "not a finite number"),
    ("<transmission name='t'><joint name='j1'/></transmission>", "no <type> or <plugin>"),
    (SIMPLE.format(""), "1 <joint> and 1 <actuator>, this one 0 and 0"),
    (SIMPLE.format("<joint name='j1'/><joint name='j2'/><actuator name='a'/>").replace("Simple", "Differential"),
     "2 <joint> and 2 <actuator>"),
    (SIMPLE.format("<joint name='jx'/>"), "'jx', which is not a joint of this URDF"),
    (SIMPLE.format("<joint/>"), "has no name"),
    (SIMPLE.format("<joint name='j1'><offset>10</offset></joint>"), "beyond one turn"),
    (SIMPLE.format("<joint name='j1'><mechanicalReduction>1e4</mechanicalReduction></joint>"
                   "<actuator name='m'><mechanicalReduction>-1e4</mechanicalReduction></actuator>"),
     "reduction -1e+08 is outside"),
    (SIMPLE.format("<joint name='j1'><mechanicalReduction>1e300</mechanicalReduction></joint>"
                   "<actuator name='m'><mechanicalReduction>1e300</mechanicalReduction></actuator>"), "outside"),
    (SIMPLE.format("<joint name='j1'/><joint name='j1'/><actuator name='a'/><actuator name='b'/>")
     .replace("Simple", "Differential"), "lists joint 'j1' twice"),
    (SIMPLE.format("<joint name='j1'/><joint name='j2'/><actuator name='a'><mechanicalReduction>1e200"
                   "</mechanicalReduction></actuator><actuator name='b'/>").replace("Simple", "Differential"),
     "singular matrix"),
    ("<transmission><type>x<sub>y</sub></type><joint name='j1'><joint name='j2'/></joint></transmission>",
     "applies only"),
])
def test_malformed_transmission_is_kept_with_its_problem_never_raised(body, words):
    (t,) = urdf_with(body).transmissions
    assert words in t.problem
    assert t.line == 9 and not t.matrix and not t.offsets


def test_no_transmission_no_field():
    assert urdf_with("").transmissions == ()
    assert math.isclose(urdf_with("<transmission name='t'><type>transmission_interface/SimpleTransmission</type>"
                                  "<joint name='j1'><mechanicalReduction>3</mechanicalReduction></joint>"
                                  "<actuator name='m'><mechanicalReduction>-2</mechanicalReduction></actuator>"
                                  "</transmission>").transmissions[0].reduction, -6.0)
