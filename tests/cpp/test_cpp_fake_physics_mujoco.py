"""The fake robot's physics backend (rhi_gen/cpp/common/fake_physics_mujoco.hpp, issue 36) against the real
MuJoCo: the `mujoco-core` wheel of the test extra, its libmujoco.so and C headers, no stand-in.

A small program (tests/cpp/physics/fake_physics_check.cpp) drives FakeMujocoPhysics as a fake robot's loop
does (commands at the driver's 500 Hz, physics at 1 kHz) and prints what it measured; the joint table it reads
is rhi-gen's own reading of the robot's URDF (limits, effort) and vendor YAML (slots, default_gains).

The arm is the harness's PAL TALOS left arm (tests/cpp/harness/robots/pal/talos_arm.*, example-robot-data's
URDF, 7 motors, base fixed), its collision meshes resolved from example-robot-data's installed share/ folder
(the test extra installs it), its transmissions left out (the backend drives each URDF joint one to one).
Tolerances, and where they come from:
- tracking: sines of 0.25 rad at 0.5 Hz on the six arm joints at once, with the YAML's gains (kp 40 / 20 N m/rad,
  kd 2 / 1 N m s/rad) and a model's gravity feed-forward: at most 0.15 rad from the target at any time, RMS
  below 0.08 rad. What is left is what the URDF asks for: 1 N m of friction and 1 N m s/rad of damping per
  joint against those soft gains (about 0.1 rad at the wrist's kp 20). The gripper (friction 1 N m = its
  effort limit 1 N m: it cannot follow anything) holds still.
- holding still without feed-forward: at rest, kp * error equals the gravity torque up to the joint's friction
  (within 0.05 N m), and the error is more than 0.05 rad somewhere (gravity is really there).
- sagging: every motor passive (kp = kd = 0) for 2 s, from a pose 0.6 rad away from hanging down, the shoulder
  and elbow fall by more than 0.3 rad.

The floating bases are the upstream G1 and PM01 URDFs (tests/data/upstream_urdf: real inertials; their meshes
are not carried, so the model is inertial-only, the one warning), with their reference YAMLs' default_gains and
IMU frames, starting at their description's start pose (every joint at zero, clamped into its limits):
- on the band, holding the start pose for 5 s: the base within 5 mm of its start height (the band stretches
  2 cm under the robot's full weight and is anchored that much higher), upright within 2 degrees, the IMU's
  mean vertical acceleration 9.81 +- 0.1 m/s^2 (gravity, the robot held). Joint errors: the PM01 within
  0.05 rad; the G1 within 0.5 rad, its YAML's waist_pitch kp of 40 N m/rad leaning under the torso's weight
  (measured 0.26 rad; the legs and arms within 0.05 rad, the elbows' 0.043 the largest).
- free, no band: the same robot falls (nothing balances it).
"""
from __future__ import annotations

import importlib.util
import math
import platform
import re
import subprocess
from pathlib import Path

import pytest

from rhi_gen.assemble.joint_inertia import joint_dynamics
from rhi_gen.inputs.urdf_loader import load_urdf
from rhi_gen.render.environment import SOURCE_ROOT
from tests.support.ament_lint import run_cpplint, run_uncrustify
from tests.support.cpp_build import (
    HARNESS_ROBOTS,
    WARNING_FLAGS,
    run_compiler,
    yaml_joint_map,
    yaml_modes_and_gains,
)
from tests.support.example_robot_data import example_robot_data_prefix
from tests.support.repo import REPO

HERE = Path(__file__).resolve().parent
CHECK_SOURCE = HERE / "physics" / "fake_physics_check.cpp"
HEADERS = ("fake_physics_mujoco.hpp", "fake_physics.hpp", "fake_joint_dynamics.hpp")
TALOS_YAML = HARNESS_ROBOTS / "pal" / "talos_arm.yaml"
TALOS_URDF = HARNESS_ROBOTS / "pal" / "talos_arm.urdf"
SCARA_YAML = HARNESS_ROBOTS / "acme" / "scara.yaml"
SCARA_URDF = HARNESS_ROBOTS / "acme" / "scara.urdf"
UPSTREAM_URDF = REPO / "tests" / "data" / "upstream_urdf"
# label: (vendor YAML, upstream URDF, IMU link as the YAML's imu.frame_id names it, joint error bound [rad])
FLOATING = {
    "g1": (REPO / "robots" / "unitree" / "g1.yaml", UPSTREAM_URDF / "unitree_g1.urdf", "imu_in_pelvis", 0.5),
    "pm01": (REPO / "robots" / "engineai" / "pm01.yaml", UPSTREAM_URDF / "engineai_pm01.urdf", "LINK_BASE", 0.05),
}
AMPLITUDE = 0.25        # [rad] of the tracked sines
HELD_STILL = ("gripper_left_joint",)

