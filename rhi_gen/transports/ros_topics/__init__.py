"""Options shared by the ROS 2 topic transports (QoS); each topic transport imports what it uses."""
from __future__ import annotations

from typing import Any

from ...model import QosConfig
from ...typed_yaml.validator import Validator

QOS_KEYS = ("reliability", "durability", "depth")


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
