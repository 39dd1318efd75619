"""The C++ checks bite: break a template on purpose and the harness must fail.

Each mutation copies rhi_gen's sources (templates/, cpp/, transports/) to a temporary folder, changes one thing (the pattern must
match exactly where expected, so a template rewrite cannot silently turn a mutation into a no-op),
renders the reference G1 (unitree_dds hg, float, CRC) and PM01 (a ROS topic transport, double), or
the harness's go2w test robot (unitree_dds go family) for the go mutations, with that template
folder (render_package's env_factory: make_environment()'s settings, FileSystemLoader on the copy),
builds tests/cpp/harness/driver_harness.cpp against the result (plain flavour) and runs it. The run
must fail, with failed checks in the section that guards the broken property. The
DataBuffer mutation builds tests/cpp/harness/data_buffer_stress.cpp instead. A control run of the
unmodified copy must pass, so the failures come from the mutations, not from the machinery.
"""
from __future__ import annotations

import re
import shutil
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.support import vendor_msgs
from tests.support.cpp_build import (
    REPO,
    build_harness,
    compile_data_buffer_stress,
    render_test_package,
    run_binary,
    run_parallel,
    session_builder,
)

SOURCES = REPO / "rhi_gen"
SOURCE_FOLDERS = ("templates", "cpp", "transports")  # what render_package reads (render/environment.py)
ROBOTS = ("unitree/g1", "engineai/pm01")
GO_ROBOTS = ("unitree/go2w",)  # tests/cpp/harness/robots/: the go message family
CONTROL_ROBOTS = (*ROBOTS, *GO_ROBOTS)  # every robot a mutation runs on passes unmodified
THREADS_MS = 100

BROKEN_DOUBLE_BUFFER = (REPO / "tests/cpp/harness/mutants/double_buffer.inc").read_text()


@dataclass(frozen=True)
class Mutation:
    id: str
    what: str
    template: str          # path under rhi_gen/ (a template or a C++ source)
    pattern: str           # regular expression (MULTILINE)
    replacement: str
    sections: tuple[str, ...]   # the harness sections expected to catch it
    robots: tuple[str, ...] = ROBOTS
    count: int | None = 1  # matches the pattern must have (None: at least one)
    data_buffer: bool = False  # run data_buffer_stress instead of the driver harness


