"""Every generated driver compiles with g++ -Werror and runs correctly against a simulated robot.

For every robot of robots/ (and the harness's test-only generic_topics robot, tests/cpp/harness/robots/)
the package is rendered into a temporary folder, then:

* each robot's driver header compiles on its own, twice included, with -std=c++17 -Wall -Wextra
  -Wpedantic -Werror (the shared headers are checked the same way where they live:
  tests/cpp/test_cpp_sources.py);
* the ros2_control description, expanded by xacro as a user includes it, lists exactly the YAML's
  mapped joints with their interfaces, the IMU sensor, and a plugin the plugin descriptor exports;
* the driver and the harness (through rhi_fake/hw.hpp) are compiled against every distro's stand-ins
  (MATRIX: plain -O2 on Humble, Jazzy, Kilted and Rolling/Lyrical; TSan on Humble, raw-pointer
  interfaces, for one robot per transport thread kind; ASan+UBSan and TSan on Rolling,
  framework-owned handles; on Kilted the driver object alone; a feature robot of the harness, one that sets
  authority, hands or take_control, skips plain Rolling) with -Werror and linked into
  tests/cpp/harness/driver_harness.cpp, which creates it through pluginlib's registry and checks, per
  section: interfaces, transmission (the robot's motors that are not joints, with a calibration_file on
  top, state and commands through the whole transport; broken calibration files refused in one line),
  safety (the three layers, re-armed on re-activation), joint_map, imu, commands
  (slots and float type; CRC, mode_pr, mode_machine for unitree), command_safety, crc (unitree:
  SDK_FACTS.md vectors, every field, bad frames dropped), parameters (description values, defaults,
  overrides, invalid values), decimation, faults (a dead link: read() OK while held, ERROR after
  fault_timeout_ms, one error line, on_error keeps the hold, configure + activate pass the safe start;
  a robot that never answers faults after first_state_timeout_ms, a first state later than
  fault_timeout_ms does not), allocations (zero in read/write/callbacks/writer after
  warm-up), threads (real writer/executor threads, no torn frames) and, Jazzy and later, async
  (read()/write() on a thread of their own as an is_async component's, claims switched meanwhile);
* sanitizer runs must print no report.

The checks are counted by the harness; scripts/cpp_report.py prints the counts per robot, flavour and
section, the sanitizer and allocation results and the timings (the tests assert them).
A missing g++ fails these tests (never a skip).
"""
from __future__ import annotations

import re
import subprocess
from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

import pytest

from rhi_gen.render.fake_robot_views import has_fake_robot
from tests.support import selected, shared_use, vendor_msgs
from tests.support.cpp_build import (
    HARNESS_ROBOTS,
    OVERLAP_WORKERS,
    PACKAGE,
    PHYSICS_CELL,
    WARNING_FLAGS,
    HarnessRun,
    build_driver_object,
    build_harness,
    expand_description,
    label_yaml,
    message_include_flags,
    message_variants,
    physics_arguments,
    physics_robot,
    project_robot_labels,
    render_test_package,
    require_compiler,
    run_binary_retrying,
    run_parallel,
    standin_flags,
    yaml_arm_sdk,
    yaml_hands,
    yaml_take_control,
)
from tests.support.description_checks import check_ros2_control
from tests.support.repo import REPO

ROBOTS = project_robot_labels()
SECTION_ORDER = ("interfaces", "transmission", "safety", "joint_map", "imu", "commands", "command_safety",
                 "command_modes",
                 "crc", "parameters", "decimation", "faults", "allocations", "threads")
