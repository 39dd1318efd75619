"""A fix speaks the language of the command used.

`inspect` and `new` take the description's inputs as options (--urdf, --xacro-arg NAME=VALUE,
--package-path PKG=DIR); `generate`, `check` and `diff` read them from the vendor YAML (urdf:,
xacro_args:, package_paths:). The same broken xacro is therefore answered with the option on the
command line and with the YAML key in a project, and never the other way round. An include that
cannot be read is named by the path that was tried ($(find ...) expanded) and by the including
file's line. Every rejection is the whole contract: exit 2, one line, nothing written.
"""
from __future__ import annotations

import builtins
import errno
import os
import shutil
from pathlib import Path

import pytest

from tests.support.cli import assert_rejected, new_rejected, run_cli, snapshot
from tests.support.repo import HOSTILE
from tests.support.repo import URDF_FIXTURES as FIX

XACRO = FIX / "xacro"
MYPKG = FIX / "mypkg"
YAML_WORDS = ("xacro_args", "package_paths", "vendor YAML", "urdf: path", "point urdf:")
CLI_WORDS = ("--xacro-arg", "--package-path", "--urdf")
ANY = -1  # assert_rejected(line=ANY): some line number


def assert_cli_words(message: str) -> None:
    assert not any(w in message for w in YAML_WORDS), f"a YAML key in a command-line fix: {message!r}"


def assert_yaml_words(message: str) -> None:
    assert not any(w in message for w in CLI_WORDS), f"a command-line option in a YAML fix: {message!r}"


def inspect_rejected(*args: str | os.PathLike, **expect) -> str:
    message = assert_rejected(run_cli("inspect", *args), **expect)
    assert_cli_words(message)
    return message


@pytest.fixture
def xacro_copy(tmp_path: Path) -> Path:
    """tests/fixtures' xacro robot and its package, copied where the tests may break them."""
    root = tmp_path / "desc"
    shutil.copytree(XACRO, root / "xacro")
    shutil.copytree(MYPKG, root / "pkgs" / "mypkg")
    return root


def yaml_project(tmp_path: Path, xacro: Path, extra: str = "") -> Path:
    """A project whose robot is ``xacro`` (copied with its folder into robots/acme/)."""
    root = tmp_path / "proj"
    robots = root / "robots" / "acme"
    shutil.copytree(xacro.parent, robots)
    if (xacro.parent.parent / "pkgs").is_dir():
        shutil.copytree(xacro.parent.parent / "pkgs", root / "pkgs")
    (robots / "bot.yaml").write_text(
        "vendor: acme\nrobot: bot\n"
        f"urdf: {xacro.name}\ntransport: generic_topics\nmotor_count: 2\n{extra}"
        "joint_map:\n  joint_a: 0\n  left_hip: 1\n")
    return root


def yaml_rejected(root: Path, command: str, **expect) -> str:
    before = snapshot(root)
    message = assert_rejected(run_cli(command, "--project", root), **expect)
    assert snapshot(root) == before
    assert_yaml_words(message)
    return message


# ---------------------------------------------------------------- $(find pkg) without a package path
def test_unknown_package_on_inspect_names_the_option():
    xacro = XACRO / "robot.urdf.xacro"
    message = inspect_rejected("--urdf", xacro, file=str(xacro), line=7,
                               words=("$(find mypkg): unknown package 'mypkg'", "add --package-path mypkg=<dir>"))
    # the fix works as written
    ok = run_cli("inspect", "--urdf", xacro, "--package-path", f"mypkg={MYPKG}")
    assert ok.code == 0 and "left_hip" in ok.out, ok.err
    assert "package_paths" not in message


def test_unknown_package_on_new_names_the_option(tmp_path):
    xacro = XACRO / "robot.urdf.xacro"
    message = new_rejected(tmp_path / "proj", "--vendor", "acme", "--robot", "bot", "--urdf", xacro,
                           file=str(xacro), line=7, words=("add --package-path mypkg=<dir>",))
    assert_cli_words(message)


@pytest.mark.parametrize("command", ["generate", "check", "diff"])
def test_unknown_package_in_a_project_names_the_yaml_key(tmp_path, command):
    root = yaml_project(tmp_path, XACRO / "robot.urdf.xacro")
    yaml_rejected(root, command, file="robots/acme/robot.urdf.xacro", line=7,
                  words=("add package_paths: {mypkg: <dir>} to the vendor YAML",))


