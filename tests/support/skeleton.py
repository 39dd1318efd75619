"""A kinematic skeleton of a real URDF, as the reference robots were before issue 49: the same joints and
links, every inertial 1 kg with 0.01 kg m^2, no visual, collision, material or <mujoco> element. The body
tests compare a skeleton with its real robot (what `rhi-gen diff` told when the vendors' files came in)."""
from __future__ import annotations

from pathlib import Path

from lxml import etree

STRIPPED = ("visual", "collision", "material", "mujoco")


def write_skeleton(real: Path, to: Path) -> Path:
    root = etree.parse(str(real), etree.XMLParser(remove_comments=True)).getroot()
    for tag in STRIPPED:
        for el in list(root.iter(tag)):
            parent = el.getparent()
            if parent is not None:
                parent.remove(el)
    for inertial in root.iter("inertial"):
        for child in list(inertial):
            inertial.remove(child)
        etree.SubElement(inertial, "mass", value="1.0")
        etree.SubElement(inertial, "inertia", ixx="0.01", ixy="0", ixz="0", iyy="0.01", iyz="0", izz="0.01")
    to.write_bytes(etree.tostring(root, xml_declaration=True, encoding="utf-8"))
    return to