THREADS_MS = 300
# (distro, flavour) of every build. RUN cells build the harness and drive the robot: plain on Humble
# (2.x: interfaces over driver-owned doubles), Jazzy (4.x) and Rolling (6.x: framework-owned handles,
# the path of Kilted and Lyrical too), the sanitizers on Rolling. COMPILE cells build the driver
# object alone (-Werror against Kilted's stand-ins: deprecations, removed API), since its runtime
# path is Jazzy's and Rolling's. TSan also runs on Humble's path, for one robot per kind of transport thread
# (an SDK recurrent thread, a ROS executor): that path is the same code for every robot.
RUN_MATRIX = (("humble", "plain"), ("humble", "tsan"), ("jazzy", "plain"), ("rolling", "plain"),
              ("rolling", "asan_ubsan"), ("rolling", "tsan"))
COMPILE_MATRIX = (("kilted", "plain"),)
MATRIX = RUN_MATRIX + COMPILE_MATRIX
# cells not built for every robot; the native-SDK PM01 runs in every cell: its error codes and offline motors
# are the only ones that arrive in a MotorDebug of their own
ONLY = {("humble", "tsan"): {"unitree/g1", "agibot/x2", "engineai/pm01_native_sdk"}}
# A feature robot (a harness test robot that sets authority, hands or take_control) shares every code path but
# its feature with a reference robot: it skips plain Rolling, whose path its Rolling sanitizer cells run too.
FEATURE_SKIPS = (("rolling", "plain"),)


def is_feature_robot(label: str) -> bool:
    yaml_path = label_yaml(label)
    return yaml_path.is_relative_to(HARNESS_ROBOTS) and (
        yaml_arm_sdk(yaml_path) is not None or yaml_hands(yaml_path) != "none" or yaml_take_control(yaml_path))


def in_cell(label: str, distro: str, flavour: str) -> bool:
    if (distro, flavour) in FEATURE_SKIPS and is_feature_robot(label):
        return False
    return label in ONLY.get((distro, flavour), {label})


DISTRO = "humble"  # what the headers-alone checks compile against

def build_and_run_cells(reference, builder, labels: set[str] | None = None
                        ) -> tuple[shared_use.Recorded, shared_use.Recorded]:
    """({(robot, distro, flavour): (link result, [compile results])}, {same key: HarnessRun} for every RUN cell
    that linked), for the robots ``labels`` (None: all). Each cell is built, then run, by one of OVERLAP_WORKERS
    threads: the builder keeps the compilers to one per core, and a run (which mostly waits on its timers)
    overlaps the next compiles. Each cell records what it read of ../shared (only the X2's:
    tests/support/shared_use.py)."""
    jobs = [(b, distro, flavour) for b in selected.keep(reference.builds, labels, key=lambda b: b.label)
            for distro, flavour in MATRIX if in_cell(b.label, distro, flavour)]
    # the sanitizer cells first (the slowest compiles and runs), the driver objects alone last: the cells still
    # building at the end are small ones, and both cores stay busy to the end
    jobs.sort(key=lambda job: (job[2] == "plain", (job[1], job[2]) in COMPILE_MATRIX))

    def build_and_run(job):
        b, distro, flavour = job
        with shared_use.recording() as used:
            if vendor_msgs.skip_reason(b.model.transport):
                return None, None, set(used)
            if (distro, flavour) in COMPILE_MATRIX:
                return build_driver_object(builder, b, flavour, distro=distro), None, set(used)
            physics = physics_robot(b.label, distro, flavour)
            built = build_harness(builder, b, flavour, distro=distro, physics=physics is not None)
            args = [f"--threads-ms={THREADS_MS}", *(physics_arguments(b, physics) if physics else [])]
            run = run_binary_retrying(built[0].path, args) if built[0].ok else None
            return built, run, set(used)

    results = dict(zip(((b.label, d, f) for b, d, f in jobs), run_parallel(jobs, build_and_run, OVERLAP_WORKERS),
                       strict=True))
    binaries = {key: (built, used) for key, (built, _, used) in results.items() if built is not None}
    runs = {key: (run, used) for key, (_, run, used) in results.items() if run is not None}
    return shared_use.Recorded(binaries), shared_use.Recorded(runs)


