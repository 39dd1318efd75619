"""View-models of a robot's bring-up files: the complete description, the installed URDF and the launch file.

- ``description_view``: description/<robot>.urdf.xacro (the robot's URDF + the generated ros2_control
  macro; every macro parameter a xacro argument).
- ``urdf_view``: urdf/<robot>.urdf (the robot's expanded URDF, installed with the package so the
  description and the launch file need nothing outside it).
- ``launch_view``: launch/<robot>.launch.py (its arguments and which controllers start active).

Text is prepared here and escaped by the filters / autoescape, as in render/views.py.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from html import escape, unescape

from ..model import RobotModel
from ..model.robot import KdlRoot
from .fake_robot_views import has_fake_robot
from .views import DESCRIPTION_ARGUMENTS, HEALTH_CONTROLLER, controllers_view, xacro_text

ARGUMENT_HELP = {
    "use_mock_hardware": "true: ros2_control's mock_components/GenericSystem instead of the robot (no hardware "
                         "needed)",
    "use_fake_robot": "true: also start <robot>_fake_robot, a simulated robot that answers the driver on the "
                      "robot's own topics, with ROS 2 discovery kept on this host (no robot needed)",
    "physics": "with use_fake_robot:=true, how its joints move: vacuum (alone, no gravity) or mujoco (the robot "
               "compiled by MuJoCo from description_file: gravity, a floor, its links' coupling, hung in an elastic "
               "band; the package must be built with MuJoCo, docs/try-without-the-robot.md)",
    "physics_base": "with physics:=mujoco, how the robot's base is held: band (an elastic band above it; `ros2 param "
                    "set /<robot>_fake_robot release_band true` lets go), free (it stands or falls), fixed (welded to "
                    "the world: an arm)",
    "network_interface": "network interface of the robot (driver parameter network_interface)",
    "enable_monitor": "true: the driver warns on the console about read/write latency and send jitter above "
                      "its thresholds, for timing bring-up (driver parameter enable_monitor)",
    "command_writer_period_us": "period of the command writer in microseconds",
    "command_writer_mode": "timer: the command writer sends every command_writer_period_us; on_write: it sends each "
                           "command as soon as write() has built it (at most one per period on average)",
    "state_decimation": "process every n-th state message",
    "state_timeout_ms": "milliseconds without state before the driver holds the joints",
    "fault_timeout_ms": "milliseconds without state before read() returns ERROR (the link is dead)",
    "first_state_timeout_ms": "milliseconds after activation to wait for the robot's first state (DDS discovery) "
                              "before read() returns ERROR",
    "calibration_file": "the motors' calibration file (driver parameter calibration_file; '': none)",
    "is_async": "true: ros2_control runs the driver's read() and write() in a thread of their own (Jazzy and "
                "later)",
    "rw_rate": "read() and write() per second (Jazzy and later; 0: the controller manager's update rate)",
    "description_file": "the robot's URDF the description includes ('': urdf/<robot>.urdf of the package)",
    "controllers_file": "controller manager parameters and controllers ('': config/<robot>_controllers.yaml)",
    "active_controllers": "controllers to activate (names in the controllers file, space-separated)",
    "inactive_controllers": "controllers to load without activating them (space-separated)",
}


def argument_defaults(robot: RobotModel) -> tuple[tuple[str, str], ...]:
    """(argument, default) of the description: use_mock_hardware, then the transport parameters."""
    p = robot.parameters
    values = {"network_interface": p.network_interface, "enable_monitor": "true" if p.enable_monitor else "false",
              "command_writer_period_us": str(p.command_writer_period_us),
              "command_writer_mode": p.command_writer_mode,
              "state_decimation": str(p.state_decimation), "state_timeout_ms": str(p.state_timeout_ms),
              "fault_timeout_ms": str(p.fault_timeout_ms), "first_state_timeout_ms": str(p.first_state_timeout_ms),
              "calibration_file": "", "is_async": "true" if p.is_async else "false", "rw_rate": str(p.rw_rate)}
    return (("use_mock_hardware", "false"), *((name, values[name]) for name in DESCRIPTION_ARGUMENTS[1:]))


@dataclass(frozen=True)
class DescriptionView:
    robot_name: str                          # the URDF's <robot name>, xacro_text
    macro_name: str
    macro_file: str                          # <robot>.ros2_control.xacro, beside the description
    urdf_file: str                           # <robot>.urdf, in ../urdf/
    arguments: tuple[tuple[str, str], ...]   # xacro:arg name -> default (xacro_text)


def description_view(robot: RobotModel) -> DescriptionView:
    return DescriptionView(
        robot_name=xacro_text(robot.urdf_name or robot.robot), macro_name=f"{robot.robot}_ros2_control",
        macro_file=f"{robot.robot}.ros2_control.xacro", urdf_file=f"{robot.robot}.urdf",
        arguments=tuple((name, xacro_text(value)) for name, value in argument_defaults(robot)))


@dataclass(frozen=True)
class UrdfView:
    prolog: str   # the XML declaration line(s) before the banner, "" when the URDF has none
    body: str     # the rest of the expanded URDF, byte for byte


_XACRO_SUBSTITUTION = re.compile(r"\$+(?=[{(])")
_MESH_FILENAME = re.compile(r"(<mesh\b[^>]*?\bfilename\s*=\s*)([\"'])(.*?)\2", re.S)


def xacro_literal(text: str) -> str:
    """``text`` as xacro reads it back unchanged: description/<robot>.urdf.xacro includes the URDF, so
    xacro would evaluate a ``${...}`` or ``$(...)`` in it; one more ``$`` before each makes it literal."""
    return _XACRO_SUBSTITUTION.sub(lambda m: "$" + m.group(0), text)


def urdf_view(robot: RobotModel) -> UrdfView:
    """The expanded URDF split after its XML declaration, so the banner comment can follow it; xacro
    substitutions escaped, since the description includes it through xacro; a massless root added before
    the closing </robot> where the robot's root link has an inertia (model KdlRoot)."""
    text = robot.urdf_xml.lstrip("\ufeff")
    prolog = ""
    if text.startswith("<?xml"):
        end = text.index("?>") + 2
        prolog, text = text[:end] + "\n", text[end:].lstrip("\n")
    if robot.kdl_root is not None:
        close = text.rindex("</robot>")
        text = text[:close] + kdl_root_xml(robot.kdl_root) + text[close:]
    return UrdfView(prolog=prolog, body=xacro_literal(packaged_meshes(text, robot)))


