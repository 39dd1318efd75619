"""The <ros2_control> blocks a URDF already has, as :class:`~rhi_gen.model.Ros2ControlBlock`.

Read as they are (names, type, hardware plugin, joints and their interfaces), without judging
them: ``assemble/robot_model.py`` applies ros2_control's rules to them and ``pipeline/existing_tags.py``
decides what to warn about. Its <transmission>s are read by ``urdf_transmissions.py``.
"""
from __future__ import annotations

from lxml import etree

from ..model import Ros2ControlBlock, Ros2ControlJoint
from .urdf_parse import Tag, UrdfContext

__all__ = ["read_ros2_control"]


def read_ros2_control(root: etree._Element, q: Tag, ctx: UrdfContext) -> tuple[Ros2ControlBlock, ...]:
    """Every <ros2_control> below ``root``, in document order."""
    blocks = []
    tag_hw, tag_plugin, tag_joint = q("hardware"), q("plugin"), q("joint")
    tag_cmd, tag_state = q("command_interface"), q("state_interface")
    for rc in root.iter(q("ros2_control")):
        plugin = None
        hw = rc.find(tag_hw)
        if hw is not None:
            plugin_el = hw.find(tag_plugin)
            if plugin_el is not None:
                plugin = "".join(plugin_el.itertext()).strip() or None
        rc_joints = tuple(
            Ros2ControlJoint(
                name=j.get("name", ""),
                command_interfaces=tuple(c.get("name", "") for c in j.iterchildren(tag_cmd)),
                state_interfaces=tuple(s.get("name", "") for s in j.iterchildren(tag_state)),
                line=ctx.line(j))
            for j in rc.iterchildren(tag_joint))
        blocks.append(Ros2ControlBlock(name=rc.get("name", ""), type=rc.get("type", ""),
                                       plugin=plugin, joints=rc_joints, line=ctx.line(rc)))
    return tuple(blocks)
