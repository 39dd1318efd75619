"""The ros2_control description checks: what a <ros2_control> block of a generated description must say.

Shared by the driver harness tests (tests/cpp/test_cpp_drivers.py, the macro alone) and the bring-up tests
(tests/cli/test_bringup.py, the complete description with and without mock hardware).
"""
from __future__ import annotations

import math
from pathlib import Path

from lxml import etree

from rhi_gen.model import RobotModel
from rhi_gen.transports import TRANSPORTS
from tests.support.cpp_build import Description, plugin_types, yaml_joint_map
from tests.support.xml_tree import attribute

IMU_INTERFACES = ["orientation.x", "orientation.y", "orientation.z", "orientation.w", "angular_velocity.x",
                  "angular_velocity.y", "angular_velocity.z", "linear_acceleration.x", "linear_acceleration.y",
                  "linear_acceleration.z"]
MOCK_PLUGIN = "mock_components/GenericSystem"
# The driver's health GPIO (docs/health-and-faults.md, "See the driver's health"), written out here independently
# of rhi_gen.
HEALTH_STATES = ["state_age_ms", "invalid_states", "stale_holds", "rejected_commands", "writer_overruns", "fault",
                 "estop"]


def motor_health(model: RobotModel) -> list[str]:
    """The motor health each robot's state message carries, from SDK_FACTS.md (written out here, not taken
    from rhi_gen): hg MotorState_ temperature / vol / motorstate, go MotorState_ temperature, AimDK hal
    JointState v1.0.0 error_code, EngineAI MotorDebug motor_temperature; the other transports none."""
    if model.transport == "unitree_dds":
        from rhi_gen.transports.unitree_dds.options import UnitreeDdsOptions

        assert isinstance(model.transport_options, UnitreeDdsOptions)
        family = model.transport_options.family
        return ["temperature", "voltage", "error_code"] if family == "hg" else ["temperature"]
    return {"agibot_topics": ["error_code"], "engineai_topics": ["temperature"]}.get(model.transport, [])


def params(element: etree._Element) -> dict[str, str]:
    return {attribute(p, "name"): (p.text or "").strip() for p in element.findall("param")}


def parse_ros2_control(xml: str | bytes) -> tuple[Description, etree._Element]:
    """The one <ros2_control> block of an expanded description (and the document's root)."""
    root = etree.fromstring(xml.encode("utf-8") if isinstance(xml, str) else xml)
    blocks = root.findall("ros2_control")
    assert len(blocks) == 1, f"expected one <ros2_control>, found {len(blocks)}"
    block = blocks[0]
    hardware = block.find("hardware")
    assert hardware is not None, "<ros2_control> has no <hardware>"

    def component(element: etree._Element) -> dict:
        return {
            "name": element.get("name"),
            "command_interfaces": [(c.get("name"), params(c)) for c in element.findall("command_interface")],
            "state_interfaces": [s.get("name") for s in element.findall("state_interface")],
            "initial_values": {s.get("name"): params(s).get("initial_value")
                               for s in element.findall("state_interface")},
            "parameters": params(element),
        }

    return Description(
        name=attribute(block, "name"), type=attribute(block, "type"),
        plugin=(hardware.findtext("plugin") or "").strip(), parameters=params(hardware),
        joints=[component(j) for j in block.findall("joint")],
        sensors=[component(s) for s in block.findall("sensor")],
        gpios=[component(g) for g in block.findall("gpio")]), root


