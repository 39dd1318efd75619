"""transport_options.take_control (AgiBot): the driver stops AgiBot's motion control the vendor's way.

The facts (tests/support/aimdk_facts.py): MigrateSystemState("Develop_MC") stops MC, "Ready" gives it back; the
generated driver calls them before its first and after its last command. Here: what the YAML may say and what
the generated C++ gets; the calls themselves are the C++ harness's section take_control.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rhi_gen.errors import ConfigError
from rhi_gen.inputs.vendor_config import load_config
from rhi_gen.transports.agibot_topics import TAKE_CONTROL_TIMEOUT_S, AgibotTopicsOptions
from tests.support import aimdk_facts
from tests.support.repo import REPO

X2_YAML = (REPO / "robots/agibot/x2.yaml").read_text(encoding="utf-8")


def x2_yaml(tmp_path: Path, options: str) -> Path:
    text = X2_YAML.replace("urdf: x2.urdf", f"urdf: {REPO / 'robots/agibot/x2.urdf'}")
    text = text.replace("transport_options:\n", "transport_options:\n" + options, 1)
    path = tmp_path / "x2.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_reference_x2_does_not_take_control():
    options = load_config(REPO / "robots/agibot/x2.yaml").transport_options
    assert isinstance(options, AgibotTopicsOptions) and not options.take_control


def test_take_control_and_its_timeout_are_read(tmp_path):
    options = load_config(x2_yaml(tmp_path, "  take_control: true\n  take_control_timeout_s: 12.5\n")).transport_options
    assert isinstance(options, AgibotTopicsOptions)
    assert options.take_control and options.take_control_timeout_s == 12.5
    options = load_config(x2_yaml(tmp_path, "  take_control: true\n")).transport_options
    assert isinstance(options, AgibotTopicsOptions) and options.take_control_timeout_s == TAKE_CONTROL_TIMEOUT_S


@pytest.mark.parametrize(("options", "key", "words"), [
    ("  take_control_timeout_s: 10\n", "take_control_timeout_s", "used only with take_control: true"),
    ("  take_control: true\n  take_control_timeout_s: 0.5\n", "take_control_timeout_s", "from 1 to 600 seconds"),
    ("  take_control: yes please\n", "take_control", "true or false"),
])
def test_refusals(tmp_path, options, key, words):
    path = x2_yaml(tmp_path, options)
    with pytest.raises(ConfigError) as caught:
        load_config(path)
    assert words in str(caught.value) and caught.value.fix and caught.value.line is not None
    line = path.read_text(encoding="utf-8").splitlines()[caught.value.line - 1]
    assert line.strip().startswith(f"{key}:"), line


def test_the_driver_names_the_vendor_services():
    """The C++ client's service and state names are the vendor's (aimdk_facts, read from AimDK's examples)."""
    header = (REPO / "rhi_gen/transports/agibot_topics/agibot_system_state.hpp").read_text(encoding="utf-8")
    for name in (aimdk_facts.MIGRATE_SYSTEM_STATE, aimdk_facts.GET_SYSTEM_STATE):
        assert f'"{name}"' in header
    assert '"Develop_MC"' in header and '"Ready"' in header
    assert {"Develop_MC", "Ready"} <= set(aimdk_facts.SYSTEM_STATES)
    assert f"kAttempts = {aimdk_facts.SERVICE_ATTEMPTS};" in header
    assert f"kAttemptTimeout{{{int(aimdk_facts.SERVICE_ATTEMPT_S * 1000)}}}" in header


def test_new_x2_takes_control(tmp_path):
    from rhi_gen.inputs.scaffold import suggest_yaml
    from rhi_gen.inputs.urdf_loader import load_urdf

    urdf = REPO / "robots/agibot/x2.urdf"
    text = suggest_yaml(vendor="agibot", robot="x2", urdf=load_urdf(urdf), urdf_relative=str(urdf))
    path = tmp_path / "x2.yaml"
    path.write_text(text, encoding="utf-8")
    options = load_config(path).transport_options
    assert isinstance(options, AgibotTopicsOptions) and options.take_control