TRACK_MAX = 0.15        # [rad]
TRACK_RMS = 0.08        # [rad]
BALANCE = 0.05          # [N m]
GRAVITY_SHOWS = 0.05    # [rad]
SAG = 0.3               # [rad]


def mujoco_dir() -> Path:
    """The folder of the installed `mujoco-core` wheel: libmujoco.so.* and include/mujoco/."""
    spec = importlib.util.find_spec("mujoco")
    if spec is None or spec.origin is None:
        if tuple(int(x) for x in platform.python_version_tuple()[:2]) < (3, 11):
            pytest.skip("mujoco-core has wheels for Python 3.11 and newer only (pyproject.toml's test extra)")
        pytest.fail("MuJoCo is not installed: pip install -e '.[test]' installs mujoco-core (never skipped)")
    return Path(spec.origin).parent


@pytest.fixture(scope="module")
def include_tree(tmp_path_factory) -> Path:
    """The headers as a generated package lays them out (they include each other by package path)."""
    root = tmp_path_factory.mktemp("physics") / "robot_hardware_interface"
    common = root / "include" / "robot_hardware_interface" / "common"
    common.mkdir(parents=True)
    for name in HEADERS:
        (common / name).symlink_to(SOURCE_ROOT / "cpp" / "common" / name)
    return root


@pytest.fixture(scope="module")
def checker(include_tree, tmp_path_factory) -> Path:
    mj = mujoco_dir()
    libs = sorted(mj.glob("libmujoco.so*"))
    assert libs and (mj / "include" / "mujoco" / "mujoco.h").is_file(), f"no libmujoco.so or headers in {mj}"
    binary = tmp_path_factory.mktemp("physics_bin") / "fake_physics_check"
    run_compiler([*WARNING_FLAGS, "-O2", f"-I{include_tree / 'include'}", f"-I{mj / 'include'}",
                  str(CHECK_SOURCE), str(libs[0]), f"-Wl,-rpath,{mj}", "-o", str(binary)],
                 what="tests/cpp/physics/fake_physics_check.cpp")
    return binary


def joint_table(yaml_path: Path, urdf_path: Path, path: Path, *, held: tuple[str, ...] = HELD_STILL,
                inset: bool = True) -> Path:
    """The joints as rhi-gen reads them: slots and gains from the YAML, limits from the URDF. Each starts at
    zero clamped into its limits or, `inset`, 2 amplitudes + 0.1 rad inside them, so that gravity pulls on it."""
    joints = {j.name: j for j in load_urdf(urdf_path).joints}
    dynamics = joint_dynamics(urdf_path.read_text(encoding="utf-8"))
    _, gains = yaml_modes_and_gains(yaml_path)
    lines = []
    for name, slot in yaml_joint_map(yaml_path).items():
        j = joints[name]
        lim = j.limits
        lo, hi = -math.inf, math.inf
        if j.type != "continuous" and lim is not None and lim.lower is not None and lim.upper is not None:
            lo, hi = lim.lower, lim.upper
        margin = 2 * AMPLITUDE + 0.1 if inset else 0.0
        start = min(max(0.0, lo + margin), hi - margin) if lo + margin <= hi - margin else (lo + hi) / 2
        velocity = lim.velocity if lim is not None and lim.velocity else math.inf
        effort = lim.effort if lim is not None and lim.effort else math.inf
        kp, kd = gains.get(name, (0.0, 0.0))
        amplitude = 0.0 if name in held else AMPLITUDE
        d = dynamics[name]
        lines.append(f"{name} {slot} {lo!r} {hi!r} {velocity!r} {effort!r} {start!r} {kp!r} {kd!r} {amplitude!r} "
                     f"{d.urdf_damping!r} {d.urdf_friction!r}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def run_check(checker: Path, scenario: str, table: Path, urdf: Path, *, base: str = "fixed",
              package_path: str = "", imu: str = "", seconds: float = 4.0,
              timestep: float = 0.001) -> subprocess.CompletedProcess:
    return subprocess.run([str(checker), scenario, str(table), str(urdf), base, package_path, imu, str(seconds),
                           str(timestep)], capture_output=True, text=True, timeout=300)


