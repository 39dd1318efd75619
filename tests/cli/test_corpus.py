"""Real robot descriptions no one here wrote: each generates a driver that compiles, or is rejected.

The corpus is every URDF (and every xacro that needs no ROS package) of the ``example-robot-data``
package on PyPI (a test dependency: G1, Go1/Go2, A1, B1, Talos with mimic joints, Tiago, UR, Panda,
Allegro, ...) plus the upstream vendor URDFs in ../shared/upstream/urdf when that folder exists.

For each file the test does what a user does: ``rhi-gen new --vendor corpus --robot <name> --urdf
FILE --transport generic_topics`` in a fresh project (the vendor YAML is built from the URDF's
actuated joints), then compiles one generated driver per driver shape (joint count in steps of 8,
wheels, IMU, escaped names, vendor file: see compile_set) against the stand-in headers (g++ -Werror,
two files at a time). A file may instead be rejected with exit 2 and one clear line, but only the
rejections listed in EXPECTED_REJECTIONS: each is a genuine defect of that input, explained there.
Anything else — a crash, a driver that does not compile, a new rejection, or an expected rejection
that disappeared — fails the test.

The per-file outcome and the summary ("N descriptions: G generated, C of them compiled, R rejected with
reasons") are shown in the run's "reports" summary section (tests/conftest.py: report) and written to
tests/.corpus_report.txt.
"""
from __future__ import annotations

import re
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import pytest
import yaml
from lxml import etree

from rhi_gen.inputs.urdf_loader import canonical_urdf_bytes, is_xacro
from rhi_gen.inputs.xacro_expand import expand_xacro
from tests.support import upstream_urdf
from tests.support.cli import run_cli, snapshot
from tests.support.corpus import EXPECTED_REJECTIONS, Description, corpus
from tests.support.cpp_build import syntax_check_driver
from tests.support.repo import PACKAGE, TESTS
from tests.support.xml_tree import attribute

REPORT = TESTS / ".corpus_report.txt"
COMPILE_WORKERS = 2

@dataclass
class Outcome:
    description: Description
    status: str = ""            # "generated" | "rejected" | "crashed"
    reason: str = ""            # the error line for "rejected"/"crashed"
    compile_error: str = ""     # g++'s first errors when the driver does not compile
    problems: list[str] = field(default_factory=list)  # contract violations found along the way
    status_note: str = ""       # a generated driver not compiled itself (another of its shape was)

    @property
    def ok(self) -> bool:
        return not self.problems and not self.compile_error and self.status in ("generated", "rejected")


def joint_names(path: Path, *, expand: bool = False) -> list[str]:
    """The top-level <joint> names of a URDF (of a xacro's expansion when ``expand``), read with lxml."""
    data = expand_xacro(path, {}, {}) if expand else path.read_bytes()
    return [attribute(j, "name") for j in etree.fromstring(data).findall("joint")]


