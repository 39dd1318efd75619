"""The URDF corpus of tests/cli/test_corpus.py (and the yourdfpy oracle's): every URDF, and every xacro
that needs no ROS package, of the ``example-robot-data`` package, plus ../shared/upstream/urdf when it exists."""
from __future__ import annotations

import importlib.metadata
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.support import upstream_urdf

# label -> (words the one-line reason must contain, why the input itself is at fault)
EXPECTED_REJECTIONS: dict[str, tuple[tuple[str, ...], str]] = {
    "example-robot-data:alex_description/urdf/alex_psyonic_hands.urdf": (
        (":1037:", "mimics 'index_q1', which is not a joint of this URDF", "did you mean 'Left_index_q1'?"),
        ("the <mimic> tags name 'index_q1', 'middle_q1', ... but the joints are called 'Left_index_q1', "
         "'Right_index_q1', ...: the mimic targets do not exist")),
    "example-robot-data:hector_description/robots/quadrotor_base.urdf": (
        ("has no actuated joints",),
        "a quadrotor body: one link, no joint at all, so nothing a ros2_control driver could command"),
    "example-robot-data:iris_description/robots/iris_simple.urdf": (
        ("has no actuated joints",),
        "a drone whose rotor joints are all type=\"fixed\": nothing a ros2_control driver could command"),
    "example-robot-data:ur_description/urdf/ur3.urdf": (
        (":6:", "<robot> has no name attribute"),
        ("the root <robot> element has no name; urdfdom (and so robot_state_publisher and ros2_control) "
         "rejects such a file")),
    "example-robot-data:hector_description/robots/quadrotor_base.urdf.xacro": (
        ("<robot> has no name attribute",),
        ("a xacro macro library (it only defines quadrotor_base_macro, never calls it): not a robot; its "
         "<robot> has no name")),
    "example-robot-data:hector_description/robots/quadrotor_base.xacro": (
        ("cannot include 'package://example-robot-data/robots/hector_description/urdf/quadrotor_base.urdf.xacro'",
         "xacro does not resolve package:// URLs"),
        ("xacro:include with a package:// URL (xacro itself cannot open it) that points at a file the "
         "package does not contain (it lives in robots/, not urdf/)")),
}


@dataclass(frozen=True)
class Description:
    label: str   # "example-robot-data:<path under robots/>" or "upstream:<file>"
    path: Path
    robot: str   # the --robot name used


def robot_name(stem: str, taken: set[str]) -> str:
    """A valid, unique --robot name from a file stem: 'anymal-kinova' -> 'anymal_kinova'."""
    name = re.sub(r"[^a-z0-9]+", "_", stem.lower()).strip("_") or "robot"
    if not name[0].isalpha():
        name = f"r_{name}"
    name = re.sub(r"_+", "_", name)[:40]
    base, n = name, 2
    while name in taken:
        name = f"{base}_{n}"
        n += 1
    taken.add(name)
    return name


def example_robot(under: str) -> Path:
    """A description of example-robot-data by its path under robots/ (``talos_data/robots/talos_reduced.urdf``)."""
    for description in corpus():
        if description.label == f"example-robot-data:{under}":
            return description.path
    pytest.fail(f"example-robot-data has no robots/{under}")


def corpus() -> list[Description]:
    try:
        files = importlib.metadata.files("example-robot-data") or []
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        pytest.fail("example-robot-data is not installed: pip install -e '.[test]' (it is a test dependency)")
    found: list[tuple[str, Path]] = []
    for f in files:
        text = str(f)
        if not text.endswith((".urdf", ".xacro")) or "/robots/" not in f"/{text}":
            continue
        under = text.split("example-robot-data/robots/", 1)[-1]
        found.append((f"example-robot-data:{under}", Path(str(dist.locate_file(f)))))
    found += [(f"upstream:{p.name}", p) for p in (*upstream_urdf.in_repo(), *upstream_urdf.shared_only())]
    found.sort(key=lambda item: item[0])
    taken: set[str] = set()
    return [Description(label, path, robot_name(path.name.split(".")[0], taken)) for label, path in found]
