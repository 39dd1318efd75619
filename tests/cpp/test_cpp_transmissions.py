"""Motors that are not joints, in the generated common core: tests/cpp/harness/transmission_checks.cpp.

The program builds a DriverCore for a robot with a geared and reversed motor, a zero offset, a
differential pair and a geared wheel, and checks it against the formulas written out in the program:
state motor -> joint (position, velocity, effort), commands joint -> motor -> joint within float
precision (gains through the square of the ratio, coupled gains as documented), limits in joint space,
NaN and negative gains of a coupled joint held by the command guard on both motors, the safe start
holding the measured pose, no heap allocation in the hot paths, a singular matrix refused, and the
calibration file (applied on top of the generated values, and 15 broken files each refused with one
line naming the file, the line and the fix). Compiled with -Wall -Wextra -Werror on every distro's
stand-ins (plain), and under ASan+UBSan and TSan on the oldest and the newest.
"""
from __future__ import annotations

import pytest

from tests.support import selected
from tests.support.cpp_build import (
    OVERLAP_WORKERS,
    CompileResult,
    compile_transmission_checks,
    run_binary_retrying,
    run_parallel,
)

CELLS = [("humble", "plain"), ("jazzy", "plain"), ("kilted", "plain"), ("rolling", "plain"),
         ("humble", "asan_ubsan"), ("rolling", "asan_ubsan"), ("humble", "tsan"), ("rolling", "tsan")]
SECTIONS = ("transmission_state", "transmission_commands", "calibration", "transmission_spec")


@pytest.fixture(scope="module")
def programs(reference, cpp_builder, request) -> dict[tuple[str, str], CompileResult]:
    """The program of every cell the session's selected tests name, built at once (the builder runs one compiler
    per core), not one cell after the other."""
    cells = selected.keep(CELLS, selected.values(request, ("distro", "flavour")))
    links = run_parallel(cells, lambda cell: compile_transmission_checks(cpp_builder, reference.package_dir,
                                                                          cell[1], cell[0]), OVERLAP_WORKERS)
    return dict(zip(cells, links, strict=True))


@pytest.mark.parametrize(("distro", "flavour"), CELLS)
def test_transmissions_in_the_core(programs, distro, flavour):
    link = programs[(distro, flavour)]
    assert link.ok, f"transmission_checks does not compile ({distro}, {flavour}):\n{link.stderr[:6000]}"
    run = run_binary_retrying(link.path)
    reports = run.sanitizer_reports()
    assert not reports, f"{distro}/{flavour}: sanitizer reports:\n" + "\n".join(reports[:20]) + run.stderr[-4000:]
    assert run.returncode == 0 and run.failed == 0, f"{distro}/{flavour}: {run.describe()}"
    for section in SECTIONS:
        assert f"section {section}: " in run.stdout and f"section {section}: 0 passed" not in run.stdout, \
            f"{distro}/{flavour}: section {section} did not run:\n{run.stdout[-3000:]}"