def test_package_path_that_is_not_a_directory_on_inspect():
    xacro = XACRO / "robot.urdf.xacro"
    inspect_rejected("--urdf", xacro, "--package-path", "mypkg=/no/such/dir", file=str(xacro), line=7,
                     words=("/no/such/dir (given by --package-path mypkg=...) is not a directory",
                            "fix --package-path mypkg=<dir>"))


def test_package_path_that_is_not_a_directory_in_a_project(tmp_path):
    root = yaml_project(tmp_path, XACRO / "robot.urdf.xacro", extra="package_paths:\n  mypkg: ../../nowhere\n")
    yaml_rejected(root, "generate", file="robots/acme/robot.urdf.xacro", line=7,
                  words=("is not a directory", "fix package_paths: {mypkg: <dir>} in the vendor YAML"))


# ---------------------------------------------------------------- $(arg name) without a value
def test_missing_arg_on_inspect_names_the_option():
    xacro = XACRO / "needs_arg.urdf.xacro"
    inspect_rejected("--urdf", xacro, file=str(xacro), line=3,
                     words=("xacro arg 'base_name' is not set", "add --xacro-arg base_name=<value>"))
    ok = run_cli("inspect", "--urdf", xacro, "--xacro-arg", "base_name=torso")
    assert ok.code == 0 and "'needs_arg'" in ok.out, ok.err


def test_missing_arg_in_a_project_names_the_yaml_key(tmp_path):
    root = tmp_path / "proj"
    (root / "robots" / "acme").mkdir(parents=True)
    shutil.copy(HOSTILE / "needs_arg.urdf.xacro", root / "robots/acme/arm.urdf.xacro")
    (root / "robots/acme/arm.yaml").write_text(
        "vendor: acme\nrobot: arm\nurdf: arm.urdf.xacro\ntransport: generic_topics\nmotor_count: 1\n"
        "joint_map:\n  left_shoulder_pan: 0\n")
    yaml_rejected(root, "generate", file="robots/acme/arm.urdf.xacro", line=ANY,
                  words=("xacro arg 'prefix' is not set", "add xacro_args: {prefix: <value>} to the vendor YAML"))



# ---------------------------------------------------------------- includes that cannot be read
def _break_include(xacro: Path, old: str, new: str) -> None:
    text = xacro.read_text()
    assert text.count(old) == 1
    xacro.write_text(text.replace(old, new))


def test_missing_package_file_shows_the_expanded_path_and_the_include_line(xacro_copy):
    top = xacro_copy / "xacro" / "robot.urdf.xacro"
    _break_include(top, "$(find mypkg)/urdf/leg.xacro", "$(find mypkg)/urdf/no_leg.xacro")
    pkg = xacro_copy / "pkgs" / "mypkg"
    message = inspect_rejected("--urdf", top, "--package-path", f"mypkg={pkg}", file=str(top), line=7,
                               words=(f"cannot open {pkg}/urdf/no_leg.xacro (No such file or directory)",
                                      f"package 'mypkg' is {pkg} (given by --package-path mypkg=...)"))
    assert "$(find mypkg)/urdf/no_leg" not in message


def test_missing_package_file_through_generate_is_project_relative(tmp_path, xacro_copy):
    top = xacro_copy / "xacro" / "robot.urdf.xacro"
    _break_include(top, "$(find mypkg)/urdf/leg.xacro", "$(find mypkg)/urdf/no_leg.xacro")
    root = yaml_project(tmp_path, top, extra="package_paths:\n  mypkg: ../../pkgs/mypkg\n")
    message = yaml_rejected(root, "generate", file="robots/acme/robot.urdf.xacro", line=7,
                            words=("cannot open pkgs/mypkg/urdf/no_leg.xacro (No such file or directory)",
                                   "package_paths: {mypkg: ...} in the vendor YAML"))
    assert str(tmp_path) not in message.split(" -> ")[0]


