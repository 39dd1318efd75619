"""Two robots of one project must not generate the same thing.

`--robot h1_2` and `--robot h12` of one vendor both become class H12HardwareInterface; two vendors'
`arm` both write description/arm.ros2_control.xacro. `new` refuses such a robot (exit 2, one line
naming the other robot's YAML and the fix, nothing written) instead of accepting it and leaving a
project every later command rejects. A project that already holds a clash (YAMLs written by hand)
is rejected by generate/check/diff in the words of the YAML. Both use one check, pipeline.load.find_clash.
"""
from __future__ import annotations

import dataclasses
import shutil
from pathlib import Path

import pytest

from rhi_gen.pipeline.load import clash_error, find_clash, load_robots
from rhi_gen.project import Project
from tests.support.cli import assert_rejected, new_rejected, run_cli, snapshot
from tests.support.repo import URDF_FIXTURES as FIX

ARM = FIX / "simple_arm.urdf"
PLUGINS = "generated/robot_hardware_interface/robot_hardware_interface.xml"


def new(root: Path, vendor: str, robot: str, *extra: str) -> None:
    result = run_cli("new", "--vendor", vendor, "--robot", robot, "--urdf", ARM, *extra, "--project", root)
    assert result.code == 0, result.err


@pytest.fixture
def h1_2(tmp_path: Path) -> Path:
    root = tmp_path / "proj"
    root.mkdir()
    new(root, "unitree", "h1_2")
    return root


def test_new_refuses_a_plugin_class_clash(h1_2):
    message = new_rejected(h1_2, "--vendor", "unitree", "--robot", "h12", "--urdf", ARM, file="--robot",
                           words=(("robot 'h12' would generate plugin class "
                                   "robot_hardware_interface::unitree::H12HardwareInterface"),
                                  "which robots/unitree/h1_2.yaml already generates",
                                  "choose another --robot name", "--class-prefix NAME"))
    assert "class_prefix:" in message
    # the project is as usable as before
    assert run_cli("check", "--project", h1_2).code == 0
    assert run_cli("generate", "--project", h1_2).code == 0


def test_the_class_prefix_fix_works(h1_2):
    new(h1_2, "unitree", "h12", "--class-prefix", "H12V2")
    assert "class_prefix: H12V2\n" in (h1_2 / "robots/unitree/h12.yaml").read_text()
    plugins = (h1_2 / PLUGINS).read_text()
    assert 'type="robot_hardware_interface::unitree::H12HardwareInterface"' in plugins
    assert 'type="robot_hardware_interface::unitree::H12V2HardwareInterface"' in plugins
    assert run_cli("check", "--project", h1_2).code == 0
    assert run_cli("generate", "--project", h1_2).code == 0


def test_the_other_robot_name_fix_works(h1_2):
    new(h1_2, "unitree", "h1_2b", "--transport-option", "family=hg")
    assert run_cli("check", "--project", h1_2).code == 0


def test_a_class_prefix_that_clashes_names_the_option(h1_2):
    new_rejected(h1_2, "--vendor", "unitree", "--robot", "h2", "--urdf", ARM, "--class-prefix", "H12",
                 "--transport-option", "family=hg",
                 file="--class-prefix",
                 words=(("plugin class robot_hardware_interface::unitree::H12HardwareInterface is already "
                         "generated for robots/unitree/h1_2.yaml"), "choose another --class-prefix"))


@pytest.mark.parametrize("value", ["h12", "H 12", "1H", "Class", "H12_b"])
def test_a_class_prefix_that_is_no_identifier(tmp_path, value):
    new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "arm", "--urdf", ARM, "--class-prefix", value,
                 file="--class-prefix", words=("must be a C++ identifier",))


def test_new_refuses_a_robot_name_of_another_vendor(h1_2):
    new_rejected(h1_2, "--vendor", "acme", "--robot", "h1_2", "--urdf", ARM, file="--robot",
                 words=("robot name 'h1_2' is already used by robots/unitree/h1_2.yaml", "description/",
                        "choose another --robot name"))


def test_the_same_class_name_in_two_vendors_is_fine(h1_2):
    """Different namespaces, different plugin names: robot_hardware_interface::acme::H12HardwareInterface is
    another class."""
    new(h1_2, "acme", "h12")
    assert run_cli("check", "--project", h1_2).code == 0


def test_new_force_over_the_same_robot_is_no_clash(h1_2):
    new(h1_2, "unitree", "h1_2", "--force")


# ---------------------------------------------------------------- a clash already in the project
def _clashing_yaml(root: Path, vendor: str, robot: str) -> Path:
    """A copy of h1_2's YAML as robots/<vendor>/<robot>.yaml, next to a copy of its URDF."""
    text = (root / "robots/unitree/h1_2.yaml").read_text()
    text = text.replace("vendor: unitree", f"vendor: {vendor}").replace("robot: h1_2", f"robot: {robot}")
    path = root / "robots" / vendor / f"{robot}.yaml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    if vendor != "unitree":
        shutil.copy(root / "robots/unitree/h1_2.urdf", path.parent / "h1_2.urdf")
    return path


@pytest.mark.parametrize("command", ["generate", "check", "diff"])
def test_a_class_clash_in_the_project_is_named_in_yaml_words(h1_2, command):
    _clashing_yaml(h1_2, "unitree", "h12")
    before = snapshot(h1_2)
    # robots/unitree/h12.yaml sorts before h1_2.yaml ('2' < '_'), so h1_2.yaml is the second one
    message = assert_rejected(run_cli(command, "--project", h1_2), file="robots/unitree/h1_2.yaml", line=5,
                              key="robot",
                              words=(("plugin class robot_hardware_interface::unitree::H12HardwareInterface is also "
                                      "generated for robots/unitree/h12.yaml"), "set class_prefix: <Name>"))
    assert "--" not in message.split(" -> ")[1]
    assert snapshot(h1_2) == before


def test_a_robot_name_clash_in_the_project_is_named_in_yaml_words(h1_2):
    _clashing_yaml(h1_2, "zeta", "h1_2")
    assert_rejected(run_cli("generate", "--project", h1_2), file="robots/zeta/h1_2.yaml", line=5, key="robot",
                    words=("robot name 'h1_2' is also used by robots/unitree/h1_2.yaml", "rename one of the two"))


def test_new_in_a_project_that_already_clashes_names_the_yaml(h1_2):
    _clashing_yaml(h1_2, "unitree", "h12")
    new_rejected(h1_2, "--vendor", "acme", "--robot", "other", "--urdf", ARM,
                 file="robots/unitree/h1_2.yaml", line=5, key="robot", words=("plugin class",))


def test_a_robot_file_on_a_shared_file_is_a_clash(h1_2):
    """Unreachable through the name rules (vendor 'common' is refused), so checked on a forged model."""
    (robot,) = load_robots(Project(h1_2))
    forged = dataclasses.replace(robot, model=dataclasses.replace(robot.model, vendor="common", robot="types"))
    clash = find_clash([forged])
    assert clash is not None and clash.kind == "path" and clash.other is None
    assert clash.value == "include/robot_hardware_interface/common/types.hpp"
    error = clash_error(Project(h1_2), clash)
    assert ("would write generated/robot_hardware_interface/include/robot_hardware_interface/common/types.hpp, "
            "which is one of rhi-gen's shared files") in str(error)
