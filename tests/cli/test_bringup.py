"""Bring-up: the complete description, mock hardware and the launch files of every robot.

For every reference robot and every test robot (each transport: unitree hg and go, agibot, engineai,
generic_topics, custom): description/<robot>.urdf.xacro expands with the real xacro (its command line,
as a user runs it) for both values of use_mock_hardware, both pass the ros2_control description checks
(tests/support/description_checks.py) and name the same joints, interfaces and sensors; the mock one names
mock_components/GenericSystem and its parameters. launch/<robot>.launch.py is loaded with the launch stand-in
(tests/support/launch_standin.py) and run: its arguments, the nodes it starts, and the controllers its
spawners name (each in the controllers YAML, claiming interfaces the description exports).
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from lxml import etree

from rhi_gen.render.bringup_views import start_controllers
from rhi_gen.render.fake_robot_views import has_fake_robot
from tests.support.cli import run_cli
from tests.support.cpp_build import PACKAGE, load_models, make_test_project, project_robot_labels, render_package_to
from tests.support.description_checks import check_ros2_control, exported, parse_ros2_control
from tests.support.launch_standin import LaunchContext, Launched, StartedNode, launch, load_launch_file
from tests.support.repo import URDF_FIXTURES, copy_project

LABELS = project_robot_labels()
XACRO = Path(sys.executable).parent / "xacro"
DESCRIPTION_ARGUMENTS = ["use_mock_hardware", "network_interface", "enable_monitor", "command_writer_period_us",
                         "command_writer_mode", "state_decimation", "state_timeout_ms", "fault_timeout_ms",
                         "first_state_timeout_ms", "calibration_file", "is_async", "rw_rate"]
LAUNCH_ARGUMENTS = [*DESCRIPTION_ARGUMENTS, "description_file", "controllers_file", "active_controllers",
                    "inactive_controllers"]


@pytest.fixture(scope="module")
def package(tmp_path_factory):
    """The package of every robot of robots/ and of the harness's test robots, rendered once."""
    root = tmp_path_factory.mktemp("bringup")
    loaded = load_models(make_test_project(root / "project"))
    package_dir = root / "share" / PACKAGE  # laid out as installed: description/, urdf/, config/, launch/
    render_package_to(loaded, package_dir)
    return package_dir, {f"{r.model.vendor}/{r.model.robot}": r for r in loaded}


def xacro(path: Path, *args: str) -> str:
    """The real xacro, from another folder, as `xacro <robot>.urdf.xacro NAME:=VALUE` is run by a user."""
    result = subprocess.run([str(XACRO), str(path), *args], capture_output=True, text=True, cwd="/")
    assert result.returncode == 0 and not result.stderr, f"xacro {path.name} {' '.join(args)}:\n{result.stderr}"
    return result.stdout


def _attr(element: etree._Element, path: str, name: str) -> str | None:
    """Attribute ``name`` of the element at ``path`` below ``element``, which must exist."""
    found = element.find(path)
    assert found is not None, f"no <{path}> in <{element.tag!r}>"
    return found.get(name)


def interfaces(d) -> dict:
    """Everything but the <hardware>: what mock and real must share."""
    return {"joints": d.joints, "sensors": d.sensors, "name": d.name, "type": d.type}