@pytest.fixture(scope="module")
def harness_cells(reference, cpp_builder, request):
    """Every cell of the robots the session's selected tests name (all of them in a whole run)."""
    return build_and_run_cells(reference, cpp_builder, selected.values(request, "label"))


@pytest.fixture(scope="module")
def harness_binaries(harness_cells):
    return harness_cells[0]


@pytest.fixture(scope="module")
def harness_runs(harness_cells):
    return harness_cells[1]


def _robot(reference, label):
    return reference.build(label)


def _compilable_robot(reference, label):
    """The robot, or a skip when its transport's vendor messages cannot be generated (no ../shared)."""
    b = reference.build(label)
    reason = vendor_msgs.skip_reason(b.model.transport)
    if reason:
        pytest.skip(reason)
    return b


# ------------------------------------------------------------------------------------ coverage
def test_every_robot_of_the_project_gets_a_harness(reference):
    """robots/ as it is on disk (so a robot a user adds is covered), plus the test-only robots."""
    assert [b.label for b in reference.builds] == ROBOTS
    for label in ("unitree/g1", "agibot/x2", "engineai/pm01"):
        assert label in ROBOTS, f"reference robot {label} is missing from robots/"
    transports = {b.model.transport for b in reference.builds}
    assert transports == {"unitree_dds", "agibot_topics", "engineai_topics", "generic_topics", "custom"}, transports


# ------------------------------------------------------------------------------------ headers alone
# The shared headers compile alone where they live (tests/cpp/test_cpp_sources.py); the package holds
# them byte for byte (tests/unit/render/test_static_files.py). The robot's own header is checked here.
@pytest.mark.parametrize("label", ROBOTS)
def test_driver_header_compiles_on_its_own(reference, label, tmp_path):
    cxx = require_compiler()
    b = _compilable_robot(reference, label)
    rel = f"{PACKAGE}/{b.model.vendor}/{b.model.robot}.hpp"
    src = tmp_path / "alone.cpp"
    src.write_text(f'#include "{rel}"\n#include "{rel}"\nint main() {{ return 0; }}\n')
    proc = subprocess.run([cxx, *WARNING_FLAGS, "-fsyntax-only",
                           f"-I{reference.package_dir / 'include'}", *standin_flags(DISTRO),
                           *message_include_flags(b.model.transport), str(src)], capture_output=True, text=True)
    assert proc.returncode == 0, f"{rel} does not compile on its own:\n{proc.stderr[:4000]}"


# ------------------------------------------------------------------------------------ description
@pytest.mark.parametrize("label", ROBOTS)
def test_description_lists_exactly_the_mapped_joints(reference, label, tmp_path):
    b = _robot(reference, label)
    d = expand_description(reference.package_dir, b.model.robot, tmp_path)
    check_ros2_control(d, b.model, b.loaded.yaml_path, reference.package_dir)


# ------------------------------------------------------------------------------------ compile
COMPILE_CELLS = [(label, d, f) for label in ROBOTS for d, f in MATRIX if in_cell(label, d, f)]
RUN_CELLS = [(label, d, f) for label, d, f in COMPILE_CELLS if (d, f) in RUN_MATRIX]


@pytest.mark.parametrize(("label", "distro", "flavour"), COMPILE_CELLS,
                         ids=[f"{label}-{d}-{f}" for label, d, f in COMPILE_CELLS])
def test_driver_compiles_with_werror(harness_binaries, reference, label, distro, flavour):
    """-Wall -Wextra -Wpedantic -Werror on each distro: deprecated declarations are errors."""
    _compilable_robot(reference, label)
    link, steps = harness_binaries[(label, distro, flavour)]
    driver = steps[0]
    assert driver.ok, (f"{label} driver does not compile ({distro}, {flavour}, -Werror):\n"
                       f"{' '.join(driver.command)}\n{driver.stderr[:6000]}")
    for step in steps[1:]:
        assert step.ok, f"{label} harness part does not compile ({distro}, {flavour}):\n{step.stderr[:6000]}"
    assert link.ok, f"{label} harness does not link ({distro}, {flavour}):\n{link.stderr[:6000]}"