def check_generated(root: Path, d: Description, outcome: Outcome) -> None:
    """What `new` wrote follows ros2_control's rules for this URDF."""
    yaml_path = root / "robots" / "corpus" / f"{d.robot}.yaml"
    pkg = root / "generated" / PACKAGE
    for needed in (yaml_path, pkg / "src" / "corpus" / f"{d.robot}.cpp",
                   pkg / "include" / PACKAGE / "corpus" / f"{d.robot}.hpp",
                   pkg / "description" / f"{d.robot}.ros2_control.xacro"):
        if not needed.is_file():
            outcome.problems.append(f"missing {needed.relative_to(root)}")
            return
    config = yaml.safe_load(yaml_path.read_text())
    mapped = list(config["joint_map"])
    # the URDF as ros2_control's parser sees it (an independent read, lxml only): movable joints
    # without <mimic> get interfaces, mimic joints get none
    # the description lies outside the project: `new` wrote it, expanded, next to the YAML
    copy = yaml_path.parent / config["urdf"]
    if copy != yaml_path.with_suffix(".urdf") or not copy.is_file():
        outcome.problems.append(f"the YAML's urdf: {config['urdf']!r} is not the copy {d.robot}.urdf")
    elif not is_xacro(d.path) and copy.read_bytes() != canonical_urdf_bytes(d.path.read_bytes()):
        outcome.problems.append(f"{copy.name} is not a copy of {d.path}")
    elif is_xacro(d.path) and joint_names(copy) != joint_names(d.path, expand=True):
        outcome.problems.append(f"{copy.name} does not hold the joints of {d.path} expanded")
    urdf = etree.parse(str(d.path)) if not d.path.name.endswith(".xacro") else None
    if urdf is not None:
        joints = urdf.getroot().findall("joint")
        movable = [attribute(j, "name") for j in joints if j.get("type") in ("revolute", "continuous", "prismatic")]
        mimic = {attribute(j, "name") for j in joints if j.find("mimic") is not None}
        expected = [n for n in movable if n not in mimic]
        if sorted(mapped) != sorted(expected):
            outcome.problems.append(f"joint_map {len(mapped)} joints, URDF has {len(expected)} actuated non-mimic")
        types = {j.get("name"): j.get("type") for j in joints}
    else:
        mimic, types = set(), {}
    described = etree.parse(str(pkg / "description" / f"{d.robot}.ros2_control.xacro"))
    rc_joints = {j.get("name"): j for j in described.iter("joint")}
    if set(rc_joints) != set(mapped):
        outcome.problems.append("ros2_control description joints differ from joint_map")
    for name, el in rc_joints.items():
        if name in mimic and el.find("command_interface") is not None:
            outcome.problems.append(f"mimic joint {name!r} got command interfaces")
        if types.get(name) == "continuous" and el.find("command_interface/param[@name='min']") is not None:
            outcome.problems.append(f"continuous joint {name!r} got position limits")


def run_new(tmp_path: Path, index: int, d: Description) -> Outcome:
    outcome = Outcome(d)
    root = tmp_path / f"{index:03d}_{d.robot}"
    root.mkdir()
    before = snapshot(root)
    result = run_cli("new", "--vendor", "corpus", "--robot", d.robot, "--urdf", d.path,
                     "--transport", "generic_topics", "--project", root)
    lines = result.error_lines
    if result.code == 0:
        outcome.status = "generated"
        check_generated(root, d, outcome)
    elif result.code == 2:
        outcome.status = "rejected"
        outcome.reason = lines[0] if lines else "(no message)"
        if len(lines) != 1 or not lines[0].startswith("error: ") or " -> " not in lines[0]:
            outcome.problems.append(f"rejection is not one 'error: ... -> fix' line: {lines!r}")
        if snapshot(root) != before:
            outcome.problems.append("files were written although the input was rejected")
    else:
        outcome.status = "crashed"
        outcome.reason = f"exit {result.code}: " + " | ".join(lines[-3:])
    return outcome


def compile_driver(tmp_path: Path, index: int, outcome: Outcome) -> None:
    root = tmp_path / f"{index:03d}_{outcome.description.robot}"
    try:
        syntax_check_driver(root / "generated" / PACKAGE, "corpus", outcome.description.robot)
    except AssertionError as exc:
        outcome.compile_error = "\n".join(str(exc).splitlines()[:8])


