"""Benchmark: the generated drivers' hot paths against their floors, per reference robot.

Run (from the repository root):

    .venv/bin/python benchmarks/bench_hot_paths.py [--iterations N] [--count-iterations N] [--robot g1]
                                                      [--distro jazzy] [--no-callgrind]

It renders the package of the reference robots of robots/ (Unitree G1 unitree_dds, AgiBot X2
agibot_topics, EngineAI PM01 engineai_topics) and the G1 with its Dex3-1 hands (the harness's g1_dex3) into a
temporary folder, compiles
benchmarks/cpp/bench_hot_paths.cpp per robot (-O2, like the harness's `plain` flavour) against the
C++ stand-ins and the real ROS message headers (tests/support/cpp_build.py), and drives each driver's REAL
code through the harness's fake robot (tests/cpp/harness/transport_<transport>.hpp):

* state       the state callback (one complete state frame delivered by the stand-in transport)
* state_dec4  the same with state_decimation = 4 (average per delivered frame)
* writer      one command writer cycle
* health_msg  the motor health callback, where motor health is a message of its own (EngineAI MotorDebug,
              50 Hz or more on the robot; a health frame is kept every 10 ms, so most calls only look at
              the clock)
* readwrite_pos  read() + write() of one controller cycle with a producer thread delivering state, under
                 a position-only claim (each joint's position, or velocity for a wheel: the common case)
* readwrite_all  the same with every command interface claimed
* readwrite_cal  readwrite_all with a calibration_file that offsets every joint: the motors are not the
                 joints, so read() and write() convert between them (the cost of a robot with transmissions;
                 readwrite_all is the same robot without)

with monitoring on (enable_monitor = true), and, in the same binary, the floors over the same
arrays: a memcpy, and the seed template's std::shared_mutex hand-off (the writer takes a unique
lock and copies, the reader a shared lock and copies), and with framework-owned handles the handles'
own locks alone (locks_pos / locks_all: a set_value() on every exported state handle and a
get_optional() on every claimed command handle, the least read() + write() can do through upstream's
API; "x locks" = readwrite instructions / that floor). Per path it prints the latency (median,
p99, p99.9 in ns; steady_clock around each call, its own cost is shown as "clock") and the
instructions per call counted by valgrind's callgrind on a mode of the binary that runs only that
path N times (client requests around the loop; the empty loop's count is subtracted). Without
valgrind the instruction column says "n/a".

The instruction counts are the comparable figures; the nanoseconds are indicative only (shared
machines, frequency scaling). "driver" is callgrind's inclusive cost of the driver's entry point on
the path (the std::function invoker of its SDK handler / subscription callback, its wall timer; all of
read() + write()), so it includes what the driver itself calls (the SDK or rclcpp publish of the
command); "stand-in" = total - driver is the stand-in transport's dispatch around it (registry
look-up, the copy of the message it keeps). "x memcpy" = instructions / the memcpy floor.

A robot whose vendor message definitions are not available here (AgiBot X2 without ../shared: the
AimDK messages are not carried in the repository, tests/support/vendor_msgs.py) is skipped with one line saying
why and how to provide them; the others are measured.

--distro (repeatable; default humble, jazzy and rolling) picks the ros2_control stand-ins the driver is
compiled against (tests/cpp/standins; docs/benchmarks.md). It changes only read() + write(): with humble
(hardware_interface 2.x) the exported interfaces point at the driver's own doubles, so read() + write()
touch nothing else; with jazzy (4.x, 4.34+), kilted (5.x) and rolling (6.x, also Lyrical) the framework
owns the handles, so read() ends by copying every state value into its handle and write() starts by
fetching every claimed command from its handle (each handle's lock taken without blocking). `state`,
`state_dec4` and `writer` are the transport side and the same code on every distro: they are measured on
the first distro only; the others add their readwrite and locks rows.

Environment: RHI_CPP_CACHE=<dir> keeps compiled objects between runs (tests/support/cpp_build.py); RHI_UPSTREAM
as for the tests (tests/support/vendor_msgs.py).
"""
from __future__ import annotations

import argparse
import hashlib
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from tests.support import cpp_build, vendor_msgs  # noqa: E402

