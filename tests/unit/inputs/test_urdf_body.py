"""The body summary read from a URDF: masses, inertials, geometry by kind, mesh reference patterns."""
from __future__ import annotations

from rhi_gen.inputs.urdf_body import mesh_pattern
from rhi_gen.inputs.urdf_loader import load_urdf, parse_urdf_bytes
from tests.support import upstream_urdf
from tests.support.skeleton import write_skeleton

URDF = b"""<robot name="r">
  <link name="base">
    <inertial><mass value="2.5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <visual><geometry><mesh filename="meshes/base.STL"/></geometry></visual>
    <collision><geometry><box size="1 1 1"/></geometry></collision>
    <collision><geometry><mesh filename="package://pkg/meshes/base.dae"/></geometry></collision>
  </link>
  <link name="arm">
    <inertial><origin xyz="0 0 0.1"/><mass value="0.75"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <visual><geometry><mesh filename="file:///home/me/arm.stl"/></geometry></visual>
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
    <collision><geometry><cylinder radius="0.1" length="1"/></geometry></collision>
  </link>
  <link name="tool"/>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="f" type="fixed"><parent link="arm"/><child link="tool"/></joint>
</robot>"""


def test_body_is_summed_up_by_kind_and_pattern():
    body = parse_urdf_bytes(URDF, source="r.urdf").body
    assert body is not None
    assert (body.links, body.inertial_links, body.total_mass) == (3, 2, 3.25)
    assert [(i.link, i.mass) for i in body.inertials] == [("arm", 0.75), ("base", 2.5)]
    assert body.collisions == (("box", 1), ("cylinder", 1), ("mesh", 1), ("sphere", 1))
    assert body.visuals == (("mesh", 2),)
    # no machine path: a file:// reference keeps only its extension
    assert body.mesh_files == (("file://*.stl", 1), ("meshes/*.STL", 1), ("package://pkg/meshes/*.dae", 1))


def test_inertial_digest_sees_origin_and_tensor_but_not_number_spelling():
    base = parse_urdf_bytes(URDF, source="r.urdf").body
    respelled = parse_urdf_bytes(URDF.replace(b'<mass value="2.5"/>', b'<mass value="2.50"/>'), source="r.urdf").body
    moved = parse_urdf_bytes(URDF.replace(b'xyz="0 0 0.1"', b'xyz="0 0 0.2"'), source="r.urdf").body
    assert respelled == base
    assert moved is not None and base is not None
    assert moved.inertials[0].mass == base.inertials[0].mass and moved.inertials[0].digest != base.inertials[0].digest


def test_a_mass_that_is_not_a_number_is_kept_not_refused():
    body = parse_urdf_bytes(URDF.replace(b'<mass value="2.5"/>', b'<mass value="heavy"/>'), source="r.urdf").body
    assert body is not None and body.total_mass == 0.75 and body.inertials[1].mass is None


def test_mesh_patterns():
    assert mesh_pattern("./meshes/pelvis.stl") == "./meshes/*.stl"
    assert mesh_pattern("/opt/robot/x.STL") == "/*.STL"
    assert mesh_pattern("model://m/meshes/x") == "model://m/meshes/*"
    assert mesh_pattern(None) == "(no filename)"


def test_reference_skeleton_and_real_g1(tmp_path):
    real_path = upstream_urdf.require("unitree_g1.urdf")
    skeleton = load_urdf(write_skeleton(real_path, tmp_path / "g1.urdf")).body
    real = load_urdf(real_path).body
    assert skeleton is not None and real is not None
    assert skeleton.collisions == () and skeleton.visuals == ()
    assert {i.mass for i in skeleton.inertials} == {1.0}
    assert 30 < real.total_mass < 40 and real.inertial_links >= skeleton.inertial_links
    assert dict(real.collisions)["mesh"] > 0 and dict(real.visuals) == {"mesh": dict(real.visuals)["mesh"]}
    assert {pattern for pattern, _ in real.mesh_files} == {"meshes/*.STL"}
