"""benchmarks/bench_latency.py (issue 37): the closed-loop latency from a state on the wire to the command that
answers it, per mode (timer, on_write), next to its floor. Figures are never asserted; what is: the benchmark
builds and runs, each mode reports a distribution over the states it answered, and the floor (each state
answered from its callback, one thread) answers every state it sent, as only a working probe can.
"""
from __future__ import annotations

import os
import re
import subprocess
import sys

from tests.support.repo import REPO

LINE = re.compile(r"^  (timer|on_write|floor) +(idle|loaded) *: median ([\d.]+) us, p99 ([\d.]+) us, "
                  r"p99\.9 ([\d.]+) us, max ([\d.]+) us \((\d+) of (\d+) states answered\)$", re.M)


def test_latency_benchmark_reports_each_mode_next_to_its_floor(cpp_builder, report):
    run = subprocess.run([sys.executable, str(REPO / "benchmarks" / "bench_latency.py"), "--robot", "pm01",
                          "--seconds", "0.5"], capture_output=True, text=True, timeout=900,
                         env={**os.environ, "RHI_CPP_CACHE": str(cpp_builder.cache_dir)})
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    assert "== engineai/pm01 on jazzy: states 500 Hz, update_rate 500 Hz, command_writer_period_us 2000" in run.stdout
    rows = {(m[0], m[1]): m for m in LINE.findall(run.stdout)}
    assert set(rows) == {(mode, load) for mode in ("timer", "on_write", "floor") for load in ("idle", "loaded")}, \
        run.stdout
    for (mode, load), (_, _, median, p99, p999, worst, answered, states) in rows.items():
        assert int(answered) > 0 and float(median) <= float(p99) <= float(p999) <= float(worst), (mode, load)
        if mode == "floor":
            assert answered == states, f"the floor left states unanswered ({load}): {run.stdout}"
    report("latency (PM01, 0.5 s, stand-ins): " + "; ".join(
        f"{mode} {load} median {row[2]} us p99 {row[3]} us" for (mode, load), row in sorted(rows.items())))
