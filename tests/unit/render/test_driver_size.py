"""Generate data, not logic: a reference robot's driver carries its data and transport glue only.

The robot-independent logic lives once in the package's common/ headers. Measured on the checked-in
drivers (header + source of each reference robot): each is at most 450 lines, and at most 15% of
its code lines appear verbatim in another robot's driver. Code lines are what a reviewer reads as
logic: not blank, not comments, not preprocessor lines, not a lone brace or access specifier (the
namespace skeleton and include lists every C++ file shares), not a line of literals only (data, such
as the motor group names two robots with the same limbs share).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.support.repo import PACKAGE, REPO

PKG = REPO / "generated" / PACKAGE
REFERENCE = ("unitree/g1", "agibot/x2", "engineai/pm01")
SKELETON = {"{", "}", "};", "});", "public:", "private:", "protected:"}
NAMESPACE_LINE = re.compile(r"^(namespace(\s+[\w:]+)?|\}\s*// namespace(\s+[\w:]+)?)$")  # opening or closing one
_LITERAL = r'"(?:[^"\\]|\\.)*"|-?(?:0x[0-9A-Fa-f]+|[0-9.]+(?:e[-+]?[0-9]+)?)U?|true|false|nullptr'
LITERALS_ONLY = re.compile(rf"^[{{(]*\s*(?:(?:{_LITERAL})\s*[,}})]*\s*)+;?$")  # "a", "b", / {1, 2.5}},


def driver_files(robot: str) -> tuple[Path, Path]:
    return PKG / "include" / "robot_hardware_interface" / f"{robot}.hpp", PKG / "src" / f"{robot}.cpp"


def code_lines(robot: str) -> list[str]:
    out = []
    for path in driver_files(robot):
        for line in path.read_text(encoding="utf-8").splitlines():
            s = line.strip()
            if (s and not s.startswith(("//", "#")) and s not in SKELETON and not NAMESPACE_LINE.match(s)
                    and not LITERALS_ONLY.match(s)):
                out.append(s)
    return out


@pytest.mark.parametrize("robot", REFERENCE)
def test_a_driver_is_at_most_450_lines(robot):
    lines = sum(len(p.read_text(encoding="utf-8").splitlines()) for p in driver_files(robot))
    assert lines <= 450, f"{robot}: {lines} lines (header + source)"


@pytest.mark.parametrize("robot", REFERENCE)
def test_at_most_15_percent_of_a_driver_repeats_another(robot):
    mine = code_lines(robot)
    others = {line for other in REFERENCE if other != robot for line in code_lines(other)}
    repeated = [line for line in mine if line in others]
    assert len(mine) >= 40, f"{robot}: only {len(mine)} code lines; is the joint table still generated?"
    share = len(repeated) / len(mine)
    assert share <= 0.15, f"{robot}: {len(repeated)} of {len(mine)} code lines repeated:\n" + "\n".join(repeated)


def test_the_measure_catches_repeated_logic():
    """The same measure on a driver that pasted logic from another is above the bar."""
    g1 = code_lines("unitree/g1")
    pasted = code_lines("agibot/x2") + g1[: len(g1) // 2]
    others = set(g1)
    assert sum(line in others for line in pasted) / len(pasted) > 0.15


@pytest.mark.parametrize(("line", "data"), [
    ('"left leg motors", "right leg motors",', True), ('{{"waist motors", "head motors"}},', True),
    ('{"lo", true, 2000, 1, 100, 1000, 1000, 70, 85, 0x0U}};', True), ("-0.5, 2.5e-3, nullptr},", True),
    ("kMotorGroups.data(), kMotorGroups.size(),", False), ('RCLCPP_INFO(logger, "x");', False),
    ('{"j1", 0, kPosition, -1.0, 1.0, 2.0, 3.0, 0.0, 0.0, 0},', False), ("return 0;", False),
])
def test_only_lines_of_literals_count_as_data(line, data):
    assert bool(LITERALS_ONLY.match(line)) == data
