"""The G1 standing on MuJoCo with its vendor's meshes installed (issue 49): the mesh collisions in place of the
stand-ins that the physics keeps without them.

A scratch project holds the reference G1 (robots/unitree/g1.{yaml,urdf}: unitree_ros's URDF) with a meshes/
folder beside its URDF holding the meshes it names, Unitree's own STL files as the test extra's example-robot-data
wheel installs them (g1_description/meshes, BSD-3-Clause). `rhi-gen generate` copies them into the package and
names them by package:// in the installed URDF; the fake robot resolves them under the package's prefix, as
AMENT_PREFIX_PATH would. The driver harness is built in the physics cell (Jazzy, MuJoCo) and its physics_stand_stiff
section run: the base free on the floor, 10 s, held to the same bounds as without meshes
(tests/cpp/test_cpp_drivers.py STAND_HEIGHT, STAND_TILT), nothing but the feet touching the floor (the legs'
collision meshes are there now: a knee or a shin on the floor would show), and MuJoCo's model as heavy as Unitree's
URDF says (the meshes' own volumes add nothing: the URDF's inertials stand).
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from lxml import etree

from rhi_gen.cli import main
from tests.cpp.test_cpp_drivers import STAND_HEIGHT, STAND_TILT, STANDS, physics_figures
from tests.support.cpp_build import PACKAGE, PHYSICS_CELL, build_harness, load_models, prepare_robot_builds, run_binary
from tests.support.example_robot_data import example_robot_data_prefix
from tests.support.repo import REPO

LABEL = "unitree/g1"


def scratch_project(root: Path) -> Path:
    """The reference G1 with Unitree's meshes beside its URDF (only the files the URDF names)."""
    robot = root / "robots" / "unitree"
    robot.mkdir(parents=True)
    for name in ("g1.yaml", "g1.urdf"):
        shutil.copyfile(REPO / "robots" / "unitree" / name, robot / name)
    source = example_robot_data_prefix() / "share/example-robot-data/robots/g1_description"
    for ref in sorted({str(m.get("filename")) for m in etree.parse(str(robot / "g1.urdf")).iter("mesh")}):
        (robot / ref).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source / ref, robot / ref)
    return root


def test_the_g1_stands_on_its_mesh_collisions(tmp_path, cpp_builder, capsys, report):
    project = scratch_project(tmp_path / "project")
    assert main(["generate", "--project", str(project)]) == 0
    assert "meshes:" not in capsys.readouterr().out  # every mesh found: nothing to say
    package = project / "generated" / PACKAGE
    assert len(list((package / "meshes" / "g1").rglob("*.STL"))) == 35
    build = prepare_robot_builds(load_models(project), package, tmp_path / "work")[0]
    linked, _ = build_harness(cpp_builder, build, PHYSICS_CELL[1], distro=PHYSICS_CELL[0], physics=True)
    assert linked.ok, linked.stderr[-4000:]
    run = run_binary(linked.path, ["--only=physics", f"--physics-urdf={package / 'urdf' / 'g1.urdf'}",
                                   "--physics-base=band", "--physics=stand_stiff",
                                   f"--physics-package-path={project / 'generated'}"])
    assert run.returncode == 0, run.describe()
    assert "meshes not found" not in run.stdout, run.stdout[-3000:]
    figures = {k.split(".", 1)[1]: v for k, v in physics_figures(run.stdout).items() if k.startswith("stand_stiff.")}
    touched = {k.split(".", 1)[1] for k in figures if k.startswith("touch.")}
    stand = STANDS[LABEL]
    assert touched == stand.feet, f"with meshes, the links that touched the floor: {sorted(touched)}"
    assert figures["fell_at_s"] < 0 and figures["base_z"] < STAND_HEIGHT and figures["tilt_deg"] < STAND_TILT, \
        {k: v for k, v in figures.items() if "." not in k}
    assert abs(figures["mass_kg"] - stand.vendor_mass) < 1e-5, figures["mass_kg"]
    geoms = re.search(r"^physics warning: (.*)$", run.stdout, re.M)
    assert geoms is None, geoms.group(1) if geoms else ""
    report(f"{LABEL} on MuJoCo with Unitree's meshes (35 STL), base free, 10 s, lower body at 500 N m/rad: base "
           f"{figures['base_z'] * 1000:.1f} mm from its start, tilt {figures['tilt_deg']:.2f} deg, on "
           f"{', '.join(sorted(touched))}; real-time factor {figures['rtf']:.2f}")
