"""Benchmark: the fake robot on MuJoCo with the driver and the controller beside it, in real-time factors (issue 36).

Run (from the repository root):

    .venv/bin/python benchmarks/bench_physics.py [--robot g1] [--repeat 3]

It renders the reference robots' package into a temporary folder and builds each robot's driver harness in the
cell whose fake robot runs on MuJoCo (tests/support/cpp_build.py PHYSICS_CELL: Jazzy, -O2, the test extra's
mujoco-core), then runs its physics sections (tests/cpp/harness/physics_checks.inc): the robot compiled by MuJoCo
from the package's URDF, on the elastic band, the physics at 1 kHz, the fake robot answering the real driver at the
robot's state rate through the robot's own protocol, the harness playing the controller manager (read(), a
controller holding the start pose with the YAML's gains, write()), all of it on one thread as fast as it goes, for
5 simulated seconds. The real-time factor is simulated time over wall time (above 1.0: the physics, both sides of
the protocol and the control loop together keep up with the robot's clock on one core). Then the same with contacts
on (issue 49): the base free, the robot standing on its feet on the floor for 10 simulated seconds (physics_stand
with the YAML's gains, or physics_stand_stiff, the lower body held at 500 N m/rad, for a robot whose YAML gains do
not stand it: the G1 and the X2). Figures, never asserted: they depend on the machine and its load. --repeat runs
each robot that many times (the median is printed).

A robot whose vendor messages are not available here (AgiBot X2 without ../shared) is skipped with one line.
Environment: RHI_CPP_CACHE=<dir> keeps compiled objects between runs.
"""
from __future__ import annotations

import argparse
import re
import statistics
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from reference_builds import chosen, reference_builds  # noqa: E402  (benchmarks/, the script's folder)

from tests.support import cpp_build  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", action="append", help="g1, x2 or pm01 (repeatable; default all)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per robot (default 3; the median is printed)")
    args = parser.parse_args()
    distro, flavour = cpp_build.PHYSICS_CELL
    band = cpp_build.PhysicsRobot("band", ("band", "stand", "stand_stiff"))
    with reference_builds(chosen(args.robot), "rhi_bench_physics_") as (builder, builds):
        for rb in builds:
            label = rb.label
            linked, _ = cpp_build.build_harness(builder, rb, flavour, distro, physics=True)
            if not linked.ok:
                sys.exit(f"bench_physics: {label} did not build:\n{linked.stderr[-4000:]}")
            factors, standing, rate, how = [], [], 0.0, ""
            for _ in range(max(1, args.repeat)):
                run = cpp_build.run_binary(linked.path, ["--only=physics", *cpp_build.physics_arguments(rb, band)])
                figures = dict(re.findall(r"^physics (\S+)=(\S+)$", run.stdout, re.M))
                if run.returncode != 0 or "band.rtf" not in figures:
                    sys.exit(f"bench_physics: {label} failed:\n{run.describe()}")
                factors.append(float(figures["band.rtf"]))
                rate = float(figures["band.rate_hz"])
                how = next((s for s in ("stand", "stand_stiff") if float(figures.get(f"{s}.fell_at_s", "0")) < 0), "")
                if how:
                    standing.append(float(figures[f"{how}.rtf"]))
            print(f"{label}: physics 1000 Hz, robot {rate:.0f} Hz, driver + controller on the same thread: real-time "
                  f"factor {statistics.median(factors):.2f} on the band (median of {len(factors)}: "
                  f"{', '.join(f'{f:.2f}' for f in factors)}); " +
                  (f"{statistics.median(standing):.2f} standing on its feet, contacts on ({how}; "
                   f"{', '.join(f'{f:.2f}' for f in standing)})" if standing else "it does not stand"), flush=True)


if __name__ == "__main__":
    main()
