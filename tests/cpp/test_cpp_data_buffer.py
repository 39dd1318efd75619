"""The generated DataBuffer<T> hands frames over whole, without allocating, under ThreadSanitizer.

tests/cpp/harness/data_buffer_stress.cpp is compiled against the generated common/data_buffer.hpp
(-std=c++17 -Wall -Wextra -Werror) in three flavours: plain -O2, ASan+UBSan and TSan. It checks the
contract (nullptr before the first frame, newest frame afterwards, the consumer's frame untouched by
any number of writes until its next get_data(), no heap allocation, not copyable), then hands 10^6
frames whose last field is a checksum of the rest from one producer through a
DataBuffer<T, Producers::kOne> (no mutex: the driver's state and IMU buffers), and again from two
producers through a DataBuffer<T> (the driver's command buffer has two: write() and the first-state
callback), to a consumer that
verifies every frame, holds it a while and verifies it again. Torn frames, frames changed while
held and frames going backwards must all be zero, and the sanitizers must report nothing.

The last test proves the stress bites: the seed's double buffer (get_data() returns a slot the
producer may overwrite) must fail it.
"""
from __future__ import annotations

import re

import pytest

from tests.support.cpp_build import (
    FLAVOURS,
    HARNESS_DIR,
    CompileResult,
    compile_data_buffer_stress,
    require_compiler,
    run_binary_retrying,
    run_parallel,
)

FRAMES = 1_000_000


def build_and_run_stress(reference, builder) -> dict:
    """{flavour: (link result, run or None)}: the stress built in every flavour in parallel, run one at a time."""
    links: list[CompileResult] = run_parallel(
        list(FLAVOURS), lambda flavour: compile_data_buffer_stress(builder, reference.package_dir, flavour))
    runs = run_parallel(list(zip(FLAVOURS, links, strict=True)),
                        lambda item: run_binary_retrying(item[1].path, [f"--frames={FRAMES}"]) if item[1].ok else None,
                        workers=1)
    return {flavour: (link, run) for flavour, link, run in zip(FLAVOURS, links, runs, strict=True)}


@pytest.fixture(scope="module")
def stress_runs(reference, cpp_builder):
    return build_and_run_stress(reference, cpp_builder)


@pytest.mark.parametrize("flavour", list(FLAVOURS))
def test_data_buffer_contract_and_stress(stress_runs, flavour):
    link, run = stress_runs[flavour]
    assert link.ok, f"data_buffer_stress does not compile ({flavour}):\n{link.stderr[:6000]}"
    reports = run.sanitizer_reports()
    assert not reports, f"{flavour}: sanitizer reports:\n" + "\n".join(reports[:20]) + f"\n{run.stderr[-6000:]}"
    assert run.returncode == 0 and run.failed == 0 and run.passed > 0, f"{flavour}: {run.describe()}"
    lines = re.findall(r"^stress (\d) producer\(s\): (\d+) hand-offs, (\d+) distinct frames consumed, torn (\d+), "
                       r"changed while held (\d+), out of order (\d+)", run.stdout, re.M)
    assert [found[0] for found in lines] == ["1", "2"], run.stdout
    for producers, handed, consumed, torn, changed, backwards in lines:
        assert int(handed) == FRAMES, f"{producers} producer(s): {handed} hand-offs"
        assert int(consumed) > 0
        assert (torn, changed, backwards) == ("0", "0", "0"), f"{producers} producer(s): {lines}"


BROKEN = ("#pragma once\n#include <array>\n#include <atomic>\n#include <mutex>\n"
          + (HARNESS_DIR / "mutants" / "double_buffer.inc").read_text())


def test_stress_catches_a_buffer_that_hands_out_an_overwritable_slot(tmp_path, cpp_builder):
    require_compiler()
    package = tmp_path / "pkg"
    header = package / "include" / "robot_hardware_interface" / "common" / "data_buffer.hpp"
    header.parent.mkdir(parents=True)
    header.write_text(BROKEN)
    link = compile_data_buffer_stress(cpp_builder, package, "plain")
    assert link.ok, link.stderr[:4000]
    run = run_binary_retrying(link.path, ["--frames=200000"])
    assert run.returncode != 0, f"the stress did not notice a double buffer:\n{run.stdout}"
    assert run.sections.get("contract", (0, 0))[1] > 0, run.stdout
    assert HARNESS_DIR.is_dir()