@pytest.mark.parametrize("label", LABELS)
def test_description_expands_for_the_robot_and_for_mock_hardware(package, label):
    package_dir, robots = package
    r = robots[label]
    path = package_dir / "description" / f"{r.model.robot}.urdf.xacro"
    real, real_root = parse_ros2_control(xacro(path))
    mock, mock_root = parse_ros2_control(xacro(path, "use_mock_hardware:=true"))
    check_ros2_control(real, r.model, r.yaml_path, package_dir)
    check_ros2_control(mock, r.model, r.yaml_path, package_dir, mock=True)
    assert interfaces(mock) == interfaces(real)
    assert parse_ros2_control(xacro(path, "use_mock_hardware:=false"))[0] == real  # the default is the robot
    # the whole robot: every link and joint of its URDF, under the URDF's robot name, and where the URDF's
    # root link has an inertia a massless root above it (KDL, robot_state_publisher, refuses that root)
    added = r.model.kdl_root
    assert (added is not None) == r.urdf.root_has_inertia
    for root in (real_root, mock_root):
        assert root.get("name") == r.urdf.name
        assert [j.get("name") for j in root.findall("joint")] == [j.name for j in r.urdf.joints] + (
            [added.joint] if added else [])
        assert [link.get("name") for link in root.findall("link")] == list(r.urdf.links) + (
            [added.link] if added else [])
        children = {_attr(j, "child", "link") for j in root.findall("joint")}
        tops = [link for link in root.findall("link") if link.get("name") not in children]
        assert len(tops) == 1 and tops[0].find("inertial") is None, f"{label}: the root link has an inertia"
        if added:
            joint = root.findall("joint")[-1]
            assert (joint.get("type"), _attr(joint, "parent", "link"), _attr(joint, "child", "link")) == (
                "fixed", added.link, r.urdf.root_link)
            assert joint.find("origin") is None  # the identity: the robot's frames stay where they were


def test_description_arguments_reach_the_driver(package):
    package_dir, _ = package
    path = package_dir / "description" / "g1.urdf.xacro"
    d, _ = parse_ros2_control(xacro(path, "network_interface:=enp3s0", "enable_monitor:=false",
                                    "command_writer_period_us:=5000", "command_writer_mode:=on_write",
                                    "state_decimation:=4", "state_timeout_ms:=250",
                                    "fault_timeout_ms:=3000", "first_state_timeout_ms:=20000"))
    assert d.parameters == {"network_interface": "enp3s0", "enable_monitor": "false",
                            "command_writer_period_us": "5000", "command_writer_mode": "on_write",
                            "state_decimation": "4", "state_timeout_ms": "250",
                            "fault_timeout_ms": "3000", "first_state_timeout_ms": "20000"}


def test_calibration_file_is_a_description_argument(package):
    """calibration_file:=<file> reaches the <hardware> as the driver's parameter; empty (the default) adds none."""
    package_dir, _ = package
    path = package_dir / "description" / "pm01.urdf.xacro"
    given, _ = parse_ros2_control(xacro(path, "calibration_file:=/opt/robot/pm01 calibration.yaml"))
    assert given.parameters["calibration_file"] == "/opt/robot/pm01 calibration.yaml"
    assert "calibration_file" not in parse_ros2_control(xacro(path))[0].parameters
    assert "calibration_file" not in parse_ros2_control(xacro(path, "calibration_file:="))[0].parameters
    mock, _ = parse_ros2_control(xacro(path, "use_mock_hardware:=true", "calibration_file:=/c.yaml"))
    assert "calibration_file" not in mock.parameters  # mock hardware has no motors to calibrate


def test_async_attributes_are_description_arguments(package):
    """is_async and rw_rate are attributes of <ros2_control> (ros2_control's parser reads them there)."""
    package_dir, _ = package
    path = package_dir / "description" / "pm01.urdf.xacro"
    default = etree.fromstring(xacro(path).encode())
    assert (_attr(default, "ros2_control", "is_async"), _attr(default, "ros2_control", "rw_rate")) == ("false", "0")
    for given in ("true", "True"):  # xacro turns a bare true into True: the description normalises it
        root = etree.fromstring(xacro(path, f"is_async:={given}", "rw_rate:=250").encode())
        assert (_attr(root, "ros2_control", "is_async"), _attr(root, "ros2_control", "rw_rate")) == ("true", "250")


