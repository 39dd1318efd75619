"""yourdfpy as an independent oracle for the strict URDF loader (rhi_gen/inputs/urdf_loader.py).

rhi-gen never imports yourdfpy (it recovers from malformed XML, drops nothing it does not know and
pulls trimesh and numpy in), so it is a test dependency only. On every plain URDF of the
example-robot-data corpus that our loader accepts, both must agree on every joint: name and order,
type, parent and child, limits, mimic (target, multiplier, offset), and which joints are actuated.
Files our loader rejects must be ones the corpus test lists as genuinely broken.
"""
from __future__ import annotations

import io
import math

import pytest
import yourdfpy

from rhi_gen.errors import UrdfError
from rhi_gen.inputs.urdf_loader import load_urdf
from tests.support.corpus import EXPECTED_REJECTIONS, corpus

PLAIN = [d for d in corpus() if d.label.startswith("example-robot-data:") and d.path.name.endswith(".urdf")]


def _same_number(ours: float | None, theirs: float | None) -> bool:
    if ours is None or theirs is None:
        return ours is None and theirs is None
    return ours == theirs or (math.isinf(ours) and math.isinf(theirs) and (ours > 0) == (theirs > 0))


def _their_limit(limit: object, attr: str) -> float | None:
    value = getattr(limit, attr, None) if limit is not None else None
    return None if value is None else float(value)


def test_the_corpus_has_plain_urdfs_with_mimic_joints_and_limits():
    assert len(PLAIN) >= 30, [d.label for d in PLAIN]
    loaded = []
    for d in PLAIN:
        try:
            loaded.append(load_urdf(d.path))
        except UrdfError:
            continue
    assert sum(len(r.mimic_joints) for r in loaded) >= 4  # the comparison below covers mimic handling
    assert sum(1 for r in loaded for j in r.joints if j.limits and j.limits.lower is not None) >= 100


@pytest.mark.parametrize("description", PLAIN, ids=lambda d: d.label.split(":", 1)[1])
def test_loader_agrees_with_yourdfpy(description):
    try:
        ours = load_urdf(description.path)
    except UrdfError as exc:
        assert description.label in EXPECTED_REJECTIONS, f"rejected but not an expected rejection: {exc}"
        return
    theirs = yourdfpy.URDF.load(io.BytesIO(description.path.read_bytes()), build_scene_graph=False,
                                load_meshes=False, build_collision_scene_graph=False,
                                load_collision_meshes=False)
    their_joints = theirs.robot.joints
    assert [j.name for j in ours.joints] == [j.name for j in their_joints]
    assert list(ours.links) == [link.name for link in theirs.robot.links]
    for mine, other in zip(ours.joints, their_joints, strict=True):
        where = f"{description.label}: joint {mine.name}"
        assert (mine.type, mine.parent, mine.child) == (other.type, other.parent, other.child), where
        if other.limit is None:
            assert mine.limits is None, where
        else:
            assert mine.limits is not None, where
            for attr in ("lower", "upper", "velocity", "effort"):
                assert _same_number(getattr(mine.limits, attr), _their_limit(other.limit, attr)), (where, attr)
        if other.mimic is None:
            assert mine.mimic is None, where
        else:
            assert mine.mimic is not None, where
            assert mine.mimic.joint == other.mimic.joint, where
            assert mine.mimic.multiplier == float(other.mimic.multiplier if other.mimic.multiplier is not None
                                                  else 1.0), where
            assert mine.mimic.offset == float(other.mimic.offset if other.mimic.offset is not None else 0.0), where
    assert [j.name for j in ours.actuated_joints] == list(theirs.actuated_joint_names)
