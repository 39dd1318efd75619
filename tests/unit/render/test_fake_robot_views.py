"""The fake robot's table (render/fake_robot_views.py): the motors as the firmware sees them."""
from __future__ import annotations

import math
from dataclasses import replace

from rhi_gen.model.robot import CoupledGroup, JointTransmission
from rhi_gen.model.urdf import JointLimits
from rhi_gen.render.fake_robot_views import fake_robot_view, has_fake_robot
from tests.support.models import robot_model


def _arm(transport: str = "generic_topics"):
    robot = robot_model(transport)
    first = replace(robot.joints[0], limits=JointLimits(-1.0, 2.0, 10.0, 20.0), inertia=0.8, damping=0.3,
                    initial_position=0.5)
    return replace(robot, joints=(first, *robot.joints[1:]))


def test_a_joint_that_is_its_motor_keeps_its_urdf_values():
    view = fake_robot_view(_arm())
    line = view.joints[0]
    assert (line.position_min, line.position_max, line.velocity_max, line.effort_max) == (-1.0, 2.0, 10.0, 20.0)
    assert (line.inertia, line.damping, line.initial_position) == (0.8, 0.3, 0.5)
    assert [j.slot for j in view.joints] == sorted(j.slot for j in view.joints)  # slot order
    assert view.node_name == f"{_arm().robot}_fake_robot" and view.rate_hz == 500.0


def test_a_simple_transmission_is_simulated_in_motor_units():
    """motor = direction * reduction * (joint - offset): limits -2 * ([-1, 2] - 0.1) = [-3.8, 2.2] (sorted),
    velocity times the reduction, effort divided by it, inertia by its square, the start pose mapped."""
    robot = _arm()
    geared = replace(robot.joints[0], transmission=JointTransmission(direction=-1, reduction=2.0, offset=0.1))
    line = fake_robot_view(replace(robot, joints=(geared, *robot.joints[1:]))).joints[0]
    assert math.isclose(line.position_min, -3.8) and math.isclose(line.position_max, 2.2)
    assert (line.velocity_max, line.effort_max, line.inertia) == (20.0, 10.0, 0.2)
    assert math.isclose(line.initial_position, -0.8)
    assert (line.gain, line.offset) == (-2.0, 0.1)  # for the physics, which simulates the URDF's joint


def test_the_physics_gets_the_urdf_the_imu_link_and_the_transmissions():
    robot = _arm()
    view = fake_robot_view(robot)
    assert view.urdf == f"urdf/{robot.robot}.urdf" and view.imu_link == robot.imu.frame_id
    assert not view.has_transmissions and all((j.gain, j.offset) == (1.0, 0.0) for j in view.joints)
    geared = replace(robot.joints[0], transmission=JointTransmission(direction=1, reduction=3.0))
    assert fake_robot_view(replace(robot, joints=(geared, *robot.joints[1:]))).has_transmissions
    assert fake_robot_view(replace(robot, imu=replace(robot.imu, enabled=False))).imu_link == ""


def test_coupled_motors_have_no_limits_and_a_continuous_joint_none_either():
    robot = _arm()
    names = (robot.joints[0].name, robot.joints[1].name)
    coupled = replace(robot, coupled_groups=(CoupledGroup("wrist", names, ((0.5, 0.5), (0.5, -0.5))),))
    for line in fake_robot_view(coupled).joints[:2]:
        assert (line.position_min, line.position_max, line.effort_max) == (-math.inf, math.inf, math.inf)
    spinning = replace(robot.joints[0], type="continuous")
    line = fake_robot_view(replace(robot, joints=(spinning, *robot.joints[1:]))).joints[0]
    assert (line.position_min, line.position_max) == (-math.inf, math.inf) and line.velocity_max == 10.0


def test_every_transport_but_custom_has_a_fake_robot():
    for transport in ("unitree_dds", "agibot_topics", "engineai_topics", "generic_topics"):
        assert has_fake_robot(robot_model(transport)), transport
    assert not has_fake_robot(robot_model("custom"))