# ------------------------------------------------------------------------------------ run
@pytest.mark.parametrize(("label", "distro", "flavour"), RUN_CELLS,
                         ids=[f"{label}-{d}-{f}" for label, d, f in RUN_CELLS])
def test_driver_against_simulated_robot(harness_runs, harness_binaries, reference, label, distro, flavour):
    _compilable_robot(reference, label)
    link, _ = harness_binaries[(label, distro, flavour)]
    assert link.ok, f"{label} ({distro}, {flavour}) did not build: see test_driver_compiles_with_werror"
    run = harness_runs[(label, distro, flavour)]
    reports = run.sanitizer_reports()
    assert not reports, f"{label} ({flavour}): sanitizer reports:\n" + "\n".join(reports[:20]) + \
        f"\n{run.stderr[-6000:]}"
    assert run.returncode == 0 and run.failed == 0 and run.passed > 0, f"{label} ({flavour}): {run.describe()}"
    model = _robot(reference, label).model
    expected = {"interfaces", "safety", "joint_map", "imu", "commands", "command_safety", "command_modes", "parameters",
                "decimation", "faults", "allocations", "threads", "transmission", "on_write"}
    if model.has_transmission:
        # motors that are not joints: the exact motor = joint checks give way to the transmission section's
        expected = {"interfaces", "transmission", "faults", "threads"}
    if model.transport == "unitree_dds" and not model.has_transmission:
        expected.add("crc")
    if has_fake_robot(model):
        expected.add("fake_robot")
    if distro != "humble":  # <ros2_control is_async>: read()/write() on a thread of their own (Jazzy and later)
        expected.add("async")
    if model.authority == "upper_body":  # the legs are state-only: the arm SDK's own scenarios
        expected = {"interfaces", "crc", "arm_sdk"} | ({"fake_robot"} if has_fake_robot(model) else set())
    if yaml_hands(label_yaml(label)) != "none":  # hands: dex3 / omnihand, the hands' own section
        expected.add("hands")
    if yaml_take_control(label_yaml(label)):  # AimDK's system-state services around the commands
        expected.add("take_control")
    if vendor_msgs.ENGINEAI_NATIVE_SDK in message_variants(label):  # MotorDebug.offline: an offline motor faults
        expected.add("offline")
    physics = physics_robot(label, distro, flavour)
    if physics is not None:  # the fake robot on MuJoCo (tests/cpp/harness/physics_checks.inc)
        expected |= {"physics_faults", *(f"physics_{s}" for s in physics.scenarios)}
    missing = expected - set(run.sections)
    assert not missing, f"{label} ({flavour}): sections not run: {sorted(missing)}"


PLAIN_RUN_CELLS = [(label, d) for label, d, f in RUN_CELLS if f == "plain"]


@pytest.mark.parametrize(("label", "distro"), PLAIN_RUN_CELLS, ids=[f"{label}-{d}" for label, d in PLAIN_RUN_CELLS])
def test_hot_paths_allocate_nothing(harness_runs, reference, label, distro):
    _compilable_robot(reference, label)
    run = harness_runs.get((label, distro, "plain"))
    assert run is not None, f"{label}: plain harness did not build for {distro}"
    m = re.search(r"^allocations over (\d+) cycles: state callback (\d+), IMU callback (\d+), read\(\) (\d+), "
                  r"write\(\) (\d+), command writer (\d+)$", run.stdout, re.M)
    assert m, f"{label}: no allocation line in the harness output:\n{run.stdout[-3000:]}"
    counts = dict(zip(("state callback", "IMU callback", "read()", "write()", "command writer"),
                      map(int, m.groups()[1:]), strict=False))
    assert all(v == 0 for v in counts.values()), f"{label}: heap allocations after activation: {counts}"


