"""The <transmission> elements of a URDF -> :class:`~rhi_gen.model.UrdfTransmission`, never an error.

Two forms are in real descriptions: ROS 1's, at the top level (``<type>`` or a ``type=""`` attribute,
``<mechanicalReduction>`` under <actuator>, under <joint> or, in PR2's, under <transmission>), and
ros2_control's, inside <ros2_control> (``<plugin>``, ``role=""`` attributes, ``<mechanical_reduction>``
and ``<offset>`` under <joint>). Both are read into ros2_control's transmission_interface convention:

- SimpleTransmission: joint = motor / reduction + offset, where reduction is the product of every
  mechanical reduction given (actuator and joint; 1 where none is) and may be negative.
- DifferentialTransmission: joint = A @ motor + offset with, for joint reductions jr and actuator
  reductions ar in role order (joint1, joint2; actuator1, actuator2; document order without roles),
  A = [[1/(2 jr0 ar0), 1/(2 jr0 ar1)], [1/(2 jr1 ar0), -1/(2 jr1 ar1)]] (DifferentialTransmission::
  actuator_to_joint). Motor k is the motor of joint k: rhi-gen assumes the actuator of role
  actuatorK sits in the SDK slot of the joint of role jointK.

A URDF is often third-party, so nothing here raises: a kind rhi-gen does not apply, a transmission
on a joint that is missing, fixed or a mimic, and a malformed number or a zero reduction each give a
transmission with ``problem`` set, which assemble/transmissions.py turns into one warning. The vendor
YAML's bounds hold here too: an offset within one turn, a reduction from 1e-6 to 1e6, an invertible
matrix.
"""
from __future__ import annotations

import math
from dataclasses import replace

from lxml import etree

from ..model import UrdfJoint, UrdfTransmission
from ..model.urdf import TRANSMISSION_KINDS
from .urdf_joints import _number
from .urdf_parse import Tag, UrdfContext
from .vendor_transmissions import MAX_OFFSET, MAX_REDUCTION, MIN_CONDITION, condition

__all__ = ["describe", "read_transmissions"]

_REDUCTION_TAGS = ("mechanicalReduction", "mechanical_reduction")
MIN_REDUCTION = 1.0 / MAX_REDUCTION


class _Malformed(Exception):
    """A value of the transmission cannot be used (the message says which)."""


def _text(el: etree._Element | None) -> str | None:
    return None if el is None else "".join(el.itertext()).strip()


def _value(el: etree._Element, q: Tag, tags: tuple[str, ...], what: str, default: float) -> float:
    """The number under the first of ``tags`` in ``el``, ``default`` when there is none."""
    for tag in tags:
        child = el.find(q(tag))
        if child is not None:
            text = _text(child) or ""
            try:
                value = _number(text)
            except ValueError:
                raise _Malformed(f"<{tag}> of {what} is {text!r}, not a number") from None
            if value is None or not math.isfinite(value):
                raise _Malformed(f"<{tag}> of {what} is {text!r}, not a finite number")
            return value
    return default


def _role(el: etree._Element, q: Tag) -> str:
    return el.get("role") or _text(el.find(q("role"))) or ""


def _in_role_order(els: list[etree._Element], q: Tag) -> list[etree._Element]:
    """Elements sorted by role (joint1, joint2 / actuator1, actuator2) when every one has a distinct role."""
    roles = [_role(e, q) for e in els]
    if all(roles) and len(set(roles)) == len(roles):
        return [e for _, e in sorted(zip(roles, els, strict=True), key=lambda p: p[0])]
    return els


def _reductions(els: list[etree._Element], q: Tag, kind: str) -> list[float]:
    out = []
    for el in els:
        value = _value(el, q, _REDUCTION_TAGS, f"{kind} {el.get('name')!r}", 1.0)
        if value == 0.0:
            raise _Malformed(f"the mechanical reduction of {kind} {el.get('name')!r} is 0")
        out.append(value)
    return out


def _joint_problem(name: str, joints: dict[str, UrdfJoint]) -> str:
    joint = joints.get(name)
    if not name:
        return "a <joint> has no name"
    if joint is None:
        return f"names joint {name!r}, which is not a joint of this URDF"
    if joint.mimic is not None:
        return f"names joint {name!r}, which mimics {joint.mimic.joint!r} (a mimic joint has no motor)"
    if not joint.actuated:
        return f"names joint {name!r}, a {joint.type} joint (no motor drives it)"
    return ""


