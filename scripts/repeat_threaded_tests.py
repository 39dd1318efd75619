"""Run the threaded C++ test binaries N times in a row: a flaky threaded test is a broken one.

Builds, under TSan against the Rolling stand-ins, the driver harness of G1, X2 and the custom Solo-12
(its threaded scenario only, --only=threads) and the DataBuffer stress test, then runs each N times
(default 200) and prints the count that passed; any failure prints its output. Run it while something
else keeps the cores busy (e.g. the test suite) to check behaviour under load:

    .venv/bin/python scripts/repeat_threaded_tests.py [N]
"""
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.support.cpp_build import CppBuilder, build_harness, compile_data_buffer_stress, render_test_package

N = int(sys.argv[1]) if len(sys.argv) > 1 else 200
root = Path(tempfile.mkdtemp(prefix="rhi_repeat_"))
labels = ["unitree/g1", "agibot/x2", "odri/solo12"]
pkg = render_test_package(root, only=labels)
b = CppBuilder(root / "cache")
bins = []
for label in labels:
    link, steps = build_harness(b, pkg.build(label), "tsan", distro="rolling")
    assert link.ok, (label, [s.stderr[:2000] for s in steps if not s.ok], link.stderr[:2000])
    bins.append((f"{label} rolling tsan --only=threads", [str(link.path), "--only=threads", "--threads-ms=100"]))
db = compile_data_buffer_stress(b, pkg.package_dir, "tsan")
assert db.ok, db.stderr[:2000]
bins.append(("data_buffer_stress tsan", [str(db.path)]))
for name, cmd in bins:
    fails = 0
    t = time.time()
    for i in range(N):
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        bad = p.returncode != 0 or "WARNING: ThreadSanitizer" in p.stderr
        if bad:
            fails += 1
            print("FAIL", name, i, p.stdout[-500:], p.stderr[-1500:], flush=True)
    print(f"{name}: {N - fails}/{N} runs passed ({time.time() - t:.0f}s)", flush=True)
shutil.rmtree(root, ignore_errors=True)
