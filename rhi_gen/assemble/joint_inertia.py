"""Per actuated joint, the inertia and damping a fake robot's PD-driven rotor simulates, from the URDF alone.

The fake robot moves each joint as one rotor; for its response to resemble the real joint's, the rotor carries
what the joint carries: every link below the joint (all joints at zero position), as an inertia about the joint
axis (parallel-axis theorem), or, for a prismatic joint, as a mass. A floor (MIN_INERTIA) stands for the motor's
reflected rotor inertia, which the URDF leaves out, and keeps the simulation stiff-stable. Pure: text in, numbers
out; a missing or garbled number counts as absent, never as an error (the URDF is often third-party).
"""
from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

from lxml import etree

__all__ = ["DEFAULT_DAMPING", "MIN_INERTIA", "JointDynamics", "joint_dynamics"]

MIN_INERTIA = 0.01      # a motor's reflected rotor inertia through its gearbox is of this order; keeps the sim stable
DEFAULT_DAMPING = 0.1   # when the URDF gives no usable <dynamics damping>
ACTUATED = ("revolute", "continuous", "prismatic")

Vec = tuple[float, float, float]
Mat = tuple[Vec, Vec, Vec]   # rows

_ZERO: Vec = (0.0, 0.0, 0.0)
_IDENTITY: Mat = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
_ZERO_MAT: Mat = (_ZERO, _ZERO, _ZERO)


@dataclass(frozen=True)
class JointDynamics:
    inertia: float   # kg m^2 (revolute/continuous) or kg (prismatic), >= MIN_INERTIA
    damping: float   # N m s/rad or N s/m, >= 0 (DEFAULT_DAMPING where the URDF gives none: the vacuum's)
    # What MuJoCo's URDF reader takes from <dynamics damping friction>: 0 where the URDF gives none
    urdf_damping: float = 0.0
    urdf_friction: float = 0.0


@dataclass(frozen=True)
class _Link:
    mass: float
    com: Vec        # in the link frame
    tensor: Mat     # about the COM, in the link frame


@dataclass(frozen=True)
class _Joint:
    name: str
    kind: str
    parent: str
    child: str
    rotation: Mat   # child frame (at zero position) in the parent link frame
    origin: Vec
    axis: Vec       # unit, in the joint frame
    mimic: bool
    damping: float
    urdf_damping: float = 0.0
    urdf_friction: float = 0.0


# ---------------------------------------------------------------- 3x3 / vector math
def _dot(a: Vec, b: Vec) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _scale(a: Vec, s: float) -> Vec:
    return (a[0] * s, a[1] * s, a[2] * s)


def _apply(m: Mat, v: Vec) -> Vec:
    return (_dot(m[0], v), _dot(m[1], v), _dot(m[2], v))


def _transpose(m: Mat) -> Mat:
    return ((m[0][0], m[1][0], m[2][0]), (m[0][1], m[1][1], m[2][1]), (m[0][2], m[1][2], m[2][2]))


def _matmul(a: Mat, b: Mat) -> Mat:
    bt = _transpose(b)
    return (_apply(bt, a[0]), _apply(bt, a[1]), _apply(bt, a[2]))


