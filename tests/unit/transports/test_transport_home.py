"""A transport's folder is its one home: adding one touches only its folder and one registry line.

The test builds a toy transport in a temporary copy of the rhi_gen package (transports/toy_bus/:
``__init__.py``, a header, ``glue.j2``; plus its line in transports/__init__.py), generates a project
whose robot uses it with that copy, and checks that the package carries the transport's header and
declares exactly its dependencies, while nothing else in the copy changed.
"""
from __future__ import annotations

import filecmp
import os
import shutil
import subprocess
import sys
from pathlib import Path

from tests.support.repo import REPO

SOURCES = REPO / "rhi_gen"
FIXTURES = REPO / "tests" / "fixtures"
REGISTRY = "transports/__init__.py"
REGISTRY_LINE = "from .toy_bus import TRANSPORT as TOY_BUS  # noqa: F401\n"

TOY_INIT = '''"""toy_bus: a test transport (tests/unit/transports/test_transport_home.py)."""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ...model import TransportOptions
from ...typed_yaml.validator import Validator
from ..base import PLAIN_CMAKE, ROSDISTRO, Dependency, KnownRobot, Transport, transport_header

NAME = "toy_bus"


@dataclass(frozen=True)
class ToyBusOptions(TransportOptions):
    bus: str = "can0"


class ToyBus(Transport):
    name = NAME
    summary = "a toy bus"
    option_keys = ("bus",)
    default_float_type = "double"
    dependencies = (
        Dependency("toy_msgs", ROSDISTRO),
        Dependency("toy_sdk", PLAIN_CMAKE,
                   cmake_find="find_package(toy_sdk QUIET)\\nset(RHI_TOY_SDK_TARGET toy_sdk)\\n",
                   cmake_target="RHI_TOY_SDK_TARGET", package_xml_note=("toy_sdk has no package.xml.",)),
    )
    shared_files = (transport_header(NAME, "toy_bus.hpp"),)
    vendors = ("toyco",)

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> ToyBusOptions:
        return ToyBusOptions(bus=v.optional(options, "transport_options", "bus", v.topic, "can0"),
                             sdk_slots=motor_count)

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        return ["  bus: can0"]


TRANSPORT = ToyBus()
'''
TOY_HEADER = """// The toy bus (tests/unit/transports/test_transport_home.py).

#pragma once
namespace robot_hardware_interface {}  // TOY_BUS_HEADER
"""
# The glue interface of today's robot templates (templates/robot/driver.cpp.j2 imports it by name).
TOY_GLUE = """{% set headers = ['robot_hardware_interface/transport/toy_bus.hpp'] %}
{% macro transport_type(N, T) %}robot_hardware_interface::ToyBusTransport<{{ N }}, {{ T }}>{% endmacro %}
{% macro options() %}
constexpr const char * kTransport = {{ robot.transport_options.bus | cpp_string }};
{%- endmacro %}
"""


def _copy_with_toy(root: Path) -> Path:
    copy = root / "rhi_gen"
    shutil.copytree(SOURCES, copy, ignore=shutil.ignore_patterns("__pycache__"))
    folder = copy / "transports" / "toy_bus"
    folder.mkdir()
    (folder / "__init__.py").write_text(TOY_INIT)
    (folder / "toy_bus.hpp").write_text(TOY_HEADER)
    (folder / "glue.j2").write_text(TOY_GLUE)
    registry = copy / REGISTRY
    text = registry.read_text()
    assert "# isort: on\n" in text
    registry.write_text(text.replace("# isort: on\n", REGISTRY_LINE + "# isort: on\n", 1))
    return copy


def _changed(a: Path, b: Path, rel: str = "") -> list[str]:
    """Paths (relative) that differ between two trees, or exist in only one."""
    cmp = filecmp.dircmp(a, b, ignore=["__pycache__"])
    out = [f"{rel}{n}" for n in cmp.left_only + cmp.right_only + cmp.diff_files + cmp.funny_files]
    for sub in cmp.common_dirs:
        out += _changed(a / sub, b / sub, f"{rel}{sub}/")
    return sorted(out)


def _rhi_gen(copy_root: Path, project: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(copy_root)}
    code = ("import sys, rhi_gen; assert rhi_gen.__file__.startswith(sys.argv[1]); sys.argv[1:2] = []; "
            "sys.argv[0] = 'rhi-gen'; from rhi_gen.cli import entry; entry()")
    return subprocess.run([sys.executable, "-c", code, str(copy_root), *args], cwd=project, env=env,
                          capture_output=True, text=True, timeout=300)


def test_a_new_transport_is_its_folder_and_one_registry_line(tmp_path):
    copy = _copy_with_toy(tmp_path / "src")
    assert _changed(SOURCES, copy) == [REGISTRY, "transports/toy_bus"]
    added = set(copy.joinpath(REGISTRY).read_text().splitlines(keepends=True)) - \
        set(SOURCES.joinpath(REGISTRY).read_text().splitlines(keepends=True))
    assert added == {REGISTRY_LINE}

    project = tmp_path / "project"
    (project / "robots").mkdir(parents=True)
    done = _rhi_gen(tmp_path / "src", project, "new", "--vendor", "toyco", "--robot", "arm",
                    "--urdf", str(FIXTURES / "urdf" / "simple_arm.urdf"))
    assert done.returncode == 0, done.stderr
    assert "transport: toy_bus" in (project / "robots/toyco/arm.yaml").read_text()  # for_vendor() found it

    package = project / "generated" / "robot_hardware_interface"
    header = package / "include/robot_hardware_interface/transport/toy_bus.hpp"
    assert "TOY_BUS_HEADER" in header.read_text()
    assert sorted(p.name for p in header.parent.iterdir()) == ["toy_bus.hpp"]  # no other transport's files
    assert 'kTransport = "can0"' in (package / "src/toyco/arm.cpp").read_text()

    cmake = (package / "CMakeLists.txt").read_text()
    xml = (package / "package.xml").read_text()
    assert "find_package(toy_msgs QUIET)" in cmake and "find_package(toy_sdk QUIET)" in cmake
    assert "RHI_MISSING toy_msgs toy_sdk)" in cmake
    assert "${toy_msgs_TARGETS}\n    ${RHI_TOY_SDK_TARGET}\n" in cmake
    assert 'if(dep STREQUAL "toy_sdk")\n      if(NOT RHI_TOY_SDK_TARGET)' in cmake
    assert "<depend>toy_msgs</depend>" in xml and "<!-- toy_sdk has no package.xml. -->" in xml
    assert "<depend>toy_sdk</depend>" not in xml
    for other in ("unitree_sdk2", "aimdk_msgs", "interface_protocol", "sensor_msgs", "geometry_msgs"):
        assert other not in cmake and other not in xml, other