# ------------------------------------------------------------------------------------ physics (issue 36)
# The driver against its fake robot on MuJoCo (tests/cpp/harness/physics_checks.inc), in the harness cell
# PHYSICS_CELL: the package's own URDF (the vendors' own, issue 49: real inertials; no mesh file is present, so
# the mesh geoms are left out and the YAML's contacts stand in for the feet), the YAML's default_gains, no
# feed-forward. Bounds [rad, degrees, m], with what was measured:
# - band, 5 s (the harness checks the base within 5 mm and the IMU's 9.81 +- 0.1 m/s^2 itself): every joint
#   held. The G1 within 0.05 (0.039, the elbows at kp 50; the waist pitch at kp 300: 0.020), upright within 2
#   (0.29); the PM01 within 0.02 (0.0048, the shoulder rolls), upright within 2 (0.06); the X2's legs, waist and
#   head within 0.02 (0.010, the waist pitch), its arms within 0.1 (0.061, the shoulder rolls at AimDK's kp 20),
#   upright within 2 (0.68).
# - stand, 10 s, base free on the floor at the YAML's initial_positions (the vendor's stand pose): the base within
#   STAND_HEIGHT of its start height, its root link within STAND_TILT of upright, nothing but the feet touching
#   the floor. The PM01 stands on EngineAI's pd_stand gains (base 1.5 mm, 1.7 degrees). The G1's and the X2's
#   YAML gains are what their vendors hold them with while a policy (or a gantry) balances them: standing on
#   them alone, the G1 falls after 1.0 s and the X2 after 1.5 s (reported, not asserted; the ankles' 40 N m/rad
#   each against the m g h of about 200 N m/rad of the body above them). They are held to the same bounds with
#   the legs and waist at 500 / 10 N m s/rad (physics_stand_stiff): the G1 1.7 mm, 3.1 degrees; the X2 0.6 mm,
#   1.1 degrees.
# - mass: the compiled model's equals the generated description's and the vendor's (SIM_FACTS), to 1e-6 kg.
# - arm, base fixed: the G1's left arm follows 0.5 Hz sines of 0.25 rad (Unitree's kp 100 / 50 / 20) within 0.15
#   at most (0.046, the elbow: gravity over kp) and 0.1 RMS (0.036); passive (kp = kd = 0) for 2 s, the shoulder
#   pitch and the elbow fall by more than 0.2 (0.29 and 1.97: the arm starts near hanging, and each joint has
#   unitree_mujoco's 0.2 N m of friction).
# - roll, base free: the Go2-W (tests/cpp/harness/robots/unitree/go2w.urdf: the Go2's kinematics and inertials,
#   primitive collisions, 0.09 m wheels) stands on its wheels at the YAML's initial_positions (go2w_stand_example's
#   pose), legs held with kp 70, kd 5; its wheels ramped to 10 rad/s over 0.5 s (kd 5) for 2 s: it travels more
#   than 1.0 m forwards (1.55; 1.58 without slip), less than 0.05 m sideways (0.000), its wheels within 0.5 rad/s
#   of the command after the first second (0.10), its IMU link within 10 degrees of upright (2.5).
# label: ({part of a joint's name: its bound}, the tilt's bound, the joints not held)
BAND_BOUNDS: dict[str, tuple[dict[str, float], float, set[str]]] = {"unitree/g1": ({"": 0.05}, 2.0, set()),
               "engineai/pm01": ({"": 0.02}, 2.0, set()),
               "agibot/x2": ({"hip": 0.02, "knee": 0.02, "ankle": 0.02, "waist": 0.02, "head": 0.02, "shoulder": 0.1,
                              "elbow": 0.1, "wrist": 0.1}, 2.0, set())}
STAND_HEIGHT, STAND_TILT = 0.03, 5.0  # [m], [degrees]


