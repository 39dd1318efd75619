"""One <joint> of a URDF -> :class:`~rhi_gen.model.UrdfJoint`, and the checks of its <mimic>.

A joint is read the way ROS' urdfdom reads it (a type, a parent and a child link; revolute and
prismatic joints have a <limit> with effort and velocity; numbers are plain decimals) plus what
rhi-gen relies on (no duplicate names, lower <= upper, mimic targets exist and do not loop). Every
problem is a :class:`UrdfError` at the line of the offending element, with a fix.
"""
from __future__ import annotations

import re

from lxml import etree

from ..model import JointLimits, Mimic, UrdfJoint
from .urdf_parse import Tag, UrdfContext, did_you_mean, quoted

__all__ = ["JOINT_TYPES", "JointRefs", "check_mimic", "read_joint"]

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
_LIMITED_TYPES = ("revolute", "prismatic")  # urdfdom rejects these without <limit>
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
# per joint: (parent element, child element, mimic element)
JointRefs = tuple[etree._Element, etree._Element, etree._Element | None]


def _number(text: str | None) -> float | None:
    if text is None:
        return None
    text = text.strip()
    if not _NUMBER.fullmatch(text):
        raise ValueError(text)
    return float(text)


def _bad_number_fix(value: str) -> str:
    if "${" in value or "$(" in value:
        return "this is an unexpanded xacro expression: name the file *.xacro so rhi-gen runs xacro"
    return "write a plain decimal number (SI units: radians, metres, N, N*m)"


def read_joint(el: etree._Element, ctx: UrdfContext, q: Tag, joint_el: dict[str, etree._Element],
               refs: list[JointRefs]) -> UrdfJoint:
    """One <joint>; records it in ``joint_el`` and its (parent, child, mimic) elements in ``refs``."""
    name = el.get("name")
    if not name:
        raise ctx.err("<joint> has no name attribute", el, fix="add name=\"...\" to the joint")
    jtype = el.get("type")
    types = ", ".join(JOINT_TYPES)
    if not jtype:
        raise ctx.err(f"joint {quoted(name)} has no type attribute", el,
                      fix=f"add type=\"...\" (one of {types})")
    if jtype not in JOINT_TYPES:
        raise ctx.err(f"joint {quoted(name)} has unknown type {quoted(jtype)}", el,
                      fix=f"use one of {types}")
    # one pass over the children (lxml's find() costs more than the whole joint otherwise)
    first: dict[str, etree._Element] = {}
    for sub in el:
        tag = sub.tag
        if isinstance(tag, str) and tag not in first:
            first[tag] = sub
    parent = first.get(q("parent"))
    parent_link = parent.get("link") if parent is not None else None
    if parent is None or not parent_link:
        raise ctx.err(f"joint {quoted(name)} has no <parent link=\"...\"/>", el if parent is None
                      else parent, fix="add <parent link=\"...\"/> inside the joint")
    child = first.get(q("child"))
    child_link = child.get("link") if child is not None else None
    if child is None or not child_link:
        raise ctx.err(f"joint {quoted(name)} has no <child link=\"...\"/>", el if child is None
                      else child, fix="add <child link=\"...\"/> inside the joint")
    if name in joint_el:
        raise ctx.err(f"duplicate joint name {quoted(name)} (first defined on line "
                      f"{ctx.line(joint_el[name])})", el, fix="give every joint a unique name")
    joint_el[name] = el

    axis = (1.0, 0.0, 0.0)
    axis_el = first.get(q("axis"))
    xyz = axis_el.get("xyz") if axis_el is not None else None
    if xyz is not None:
        parts = xyz.split()
        try:
            if len(parts) != 3:
                raise ValueError(xyz)
            axis = tuple(_number(p) for p in parts)  # type: ignore[assignment]
        except ValueError:
            raise ctx.err(f"joint {quoted(name)}: <axis xyz=\"{xyz}\"> is not three numbers", axis_el,
                          fix="write the axis as three numbers, e.g. xyz=\"0 0 1\"") from None

    limits = None
    limit_el = first.get(q("limit"))
    if limit_el is None and jtype in _LIMITED_TYPES:
        raise ctx.err(
            f"{jtype} joint {quoted(name)} has no <limit>", el,
            fix="add <limit lower=\"...\" upper=\"...\" effort=\"...\" velocity=\"...\"/> "
                "(ROS URDF requires it for revolute and prismatic joints; use type=\"continuous\" "
                "for an unlimited revolute joint)")
    if limit_el is not None:
        values: dict[str, float | None] = {}
        for attr in ("lower", "upper", "effort", "velocity"):
            raw = limit_el.get(attr)
            if raw is None and attr in ("effort", "velocity"):
                raise ctx.err(f"joint {quoted(name)}: <limit> has no {attr} attribute", limit_el,
                              fix=f"add {attr}=\"...\" to the <limit> (ROS URDF requires effort "
                                  "and velocity)")
            try:
                values[attr] = _number(raw)
            except ValueError:
                raise ctx.err(f"joint {quoted(name)}: <limit {attr}=\"{raw}\"> is not a number",
                              limit_el, fix=_bad_number_fix(raw or "")) from None
        lower, upper = values["lower"], values["upper"]
        if jtype in _LIMITED_TYPES and lower is not None and upper is not None and lower > upper:
            raise ctx.err(f"joint {quoted(name)}: <limit> lower {_raw(limit_el, 'lower')} is "
                          f"greater than upper {_raw(limit_el, 'upper')}", limit_el,
                          fix="swap lower and upper")
        limits = JointLimits(lower=lower, upper=upper, velocity=values["velocity"],
                             effort=values["effort"])

    mimic = None
    mimic_el = first.get(q("mimic"))
    if mimic_el is not None:
        target = mimic_el.get("joint")
        if not target:
            raise ctx.err(f"joint {quoted(name)}: <mimic> has no joint attribute", mimic_el,
                          fix="add joint=\"<name of the joint to follow>\" to the <mimic>")
        nums: dict[str, float] = {}
        for attr, default in (("multiplier", 1.0), ("offset", 0.0)):
            raw = mimic_el.get(attr)
            try:
                value = _number(raw)
            except ValueError:
                raise ctx.err(f"joint {quoted(name)}: <mimic {attr}=\"{raw}\"> is not a number",
                              mimic_el, fix=_bad_number_fix(raw or "")) from None
            nums[attr] = default if value is None else value
        mimic = Mimic(joint=target, multiplier=nums["multiplier"], offset=nums["offset"])

    refs.append((parent, child, mimic_el))
    return UrdfJoint(name=name, type=jtype, parent=parent_link, child=child_link,
                     axis=axis, limits=limits, mimic=mimic, line=ctx.line(el))


