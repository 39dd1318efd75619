"""The robot's body as the URDF describes it, summed up: what its inertials weigh, and its geometry by kind.

The driver's tables do not depend on it, but the fake robot's physics and every simulator or planner
reading the installed URDF do, so `rhi-gen diff` tells a reviewer when it changed (write/body_diff.py).
Built by inputs/urdf_body.py; recorded in the manifest (write/manifest_body.py); plain frozen data.
"""
from __future__ import annotations

from dataclasses import dataclass

GEOMETRY_KINDS = ("mesh", "box", "sphere", "cylinder", "capsule")  # known; any other tag is counted by its name


@dataclass(frozen=True)
class LinkInertial:
    link: str
    mass: float | None  # kg; None when the <mass value> is not a number
    digest: str         # 12 hex digits of sha256 over mass, origin and inertia tensor: any change shows


@dataclass(frozen=True)
class BodySummary:
    links: int                                   # every <link>
    total_mass: float                            # sum of the inertials' masses, kg, rounded to 1e-6
    inertials: tuple[LinkInertial, ...]          # the links with an <inertial>, by link name
    collisions: tuple[tuple[str, int], ...]      # (geometry kind, count), by kind, only non-zero
    visuals: tuple[tuple[str, int], ...]         # (geometry kind, count), by kind, only non-zero
    mesh_files: tuple[tuple[str, int], ...]      # (reference pattern, count) of every <mesh filename>, by pattern

    @property
    def inertial_links(self) -> int:
        return len(self.inertials)


def mesh_form(pattern: str) -> str:
    """How a mesh reference pattern (see inputs/urdf_body.mesh_pattern) names its file, in words."""
    if pattern.startswith("package://"):
        return "package://"
    if pattern.startswith("file://"):
        return "file://"
    if pattern.startswith("/"):
        return "absolute path"
    if "://" in pattern:
        return pattern.split("://", 1)[0] + "://"
    return "relative path"