BENCH_SOURCE = REPO / "benchmarks" / "cpp" / "bench_hot_paths.cpp"
# The G1 with its Dex3-1 hands (hands: dex3) is the harness's test robot tests/cpp/harness/robots/unitree/g1_dex3:
# its state path also carries both hands' HandState_, its writer both HandCmd_.
ROBOTS = ("unitree/g1", "unitree/g1_dex3", "agibot/x2", "engineai/pm01")
HARNESS_ROBOTS = ("unitree/g1_dex3", "unitree/g1_upper_body")  # tests/cpp/harness/robots/, not robots/
# Measured only when asked for (--robot g1_upper_body): the harness's test robot under authority upper_body
# (tests/cpp/harness/robots/unitree/), whose writer also steps the arm SDK's blend weight.
ON_REQUEST = ("unitree/g1_upper_body",)
TRANSPORT_OF = {"unitree/g1": "unitree_dds", "agibot/x2": "agibot_topics", "engineai/pm01": "engineai_topics",
                "unitree/g1_upper_body": "unitree_dds", "unitree/g1_dex3": "unitree_dds"}
DRIVER_PATHS = ("state", "state_dec4", "health_msg", "writer", "readwrite_pos", "readwrite_all", "readwrite_cal")
READWRITE_PATHS = ("readwrite_pos", "readwrite_all", "readwrite_cal")
FLOOR_OF = {"state": "state", "state_dec4": "state", "health_msg": "state", "writer": "writer",
            "readwrite_pos": "readwrite", "readwrite_all": "readwrite", "readwrite_cal": "readwrite"}
LOCKS_OF = {"readwrite_pos": "locks_pos", "readwrite_all": "locks_all", "readwrite_cal": "locks_all"}
DEFAULT_DISTROS = ("humble", "jazzy", "rolling")
FLAGS = ("-O2", "-g")  # -g: function names for callgrind's per-function figures; code is the same


def build(builder: cpp_build.CppBuilder, rb: cpp_build.RobotBuild, distro: str) -> Path:
    m = rb.model
    standins = cpp_build.DISTROS[distro].include_dirs
    pkg_include = rb.package_dir / "include"
    tag = f"{m.vendor}_{m.robot}_{distro}"
    # at once: the builder runs one compiler per core, so one robot's benchmark compiles on both cores
    driver, bench = cpp_build.run_concurrently([
        lambda: builder.compile(cpp_build.driver_source(rb.package_dir, m.vendor, m.robot), FLAGS,
                                [pkg_include, *standins], package=rb.package_dir,
                                name=f"bench_driver_{tag}", distro=distro, transport=m.transport),
        lambda: builder.compile(BENCH_SOURCE, FLAGS, [rb.data_dir, cpp_build.HARNESS_DIR, *standins],
                                digest_parts=[rb.data_header, builder._harness], name=f"bench_{tag}",
                                distro=distro, transport=m.transport)])
    for step in (driver, bench):
        if not step.ok:
            sys.exit(f"compiling {step.command[-3:]} failed:\n{step.stderr[:4000]}")
    linked = builder.link([driver, bench], FLAGS, f"bench_{tag}")
    if not linked.ok:
        sys.exit(f"linking the {rb.label} benchmark failed:\n{linked.stderr[:4000]}")
    return linked.path


def run_times(binary: Path, iterations: int, paths: tuple[str, ...] = ()) -> dict[str, dict[str, int]]:
    out = subprocess.run([str(binary), "time", str(iterations), *paths], capture_output=True, text=True,
                         check=True, env=cpp_build.ENV_C).stdout
    times = {}
    for name, med, p99, p999, mx in re.findall(
            r"^time (\S+) median (-?\d+) p99 (-?\d+) p99\.9 (-?\d+) max (-?\d+)$", out, re.M):
        times[name] = {"median": int(med), "p99": int(p99), "p99.9": int(p999), "max": int(mx)}
    return times