def test_description_takes_another_urdf(package, tmp_path):
    package_dir, _ = package
    urdf = tmp_path / "mine.urdf"
    urdf.write_text((package_dir / "urdf" / "scara.urdf").read_text().replace('<link name="base_link"',
                                                                                '<link name="extra_link"/>\n  '
                                                                                '<link name="base_link"'))
    _, root = parse_ros2_control(xacro(package_dir / "description" / "scara.urdf.xacro", f"description_file:={urdf}"))
    assert "extra_link" in [link.get("name") for link in root.findall("link")]


def test_the_macro_alone_still_defaults_to_the_robot(package, tmp_path):
    """Users who include <robot>.ros2_control.xacro from their own description get the driver, as before."""
    package_dir, robots = package
    r = robots["unitree/g1"]
    wrapper = tmp_path / "mine.urdf.xacro"
    wrapper.write_text('<?xml version="1.0"?>\n<robot name="mine" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                       f'  <xacro:include filename="{package_dir}/description/g1.ros2_control.xacro"/>\n'
                       '  <xacro:g1_ros2_control name="g1_hardware"/>\n</robot>\n')
    d, _ = parse_ros2_control(xacro(wrapper))
    check_ros2_control(d, r.model, r.yaml_path, package_dir)


# ---------------------------------------------------------------- launch files
def run(package_dir: Path, robot: str, **overrides: str) -> Launched:
    return launch(package_dir / "launch" / f"{robot}.launch.py", {PACKAGE: package_dir}, overrides)


def node(launched: Launched, executable: str) -> list[StartedNode]:
    return [n for n in launched.nodes if n.executable == executable]


def spawned(spawners: list[StartedNode], controllers_file: Path | None = None) -> tuple[list[str], list[str]]:
    """(activated, loaded inactive) controller names of the spawners (parsed as the spawner's argparse
    does: names, then the flags); each passes the controllers file and the controller manager."""
    active: list[str] = []
    inactive: list[str] = []
    for s in spawners:
        assert s.package == "controller_manager"
        args = s.arguments
        assert args[-4:-2] == ["--param-file", str(controllers_file or args[-3])], args
        assert args[-2:] == ["--controller-manager", "/controller_manager"], args
        flags = args[:-4]
        names = [a for a in flags if not a.startswith("--")]
        assert flags == [*names, *(["--inactive"] if "--inactive" in flags else [])], args
        (inactive if "--inactive" in flags else active).extend(names)
    return active, inactive


def check_controllers(launched: Launched, description, controllers_file: Path, model) -> None:
    """Every spawned controller is in the controllers YAML with a type, and claims (or reads) interfaces
    the description exports; every controller of the YAML is spawned."""
    data = yaml.safe_load(controllers_file.read_text())
    manager = data["controller_manager"]["ros__parameters"]
    declared = {name for name, value in manager.items() if isinstance(value, dict) and "type" in value}
    active, inactive = spawned(node(launched, "spawner"), controllers_file)
    assert sorted(active + inactive) == sorted(declared), "every controller of the YAML is spawned once"
    commands, states = exported(description)
    for name in active + inactive:
        kind = manager[name]["type"]
        params = data.get(name, {}).get("ros__parameters", {})
        if kind == "forward_command_controller/ForwardCommandController":
            claimed = {f"{j}/{params['interface_name']}" for j in params["joints"]}
            assert params["joints"] and claimed <= commands, f"{name} claims {sorted(claimed - commands)}"
        elif kind == "gpio_controllers/GpioCommandController":
            # generate_parameter_library's maps: <key>.<gpio>.interfaces (a list there is not read)
            gpios = params["gpios"]
            claimed = {f"{g}/{i}" for g in gpios for i in params["command_interfaces"][g]["interfaces"]}
            read = {f"{g}/{i}" for g in gpios for i in params["state_interfaces"][g]["interfaces"]}
            assert gpios == [f"{description.name}_health"], gpios
            assert claimed == {f"{gpios[0]}/estop"} and claimed <= commands, sorted(claimed)
            assert read and read <= states, f"{name} reads {sorted(read - states)}"
        elif kind == "imu_sensor_broadcaster/IMUSensorBroadcaster":
            assert model.imu.enabled
            assert {f"{params['sensor_name']}/{i}" for i in ("orientation.w", "angular_velocity.x")} <= states
        else:
            assert kind == "joint_state_broadcaster/JointStateBroadcaster", kind
            assert {f"{j.name}/position" for j in model.joints} <= states


