"""Run driver harness cells N times in a row, optionally beside busy processes: a check that fails on a busy
machine judges the machine's speed, not the driver (issue 48, docs/testing.md "Timing").

Builds each cell (robot, distro, flavour) as tests/cpp/test_cpp_drivers.py does (the objects cached in
RHI_CPP_CACHE when set), then runs its binary N times with the test's arguments, beside ``--load`` busy
processes per core (tests/support/load.py) if asked, and prints per cell the runs that passed and the
figures the sections print (tracking errors, fault times, the on_write latency, runs not judged):

    .venv/bin/python scripts/repeat_harness_cells.py --load 3 -n 5 acme/scara:rolling:tsan \\
        engineai/pm01_native_sdk:rolling:tsan unitree/g1:jazzy:plain [--only=fake_robot,health]
"""
import argparse
import os
import re
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.support import load
from tests.support.cpp_build import (
    CppBuilder,
    build_harness,
    physics_arguments,
    physics_robot,
    render_test_package,
    run_binary_retrying,
)

# Lines of the harness's output worth reading across runs: figures, and the checks a stall left unjudged.
FIGURES = re.compile(r"^(fake robot: worst|faults: read\(\) ERROR|on_write: a command reached|on_write rate limit"
                     r"|.*not judged|physics band\.rtf)")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cells", nargs="+", help="robot:distro:flavour, e.g. acme/scara:rolling:tsan")
    parser.add_argument("-n", type=int, default=5, help="runs per cell (5)")
    parser.add_argument("--load", type=int, default=0, help="busy processes per core beside the runs (0)")
    parser.add_argument("--only", default="", help="the harness's --only=<sections> (all by default)")
    args = parser.parse_args()
    cells = [tuple(c.split(":")) for c in args.cells]
    root = Path(tempfile.mkdtemp(prefix="rhi_repeat_cells_"))
    try:
        pkg = render_test_package(root, only=sorted({c[0] for c in cells}))
        builder = CppBuilder(Path(os.environ.get("RHI_CPP_CACHE") or root / "cache"))
        runs = []
        for label, distro, flavour in cells:
            rb = pkg.build(label)
            physics = physics_robot(label, distro, flavour)
            link, steps = build_harness(builder, rb, flavour, distro=distro, physics=physics is not None)
            if not link.ok:
                print(f"{label} {distro} {flavour}: did not build\n{link.stderr[:2000]}",
                      *(s.stderr[:2000] for s in steps if not s.ok), sep="\n")
                return 1
            extra = [f"--only={args.only}"] if args.only else []
            runs.append((f"{label} {distro} {flavour}", [str(link.path), "--threads-ms=300", *extra,
                                                         *(physics_arguments(rb, physics) if physics else [])]))
        spinners = load.Load(args.load * load.cores())
        spinners.start()
        try:
            print(f"{spinners.running()} busy processes beside the runs ({args.load} per core)", flush=True)
            failed = 0
            for name, cmd in runs:
                passed = 0
                start = time.monotonic()
                for i in range(args.n):
                    run = run_binary_retrying(Path(cmd[0]), cmd[1:])
                    ok = run.returncode == 0 and run.failed == 0 and run.passed > 0 and not run.sanitizer_reports()
                    passed += ok
                    for line in run.stdout.splitlines():
                        if FIGURES.match(line):
                            print(f"  {name} run {i + 1}: {line}")
                    if not ok:
                        print(f"FAIL {name} run {i + 1}:\n{run.describe()}", flush=True)
                print(f"{name}: {passed}/{args.n} runs passed ({time.monotonic() - start:.0f} s)", flush=True)
                failed += args.n - passed
        finally:
            spinners.stop()
        return 1 if failed else 0
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
