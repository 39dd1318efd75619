"""tests/support/ament_lint.py runs the real ament_cpplint / ament_uncrustify and reads their findings right.

A small package in the ROS 2 style gives no finding; the same package with known defects gives exactly
the findings expected (file, line, rule). The README-ready command line runs the same linters.
A missing linter wheel fails these tests (never a skip).
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.ament_lint import COMMAND_LINE, run_cpplint, run_uncrustify

HEADER = """// Copyright 2025 rhi-gen contributors
//
// Licensed under the Apache License, Version 2.0 (the "License");

#ifndef DEMO__DEMO_HPP_
#define DEMO__DEMO_HPP_

#include <cstdint>

namespace demo
{

int64_t add(int64_t a, int64_t b);

}  // namespace demo

#endif  // DEMO__DEMO_HPP_
"""
SOURCE = """// Copyright 2025 rhi-gen contributors
//
// Licensed under the Apache License, Version 2.0 (the "License");

#include "demo/demo.hpp"

namespace demo
{

int64_t add(int64_t a, int64_t b)
{
  return a + b;
}

}  // namespace demo
"""
# No copyright (line 0), K&R braces (line 3), a C `long` (line 4), a 102-character line (line 5).
BAD_SOURCE = "\n".join([
    '#include "demo/demo.hpp"',
    "",
    "namespace demo {",
    "long twice(long a) { return 2 * a; }",
    'const char kText[] = "' + "x" * 78 + '";',
    "}  // namespace demo",
    "",
])


def _package(root: Path, source: str) -> Path:
    (root / "include" / "demo").mkdir(parents=True)
    (root / "src").mkdir()
    (root / "include" / "demo" / "demo.hpp").write_text(HEADER)
    (root / "src" / "demo.cpp").write_text(source)
    return root


def test_ros2_style_package_has_no_finding(tmp_path):
    package = _package(tmp_path / "good", SOURCE)
    assert run_cpplint(package) == []
    result = run_uncrustify(package)
    assert result.findings == [] and result.diffs == {}


def test_known_defects_are_reported(tmp_path):
    package = _package(tmp_path / "bad", BAD_SOURCE)
    found = {(f.file, f.line, f.rule) for f in run_cpplint(package)}
    assert found == {("src/demo.cpp", 0, "legal/copyright"), ("src/demo.cpp", 4, "runtime/int"),
                     ("src/demo.cpp", 5, "whitespace/line_length")}, found
    result = run_uncrustify(package)
    assert set(result.diffs) == {"src/demo.cpp"}
    assert [f.line for f in result.findings] == [3], result.findings
    hunk = result.findings[0].message.splitlines()
    assert hunk[:2] == ["-namespace demo {", "-long twice(long a) { return 2 * a; }"], hunk
    assert "+namespace demo" in hunk and "+{" in hunk, hunk
    assert "+long twice(long a) {return 2 * a;}" in hunk, hunk   # the ROS 2 style of one-line bodies
    assert result.lines_changed() == {"src/demo.cpp": (3, 5)}


def test_readme_command_line_runs_both_linters(tmp_path):
    """COMMAND_LINE from a repository root whose .venv is this interpreter's prefix."""
    root = tmp_path / "repo"
    _package(root / "generated" / "robot_hardware_interface", BAD_SOURCE)
    os.symlink(sys.prefix, root / ".venv")
    proc = subprocess.run(["bash", "-c", COMMAND_LINE], cwd=root, capture_output=True, text=True,
                          env={**os.environ, "LC_ALL": "C"}, timeout=300)
    out = proc.stdout + proc.stderr
    assert "Category 'runtime/int' errors found: 1" in out, out[-3000:]
    assert "Code style divergence in file 'src/demo.cpp'" in out, out[-3000:]
    assert proc.returncode != 0


@pytest.mark.parametrize("tool", ["ament_cpplint", "ament_uncrustify"])
def test_linters_come_from_the_wheels(tool):
    import sysconfig
    assert (Path(sysconfig.get_path("scripts")) / tool).is_file(), f"{tool}: pip install -e '.[test]'"
