"""rhi-gen's robot-independent C++ is checked where it lives, as C++: compiled and linted in place.

The headers in rhi_gen/cpp/ and rhi_gen/transports/<name>/ are copied into every generated package
below its banner (render/static_files.py). Here the sources themselves are checked, before any
package exists: each header compiles on its own (twice included: its guard works; alone: it includes
what it uses) with -Wall -Wextra -Wpedantic -Werror against the Humble stand-ins, and the set passes
ament_cpplint and ament_uncrustify. Both see the files through a tree of links laid out as the
package's include/ folder, because the headers include each other by their package paths
(robot_hardware_interface/common/...); an error names the link, whose file name is the source's.
"""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from rhi_gen import transports
from rhi_gen.render.environment import SOURCE_ROOT
from rhi_gen.render.package import COMMON_FILES, FAKE_ROBOT_FILES
from tests.support import vendor_msgs
from tests.support.ament_lint import run_cpplint, run_uncrustify
from tests.support.cpp_build import (
    WARNING_FLAGS,
    message_include_flags,
    mujoco_include_flags,
    require_compiler,
    run_parallel,
    standin_flags,
)

DISTRO = "humble"


def _sources() -> dict[str, tuple[Path, str]]:
    """package path -> (source file, transport that needs it or "") for every header copied as it is."""
    found: dict[str, tuple[Path, str]] = {out: (SOURCE_ROOT / src, "") for src, out in COMMON_FILES}
    found.update((out, (SOURCE_ROOT / src, "")) for src, out in FAKE_ROBOT_FILES if out.endswith(".hpp"))
    for name, transport in transports.TRANSPORTS.items():
        for src, out in transport.shared_files:
            found.setdefault(out, (SOURCE_ROOT / src, name))
    return found


SOURCES = _sources()


@pytest.fixture(scope="module")
def linked_tree(tmp_path_factory) -> Path:
    """A folder shaped like a generated package whose headers are links to rhi-gen's sources."""
    root = tmp_path_factory.mktemp("sources") / "robot_hardware_interface"
    for out, (source, _) in SOURCES.items():
        link = root / out
        link.parent.mkdir(parents=True, exist_ok=True)
        link.symlink_to(source)
    return root


def test_every_copied_header_is_a_real_file():
    assert len(SOURCES) >= 15, sorted(SOURCES)
    names = {Path(out).name for out in SOURCES}
    assert {"data_buffer.hpp", "types.hpp", "motor_types.hpp", "monitor.hpp", "unitree_crc.hpp"} <= names, names
    for out, (source, _) in SOURCES.items():
        assert source.suffix == ".hpp" and source.is_file(), (out, source)
        assert "{%" not in source.read_text(encoding="utf-8"), f"{source} holds Jinja: it is copied as it is"


def test_each_header_compiles_on_its_own_in_place(linked_tree, tmp_path):
    cxx = require_compiler()
    include = linked_tree / "include"
    # A transport whose vendor messages are not available here is named with its reason, never dropped silently.
    missing = {name: vendor_msgs.skip_reason(name) for name in transports.NAMES if vendor_msgs.skip_reason(name)}
    headers = [out for out, (_, needs) in SOURCES.items() if needs not in missing]

    def compile_one(out: str):
        rel = Path(out).relative_to("include").as_posix()
        src = tmp_path / f"alone_{Path(out).stem}.cpp"
        src.write_text(f'#include "{rel}"\n#include "{rel}"\nint main() {{ return 0; }}\n')
        return rel, subprocess.run([cxx, *WARNING_FLAGS, "-fsyntax-only", f"-I{include}", *standin_flags(DISTRO),
                                    *message_include_flags(), *mujoco_include_flags(), str(src)],
                              capture_output=True, text=True)

    failures = [f"{rel} ({SOURCES[f'include/{rel}'][0]}):\n{proc.stderr[:3000]}"
                for rel, proc in run_parallel(headers, compile_one) if proc.returncode != 0]
    assert not failures, "\n".join(failures)
    if missing:
        pytest.skip("; ".join(f"not compiled: {reason}" for reason in missing.values()))


def test_sources_pass_cpplint_in_place(linked_tree):
    findings = run_cpplint(linked_tree)
    assert not findings, "\n".join(f"{f.file}:{f.line}: [{f.rule}] {f.message}" for f in findings[:40])


def test_sources_pass_uncrustify_in_place(linked_tree):
    result = run_uncrustify(linked_tree)
    assert not result.findings, "\n".join(f"--- {name}\n{diff}" for name, diff in list(result.diffs.items())[:3])
