"""A parsed <robot> element -> :class:`~rhi_gen.model.UrdfRobot`.

Checks the root (a named <robot>, no xacro element left over), reads the links here and each
joint with :mod:`.urdf_joints`, checks the mimics and the tree (:mod:`.urdf_tree`), reads the
existing <ros2_control> blocks (:mod:`.urdf_ros2_control`) and the <transmission>s
(:mod:`.urdf_transmissions`), sums up the body (:mod:`.urdf_body`) and keeps the canonical bytes the
manifest fingerprints (:mod:`.urdf_canonical`).
"""
from __future__ import annotations

from lxml import etree

from ..model import UrdfJoint, UrdfRobot
from .urdf_body import read_body
from .urdf_canonical import canonical_urdf_bytes
from .urdf_joints import JointRefs, check_mimic, read_joint
from .urdf_parse import UrdfContext, first_xacro_element, quoted
from .urdf_ros2_control import read_ros2_control
from .urdf_transmissions import read_transmissions
from .urdf_tree import check_tree

__all__ = ["robot_from_root"]


def robot_from_root(root: etree._Element, data: bytes, ctx: UrdfContext, canonical: bytes | None = None) -> UrdfRobot:
    """The robot ``root`` (parsed from ``data``) describes; ``canonical``: its fingerprint bytes when
    they are not ``canonical_urdf_bytes(data)`` (a xacro expansion made portable)."""
    ns = etree.QName(root).namespace  # URDF has no namespace; a default xmlns on <robot> is tolerated

    def q(local: str) -> str:
        return f"{{{ns}}}{local}" if ns else local

    local = etree.QName(root).localname
    if local != "robot":
        raise ctx.err(f"the root element is <{local}>, not <robot>", root,
                      fix="a URDF's root element is <robot name=\"...\">")
    robot_name = root.get("name")
    if not robot_name:
        raise ctx.err("<robot> has no name attribute", root, fix="add name=\"...\" to <robot>")

    if b"xacro" in data:
        leftover = first_xacro_element(root)
        if leftover is not None:
            shown = f"{leftover.prefix}:{etree.QName(leftover).localname}" if leftover.prefix \
                else etree.QName(leftover).localname
            if ctx.expanded:
                raise ctx.err(f"xacro element <{shown}> was not expanded", leftover,
                              fix="xacro only expands elements written with the 'xacro:' prefix")
            raise ctx.err(f"xacro element <{shown}> in a URDF that was not run through xacro",
                          leftover, fix="name the file *.xacro (or load it with load_urdf)")

    tag_link, tag_joint = q("link"), q("joint")

    links: list[str] = []
    link_el: dict[str, etree._Element] = {}
    joints: list[UrdfJoint] = []
    joint_el: dict[str, etree._Element] = {}
    refs: list[JointRefs] = []

    for el in root:
        tag = el.tag
        if tag == tag_link:
            name = el.get("name")
            if not name:
                raise ctx.err("<link> has no name attribute", el, fix="add name=\"...\" to the link")
            if name in link_el:
                raise ctx.err(
                    f"duplicate link name {quoted(name)} (first defined on line "
                    f"{ctx.line(link_el[name])})", el, fix="give every link a unique name")
            link_el[name] = el
            links.append(name)
        elif tag == tag_joint:
            joints.append(read_joint(el, ctx, q, joint_el, refs))

    if not links:
        raise ctx.err("the robot has no <link>", root, fix="a URDF needs at least one <link>")

    check_mimic(joints, refs, ctx)
    check_tree(joints, refs, links, link_el, ctx)
    children = {j.child for j in joints}
    root_link = next(name for name in links if name not in children)

    return UrdfRobot(
        name=robot_name,
        source=ctx.source,
        joints=tuple(joints),
        links=tuple(links),
        ros2_control=read_ros2_control(root, q, ctx),
        transmissions=read_transmissions(root, q, ctx, joints),
        canonical_xml=canonical_urdf_bytes(data) if canonical is None else canonical,
        root_link=root_link,
        root_has_inertia=link_el[root_link].find(q("inertial")) is not None,
        body=read_body(root, q),
    )