MUTATIONS = (
    Mutation("layer1_writer_guard", "delete layer 1: the command writer no longer waits for the first state",
             "cpp/common/driver_core.hpp",
             r"^[ \t]*if \(!first_state_received_\.load\(std::memory_order_acquire\)\) \{\n[ \t]*return nullptr;\n"
             r"[ \t]*\}\n", "", ("safety",)),
    Mutation("layer2_initial_command", "delete layer 2: the first state no longer seeds the hold command",
             "cpp/common/driver_core.hpp", r"^[ \t]*motor_command_buffer_\.setData\(initial_cmd_cache_\);\n", "",
             ("safety",)),
    Mutation("layer3_write_guard", "delete layer 3: write() forwards commands before read() copied a state",
             "cpp/common/driver_core.hpp",
             r"^[ \t]*if \(!state_copied_\.load\(std::memory_order_relaxed\)\) \{\n[ \t]*return false;\n"
             r"[ \t]*\}\n", "", ("safety",)),
    Mutation("layer3_first_write_seed", "layer 3: the first write() no longer targets the measured position",
             "cpp/common/driver_core.hpp",
             r"^[ \t]*frames_\.joints\.pos_des = frames_\.joints\.pos;\n", "", ("safety",)),
    Mutation("default_gains_ignored", "a position-only controller gets zero stiffness instead of the default",
             "cpp/common/driver_core.hpp", r"\(claims & kClaimPosition\) != 0U \? default_stiffness_\[i\] : 0\.0",
             "0.0", ("command_modes",), robots=("unitree/g1",)),
    Mutation("velocity_joint_position_target", "a velocity-commanded joint is sent the stale position target",
             "cpp/common/driver_core.hpp", r"(static_cast<T>\(frames_\.joints\.)pos(\[slot\]\);)", r"\g<1>pos_des\2",
             ("command_modes",), robots=("acme/scara",)),
    Mutation("nan_command_bounded", "write() bounds a NaN command to the lower limit instead of passing it on",
             "cpp/common/slot_kernels.hpp", r"const T raised = rounded < lower \? lower : rounded;",
             "const T raised = !(rounded >= lower) ? lower : rounded;", ("command_safety",)),
    Mutation("agibot_duplicate_entry", "a JointStateArray naming one joint twice stands in for a missing joint",
             "transports/agibot_topics/agibot_topics.hpp", r"if \(slot_stamps_\[slot\] == stamp\) \{",
             "if (false) {", ("joint_map",), robots=("agibot/x2",)),
    Mutation("joint_map_swap", "the robot's joint table swaps the SDK slots of motors 0 and 1",
             "templates/robot/driver.cpp.j2", r"(\{\{ joint\.name \| cpp_string \}\}, )\{\{ joint\.index \}\}",
             r"\1{{ (1 - joint.index) if joint.index < 2 else joint.index }}", ("joint_map",)),
    Mutation("crc_polynomial", "CRC32 with a wrong polynomial", "transports/unitree_dds/unitree_crc.hpp",
             r"(kPolynomial = )0x04C11DB7U", r"\g<1>0x04C11DB6U", ("crc", "commands", "safety"),
             robots=("unitree/g1",)),
    Mutation("crc_skips_lowcmd_field", "LowCmd_ CRC skips MotorCmd_.reserve", "transports/unitree_dds/unitree_hg.hpp",
             r"\{8, 24, kMotorSlots, 28\}", "{8, 20, kMotorSlots, 28}", ("crc", "commands"),
             robots=("unitree/g1",)),
    Mutation("crc_skips_lowstate_field", "LowState_ CRC skips MotorState_.reserve[3]", "transports/unitree_dds/unitree_hg.hpp",
             r"\{76, 52, kMotorSlots, 56\}", "{76, 48, kMotorSlots, 56}", ("crc", "safety"), robots=("unitree/g1",)),
    Mutation("crc_hashes_lowstate_padding", "hg LowState_ CRC hashes the 2 padding bytes after mode_machine",
             "transports/unitree_dds/unitree_hg.hpp", r"\{8, 2, 1, 0\}", "{8, 4, 1, 0}", ("crc", "safety"),
             robots=("unitree/g1",)),
    # unitree go family (Go2, Go2-W, B2, B2-W, H1), on the harness's go2w test robot.
    Mutation("go_crc_hashes_padding", "go LowState_ CRC hashes the 3 padding bytes after imu_state.temperature",
             "transports/unitree_dds/unitree_go.hpp", r"\{24, 53, 1, 0\}", "{24, 56, 1, 0}", ("crc", "safety"),
             robots=GO_ROBOTS),
    Mutation("go_head_bytes", "go LowCmd_.head[0] is 0xEF instead of 0xFE", "transports/unitree_dds/unitree_go.hpp",
             r"(kHead0 = )0xFE;", r"\g<1>0xEF;", ("commands",), robots=GO_ROBOTS),
    Mutation("go_motor_modes_ignored", "go LowCmd_ slots get mode 0x01 where motor_modes says 0 (stop)",
             "transports/unitree_dds/unitree_go.hpp", r"motor\.mode\(\) = motor_modes\[slot\];",
             "motor.mode() = static_cast<uint8_t>(motor_modes[slot] | 0x01U);",
             ("commands",), robots=GO_ROBOTS),
    Mutation("imu_quaternion_order", "read() exports x as orientation.w", "cpp/common/driver_core.hpp",
             r"(imu_data_\.ori_\[3\] = static_cast<double>\(imu->quat\[)0(\]\))", r"\g<1>1\2", ("imu",)),
    Mutation("decimation", "state decimation off by one", "cpp/common/driver_core.hpp",
             r"% parameters_\.state_decimation\)", "% (parameters_.state_decimation + 1))", ("decimation",)),
    Mutation("stale_ignores_decimated_frames", "decimated frames no longer count as state arriving",
             "cpp/common/driver_core.hpp",
             r"^[ \t]*if \(state_frames_valid_\) \{\n[ \t]*markStateFresh\(.*\n[ \t]*\}\n", "", ("decimation",)),
    Mutation("stale_masked_by_decimated_frames", "decimated frames keep the state fresh after a rejected frame",
             "cpp/common/driver_core.hpp", r"if \(state_frames_valid_\) \{", "if (true) {", ("decimation",)),
    Mutation("parameter_range", "an out-of-range parameter (0) is accepted", "cpp/common/hardware_parameters.hpp",
             r"parsed < min \|\| ", "", ("parameters",)),
    Mutation("hot_path_allocation", "write() allocates", "cpp/common/system_driver.hpp",
             r"(\n[ \t]*fetchCommandValues\(\);\n)",
             r"\1    { std::vector<double> rhi_mutant(8); (void)rhi_mutant; }\n",
             ("allocations",)),
    Mutation("double_buffer", "DataBuffer hands out a slot the producer can overwrite (the seed's double buffer)",
             "cpp/common/data_buffer.hpp",
             r"(?s)^namespace robot_hardware_interface\n\{\n.*^\}  // namespace robot_hardware_interface",
             BROKEN_DOUBLE_BUFFER.replace("\\", "\\\\"),
             ("contract", "stress_1_producer", "stress_2_producers"), robots=(), data_buffer=True),
)


