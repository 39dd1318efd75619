"""The transport registry: each transport's module is its one home, and everything reads it."""
from __future__ import annotations

import dataclasses
import functools

import pytest
import yaml

from rhi_gen import transports
from rhi_gen.errors import ConfigError
from rhi_gen.model import TransportOptions
from rhi_gen.typed_yaml.validator import Validator
from rhi_gen.typed_yaml.yaml_source import parse_yaml_text
from tests.support.repo import REPO

SOURCES = REPO / "rhi_gen"  # render/environment.py SOURCE_ROOT


def test_registry_names_match_the_modules():
    assert transports.NAMES == ("unitree_dds", "agibot_topics", "engineai_topics", "generic_topics", "custom")
    assert all(transports.get(name).name == name for name in transports.NAMES)
    assert transports.DEFAULT in transports.NAMES


def test_unknown_transport_is_one_line_with_a_hint():
    with pytest.raises(Exception, match=r"unknown transport 'unitree_ds'.*did you mean 'unitree_dds'"):
        transports.get("unitree_ds", key="--transport")


@pytest.mark.parametrize("name", transports.NAMES)
def test_every_transport_has_its_templates(name):
    t = transports.get(name)
    assert (SOURCES / t.glue_template).is_file(), t.glue_template
    for template, out in t.shared_files:
        assert (SOURCES / template).is_file() and not out.startswith("/"), template


# Options that apply to one message family only: a robot of the other family is not offered them.
# Options `new` leaves out: the other family's, the arm SDK's (authority upper_body only) and the hands' (hands:
# dex3 only).
FAMILY_SPECIFIC = {"unitree_dds": {"mode_pr", "motor_modes", "arm_sdk_topic", "arm_sdk_weight_slot", "arm_sdk_ramp_s",
                                   "hand_command_topic", "hand_state_topic"},
                    # take_control's timeout: its default unless asked for
                    "agibot_topics": {"take_control_timeout_s", "hand_command_topic", "hand_state_topic"}}
# Options `new` deliberately writes with another value than the default: a new X2 takes control the vendor's way
# (take_control: true), while a YAML without the key keeps the driver it had.
SUGGESTED_OVER_DEFAULT = {"agibot_topics": {"take_control": True}}
SUGGESTION_CASES = [(name, known) for name in transports.NAMES
                    for known in (None, *transports.get(name).known_robots)]


@pytest.mark.parametrize(("name", "known"), SUGGESTION_CASES,
                         ids=[f"{n}-{k.robot if k else 'unknown'}" for n, k in SUGGESTION_CASES])
def test_suggested_options_are_the_accepted_keys_and_read_back_as_the_defaults(name, known):
    """What `rhi-gen new` writes under transport_options is valid for, and complete over, the transport."""
    t = transports.get(name)
    order = [n for n in known.joint_order if n] if known else [f"j{i}" for i in range(6)]
    text = "transport_options:\n" + "\n".join(t.suggest_options(order, known)) + "\n"
    options = yaml.safe_load(text)["transport_options"]
    assert set(options) <= set(t.option_keys)
    assert set(t.option_keys) - set(options) <= FAMILY_SPECIFIC.get(name, set()) | (
        {"family", "sdk_slots"} if name == "unitree_dds" and known is None else set())
    data, lines = parse_yaml_text(text, "x.yaml")
    v = Validator("x.yaml", lines)
    read = t.read_options(v, v.mapping(data["transport_options"], "transport_options", t.option_keys), len(order))
    assert isinstance(read, TransportOptions)
    given = v.mapping(data["transport_options"], "transport_options", t.option_keys)
    vendor, robot = (known.vendor, known.robot) if known else ("acme", "arm")
    resolve = functools.partial(t.resolve_options, v, vendor=vendor, robot=robot, motor_count=len(order))
    if name == "unitree_dds" and known is None:  # no family is suggested: validation asks for it
        with pytest.raises(ConfigError, match="family"):
            resolve(read)
        return
    got = resolve(read)
    try:  # the defaults, for the same family; they may not fit this motor count (AgiBot's groups)
        expected = resolve(t.read_options(v, {k: given[k] for k in ("family",) if k in given}, len(order)))
    except ConfigError:
        expected = None
    if expected is not None:
        expected = dataclasses.replace(expected, **SUGGESTED_OVER_DEFAULT.get(name, {}))
    assert expected is None or got == expected, "the suggested options should spell out the defaults"
    labels = t.joint_labels(order, known)
    assert labels == [] or len(labels) == len(order)


def test_vendor_defaults_and_known_robots():
    assert transports.for_vendor("unitree").name == "unitree_dds"
    assert transports.for_vendor("acme").name == transports.DEFAULT
    g1 = transports.known_robot("unitree", "g1")
    assert g1 is not None and g1.transport == "unitree_dds" and len(g1.joint_order) == 29
    h1 = transports.known_robot("unitree", "h1")
    assert h1 is not None and h1.family == "go" and len(h1.joint_order) == 20 and h1.joint_order[9] == ""
    assert transports.known_robot("unitree", "h2") is None
    order = transports.suggest_order(["extra", "left_knee_joint", "left_hip_pitch_joint"], g1)
    assert order == ["left_hip_pitch_joint", "left_knee_joint", "extra"]