def test_launch_applies_a_calibration_file(package, tmp_path) -> None:
    """`ros2 launch robot_hardware_interface pm01.launch.py calibration_file:=<file>`: the file reaches the
    <hardware> of the description robot_state_publisher and the controller manager get (expanded by the real
    xacro); is_async and rw_rate reach <ros2_control>."""
    package_dir, _ = package
    calibration = tmp_path / "pm01 calibration.yaml"
    calibration.write_text("J00_HIP_PITCH_L: {offset: 0.01}\n")
    launched = run(package_dir, "pm01", calibration_file=str(calibration), is_async="true", rw_rate="250")
    (rsp,) = node(launched, "robot_state_publisher")
    (description_xml,) = [p["robot_description"] for p in rsp.parameters if isinstance(p, dict)]
    d, root = parse_ros2_control(description_xml)
    assert d.parameters["calibration_file"] == str(calibration)
    assert (_attr(root, "ros2_control", "is_async"), _attr(root, "ros2_control", "rw_rate")) == ("true", "250")
    (default_rsp,) = node(run(package_dir, "pm01"), "robot_state_publisher")
    (default_xml,) = [p["robot_description"] for p in default_rsp.parameters if isinstance(p, dict)]
    assert "calibration_file" not in parse_ros2_control(default_xml)[0].parameters


@pytest.mark.parametrize("mock", [False, True], ids=["robot", "mock"])
@pytest.mark.parametrize("label", LABELS)
def test_launch_file_starts_the_robot(package, label, mock) -> None:
    package_dir, robots = package
    r = robots[label]
    m = r.model
    launched = run(package_dir, m.robot, **({"use_mock_hardware": "true"} if mock else {}))

    fake = has_fake_robot(m)
    assert list(launched.arguments) == [LAUNCH_ARGUMENTS[0],
                                        *(["use_fake_robot", "physics", "physics_base"] if fake else []),
                                        *LAUNCH_ARGUMENTS[1:]]
    defaults = {}
    for name, a in launched.arguments.items():
        assert a.default_value is not None, f"launch argument {name!r} has no default"
        defaults[name] = "".join(s.perform(LaunchContext({})) for s in a.default_value)
    p = m.parameters
    assert defaults == {
        "use_mock_hardware": "false",
        **({"use_fake_robot": "false", "physics": "vacuum", "physics_base": "band"} if fake else {}),
        "network_interface": p.network_interface,
        "enable_monitor": "true" if p.enable_monitor else "false",
        "command_writer_period_us": str(p.command_writer_period_us),
        "command_writer_mode": p.command_writer_mode, "state_decimation": str(p.state_decimation),
        "state_timeout_ms": str(p.state_timeout_ms), "fault_timeout_ms": str(p.fault_timeout_ms),
        "first_state_timeout_ms": str(p.first_state_timeout_ms), "calibration_file": "",
        "is_async": "true" if p.is_async else "false", "rw_rate": str(p.rw_rate),
        "description_file": "", "controllers_file": "",
        "active_controllers": " ".join(start_controllers(m)[0]),
        "inactive_controllers": " ".join(start_controllers(m)[1])}
    assert all(a.description for a in launched.arguments.values())

    assert sorted(n.executable for n in launched.nodes) == \
        ["robot_state_publisher", "ros2_control_node", "spawner", *(["spawner"] if start_controllers(m)[1] else [])]
    (rsp,) = node(launched, "robot_state_publisher")
    assert rsp.package == "robot_state_publisher"
    (description_xml,) = [p["robot_description"] for p in rsp.parameters if isinstance(p, dict)]
    d, _ = parse_ros2_control(description_xml)
    check_ros2_control(d, m, r.yaml_path, package_dir, mock=mock)

    (cm,) = node(launched, "ros2_control_node")
    assert cm.package == "controller_manager"
    controllers_file = package_dir / "config" / f"{m.robot}_controllers.yaml"
    assert cm.parameters == [str(controllers_file)]
    assert cm.remappings == [("~/robot_description", "/robot_description")]
    active, _ = spawned(node(launched, "spawner"))
    assert active == ["joint_state_broadcaster", *(["imu_sensor_broadcaster"] if m.imu.enabled else []),
                      "health_controller",
                      "forward_position_controller" if any(j.command_mode == "position" for j in m.joints)
                      else "forward_velocity_controller",
                      # hands: their own position controller, beside the body's
                      *(["hand_position_controller"] if m.hands != "none" else [])]
    check_controllers(launched, d, controllers_file, m)