def _read_one(el: etree._Element, q: Tag, joints: dict[str, UrdfJoint]) -> UrdfTransmission:
    name = el.get("name") or ""
    kind = _text(el.find(q("type"))) or _text(el.find(q("plugin"))) or el.get("type") or ""
    joint_els = _in_role_order(list(el.iterchildren(q("joint"))), q)
    actuator_els = _in_role_order(list(el.iterchildren(q("actuator"))), q)
    names = tuple(j.get("name") or "" for j in joint_els)
    short = kind.rsplit("/", 1)[-1]
    base = UrdfTransmission(name=name, kind=kind or "?", joints=names)
    if not kind:
        return replace(base, problem="has no <type> or <plugin>, so its kind is unknown")
    if short not in TRANSMISSION_KINDS:
        return replace(base, problem=f"rhi-gen applies only {' and '.join(TRANSMISSION_KINDS)}")
    wanted = 1 if short == "SimpleTransmission" else 2
    if len(names) != wanted or len(actuator_els) > wanted or (wanted == 2 and len(actuator_els) != 2):
        return replace(base, problem=f"a {short} has {wanted} <joint> and {wanted} <actuator>, this one "
                           f"{len(names)} and {len(actuator_els)}")
    if len(set(names)) != len(names):
        return replace(base, problem=f"lists joint {names[0]!r} twice")
    for joint_name in names:
        if (problem := _joint_problem(joint_name, joints)):
            return replace(base, problem=problem)
    try:
        return _applied(base, el, q, joint_els, actuator_els)
    except _Malformed as exc:
        return replace(base, problem=str(exc))


def _applied(base: UrdfTransmission, el: etree._Element, q: Tag, joint_els: list[etree._Element],
             actuator_els: list[etree._Element]) -> UrdfTransmission:
    """The transmission in ros2_control's convention (``_Malformed`` when a value cannot be used)."""
    offsets = tuple(_value(j, q, ("offset",), f"joint {j.get('name')!r}", 0.0) for j in joint_els)
    if any(abs(o) > MAX_OFFSET for o in offsets):
        raise _Malformed(f"an <offset> of {max(offsets, key=abs):g} is beyond one turn ({MAX_OFFSET:.4f} rad)")
    jr = _reductions(joint_els, q, "joint")
    ar = _reductions(actuator_els, q, "actuator")
    if len(joint_els) == 1:
        # PR2's form: the reduction straight under <transmission>.
        reduction = _reductions([el], q, "transmission")[0] * jr[0] * (ar[0] if ar else 1.0)
        if not MIN_REDUCTION <= abs(reduction) <= MAX_REDUCTION:
            raise _Malformed(f"the reduction {reduction:g} is outside {MIN_REDUCTION:g}..{MAX_REDUCTION:g}")
        return replace(base, offsets=offsets, reduction=reduction)
    matrix = ((1.0 / (2.0 * jr[0] * ar[0]), 1.0 / (2.0 * jr[0] * ar[1])),
              (1.0 / (2.0 * jr[1] * ar[0]), -1.0 / (2.0 * jr[1] * ar[1])))
    if condition([*matrix]) < MIN_CONDITION:
        raise _Malformed("its reductions make a singular matrix (a reduction too large or too small)")
    return replace(base, offsets=offsets, matrix=matrix)


def read_transmissions(root: etree._Element, q: Tag, ctx: UrdfContext,
                       joints: list[UrdfJoint]) -> tuple[UrdfTransmission, ...]:
    """Every <transmission> below ``root`` (top level or inside <ros2_control>), in document order."""
    by_name = {j.name: j for j in joints}
    out = []
    for el in root.iter(q("transmission")):
        out.append(replace(_read_one(el, q, by_name), line=None if ctx.expanded else ctx.line(el)))
    return tuple(out)


def _num(value: float) -> str:
    return f"{value:g}"


def describe(t: UrdfTransmission) -> str:
    """One line for a reader (`inspect`, `new`): joints, kind and name, then what it does or why not."""
    head = f"{', '.join(t.joints) or '(no joint)'}: {t.short_kind} '{t.name}'"
    if t.problem:
        return f"{head}: not applied, {t.problem}"
    offsets = [f"offset {_num(o)}" for o in t.offsets if o != 0.0]
    if t.matrix:
        matrix = ", ".join("[" + ", ".join(_num(x) for x in row) + "]" for row in t.matrix)
        return f"{head}: matrix [{matrix}]" + "".join(f", {o}" for o in offsets)
    if abs(t.reduction) == 1.0 and not offsets and t.reduction > 0:
        return f"{head}: identity (changes nothing)"
    parts = [f"reduction {_num(abs(t.reduction))}", f"direction {'-1' if t.reduction < 0 else '+1'}", *offsets]
    return f"{head}: {', '.join(parts)}"
