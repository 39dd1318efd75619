"""Benchmark: the generated fake robots hold their rate (issue 22).

Run (from the repository root):

    .venv/bin/python benchmarks/bench_fake_robot.py [--seconds 3] [--steps 20000] [--robot g1]

It renders the reference robots' package into a temporary folder, builds benchmarks/cpp/bench_fake_robot.cpp
with each robot's generated src/<vendor>/<robot>_fake_robot.cpp (-O2) against the Rolling stand-ins and the
real ROS message headers, and runs it: the fake robot's loop on its wall timer, spun by an executor thread
(the stand-in rclcpp fires a due timer from the spinning thread, as rclcpp's executor does), for --seconds,
reporting the achieved rate against the robot's nominal one and the jitter of the period (mean of
|period - nominal|, and the largest late and early period); then one loop iteration (the physics of every
motor and the publication of every message of a step) timed --steps times (median, p99, p99.9). The
rate and jitter depend on the machine's load and timer resolution: they are indicative, not asserted.

A robot whose vendor messages are not available here (AgiBot X2 without ../shared) is skipped with one line.
Environment: RHI_CPP_CACHE=<dir> keeps compiled objects between runs.
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from reference_builds import chosen, reference_builds  # noqa: E402  (benchmarks/, the script's folder)

from tests.support import cpp_build  # noqa: E402

BENCH_SOURCE = REPO / "benchmarks" / "cpp" / "bench_fake_robot.cpp"
DISTRO = "rolling"
FLAGS = cpp_build.FLAVOURS["plain"]


def build(builder: cpp_build.CppBuilder, rb: cpp_build.RobotBuild) -> Path:
    m = rb.model
    source = cpp_build.fake_robot_source(rb.package_dir, m.vendor, m.robot)
    assert source is not None, f"{m.vendor}/{m.robot} has no fake robot"
    includes = [rb.package_dir / "include", *cpp_build.DISTROS[DISTRO].include_dirs]
    tag = f"{m.vendor}_{m.robot}"
    # at once: the builder runs one compiler per core
    objects = cpp_build.run_concurrently([
        lambda: builder.compile(source, FLAGS, includes, package=rb.package_dir, name=f"benchfake_robot_{tag}",
                                distro=DISTRO, transport=m.transport),
        lambda: builder.compile(BENCH_SOURCE, FLAGS, includes, package=rb.package_dir, name=f"benchfake_{tag}",
                                distro=DISTRO, transport=m.transport)])
    for o in objects:
        if not o.ok:
            sys.exit(f"bench_fake_robot: {o.path.name} did not compile:\n{o.stderr[-4000:]}")
    linked = builder.link(objects, FLAGS, f"benchfake_{tag}")
    if not linked.ok:
        sys.exit(f"bench_fake_robot: {tag} did not link:\n{linked.stderr[-4000:]}")
    return linked.path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=3.0, help="how long the loop runs (default 3)")
    parser.add_argument("--steps", type=int, default=20000, help="timed loop iterations (default 20000)")
    parser.add_argument("--robot", action="append", help="g1, x2 or pm01 (repeatable; default all)")
    args = parser.parse_args()
    with reference_builds(chosen(args.robot), "rhi_bench_fake_") as (builder, builds):
        for rb in builds:
            label = rb.label
            binary = build(builder, rb)
            run = subprocess.run([str(binary), f"--seconds={args.seconds}", f"--steps={args.steps}"],
                                 capture_output=True, text=True, timeout=120 + args.seconds)
            if run.returncode != 0:
                sys.exit(f"bench_fake_robot: {label} exited with {run.returncode}:\n{run.stderr[-4000:]}")
            print(run.stdout.rstrip(), flush=True)


if __name__ == "__main__":
    main()
