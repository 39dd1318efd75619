"""What each command does with its parsed arguments: run the pipeline, apply its plan, print the outcome.

cli.py parses the command line and maps errors to exit codes; each function here takes the parsed
values and returns the exit code (0 ok, 1 differences found). The pipeline is imported inside each
command, so `--help` and `--version` stay fast.
"""
from __future__ import annotations

import os
import re
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from .errors import InputWarning, ProjectError, RhiGenError

if TYPE_CHECKING:
    from .model import RobotModel, UrdfRobot, VendorConfig
    from .project import Project
    from .write.api_migration import ApiRename
    from .write.changes import FileChange
    from .write.semantic_diff import RobotDiff


def _out(text: str) -> None:
    sys.stdout.write(text + "\n")


def _err(text: str) -> None:
    sys.stderr.write(text + "\n")


def _warn(warnings: Sequence[InputWarning]) -> None:
    """Warnings go to stderr after the command succeeded: one line each, the command still exits 0."""
    for w in warnings:
        _err(f"warning: {w}")


def _parse_pairs(values: Sequence[str] | None, option: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for value in values or []:
        if "=" not in value or not value.split("=", 1)[0]:
            raise RhiGenError(f"expected NAME=VALUE, got {value!r}", key=option,
                              fix=f"write it as {option} NAME=VALUE (repeat the option for each pair)")
        name, val = value.split("=", 1)
        out[name] = val
    return out


def _project(project: Path | None) -> Project:
    from .project import find_project

    return find_project(project)


_MESH_FOLDER = re.compile(r"^(.*robot_hardware_interface/meshes/[^/]+/)")


def _print_changes(changes: Sequence[FileChange], *, verbose: bool) -> dict[str, int]:
    """One line per file; a robot's copied meshes in one line per status unless verbose (a robot has dozens)."""
    counts = {"created": 0, "changed": 0, "unchanged": 0, "removed": 0}
    meshes: dict[tuple[str, str], int] = {}
    for c in changes:
        counts[c.status] += 1
        folder = _MESH_FOLDER.match(c.path)
        if folder is not None and not verbose:
            if c.status != "unchanged":
                key = (folder.group(1), c.status)
                meshes[key] = meshes.get(key, 0) + 1
        elif c.status != "unchanged" or verbose:
            _out(f"  {c.status:<9} {c.path}")
    for (folder_path, status), n in sorted(meshes.items()):
        _out(f"  {status:<9} {folder_path} ({n} mesh{'es' if n > 1 else ''})")
    return counts


def _summary(counts: dict[str, int], *, dry_run: bool = False) -> str:
    parts = ", ".join(f"{n} {k}" for k, n in counts.items())
    return f"summary: {parts}" + (" (would be written: dry run)" if dry_run else "")


def new(*, vendor: str, robot: str, urdf: Path, transport: str | None, xacro_arg: Sequence[str] | None,
        package_path: Sequence[str] | None, force: bool, class_prefix: str | None,
        transport_option: Sequence[str] | None, project: Path | None) -> int:
    """Create robots/VENDOR/ROBOT.yaml with a joint map suggested from the URDF, and generate it."""
    from .pipeline.new_robot import bringup_commands, plan_new_robot
    from .render.fake_robot_views import has_fake_robot
    from .write.transaction import apply

    proj = _project(project)
    plan = plan_new_robot(proj, vendor=vendor, robot=robot, urdf_path=urdf, transport=transport,
                          xacro_args=_parse_pairs(xacro_arg, "--xacro-arg"),
                          package_paths=_parse_pairs(package_path, "--package-path"), force=force,
                          class_prefix=class_prefix,
                          transport_options=_parse_pairs(transport_option, "--transport-option"))
    apply(proj.root, plan.changes)
    m = plan.robot.model
    _out(f"wrote {plan.yaml_relpath}: {len(m.joints)} joints, {m.motor_count} motors, "
         f"transport {m.transport}, {m.float_type}")
    inputs = {plan.yaml_relpath}
    if plan.copy is not None:
        _out(plan.copy.note(plan.yaml_relpath))
        inputs.add(plan.copy.rel)
    counts = _print_changes([c for c in plan.changes if c.path not in inputs], verbose=False)
    _out(_summary(counts))
    if plan.robot.urdf.transmissions:
        _out(_transmissions_line(plan.robot.config, plan.robot.urdf, plan.yaml_relpath))
    _print_missing_meshes([m])
    _out(f"next: review the joint_map in {plan.yaml_relpath}, then `rhi-gen generate`.")
    _out("then build the package in a ROS 2 workspace (docs/try-without-the-robot.md) and bring it up:")
    for label, command in bringup_commands(m.robot, fake_robot=has_fake_robot(m)):
        _out(f"  {label + ':':<19}{command}")
    _warn(plan.warnings)
    return 0


def _print_missing_meshes(models: Sequence[RobotModel]) -> None:
    """One line per robot whose URDF names meshes by a relative path that are not in the project."""
    from .inputs.urdf_meshes import missing_line

    for m in models:
        line = missing_line(f"{m.vendor}/{m.robot}", m.provenance.urdf_path, m.missing_meshes)
        if line is not None:
            _out(line)


def _transmissions_line(config: VendorConfig, urdf: UrdfRobot, yaml_relpath: str) -> str:
    """`new`: how many <transmission>s the URDF has and how many apply to the mapped joints."""
    from .assemble.transmissions import decide_transmissions

    decided = decide_transmissions(config, urdf)
    total = len(urdf.transmissions)
    return (f"transmissions: {total} in the URDF, {decided.urdf_applied} applied, {decided.urdf_skipped} not "
            f"(listed in {yaml_relpath}; docs/transmissions.md)")


def _use_colour() -> bool:
    """Colour only for a person at a terminal: stdout is a TTY and NO_COLOR is not set."""
    return "NO_COLOR" not in os.environ and sys.stdout.isatty()


def _bold(text: str, colour: bool) -> str:
    return f"\x1b[1m{text}\x1b[0m" if colour else text


def _print_robot_diffs(diffs: Sequence[RobotDiff], colour: bool, prefix: str = "") -> None:
    for d in diffs:
        first, *rest = d.lines()
        _out(_bold(prefix + first, colour))
        for line in rest:
            _out(line)


def _print_file_diffs(changes: Sequence[FileChange], colour: bool) -> None:
    from .write.diff_text import colour_diff, unified_diff

    for c in changes:
        if c.status != "unchanged":
            text = unified_diff(c, prefix="generated/")
            sys.stdout.write(colour_diff(text) if colour else text)
    sys.stdout.flush()


def _version_line(old: str, new: str) -> str:
    return (f"generated/ was made by rhi-gen {old}, not by this rhi-gen {new}: `rhi-gen generate` records "
            "the new version and rewrites only files whose content changes")


def _print_renames(renames: Sequence[ApiRename], *, dry_run: bool = False) -> None:
    """Old C++ API names rewritten in user regions: the user's code changed, so say where."""
    for r in renames:
        _out(f"  {'would rename' if dry_run else 'renamed'} in {r.note()}")


def generate(*, robots: Sequence[str] | None, dry_run: bool, verbose: bool, force: bool,
             project: Path | None) -> int:
    """(Re)generate generated/robot_hardware_interface; a hand-edited file blocks the run unless force."""
    from .pipeline.existing_tags import existing_tag_warnings
    from .pipeline.generate import plan_generation
    from .pipeline.load import load_selected
    from .write.backups import BACKUP_DIR, BACKUP_MARKERS
    from .write.transaction import apply

    proj = _project(project)
    loaded, only = load_selected(proj, robots, progress=_out if verbose else None)
    plan = plan_generation(proj, loaded, only, force=force)
    if plan.blocked and not force:
        if len(plan.blocked) > 1:  # the details on stdout; stderr gets the one error line
            for b in plan.blocked:
                _out(f"blocked: {b.note()}")
        raise plan.blocked_error()
    counts = _print_changes([*plan.files, plan.manifest_change], verbose=verbose)
    _print_renames(plan.renames, dry_run=dry_run)
    if not dry_run:
        apply(proj.generated_dir, plan.changes)
    for c in plan.backups:
        if c.path not in BACKUP_MARKERS:
            original = c.path[len(BACKUP_DIR) + 1:].rsplit(".", 1)[0]
            _out(f"  {'would keep' if dry_run else 'kept'} your version of {original} in generated/{c.path}")
    names = ", ".join(f"{r.model.vendor}/{r.model.robot} ({len(r.model.joints)} joints)" for r in loaded)
    _out(f"robots: {names}")
    _out(_summary(counts, dry_run=dry_run))
    _print_missing_meshes([r.model for r in (loaded if only is None else only)])
    _warn(existing_tag_warnings(loaded if only is None else only))
    _warn([w for r in (loaded if only is None else only) for w in r.transmission_warnings])
    return 0


def diff(*, robots: Sequence[str] | None, project: Path | None) -> int:
    """Explain what `generate` would change: robot terms first, then the file diff; 1 when it would."""
    from .pipeline.generate import plan_generation
    from .pipeline.load import load_selected

    proj = _project(project)
    loaded, only = load_selected(proj, robots)
    plan = plan_generation(proj, loaded, only)
    colour = _use_colour()
    if plan.other_version:
        _out(_version_line(plan.other_version, plan.generator_version))
    _print_robot_diffs(plan.robot_diffs, colour)
    _print_renames(plan.renames, dry_run=True)
    files = [c for c in plan.files if c.status != "unchanged"]
    if files:
        _out("")
    _print_file_diffs(files, colour)
    for b in plan.blocked:
        _err(f"note: `rhi-gen generate` would refuse: {b.note()} -> {b.fix}")
    if not plan.differs:
        _err("nothing to regenerate: generated/ matches the inputs")
        return 0
    extra = " and generated/.rhi-gen-manifest" if plan.manifest_change.status != "unchanged" else ""
    _err(f"{len(files)} file(s){extra} would change; run `rhi-gen generate"
         f"{' ' + ' '.join(robots) if robots else ''}` to write them")
    return 1


def check(*, project: Path | None) -> int:
    """CI gate: 1 when generated/ is not what `generate` would write now (stale inputs, a file, a version).

    When the last check that passed read exactly these bytes with this rhi-gen, it answers from that memo
    (pipeline/verified.py): a pre-commit hook with nothing changed loads no robot and renders nothing.
    """
    from .pipeline import verified

    began = time.time()
    proj = _project(project)
    robots = verified.still_verified(proj)
    if robots is not None:  # exactly the bytes the last passing check read, with this rhi-gen
        _out(f"generated/ is up to date ({robots} robots)")
        return 0

    from .pipeline.generate import plan_generation
    from .pipeline.load import load_robots

    loaded = load_robots(proj)
    if not loaded:
        raise ProjectError("no robots found", file=proj.relative(proj.robots_dir), fix="add one with `rhi-gen new`")
    plan = plan_generation(proj, loaded)
    colour = _use_colour()
    stale = plan.stale
    if plan.old_manifest is None:
        _out(_bold("stale: generated/.rhi-gen-manifest is missing (never generated, or generated by an "
                   "older rhi-gen)", colour))
    else:
        if plan.other_version:
            _out(_bold(_version_line(plan.other_version, plan.generator_version), colour))
        _print_robot_diffs(stale, colour, prefix="stale: ")
    files = [c for c in plan.files if c.status != "unchanged"]
    _print_file_diffs(files, colour)
    if plan.manifest_change.status != "unchanged" and not stale and plan.old_manifest is not None \
            and not plan.other_version:
        _out("generated/.rhi-gen-manifest differs from what `rhi-gen generate` would write")
    for b in plan.blocked:
        _out(f"hand edit: {b.note()}")
    if not plan.differs and not stale:
        verified.record(proj, loaded, [c.path for c in plan.files], began)
        _out(f"generated/ is up to date ({len(loaded)} robots)")
        return 0
    _err(f"generated/ is stale: {len(stale)} robot(s) with changed inputs, {len(files)} file(s) differ; "
         "run `rhi-gen diff` to review, then `rhi-gen generate`")
    return 1


def inspect(*, urdf: Path, vendor: str | None, robot: str | None, xacro_arg: Sequence[str] | None,
            package_path: Sequence[str] | None) -> int:
    """Show actuated joints, types, limits, mimic joints and the suggested joint map."""
    from .inputs import wording
    from .inputs.inspect_report import inspect_text
    from .inputs.urdf_loader import load_urdf

    robot_model = load_urdf(urdf, xacro_args=_parse_pairs(xacro_arg, "--xacro-arg"),
                            package_paths={k: Path(v) for k, v in _parse_pairs(package_path, "--package-path").items()},
                            display_path=str(urdf), wording=wording.CLI)
    sys.stdout.write(inspect_text(robot_model, vendor=vendor, robot=robot))
    return 0


def list_robots(*, project: Path | None) -> int:
    """List the robots of the project."""
    from .project import robot_yamls

    proj = _project(project)
    for path in robot_yamls(proj):
        _out(f"{path.parent.name}/{path.stem}  ({proj.relative(path)})")
    return 0
