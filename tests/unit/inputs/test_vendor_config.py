"""Vendor YAML validation: every bad input is one line naming file, line, key and fix."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.transports.agibot_topics import AgibotTopicsOptions
from rhi_gen.transports.generic_topics import GenericTopicsOptions
from tests.support.repo import REPO
from tests.support.vendor_yaml import ARM_YAML

BASE = ARM_YAML  # the next line is line 10


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "arm.yaml"
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def error_of(tmp_path: Path, text: str) -> ConfigError:
    with pytest.raises(ConfigError) as info:
        load_config(write(tmp_path, text))
    message = str(info.value)
    assert "\n" not in message
    assert "arm.yaml" in message
    return info.value


def test_base_config_loads_with_transport_defaults(tmp_path):
    cfg = load_config(write(tmp_path, BASE))
    assert cfg.vendor == "acme" and cfg.robot == "arm" and cfg.motor_count == 3
    assert cfg.joint_map == (("j1", 0), ("j2", 1), ("j3", 2))
    assert cfg.float_type == "double"
    assert cfg.parameters.command_writer_period_us == 2000 and cfg.parameters.state_decimation == 1
    assert cfg.parameters.enable_monitor is False and cfg.parameters.network_interface == "lo"
    assert cfg.parameters.state_timeout_ms == 100 and cfg.parameters.fault_timeout_ms == 1000
    options = cfg.transport_options
    assert isinstance(options, GenericTopicsOptions)
    assert options.state_topic == "/hardware/joint_states"
    assert options.qos.reliability == "best_effort"
    assert cfg.urdf == str(tmp_path / "arm.urdf")


@pytest.mark.parametrize("robot", ["unitree/g1", "agibot/x2", "engineai/pm01"])
def test_reference_yamls_load(robot):
    cfg = load_config(REPO / "robots" / f"{robot}.yaml")
    assert len(cfg.joint_map) == cfg.motor_count
    assert sorted(i for _, i in cfg.joint_map) == list(range(cfg.motor_count))


def test_agibot_groups_get_offsets():
    cfg = load_config(REPO / "robots/agibot/x2.yaml")
    assert isinstance(cfg.transport_options, AgibotTopicsOptions)
    assert [(g.name, g.size, g.offset) for g in cfg.transport_options.groups] == [
        ("leg", 12, 0), ("waist", 3, 12), ("arm", 14, 15), ("head", 2, 29)]


@pytest.mark.parametrize("text, line, key, words", [
    (BASE.replace("transport: generic_topics", "transport: generic_topic"), 4, "transport",
     "did you mean 'generic_topics'"),
    (BASE + "joint_mapp: {}\n", 10, "joint_mapp", "did you mean 'joint_map'"),
    (BASE.replace("  j3: 2", "  j3: 1"), 9, "joint_map.j3", "already used by 'j2'"),
    (BASE.replace("  j3: 2", "  j3: 3"), 9, "joint_map.j3", "out of range 0..2"),
    (BASE.replace("  j3: 2", "  j3: -1"), 9, "joint_map.j3", "out of range"),
    (BASE.replace("  j3: 2", "  j3: two"), 9, "joint_map.j3", "whole number"),
    (BASE.replace("  j3: 2", "  j3: true"), 9, "joint_map.j3", "whole number"),
    (BASE.replace("  j3: 2", "  j2: 2"), 9, "joint_map.j2", "duplicate key"),
    (BASE + "float_type: half\n", 10, "float_type", "float, double"),
    (BASE.replace("motor_count: 3", "motor_count: many"), 5, "motor_count", "whole number"),
    (BASE.replace("motor_count: 3", "motor_count: 0"), 5, "motor_count", "out of range"),
    (BASE.replace("robot: arm", "robot: ../x"), 2, "robot", "lowercase letters"),
    (BASE.replace("robot: arm", "robot: /abs"), 2, "robot", "lowercase letters"),
    (BASE.replace("vendor: acme", "vendor: namespace"), 1, "vendor", "C++ keyword"),
    (BASE.replace("vendor: acme", "vendor: std"), 1, "vendor", "clash"),
    (BASE.replace("robot: arm", "robot: Arm"), 2, "robot", "lowercase"),
    (BASE + "parameters:\n  state_decimation: 0\n", 11, "parameters.state_decimation", "out of range"),
    (BASE + "parameters:\n  command_writer_period_us: fast\n", 11, "parameters.command_writer_period_us",
     "whole number"),
    (BASE + "parameters:\n  fault_timeout_ms: soon\n", 11, "parameters.fault_timeout_ms", "whole number"),
    (BASE + "parameters:\n  fault_timeout_ms: 2.5\n", 11, "parameters.fault_timeout_ms", "whole number"),
    (BASE + "parameters:\n  state_timeout_ms: 200\n  fault_timeout_ms: 200\n", 12, "parameters.fault_timeout_ms",
     "must be greater than state_timeout_ms (200) -> set fault_timeout_ms above 200"),
    (BASE + "parameters:\n  state_timeout_ms: 1500\n", 11, "parameters.state_timeout_ms",
     "must be less than fault_timeout_ms (1000, the default) -> set parameters.fault_timeout_ms above 1500"),
    (BASE + "parameters:\n  enable_monitor: maybe\n", 11, "parameters.enable_monitor", "true or false"),
    (BASE + "parameters:\n  first_state_timeout_ms: 1\n", 11, "parameters.first_state_timeout_ms", "out of range"),
    (BASE + "parameters:\n  first_state_timeout_ms: later\n", 11, "parameters.first_state_timeout_ms",
     "whole number"),
    (BASE + "parameters:\n  is_async: sometimes\n", 11, "parameters.is_async", "true or false"),
    (BASE + "parameters:\n  rw_rate: -5\n", 11, "parameters.rw_rate", "out of range"),
    (BASE + "parameters:\n  rw_rate: 100001\n", 11, "parameters.rw_rate", "out of range"),
    (BASE + "parameters:\n  diagnostics_period_ms: 60001\n", 11, "parameters.diagnostics_period_ms", "out of range"),
    (BASE + "parameters:\n  motor_temperature_warn_c: 90\n", 11, "parameters.motor_temperature_warn_c",
     ("must be less than motor_temperature_error_c (85, the default) -> set parameters.motor_temperature_error_c "
      "above 90")),
    (BASE + "parameters:\n  motor_temperature_warn_c: 60\n  motor_temperature_error_c: 60\n", 12,
     "parameters.motor_temperature_error_c", "must be greater than motor_temperature_warn_c (60)"),
    (BASE + "parameters:\n  motor_error_fault_mask: 4\n", 11, "parameters.motor_error_fault_mask",
     "carries no motor error codes"),
    (BASE + "parameters:\n  motor_error_fault_mask: -1\n", 11, "parameters.motor_error_fault_mask", "out of range"),
    (BASE + "parameters:\n  network_iface: eth0\n", 11, "parameters.network_iface", "did you mean 'network_interface'"),
    (BASE + "transport_options:\n  lowcmd_topic: rt/lowcmd\n", 11, "transport_options.lowcmd_topic", "unknown key"),
    (BASE + "transport_options:\n  state_topic: 'bad topic'\n", 11, "transport_options.state_topic",
     "not a valid ROS topic"),
    (BASE + "unmapped_joints: [j1]\n", 10, "unmapped_joints[0]", "also in joint_map"),
    (BASE + "imu: {enabled: yes please}\n", 10, "imu.enabled", "true or false"),
    # an integer too large for a float is one line too, not an OverflowError
    (BASE + "initial_positions:\n  j1: 1" + "0" * 400 + "\n", 11, "initial_positions.j1", "finite number"),
    (BASE + "default_gains:\n  j1: {stiffness: 1" + "0" * 400 + "}\n", 11, "default_gains.j1.stiffness",
     "number from 0 to 1e+06"),
])
def test_bad_values_name_line_key_and_fix(tmp_path, text, line, key, words):
    err = error_of(tmp_path, text)
    assert err.line == line, str(err)
    assert err.key == key, str(err)
    assert words in str(err)


def test_diagnostics_parameters_are_read_with_their_defaults(tmp_path):
    defaults = load_config(write(tmp_path, BASE)).parameters
    assert (defaults.diagnostics_period_ms, defaults.motor_temperature_warn_c,
            defaults.motor_temperature_error_c) == (1000, 70, 85)
    given = load_config(write(tmp_path, BASE + "parameters:\n  diagnostics_period_ms: 0\n"
                              "  motor_temperature_warn_c: 50\n  motor_temperature_error_c: 65\n")).parameters
    assert (given.diagnostics_period_ms, given.motor_temperature_warn_c, given.motor_temperature_error_c) == (0, 50, 65)


def test_fault_timeout_is_read_and_follows_the_state_timeout(tmp_path):
    cfg = load_config(write(tmp_path, BASE + "parameters:\n  state_timeout_ms: 50\n  fault_timeout_ms: 400\n"))
    assert (cfg.parameters.state_timeout_ms, cfg.parameters.fault_timeout_ms) == (50, 400)
    just_above = load_config(write(tmp_path, BASE + "parameters:\n  state_timeout_ms: 999\n"))
    assert just_above.parameters.fault_timeout_ms == 1000


def test_start_up_and_async_parameters_are_read_with_their_defaults(tmp_path):
    defaults = load_config(write(tmp_path, BASE)).parameters
    assert (defaults.first_state_timeout_ms, defaults.is_async, defaults.rw_rate) == (10000, False, 0)
    given = load_config(write(tmp_path, BASE + "parameters:\n  first_state_timeout_ms: 30000\n"
                              "  is_async: true\n  rw_rate: 250\n")).parameters
    assert (given.first_state_timeout_ms, given.is_async, given.rw_rate) == (30000, True, 250)
    # shorter than fault_timeout_ms is no error: the driver waits at least fault_timeout_ms for a first state
    short = load_config(write(tmp_path, BASE + "parameters:\n  first_state_timeout_ms: 500\n")).parameters
    assert short.first_state_timeout_ms == 500


def test_unitree_motor_count_above_slots(tmp_path):
    text = (BASE.replace("transport: generic_topics", "transport: unitree_dds")
            .replace("motor_count: 3", "motor_count: 36") + "transport_options: {family: hg}\n")
    err = error_of(tmp_path, text)
    assert err.key == "motor_count" and "35 motor slots" in str(err)


def test_unknown_unitree_robot_must_name_its_family(tmp_path):
    text = BASE.replace("transport: generic_topics", "transport: unitree_dds")
    err = error_of(tmp_path, text)
    assert err.key == "transport_options" and "family: hg" in str(err) and "go (" in str(err)
    go = text + "transport_options: {family: go}\n"
    assert "20 motor slots" in str(error_of(tmp_path, go.replace("motor_count: 3", "motor_count: 21")))


def test_agibot_groups_must_sum_to_motor_count(tmp_path):
    text = BASE.replace("transport: generic_topics", "transport: agibot_topics") + (
        "transport_options:\n  groups:\n    - {name: leg, size: 2}\n")
    err = error_of(tmp_path, text)
    assert err.key == "motor_count" and "groups hold 2 slots" in str(err)


@pytest.mark.parametrize("text, words", [
    ("", "empty"),
    ("   \n# only a comment\n", "empty"),
    ("- a\n- b\n", "not a mapping"),
    ("just text\n", "not a mapping"),
    ("a: [unclosed\n", "invalid YAML"),
    ("a: &x [*x]\n", "refers to itself"),
    ("vendor: !!python/object:os.system x\n", "cannot read this value"),
    ("a: 1\n---\nb: 2\n", "several YAML documents"),
])
def test_malformed_files(tmp_path, text, words):
    err = error_of(tmp_path, text)
    assert words in str(err)


def test_missing_required_key(tmp_path):
    err = error_of(tmp_path, BASE.replace("motor_count: 3\n", ""))
    assert err.key == "motor_count" and "missing" in str(err)


def test_missing_file_and_directory(tmp_path):
    with pytest.raises(ConfigError, match="not found"):
        load_config(tmp_path / "nope.yaml")
    with pytest.raises(ConfigError, match="directory"):
        load_config(tmp_path)


def test_non_utf8(tmp_path):
    path = tmp_path / "arm.yaml"
    path.write_bytes(b"vendor: \xff\xfe\n")
    with pytest.raises(ConfigError, match="UTF-8"):
        load_config(path)


def test_yaml_booleans_as_joint_names_stay_names(tmp_path):
    text = BASE.replace("  j1: 0", "  on: 0").replace("  j2: 1", "  no: 1")
    cfg = load_config(write(tmp_path, text))
    assert [n for n, _ in cfg.joint_map] == ["on", "no", "j3"]


@pytest.mark.parametrize("robot", ["unitree/g1", "agibot/x2", "engineai/pm01"])
def test_motor_error_fault_mask_is_read_where_error_codes_travel(tmp_path, robot):
    """Hex as in a vendor's error table, 0 (codes never fault) by default, at most 32 bits. EngineAI: only the
    native SDK's interface_protocol carries error codes, which the driver finds when it is compiled (it refuses
    a mask in on_init without them), so the YAML takes it."""
    source = (REPO / "robots" / f"{robot}.yaml").read_text(encoding="utf-8")
    assert load_config(REPO / "robots" / f"{robot}.yaml").parameters.motor_error_fault_mask == 0
    with_block = source if "\nparameters:\n" in source else source.replace("\njoint_map:", "\nparameters:\njoint_map:")
    text = with_block.replace("\nparameters:\n", "\nparameters:\n  motor_error_fault_mask: 0x0000000C\n")
    (tmp_path / "robot.yaml").write_text(text, encoding="utf-8")
    assert load_config(tmp_path / "robot.yaml").parameters.motor_error_fault_mask == 12
    (tmp_path / "robot.yaml").write_text(text.replace("0x0000000C", "0x100000000"), encoding="utf-8")
    with pytest.raises(ConfigError, match=r"out of range 0\.\.4294967295"):
        load_config(tmp_path / "robot.yaml")