@dataclass(frozen=True)
class Stand:
    feet: frozenset[str]   # the links that may touch the floor
    scenario: str          # the harness section held to the bounds: stand (the YAML's gains) or stand_stiff
    vendor_mass: float     # [kg] the vendor's description (shared upstream SIM_FACTS.md, section Descriptions)


STANDS = {
    "unitree/g1": Stand(frozenset({"left_ankle_roll_link", "right_ankle_roll_link"}), "stand_stiff", 33.341142),
    "engineai/pm01": Stand(frozenset({"LINK_ANKLE_ROLL_L", "LINK_ANKLE_ROLL_R"}), "stand", 40.920828),
    "agibot/x2": Stand(frozenset({"left_ankle_roll_link", "right_ankle_roll_link"}), "stand_stiff", 44.801),
}


def urdf_mass(path: Path) -> float:
    """The sum of a URDF's <inertial><mass value> (read here, not with rhi-gen's own parser)."""
    root = ElementTree.parse(path).getroot()
    return sum(float(m.get("value", "0")) for link in root.iter("link") for m in link.findall("inertial/mass"))
ARM_TRACK_MAX, ARM_TRACK_RMS, ARM_SAG = 0.15, 0.1, 0.2
ARM_SAGS = {"unitree/g1": ("left_shoulder_pitch_joint", "left_elbow_joint")}
ROLL_FORWARD, ROLL_SIDEWAYS, ROLL_SPEED, ROLL_TILT = 1.0, 0.05, 0.5, 10.0
PHYSICS_LABELS = sorted(label for label in ROBOTS if physics_robot(label, *PHYSICS_CELL) is not None)


def physics_figures(stdout: str) -> dict[str, float]:
    """The harness's "physics <scenario>.<name>=<value>" lines."""
    return {k: float(v) for k, v in re.findall(r"^physics (\S+)=(\S+)$", stdout, re.M)}


def check_stand(label: str, figures: dict[str, float], stand: Stand, run: HarnessRun, package_urdf: Path,
                report) -> None:
    """The free base on the floor (physics_stand, physics_stand_stiff): it stands where the bounds say, only its
    feet touch the floor, and its mass is the vendor's in the compiled model and in the generated description."""
    got = {k.split(".", 1)[1]: v for k, v in figures.items() if k.startswith(f"{stand.scenario}.")}
    assert got, f"{label}: no {stand.scenario} figures:\n{run.stdout[-3000:]}"
    touched = {k.split(".", 1)[1] for k in got if k.startswith("touch.")}
    assert touched == stand.feet, f"{label} standing: the links that touched the floor: {sorted(touched)}"
    assert got["fell_at_s"] < 0 and got["base_z"] < STAND_HEIGHT and got["tilt_deg"] < STAND_TILT, \
        f"{label} did not stand ({stand.scenario}): {({k: v for k, v in got.items() if '.' not in k})}"
    mass = figures["stand.mass_kg"]
    for what, kg in (("MuJoCo's compiled model", mass), (str(package_urdf), urdf_mass(package_urdf)),
                     (f"robots/{label}.urdf", urdf_mass(REPO / "robots" / f"{label}.urdf"))):
        assert abs(kg - stand.vendor_mass) < 1e-5, f"{label}: {what} weighs {kg} kg, the vendor's {stand.vendor_mass}"
    vendor = {k.split(".", 1)[1]: v for k, v in figures.items() if k.startswith("stand.")}
    report(f"{label} on MuJoCo, base free, 10 s ({stand.scenario}): base {got['base_z'] * 1000:.1f} mm from its "
           f"start, tilt {got['tilt_deg']:.2f} deg, on {', '.join(sorted(touched))}; on the YAML's gains alone: " +
           (f"fell after {vendor['fell_at_s']:.2f} s" if vendor["fell_at_s"] >= 0 else
            f"stood (tilt {vendor['tilt_deg']:.2f} deg)") + f"; mass {mass:.6f} kg; real-time factor {got['rtf']:.2f} "
           f"(contacts on, driver and controller beside it)")


