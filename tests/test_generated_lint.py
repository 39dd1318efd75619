"""A freshly generated package passes the ROS 2 linters `colcon test` runs (ament_lint_auto):
zero ament_cpplint and zero ament_uncrustify findings (ROS 2 default configuration, tests/ament_lint.py).

The package holds the reference robots of robots/ plus the harness's generic_topics robot
(tests/cpp/harness/robots/acme/scara), so every transport's templates are linted. To see and fix the
findings by hand: tests/ament_lint.py COMMAND_LINE, or `.venv/bin/python -m tests.ament_lint DIR`.
"""
from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from rhi_gen.cli import main
from tests.ament_lint import Finding, run_cpplint, run_uncrustify
from tests.cpp_build import PACKAGE, make_test_project


@pytest.fixture(scope="module")
def package(tmp_path_factory) -> Path:
    project = make_test_project(tmp_path_factory.mktemp("lint") / "project")
    assert main(["generate", "--project", str(project)]) == 0
    return project / "generated" / PACKAGE


def _report(findings: list[Finding], shown: int = 60) -> str:
    per_rule = ", ".join(f"{rule} {n}" for rule, n in Counter(f.rule for f in findings).most_common())
    lines = [f"{len(findings)} findings ({per_rule})"]
    lines += [f"{f.file}:{f.line}: [{f.rule}] {f.message}" for f in findings[:shown]]
    return "\n".join(lines)


def test_every_transport_is_linted(package):
    drivers = {p.relative_to(package / "src").as_posix() for p in (package / "src").glob("*/*.cpp")}
    assert {"unitree/g1.cpp", "agibot/x2.cpp", "engineai/pm01.cpp", "acme/scara.cpp"} <= drivers, drivers


def test_cpplint_finds_nothing(package):
    findings = run_cpplint(package)
    if findings:
        pytest.fail(_report(findings), pytrace=False)


def test_uncrustify_finds_nothing(package):
    result = run_uncrustify(package)
    if result.findings:
        head = (f"{len(result.diffs)} files differ from the ROS 2 style in {len(result.findings)} places "
                "(ament_uncrustify --reformat fixes them):")
        diffs = [f"--- {name}\n{diff}" for name, diff in list(result.diffs.items())[:3]]
        pytest.fail("\n".join([head, *diffs])[:20000], pytrace=False)
