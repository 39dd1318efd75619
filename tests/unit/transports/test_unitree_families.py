"""`rhi-gen new` on Unitree robots: the message family is known or asked for, never guessed.

Sending one family's LowCmd_ bytes to a robot of the other family commands garbage, so a known
robot brings its family, its real SDK slots (the original H1 leaves slot 9 empty) and the gains of
the SDK's own examples, and an unknown one is refused until `--transport-option family=...` names it.
The robots' URDFs are built here from the SDK orders, shuffled so that a URDF-order map would differ.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest
import yaml

from rhi_gen.transports.unitree_dds.known_robots import H1_ORDER, QUADRUPED_ORDER, WHEELED_ORDER
from tests.support.cli import new_rejected, run_cli

PKG = "generated/robot_hardware_interface"


def write_urdf(path: Path, joints: list[str], wheels: tuple[str, ...] = ()) -> Path:
    links = "".join(f'<link name="l{i}"/>' for i in range(len(joints) + 1))
    body = "".join(
        f'<joint name="{j}" type="{"continuous" if j in wheels else "revolute"}"><parent link="l0"/>'
        f'<child link="l{i + 1}"/><axis xyz="0 0 1"/>'
        f'<limit lower="-1" upper="1" effort="10" velocity="5"/></joint>' for i, j in enumerate(joints))
    path.write_text(f'<?xml version="1.0"?>\n<robot name="{path.stem}">{links}{body}</robot>\n')
    return path


def shuffled(names: tuple[str, ...]) -> list[str]:
    out = [n for n in names if n]
    random.Random(7).shuffle(out)
    return out


def new_ok(root: Path, robot: str, urdf: Path, *extra: str) -> dict:
    result = run_cli("new", "--vendor", "unitree", "--robot", robot, "--urdf", urdf, *extra, "--project", root)
    assert result.code == 0, result.err
    return yaml.safe_load((root / f"robots/unitree/{robot}.yaml").read_text())


def test_h1_gets_the_go_family_its_real_slots_and_its_example_gains(tmp_path):
    root = tmp_path / "proj"
    root.mkdir()
    data = new_ok(root, "h1", write_urdf(tmp_path / "h1.urdf", shuffled(H1_ORDER)))
    options = data["transport_options"]
    assert options["family"] == "go" and options["sdk_slots"] == 20
    assert options["motor_modes"] == [10] * 10 + [1] * 10  # strong motors first (humanoid.hpp)
    assert data["motor_count"] == 20
    assert data["joint_map"] == {name: slot for slot, name in enumerate(H1_ORDER) if name}
    assert 9 not in data["joint_map"].values()  # slot 9 drives no joint on the H1
    gains = data["default_gains"]
    assert gains["right_knee_joint"] == {"stiffness": 200.0, "damping": 5.0}
    assert gains["left_elbow_joint"] == {"stiffness": 60.0, "damping": 1.5}
    assert run_cli("check", "--project", root).code == 0


def test_go2w_wheels_are_velocity_commanded_and_damped_only(tmp_path):
    root = tmp_path / "proj"
    root.mkdir()
    wheels = tuple(n for n in WHEELED_ORDER if n.endswith("_foot_joint"))
    urdf_order = shuffled(WHEELED_ORDER)
    data = new_ok(root, "go2w", write_urdf(tmp_path / "go2w.urdf", urdf_order, wheels))
    assert data["transport_options"]["family"] == "go" and data["motor_count"] == 16
    assert all(data["default_gains"][w] == {"stiffness": 0.0, "damping": 5.0} for w in wheels)
    controllers = yaml.safe_load((root / PKG / "config/go2w_controllers.yaml").read_text())
    # controllers list joints in URDF order
    assert controllers["forward_velocity_controller"]["ros__parameters"]["joints"] == \
        [n for n in urdf_order if n in wheels]
    assert controllers["forward_position_controller"]["ros__parameters"]["joints"] == \
        [n for n in urdf_order if n in QUADRUPED_ORDER]


def test_an_unknown_unitree_robot_is_asked_for_its_family(tmp_path):
    urdf = write_urdf(tmp_path / "h2.urdf", [f"j{i}" for i in range(6)])
    message = new_rejected(tmp_path / "proj", "--vendor", "unitree", "--robot", "h2", "--urdf", urdf,
                           file="--transport-option", words=("unitree/h2", "family=hg", "family=go"))
    assert "G1" in message and "Go2" in message


@pytest.mark.parametrize(("family", "slots"), [("hg", 35), ("go", 20)])
def test_a_named_family_is_written_and_bounds_the_motor_count(tmp_path, family, slots):
    root = tmp_path / "proj"
    root.mkdir()
    data = new_ok(root, "h2", write_urdf(tmp_path / "h2.urdf", [f"j{i}" for i in range(6)]),
                  "--transport-option", f"family={family}")
    assert data["transport_options"]["family"] == family and data["transport_options"]["sdk_slots"] == slots
    assert data["default_gains"] == {}  # none known: the YAML says so instead of inventing gains
    assert "None here: rhi-gen knows no gains for unitree/h2" in (root / "robots/unitree/h2.yaml").read_text()
    too_many = write_urdf(tmp_path / "big.urdf", [f"j{i}" for i in range(slots + 1)])
    new_rejected(root, "--vendor", "unitree", "--robot", "big", "--urdf", too_many,
                 "--transport-option", f"family={family}", file=str(too_many),
                 words=(f"{slots + 1} actuated joints", f"unitree {family} LowCmd_ has {slots} motor slots"))


@pytest.mark.parametrize(("option", "words"), [
    ("family=gx", ("unknown unitree message family 'gx'", "family=hg or family=go")),
    ("domain_id=abc", ("domain_id=abc", "whole number")),
    ("colour=1", ("unitree_dds has no option 'colour'", "lowcmd_topic")),
    ("family", ("expected NAME=VALUE",)),
])
def test_a_bad_transport_option_is_named_as_the_option(tmp_path, option, words):
    urdf = write_urdf(tmp_path / "h2.urdf", [f"j{i}" for i in range(6)])
    extra = () if option.startswith("family") else ("--transport-option", "family=go")
    new_rejected(tmp_path / "proj", "--vendor", "unitree", "--robot", "h2", "--urdf", urdf, *extra,
                 "--transport-option", option, file="--transport-option", words=words)