@pytest.mark.parametrize("label", PHYSICS_LABELS)
def test_the_driver_drives_its_fake_robot_on_mujoco(harness_runs, reference, label, report):
    _compilable_robot(reference, label)
    run = harness_runs.get((label, *PHYSICS_CELL))
    assert run is not None and "physics_faults" in run.sections, f"{label}: no physics run (see the cell's test)"
    assert run.sections["physics_faults"][1] == 0, run.describe()
    figures = physics_figures(run.stdout)
    physics = physics_robot(label, *PHYSICS_CELL)
    assert physics is not None
    # physics_faults: fault, the README's recovery and a position command under the default gains, twice (issue 48)
    # (the motors receive the default gains: asserted; how closely the joints follow: the body's, a figure)
    rounds = [(int(figures[f"recovery{r}.gains_received"]), int(figures[f"recovery{r}.followed"]),
               int(figures[f"recovery{r}.joints"]), figures[f"recovery{r}.worst"])
              for r in (1, 2) if f"recovery{r}.gains_received" in figures]
    assert len(rounds) == 2 and all(g == n for g, _, n, _ in rounds), f"{label}: after recovery: {rounds}"
    report(f"{label} on MuJoCo, after fault + recovery, default gains: " +
           ", ".join(f"round {r}: gains on {g}/{n} motors, {f}/{n} followed within 0.03 rad of the claimed gains' "
                     f"error, worst {w:.4f} rad" for r, (g, f, n, w) in enumerate(rounds, 1)))
    if "band" in physics.scenarios:
        bounds, tilt, unheld = BAND_BOUNDS[label]
        errors = {k.split(".", 2)[2]: v for k, v in figures.items() if k.startswith("band.error.")}
        assert errors, run.stdout[-3000:]
        bounded = {j: (e, next(b for part, b in bounds.items() if part in j))
                   for j, e in errors.items() if j not in unheld and any(part in j for part in bounds)}
        assert set(bounded) | unheld == set(errors), f"{label}: joints without a bound: {set(errors) - set(bounded)}"
        over = {j: e for j, (e, b) in bounded.items() if e > b}
        assert not over, f"{label} on the band: joints off their start pose beyond the bounds: {over}"
        assert figures["band.tilt_deg"] < tilt, f"{label} on the band tilts {figures['band.tilt_deg']:.2f} degrees"
        worst = max(bounded.items(), key=lambda kv: kv[1][0])
        report(f"{label} on MuJoCo, on the band 5 s: worst held joint {worst[0]} {worst[1][0]:.4f} rad, base "
               f"{figures['band.base_z'] * 1000:.2f} mm, tilt {figures['band.tilt_deg']:.2f} deg, "
               f"IMU {figures['band.imu_acc']:.3f} m/s^2")
    if "arm" in physics.scenarios:
        track = {k.split(".", 2)[2]: v for k, v in figures.items() if k.startswith("arm.track_max.")}
        rms = {k.split(".", 2)[2]: v for k, v in figures.items() if k.startswith("arm.track_rms.")}
        assert track and max(track.values()) < ARM_TRACK_MAX and max(rms.values()) < ARM_TRACK_RMS, (track, rms)
        for joint in ARM_SAGS[label]:
            assert figures[f"arm.sag.{joint}"] > ARM_SAG, f"{label}: passive, {joint} did not sag: {figures}"
        report(f"{label} on MuJoCo, arm base fixed: tracking max {max(track.values()):.4f} rad, RMS "
               f"{max(rms.values()):.4f} rad; passive sag " +
               ", ".join(f"{j} {figures[f'arm.sag.{j}']:.2f}" for j in ARM_SAGS[label]))
    if "stand" in physics.scenarios:
        check_stand(label, figures, STANDS[label], run,
                    _robot(reference, label).package_dir / "urdf" / f"{label.split('/')[1]}.urdf", report)
    if "roll" in physics.scenarios:
        roll = {k.split(".", 1)[1]: v for k, v in figures.items() if k.startswith("roll.")}
        assert roll["dx"] > ROLL_FORWARD and abs(roll["dy"]) < ROLL_SIDEWAYS, f"{label} did not roll: {roll}"
        assert roll["speed_error"] < ROLL_SPEED and roll["tilt_deg"] < ROLL_TILT, f"{label}: {roll}"
        report(f"{label} on MuJoCo, wheels at 10 rad/s for 2 s: {roll['dx']:.3f} m forwards, {roll['dy']:.3f} m "
               f"sideways, wheel speed within {roll['speed_error']:.3f} rad/s, tilt {roll['tilt_deg']:.1f} deg")