def values(stdout: str) -> dict[str, str]:
    return dict(line.split("=", 1) for line in stdout.splitlines() if "=" in line)


@pytest.fixture(scope="module")
def talos_table(tmp_path_factory) -> Path:
    return joint_table(TALOS_YAML, TALOS_URDF, tmp_path_factory.mktemp("tables") / "talos.tab")


def test_the_header_compiles_alone_and_passes_the_ros2_linters(include_tree, tmp_path):
    mj = mujoco_dir()
    src = tmp_path / "alone.cpp"
    src.write_text('#include "robot_hardware_interface/common/fake_physics_mujoco.hpp"\n'
                   '#include "robot_hardware_interface/common/fake_physics_mujoco.hpp"\n'
                   "template class robot_hardware_interface::FakeMujocoPhysics<8>;  // every member\n"
                   "int main() { return 0; }\n")
    run_compiler([*WARNING_FLAGS, "-fsyntax-only", f"-I{include_tree / 'include'}", f"-I{mj / 'include'}", str(src)],
                 what="fake_physics_mujoco.hpp")
    findings = run_cpplint(include_tree)
    assert not findings, "\n".join(f"{f.file}:{f.line}: [{f.rule}] {f.message}" for f in findings[:40])
    result = run_uncrustify(include_tree)
    assert not result.findings, "\n".join(f"--- {name}\n{diff}" for name, diff in list(result.diffs.items())[:3])


