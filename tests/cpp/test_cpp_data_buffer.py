"""The generated DataBuffer<T> hands frames over whole, without allocating, under ThreadSanitizer.

tests/cpp/harness/data_buffer_stress.cpp is compiled against the generated common/data_buffer.hpp
(-std=c++17 -Wall -Wextra -Werror) in three flavours: plain -O2, ASan+UBSan and TSan. It checks the
contract (nullptr before the first frame, newest frame afterwards, the consumer's frame untouched by
any number of writes until its next getData(), no heap allocation, not copyable), then hands 10^6
frames whose last field is a checksum of the rest from one producer through a
DataBuffer<T, Producers::kOne> (no mutex: the driver's state and IMU buffers), and again from two
producers through a DataBuffer<T> (the driver's command buffer has two: write() and the first-state
callback), to a consumer that
verifies every frame, holds it a while and verifies it again. Torn frames, frames changed while
held and frames going backwards must all be zero, and the sanitizers must report nothing.

The last test proves the stress bites: the seed's double buffer (getData() returns a slot the
producer may overwrite) must fail it.
"""
from __future__ import annotations

import re
import time

import pytest

from tests.support.cpp_build import (FLAVOURS, HARNESS_DIR, CompileResult, compile_data_buffer_stress, require_compiler,
                             run_binary_retrying, run_parallel, session_builder, session_reference_package)

FRAMES = 1_000_000
_TIMES: dict[str, float] = {}


@pytest.fixture(scope="module")
def stress_runs(tmp_path_factory):
    reference = session_reference_package(tmp_path_factory)
    builder = session_builder(tmp_path_factory)
    start = time.monotonic()
    links: list[CompileResult] = run_parallel(
        list(FLAVOURS), lambda flavour: compile_data_buffer_stress(builder, reference.package_dir, flavour))
    _TIMES["build"] = time.monotonic() - start
    start = time.monotonic()
    runs = run_parallel(list(zip(FLAVOURS, links)),
                        lambda item: run_binary_retrying(item[1].path, [f"--frames={FRAMES}"]) if item[1].ok else None,
                        workers=1)
    _TIMES["run"] = time.monotonic() - start
    return {flavour: (link, run) for flavour, link, run in zip(FLAVOURS, links, runs)}


@pytest.mark.parametrize("flavour", list(FLAVOURS))
def test_data_buffer_contract_and_stress(stress_runs, flavour):
    link, run = stress_runs[flavour]
    assert link.ok, f"data_buffer_stress does not compile ({flavour}):\n{link.stderr[:6000]}"
    reports = run.sanitizer_reports()
    assert not reports, f"{flavour}: sanitizer reports:\n" + "\n".join(reports[:20]) + f"\n{run.stderr[-6000:]}"
    assert run.returncode == 0 and run.failed == 0 and run.passed > 0, f"{flavour}: {run.describe()}"
    lines = re.findall(r"^stress (\d) producer\(s\): (\d+) hand-offs, (\d+) distinct frames consumed, torn (\d+), "
                       r"changed while held (\d+), out of order (\d+)", run.stdout, re.M)
    assert [l[0] for l in lines] == ["1", "2"], run.stdout
    for producers, handed, consumed, torn, changed, backwards in lines:
        assert int(handed) == FRAMES, f"{producers} producer(s): {handed} hand-offs"
        assert int(consumed) > 0
        assert (torn, changed, backwards) == ("0", "0", "0"), f"{producers} producer(s): {lines}"


def test_data_buffer_report(stress_runs, capsys):
    out = ["DataBuffer stress (tests/test_cpp_data_buffer.py)"]
    for flavour, (link, run) in stress_runs.items():
        if run is None:
            out.append(f"  {flavour:10s} BUILD FAILED")
            continue
        out.append(f"  {flavour:10s} exit {run.returncode}: {run.passed} passed, {run.failed} failed, "
                   f"{'no sanitizer reports' if not run.sanitizer_reports() else 'SANITIZER REPORTS'} "
                   f"(run {run.seconds:.1f}s)")
        out += [f"             {line}" for line in run.stdout.splitlines() if line.startswith("stress ")]
    out.append(f"  build {_TIMES.get('build', 0):.1f}s, runs {_TIMES.get('run', 0):.1f}s")
    with capsys.disabled():
        print("\n" + "\n".join(out))


BROKEN = ("#pragma once\n#include <array>\n#include <atomic>\n#include <mutex>\n"
          + (HARNESS_DIR / "mutants" / "double_buffer.inc").read_text())


def test_stress_catches_a_buffer_that_hands_out_an_overwritable_slot(tmp_path, tmp_path_factory):
    require_compiler()
    package = tmp_path / "pkg"
    header = package / "include" / "robot_hardware_interface" / "common" / "data_buffer.hpp"
    header.parent.mkdir(parents=True)
    header.write_text(BROKEN)
    link = compile_data_buffer_stress(session_builder(tmp_path_factory), package, "plain")
    assert link.ok, link.stderr[:4000]
    run = run_binary_retrying(link.path, ["--frames=200000"])
    assert run.returncode != 0, f"the stress did not notice a double buffer:\n{run.stdout}"
    assert run.sections.get("contract", (0, 0))[1] > 0, run.stdout
    assert HARNESS_DIR.is_dir()