# The driver's entry points on a path: the std::function invoker of a driver lambda (SDK handler,
# subscription callback, wall timer) or the transport's callback itself. Their inclusive cost is the
# driver's share; the rest of a path is the stand-in transport (dispatch, the copy it keeps, ...).
DRIVER_ENTRY = re.compile(
    r"^std::_Function_handler<[^,]*, robot_hardware_interface::"
    r"|^rclcpp::GenericTimer<robot_hardware_interface::.*>::execute_callback\("
    r"|^robot_hardware_interface::.*::(on_low_state|on_group_state|on_joint_state|on_motor_debug|write_command)\(")


def callgrind(binary: Path, path: str, iterations: int, work: Path) -> tuple[float, dict[str, int]]:
    """Instructions per call of ``path`` (the instrumented loop), and inclusive Ir of functions."""
    out = work / f"cg.{binary.name}.{path}"
    for old in work.glob(out.name + "*"):
        old.unlink()
    subprocess.run(["valgrind", "--tool=callgrind", "--instr-atstart=no", "--separate-threads=yes",
                    f"--callgrind-out-file={out}.%p", str(binary), "count", path, str(iterations)],
                   capture_output=True, text=True, check=True, env=cpp_build.ENV_C)
    # The dump of the measured loop is the one carrying the path's name; thread 1 runs the loop.
    trigger = f"Trigger: Client Request: {path}\n"
    dumps = [p for p in work.glob(out.name + ".*") if trigger in p.read_text(errors="replace")]
    main = [p for p in dumps if p.name.endswith("-01")] or dumps
    if not main:
        raise RuntimeError(f"no callgrind dump for {path} of {binary.name}")
    text = main[0].read_text(errors="replace")
    summary = re.search(r"^(?:summary|totals): (\d+)", text, re.M)
    if summary is None:
        raise RuntimeError(f"no summary line in the callgrind dump {main[0]}")
    total = int(summary.group(1))
    inclusive: dict[str, int] = {}
    if shutil.which("callgrind_annotate"):
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", str(main[0])],
                             capture_output=True, text=True, env=cpp_build.ENV_C).stdout
        for count, fn in re.findall(r"^\s*([\d,]+) \([^)]*\)\s+[^:\s]*:(.*?)(?: \[.*\])?$", ann, re.M):
            inclusive[fn.strip()] = max(inclusive.get(fn.strip(), 0), int(count.replace(",", "")))
    return total / iterations, inclusive


def driver_share(inclusive: dict[str, int]) -> int:
    """Inclusive Ir of the outermost driver entry point (they nest: invoker -> callback)."""
    return max((n for fn, n in inclusive.items() if DRIVER_ENTRY.search(fn)), default=0)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--iterations", type=int, default=200_000, help="timed calls per path")
    ap.add_argument("--count-iterations", type=int, default=2_000, help="calls per path under callgrind")
    ap.add_argument("--robot", action="append",
                    help="only this robot (g1, g1_dex3, x2, pm01; g1_upper_body only when named); repeatable")
    ap.add_argument("--distro", action="append", choices=sorted(cpp_build.DISTROS),
                    help="the ros2_control stand-ins compiled against (repeatable; default humble, jazzy, rolling); "
                         "changes read() + write() only (see the docstring)")
    ap.add_argument("--no-callgrind", action="store_true", help="latency only")
    args = ap.parse_args()

    robots = [r for r in ROBOTS if not args.robot or r.split("/")[1] in args.robot]
    robots += [r for r in ON_REQUEST if args.robot and r.split("/")[1] in args.robot]
    known = {r.split("/")[1] for r in (*ROBOTS, *ON_REQUEST)}
    unknown = sorted(set(args.robot or ()) - known)
    if unknown:
        ap.error(f"unknown --robot {', '.join(unknown)} (choose from {', '.join(sorted(known))})")
    for label in list(robots):
        reason = vendor_msgs.skip_reason(TRANSPORT_OF[label])
        if reason:
            print(f"skipped {label}: {reason}", flush=True)
            robots.remove(label)
    if not robots:
        sys.exit("nothing to measure: every robot asked for was skipped (see above)")
    have_valgrind = shutil.which("valgrind") is not None and not args.no_callgrind
    cache = Path(os.environ.get("RHI_CPP_CACHE") or Path(tempfile.gettempdir()) / "rhi_bench_cache")
    builder = cpp_build.CppBuilder(cache)
    with tempfile.TemporaryDirectory(prefix="rhi_bench_") as tmp:
        root = Path(tmp)
        print(f"rendering {', '.join(robots)} into {root} ...", flush=True)
        package = cpp_build.render_test_package(root, only=robots,
                                                extra_robots=any(r in HARNESS_ROBOTS for r in robots))
        digest = hashlib.sha256(BENCH_SOURCE.read_bytes()).hexdigest()[:12]
        distros = list(dict.fromkeys(args.distro or DEFAULT_DISTROS))
        print(f"compiling with {' '.join(FLAGS)} against the {', '.join(distros)} stand-ins (bench source "
              f"{digest}) ...", flush=True)
        jobs = [(label, distro) for label in robots for distro in distros]
        binaries = cpp_build.run_parallel(jobs, lambda job: build(builder, package.build(job[0]), job[1]))
        for (label, distro), binary in zip(jobs, binaries, strict=True):
            report(label, distro, binary, args, have_valgrind, root, full=distro == distros[0])


