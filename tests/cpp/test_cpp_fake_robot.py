"""The generated fake robot executables (<robot>_fake_robot: src/fake_robot_main.cpp + the robot's
src/<vendor>/<robot>_fake_robot.cpp) build with g++ -Werror against the distros' stand-ins, and, run as a
user runs them, refuse to start where their traffic could reach other hosts (ROS 2 discovery settings; an SDK
network interface other than lo), say how to fix it in one line, answer --help, refuse bad arguments, and
keep running where the traffic stays on this host. Their physics options (--physics, --base) refuse what they do
not know in one line, and --physics mujoco says so in one line where the executable was built without MuJoCo.
Built with MuJoCo (as the package's CMakeLists.txt builds it where it finds MuJoCo), the G1's fake robot moves
its joints under gravity with --physics mujoco, and holds them with the YAML's gains. The benchmark that reports
their rate and jitter runs.

What the fake robot does with the driver (motor maps agree, a trajectory is followed, injected faults get
the driver's documented reaction, the loop allocates nothing) is the driver harness's fake_robot section
(tests/cpp/harness/fake_robot_checks.inc, run by test_cpp_drivers.py in every cell).
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from functools import partial

import pytest
import yaml

from rhi_gen import transports
from rhi_gen.render.fake_robot_views import has_fake_robot
from tests.support import selected, shared_use, vendor_msgs
from tests.support.cpp_build import (
    DISTROS,
    FLAVOURS,
    OVERLAP_WORKERS,
    fake_robot_source,
    label_transport,
    message_variants,
    mujoco_dir,
    mujoco_include_flags,
    project_robot_labels,
    run_concurrently,
    run_parallel,
    yaml_joint_map,
    yaml_modes_and_gains,
)
from tests.support.repo import REPO

RUN_DISTRO = "rolling"  # the executables run once, on the newest API (their logic is the same on every distro)
# ... and compile with -Werror on the distros whose harness does not link the fake robot source (Kilted) or
# whose rclcpp differs most (Humble); Jazzy's and Rolling's harness cells compile it too.
COMPILE_DISTROS = ("humble", "kilted")
CLEAN_ENV = {k: v for k, v in os.environ.items()
             if k not in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_LOCALHOST_ONLY", "ROS_STATIC_PEERS")}


def fake_robot_labels(reference) -> list[str]:
    """Robots with a fake robot, but those compiled against another release of their messages (the native-SDK
    PM01: the same sources as the PM01's, compiled on every distro by test_cpp_engineai_native_sdk.py and run
    in the harness's fake_robot section)."""
    return [b.label for b in reference.builds if has_fake_robot(b.model) and not message_variants(b.label)]


def build_objects(builder, rb, distro: str):
    m = rb.model
    pkg = rb.package_dir
    includes = [pkg / "include", *DISTROS[distro].include_dirs]
    sources = [s for s in (pkg / "src" / "fake_robot_main.cpp", fake_robot_source(pkg, m.vendor, m.robot)) if s]
    # at once: the builder runs one compiler per core however many ask
    objects = run_concurrently([partial(builder.compile, source, FLAVOURS["plain"], includes, package=pkg,
                                        name=f"fakeexe_{source.stem}_{m.vendor}_{m.robot}_{distro}", distro=distro,
                                        transport=m.transport) for source in sources])
    for o in objects:
        assert o.ok, f"{o.path.name}: {' '.join(o.command)}\n{o.stderr[-6000:]}"
    return objects


def build_executable(builder, rb, distro: str):
    objects = build_objects(builder, rb, distro)
    link = builder.link(objects, FLAVOURS["plain"], f"fakeexe_{rb.model.vendor}_{rb.model.robot}_{distro}")
    assert link.ok, link.stderr[-4000:]
    return link.path


def run(binary, *args: str, env: dict[str, str] | None = None, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run([str(binary), *args], capture_output=True, text=True, timeout=timeout,
                          env={**CLEAN_ENV, **(env or {})})


def test_robots_with_a_fake_robot(reference):
    """Every robot whose transport has a fake robot side gets its executable: every transport but custom."""
    labels = fake_robot_labels(reference)
    assert {"unitree/g1", "unitree/go2w", "agibot/x2", "engineai/pm01", "acme/scara"} <= set(labels)
    for b in reference.builds:
        assert (fake_robot_source(b.package_dir, b.model.vendor, b.model.robot) is not None) == has_fake_robot(b.model)
    assert set(labels) <= set(project_robot_labels())


def _buildable(reference):
    """The fake robots whose messages are available here (without ../shared AimDK's are not: the harness
    section skips the X2 for the same reason)."""
    builds = [reference.build(label) for label in fake_robot_labels(reference)]
    return [rb for rb in builds if not vendor_msgs.skip_reason(rb.model.transport)]


@pytest.fixture(scope="module")
def werror_builds(reference, cpp_builder, request) -> dict[str, list[str]]:
    """{distro: why each robot's objects did not build} for the COMPILE_DISTROS the session's selected tests
    name, every robot and distro compiled at once (one compiler per core, busy to the last object)."""
    distros = selected.keep(list(COMPILE_DISTROS), selected.values(request, "distro"))
    jobs = [(rb, distro) for distro in distros for rb in _buildable(reference)]

    def build(job) -> str:
        try:
            build_objects(cpp_builder, *job)
            return ""
        except AssertionError as err:  # that distro's test fails with it
            return str(err)

    problems = run_parallel(jobs, build, OVERLAP_WORKERS)
    return {distro: [p for (_, d), p in zip(jobs, problems, strict=True) if d == distro and p] for distro in distros}


@pytest.mark.parametrize("distro", COMPILE_DISTROS)
def test_fake_robot_sources_compile_with_werror(reference, werror_builds, distro):
    assert _buildable(reference)
    assert not werror_builds[distro], "\n".join(werror_builds[distro])


# Known before anything is rendered (the YAML's transport), so each robot is a test of its own: only the X2's
# read ../shared (its messages), and a fresh clone re-runs only those (tests/support/fresh_clone_selection.py).
EXECUTABLE_LABELS = [label for label in project_robot_labels()
                     if transports.get(label_transport(label)).fake_robot_header and not message_variants(label)]


def test_executable_labels_are_the_robots_with_a_fake_robot(reference):
    assert fake_robot_labels(reference) == EXECUTABLE_LABELS


@pytest.fixture(scope="module")
def executables(reference, cpp_builder, request):
    """{label: its fake robot executable on RUN_DISTRO, or why it did not build} for the robots the session's
    selected tests name, built at once (one compiler per core); each records what it read of ../shared."""
    labels = selected.keep(EXECUTABLE_LABELS, selected.values(request, "label"))

    def build(label: str):
        with shared_use.recording() as used:
            rb = reference.build(label)
            if vendor_msgs.skip_reason(rb.model.transport):
                return None, set(used)
            try:
                return build_executable(cpp_builder, rb, RUN_DISTRO), set(used)
            except AssertionError as err:  # that robot's test fails with it
                return err, set(used)

    return shared_use.Recorded(dict(zip(labels, run_parallel(labels, build, OVERLAP_WORKERS), strict=True)))


@pytest.mark.parametrize("label", EXECUTABLE_LABELS)
def test_fake_robot_executable_guards_the_network(reference, executables, label):
    rb = reference.build(label)
    reason = vendor_msgs.skip_reason(rb.model.transport)
    if reason:
        pytest.skip(reason)
    binary = executables[label]
    if isinstance(binary, AssertionError):
        raise binary
    name = f"{rb.model.robot}_fake_robot"

    helped = run(binary, "--help")
    assert helped.returncode == 0 and "--allow-network" in helped.stdout
    assert f"ros2 param set /{name} fault" in helped.stdout

    sdk = rb.model.transport == "unitree_dds"
    if sdk:  # the SDK on lo: it starts whatever ROS 2 discovery does; another interface is refused
        eth = run(binary, "--network-interface", "eth0")
        assert eth.returncode == 2 and "network interface 'eth0'" in eth.stderr, eth
        assert len(eth.stderr.strip().splitlines()) == 1 and "--allow-network" in eth.stderr
    else:
        refused = run(binary)
        assert refused.returncode == 2, refused
        lines = refused.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"{name}: refusing to start: "), refused.stderr
        assert "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST" in lines[0] and "--allow-network" in lines[0]
        assert "use_fake_robot:=true" in lines[0]
        subnet = run(binary, env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_LOCALHOST_ONLY": "1"})
        assert subnet.returncode == 2 and "ROS_AUTOMATIC_DISCOVERY_RANGE is SUBNET" in subnet.stderr
        peers = run(binary, env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST", "ROS_STATIC_PEERS": "10.0.0.7"})
        assert peers.returncode == 2 and "ROS_STATIC_PEERS" in peers.stderr
        no_interface = run(binary, "--network-interface", "lo", env={"ROS_LOCALHOST_ONLY": "1"})
        assert no_interface.returncode == 2 and "has none" in no_interface.stderr

    # The physics options: one line naming the option and what it takes; this build has no MuJoCo.
    local = {"ROS_LOCALHOST_ONLY": "1"}
    assert "--physics vacuum|mujoco" in helped.stdout and "this build has no MuJoCo" in helped.stdout
    without_mujoco = (f"{name}: --physics mujoco: this robot_hardware_interface was built without MuJoCo: install "
                      "it (pip install mujoco-core, or a MuJoCo release and -DRHI_MUJOCO_ROOT=<its folder>) and "
                      "build the package again")
    refusals = [(("--physics", "bullet"), f"{name}: --physics bullet: expected vacuum or mujoco"),
                (("--physics", "mujoco", "--base", "up"), f"{name}: --base up: expected free, band or fixed"),
                (("--base", "free"), f"{name}: --base is for --physics mujoco only"),
                (("--physics", "mujoco"), without_mujoco)]
    for refused_args, line in refusals:
        refused = run(binary, *refused_args, env=local)
        assert refused.returncode == 2 and refused.stderr.splitlines() == [line], (refused_args, refused)

    bad_rate = run(binary, "--rate", "0", env={"ROS_LOCALHOST_ONLY": "1"})
    assert bad_rate.returncode == 2 and "--rate 0: expected a rate in Hz" in bad_rate.stderr
    unknown = run(binary, "--fast", env={"ROS_LOCALHOST_ONLY": "1"})
    assert unknown.returncode == 2 and "unknown argument '--fast'" in unknown.stderr

    # Discovery on this host (or --allow-network): it starts and spins until stopped.
    starts = [({"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}, ()), ({"ROS_LOCALHOST_ONLY": "1"}, ()),
              ({}, ("--allow-network",)), ({"ROS_LOCALHOST_ONLY": "1"}, ("--ros-args", "-p", "x:=1")),
              ({"ROS_LOCALHOST_ONLY": "1"}, ("--physics", "vacuum"))]
    if sdk:
        starts += [({}, ()), ({}, ("--network-interface", "eth0", "--allow-network"))]
    # all at once: each must still be running half a second later (a refusal exits at once)
    started = [subprocess.Popen([str(binary), *args], env={**CLEAN_ENV, **env}, stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, text=True) for env, args in starts]
    time.sleep(0.5)
    exited = [(starts[i], p.poll(), p) for i, p in enumerate(started)]
    for p in started:
        p.kill()
    for (env, args), code, p in exited:
        _, err = p.communicate()
        assert code is None, f"{name} {args} with {env} exited with {code}: {err}"


# The fake robot on MuJoCo: the G1's generated fake robot (unitree_dds, needs nothing of ../shared), compiled
# with RHI_FAKE_PHYSICS_MUJOCO as the package's CMakeLists.txt compiles it where it finds MuJoCo, chosen onto the
# physics by the executable's own argument parsing and set-up (tests/cpp/physics/fake_robot_physics_check.cpp),
# the installed URDF of the package (urdf/g1.urdf: the skeleton's placeholder inertials, 1 kg per link), its base
# fixed to the world. Bounds, from 1 s at 500 Hz:
PHYSICS_LABEL = "unitree/g1"
PHYSICS_CHECK = REPO / "tests" / "cpp" / "physics" / "fake_robot_physics_check.cpp"
FALLS = 1.0         # [rad] passive: an elbow falls at least this far (measured 2.16)
ARMS_HOLD = 0.2     # [rad] held by the YAML's gains: shoulders, elbows, wrists (measured 0.14, the elbows)
LEGS_HOLD = 0.05    # [rad] and the legs (measured 0.024, the hip pitches at Unitree's kp 100 under the real legs)
# The waist pitch is not held: the YAML's kp 40 N m/rad (unitree_sdk2's g1_ankle_swing) against the placeholder
# torso, arms and head leans it to its 0.52 rad limit, as it does passive.


@pytest.fixture(scope="module")
def physics_check(reference, cpp_builder):
    mj = mujoco_dir()
    assert mj is not None, "MuJoCo is not installed: pip install -e '.[test]' installs mujoco-core (never skipped)"
    libs = sorted(mj.glob("libmujoco.so*"))
    assert libs, f"no libmujoco.so in {mj}"
    rb = reference.build(PHYSICS_LABEL)
    pkg = rb.package_dir
    flags = [*FLAVOURS["plain"], "-DRHI_FAKE_PHYSICS_MUJOCO", *mujoco_include_flags()]
    includes = [pkg / "include", *DISTROS[RUN_DISTRO].include_dirs]
    mujoco_version = libs[-1].name
    fake_robot = fake_robot_source(pkg, rb.model.vendor, rb.model.robot)
    assert fake_robot is not None
    objects = run_concurrently([partial(cpp_builder.compile, source, flags, includes, package=pkg,  # at once
                                        digest_parts=[mujoco_version], name=f"fakephys_{source.stem}",
                                        distro=RUN_DISTRO, transport=rb.model.transport)
                                for source in (PHYSICS_CHECK, fake_robot)])
    for o in objects:
        assert o.ok, f"{o.path.name}: {' '.join(o.command)}\n{o.stderr[-6000:]}"
    link = cpp_builder.link(objects, ["-Wl,--no-as-needed", str(libs[-1]), f"-Wl,-rpath,{mj}"], "fakephys_g1")
    assert link.ok, link.stderr[-4000:]
    return link.path, pkg


def _physics_run(binary, scenario: str, gains, *args: str) -> dict[str, str]:
    yaml_path = REPO / "robots" / "unitree" / "g1.yaml"
    options = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))["transport_options"]
    proc = run(binary, scenario, str(gains), options["lowcmd_topic"], options["lowstate_topic"], *args)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return dict(line.split("=", 1) for line in proc.stdout.splitlines())


def test_fake_robot_on_mujoco_falls_passive_and_holds_with_the_yaml_gains(physics_check, tmp_path, report):
    """--physics mujoco puts the generated fake robot's joints on real physics: passive, its arms fall under
    gravity; held at their start by the YAML's default_gains, they stay; in the vacuum (no option) nothing moves.
    Its LowState_ carries the simulation's IMU."""
    binary, pkg = physics_check
    yaml_path = REPO / "robots" / "unitree" / "g1.yaml"
    _, gains = yaml_modes_and_gains(yaml_path)
    gains_file = tmp_path / "gains"
    gains_file.write_text("".join(f"{slot} {gains[name][0]!r} {gains[name][1]!r}\n"
                                  for name, slot in yaml_joint_map(yaml_path).items()), encoding="utf-8")
    mujoco = ("--physics", "mujoco", "--base", "fixed", "--urdf", str(pkg / "urdf" / "g1.urdf"))
    vacuum = _physics_run(binary, "passive", gains_file)
    passive = _physics_run(binary, "passive", gains_file, *mujoco)
    held = _physics_run(binary, "hold", gains_file, *mujoco)
    assert vacuum["physics"] == "vacuum" and float(vacuum["moved_max"]) == 0.0, vacuum
    assert passive["physics"] == held["physics"] == "mujoco"
    assert float(passive["moved.left_elbow_joint"]) > FALLS, passive
    arms = {k: float(v) for k, v in held.items() if k.startswith("moved.") and any(
        part in k for part in ("shoulder", "elbow", "wrist"))}
    legs = {k: float(v) for k, v in held.items() if k.startswith("moved.") and any(
        part in k for part in ("hip", "knee", "ankle"))}
    assert len(arms) == 14 and len(legs) == 12, held
    assert max(arms.values()) < ARMS_HOLD, arms
    assert max(legs.values()) < LEGS_HOLD, legs
    # The IMU the fake robot publishes is the simulation's: in the vacuum at rest (standard gravity, level);
    # welded upright, MuJoCo's gravity (9.81); with a free base and no gain ever sent, held still in its start
    # pose as on its gantry (fake_physics_mujoco.hpp): level, gravity, nothing moved.
    assert vacuum["imu_acc"].split() == ["0.0000", "0.0000", "9.8067"], vacuum  # float(9.80665)
    assert [round(float(a), 2) for a in held["imu_acc"].split()] == [0.0, 0.0, 9.81], held
    assert held["imu_quat"].split() == ["1.00000", "0.00000", "0.00000", "0.00000"], held
    gantry = _physics_run(binary, "passive", gains_file, *mujoco[:2], "--base", "free", *mujoco[4:])
    assert [round(float(a), 2) for a in gantry["imu_acc"].split()] == [0.0, 0.0, 9.81], gantry
    assert gantry["imu_quat"].split() == ["1.00000", "0.00000", "0.00000", "0.00000"], gantry
    assert float(gantry["moved_max"]) == 0.0, gantry
    report(f"fake robot on MuJoCo (G1, base fixed, 1 s): passive elbow falls "
           f"{float(passive['moved.left_elbow_joint']):.2f} rad; held by the YAML gains: arms within "
           f"{max(arms.values()):.3f} rad, legs within "
           f"{max(legs.values()):.3f} rad; vacuum: {float(vacuum['moved_max']):.1f} rad; IMU z welded "
           f"{float(held['imu_acc'].split()[2]):.2f}, free base waiting for its first gains "
           f"{float(gantry['imu_acc'].split()[2]):.2f} m/s^2")


def test_a_fake_robot_with_a_transmission_gives_the_physics_its_gain_and_offset(tmp_path):
    """No test robot with a fake robot has a transmission: the SCARA (generic_topics) gets one on its elbow, and
    its fake robot source, which then carries kFakeTransmissions for the physics, compiles with -Werror, with
    and without MuJoCo."""
    from tests.support.cpp_build import (
        WARNING_FLAGS,
        load_models,
        make_test_project,
        message_include_flags,
        render_package_to,
        run_compiler,
        standin_flags,
    )

    project = make_test_project(tmp_path / "project", only=["acme/scara"])
    yaml_path = project / "robots" / "acme" / "scara.yaml"
    yaml_path.write_text(yaml_path.read_text(encoding="utf-8") +
                         "transmissions:\n  elbow: {direction: -1, reduction: 2.0, offset: 0.1}\n", encoding="utf-8")
    package = tmp_path / "package"
    render_package_to(load_models(project), package)
    source = package / "src" / "acme" / "scara_fake_robot.cpp"
    text = source.read_text(encoding="utf-8")
    assert "kFakeTransmissions.data()," in text
    assert '  {-2.0, 0.1},  // "elbow"\n' in text and text.count("  {1.0, 0.0},  // ") == 4, text
    run_concurrently([partial(run_compiler, [*WARNING_FLAGS, *extra, "-fsyntax-only", f"-I{package / 'include'}",
                                             *standin_flags(RUN_DISTRO), *message_include_flags("generic_topics"),
                                             str(source)], what=f"scara_fake_robot.cpp {' '.join(extra[:1])}")
                      for extra in ([], ["-DRHI_FAKE_PHYSICS_MUJOCO", *mujoco_include_flags()])])  # both cores


def test_benchmark_reports_rate_and_jitter(tmp_path):
    """benchmarks/bench_fake_robot.py runs (a short loop, the PM01) and reports what docs/benchmarks.md says it does."""
    run = subprocess.run([sys.executable, str(REPO / "benchmarks" / "bench_fake_robot.py"), "--robot", "pm01",
                          "--seconds", "0.3", "--steps", "200"], capture_output=True, text=True, timeout=600,
                         env={**os.environ, "RHI_CPP_CACHE": os.environ.get("RHI_CPP_CACHE") or str(tmp_path)})
    assert run.returncode == 0, run.stderr[-4000:]
    loop = re.search(r"^loop pm01_fake_robot 500 Hz nominal: (\d+) steps, ([\d.]+) Hz achieved, mean \|jitter\| "
                     r"[\d.]+ us", run.stdout, re.M)
    assert loop and int(loop.group(1)) > 0 and float(loop.group(2)) > 0, run.stdout
    assert re.search(r"^step pm01_fake_robot: median \d+ ns, p99 \d+ ns, p99\.9 \d+ ns over 200 steps$", run.stdout,
                     re.M), run.stdout


def test_physics_benchmark_reports_the_real_time_factor(cpp_builder):
    """benchmarks/bench_physics.py builds the PM01's harness with MuJoCo (the suite's own objects: the same keys in
    the session's cache) and reports the real-time factor of physics, driver and controller on one thread."""
    run = subprocess.run([sys.executable, str(REPO / "benchmarks" / "bench_physics.py"), "--robot", "pm01",
                          "--repeat", "1"], capture_output=True, text=True, timeout=900,
                         env={**os.environ, "RHI_CPP_CACHE": str(cpp_builder.cache_dir)})
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    assert re.search(r"^engineai/pm01: physics 1000 Hz, robot 500 Hz, driver \+ controller on the same thread: "
                     r"real-time factor [\d.]+ on the band \(median of 1: [\d.]+\); [\d.]+ standing on its feet, "
                     r"contacts on \(stand; [\d.]+\)$", run.stdout, re.M), run.stdout