def _mutated_templates(root: Path, mutation: Mutation | None) -> Path:
    dest = root / "sources"
    for folder in SOURCE_FOLDERS:
        shutil.copytree(SOURCES / folder, dest / folder, ignore=shutil.ignore_patterns("*.py", "__pycache__"))
    if mutation is not None:
        path = dest / mutation.template
        text = path.read_text(encoding="utf-8")
        new, n = re.subn(mutation.pattern, mutation.replacement, text, flags=re.M)
        if mutation.count is None:
            assert n >= 1, f"{mutation.id}: pattern not found in {mutation.template}; update the mutation"
        else:
            assert n == mutation.count, (f"{mutation.id}: pattern matched {n} times in {mutation.template}, "
                                         f"expected {mutation.count}; update the mutation")
        path.write_text(new, encoding="utf-8")
    return dest


@dataclass
class Outcome:
    mutation: Mutation | None
    robot: str            # "vendor/robot" or "data_buffer"
    built: bool
    build_error: str
    run: object | None
    seconds: float
    skipped: str | None = None   # why this robot was not built (its vendor messages are missing)


def _run_one(job, tmp_root: Path, builder) -> list[Outcome]:
    mutation: Mutation | None = job
    name = mutation.id if mutation else "control"
    root = tmp_root / name
    start = time.monotonic()
    templates = _mutated_templates(root, mutation)
    robots = mutation.robots if mutation else CONTROL_ROBOTS
    package = render_test_package(root, only=robots or ROBOTS[:1], template_dir=templates,
                                  # the harness's test robots
                                  extra_robots=any(label not in ROBOTS for label in robots))
    outcomes = []
    if mutation is None or mutation.data_buffer:
        link = compile_data_buffer_stress(builder, package.package_dir, "plain")
        run = run_binary(link.path, timeout=120) if link.ok else None
        outcomes.append(Outcome(mutation, "data_buffer", link.ok, link.stderr, run, time.monotonic() - start))
    for label in robots:
        reason = vendor_msgs.skip_reason(package.build(label).model.transport)
        if reason:
            outcomes.append(Outcome(mutation, label, False, "", None, 0.0, skipped=reason))
            continue
        link, _ = build_harness(builder, package.build(label), "plain")
        run = run_binary(link.path, [f"--threads-ms={THREADS_MS}"], timeout=120) if link.ok else None
        outcomes.append(Outcome(mutation, label, link.ok, link.stderr, run, time.monotonic() - start))
    return outcomes


@pytest.fixture(scope="module")
def outcomes(tmp_path_factory):
    builder = session_builder(tmp_path_factory)
    tmp_root = tmp_path_factory.mktemp("mutations")
    jobs = [None, *MUTATIONS]
    start = time.monotonic()
    results = run_parallel(jobs, lambda job: _run_one(job, tmp_root, builder))
    elapsed = time.monotonic() - start
    by_id = {(job.id if job else "control"): result for job, result in zip(jobs, results, strict=False)}
    by_id["_seconds"] = elapsed  # type: ignore[assignment]
    return by_id


def _built(outcomes_of_one: list[Outcome]) -> list[Outcome]:
    """The outcomes that were attempted; a skip when none was (no robot had its vendor messages)."""
    attempted = [o for o in outcomes_of_one if o.skipped is None]
    if not attempted:
        pytest.skip("; ".join(o.skipped for o in outcomes_of_one))
    return attempted


def test_control_unmodified_templates_pass(outcomes):
    for o in _built(outcomes["control"]):
        assert o.built, f"control {o.robot} does not build:\n{o.build_error[:4000]}"
        assert o.run.returncode == 0 and o.run.failed == 0, f"control {o.robot}: {o.run.describe()}"


@pytest.mark.parametrize("mutation", MUTATIONS, ids=[m.id for m in MUTATIONS])
def test_mutation_is_caught(outcomes, mutation):
    for o in _built(outcomes[mutation.id]):
        assert o.built, (f"{mutation.id} ({mutation.what}): {o.robot} no longer compiles, so this mutation "
                         f"proves nothing; adjust it:\n{o.build_error[:4000]}")
        run = o.run
        failed_sections = sorted(name for name, (_, f) in run.sections.items() if f > 0)
        assert run.returncode != 0, (f"{mutation.id} ({mutation.what}) was NOT caught for {o.robot}: "
                                     f"{run.passed} checks passed, none failed")
        assert set(failed_sections) & set(mutation.sections), (
            f"{mutation.id} ({mutation.what}) on {o.robot} failed, but not in {mutation.sections}: "
            f"failed sections {failed_sections}\n{run.describe()}")
