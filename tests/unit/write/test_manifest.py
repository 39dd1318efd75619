"""generated/.rhi-gen-manifest: deterministic text, round trip, hashes that ignore user regions."""
from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path

import pytest

from rhi_gen import __version__
from rhi_gen.cli import main
from rhi_gen.errors import ManifestError
from rhi_gen.render.markers import REGION_BEGIN, REGION_END
from rhi_gen.write.manifest import (
    GroupRecord,
    JointRecord,
    Manifest,
    RobotRecord,
    TransmissionRecord,
    dumps,
    generated_hash,
    loads,
    parse,
)
from tests.support.repo import REPO, copy_project


def _record(key="unitree/g1", joints=None) -> RobotRecord:
    joints = joints or (JointRecord(0, "hip", "revolute", -1.5, 2.25, 32.0, 88.0),
                        JointRecord(1, "wheel", "continuous", None, None, 10.0, 5.0),
                        JointRecord(2, "odd", "prismatic", float("-inf"), float("inf"), 0.1, 1e-9))
    return RobotRecord(key, "robots/unitree/g1.yaml", "a" * 64, "robots/unitree/g1.urdf", "b" * 64,
                       35, "float", tuple(joints))


def test_round_trip_and_layout():
    m = Manifest("0.1.0", {"unitree/g1": _record(), "acme/arm": _record("acme/arm")},
                 {"robot_hardware_interface/b.cpp": "1" * 64, "robot_hardware_interface/a.cpp": "2" * 64})
    text = dumps(m)
    assert loads(text) == m
    assert text.endswith("}\n") and "\r" not in text
    data = json.loads(text)
    assert list(data) == sorted(data)
    assert list(data["robots"]) == ["acme/arm", "unitree/g1"]
    assert list(data["files"]) == sorted(data["files"])
    # one joint per line, one file per line: a rename is a one-line manifest diff
    assert '        [0, "hip", "revolute", -1.5, 2.25, 32.0, 88.0],\n' in text
    assert '        [2, "odd", "prismatic", "-inf", "inf", 0.1, 1e-09]\n' in text
    assert f'    "robot_hardware_interface/a.cpp": "{"2" * 64}",\n' in text
    assert dumps(loads(text)) == text


def test_command_modes_round_trip_and_an_old_manifest_has_none():
    record = replace(_record(), command_modes=(("hip", "state"), ("wheel", "velocity")))
    text = dumps(Manifest("0.1.0", {"unitree/g1": record}, {}))
    assert loads(text).robots["unitree/g1"].command_modes == (("hip", "state"), ("wheel", "velocity"))
    data = json.loads(text)
    del data["robots"]["unitree/g1"]["command_modes"]  # a manifest from before they were recorded
    assert loads(json.dumps(data)).robots["unitree/g1"].command_modes is None


def test_generated_hash_ignores_region_bodies_only():
    base = f"a\n// {REGION_BEGIN} r\n// {REGION_END} r\nb\n"
    assert generated_hash(base.replace("r\n//", "r\nuser();\n//", 1)) == generated_hash(base)
    assert generated_hash(base.replace("b\n", "c\n")) != generated_hash(base)


@pytest.mark.parametrize("text, line", [("{\n  \"format\": 1,\n  oops\n}\n", 3), ("[]", None),
                                        ('{"format": 99, "robots": {}, "files": {}, "generator_version": "x"}', None)])
def test_corrupt_manifest_is_one_line_error(text, line):
    with pytest.raises(ManifestError) as info:
        loads(text)
    assert str(info.value).startswith("generated/.rhi-gen-manifest" + (f":{line}" if line else "") + ": ")
    assert "--force" in str(info.value)
    with pytest.raises(ManifestError, match="UTF-8"):
        parse(b"\xff\xfe")


def _project(tmp_path: Path, name: str) -> Path:
    return copy_project(tmp_path / name)


