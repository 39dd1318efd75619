"""The transport registry: every transport rhi-gen can generate, one folder each.

Adding a transport: make its folder ``transports/<name>/`` holding ``__init__.py`` (a ``Transport``
subclass, see base.py, and a ``TRANSPORT`` instance), its C++ header(s) ``<name>.hpp`` (the logic,
copied into every package that uses the transport) and ``glue.j2`` (the template of what a robot's
source passes to it), then give it its line in the registry below. A glue template may also define
``definitions(N, T)``: C++ the robot's source emits before ``using Transport`` (custom: the transport
class holding the user's SDK regions). Its ``Transport`` subclass declares everything else: its
options (a ``TransportOptions`` subclass, read and validated by it), the packages it needs
(``dependencies``) and the files it adds (``shared_files``). Validation, defaults, `rhi-gen new`, the
package's CMakeLists.txt and package.xml, and the CLI's help all read the registry.
"""
from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from ..errors import ConfigError
from ..model.naming import suggest
from .base import (
    COMMON_DEPENDENCIES,
    COMMON_MESSAGE_DEPENDENCIES,
    PLAIN_CMAKE,
    ROSDISTRO,
    VENDOR_SOURCE,
    Dependency,
    HandSuggestion,
    KnownRobot,
    Transport,
    suggest_order,
    suggest_slots,
)

# isort: off
# The registry: one line per transport, in the order help texts list them (collected into _ALL).
from .unitree_dds import TRANSPORT as UNITREE_DDS  # noqa: F401
from .agibot_topics import TRANSPORT as AGIBOT_TOPICS  # noqa: F401
from .engineai_topics import TRANSPORT as ENGINEAI_TOPICS  # noqa: F401
from .generic_topics import TRANSPORT as GENERIC_TOPICS
from .custom import TRANSPORT as CUSTOM  # noqa: F401
# isort: on

_ALL: tuple[Transport, ...] = tuple(t for t in dict(globals()).values() if isinstance(t, Transport))
TRANSPORTS: Mapping[str, Transport] = MappingProxyType({t.name: t for t in _ALL})
NAMES: tuple[str, ...] = tuple(TRANSPORTS)
DEFAULT = GENERIC_TOPICS.name  # for a vendor rhi-gen has no transport of its own for

__all__ = ["COMMON_DEPENDENCIES", "COMMON_MESSAGE_DEPENDENCIES", "DEFAULT", "NAMES",
           "PLAIN_CMAKE", "ROSDISTRO", "TRANSPORTS", "VENDOR_SOURCE", "Dependency", "HandSuggestion", "KnownRobot",
           "Transport",
           "for_vendor", "get", "known_robot", "suggest_order", "suggest_slots"]


def get(name: str, *, key: str = "transport") -> Transport:
    """The transport called ``name``; a ConfigError with a did-you-mean otherwise."""
    try:
        return TRANSPORTS[name]
    except KeyError:
        hint = suggest(name, NAMES)
        raise ConfigError(f"unknown transport {name!r}", key=key,
                          fix=(f"did you mean {hint!r}? " if hint else "") + f"use one of {', '.join(NAMES)}") from None


def for_vendor(vendor: str) -> Transport:
    """The transport `rhi-gen new` picks for ``vendor`` when none is given."""
    for t in _ALL:
        if vendor in t.vendors:
            return t
    return TRANSPORTS[DEFAULT]


def known_robot(vendor: str, robot: str) -> KnownRobot | None:
    """The vendor robot whose SDK motor order rhi-gen knows, if any."""
    for t in _ALL:
        for known in t.known_robots:
            if known.vendor == vendor and known.named(robot):
                return known
    return None