def test_a_fixed_base_arm_tracks_a_trajectory_under_gravity(checker, talos_table, report):
    proc = run_check(checker, "track", talos_table, TALOS_URDF, package_path=str(example_robot_data_prefix()),
                     seconds=6.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert "warning" not in v, v["warning"]           # every mesh found
    assert int(v["nmesh"]) == 13 and float(v["timestep"]) == 0.001
    assert float(v["floor"]) < -1.0                    # below the arm's reach: it never touches it
    per_joint = {k.removeprefix("track."): float(x) for k, x in v.items() if k.startswith("track.")}
    assert float(v["track_max"]) < TRACK_MAX, per_joint
    assert float(v["track_rms"]) < TRACK_RMS, per_joint
    assert float(v["unbalanced_max"]) < BALANCE, proc.stdout
    assert float(v["hold_max"]) > GRAVITY_SHOWS, proc.stdout
    report(f"fake physics (MuJoCo): TALOS arm tracking, YAML gains + gravity feed-forward: max "
           f"{float(v['track_max']):.3f} rad, RMS {float(v['track_rms']):.3f} rad; static error without "
           f"feed-forward {float(v['hold_max']):.3f} rad; {float(v['rtf']):.0f}x real time with the controller's model")


def test_with_kp_zero_a_fixed_base_arm_sags_under_gravity(checker, talos_table, report):
    proc = run_check(checker, "sag", talos_table, TALOS_URDF, package_path=str(example_robot_data_prefix()),
                     seconds=2.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert float(v["sag.arm_left_2_joint"]) > SAG, proc.stdout
    assert float(v["sag.arm_left_4_joint"]) > SAG, proc.stdout
    report(f"fake physics (MuJoCo): TALOS arm, motors passive for 2 s: sags {float(v['sag_max']):.3f} rad "
           f"({v['sag_joint']})")


def test_the_imu_on_a_moving_link_reads_its_rotation(checker, talos_table):
    """The IMU at arm_left_2_link (its joint turns about the link's x axis, the root link is welded upright),
    0.3 s into a sag: the orientation is a rotation about x by the joint's angle, the angular velocity the
    joint's velocity about x. MuJoCo's sensors are computed before the last 1 ms step's integration, so they
    lag the joint state by one physics step: tolerances 0.01 rad and 5 % + 0.05 rad/s."""
    proc = run_check(checker, "sag", talos_table, TALOS_URDF, imu="arm_left_2_link", seconds=0.3)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    q, dq = float(v["pos.arm_left_2_joint"]), float(v["vel.arm_left_2_joint"])
    assert abs(dq) > 0.5, proc.stdout        # mid-fall
    w, x, y, z = (float(c) for c in v["imu_quat"].split())
    assert abs(2 * math.atan2(x, w) - q) < 0.01 and abs(y) < 1e-3 and abs(z) < 1e-3, (q, v["imu_quat"])
    gx, gy, gz = (float(c) for c in v["imu_gyro"].split())
    assert abs(gx - dq) < 0.05 * abs(dq) + 0.05 and abs(gy) < 0.05 and abs(gz) < 0.05, (dq, v["imu_gyro"])


def test_the_fake_robots_joint_dynamics_hand_their_joints_to_the_physics(checker, talos_table):
    """FakeJointDynamics::use_engine: what the runner and the transports read is MuJoCo's state, the same
    motion as driving FakeMujocoPhysics directly, bit for bit."""
    runs = {scenario: run_check(checker, scenario, talos_table, TALOS_URDF, seconds=2.0)
            for scenario in ("sag", "engine")}
    for proc in runs.values():
        assert proc.returncode == 0, proc.stdout + proc.stderr
    direct, through = (values(runs[s].stdout) for s in ("sag", "engine"))
    assert through["physics_steps"] == "2000"
    assert {k: x for k, x in through.items() if k.startswith("sag")} == \
        {k: x for k, x in direct.items() if k.startswith("sag")}
    assert float(through["sag_max"]) > SAG


def test_motors_behind_transmissions_move_their_joints_as_the_urdf_joints_would(checker, talos_table, tmp_path):
    """The TALOS arm's YAML puts three motors behind transmissions (arm_left_2: offset 0.1; arm_left_4: reversed,
    reduction 100; the gripper: reduction 2.5, offset -0.05). The same arm, held by the same joint gains, is
    simulated twice: in joint units, and in motor units with each motor's gain and offset (its limits, start
    and gains converted; the limits are the fake robot's own, rhi-gen's fake_robot_view). The joints must
    move the same. The wrist's differential pair (coupled joints) is simulated one to one both times."""
    from rhi_gen.render.fake_robot_views import fake_robot_view
    from tests.support.cpp_build import load_models, make_test_project

    loaded = load_models(make_test_project(tmp_path / "proj", only=["pal/talos_arm"]))
    model = next(item.model for item in loaded if item.model.robot == "talos_arm")
    coupled = {name for group in model.coupled_groups for name in group.joints}
    view = {line.joint: line for line in fake_robot_view(model).joints}
    gains = {j.name: (1.0, 0.0) if j.name in coupled else
             (j.transmission.direction * j.transmission.reduction, j.transmission.offset)
             for j in model.joints_by_index}
    assert sum(1 for g, o in gains.values() if (g, o) != (1.0, 0.0)) == 3, gains
    motor_lines = []
    for line in talos_table.read_text(encoding="utf-8").splitlines():
        name, slot, lo, hi, vel, eff, start, kp, kd, amplitude, damping, friction = line.split()
        g, o = gains[name]
        lo_m, hi_m = sorted((g * (float(lo) - o), g * (float(hi) - o)))
        vel_m, eff_m = float(vel) * abs(g), float(eff) / abs(g)
        if name not in coupled:  # the limits as the generated fake robot has them
            v = view[name]
            assert (math.isclose(lo_m, v.position_min, abs_tol=1e-12) and math.isclose(hi_m, v.position_max)
                    and math.isclose(vel_m, v.velocity_max) and math.isclose(eff_m, v.effort_max)), (name, v)
        motor_lines.append(f"{name} {slot} {lo_m!r} {hi_m!r} {vel_m!r} {eff_m!r} {g * (float(start) - o)!r} "
                           f"{float(kp) / g ** 2!r} {float(kd) / g ** 2!r} {amplitude} {damping} {friction} {g!r} "
                           f"{o!r}")
    motor_table = tmp_path / "talos_motors.tab"
    motor_table.write_text("\n".join(motor_lines) + "\n", encoding="utf-8")
    runs = [run_check(checker, "hold", table, TALOS_URDF, seconds=2.0) for table in (talos_table, motor_table)]
    for proc in runs:
        assert proc.returncode == 0, proc.stdout + proc.stderr
    joint_units, motor_units = (values(proc.stdout) for proc in runs)
    for name, (g, o) in gains.items():
        assert math.isclose(float(motor_units[f"pos.{name}"]) / g + o, float(joint_units[f"pos.{name}"]),
                            abs_tol=1e-6), name
        assert math.isclose(float(motor_units[f"effort.{name}"]) * g, float(joint_units[f"effort.{name}"]),
                            rel_tol=1e-6, abs_tol=1e-6), name
    assert float(joint_units["effort.arm_left_4_joint"]) != 0.0   # the geared motor holds weight


def test_each_joint_gets_its_own_rotor_inertia(checker, talos_table):
    """FakeJointSpec::armature (the vendor YAML's armatures, rhi_gen/model/config.py ARMATURE_DEFAULT otherwise)
    becomes the armature of that joint in MuJoCo's model, joint by joint."""
    proc = run_check(checker, "armature", talos_table, TALOS_URDF)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    found = re.findall(r"^armature\.(\S+)=(\S+) given=(\S+)$", proc.stdout, re.M)
    assert len(found) == len(yaml_joint_map(TALOS_YAML)), proc.stdout
    assert len({given for _, _, given in found}) == len(found)  # distinct: a mix-up would show
    for joint, held, given in found:
        assert float(held) == pytest.approx(float(given), rel=1e-12), (joint, held, given)


def test_the_physics_steps_every_step_and_allocates_nothing(checker, talos_table, report):
    proc = run_check(checker, "rate", talos_table, TALOS_URDF, package_path=str(example_robot_data_prefix()),
                     seconds=10.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert float(v["physics_steps"]) == 10000
    assert int(v["mujoco_allocations"]) > 0 and int(v["step_allocations"]) == 0, proc.stdout  # hook live; none
    # Speed is a figure, never an assertion (the benchmark and the reports section give it).
    report(f"fake physics (MuJoCo): TALOS arm with meshes, 1 kHz physics at 500 Hz commands: "
           f"{float(v['physics_hz']):.0f} steps/s, real-time factor {float(v['rtf']):.1f}")


def test_meshes_not_found_give_an_inertial_only_model_and_one_warning(checker, talos_table):
    proc = run_check(checker, "sag", talos_table, TALOS_URDF, package_path="", seconds=2.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    warnings = [line for line in proc.stdout.splitlines() if line.startswith("warning=")]
    assert len(warnings) == 1, warnings
    assert re.fullmatch(r"warning=13 of 13 meshes not found \(first: package://example-robot-data/robots/talos_data/"
                        r"meshes/arm/arm_1_collision\.STL; no package path given\): the mesh geoms left out, "
                        r"inertial-only model",
                        warnings[0]), warnings[0]
    v = values(proc.stdout)
    assert int(v["nmesh"]) == 0
    assert float(v["sag.arm_left_2_joint"]) > SAG      # the same physics without the meshes
    assert proc.stderr == ""


BROKEN = {
    "not_xml": ('<robot name="broken"><link name="a"', r"MuJoCo cannot read .*broken\.urdf: XML parse error"),
    "massless_links": (None, (r"MuJoCo cannot compile .*scara\.urdf: mass and inertia of moving bodies must be "
                              r"larger than mjMINVAL; Element name 'link1', id \d+")),
    "missing_file": ("", r"MuJoCo cannot read .*nowhere\.urdf: .*Error opening file"),
    "joint_not_in_urdf": (TALOS_URDF.read_text(encoding="utf-8").replace("arm_left_5_joint", "arm_left_five"),
                          r"joint 'arm_left_5_joint' of the joint table is not a moving joint of the URDF"),
    "imu_link_not_in_urdf": (TALOS_URDF.read_text(encoding="utf-8"),
                             r"the IMU link 'no_such_link' is not a link of the URDF"),
    "physics_slower_than_1khz": (TALOS_URDF.read_text(encoding="utf-8"),
                                 (r"the physics timestep must be more than 0 and at most 0\.001 s \(1 kHz or "
                                  r"faster\), not 0\.002$")),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_what_mujoco_cannot_take_gives_one_error_line(checker, talos_table, tmp_path, case):
    text, expected = BROKEN[case]
    table = talos_table
    if case == "massless_links":  # the SCARA's links have no <inertial>: nothing to simulate
        urdf = SCARA_URDF
        table = joint_table(SCARA_YAML, SCARA_URDF, tmp_path / "scara.tab")
    elif case == "missing_file":
        urdf = tmp_path / "nowhere.urdf"
    else:
        urdf = tmp_path / "broken.urdf"
        urdf.write_text(text, encoding="utf-8")
    proc = run_check(checker, "load", table, urdf, imu="no_such_link" if case == "imu_link_not_in_urdf" else "",
                     timestep=0.002 if case == "physics_slower_than_1khz" else 0.001)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    lines = proc.stdout.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error="), lines
    assert re.match(expected, lines[0].removeprefix("error=")), lines[0]
    assert proc.stderr == "", proc.stderr                  # MuJoCo itself printed nothing



@pytest.mark.parametrize("robot", sorted(FLOATING))
def test_on_the_band_a_humanoid_holds_its_start_pose(checker, tmp_path, robot, report):
    yaml_path, urdf, imu, joint_bound = FLOATING[robot]
    table = joint_table(yaml_path, urdf, tmp_path / f"{robot}.tab", held=(), inset=False)
    proc = run_check(checker, "hold", table, urdf, base="band", imu=imu, seconds=5.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    warnings = [line for line in proc.stdout.splitlines() if line.startswith("warning=")]
    assert any("meshes not found" in w for w in warnings), warnings
    start, low, high = float(v["base_start"]), float(v["base_min"]), float(v["base_max"])
    assert start > 0.5 and start - 0.005 < low <= high < start + 0.005, proc.stdout
    w = abs(float(v["imu_quat"].split()[0]))
    tilt = math.degrees(2 * math.acos(min(1.0, w)))
    assert tilt < 2.0, proc.stdout
    assert abs(float(v["imu_acc_z_mean"]) - 9.81) < 0.1, proc.stdout
    ax, ay, _ = (float(x) for x in v["imu_acc"].split())
    assert math.hypot(ax, ay) < 0.5, proc.stdout
    assert float(v["joint_max"]) < joint_bound, proc.stdout
    legs_and_arms = {k: float(x) for k, x in v.items() if k.startswith("hold.") and "waist" not in k}
    assert max(legs_and_arms.values()) < 0.05, legs_and_arms
    report(f"fake physics (MuJoCo): {robot} on the band, YAML gains, 5 s: base {low:.4f}..{high:.4f} m "
           f"(start {start:.4f}), tilt {tilt:.2f} deg, IMU z {float(v['imu_acc_z_mean']):.3f} m/s^2, joints within "
           f"{float(v['joint_max']):.3f} rad")


def test_without_the_band_a_free_humanoid_falls(checker, tmp_path):
    yaml_path, urdf, imu, _ = FLOATING["g1"]
    table = joint_table(yaml_path, urdf, tmp_path / "g1.tab", held=(), inset=False)
    proc = run_check(checker, "hold", table, urdf, base="free", imu=imu, seconds=2.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert float(v["base_min"]) < float(v["base_start"]) - 0.1, proc.stdout


def test_a_released_band_lets_the_humanoid_fall(checker, tmp_path):
    yaml_path, urdf, imu, _ = FLOATING["g1"]
    table = joint_table(yaml_path, urdf, tmp_path / "g1.tab", held=(), inset=False)
    proc = run_check(checker, "drop", table, urdf, base="band", imu=imu, seconds=3.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert v["band_holding"] == "0"
    assert float(v["lowest_after"]) < float(v["released_at"]) - 0.1, proc.stdout


@pytest.mark.parametrize("robot", sorted(FLOATING))
def test_a_humanoid_on_the_band_steps_its_physics_without_allocating(checker, tmp_path, robot, report):
    """10 s of 1 kHz physics on the band: every step taken, none allocates. How much faster than real time it runs
    is a figure (the report here, benchmarks/bench_physics.py), never a verdict: a busy machine runs it slower."""
    yaml_path, urdf, imu, _ = FLOATING[robot]
    table = joint_table(yaml_path, urdf, tmp_path / f"{robot}.tab", held=(), inset=False)
    proc = run_check(checker, "rate", table, urdf, base="band", imu=imu, seconds=10.0)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    v = values(proc.stdout)
    assert float(v["physics_steps"]) == 10000, proc.stdout
    assert int(v["step_allocations"]) == 0, proc.stdout
    report(f"fake physics (MuJoCo): {robot} on the band, 1 kHz physics at 500 Hz commands: "
           f"{float(v['physics_hz']):.0f} steps/s, real-time factor {float(v['rtf']):.1f}")
