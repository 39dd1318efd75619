"""Benchmark: how long the generator takes on the reference robots and on a very large URDF.

Run: .venv/bin/python benchmarks/bench_generate.py   (figures go to the closing notes, not to tests)
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from rhi_gen.inputs.urdf_loader import parse_urdf_bytes  # noqa: E402
from rhi_gen.pipeline.generate import plan_generation  # noqa: E402
from rhi_gen.pipeline.load import load_robots  # noqa: E402
from rhi_gen.project import Project  # noqa: E402


def timed(fn, repeat: int = 5) -> tuple[float, float]:
    runs = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        runs.append(time.perf_counter() - start)
    return statistics.median(runs), min(runs)


def big_urdf(joints: int) -> bytes:
    parts = ['<robot name="big">', '<link name="l0"/>']
    for i in range(1, joints + 1):
        parts.append(f'<link name="l{i}"/><joint name="j{i}" type="revolute"><parent link="l{i-1}"/>'
                     f'<child link="l{i}"/><axis xyz="0 0 1"/>'
                     f'<limit lower="-1" upper="1" effort="10" velocity="2"/></joint>')
    parts.append("</robot>")
    return "".join(parts).encode()


def main() -> None:
    project = Project(REPO)
    med, best = timed(lambda: plan_generation(project, load_robots(project)))
    print(f"load + render + compare, 3 reference robots: median {med*1000:.0f} ms (best {best*1000:.0f} ms)")

    tracemalloc.start()
    plan_generation(project, load_robots(project))
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    print(f"peak Python memory for that: {peak/1e6:.1f} MB")

    exe = Path(sys.executable).with_name("rhi-gen")
    med, best = timed(lambda: subprocess.run([str(exe), "check", "--project", str(REPO)], check=True,
                                             capture_output=True), repeat=3)
    print(f"`rhi-gen check` end to end (process start included): median {med*1000:.0f} ms")

    for n in (1000, 5000):
        xml = big_urdf(n)
        med, _ = timed(lambda xml=xml: parse_urdf_bytes(xml, source="big.urdf"), repeat=3)
        print(f"parse a {n}-joint URDF ({len(xml)/1e6:.2f} MB): median {med*1000:.0f} ms")

    # 1200 joints: the size tests/cli/test_hostile_inputs.py::test_large_urdf_generates_and_compiles generates
    # (the test asserts that it generates and compiles; how long it takes is this figure)
    for n in (1000, 1200):
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "big.urdf"
            urdf.write_bytes(big_urdf(n))
            start = time.perf_counter()
            subprocess.run([str(exe), "new", "--vendor", "acme", "--robot", "big", "--urdf", str(urdf),
                            "--project", tmp], check=True, capture_output=True)
            print(f"`rhi-gen new` on a {n}-joint URDF (generic transport): "
                  f"{(time.perf_counter()-start)*1000:.0f} ms")


if __name__ == "__main__":
    main()
