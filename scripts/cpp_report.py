"""Print what the C++ tier checks, cell by cell: the figures the tests assert, for a reader.

For every robot of the driver harness matrix (tests/cpp/test_cpp_drivers.py: MATRIX) the harness's
check counts per section, exit code, sanitizer verdict, allocation/thread/decimation lines and the
compile and run times; then the DataBuffer stress (tests/cpp/test_cpp_data_buffer.py) per flavour.
It builds exactly what those tests build, with the same code (their build_and_run_cells /
build_and_run_stress), so RHI_CPP_CACHE=<dir> makes it fast after a test run. Exit 1 when a cell
failed to build or a check failed (the tests say which and why):

    RHI_CPP_CACHE=/tmp/cppcache .venv/bin/python scripts/cpp_report.py [drivers] [data_buffer]
"""
from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.cpp.test_cpp_data_buffer import build_and_run_stress
from tests.cpp.test_cpp_drivers import (
    COMPILE_MATRIX,
    MATRIX,
    ROBOTS,
    SECTION_ORDER,
    build_and_run_cells,
    in_cell,
)
from tests.support import vendor_msgs
from tests.support.cpp_build import session_builder, session_reference_package


class TempDirs:
    """The one method of pytest's tmp_path_factory the session helpers call."""

    def __init__(self, root: Path) -> None:
        self.root = root

    def mktemp(self, name: str) -> Path:
        return Path(tempfile.mkdtemp(prefix=f"{name}_", dir=self.root))


def driver_report(reference, builder) -> tuple[list[str], bool]:
    start = time.monotonic()
    binaries, runs = build_and_run_cells(reference, builder)
    done = time.monotonic()
    ok = True
    lines = ["C++ driver harness (tests/cpp/test_cpp_drivers.py)", ""]
    for label in ROBOTS:
        b = reference.build(label)
        lines.append(f"{label}: {b.model.transport}, {b.model.motor_count} SDK slots, "
                     f"{len(b.model.joints)} mapped joints, {b.model.float_type}")
        if vendor_msgs.skip_reason(b.model.transport):
            lines.append(f"  SKIPPED: {vendor_msgs.skip_reason(b.model.transport)}")
            continue
        for distro, flavour in MATRIX:
            if not in_cell(label, distro, flavour):
                continue
            link, steps = binaries[(label, distro, flavour)]
            compile_s = sum(s.seconds for s in steps) + (link.seconds if link not in steps else 0.0)
            ok = ok and link.ok
            if (distro, flavour) in COMPILE_MATRIX:
                lines.append(f"  {distro:8s} {flavour:10s} driver object {'compiles' if link.ok else 'FAILS'} "
                             f"with -Werror ({compile_s:.1f}s; runtime path: jazzy, rolling)")
                continue
            run = runs.get((label, distro, flavour))
            if run is None:
                lines.append(f"  {distro:8s} {flavour:10s} BUILD FAILED")
                continue
            ok = ok and run.returncode == 0 and run.failed == 0 and not run.sanitizer_reports()
            sections = ", ".join(f"{name} {run.sections[name][0]}" + (f"/{run.sections[name][1]} FAILED"
                                                                        if run.sections[name][1] else "")
                                 for name in SECTION_ORDER if name in run.sections)
            sanitizer = "no sanitizer reports" if not run.sanitizer_reports() else \
                f"{len(run.sanitizer_reports())} SANITIZER REPORT LINES"
            lines.append(f"  {distro:8s} {flavour:10s} exit {run.returncode}: {run.passed} passed, {run.failed} failed "
                         f"({sanitizer}; compile {compile_s:.1f}s, run {run.seconds:.1f}s)")
            lines.append(f"             {sections}")
            for prefix in ("allocations over", "threads:", "decimation"):
                for line in run.stdout.splitlines():
                    if line.startswith(prefix) and flavour in ("plain", "tsan"):
                        lines.append(f"             {line}")
    lines += ["", f"time: built and run (runs overlapping the compiles) in {done - start:.1f}s"]
    return lines, ok


def data_buffer_report(reference, builder) -> tuple[list[str], bool]:
    start = time.monotonic()
    stress = build_and_run_stress(reference, builder)
    ok = True
    lines = ["DataBuffer stress (tests/cpp/test_cpp_data_buffer.py)"]
    for flavour, (_, run) in stress.items():
        if run is None:
            lines.append(f"  {flavour:10s} BUILD FAILED")
            ok = False
            continue
        ok = ok and run.returncode == 0 and run.failed == 0 and not run.sanitizer_reports()
        lines.append(f"  {flavour:10s} exit {run.returncode}: {run.passed} passed, {run.failed} failed, "
                     f"{'no sanitizer reports' if not run.sanitizer_reports() else 'SANITIZER REPORTS'} "
                     f"(run {run.seconds:.1f}s)")
        lines += [f"             {line}" for line in run.stdout.splitlines() if line.startswith("stress ")]
    lines.append(f"  build and runs {time.monotonic() - start:.1f}s")
    return lines, ok


REPORTS = {"drivers": driver_report, "data_buffer": data_buffer_report}


def main(argv: list[str]) -> int:
    wanted = argv or list(REPORTS)
    unknown = [name for name in wanted if name not in REPORTS]
    if unknown:
        print(f"unknown report {unknown}; choose from {sorted(REPORTS)}", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="rhi_cpp_report_") as tmp:
        dirs = TempDirs(Path(tmp))
        reference = session_reference_package(dirs)
        builder = session_builder(dirs)
        all_ok = True
        for name in wanted:
            lines, ok = REPORTS[name](reference, builder)
            print("\n".join(lines), end="\n\n")
            all_ok = all_ok and ok
    return 0 if all_ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