def report(label: str, distro: str, binary: Path, args, have_valgrind: bool, work: Path, full: bool) -> None:
    """The table of one robot on one distro; ``full``: the transport paths too (the same on every distro)."""
    driver_paths: tuple[str, ...] = DRIVER_PATHS if full else READWRITE_PATHS
    floors = [f"{k}_{f}" for k in ("memcpy", "shmutex") for f in ("state", "writer", "readwrite")]
    floors = [*(floors if full else ["memcpy_readwrite", "shmutex_readwrite"]), "locks_pos", "locks_all"]
    times = run_times(binary, args.iterations, () if full else (*driver_paths, *floors))
    driver_paths = tuple(path for path in driver_paths if path in times)  # health_msg: EngineAI only
    instr: dict[str, float] = {}
    driver: dict[str, float] = {}
    if have_valgrind:
        noop, _ = callgrind(binary, "noop", args.count_iterations, work)
        for path in (*driver_paths, *floors):
            per_call, inclusive = callgrind(binary, path, args.count_iterations, work)
            instr[path] = per_call - noop
            if path in driver_paths:
                driver[path] = driver_share(inclusive) / args.count_iterations

    def ins(path: str) -> str:
        return f"{instr[path]:,.0f}" if path in instr else "n/a"

    clock = times.get("clock", {}).get("median", 0)
    print(f"\n== {label} on {distro}  (ns: indicative, steady_clock around each call, its own cost ~{clock} ns "
          f"included; instructions: callgrind, per call)")
    head = (f"{'path':<20}{'median':>8}{'p99':>8}{'p99.9':>9}{'instr':>10}{'stand-in':>10}{'driver':>9}"
            f"{'memcpy':>8}{'shmutex':>9}{'x memcpy':>9}{'locks':>8}{'x locks':>8}")
    print(head)
    print("-" * len(head))
    for path in driver_paths:
        t = times[path]
        floor = FLOOR_OF[path]
        mem, shm = f"memcpy_{floor}", f"shmutex_{floor}"
        ratio = f"{instr[path] / instr[mem]:.1f}" if path in instr and instr.get(mem, 0) > 0 else "n/a"
        if path in READWRITE_PATHS and path in instr:  # read() and write() are the driver's own
            driver[path] = instr[path]
        drv = f"{driver[path]:,.0f}" if path in driver else "n/a"
        si = f"{instr[path] - driver[path]:,.0f}" if path in driver else "n/a"
        locks = LOCKS_OF.get(path, "")
        has_locks = path in instr and instr.get(locks, 0) >= 1  # Humble: no handle locks to compare with
        lock_ratio = f"{instr[path] / instr[locks]:.2f}" if has_locks else ""
        print(f"{path:<20}{t['median']:>8}{t['p99']:>8}{t['p99.9']:>9}{ins(path):>10}{si:>10}{drv:>9}"
              f"{ins(mem):>8}{ins(shm):>9}{ratio:>9}{(ins(locks) if has_locks else ''):>8}{lock_ratio:>8}")
    for path in floors:
        t = times[path]
        print(f"{path:<20}{t['median']:>8}{t['p99']:>8}{t['p99.9']:>9}{ins(path):>10}")
    sys.stdout.flush()


if __name__ == "__main__":
    main()
