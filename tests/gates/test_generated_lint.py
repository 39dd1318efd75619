"""A freshly generated package passes the ROS 2 linters `colcon test` runs (ament_lint_auto):
zero ament_cpplint and zero ament_uncrustify findings (ROS 2 default configuration, tests/support/ament_lint.py).

The package holds the reference robots of robots/ plus the harness's test robots (generic_topics
tests/cpp/harness/robots/acme/scara, unitree go family robots/unitree/go2w, custom odri/solo12 with
its regions as generated), so every transport's templates, both unitree message families included,
are linted; the custom robot is linted again with the toy-bus regions of docs/transports.md's worked example
filled in. To see and fix the findings by hand: tests/support/ament_lint.py COMMAND_LINE, or
`.venv/bin/python -m tests.support.ament_lint DIR`.
"""
from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from rhi_gen.cli import main
from tests.support.ament_lint import Finding, run_cpplint, run_uncrustify
from tests.support.cpp_build import PACKAGE, fill_custom_regions, load_models, make_test_project


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
    assert {"unitree/g1.cpp", "unitree/go2w.cpp", "agibot/x2.cpp", "engineai/pm01.cpp", "acme/scara.cpp",
            "odri/solo12.cpp"} <= drivers, \
        drivers


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


@pytest.fixture(scope="module")
def filled_custom_package(tmp_path_factory) -> Path:
    """The custom robot with the toy bus filled into its regions (docs/transports.md's worked example)."""
    project = make_test_project(tmp_path_factory.mktemp("lint_custom") / "project", only=["odri/solo12"])
    assert main(["generate", "--project", str(project)]) == 0
    package = project / "generated" / PACKAGE
    assert fill_custom_regions(load_models(project), package)
    return package


def test_filled_custom_regions_pass_both_linters(filled_custom_package):
    findings = run_cpplint(filled_custom_package)
    result = run_uncrustify(filled_custom_package)
    problems = findings + result.findings
    if problems:
        pytest.fail(_report(problems) + "\n" + "\n".join(result.diffs.values())[:6000], pytrace=False)


LONG = "a_very_long_joint_name_as_xacro_prefixes_make_them_left_arm_shoulder_pitch_joint_of_the_robot"


@pytest.fixture(scope="module")
def long_names_package(tmp_path_factory) -> Path:
    """A robot whose every name is as long as rhi-gen allows (26-character vendor and robot, joint
    names up to 128 characters): folding must keep each generated line within cpplint's limit."""
    project = tmp_path_factory.mktemp("lint_long") / "project"
    (project / "robots").mkdir(parents=True)
    names = [f"{LONG}_{i}"[:128] for i in range(3)] + ["j" * 128]
    links = "".join(f'  <link name="l{i}"/>\n' for i in range(len(names) + 1))
    joints = "".join(
        f'  <joint name="{n}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        f'<limit lower="-1.2345678901234" upper="1.2345678901234" effort="123.456789" velocity="12.3456789"/>'
        f'</joint>\n' for i, n in enumerate(names))
    urdf = project / "long.urdf"
    urdf.write_text(f'<robot name="long">\n{links}{joints}</robot>\n')
    vendor, robot = "v" * 25 + "x", "r" * 25 + "y"
    assert main(["new", "--project", str(project), "--vendor", vendor, "--robot", robot, "--urdf", str(urdf),
                 "--transport", "generic_topics"]) == 0
    return project / "generated" / PACKAGE


def test_long_names_lint_clean(long_names_package):
    findings = run_cpplint(long_names_package)
    if findings:
        pytest.fail(_report(findings), pytrace=False)
    result = run_uncrustify(long_names_package)
    if result.findings:
        pytest.fail("\n".join(f"--- {name}\n{diff}" for name, diff in result.diffs.items())[:20000], pytrace=False)


def test_colcon_test_runs_these_linters(package):
    """package.xml declares the linters as test dependencies and CMakeLists.txt hands them to
    ament_lint_auto inside BUILD_TESTING, before ament_package() (whose hook registers the tests)."""
    from lxml import etree

    test_depends = [e.text for e in etree.parse(str(package / "package.xml")).getroot().iter("test_depend")]
    assert {"ament_lint_auto", "ament_cmake_cpplint", "ament_cmake_uncrustify"} <= set(test_depends)
    cmake = (package / "CMakeLists.txt").read_text()
    testing = cmake.index("if(BUILD_TESTING)")
    call = cmake.index("ament_lint_auto_find_test_dependencies()")
    assert testing < cmake.index("find_package(ament_lint_auto QUIET)") < call < cmake.index("ament_package()")
