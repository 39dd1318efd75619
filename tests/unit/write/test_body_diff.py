"""The body in the manifest and in `rhi-gen diff`'s robot terms: told when it changed, silent otherwise."""
from __future__ import annotations

import json
from dataclasses import replace

import pytest

from rhi_gen.errors import ManifestError
from rhi_gen.inputs.urdf_loader import load_urdf, parse_urdf_bytes
from rhi_gen.model.body import BodySummary, LinkInertial
from rhi_gen.write.manifest import JointRecord, Manifest, RobotRecord, dumps, loads
from rhi_gen.write.semantic_diff import diff_manifest, diff_robot
from tests.support import upstream_urdf
from tests.support.skeleton import write_skeleton

SAME_TABLES = ("  no joint, limit, command mode, transmission, motor count or float type change: the driver's "
               "tables are the same, only the body changed")


def _urdf(masses: dict[str, float], geometry: str = "") -> bytes:
    links = "".join(
        f'<link name="{name}"><inertial><mass value="{m}"/>'
        f'<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>{geometry}</link>'
        for name, m in masses.items())
    names = list(masses)
    joints = "".join(
        f'<joint name="j{k}" type="revolute"><parent link="{names[k - 1]}"/><child link="{names[k]}"/>'
        f'<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>' for k in range(1, len(names)))
    return f'<robot name="r">{links}{joints}</robot>'.encode()


def _body(masses: dict[str, float], geometry: str = "") -> BodySummary:
    body = parse_urdf_bytes(_urdf(masses, geometry), source="r.urdf").body
    assert body is not None
    return body


def R(body: BodySummary | None, urdf: str = "u" * 64) -> RobotRecord:
    return RobotRecord("acme/arm", "robots/acme/arm.yaml", "y" * 64, "robots/acme/arm.urdf", urdf, 1, "float",
                       (JointRecord(0, "j1", "revolute", -1.0, 1.0, 1.0, 1.0),), body=body)


SKELETON = {"base": 1.0, "upper": 1.0, "lower": 1.0}
REAL_GEOMETRY = ('<visual><geometry><mesh filename="meshes/part.STL"/></geometry></visual>'
                 '<collision><geometry><mesh filename="meshes/part.STL"/></geometry></collision>'
                 '<collision><geometry><sphere radius="0.1"/></geometry></collision>'
                 '<collision><geometry><cylinder radius="0.1" length="0.2"/></geometry></collision>')


def test_a_body_change_is_told_mass_inertials_collisions_visuals():
    old = R(_body(SKELETON))
    new = R(_body({"base": 3.5, "upper": 1.25, "lower": 1.0}, REAL_GEOMETRY), urdf="v" * 64)
    d = diff_robot(old, new)
    assert d.status == "changed" and not d.robot_changed  # the driver's tables are the same
    assert d.lines() == [
        "acme/arm: robots/acme/arm.urdf changed",
        "  body        mass 3 kg -> 5.75 kg; inertials: base 1 kg -> 3.5 kg, upper 1 kg -> 1.25 kg",
        "  body        collisions: none -> 3 meshes, 3 spheres, 3 cylinders",
        "  body        visuals: none -> 3 meshes; mesh files: none -> 6 meshes/*.STL (relative paths)",
        SAME_TABLES]


def test_many_changed_inertials_are_counted_and_a_tensor_change_is_named():
    many = {f"l{k}": 1.0 for k in range(8)}
    d = diff_robot(R(_body(many)), R(_body({**dict.fromkeys(many, 2.0), "l8": 1.0}), urdf="v" * 64))
    assert d.lines()[1] == "  body        mass 8 kg -> 17 kg; links 8 -> 9; 9 links' inertials changed (1 added)"
    tensor = _body(SKELETON)
    tensor = replace(tensor, inertials=(replace(tensor.inertials[0], digest="0" * 12), *tensor.inertials[1:]))
    d = diff_robot(R(_body(SKELETON)), R(tensor, urdf="v" * 64))
    assert d.lines()[1] == "  body        inertials: base origin or inertia tensor"


def test_an_unchanged_body_says_nothing():
    d = diff_robot(R(_body(SKELETON)), R(_body(SKELETON), urdf="v" * 64))
    assert d.body == ()
    assert d.lines() == ["acme/arm: robots/acme/arm.urdf changed",
                         ("  no joint, limit, command mode, transmission, motor count or float type change (see "
                          "the file diff)")]
    assert diff_robot(R(_body(SKELETON)), R(_body(SKELETON))).lines() == ["acme/arm: inputs unchanged"]


def test_the_body_round_trips_through_the_manifest():
    record = R(_body({"base": 3.5, "upper": 1.25, "lower": 0.1 + 0.2}, REAL_GEOMETRY))
    text = dumps(Manifest("0.1.0", {"acme/arm": record}, {}))
    assert loads(text) == Manifest("0.1.0", {"acme/arm": record}, {})
    assert dumps(loads(text)) == text
    assert '"total_mass_kg": 5.05' in text and '"meshes/*.STL": 6' in text


def test_an_old_manifest_without_a_body_loads_and_tells_no_body():
    text = dumps(Manifest("0.1.0", {"acme/arm": R(_body(SKELETON))}, {}))
    data = json.loads(text)
    del data["robots"]["acme/arm"]["body"]  # written before rhi-gen recorded bodies
    old = loads(json.dumps(data))
    assert old.robots["acme/arm"].body is None
    [d] = diff_manifest(old, [R(_body({"base": 9.0}, REAL_GEOMETRY), urdf="v" * 64)])
    assert d.body == () and not any("body" in line for line in d.lines())


@pytest.mark.parametrize("bad", [{"inertials": []}, {"inertials": {"a": [1.0]}}, "x",
                                 {"inertials": {}, "links": -1, "total_mass_kg": 0, "collisions": {},
                                  "visuals": {}, "mesh_files": {}}])
def test_a_corrupt_body_is_a_one_line_error(bad):
    data = json.loads(dumps(Manifest("0.1.0", {"acme/arm": R(_body(SKELETON))}, {})))
    data["robots"]["acme/arm"]["body"] = bad
    with pytest.raises(ManifestError) as e:
        loads(json.dumps(data))
    assert "\n" not in str(e.value) and "body" in str(e.value)


def test_the_reference_g1_skeleton_against_the_real_g1(tmp_path):
    """The pair the reference robots went through (issue 49): a skeleton of the G1 -> Unitree's own URDF."""
    real_path = upstream_urdf.require("unitree_g1.urdf")
    skeleton, real = load_urdf(write_skeleton(real_path, tmp_path / "g1.urdf")).body, load_urdf(real_path).body
    assert skeleton is not None and real is not None
    d = diff_robot(R(skeleton), R(real, urdf="v" * 64))
    lines = d.lines()
    assert lines[-1] == SAME_TABLES
    body = [line for line in lines if line.startswith("  body        ")]
    assert body[0].startswith(f"  body        mass {skeleton.inertial_links} kg -> 33.") and \
        "links' inertials changed" in body[0]
    assert body[1].startswith("  body        collisions: none -> ") and "meshes" in body[1] and "spheres" in body[1]
    assert body[2].startswith("  body        visuals: none -> 35 meshes; mesh files: none -> ")
    assert body[2].endswith("meshes/*.STL (relative paths)")


def test_the_link_inertial_record_keeps_an_unreadable_mass():
    body = BodySummary(1, 0.0, (LinkInertial("a", None, "f" * 12),), (), (), ())
    text = dumps(Manifest("0.1.0", {"acme/arm": R(body)}, {}))
    assert loads(text).robots["acme/arm"].body == body