def check_ros2_control(d: Description, model: RobotModel, yaml_path: Path, package_dir: Path, *,
                       mock: bool = False) -> None:
    """``d`` describes ``model``: exactly the YAML's mapped joints with the command interfaces of their mode,
    position/velocity/effort state, the IMU sensor, and the robot's plugin (or, ``mock``, GenericSystem)."""
    assert d.type == "system", d.type
    joint_map = yaml_joint_map(yaml_path)
    names = [j["name"] for j in d.joints]
    assert len(names) == len(set(names)), f"a joint is described twice: {names}"
    assert set(names) == set(joint_map), \
        f"description joints must be exactly the YAML's mapped joints: {sorted(set(names) ^ set(joint_map))}"
    gains = ["stiffness", "damping"] if TRANSPORTS[model.transport].carries_gains else []
    by_name = {j.name: j for j in model.joints}
    for j in d.joints:
        joint = by_name[j["name"]]
        expected = {"position": ["position", "velocity", *gains, "effort"],
                    "velocity": ["velocity", *gains[1:], "effort"],  # no position, no stiffness
                    "state": [],  # a leg under authority upper_body: state only
                    "position_target": ["position"]}[joint.command_mode]  # an OmniHand axis
        assert [c for c, _ in j["command_interfaces"]] == expected, j["name"]
        assert j["state_interfaces"] == ["position", "velocity", "effort", *motor_health(model)], j["name"]
        if "initial_values" not in j:  # tests/support/cpp_build.py expand_description reads only the names
            continue
        initial = {k: float(v) for k, v in j["initial_values"].items()}
        assert initial == {"position": joint.initial_position, "velocity": 0.0, "effort": 0.0,
                           **dict.fromkeys(motor_health(model), 0.0)}, j["name"]
        lim = joint.limits
        if joint.type in ("revolute", "prismatic") and lim is not None:
            assert (lim.lower is None or lim.lower <= initial["position"]) and \
                (lim.upper is None or initial["position"] <= lim.upper), f"{j['name']} starts outside its limits"
    if model.imu.enabled:
        assert [s["name"] for s in d.sensors] == [model.imu.name]
        assert d.sensors[0]["state_interfaces"] == IMU_INTERFACES
    if model.imu.enabled and "initial_values" in d.sensors[0]:
        orientation = [float(d.sensors[0]["initial_values"][f"orientation.{a}"]) for a in "xyzw"]
        assert math.isclose(math.hypot(*orientation), 1.0), f"IMU starts at a non-unit quaternion {orientation}"
    if not model.imu.enabled:
        assert d.sensors == []
    assert [g["name"] for g in d.gpios] == [f"{d.name}_health"], "one health GPIO named after the hardware"
    health = d.gpios[0]
    assert health["state_interfaces"] == HEALTH_STATES
    assert [c for c, _ in health["command_interfaces"]] == ["estop"]
    assert dict(health["command_interfaces"])["estop"].get("initial_value") == "0.0", "the e-stop starts released"
    if "initial_values" in health:
        assert health["initial_values"] == {n: "-1.0" if n == "state_age_ms" else "0.0" for n in HEALTH_STATES}
    if mock:
        assert d.plugin == MOCK_PLUGIN
        wheels = any(j.command_mode == "velocity" for j in model.joints)
        expected_params = {"calculate_dynamics": "true" if wheels else "false"}
        if model.imu.enabled:
            expected_params["mock_sensor_commands"] = "true"
        assert d.parameters == expected_params
        return
    assert d.plugin == model.plugin_name
    assert plugin_types(package_dir).get(d.plugin) == f"robot_hardware_interface::{model.vendor}::{model.class_name}"
    p = model.parameters
    assert d.parameters["command_writer_period_us"] == str(p.command_writer_period_us)
    assert d.parameters["state_decimation"] == str(p.state_decimation)
    assert d.parameters["enable_monitor"] == ("true" if p.enable_monitor else "false")


def exported(d: Description) -> tuple[set[str], set[str]]:
    """(command interfaces, state interfaces) the description exports, as "<component>/<interface>"."""
    commands = {f"{j['name']}/{c}" for j in (*d.joints, *d.gpios) for c, _ in j["command_interfaces"]}
    states = {f"{c['name']}/{s}" for c in (*d.joints, *d.sensors, *d.gpios) for s in c["state_interfaces"]}
    return commands, states
