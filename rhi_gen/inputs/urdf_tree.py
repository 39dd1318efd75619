"""The links and joints of a URDF form exactly one tree, as ROS' urdfdom requires.

Checked after every joint was read: each joint names links that exist, no link has two parent
joints, there is no cycle and there is one root link. Each violation is one :class:`UrdfError` at
the line of the joint or link to fix.
"""
from __future__ import annotations

from lxml import etree

from ..model import UrdfJoint
from .urdf_joints import JointRefs
from .urdf_parse import UrdfContext, did_you_mean, quoted

__all__ = ["check_tree"]


def check_tree(joints: list[UrdfJoint], refs: list[JointRefs], links: list[str],
               link_el: dict[str, etree._Element], ctx: UrdfContext) -> None:
    """``links`` (in document order, ``link_el`` their elements) and ``joints`` form one tree."""
    parent_joint: dict[str, int] = {}  # child link -> index of its joint
    children: dict[str, list[str]] = {}
    for i, (j, (parent_el, child_el, _)) in enumerate(zip(joints, refs, strict=True)):
        for role, link, ref_el in (("parent", j.parent, parent_el), ("child", j.child, child_el)):
            if link not in link_el:
                raise ctx.err(
                    f"joint {quoted(j.name)}: {role} link {quoted(link)} is not defined"
                    + did_you_mean(link, link_el), ref_el,
                    fix=f"add <link name=\"{link}\"/> or fix the joint's <{role} link=...>")
        if j.child in parent_joint:
            first = joints[parent_joint[j.child]]
            raise ctx.err(
                f"link {quoted(j.child)} is the child of two joints: {quoted(first.name)} (line "
                f"{first.line}) and {quoted(j.name)}", child_el,
                fix="a URDF is a tree: give each link at most one parent joint")
        parent_joint[j.child] = i
        children.setdefault(j.parent, []).append(j.child)

    roots = [name for name in links if name not in parent_joint]
    reached: set[str] = set()
    sizes: dict[str, int] = {}
    for r in roots:
        before = len(reached)
        stack = [r]
        while stack:
            cur = stack.pop()
            if cur in reached:
                continue
            reached.add(cur)
            stack.extend(children.get(cur, ()))
        sizes[r] = len(reached) - before

    if len(reached) != len(links):
        start = next(name for name in links if name not in reached)
        path: list[str] = []
        on_path: dict[str, int] = {}
        cur = start
        while cur not in on_path:  # every unreached link has a parent joint, so this loops
            on_path[cur] = len(path)
            path.append(cur)
            cur = joints[parent_joint[cur]].parent
        cycle_links = path[on_path[cur]:]
        cycle_joints = [joints[parent_joint[name]] for name in cycle_links]
        cycle_joints.reverse()  # parent -> child order
        first = min(cycle_joints, key=lambda j: j.line or 0)
        names = " -> ".join(quoted(j.name) for j in cycle_joints)
        raise ctx.err(f"the joints form a cycle: {names} -> {quoted(cycle_joints[0].name)}",
                      line=first.line, fix="a URDF is a tree: remove one joint of the cycle")

    if len(roots) > 1:
        main = max(roots, key=lambda r: sizes[r])  # first of the largest trees
        strays = [r for r in roots if r != main]
        stray = strays[0]
        listed = ", ".join(quoted(r) for r in roots[:6]) + (", ..." if len(roots) > 6 else "")
        raise ctx.err(
            f"the links do not form one tree: {len(roots)} root links ({listed}); link "
            f"{quoted(stray)} is not the child of any joint", link_el[stray],
            fix=f"connect {quoted(stray)} to the robot with a joint (e.g. type=\"fixed\") or remove it")
