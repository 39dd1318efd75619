"""The transport registry: each transport's module is its one home, and everything reads it."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from rhi_gen import transports
from rhi_gen.inputs.validator import Validator
from rhi_gen.inputs.yaml_source import parse_yaml_text
from rhi_gen.model import TransportOptions

TEMPLATES = Path(__file__).resolve().parents[1] / "rhi_gen" / "templates"


def test_registry_names_match_the_modules():
    assert transports.NAMES == ("unitree_dds", "agibot_topics", "engineai_topics", "generic_topics")
    assert all(transports.get(name).name == name for name in transports.NAMES)
    assert transports.DEFAULT in transports.NAMES


def test_unknown_transport_is_one_line_with_a_hint():
    with pytest.raises(Exception, match=r"unknown transport 'unitree_ds'.*did you mean 'unitree_dds'"):
        transports.get("unitree_ds", key="--transport")


@pytest.mark.parametrize("name", transports.NAMES)
def test_every_transport_has_its_templates(name):
    t = transports.get(name)
    assert (TEMPLATES / t.glue_template).is_file(), t.glue_template
    for template, out in t.shared_files:
        assert (TEMPLATES / template).is_file() and not out.startswith("/"), template


@pytest.mark.parametrize("name", transports.NAMES)
def test_suggested_options_are_exactly_the_accepted_keys_and_read_back(name):
    """What `rhi-gen new` writes under transport_options is valid for, and complete over, the transport."""
    t = transports.get(name)
    known = next(iter(t.known_robots), None)
    order = list(known.joint_order) if known else [f"j{i}" for i in range(6)]
    text = "transport_options:\n" + "\n".join(t.suggest_options(order, known)) + "\n"
    options = yaml.safe_load(text)["transport_options"]
    assert set(options) == set(t.option_keys)
    data, lines = parse_yaml_text(text, "x.yaml")
    v = Validator("x.yaml", lines)
    read = t.read_options(v, v.mapping(data["transport_options"], "transport_options", t.option_keys), len(order))
    assert isinstance(read, TransportOptions)
    defaults = t.read_options(v, {}, len(order))
    assert read == defaults, "the suggested options should spell out the defaults"
    labels = t.joint_labels(order, known)
    assert labels == [] or len(labels) == len(order)


def test_vendor_defaults_and_known_robots():
    assert transports.for_vendor("unitree").name == "unitree_dds"
    assert transports.for_vendor("acme").name == transports.DEFAULT
    g1 = transports.known_robot("unitree", "g1")
    assert g1 is not None and g1.transport == "unitree_dds" and len(g1.joint_order) == 29
    assert transports.known_robot("unitree", "h1") is None
    order = transports.suggest_order(["extra", "left_knee_joint", "left_hip_pitch_joint"], g1)
    assert order == ["left_hip_pitch_joint", "left_knee_joint", "extra"]

