"""The generated CMakeLists.txt finds MuJoCo for the fake robots' physics (--physics mujoco), or says in one line
that it did not, and builds the package as before either way.

Its MuJoCo block, taken from the reference package's CMakeLists.txt as generated, is configured by the real
cmake in a project of its own (the rest of the file needs ament_cmake, which a test machine has not): with
RHI_MUJOCO_ROOT naming a MuJoCo release's layout (include/mujoco/mujoco.h, lib/libmujoco.so*), naming a folder
without it, and empty, where it asks Python3_EXECUTABLE for the `mujoco` package: the test extra's `mujoco-core`
(libmujoco.so.* beside include/mujoco/), or an interpreter without it.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.cpp_build import mujoco_dir
from tests.support.repo import REPO

CMAKELISTS = REPO / "generated" / "robot_hardware_interface" / "CMakeLists.txt"
BEGIN = "# ---------------------------------------------------------------- MuJoCo (optional)"
END = 'set(RHI_BUILT_TARGETS "")'
PROBE = """
if(TARGET rhi_mujoco)
  get_target_property(location rhi_mujoco IMPORTED_LOCATION)
  get_target_property(include rhi_mujoco INTERFACE_INCLUDE_DIRECTORIES)
  message(STATUS "probe: ${location} | ${include}")
endif()
"""


def configure(tmp_path: Path, *defines: str) -> list[str]:
    """The STATUS lines the MuJoCo block prints (and the probe's), configured with ``defines``."""
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.fail("cmake is not installed (Debian's cmake; never skipped)")
    text = CMAKELISTS.read_text(encoding="utf-8")
    block = text[text.index(BEGIN):text.index(END)]
    source = tmp_path / "src"
    source.mkdir(exist_ok=True)
    (source / "CMakeLists.txt").write_text(
        f"cmake_minimum_required(VERSION 3.16)\nproject(probe LANGUAGES NONE)\n{block}{PROBE}", encoding="utf-8")
    build = tmp_path / f"build{len(list(tmp_path.glob('build*')))}"
    proc = subprocess.run([cmake, "--no-warn-unused-cli", "-S", str(source), "-B", str(build), *defines],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0 and "CMake Warning" not in proc.stderr, proc.stdout + proc.stderr
    return [line.removeprefix("-- ") for line in proc.stdout.splitlines()
            if line.startswith(("-- robot_hardware_interface:", "-- probe:"))]


def test_every_fake_robot_gets_mujoco_only_where_it_was_found():
    text = CMAKELISTS.read_text(encoding="utf-8")
    executables = re.findall(r"add_executable\((\w+_fake_robot)\n", text)
    assert executables == ["x2_fake_robot", "pm01_fake_robot", "g1_fake_robot"]
    for exe in executables:
        assert (f"  if(TARGET rhi_mujoco)\n"
                f"    # --physics mujoco; the installed executable finds libmujoco where it was linked from.\n"
                f"    target_compile_definitions({exe} PRIVATE RHI_FAKE_PHYSICS_MUJOCO)\n"
                f"    target_link_libraries({exe} PRIVATE rhi_mujoco)\n"
                f"    set_target_properties({exe} PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)\n"
                f"  endif()\n") in text, exe
    assert text.count("RHI_FAKE_PHYSICS_MUJOCO") == len(executables)  # the drivers never get it


def test_a_mujoco_release_named_by_rhi_mujoco_root(tmp_path):
    release = tmp_path / "mujoco-3.3.0"
    (release / "include" / "mujoco").mkdir(parents=True)
    (release / "include" / "mujoco" / "mujoco.h").write_text("", encoding="utf-8")
    (release / "lib").mkdir()
    for name in ("libmujoco.so.3.3.0", "libmujoco.so"):
        (release / "lib" / name).write_text("", encoding="utf-8")
    lines = configure(tmp_path, f"-DRHI_MUJOCO_ROOT={release}", "-DPython3_EXECUTABLE=/nonexistent/python3")
    assert lines == [(f"robot_hardware_interface: fake robots with MuJoCo physics (--physics mujoco): "
                     f"{release}/lib/libmujoco.so"),
                     f"probe: {release}/lib/libmujoco.so | {release}/include"]


def test_a_folder_without_mujoco_named_by_rhi_mujoco_root(tmp_path):
    lines = configure(tmp_path, f"-DRHI_MUJOCO_ROOT={tmp_path / 'nothing'}")
    assert lines == [(f"robot_hardware_interface: fake robots without MuJoCo physics: RHI_MUJOCO_ROOT "
                     f"{tmp_path / 'nothing'} has no include/mujoco/mujoco.h and lib/libmujoco.so")]


def test_the_pip_installed_mujoco(tmp_path):
    mj = mujoco_dir()
    assert mj is not None, "mujoco-core is not installed: pip install -e '.[test]' (never skipped)"
    (library,) = sorted(mj.glob("libmujoco.so*"))
    lines = configure(tmp_path, f"-DPython3_EXECUTABLE={sys.executable}")
    assert lines == [f"robot_hardware_interface: fake robots with MuJoCo physics (--physics mujoco): {library}",
                     f"probe: {library} | {mj / 'include'}"]


def test_no_mujoco_anywhere(tmp_path):
    python = tmp_path / "python3"  # an interpreter that finds no `mujoco` package
    python.write_text("#!/bin/sh\nexit 0\n", encoding="utf-8")
    python.chmod(0o755)
    lines = configure(tmp_path, f"-DPython3_EXECUTABLE={python}")
    assert lines == [("robot_hardware_interface: fake robots without MuJoCo physics: pip install mujoco-core, or "
                     "-DRHI_MUJOCO_ROOT=<a MuJoCo release's folder>, to build --physics mujoco")]