# The threaded scenario commands every joint; an upper_body robot's real-thread checks are in its arm_sdk section.
ARM_SDK_LABELS = {label for label in ROBOTS if yaml_arm_sdk(label_yaml(label)) is not None}
THREAD_CELLS = [c for c in RUN_CELLS if c[2] != "plain" and c[0] not in ARM_SDK_LABELS]


@pytest.mark.parametrize(("label", "distro", "flavour"), THREAD_CELLS,
                         ids=[f"{label}-{d}-{f}" for label, d, f in THREAD_CELLS])
def test_no_torn_frames_with_real_threads(harness_runs, reference, label, distro, flavour):
    _compilable_robot(reference, label)
    run = harness_runs.get((label, distro, flavour))
    assert run is not None, f"{label}: {flavour} harness did not build"
    m = re.search(r"torn states (\d+), torn commands (\d+), bad CRCs (\d+)", run.stdout)
    assert m, f"{label} ({flavour}): the threaded scenario did not report:\n{run.stdout[-3000:]}"
    assert m.groups() == ("0", "0", "0"), f"{label} ({flavour}): {m.group(0)}"


# ------------------------------------------------------------------------------------ custom, unfilled
CUSTOM_ROBOTS = [label for label in ROBOTS if label == "odri/solo12"]


@pytest.mark.parametrize("distro", ["humble", "rolling"])
@pytest.mark.parametrize("label", CUSTOM_ROBOTS)
def test_unfilled_custom_transport_refuses_activation_in_one_line(label, distro, tmp_path_factory, cpp_builder):
    """A custom-transport driver as generated (regions not filled in) compiles with -Werror, loads,
    initialises, and refuses on_activate with exactly one error line naming the region and file;
    it starts no writer and sends nothing (driver_harness.cpp, RHI_CUSTOM_EXPECT_UNFILLED)."""
    package = render_test_package(tmp_path_factory.mktemp("unfilled"), only=[label], fill_custom=False)
    b = package.build(label)
    source = (package.package_dir / "src" / b.model.vendor / f"{b.model.robot}.cpp").read_text()
    assert source.count("#define RHI_CUSTOM_NOT_FILLED_IN_") == 3, "three function regions, each marked"
    b.data_header += "#define RHI_CUSTOM_EXPECT_UNFILLED 1\n"
    (b.data_dir / "robot_data.hpp").write_text(b.data_header, encoding="utf-8")
    link, steps = build_harness(cpp_builder, b, "plain", distro=distro)
    failed = [s for s in steps if not s.ok]
    assert not failed and link.ok, \
        f"the unfilled driver does not build ({distro}):\n{(failed or [link])[0].stderr[:6000]}"
    run = run_binary_retrying(link.path)
    assert run.returncode == 0 and run.failed == 0 and run.sections.get("unfilled", (0, 0))[0] > 0, run.describe()
    refused = [line for line in run.stdout.splitlines() if line.startswith("refused: ")]
    assert refused == [(f"refused: custom transport: region 'transport_connect' of src/{b.model.vendor}/"
                        f"{b.model.robot}.cpp is not filled in: refusing to activate (write the SDK calls there and "
                        "delete its RHI_CUSTOM_NOT_FILLED_IN line)")], refused
