"""Benchmark: the closed-loop latency a controller feels, from a state on the wire to the command that answers it.

Run (from the repository root):

    .venv/bin/python benchmarks/bench_latency.py [--seconds 5] [--robot g1] [--distro jazzy]

Per reference robot it builds benchmarks/cpp/bench_hot_paths.cpp (the hot-path benchmark's binary and objects,
-O2, against the C++ stand-ins: tests/support/cpp_build.py) and runs its `latency` mode twice, on an idle
machine and with as many busy threads as the machine has cores ("loaded"):

* timer   a robot thread sends a state at the robot's rate (the fake robot's: 500 Hz for the G1 and the PM01,
          1 kHz for the X2), each joint's position carrying the state's sequence; the controller manager's
          loop, played as ros2_control runs it (one thread at the controllers YAML's update_rate: read(), a
          controller holding the measured positions, write()), echoes it into the position commands, which
          leave on the driver's own writer (its SDK thread or executor wall timer, every
          command_writer_period_us). An observer of the command topic notes the first command carrying each
          state's sequence: latency = command on the wire - state on the wire. Two free-running clocks sit in
          that path (the state waits for the loop's next cycle, the command for the writer's next tick).
* on_write the same loop with the driver's hardware parameter command_writer_mode on_write: the command leaves
          on the driver's OnWriteCommandWriter thread as soon as write() has built it (rate-limited to one per
          command_writer_period_us on average): one free-running clock fewer.
* floor   the same driver, each state answered directly from its callback on the robot's thread (read(), the
          controller, write(), the writer's send): the driver's own code, nothing waiting.

Median, p99, p99.9 and max in microseconds, over the states answered. The stand-in transports hand a state to
the driver's callback on the sending thread and a command to the observer on the writer's: no network, no DDS
listener or executor wake-up in between (those add the transport's own latency, on a robot as in a
simulation). Figures depend on the machine and its load: never asserted.

A robot whose vendor messages are not available here (AgiBot X2 without ../shared) is skipped with one line.
Environment: RHI_CPP_CACHE=<dir> keeps compiled objects between runs.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from bench_hot_paths import build  # noqa: E402  (benchmarks/, the script's folder)
from reference_builds import chosen, reference_builds  # noqa: E402

from rhi_gen import transports  # noqa: E402
from tests.support import cpp_build  # noqa: E402

LINE = re.compile(r"^latency (\w+) samples (\d+) states (\d+) commands \d+ undecoded \d+(?: median_us (\S+) "
                  r"p99_us (\S+) p99\.9_us (\S+) max_us (\S+))?$", re.M)


def update_rate(package_dir: Path, robot: str) -> float:
    """The controller manager's update_rate of the robot's generated controllers YAML."""
    config = yaml.safe_load((package_dir / "config" / f"{robot}_controllers.yaml").read_text(encoding="utf-8"))
    return float(config["controller_manager"]["ros__parameters"]["update_rate"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=5.0, help="how long each mode runs (default 5)")
    parser.add_argument("--robot", action="append", help="g1, x2 or pm01 (repeatable; default all)")
    parser.add_argument("--distro", default="jazzy", choices=sorted(cpp_build.DISTROS),
                        help="the ros2_control stand-ins compiled against (default jazzy)")
    args = parser.parse_args()
    cores = os.cpu_count() or 1
    with reference_builds(chosen(args.robot), "rhi_bench_latency_") as (builder, builds):
        for rb in builds:
            binary = build(builder, rb, args.distro)
            robot_hz = transports.get(rb.model.transport).fake_state_rate_hz
            update_hz = update_rate(rb.package_dir, rb.model.robot)
            period_us = rb.model.parameters.command_writer_period_us
            print(f"== {rb.label} on {args.distro}: states {robot_hz:.0f} Hz, update_rate {update_hz:.0f} Hz, "
                  f"command_writer_period_us {period_us}", flush=True)
            for load, busy in (("idle", 0), ("loaded", cores)):
                run = subprocess.run([str(binary), "latency", str(args.seconds), str(robot_hz), str(update_hz),
                                      str(busy)], capture_output=True, text=True, timeout=120 + 4 * args.seconds,
                                     env=cpp_build.ENV_C)
                if run.returncode != 0:
                    sys.exit(f"bench_latency: {rb.label} exited with {run.returncode}:\n{run.stderr[-4000:]}")
                for mode, samples, states, *figures in LINE.findall(run.stdout):
                    shown = (f"median {figures[0]} us, p99 {figures[1]} us, p99.9 {figures[2]} us, max {figures[3]} us"
                             if figures[0] else "no answered state")
                    print(f"  {mode:8s} {load:6s}: {shown} ({samples} of {states} states answered)", flush=True)


if __name__ == "__main__":
    main()
