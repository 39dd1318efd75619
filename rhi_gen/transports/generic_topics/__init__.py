"""generic_topics: sensor_msgs/JointState and sensor_msgs/Imu topics, for any robot.

In the manner of topic_based_ros2_control: the driver publishes commands and subscribes to states
on plain ROS 2 topics, so a bridge can connect any robot. JointState carries no stiffness/damping.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ...typed_yaml.validator import Validator
from ..base import ROSDISTRO, Dependency, KnownRobot, Transport, transport_header
from ..ros_topics import QosConfig, TopicOptions, qos_line, read_qos

NAME = "generic_topics"
COMMAND_TOPIC = "/hardware/joint_commands"
STATE_TOPIC = "/hardware/joint_states"
IMU_TOPIC = "/hardware/imu"


@dataclass(frozen=True)
class GenericTopicsOptions(TopicOptions):
    command_topic: str = ""
    state_topic: str = ""


class GenericTopics(Transport):
    name = NAME
    summary = "sensor_msgs/JointState and sensor_msgs/Imu ROS 2 topics, for any robot"
    # sensor_msgs/JointState has no stiffness or damping: the receiver applies its own gains, so
    # the driver exports no gain interfaces (and the controllers YAML starts no gain controllers).
    carries_gains = False
    option_keys = ("command_topic", "state_topic", "imu_topic", "qos")
    default_float_type = "double"
    dependencies = (Dependency("sensor_msgs", ROSDISTRO),)
    shared_files = (transport_header("ros_topics", "ros_topics.hpp"), transport_header(NAME, "generic_topics.hpp"),
                    transport_header(NAME, "generic_topics_fake_robot.hpp"))
    fake_robot_header = "robot_hardware_interface/transport/generic_topics_fake_robot.hpp"

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> GenericTopicsOptions:
        p = "transport_options"
        result = GenericTopicsOptions(
            command_topic=v.optional(options, p, "command_topic", v.topic, COMMAND_TOPIC),
            state_topic=v.optional(options, p, "state_topic", v.topic, STATE_TOPIC),
            imu_topic=v.optional(options, p, "imu_topic", v.topic, IMU_TOPIC),
            qos=read_qos(v, options.get("qos"), f"{p}.qos", QosConfig(depth=1)),
            sdk_slots=motor_count,
        )
        if result.command_topic == result.state_topic:
            raise v.error(f"{p}.command_topic", "command and state topics must differ",
                          fix="give command_topic and state_topic different names")
        return result

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        return [f"  command_topic: {COMMAND_TOPIC}", f"  state_topic: {STATE_TOPIC}", f"  imu_topic: {IMU_TOPIC}",
                qos_line(1)]


TRANSPORT = GenericTopics()