def test_missing_include_inside_a_package_file_names_that_file_and_line(xacro_copy):
    leg = xacro_copy / "pkgs" / "mypkg" / "urdf" / "leg.xacro"
    _break_include(leg, '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">',
                   '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="$(arg parts_dir)/knee.xacro"/>')
    top = xacro_copy / "xacro" / "robot.urdf.xacro"
    parts = xacro_copy / "parts"
    inspect_rejected("--urdf", top, "--package-path", f"mypkg={xacro_copy / 'pkgs' / 'mypkg'}",
                     "--xacro-arg", f"parts_dir={parts}", file=str(leg), line=3,
                     words=(f"cannot open {parts}/knee.xacro", "check the <xacro:include filename=...>",
                            "--package-path PKG=DIR"))


def test_relative_include_of_a_missing_file_is_shown_next_to_the_including_file(tmp_path):
    xacro = HOSTILE / "missing_include.urdf.xacro"
    shown = os.path.relpath(xacro)
    message = assert_rejected(run_cli("inspect", "--urdf", shown), file=shown, line=3,
                              words=(f"cannot open {os.path.dirname(shown)}/parts/arm_macros.xacro",))
    assert_cli_words(message)


def test_include_of_a_directory(xacro_copy):
    top = xacro_copy / "xacro" / "robot.urdf.xacro"
    _break_include(top, '<xacro:include filename="macros.xacro"/>', '<xacro:include filename="../pkgs"/>')
    inspect_rejected("--urdf", top, "--package-path", f"mypkg={xacro_copy / 'pkgs' / 'mypkg'}",
                     file=str(top), line=6, words=(f"cannot open {xacro_copy / 'pkgs'} (Is a directory)",))


def test_unreadable_include(xacro_copy, monkeypatch):
    macros = xacro_copy / "xacro" / "macros.xacro"
    macros.chmod(0)
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        # root opens a mode-0 file: make open() answer what the kernel answers everyone else
        real_open = builtins.open

        def denying_open(file, *args, **kwargs):
            if os.fspath(file) == str(macros):
                raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(macros))
            return real_open(file, *args, **kwargs)

        monkeypatch.setattr(builtins, "open", denying_open)
    try:
        top = xacro_copy / "xacro" / "robot.urdf.xacro"
        inspect_rejected("--urdf", top, "--package-path", f"mypkg={xacro_copy / 'pkgs' / 'mypkg'}",
                         file=str(top), line=6, words=(f"cannot open {macros} (Permission denied)", "chmod"))
    finally:
        macros.chmod(0o644)


def test_package_url_include_in_a_real_description():
    """example-robot-data's hector quadrotor includes a package:// URL, which xacro cannot open."""
    import importlib.metadata

    files = importlib.metadata.files("example-robot-data") or []
    hits = [f for f in files if str(f).endswith("hector_description/robots/quadrotor_base.xacro")]
    if not hits:
        pytest.skip("example-robot-data is not installed")
    xacro = Path(str(hits[0].locate()))
    inspect_rejected("--urdf", xacro, file=str(xacro), line=3,
                     words=("xacro does not resolve package:// URLs",
                            "write $(find example-robot-data)/robots/hector_description/urdf/quadrotor_base.urdf.xacro",
                            "add --package-path example-robot-data=<dir>"))


# ---------------------------------------------------------------- the description file itself
@pytest.mark.parametrize("name", ["none.urdf", "none.urdf.xacro"])
def test_missing_description_on_inspect_names_the_option(tmp_path, name):
    missing = tmp_path / name
    inspect_rejected("--urdf", missing, file=str(missing), words=("file not found", "--urdf"))


def test_empty_description_on_inspect_names_the_option(tmp_path):
    empty = tmp_path / "empty.urdf"
    empty.write_text("")
    inspect_rejected("--urdf", empty, file=str(empty), words=("file is empty", "point --urdf at"))


def test_directory_as_description_in_a_project_names_the_yaml_key(tmp_path):
    root = yaml_project(tmp_path, XACRO / "robot.urdf.xacro")
    yml = root / "robots/acme/bot.yaml"
    yml.write_text(yml.read_text().replace("urdf: robot.urdf.xacro", "urdf: parts"))
    yaml_rejected(root, "generate", file="robots/acme/bot.yaml", line=3, key="urdf", words=("is a directory",))