def test_launch_arguments_choose_controllers_files_and_parameters(package, tmp_path):
    package_dir, _ = package
    urdf = tmp_path / "my robots" / "g1 (Bob's).urdf"  # a space and a quote: the xacro command quotes it
    urdf.parent.mkdir()
    urdf.write_text((package_dir / "urdf" / "g1.urdf").read_text())
    controllers = tmp_path / "mine.yaml"
    controllers.write_text((package_dir / "config" / "g1_controllers.yaml").read_text())
    launched = run(package_dir, "g1", use_mock_hardware="true", network_interface="enp3s0",
                   active_controllers="joint_state_broadcaster", inactive_controllers="",
                   description_file=str(urdf), controllers_file=str(controllers))
    spawners = node(launched, "spawner")
    assert spawned(spawners, controllers) == (["joint_state_broadcaster"], [])
    assert node(launched, "ros2_control_node")[0].parameters == [str(controllers)]
    (rsp,) = node(launched, "robot_state_publisher")
    d, _ = parse_ros2_control(rsp.parameters[0]["robot_description"])
    assert d.plugin == "mock_components/GenericSystem"
    real = run(package_dir, "g1", network_interface="enp3s0", state_decimation="4")
    d, _ = parse_ros2_control(node(real, "robot_state_publisher")[0].parameters[0]["robot_description"])
    assert (d.parameters["network_interface"], d.parameters["state_decimation"]) == ("enp3s0", "4")


@pytest.mark.parametrize("distro", ["humble", "jazzy", ""])
def test_use_fake_robot_starts_it_first_with_discovery_on_this_host(package, monkeypatch, distro) -> None:
    """use_fake_robot:=true: the fake robot starts before the other nodes, the real driver (not mock hardware)
    answers it, and every node inherits discovery limited to this host (Humble's variable on Humble,
    Jazzy's after; both when ROS_DISTRO is unknown), static peers cleared."""
    package_dir, _ = package
    monkeypatch.setenv("ROS_DISTRO", distro)
    launched = run(package_dir, "pm01", use_fake_robot="true")
    assert [n.executable for n in launched.nodes][:2] == ["pm01_fake_robot", "robot_state_publisher"]
    assert node(launched, "pm01_fake_robot")[0].package == PACKAGE
    want = {"ROS_STATIC_PEERS": "", **({"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"} if distro != "humble" else {}),
            **({"ROS_LOCALHOST_ONLY": "1"} if distro in ("humble", "") else {})}
    assert all(n.environment == want for n in launched.nodes)
    d, _ = parse_ros2_control(node(launched, "robot_state_publisher")[0].parameters[0]["robot_description"])
    assert d.plugin == "robot_hardware_interface/engineai/PM01HardwareInterface"
    # the G1 (unitree_sdk2): its fake robot is on lo, so the driver is too, whatever network_interface says
    g1 = run(package_dir, "g1", use_fake_robot="true", network_interface="eth0")
    d, _ = parse_ros2_control(node(g1, "robot_state_publisher")[0].parameters[0]["robot_description"])
    assert d.parameters["network_interface"] == "lo" and node(g1, "g1_fake_robot")
    plain = run(package_dir, "pm01")
    assert not node(plain, "pm01_fake_robot") and all(not n.environment for n in plain.nodes)
    with pytest.raises(RuntimeError, match="use_fake_robot:=true and use_mock_hardware:=true exclude each other"):
        run(package_dir, "pm01", use_fake_robot="true", use_mock_hardware="true")


