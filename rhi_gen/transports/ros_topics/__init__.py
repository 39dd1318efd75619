"""What the ROS 2 topic transports share: QoS, the IMU topic, and their options base class.

Not a transport itself (it is in no registry): agibot_topics, engineai_topics, generic_topics and
custom import from here, and their packages get ros_topics.hpp (the node, executor thread and QoS
of the C++ side) through their ``shared_files``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...model import TransportOptions
from ...typed_yaml.validator import Validator

QOS_KEYS = ("reliability", "durability", "depth")


@dataclass(frozen=True)
class QosConfig:
    reliability: str = "best_effort"  # best_effort | reliable
    durability: str = "volatile"      # volatile | transient_local
    depth: int = 1


@dataclass(frozen=True)
class TopicOptions(TransportOptions):
    """The options every ROS 2 topic transport has (each transport's subclass adds its own)."""
    imu_topic: str = ""
    qos: QosConfig = field(default_factory=QosConfig)


def read_qos(v: Validator, raw: Any, path: str, default: QosConfig) -> QosConfig:
    """``transport_options.qos``: each key optional, ``default`` for the rest."""
    if raw is None:
        return default
    m = v.mapping(raw, path, QOS_KEYS)
    return QosConfig(
        reliability=v.optional(m, path, "reliability",
                               lambda x, q: v.choice(x, q, ("best_effort", "reliable")), default.reliability),
        durability=v.optional(m, path, "durability",
                              lambda x, q: v.choice(x, q, ("volatile", "transient_local")), default.durability),
        depth=v.optional(m, path, "depth", v.integer_in(1, 1000), default.depth),
    )


def qos_line(depth: int) -> str:
    """The qos line `rhi-gen new` writes (best effort + volatile, as the vendors' examples use)."""
    return f"  qos: {{reliability: best_effort, durability: volatile, depth: {depth}}}"
