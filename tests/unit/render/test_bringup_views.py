"""The view-models of render/bringup_views.py and the mock hardware part of render/views.py."""
from __future__ import annotations

import ast
from dataclasses import replace

from rhi_gen import transports
from rhi_gen.model import ImuConfig, JointLimits, MotorJoint, RobotModel
from rhi_gen.render.bringup_views import description_view, launch_view, start_controllers, urdf_view
from rhi_gen.render.views import mock_parameters, xacro_view
from tests.support.models import robot_model as _robot


def _position_only(robot: RobotModel) -> RobotModel:
    t = transports.get(robot.transport)
    return replace(robot, joints=(MotorJoint("knee", 0, "revolute", JointLimits(0.2, 1.5), initial_position=0.2,
                                             command_interfaces=t.command_interfaces("position")),))


def test_mock_hardware_computes_dynamics_only_for_wheels_and_mocks_the_imu():
    wheeled = _robot("unitree_dds")
    assert mock_parameters(wheeled) == (("calculate_dynamics", "true"), ("mock_sensor_commands", "true"))
    legged = _position_only(wheeled)
    assert mock_parameters(legged) == (("calculate_dynamics", "false"), ("mock_sensor_commands", "true"))
    assert mock_parameters(replace(legged, imu=ImuConfig(enabled=False))) == (("calculate_dynamics", "false"),)


def test_xacro_view_gives_initial_values():
    view = xacro_view(_position_only(_robot("unitree_dds")))
    assert [j.initial_position for j in view.joints] == ["0.2"]
    assert dict(view.imu_initial) == {"orientation.x": "0.0", "orientation.y": "0.0", "orientation.z": "0.0",
                                      "orientation.w": "1.0", "angular_velocity.x": "0.0",
                                      "angular_velocity.y": "0.0", "angular_velocity.z": "0.0",
                                      "linear_acceleration.x": "0.0", "linear_acceleration.y": "0.0",
                                      "linear_acceleration.z": "0.0"}


def test_start_controllers_activates_the_position_controller_or_else_the_velocity_one():
    wheeled = _robot("unitree_dds")
    assert start_controllers(wheeled) == (
        ("joint_state_broadcaster", "imu_sensor_broadcaster", "health_controller",
         "forward_position_controller"),
        ("forward_velocity_controller", "forward_stiffness_controller", "forward_damping_controller"))
    wheels_only = replace(wheeled, joints=wheeled.joints[1:], imu=ImuConfig(enabled=False))
    assert start_controllers(wheels_only) == (("joint_state_broadcaster", "health_controller",
                                               "forward_velocity_controller"),
                                              ("forward_damping_controller",))
    assert start_controllers(_robot("generic_topics"))[1] == ("forward_velocity_controller",)  # no gains


def test_urdf_view_puts_the_banner_after_the_xml_declaration():
    robot = _robot("generic_topics")
    view = urdf_view(replace(robot, urdf_xml='<?xml version="1.0" encoding="utf-8"?>\n\n<robot name="a"/>\n'))
    assert (view.prolog, view.body) == ('<?xml version="1.0" encoding="utf-8"?>\n', '<robot name="a"/>\n')
    view = urdf_view(replace(robot, urdf_xml='\ufeff<robot name="a"/>\n'))
    assert (view.prolog, view.body) == ("", '<robot name="a"/>\n')


def test_description_and_launch_views_keep_text_away_from_xacro_and_python():
    robot = replace(_robot("generic_topics"), urdf_name="my$robot", robot="arm")
    assert description_view(robot).robot_name == 'my${"\\x24"}robot'
    view = launch_view(robot)
    for argument in view.arguments:  # every field is a Python string literal
        assert isinstance(ast.literal_eval(argument.name), str)
        assert isinstance(ast.literal_eval(argument.default), str)
        assert isinstance(ast.literal_eval(argument.description), str)
    assert ast.literal_eval(view.robot) == "arm"


def test_urdf_copy_reads_back_unchanged_through_xacro(tmp_path):
    """The description includes the installed URDF through xacro: a ${...} or $(...) in the robot's own
    text (a link named like a shell variable, a comment-like attribute) must come out as it went in."""
    import xacro

    names = ["plain", "cost$5", "a${b}", "c$(find d)", "e$${f}", "g${1+1}", "tail$"]
    urdf = '<robot name="r">' + "".join(f'<link name="{n}"/>' for n in names) + "</robot>"
    robot = replace(_robot("unitree_dds"), urdf_xml=urdf)
    view = urdf_view(robot)
    (tmp_path / "r.urdf").write_text(view.prolog + view.body)
    (tmp_path / "d.xacro").write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                                      '<xacro:include filename="r.urdf"/></robot>')
    doc = xacro.process_file(str(tmp_path / "d.xacro"))
    assert [e.getAttribute("name") for e in doc.getElementsByTagName("link")] == names


def _root_urdf(root: str, *, inertia: bool, extra_links: str = "", extra_joint: str = "") -> bytes:
    inertial = '<inertial><mass value="3"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
    return (f'<?xml version="1.0"?>\n<robot name="r"><link name="{root}">{inertial if inertia else ""}</link>'
            f'<link name="leg"/>{extra_links}<joint name="hip" type="revolute"><parent link="{root}"/>'
            f'<child link="leg"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>{extra_joint}'
            f'</robot>\n').encode()


def test_a_root_link_with_an_inertia_gets_a_massless_root_above_it():
    """robot_state_publisher's KDL refuses a root link with an inertia (a warning on every launch): the
    installed URDF adds base_link, or <root>_root where base_link is taken, joined by a fixed joint."""
    from lxml import etree

    from rhi_gen.assemble.robot_model import kdl_root
    from rhi_gen.inputs.urdf_loader import parse_urdf_bytes

    assert kdl_root(parse_urdf_bytes(_root_urdf("pelvis", inertia=False), source="r.urdf")) is None
    plain = kdl_root(parse_urdf_bytes(_root_urdf("pelvis", inertia=True), source="r.urdf"))
    assert plain is not None
    assert (plain.link, plain.joint, plain.child) == ("base_link", "base_link_to_pelvis", "pelvis")
    taken = parse_urdf_bytes(_root_urdf("base_link", inertia=True, extra_links='<link name="base_link_root"/>',
                                        extra_joint='<joint name="f" type="fixed"><parent link="leg"/>'
                                                    '<child link="base_link_root"/></joint>'), source="r.urdf")
    other = kdl_root(taken)
    assert other is not None and (other.link, other.child) == ("base_link_root_", "base_link")
    # rendered: the URDF's bytes, then the new root before </robot>; a name xacro would evaluate stays literal
    robot = replace(_robot("unitree_dds"), urdf_xml=_root_urdf("${odd}&<", inertia=True).decode()
                    .replace('"${odd}&<"', '"${odd}&amp;&lt;"'))
    robot = replace(robot, kdl_root=kdl_root(parse_urdf_bytes(robot.urdf_xml.encode(), source="r.urdf")))
    view = urdf_view(robot)
    tree = etree.fromstring(view.body.replace("$${", "${").encode())
    assert [link.get("name") for link in tree.findall("link")][-1] == "base_link"
    joint = tree.findall("joint")[-1]
    assert (joint.get("type"), joint.findtext("missing"), [e.get("link") for e in joint]) == (
        "fixed", None, ["base_link", "${odd}&<"])
    assert view.prolog == '<?xml version="1.0"?>\n'
