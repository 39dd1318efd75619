"""Meshes a vendor's URDF names by relative path: copied into the package and named by package:// when they
lie beside the input, one line saying how to provide them when they do not (inputs/urdf_meshes.py).

The G1's real URDF (tests/data/upstream_urdf) with a scratch meshes/ folder of the real G1 meshes, as the
test extra example-robot-data installs them.
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from lxml import etree

from rhi_gen.cli import main
from tests.support import upstream_urdf
from tests.support.example_robot_data import example_robot_data_prefix

UPSTREAM_G1 = upstream_urdf.find("unitree_g1.urdf")
PACKAGE = "robot_hardware_interface"
PREFIX = f"package://{PACKAGE}/"


def run(args: list[str], capsys) -> tuple[int, str, str]:
    code = main(args)
    out = capsys.readouterr()
    return code, out.out, out.err


def g1_meshes_folder() -> Path:
    """example-robot-data's g1_description/meshes/ (the same STL files unitree_ros ships)."""
    folder = example_robot_data_prefix() / "share/example-robot-data/robots/g1_description/meshes"
    assert folder.is_dir(), f"example-robot-data installs no {folder}"
    return folder


def references(urdf: Path) -> list[str]:
    return sorted({str(m.get("filename")) for m in etree.parse(str(urdf)).iter("mesh")})


@pytest.fixture
def g1_project(tmp_path: Path) -> Path:
    """tmp_path/proj: a copy of the G1's URDF with meshes/ beside it holding exactly the meshes it names."""
    assert UPSTREAM_G1 is not None, "tests/data/upstream_urdf/unitree_g1.urdf is missing"
    proj = tmp_path / "proj"
    (proj / "meshes").mkdir(parents=True)
    shutil.copyfile(UPSTREAM_G1, proj / "g1.urdf")
    source = g1_meshes_folder()
    for ref in references(proj / "g1.urdf"):
        assert ref.startswith("meshes/"), ref
        shutil.copyfile(source / ref.removeprefix("meshes/"), proj / ref)
    return proj


def new_g1(proj: Path, capsys) -> tuple[int, str, str]:
    return run(["new", "--vendor", "unitree", "--robot", "g1", "--urdf", str(proj / "g1.urdf"),
                "--project", str(proj)], capsys)


def package_files(proj: Path, folder: str) -> dict[str, bytes]:
    root = proj / "generated" / PACKAGE / folder
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()} \
        if root.is_dir() else {}


def test_meshes_beside_the_input_are_copied_and_named_by_package_uri(g1_project, capsys):
    proj = g1_project
    code, out, err = new_g1(proj, capsys)
    assert code == 0, err
    assert "meshes:" not in out
    package = proj / "generated" / PACKAGE
    refs = references(proj / "g1.urdf")
    # exactly the referenced meshes, byte for byte, under meshes/<robot>/<path beside the URDF>
    copied = package_files(proj, "meshes")
    assert copied == {f"g1/{ref}": (proj / ref).read_bytes() for ref in refs}
    assert f"  created   generated/{PACKAGE}/meshes/g1/ ({len(refs)} meshes)" in out
    # every mesh of the installed URDF resolves to a file of the package
    installed = references(package / "urdf/g1.urdf")
    assert installed and all(ref.startswith(PREFIX) for ref in installed)
    for ref in installed:
        assert (package / ref.removeprefix(PREFIX)).is_file(), ref
    # the input keeps the vendor's paths; CMakeLists installs the folder
    assert references(proj / "g1.urdf") == refs
    assert "install(DIRECTORY meshes DESTINATION share/${PROJECT_NAME})" in (package / "CMakeLists.txt").read_text()
    manifest = (proj / "generated/.rhi-gen-manifest").read_text()
    assert f"{PACKAGE}/meshes/g1/meshes/pelvis.STL" in manifest
    assert run(["check", "--project", str(proj)], capsys)[0] == 0

    # a copy edited: check fails naming it, generate restores it
    edited = package / "meshes/g1/meshes/pelvis.STL"
    edited.write_bytes(edited.read_bytes() + b"x")
    code, out, _ = run(["check", "--project", str(proj)], capsys)
    assert code == 1 and f"generated/{PACKAGE}/meshes/g1/meshes/pelvis.STL" in out
    # a file that is not a copy of a referenced mesh: check fails naming it
    (package / "meshes/g1/stray.stl").write_bytes(b"")
    code, out, _ = run(["check", "--project", str(proj)], capsys)
    assert code == 1 and f"generated/{PACKAGE}/meshes/g1/stray.stl" in out
    assert run(["generate", "--project", str(proj)], capsys)[0] == 0
    assert package_files(proj, "meshes") == copied

    # the meshes gone from beside the input: regenerating removes the copies and says how to provide them
    shutil.rmtree(proj / "meshes")
    code, out, err = run(["generate", "--project", str(proj)], capsys)
    assert code == 0, err
    assert not (package / "meshes").exists()
    lines = [line for line in out.splitlines() if line.startswith("meshes:")]
    assert lines == [
        (f"meshes: unitree/g1 names {len(refs)} meshes that are not in the project (first: meshes/pelvis.STL, "
        "looked for meshes/pelvis.STL); optional, the package and the fake robot work without them: to install "
        "them, put the vendor's meshes/ folder beside g1.urdf (only the files the URDF names are copied) and run "
        "`rhi-gen generate`")], out
    assert references(package / "urdf/g1.urdf") == refs  # as the vendor wrote them
    assert "install(DIRECTORY meshes" not in (package / "CMakeLists.txt").read_text()
    assert run(["check", "--project", str(proj)], capsys)[0] == 0