def _raw(el: etree._Element, attr: str) -> str:
    return (el.get(attr) or "").strip()


def check_mimic(joints: list[UrdfJoint], refs: list[JointRefs], ctx: UrdfContext) -> None:
    """Every mimic follows another joint of this URDF, and every chain of mimics ends at a real joint."""
    by_name = {j.name: j for j in joints}
    for j, (_, _, mimic_el) in zip(joints, refs, strict=True):
        if j.mimic is None:
            continue
        target = j.mimic.joint
        if target == j.name:
            raise ctx.err(f"joint {quoted(j.name)} mimics itself", mimic_el,
                          fix="set <mimic joint=...> to the joint it should follow")
        if target not in by_name:
            raise ctx.err(
                f"joint {quoted(j.name)} mimics {quoted(target)}, which is not a joint of this URDF"
                + did_you_mean(target, by_name), mimic_el,
                fix="set <mimic joint=...> to an existing joint name")
    # mimic chains must end at a joint that is not a mimic
    for j, (_, _, mimic_el) in zip(joints, refs, strict=True):
        if j.mimic is None:
            continue
        seen = [j.name]
        cur = by_name[j.mimic.joint]
        while cur.mimic is not None:
            if cur.name in seen:
                loop = [*seen[seen.index(cur.name):], cur.name]
                raise ctx.err("mimic joints follow each other in a loop: " + " -> ".join(
                    quoted(n) for n in loop), mimic_el,
                    fix="one joint of the loop must be a real (non-mimic) joint")
            seen.append(cur.name)
            cur = by_name[cur.mimic.joint]

