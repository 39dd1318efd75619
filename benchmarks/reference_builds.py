"""The reference robots a benchmark measures, rendered into a temporary package, with the compiler front end.

Shared by the benchmarks that build a robot's generated C++ (bench_fake_robot.py, bench_physics.py): the same
object cache (RHI_CPP_CACHE=<dir> keeps it between runs, a temporary folder's otherwise) and the same one line for
a robot whose vendor messages are not available here (AgiBot X2 without ../shared).
"""
from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path

from tests.support import cpp_build, vendor_msgs

ROBOTS = ("unitree/g1", "agibot/x2", "engineai/pm01")


def chosen(names: Sequence[str] | None) -> list[str]:
    """The reference robots named by --robot (g1, x2, pm01), all of them without."""
    return [r for r in ROBOTS if not names or r.split("/")[1] in names]


@contextlib.contextmanager
def reference_builds(robots: Sequence[str], prefix: str
                     ) -> Iterator[tuple[cpp_build.CppBuilder, list[cpp_build.RobotBuild]]]:
    """(builder, the robots that can be built here): those that cannot are skipped with one printed line."""
    cache = Path(os.environ.get("RHI_CPP_CACHE") or Path(tempfile.gettempdir()) / "rhi_bench_cache")
    builder = cpp_build.CppBuilder(cache)
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        package = cpp_build.render_test_package(Path(tmp), only=list(robots), extra_robots=False)
        builds = []
        for label in robots:
            rb = package.build(label)
            reason = vendor_msgs.skip_reason(rb.model.transport)
            if reason:
                print(f"{label}: skipped: {reason}", flush=True)
            else:
                builds.append(rb)
        yield builder, builds
