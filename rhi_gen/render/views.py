"""View-models: what the package templates and the robot's YAML/XML templates place, decided in Python.

Templates only place values and loop over prepared lists; every name, rounded number, list and
dependency is computed here, where it is typed and tested (tests/unit/render/test_views.py) instead of being
spread over Jinja ``set`` blocks. Escaping stays with the filters (render/literals.py) and XML
autoescape: views hold raw text.

- ``package_view``: CMakeLists.txt, package.xml and robot_hardware_interface.xml. Every dependency
  comes from the ``dependencies`` of the transports the robots use (transports/<name>/), so a
  package declares only those.
- ``controllers_view``: config/<robot>_controllers.yaml (update rate, the forward controllers).
- ``xacro_view``: description/<robot>.ros2_control.xacro (macro defaults, joints, interfaces).
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from .. import transports
from ..model import MotorJoint, RobotModel
from ..project import PACKAGE_NAME
from ..transports import COMMON_DEPENDENCIES, COMMON_MESSAGE_DEPENDENCIES, PLAIN_CMAKE, VENDOR_SOURCE, Dependency
from .fake_robot_views import has_fake_robot

# ---------------------------------------------------------------- package files

# The ros2_control macro's parameters a launch file passes to xacro (templates/robot/ros2_control.xacro.j2):
# the mock switch, then the driver's parameters, the same for every transport.
DESCRIPTION_ARGUMENTS = ("use_mock_hardware", "network_interface", "enable_monitor", "command_writer_period_us",
                         "command_writer_mode", "state_decimation", "state_timeout_ms", "fault_timeout_ms",
                         "first_state_timeout_ms", "calibration_file", "is_async", "rw_rate")


# The driver's health GPIO, <gpio name="<hardware name>_health"> (cpp/common/driver_health.hpp holds
# the same names): its state interfaces, in order, and the e-stop command interface.
HEALTH_STATE_INTERFACES = ("state_age_ms", "invalid_states", "stale_holds", "rejected_commands",
                           "writer_overruns", "fault", "estop")
ESTOP_INTERFACE = "estop"
HEALTH_GPIO_SUFFIX = "_health"
HEALTH_CONTROLLER = "health_controller"  # gpio_controllers/GpioCommandController of the health GPIO


@dataclass(frozen=True)
class PlainCheck:
    """One plain-CMake dependency in rhi_check_dependencies: found when its target variable is set."""
    keyword: str  # "if" for the first, "elseif" after it
    name: str
    target_var: str


@dataclass(frozen=True)
class RobotTarget:
    """A robot in CMakeLists.txt and robot_hardware_interface.xml."""
    robot: RobotModel
    target: str                 # the plugin library (CMake target and pluginlib library path)
    test: str                   # its gmock test target
    depends: tuple[str, ...]    # the transport's packages, as rhi_check_dependencies checks them
    links: tuple[str, ...]      # its PRIVATE link items: ${pkg_TARGETS} of ROS packages, then SDK targets
    fake_robot: str = ""        # its fake robot executable ("" when the transport has no fake robot side)


@dataclass(frozen=True)
class PackageView:
    robots: tuple[RobotTarget, ...]
    common_deps: tuple[str, ...]         # every driver's packages
    common_msg_deps: tuple[str, ...]     # every driver's message packages (${pkg_TARGETS})
    ros_deps: tuple[str, ...]            # ROS packages of the transports in use, sorted
    vendor_msgs: str                     # of those, the ones not in rosdistro (vendor sources): "a, b"
    plain_deps: tuple[Dependency, ...]   # plain CMake packages of the transports in use, first use first
    plain_checks: tuple[PlainCheck, ...]
    found_keyword: str                   # "if" / "elseif": the ROS packages' check after the plain ones
    plain_notes: tuple[str, ...]         # package.xml: why each plain package is not declared
    description: str                     # package.xml <description>: the plugins, or "no robots yet"
    imu: bool                            # some robot exports an IMU (imu_sensor_broadcaster)
    fake_robots: bool = False            # some robot has a fake robot (CMakeLists.txt looks for MuJoCo)
    meshes: bool = False                 # some robot's meshes are copied into meshes/<robot>/ (installed)
    description_arguments: tuple[str, ...] = DESCRIPTION_ARGUMENTS  # launch/bringup.launch.py -> xacro


def _unique(items: Sequence[Dependency]) -> list[Dependency]:
    out: list[Dependency] = []
    for d in items:
        if d.name not in (o.name for o in out):
            out.append(d)
    return out


def _links(deps: Sequence[Dependency]) -> tuple[str, ...]:
    ros = [f"${{{d.name}_TARGETS}}" for d in deps if d.source != PLAIN_CMAKE]
    return (*ros, *(f"${{{d.cmake_target}}}" for d in deps if d.source == PLAIN_CMAKE))


def package_view(robots: Sequence[RobotModel]) -> PackageView:
    """What the package templates place for ``robots`` (sorted by vendor/robot)."""
    targets = []
    used: list[Dependency] = []
    for r in robots:
        transport = transports.get(r.transport)
        deps = transport.dependencies
        used += deps
        targets.append(RobotTarget(robot=r, target=f"{PACKAGE_NAME}_{r.vendor}_{r.robot}",
                                   test=f"test_{r.robot}_hardware_interface",
                                   depends=tuple(d.name for d in deps), links=_links(deps),
                                   fake_robot=f"{r.robot}_fake_robot" if has_fake_robot(r) else ""))
    used = _unique(used)
    plain = tuple(d for d in used if d.source == PLAIN_CMAKE)
    ros = sorted(d.name for d in used if d.source != PLAIN_CMAKE)
    return PackageView(
        robots=tuple(targets),
        common_deps=COMMON_DEPENDENCIES,
        common_msg_deps=COMMON_MESSAGE_DEPENDENCIES,
        ros_deps=tuple(ros),
        vendor_msgs=", ".join(sorted(d.name for d in used if d.source == VENDOR_SOURCE)),
        plain_deps=plain,
        plain_checks=tuple(PlainCheck("if" if i == 0 else "elseif", d.name, d.cmake_target)
                           for i, d in enumerate(plain)),
        found_keyword="elseif" if plain else "if",
        plain_notes=tuple("\n       ".join(d.package_xml_note) for d in plain if d.package_xml_note),
        description=", ".join(r.plugin_name for r in robots) or "no robots yet",
        imu=any(r.imu.enabled for r in robots),
        fake_robots=any(t.fake_robot for t in targets),
        meshes=any(r.meshes for r in robots),
    )


# ---------------------------------------------------------------- config/<robot>_controllers.yaml

@dataclass(frozen=True)
class Controller:
    """A forward_command_controller: its name, the interface it claims and the joints, in order."""
    name: str
    interface: str
    joints: tuple[MotorJoint, ...]


@dataclass(frozen=True)
class ControllersView:
    update_rate: int                     # Hz: round(1e6 / period) half to even, at least 1
    period_us: int
    gains: bool                          # the transport carries stiffness / damping
    controllers: tuple[Controller, ...]
    limp_count: int                      # joints without default gains (0 stiffness and 0 damping)
    joint_count: int
    velocity_count: int
    health_gpio: str = ""                # the health GPIO under the default hardware name
    health_controller: str = HEALTH_CONTROLLER
    health_states: tuple[str, ...] = HEALTH_STATE_INTERFACES
    estop: str = ESTOP_INTERFACE


def update_rate_hz(period_us: int) -> int:
    """The controller manager's rate for a command period: round(1e6 / period) in integers, half to
    even (as Python's round), at least 1 Hz."""
    q, r = divmod(1_000_000, period_us)
    if 2 * r > period_us or (2 * r == period_us and q % 2 == 1):
        q += 1
    return max(q, 1)


def controllers_view(robot: RobotModel) -> ControllersView:
    position = tuple(j for j in robot.joints if j.command_mode in ("position", "position_target"))
    velocity = tuple(j for j in robot.joints if j.command_mode == "velocity")
    commanded = robot.commanded_joints
    gained = tuple(j for j in commanded if "damping" in j.command_interfaces)  # not the position-target ones
    gains = bool(gained)
    # The hands get a position controller of their own: a grasp runs beside the arms' controller.
    hands = {j.index for j in robot.hand_joints}
    body_position = tuple(j for j in position if j.index not in hands)
    controllers = []
    if body_position:
        controllers.append(Controller("forward_position_controller", "position", body_position))
    if hands:
        controllers.append(Controller("hand_position_controller", "position",
                                      tuple(j for j in position if j.index in hands)))
    if velocity:
        controllers.append(Controller("forward_velocity_controller", "velocity", velocity))
    stiff = tuple(j for j in gained if "stiffness" in j.command_interfaces)
    if stiff:
        controllers.append(Controller("forward_stiffness_controller", "stiffness", stiff))
    if gains:
        controllers.append(Controller("forward_damping_controller", "damping", gained))
    period = robot.parameters.command_writer_period_us
    return ControllersView(
        update_rate=update_rate_hz(period), period_us=period, gains=gains, controllers=tuple(controllers),
        limp_count=sum(1 for j in gained if j.default_stiffness == 0.0 and j.default_damping == 0.0),
        joint_count=len(gained), velocity_count=len(velocity), health_gpio=health_gpio_name(robot))


# ---------------------------------------------------------------- description/<robot>.ros2_control.xacro

def xacro_text(text: object) -> str:
    """Text kept away from xacro's evaluation: "$" can start an expression ("${", "$(") or be a lexer
    error ("$$x"), so each "$" becomes the expression ${"\\x24"}, which xacro evaluates back to "$"."""
    return str(text).replace("$", '${"\\x24"}')


def xacro_default(text: object) -> str:
    """A macro parameter default, placed between single quotes (so xacro keeps it a string: '2000'
    stays "2000", 'true' stays "true"); a "'" inside would end the quotes early: ${"\\x27"}."""
    return xacro_text(text).replace("'", '${"\\x27"}')


@dataclass(frozen=True)
class CommandInterface:
    name: str
    lower: float | None = None  # position of a revolute/prismatic joint with both limits: min, max
    upper: float | None = None


@dataclass(frozen=True)
class XacroJoint:
    name: str                                   # xacro_text of the joint name
    comment: str                                # "SDK slot 3, group leg[3], velocity-commanded"
    command_interfaces: tuple[CommandInterface, ...]
    initial_position: str = "0.0"               # the position state interface's initial_value
    health_interfaces: tuple[str, ...] = ()     # motor health state interfaces after effort


@dataclass(frozen=True)
class XacroView:
    macro_name: str
    defaults: dict[str, str]                    # macro parameter -> xacro_default text
    plugin: str
    joints: tuple[XacroJoint, ...]
    joint_count: int
    imu_name: str
    imu_frame_id: str
    mock_parameters: tuple[tuple[str, str], ...] = ()  # mock_components/GenericSystem hardware parameters
    mock_note: str = ""                                 # what the mock does with commands, for the header
    imu_initial: tuple[tuple[str, str], ...] = ()       # IMU state interface -> initial_value
    health_states: tuple[str, ...] = HEALTH_STATE_INTERFACES  # the health GPIO's state interfaces
    estop: str = ESTOP_INTERFACE                              # ... and its command interface
    health_suffix: str = HEALTH_GPIO_SUFFIX                   # <gpio name="${name}_health">
    detected_health: tuple[str, ...] = ()  # motor health the driver exports beyond this description, if found


@dataclass(frozen=True)
class TestView:
    """test/test_<robot>_hardware_interface.cpp: what the template cannot read off the model."""
    detected_health: tuple[str, ...] = ()  # motor health the driver may export beyond the description


def test_view(robot: RobotModel) -> TestView:
    return TestView(detected_health=transports.get(robot.transport).detected_motor_health(robot.transport_options))


IMU_INTERFACES = ("orientation.x", "orientation.y", "orientation.z", "orientation.w", "angular_velocity.x",
                  "angular_velocity.y", "angular_velocity.z", "linear_acceleration.x", "linear_acceleration.y",
                  "linear_acceleration.z")


def health_gpio_name(robot: RobotModel) -> str:
    """The health GPIO's name under the macro's default hardware name (what the controllers YAML names)."""
    return f"{robot.robot}_hardware{HEALTH_GPIO_SUFFIX}"


def mock_parameters(robot: RobotModel) -> tuple[tuple[str, str], ...]:
    """The GenericSystem parameters that make the mock behave like the robot for the controllers of
    config/<robot>_controllers.yaml: calculate_dynamics only where a velocity command must move the
    position (wheels; with it GenericSystem refuses a controller that claims a joint's stiffness or
    damping without its position or velocity); mock_sensor_commands so a test can drive the IMU."""
    wheels = any(j.command_mode == "velocity" for j in robot.joints)
    params = [("calculate_dynamics", "true" if wheels else "false")]
    if robot.imu.enabled:
        params.append(("mock_sensor_commands", "true"))
    return tuple(params)


def _mock_note(robot: RobotModel) -> str:
    if any(j.command_mode == "velocity" for j in robot.joints):
        return ("velocity commands move the positions (calculate_dynamics), position commands are\n"
                "  followed at once.")
    return "position commands are followed at once (no dynamics)."


def _interfaces(joint: MotorJoint) -> tuple[CommandInterface, ...]:
    lim = joint.limits
    bounded = joint.type in ("revolute", "prismatic") and lim is not None and lim.lower is not None \
        and lim.upper is not None
    return tuple(CommandInterface(i, lim.lower, lim.upper) if i == "position" and bounded and lim is not None
                 else CommandInterface(i) for i in joint.command_interfaces)


def _comment(joint: MotorJoint) -> str:
    text = f"SDK slot {joint.index}"
    if joint.group is not None:  # "--" may not appear inside an XML comment
        text += f", group {joint.group.replace('-', ' -')}[{joint.group_position}]"
    return text + {"velocity": ", velocity-commanded",
                   "state": ", state only: the robot's own controller keeps it (authority upper_body)",
                   "position_target": ", position target only: the hand's own controller tracks it"
                   }.get(joint.command_mode, "")


def xacro_view(robot: RobotModel) -> XacroView:
    p = robot.parameters
    defaults = (("name", f"{robot.robot}_hardware"), ("network_interface", p.network_interface),
                ("enable_monitor", "true" if p.enable_monitor else "false"),
                ("command_writer_period_us", p.command_writer_period_us),
                ("command_writer_mode", p.command_writer_mode), ("state_decimation", p.state_decimation),
                ("state_timeout_ms", p.state_timeout_ms), ("fault_timeout_ms", p.fault_timeout_ms),
                ("first_state_timeout_ms", p.first_state_timeout_ms), ("calibration_file", ""),
                ("is_async", "true" if p.is_async else "false"), ("rw_rate", p.rw_rate))
    return XacroView(
        macro_name=f"{robot.robot}_ros2_control",
        defaults={key: xacro_default(value) for key, value in defaults},
        plugin=xacro_text(robot.plugin_name),
        joints=tuple(XacroJoint(xacro_text(j.name), _comment(j), _interfaces(j), repr(j.initial_position),
                                j.state_interfaces[3:]) for j in robot.joints),
        joint_count=len(robot.joints),
        imu_name=xacro_text(robot.imu.name),
        imu_frame_id=xacro_text(robot.imu.frame_id),
        mock_parameters=mock_parameters(robot),
        mock_note=_mock_note(robot),
        imu_initial=tuple((name, "1.0" if name == "orientation.w" else "0.0") for name in IMU_INTERFACES),
        detected_health=test_view(robot).detected_health,
    )
