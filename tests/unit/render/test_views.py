"""The view-models of render/views.py, tested directly (the templates only place what they hold)."""
from __future__ import annotations

import re
from dataclasses import replace

import pytest

from rhi_gen.pipeline.load import load_robots
from rhi_gen.project import find_project
from rhi_gen.render.views import (
    ESTOP_INTERFACE,
    HEALTH_STATE_INTERFACES,
    controllers_view,
    package_view,
    update_rate_hz,
    xacro_default,
    xacro_text,
    xacro_view,
)
from tests.support.models import robot_model as _robot
from tests.support.repo import REPO


@pytest.mark.parametrize(("period", "rate"), [(2000, 500), (3000, 333), (1600, 625), (2_000_000, 1),
                                              (400_000, 2), (2_666_667, 1), (1_333_333, 1), (800, 1250)])
def test_update_rate_rounds_half_to_even_and_is_at_least_1(period, rate):
    assert update_rate_hz(period) == rate
    assert rate == max(round(1_000_000 / period), 1)


def test_package_view_declares_only_the_transports_in_use():
    unitree = package_view([_robot("unitree_dds", "unitree", "g1")])
    assert unitree.ros_deps == () and unitree.vendor_msgs == ""
    assert [d.name for d in unitree.plain_deps] == ["unitree_sdk2"]
    assert [(c.keyword, c.name, c.target_var) for c in unitree.plain_checks] == [
        ("if", "unitree_sdk2", "RHI_UNITREE_SDK2_TARGET")]
    assert unitree.found_keyword == "elseif" and len(unitree.plain_notes) == 1
    assert unitree.robots[0].target == "robot_hardware_interface_unitree_g1"
    assert unitree.robots[0].links == ("${RHI_UNITREE_SDK2_TARGET}",)

    mixed = package_view([_robot("agibot_topics", "agibot", "x2"), _robot("generic_topics", robot="b")])
    assert mixed.ros_deps == ("aimdk_msgs", "sensor_msgs") and mixed.vendor_msgs == "aimdk_msgs"
    assert mixed.plain_deps == () and mixed.found_keyword == "if" and mixed.plain_notes == ()
    assert mixed.robots[0].depends == ("aimdk_msgs", "sensor_msgs")
    assert mixed.robots[0].links == ("${aimdk_msgs_TARGETS}", "${sensor_msgs_TARGETS}")
    assert mixed.description == "agibot/ArmHardwareInterface, acme/ArmHardwareInterface" and mixed.imu

    custom = package_view([_robot("custom", imu=False)])
    assert custom.ros_deps == () and custom.plain_deps == () and custom.robots[0].links == ()
    assert not custom.imu
    assert package_view([]).description == "no robots yet"


def test_controllers_follow_the_transport_and_the_command_modes():
    with_gains = controllers_view(_robot("unitree_dds"))
    assert [(c.name, c.interface, [j.name for j in c.joints]) for c in with_gains.controllers] == [
        ("forward_position_controller", "position", ["shoulder"]),
        ("forward_velocity_controller", "velocity", ["wheel"]),
        ("forward_stiffness_controller", "stiffness", ["shoulder"]),
        ("forward_damping_controller", "damping", ["shoulder", "wheel"]),
    ]
    assert with_gains.gains and with_gains.limp_count == 1 and with_gains.velocity_count == 1
    assert (with_gains.update_rate, with_gains.period_us, with_gains.joint_count) == (500, 2000, 2)

    no_gains = controllers_view(_robot("generic_topics", period=3000))
    assert [c.name for c in no_gains.controllers] == ["forward_position_controller", "forward_velocity_controller"]
    assert not no_gains.gains and no_gains.update_rate == 333


def test_xacro_text_keeps_dollars_and_quotes_away_from_xacro():
    assert xacro_text("a$b") == 'a${"\\x24"}b'
    assert xacro_default("it's $x") == 'it${"\\x27"}s ${"\\x24"}x'
    assert xacro_default(2000) == "2000"


def test_xacro_view_interfaces_comments_and_defaults():
    robot = _robot("unitree_dds")
    grouped = replace(robot.joints[0], group="leg--x", group_position=3)
    view = xacro_view(replace(robot, joints=(grouped, robot.joints[1])))
    assert view.macro_name == "arm_ros2_control" and view.joint_count == 2
    assert view.defaults == {"name": "arm_hardware", "network_interface": "lo", "enable_monitor": "false",
                             "command_writer_period_us": "2000", "command_writer_mode": "timer",
                             "state_decimation": "1", "state_timeout_ms": "100",
                             "fault_timeout_ms": "1000", "first_state_timeout_ms": "10000", "calibration_file": "",
                             "is_async": "false", "rw_rate": "0"}
    shoulder, wheel = view.joints
    assert shoulder.comment == "SDK slot 0, group leg - -x[3]"
    first = shoulder.command_interfaces[0]
    assert (first.name, first.lower, first.upper) == ("position", -1.5, 1.5)
    assert all(i.lower is None for i in shoulder.command_interfaces[1:])
    assert wheel.comment == "SDK slot 1, velocity-commanded"
    assert [i.name for i in wheel.command_interfaces] == ["velocity", "damping", "effort"]


def test_views_of_the_reference_robots():
    """The repository's own robots (generated/ is checked byte for byte by test_generated_is_current)."""
    models = [r.model for r in load_robots(find_project(REPO))]
    view = package_view(sorted(models, key=lambda m: (m.vendor, m.robot)))
    assert view.ros_deps == ("aimdk_msgs", "geometry_msgs", "interface_protocol", "sensor_msgs")
    assert [t.fake_robot for t in view.robots] == ["x2_fake_robot", "pm01_fake_robot", "g1_fake_robot"]
    assert view.vendor_msgs == "aimdk_msgs, interface_protocol"
    assert [d.name for d in view.plain_deps] == ["unitree_sdk2"]
    x2 = next(m for m in models if m.robot == "x2")
    assert xacro_view(x2).joints[0].comment.startswith("SDK slot 0, group leg[0]")


def test_health_interfaces_are_the_ones_the_driver_provides():
    """The xacro and the controllers YAML name the health GPIO's interfaces from views.py; the driver
    looks them up in cpp/common/driver_health.hpp: the two lists must not drift apart."""

    header = (REPO / "rhi_gen/cpp/common/driver_health.hpp").read_text()
    table = header[header.index("kHealthStateInterfaces[]"):]
    table = table[:table.index("};")]
    assert tuple(re.findall(r'\{"([a-z_]+)", &DriverHealthData::\1\}', table)) == HEALTH_STATE_INTERFACES
    assert f'kEstopCommandInterface = "{ESTOP_INTERFACE}"' in header