def test_generated_manifest_is_deterministic_and_machine_independent(tmp_path, capsys):
    one, two = _project(tmp_path, "one"), _project(tmp_path, "elsewhere_with_a_longer_name")
    assert main(["generate", "--project", str(one)]) == 0
    assert main(["generate", "--project", str(two)]) == 0
    a = (one / "generated" / ".rhi-gen-manifest").read_bytes()
    b = (two / "generated" / ".rhi-gen-manifest").read_bytes()
    assert a == b
    text = a.decode()
    assert str(tmp_path) not in text and "/tmp" not in text and "\\" not in text
    assert not re.search(r"\d{4}-\d\d-\d\d|\d\d:\d\d:\d\d", text), "no timestamps"
    m = loads(text)
    assert m.generator_version == __version__
    assert sorted(m.robots) == ["agibot/x2", "engineai/pm01", "unitree/g1"]
    g1 = m.robots["unitree/g1"]
    assert (g1.yaml_path, g1.urdf_path, g1.motor_count, g1.float_type) == \
        ("robots/unitree/g1.yaml", "robots/unitree/g1.urdf", 29, "float")
    assert [j.index for j in g1.joints] == list(range(29)) and g1.joints[3].name == "left_knee_joint"
    # and its body (Unitree's: 33.341142 kg, spheres on the feet, meshes elsewhere), deterministic with the rest
    assert g1.body is not None and round(g1.body.total_mass, 6) == 33.341142
    assert dict(g1.body.collisions)["sphere"] == 8
    # every generated file is recorded, with the hash of its text without region bodies
    package = one / "generated" / "robot_hardware_interface"
    on_disk = sorted(p.relative_to(one / "generated").as_posix() for p in package.rglob("*") if p.is_file())
    assert sorted(m.files) == on_disk
    for rel, digest in m.files.items():
        assert digest == generated_hash((one / "generated" / rel).read_text())
    # regenerating changes nothing, not even the manifest
    mtime = (one / "generated" / ".rhi-gen-manifest").stat().st_mtime_ns
    capsys.readouterr()
    assert main(["generate", "--project", str(one)]) == 0
    assert "0 created, 0 changed" in capsys.readouterr().out
    assert (one / "generated" / ".rhi-gen-manifest").stat().st_mtime_ns == mtime


def test_corrupt_manifest_blocks_generate_and_force_rebuilds_it(tmp_path, capsys):
    root = _project(tmp_path, "p")
    assert main(["generate", "--project", str(root)]) == 0
    manifest = root / "generated" / ".rhi-gen-manifest"
    good = manifest.read_bytes()
    manifest.write_text("{ not json\n")
    capsys.readouterr()
    assert main(["generate", "--project", str(root)]) == 2
    err = capsys.readouterr().err
    assert "generated/.rhi-gen-manifest:1: is not valid JSON" in err and "--force" in err
    assert main(["check", "--project", str(root)]) == 2
    assert main(["generate", "--force", "--project", str(root)]) == 0
    assert manifest.read_bytes() == good
    assert (root / "generated" / ".rhi-gen-backup" / ".rhi-gen-manifest.1").read_text() == "{ not json\n"


def test_transmissions_round_trip_only_where_there_are_any():
    plain = _record()
    geared = replace(_record("acme/arm"),
                     transmissions=(TransmissionRecord("hip", -1, 50.0, 0.25),),
                     coupled_groups=(GroupRecord("wrist", ("wheel", "odd"), ((0.5, 0.5), (0.5, -0.5))),))
    text = dumps(Manifest("0.1.0", {"unitree/g1": plain, "acme/arm": geared}, {}))
    assert loads(text) == Manifest("0.1.0", {"unitree/g1": plain, "acme/arm": geared}, {})
    data = json.loads(text)
    # a robot without transmissions has no such keys: every existing manifest keeps its bytes
    assert "transmissions" not in data["robots"]["unitree/g1"] and "coupled_groups" not in data["robots"]["unitree/g1"]
    assert data["robots"]["acme/arm"]["transmissions"] == {"hip": [-1, 50.0, 0.25]}
    assert data["robots"]["acme/arm"]["coupled_groups"] == {
        "wrist": {"joints": ["wheel", "odd"], "matrix": [[0.5, 0.5], [0.5, -0.5]]}}
    assert '      "hip": [-1, 50.0, 0.25]\n' in text


@pytest.mark.parametrize("bad", ['{"hip": [2, 50.0, 0.0]}', '{"hip": [1, "x", 0.0]}', '{"hip": [1, 2.0]}',
                                 '{"hip": "geared"}'])
def test_corrupt_transmissions_are_one_line_errors(bad):
    text = dumps(Manifest("0.1.0", {"unitree/g1": _record()}, {}))
    data = json.loads(text)
    data["robots"]["unitree/g1"]["transmissions"] = json.loads(bad)
    with pytest.raises(ManifestError) as info:
        loads(json.dumps(data))
    assert "transmissions" in str(info.value) and "\n" not in str(info.value)


def test_reference_manifest_without_transmissions_reads_as_identity():
    manifest = loads((REPO / "generated" / ".rhi-gen-manifest").read_text(encoding="utf-8"))
    assert manifest.robots and all(not r.transmissions and not r.coupled_groups for r in manifest.robots.values())