def test_physics_argument_chooses_the_fake_robots_physics(package, tmp_path) -> None:
    """physics (next to use_fake_robot, default vacuum): passed to the fake robot as --physics; mujoco also hands
    it physics_base (--base, default band) and the URDF the description includes (--urdf: the package's, or
    description_file). A value it does not know, or mujoco without the fake robot, stops the launch with one
    line."""
    package_dir, _ = package
    launched = run(package_dir, "pm01", use_fake_robot="true")
    assert "mujoco" in (launched.arguments["physics"].description or "")
    assert node(launched, "pm01_fake_robot")[0].arguments == ["--physics", "vacuum"]
    mujoco = run(package_dir, "pm01", use_fake_robot="true", physics="mujoco")
    assert node(mujoco, "pm01_fake_robot")[0].arguments == \
        ["--physics", "mujoco", "--base", "band", "--urdf", f"{package_dir}/urdf/pm01.urdf"]
    mine = tmp_path / "my pm01.urdf"
    mine.write_text((package_dir / "urdf" / "pm01.urdf").read_text())
    chosen = run(package_dir, "pm01", use_fake_robot="true", physics="mujoco", physics_base="fixed",
                 description_file=str(mine))
    assert node(chosen, "pm01_fake_robot")[0].arguments == ["--physics", "mujoco", "--base", "fixed", "--urdf",
                                                            str(mine)]
    with pytest.raises(RuntimeError, match=r"^physics:=bullet: expected vacuum or mujoco$"):
        run(package_dir, "pm01", use_fake_robot="true", physics="bullet")
    with pytest.raises(RuntimeError, match=r"^physics_base:=floating: expected band, free or fixed$"):
        run(package_dir, "pm01", use_fake_robot="true", physics="mujoco", physics_base="floating")
    with pytest.raises(RuntimeError, match=r"^physics:=mujoco is the fake robot's physics: add use_fake_robot:=true$"):
        run(package_dir, "pm01", physics="mujoco")


def test_launch_standin_rejects_what_the_real_api_rejects(package, tmp_path) -> None:
    """The stand-in keeps the real signatures: keyword-only arguments, required arguments of an include."""
    from tests.support import launch_standin as ls

    with pytest.raises(TypeError):
        ls.Node("controller_manager", "spawner")  # type: ignore[call-arg]  # keyword-only in launch_ros
    with pytest.raises(TypeError):
        ls.DeclareLaunchArgument("a", "default")  # type: ignore[call-arg]  # default_value is keyword-only
    package_dir, _ = package
    with pytest.raises(RuntimeError, match="launch argument 'robot' was not provided"):
        launch(package_dir / "launch" / "bringup.launch.py", {PACKAGE: package_dir})
    partial = tmp_path / "partial.launch.py"
    partial.write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "def generate_launch_description():\n"
        f"    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource("
        f"{str(package_dir / 'launch' / 'bringup.launch.py')!r}), launch_arguments=[('robot', 'g1')])])\n")
    with pytest.raises(RuntimeError, match="missing required argument 'use_mock_hardware'"):
        launch(partial, {PACKAGE: package_dir})
    assert load_launch_file(package_dir / "launch" / "bringup.launch.py").entities


