"""The vendor YAML's transmissions / coupled_joints / urdf_transmissions: good values, and every hostile one
a single line naming file:line, the key and a fix, never a traceback."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.inputs.vendor_transmissions import condition
from tests.support.vendor_yaml import ARM_YAML

BASE = ARM_YAML  # the next line is line 10
WRIST = "coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[0.5, 0.5], [0.5, -0.5]]\n"


def load(tmp_path: Path, text: str):
    path = tmp_path / "arm.yaml"
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return load_config(path)


def test_transmissions_and_coupled_joints_are_read(tmp_path):
    cfg = load(tmp_path, BASE + WRIST + "transmissions:\n  j3: {direction: -1, reduction: 50, offset: 0.25}\n"
                                        "  j1: {offset: -0.1}\nurdf_transmissions: false\n")
    assert cfg.transmissions == (("j3", -1, 50.0, 0.25), ("j1", 1, 1.0, -0.1))
    assert cfg.coupled_joints == (("wrist", ("j1", "j2"), ((0.5, 0.5), (0.5, -0.5))),)
    assert cfg.urdf_transmissions is False


def test_defaults_without_the_keys(tmp_path):
    cfg = load(tmp_path, BASE + "transmissions:\ncoupled_joints:\n")
    assert (cfg.transmissions, cfg.coupled_joints, cfg.urdf_transmissions) == ((), (), True)


@pytest.mark.parametrize("extra, line, key, words", [
    ("transmissions:\n  j1: {reduction: 0}\n", 11, "transmissions.j1.reduction", "direction: -1"),
    ("transmissions:\n  j1: {reduction: -50}\n", 11, "transmissions.j1.reduction", "direction: -1"),
    ("transmissions:\n  j1: {reduction: fifty}\n", 11, "transmissions.j1.reduction", "finite number"),
    ("transmissions:\n  j1: {reduction: true}\n", 11, "transmissions.j1.reduction", "finite number"),
    ("transmissions:\n  j1: {reduction: [50]}\n", 11, "transmissions.j1.reduction", "single value"),
    ("transmissions:\n  j1: {reduction: 1.0e+9}\n", 11, "transmissions.j1.reduction", "above"),
    ("transmissions:\n  j1: {direction: 2}\n", 11, "transmissions.j1.direction", "1 or -1"),
    ("transmissions:\n  j1: {direction: -1.0}\n", 11, "transmissions.j1.direction", "1 or -1"),
    ("transmissions:\n  j1: {direction: true}\n", 11, "transmissions.j1.direction", "1 or -1"),
    ("transmissions:\n  j1: {offset: .nan}\n", 11, "transmissions.j1.offset", "finite number"),
    ("transmissions:\n  j1: {offset: .inf}\n", 11, "transmissions.j1.offset", "finite number"),
    ("transmissions:\n  j1: {offset: 10}\n", 11, "transmissions.j1.offset", "beyond one turn is a mistake"),
    ("transmissions:\n  j1: {offset: '0.1'}\n", 11, "transmissions.j1.offset", "finite number"),
    ("transmissions:\n  j1: {reduction: 1" + "0" * 400 + "}\n", 11, "transmissions.j1.reduction", "finite number"),
    ("transmissions:\n  j1: {reductoin: 5}\n", 11, "transmissions.j1.reductoin", "did you mean 'reduction'"),
    ("transmissions:\n  j9: {reduction: 5}\n", 11, "transmissions.j9", "not a joint of joint_map"),
    ("transmissions:\n  j1: 50\n", 11, "transmissions.j1", "mapping"),
    ("transmissions: [j1]\n", 10, "transmissions", "mapping of joint name"),
    ("transmissions:\n  j1: {a: {b: [1, {c: 2}]}}\n", 11, "transmissions.j1.a", "unknown key"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, 2], [2, 4]]\n", 13,
     "coupled_joints.wrist.matrix", "matrix is singular: the motors cannot reach every joint position"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, 1], [1, 1.0000000000001]]\n", 13,
     "coupled_joints.wrist.matrix", "singular"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, 0], [0]]\n", 13,
     "coupled_joints.wrist.matrix[1]", "2 numbers"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: []\n", 13,
     "coupled_joints.wrist.matrix", "2 rows"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, .nan], [0, 1]]\n", 13,
     "coupled_joints.wrist.matrix[0][1]", "finite number"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, x], [0, 1]]\n", 13,
     "coupled_joints.wrist.matrix[0][1]", "finite number"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, false], [0, 1]]\n", 13,
     "coupled_joints.wrist.matrix[0][1]", "finite number"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j1]\n    matrix: [[1, 0], [0, 1]]\n", 12,
     "coupled_joints.wrist.joints[1]", "listed twice"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, jx]\n    matrix: [[1, 0], [0, 1]]\n", 12,
     "coupled_joints.wrist.joints[1]", "not a joint of joint_map"),
    ("coupled_joints:\n  wrist:\n    joints: [j1]\n    matrix: [[1]]\n", 12,
     "coupled_joints.wrist.joints", "2 to 16"),
    ("coupled_joints:\n  wrist:\n    joints: [" + ", ".join(["j1"] * 5000) + "]\n    matrix: []\n", 12,
     "coupled_joints.wrist.joints", "2 to 16"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n", 11, "coupled_joints.wrist", "'matrix' is missing"),
    (WRIST + "  ankle:\n    joints: [j3, j2]\n    matrix: [[1, 0], [0, 1]]\n", 15,
     "coupled_joints.ankle.joints[1]", "already in coupled_joints.wrist"),
    ("coupled_joints:\n  wrist:\n    joints: [j1, j2]\n    matrix: [[1, 0], [0, 1]]\n    extra: 1\n", 14,
     "coupled_joints.wrist.extra", "unknown key"),
    ("coupled_joints: [j1, j2]\n", 10, "coupled_joints", "mapping of group name"),
    ("coupled_joints:\n  'wrist\\n; x':\n    joints: [j1, j2]\n", 11, "coupled_joints.wrist\\n; x", "not a group name"),
    ("coupled_joints:\n  '':\n    joints: [j1, j2]\n", 11, "coupled_joints.", "not a group name"),
    (WRIST + "transmissions:\n  j2: {direction: -1}\n", 15, "transmissions.j2.direction",
     "joint 'j2' is coupled: its direction and reduction are in coupled_joints.wrist.matrix"),
    (WRIST + "transmissions:\n  j1: {offset: 0.1, reduction: 2}\n", 15, "transmissions.j1.reduction", "is coupled"),
    ("urdf_transmissions: sometimes\n", 10, "urdf_transmissions", "true or false"),
])
def test_hostile_values_are_one_line_with_file_line_key_and_fix(tmp_path, extra, line, key, words):
    with pytest.raises(ConfigError) as info:
        load(tmp_path, BASE + extra)
    err = info.value
    message = str(err)
    assert "\n" not in message and message.startswith(f"{tmp_path / 'arm.yaml'}:{line}: {key}: "), message
    assert (err.line, err.key) == (line, key), message
    assert words in message and " -> " in message


def test_condition_is_one_for_orthogonal_rows_and_zero_for_singular():
    assert condition([(0.5, 0.5), (0.5, -0.5)]) == pytest.approx(1.0)
    assert condition([(2.0, 0.0, 0.0), (0.0, 3.0, 0.0), (0.0, 0.0, 4.0)]) == pytest.approx(1.0)
    assert condition([(1.0, 2.0), (2.0, 4.0)]) == 0.0
    assert condition([(0.0, 0.0), (0.0, 1.0)]) == 0.0
    assert condition([(1e308, 1e308), (1e308, -1e308)]) == 0.0  # overflows: refused rather than trusted