def driver_shape(tmp_path: Path, index: int, outcome: Outcome) -> tuple:
    """What makes one generic_topics driver's C++ differ from another's beyond plain numbers: the
    joint count (in steps of 8), velocity-commanded joints, an IMU, joint names that are not plain
    identifiers (escaped into C++ literals), and a vendor URDF."""
    pkg = tmp_path / f"{index:03d}_{outcome.description.robot}" / "generated" / PACKAGE
    rc = etree.parse(str(pkg / "description" / f"{outcome.description.robot}.ros2_control.xacro"))
    joints = list(rc.iter("joint"))
    return (len(joints) // 8,
            any(j.find("command_interface[@name='position']") is None for j in joints),
            rc.find(".//sensor") is not None,
            any(not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", j.get("name", "")) for j in joints),
            outcome.description.label.startswith("upstream:"))


def compile_set(tmp_path: Path, generated: list[tuple[int, Outcome]]) -> list[tuple[int, Outcome]]:
    """One driver per shape: drivers of one shape differ only in the numbers and names of their joint
    table, which test_cpp_literals and the harness robots cover; compiling all ~70 would triple the
    test's time for no new check. Every driver is still generated and checked above."""
    chosen: dict[tuple, tuple[int, Outcome]] = {}
    for index, outcome in generated:
        shape = driver_shape(tmp_path, index, outcome)
        if shape in chosen:
            outcome.status_note = "generated (its shape compiled with another)"
        else:
            chosen[shape] = (index, outcome)
    return list(chosen.values())


@pytest.mark.cpp  # g++ -fsyntax-only on the generated drivers
def test_every_description_generates_a_compiling_driver_or_is_rejected_clearly(tmp_path, report, record_property):
    start = time.perf_counter()
    descriptions = corpus()
    erd = [d for d in descriptions if d.label.startswith("example-robot-data:")]
    assert len(erd) >= 60, f"example-robot-data holds only {len(erd)} descriptions: wrong package version?"

    outcomes = [run_new(tmp_path, i, d) for i, d in enumerate(descriptions)]
    generate_time = time.perf_counter() - start
    generated = compile_set(tmp_path, [(i, o) for i, o in enumerate(outcomes) if o.status == "generated"])
    with ThreadPoolExecutor(max_workers=COMPILE_WORKERS) as pool:
        list(pool.map(lambda item: compile_driver(tmp_path, *item), generated))
    elapsed = time.perf_counter() - start

    failures: list[str] = []
    labels = {d.label for d in descriptions}
    for o in outcomes:
        label = o.description.label
        expected = EXPECTED_REJECTIONS.get(label)
        if o.status == "crashed":
            failures.append(f"{label}: rhi-gen crashed ({o.reason})")
        elif o.status == "rejected":
            if expected is None:
                failures.append(f"{label}: unexpected rejection (a valid description? fix the loader): {o.reason}")
            else:
                missing = [w for w in expected[0] if w not in o.reason]
                if missing:
                    failures.append(f"{label}: rejected for another reason than expected ({missing}): {o.reason}")
        elif o.status == "generated" and expected is not None:
            failures.append(f"{label}: generated although listed in EXPECTED_REJECTIONS; update the list")
        if o.compile_error:
            failures.append(f"{label}: driver does not compile:\n{o.compile_error}")
        failures += [f"{label}: {p}" for p in o.problems]
    stale = [label for label in EXPECTED_REJECTIONS if label.startswith("example-robot-data:") and label not in labels]
    failures += [f"{label}: listed in EXPECTED_REJECTIONS but not in the corpus any more" for label in stale]

    ok = [o for o in outcomes if o.status == "generated" and not o.compile_error and not o.problems]
    compiled = [o for o in ok if not o.status_note]
    rejected = [o for o in outcomes if o.status == "rejected"]
    summary = (f"{len(descriptions)} descriptions: {len(ok)} generated, {len(compiled)} of them compiled "
               f"(one per driver shape), {len(rejected)} rejected with reasons"
               + (f", {len(outcomes) - len(ok) - len(rejected)} FAILED" if failures else "")
               + f" ({elapsed:.1f} s: {generate_time:.1f} s rhi-gen new, {elapsed - generate_time:.1f} s g++ "
                 f"with {COMPILE_WORKERS} workers)")
    lines = ["rhi-gen corpus: example-robot-data"
             + (f" + {upstream_urdf.SHARED}" if upstream_urdf.SHARED.is_dir() else " (shared upstream folder absent)")]
    for o in outcomes:
        mark = {"generated": "NO-COMPILE" if o.compile_error else "generated" if o.status_note else "compiled"
                }.get(o.status, o.status)
        if o.problems:
            mark += " (PROBLEM)"
        lines.append(f"  {mark:<12} {o.description.label}" + (f"\n               {o.reason}" if o.reason else ""))
    lines.append("rejected, each a genuine defect of the input:")
    for o in rejected:
        why = EXPECTED_REJECTIONS.get(o.description.label, ((), "NOT EXPECTED"))[1]
        lines.append(f"  {o.description.label}: {why}")
    lines.append(summary)
    text = "\n".join(lines) + "\n"
    REPORT.write_text(text)
    record_property("corpus_summary", summary)
    report(text)

    assert not failures, f"{summary}\n" + "\n".join(failures)