def packaged_meshes(text: str, robot: RobotModel) -> str:
    """``text`` with each mesh the package carries (model MeshCopy) named by its package:// URI; every
    other byte, and every other mesh reference, as it was."""
    uris = {m.reference: m.uri for m in robot.meshes}
    if not uris:
        return text

    def swap(match: re.Match[str]) -> str:
        uri = uris.get(unescape(match.group(3)).strip())
        if uri is None:
            return match.group(0)
        return f"{match.group(1)}{match.group(2)}{escape(uri, quote=True)}{match.group(2)}"

    return _MESH_FILENAME.sub(swap, text)


def kdl_root_xml(root: KdlRoot) -> str:
    """The massless root link and its fixed joint, indented as the usual URDF's top-level elements."""
    link, joint, child = (escape(name, quote=True) for name in (root.link, root.joint, root.child))
    return (f"  <!-- rhi-gen: robot_state_publisher (KDL) does not accept a root link with an inertia: a\n"
            f"       massless root above {child.replace('--', '- -')}, as ROS descriptions have it -->\n"
            f"  <link name=\"{link}\"/>\n"
            f"  <joint name=\"{joint}\" type=\"fixed\">\n"
            f"    <parent link=\"{link}\"/>\n"
            f"    <child link=\"{child}\"/>\n"
            f"  </joint>\n")


@dataclass(frozen=True)
class LaunchArgument:
    name: str          # a Python string literal
    default: str       # a Python string literal
    description: str   # a Python string literal


@dataclass(frozen=True)
class LaunchView:
    robot: str                               # Python string literal of the robot name
    arguments: tuple[LaunchArgument, ...]    # declared, in order, and passed to launch/bringup.launch.py
    active: tuple[str, ...]                  # controllers activated by default
    inactive: tuple[str, ...]                # the others, loaded inactive


def start_controllers(robot: RobotModel) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(active, inactive) controllers of config/<robot>_controllers.yaml: the joint state broadcaster, the
    IMU broadcaster, the health controller (the driver's health and its e-stop, ready from the start) and
    the position controller (the velocity controller when no joint is position-commanded) and the hands'
    position controller start active; the other forward controllers are loaded inactive."""
    forward = [c.name for c in controllers_view(robot).controllers]
    main = "forward_position_controller" if "forward_position_controller" in forward else forward[0]
    hands = tuple(name for name in forward if name == "hand_position_controller" and name != main)
    active = ("joint_state_broadcaster", *(("imu_sensor_broadcaster",) if robot.imu.enabled else ()),
              HEALTH_CONTROLLER, main, *hands)
    return active, tuple(name for name in forward if name != main and name not in hands)


def launch_view(robot: RobotModel) -> LaunchView:
    active, inactive = start_controllers(robot)
    description = argument_defaults(robot)
    fake = (("use_fake_robot", "false"), ("physics", "vacuum"), ("physics_base", "band")) \
        if has_fake_robot(robot) else ()
    defaults = (description[0], *fake, *description[1:], ("description_file", ""), ("controllers_file", ""),
                ("active_controllers", " ".join(active)), ("inactive_controllers", " ".join(inactive)))
    return LaunchView(
        robot=repr(robot.robot),
        arguments=tuple(LaunchArgument(repr(name), repr(value), repr(ARGUMENT_HELP[name])) for name, value in defaults),
        active=active, inactive=inactive)
