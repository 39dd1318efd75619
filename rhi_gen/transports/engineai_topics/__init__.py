"""engineai_topics: EngineAI interface_protocol ROS 2 topics, index-ordered arrays of all motors.

Facts from EngineAI's SDK: /hardware/joint_command (JointCommand: position, velocity,
feed_forward_torque, torque, stiffness, damping, parallel_parser_type), /hardware/joint_state,
/hardware/imu_info (ImuInfo), /hardware/motor_debug (MotorDebug: motor_temperature per motor, 50 Hz or
more; the native SDK's release of interface_protocol also voltage, error_code, offline); best effort,
volatile, keep last 3; the robot must be in joint_bridge mode.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ...model import TransportOptions
from ...typed_yaml.validator import Validator
from ..base import ROSDISTRO, VENDOR_SOURCE, Dependency, KnownRobot, Transport, transport_header
from ..ros_topics import QosConfig, TopicOptions, qos_line, read_qos

NAME = "engineai_topics"
COMMAND_TOPIC = "/hardware/joint_command"
STATE_TOPIC = "/hardware/joint_state"
IMU_TOPIC = "/hardware/imu_info"
MOTOR_DEBUG_TOPIC = "/hardware/motor_debug"


@dataclass(frozen=True)
class EngineaiTopicsOptions(TopicOptions):
    command_topic: str = ""
    state_topic: str = ""
    motor_debug_topic: str = ""
    parallel_parser_type: int = 0  # 0 CLASSIC_PARSER, 1 RL_PARSER

# PM01 motor order = interface_protocol array index J00..J23.
PM01_ORDER = (
    "J00_HIP_PITCH_L", "J01_HIP_ROLL_L", "J02_HIP_YAW_L", "J03_KNEE_PITCH_L", "J04_ANKLE_PITCH_L",
    "J05_ANKLE_ROLL_L", "J06_HIP_PITCH_R", "J07_HIP_ROLL_R", "J08_HIP_YAW_R", "J09_KNEE_PITCH_R",
    "J10_ANKLE_PITCH_R", "J11_ANKLE_ROLL_R", "J12_WAIST_YAW", "J13_SHOULDER_PITCH_L",
    "J14_SHOULDER_ROLL_L", "J15_SHOULDER_YAW_L", "J16_ELBOW_PITCH_L", "J17_ELBOW_YAW_L",
    "J18_SHOULDER_PITCH_R", "J19_SHOULDER_ROLL_R", "J20_SHOULDER_YAW_R", "J21_ELBOW_PITCH_R",
    "J22_ELBOW_YAW_R", "J23_HEAD_YAW",
)


class EngineaiTopics(Transport):
    name = NAME
    summary = "EngineAI interface_protocol ROS 2 topics, index-ordered arrays"
    option_keys = ("command_topic", "state_topic", "imu_topic", "motor_debug_topic", "parallel_parser_type", "qos")
    default_float_type = "double"
    dependencies = (Dependency("interface_protocol", VENDOR_SOURCE), Dependency("sensor_msgs", ROSDISTRO),
                    Dependency("geometry_msgs", ROSDISTRO))
    shared_files = (transport_header("ros_topics", "ros_topics.hpp"), transport_header(NAME, "engineai_topics.hpp"),
                    transport_header(NAME, "engineai_topics_fake_robot.hpp"))
    fake_robot_header = "robot_hardware_interface/transport/engineai_topics_fake_robot.hpp"
    fake_state_rate_hz = 500.0  # JointState and ImuInfo at 500 Hz or more, MotorDebug 50 Hz or more
    vendors = ("engineai",)
    known_robots = (
        KnownRobot("engineai", "pm01", NAME, PM01_ORDER, "PM01 motor order = interface_protocol array index J00..J23"),
    )

    def motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """MotorDebug.motor_temperature (both interface_protocol versions; only the native SDK's has more)."""
        return ("temperature",)

    def detected_motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """The native SDK's MotorDebug voltage and error_code (its offline flag faults, no interface); the
        driver exports them where the interface_protocol it is compiled against has them."""
        return ("voltage", "error_code")

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> EngineaiTopicsOptions:
        p = "transport_options"
        return EngineaiTopicsOptions(
            command_topic=v.optional(options, p, "command_topic", v.topic, COMMAND_TOPIC),
            state_topic=v.optional(options, p, "state_topic", v.topic, STATE_TOPIC),
            imu_topic=v.optional(options, p, "imu_topic", v.topic, IMU_TOPIC),
            motor_debug_topic=v.optional(options, p, "motor_debug_topic", v.topic, MOTOR_DEBUG_TOPIC),
            parallel_parser_type=v.optional(options, p, "parallel_parser_type", v.integer_in(0, 1), 0),
            qos=read_qos(v, options.get("qos"), f"{p}.qos", QosConfig(depth=3)),
            sdk_slots=motor_count,
        )

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        return [f"  command_topic: {COMMAND_TOPIC}", f"  state_topic: {STATE_TOPIC}", f"  imu_topic: {IMU_TOPIC}",
                f"  motor_debug_topic: {MOTOR_DEBUG_TOPIC}  # motor temperatures",
                "  parallel_parser_type: 0  # 0 CLASSIC_PARSER, 1 RL_PARSER", qos_line(3)]


TRANSPORT = EngineaiTopics()