def test_missing_meshes_are_one_line_and_nothing_is_copied(g1_project, capsys):
    proj = g1_project
    shutil.rmtree(proj / "meshes")
    code, out, err = new_g1(proj, capsys)
    assert code == 0, err
    lines = [line for line in out.splitlines() if line.startswith("meshes:")]
    assert len(lines) == 1 and "looked for meshes/" in lines[0] and "beside g1.urdf" in lines[0]
    assert not (proj / "generated" / PACKAGE / "meshes").exists()
    assert f"{PACKAGE}/meshes/" not in (proj / "generated/.rhi-gen-manifest").read_text()
    assert run(["check", "--project", str(proj)], capsys)[0] == 0


def test_a_mesh_provided_later_makes_check_fail(g1_project, capsys):
    """check's memo counts where missing meshes were looked for: one appearing there is a difference."""
    proj = g1_project
    keep = proj.parent / "kept"
    shutil.move(proj / "meshes", keep)
    assert new_g1(proj, capsys)[0] == 0
    assert run(["check", "--project", str(proj)], capsys)[0] == 0
    shutil.move(keep, proj / "meshes")
    code, out, _ = run(["check", "--project", str(proj)], capsys)
    assert code == 1 and f"{PACKAGE}/meshes/g1/meshes/pelvis.STL" in out


def test_copies_are_deterministic(g1_project, tmp_path, capsys):
    other = tmp_path / "other"
    shutil.copytree(g1_project, other)
    assert new_g1(g1_project, capsys)[0] == 0
    assert new_g1(other, capsys)[0] == 0
    assert run(["generate", "--project", str(other)], capsys)[0] == 0
    first, second = (package_files(p, ".") for p in (g1_project, other))
    assert first == second
    manifests = [(p / "generated/.rhi-gen-manifest").read_bytes() for p in (g1_project, other)]
    assert manifests[0] == manifests[1]


def test_two_robots_with_the_same_mesh_names_do_not_collide(g1_project, capsys):
    proj = g1_project
    assert new_g1(proj, capsys)[0] == 0
    twin = proj / "twin"
    (twin / "meshes").mkdir(parents=True)
    text = (proj / "g1.urdf").read_text()
    (twin / "g1.urdf").write_text(re.sub(r'<robot name="[^"]*"', '<robot name="twin"', text, count=1))
    for ref in references(proj / "g1.urdf"):
        (twin / ref).write_bytes(b"twin " + ref.encode())
    code, _, err = run(["new", "--vendor", "acme", "--robot", "twin", "--urdf", str(twin / "g1.urdf"),
                        "--transport", "generic_topics", "--project", str(proj)], capsys)
    assert code == 0, err
    assert run(["generate", "--project", str(proj)], capsys)[0] == 0
    meshes = package_files(proj, "meshes")
    assert meshes["g1/meshes/pelvis.STL"] == (proj / "meshes/pelvis.STL").read_bytes()
    assert meshes["twin/meshes/pelvis.STL"] == b"twin meshes/pelvis.STL"
    package = proj / "generated" / PACKAGE
    assert f"{PREFIX}meshes/twin/meshes/pelvis.STL" in (package / "urdf/twin.urdf").read_text()