# ---------------------------------------------------------------- the commands around it
def test_new_writes_a_safe_pose_and_prints_the_bringup_commands(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text((URDF_FIXTURES / "simple_arm.urdf").read_text().replace('lower="-2.5" upper="2.5"',
                                                                            'lower="0.2" upper="2.5"'))
    (tmp_path / "p").mkdir()
    result = run_cli("new", "--vendor", "acme", "--robot", "arm", "--urdf", urdf, "--project", tmp_path / "p")
    assert result.code == 0, result.err
    data = yaml.safe_load((tmp_path / "p/robots/acme/arm.yaml").read_text())
    assert data["initial_positions"] == {"shoulder_pan": 0.0, "shoulder_lift": 0.0, "elbow": 0.2}
    lines = result.out.splitlines()
    launch_command = "ros2 launch robot_hardware_interface arm.launch.py"
    assert lines[-3:] == [f"  without the robot: {launch_command} use_mock_hardware:=true",
                          f"  with a fake robot: {launch_command} use_fake_robot:=true",
                          f"  on the robot:      {launch_command}"]
    package_dir = tmp_path / "p/generated" / PACKAGE
    launched = launch(package_dir / "launch" / "arm.launch.py", {PACKAGE: package_dir}, {"use_mock_hardware": "true"})
    d, _ = parse_ros2_control(node(launched, "robot_state_publisher")[0].parameters[0]["robot_description"])
    assert [float(j["initial_values"]["position"]) for j in d.joints] == [0.0, 0.0, 0.2]


def test_check_notices_a_stale_launch_file_and_description_and_regions_survive(tmp_path):
    project = copy_project(tmp_path, generated=True)
    launch_file = project / "generated" / PACKAGE / "launch" / "g1.launch.py"
    description = project / "generated" / PACKAGE / "description" / "g1.urdf.xacro"
    for path in (launch_file, description):
        clean = path.read_text()
        path.write_text(clean.replace("use_mock_hardware", "use_fake_hardware", 1))
        result = run_cli("check", "--project", project)
        assert result.code == 1 and "g1" in result.out + result.err, result.out
        path.write_text(clean)
    assert run_cli("check", "--project", project).code == 0
    # a node of the user's in the launch file's region survives a regeneration that changes the file
    text = launch_file.read_text().replace(
        "    # rhi-gen:begin-user-region entities\n",
        "    # rhi-gen:begin-user-region entities\n"
        "    entities.append(Node(package='rviz2', executable='rviz2', output='screen'))\n").replace(
        "# rhi-gen:begin-user-region imports\n",
        "# rhi-gen:begin-user-region imports\nfrom launch_ros.actions import Node\n")
    launch_file.write_text(text)
    yml = project / "robots/unitree/g1.yaml"
    yml.write_text(yml.read_text().replace("network_interface: eth0", "network_interface: eth1"))
    assert run_cli("generate", "--project", project).code == 0
    regenerated = launch_file.read_text()
    assert "'eth1'" in regenerated and "executable='rviz2'" in regenerated
    package_dir = project / "generated" / PACKAGE
    launched = launch(launch_file, {PACKAGE: package_dir})
    assert [n.executable for n in launched.nodes][-1] == "rviz2"
    assert run_cli("check", "--project", project).code == 0


def test_a_unitree_only_package_depends_on_no_vendor_message_package(tmp_path):
    project = copy_project(tmp_path)
    for yml in (project / "robots").glob("*/*.yaml"):
        if yml.parent.name != "unitree":
            yml.unlink()
    assert run_cli("generate", "--project", project).code == 0
    from lxml import etree

    root = etree.parse(str(project / "generated" / PACKAGE / "package.xml")).getroot()
    depends = {e.text for e in root if e.tag in ("depend", "build_depend", "exec_depend")}
    assert not depends & {"aimdk_msgs", "interface_protocol", "unitree_sdk2"}
    assert {"xacro", "robot_state_publisher", "controller_manager", "ros2launch", "launch_ros",
            "joint_state_broadcaster", "imu_sensor_broadcaster", "forward_command_controller"} <= depends
