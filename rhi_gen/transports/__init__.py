"""The transport registry: every transport rhi-gen can generate, one module each.

Adding a transport: make its folder ``transports/<name>/`` holding ``__init__.py`` (a ``Transport``
subclass, see base.py, and a ``TRANSPORT`` instance), its C++ header(s) ``<name>.hpp`` (the logic,
copied into every package that uses the transport) and ``glue.j2`` (the template of what a robot's
source passes to it), then add it to ``_ALL`` below. A glue template may also define
``definitions(N, T)``: C++ the robot's source emits before ``using Transport`` (custom: the transport
class holding the user's SDK regions). Validation, defaults, `rhi-gen new`, the package's dependency
lists and the CLI's help all read the registry.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from ..errors import ConfigError
from ..model.naming import suggest
from . import agibot_topics, custom, engineai_topics, generic_topics, unitree_dds
from .base import (
    COMMON_DEPENDENCIES,
    PLAIN_CMAKE,
    VENDOR_SOURCE,
    Dependency,
    KnownRobot,
    Transport,
    suggest_order,
    suggest_slots,
)

_ALL: tuple[Transport, ...] = (unitree_dds.TRANSPORT, agibot_topics.TRANSPORT, engineai_topics.TRANSPORT,
                               generic_topics.TRANSPORT, custom.TRANSPORT)
TRANSPORTS: Mapping[str, Transport] = MappingProxyType({t.name: t for t in _ALL})
NAMES: tuple[str, ...] = tuple(TRANSPORTS)
DEFAULT = generic_topics.NAME  # for a vendor rhi-gen has no transport of its own for

__all__ = ["COMMON_DEPENDENCIES", "DEFAULT", "NAMES", "TRANSPORTS", "Dependency", "DependencyTables", "KnownRobot",
           "Transport", "dependency_tables", "for_vendor", "get", "known_robot", "suggest_order",
           "suggest_slots"]


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


@dataclass(frozen=True)
class DependencyTables:
    """The package dependencies, in the shape of templates/package/_deps.j2 (names kept for the templates)."""
    COMMON_DEPS: tuple[str, ...]                     # every driver
    TRANSPORT_DEPS: Mapping[str, tuple[str, ...]]    # per transport, besides COMMON_DEPS
    NON_ROS_DEPS: tuple[str, ...]                    # plain CMake packages: no package.xml, no rosdep key
    VENDOR_MSG_DEPS: tuple[str, ...]                 # ROS packages not in rosdistro (vendor sources)


def _names(source: str) -> tuple[str, ...]:
    out: list[str] = []
    for t in _ALL:
        out += [d.name for d in t.dependencies if d.source == source and d.name not in out]
    return tuple(out)


def dependency_tables() -> DependencyTables:
    """What CMakeLists.txt and package.xml declare, from each transport's ``dependencies``."""
    return DependencyTables(
        COMMON_DEPS=COMMON_DEPENDENCIES,
        TRANSPORT_DEPS=MappingProxyType({t.name: tuple(d.name for d in t.dependencies) for t in _ALL}),
        NON_ROS_DEPS=_names(PLAIN_CMAKE),
        VENDOR_MSG_DEPS=_names(VENDOR_SOURCE),
    )