def _rpy(roll: float, pitch: float, yaw: float) -> Mat:
    """URDF's fixed-axis roll-pitch-yaw: Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return ((cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
            (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
            (-sp, cp * sr, cp * cr))


# ---------------------------------------------------------------- tolerant reading
def _number(text: str | None) -> float | None:
    """A finite float, or None for what is missing, unparsable or not finite."""
    if text is None:
        return None
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _triple(text: str | None) -> Vec | None:
    """Three finite numbers, or None: a vector with one bad component is no vector."""
    if text is None:
        return None
    parts = [_number(p) for p in text.split()]
    numbers = [p for p in parts if p is not None]
    return (numbers[0], numbers[1], numbers[2]) if len(parts) == len(numbers) == 3 else None


def _origin(parent: etree._Element | None) -> tuple[Mat, Vec]:
    """The <origin> under ``parent`` as (rotation, translation); absent parts are the identity."""
    origin = parent.find("origin") if parent is not None else None
    if origin is None:
        return _IDENTITY, _ZERO
    rpy = _triple(origin.get("rpy"))
    return (_rpy(*rpy) if rpy is not None else _IDENTITY), (_triple(origin.get("xyz")) or _ZERO)


def _unit_axis(joint: etree._Element) -> Vec:
    axis_el = joint.find("axis")
    axis = _triple(axis_el.get("xyz")) if axis_el is not None else None
    norm = math.sqrt(_dot(axis, axis)) if axis is not None else 0.0
    if axis is None or not norm > 0.0 or not math.isfinite(norm):
        return (1.0, 0.0, 0.0)   # URDF's default; a zero axis has no direction to keep
    return _scale(axis, 1.0 / norm)


def _link(link: etree._Element) -> _Link:
    inertial = link.find("inertial")
    if inertial is None:
        return _Link(0.0, _ZERO, _ZERO_MAT)
    mass_el = inertial.find("mass")
    mass = _number(mass_el.get("value")) if mass_el is not None else None
    rotation, com = _origin(inertial)
    tensor = _ZERO_MAT
    inertia_el = inertial.find("inertia")
    if inertia_el is not None:
        def get(key: str) -> float:
            return _number(inertia_el.get(key)) or 0.0
        ixx, ixy, ixz, iyy, iyz, izz = (get(k) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"))
        inertial_frame: Mat = ((ixx, ixy, ixz), (ixy, iyy, iyz), (ixz, iyz, izz))
        tensor = _matmul(_matmul(rotation, inertial_frame), _transpose(rotation))
    # a negative mass is as garbled as an unparsable one: it would subtract from the rotor
    return _Link(mass if mass is not None and mass > 0.0 else 0.0, com, tensor)


def _joint(joint: etree._Element) -> _Joint | None:
    name, kind = joint.get("name"), joint.get("type")
    parent_el, child_el = joint.find("parent"), joint.find("child")
    parent = parent_el.get("link") if parent_el is not None else None
    child = child_el.get("link") if child_el is not None else None
    if name is None or kind is None or parent is None or child is None:
        return None
    rotation, origin = _origin(joint)
    dynamics = joint.find("dynamics")
    damping = _number(dynamics.get("damping")) if dynamics is not None else None
    friction = _number(dynamics.get("friction")) if dynamics is not None else None
    usable = damping is not None and damping >= 0.0
    return _Joint(name, kind, parent, child, rotation, origin, _unit_axis(joint), joint.find("mimic") is not None,
                  damping if usable and damping is not None else DEFAULT_DAMPING,
                  damping if usable and damping is not None else 0.0,
                  friction if friction is not None and friction >= 0.0 else 0.0)


# ---------------------------------------------------------------- the estimate
def _subtree(top: str, links: dict[str, _Link], below: dict[str, list[_Joint]]) -> Iterator[tuple[_Link, Mat, Vec]]:
    """Every link from ``top`` down, with its frame in ``top``'s frame, all joints at zero position."""
    stack: list[tuple[str, Mat, Vec]] = [(top, _IDENTITY, _ZERO)]
    seen: set[str] = set()
    while stack:
        name, rotation, position = stack.pop()
        if name in seen:   # a valid URDF is a tree; a cycle must still end
            continue
        seen.add(name)
        yield links.get(name, _Link(0.0, _ZERO, _ZERO_MAT)), rotation, position
        for j in below.get(name, []):
            stack.append((j.child, _matmul(rotation, j.rotation), _add(position, _apply(rotation, j.origin))))


def _estimate(joint: _Joint, links: dict[str, _Link], below: dict[str, list[_Joint]]) -> float:
    """What the joint carries: subtree mass (prismatic), else sum of a^T R I_c R^T a + m d^2 in the joint frame."""
    a = joint.axis
    total = 0.0
    for link, rotation, position in _subtree(joint.child, links, below):
        if joint.kind == "prismatic":
            total += link.mass
            continue
        local_a = _apply(_transpose(rotation), a)   # a^T (R I R^T) a = (R^T a)^T I (R^T a)
        spin = _dot(local_a, _apply(link.tensor, local_a))
        com = _add(position, _apply(rotation, link.com))
        off_axis = _add(com, _scale(a, -_dot(com, a)))
        total += spin + link.mass * _dot(off_axis, off_axis)
    return total


def _rounded(x: float) -> float:
    """Six significant digits: the figures end up in generated text, which must not churn."""
    return float(f"{x:.6g}")


def joint_dynamics(urdf_xml: str) -> dict[str, JointDynamics]:
    """Per actuated joint name (type revolute, continuous or prismatic, without <mimic>).

    A mimic joint follows another and gets no rotor of its own; a fixed joint moves nothing.
    """
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, remove_comments=True)
    root = etree.fromstring(urdf_xml.encode(), parser)
    links: dict[str, _Link] = {}
    for el in root.iterchildren("link"):
        name = el.get("name")
        if name is not None and name not in links:
            links[name] = _link(el)
    joints = [j for j in (_joint(el) for el in root.iterchildren("joint")) if j is not None]
    below: dict[str, list[_Joint]] = {}
    for j in joints:
        below.setdefault(j.parent, []).append(j)
    result: dict[str, JointDynamics] = {}
    for j in joints:
        if j.kind not in ACTUATED or j.mimic or j.name in result:
            continue
        estimate = _estimate(j, links, below)
        inertia = max(estimate, MIN_INERTIA) if math.isfinite(estimate) else MIN_INERTIA
        result[j.name] = JointDynamics(_rounded(inertia), _rounded(j.damping), j.urdf_damping, j.urdf_friction)
    return result
