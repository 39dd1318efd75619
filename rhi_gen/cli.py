"""Command line: parse arguments, call the pipeline, print, map errors to exit codes.

Exit codes: 0 ok, 1 differences found (check/diff), 2 bad input (one line on stderr, nothing written),
3 internal error (a bug in rhi-gen; set RHI_GEN_DEBUG=1 for the traceback).

The pipeline is imported inside each command, so `--help` and `--version` stay fast.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from . import __version__
from .errors import InputWarning, ProjectError, RhiGenError
from .transports import DEFAULT as DEFAULT_TRANSPORT
from .transports import NAMES as TRANSPORT_NAMES

if TYPE_CHECKING:
    from .project import Project
    from .write.changes import FileChange
    from .write.semantic_diff import RobotDiff

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Generate complete ros2_control hardware interfaces from a URDF and a vendor YAML.")

ProjectOpt = Annotated[Path | None, typer.Option(
    "--project", "-C", help="Project folder holding robots/ and generated/ "
    "(default: the current folder or its nearest parent with robots/).")]
XacroArgOpt = Annotated[list[str] | None, typer.Option("--xacro-arg", help="NAME=VALUE, repeatable.")]
PackagePathOpt = Annotated[list[str] | None, typer.Option(
    "--package-path", help="PKG=DIR for $(find PKG), repeatable.")]
RobotsArg = Annotated[list[str] | None, typer.Argument(
    help="Robots (name or vendor/name); default: all.", show_default=False)]


def _err(text: str) -> None:
    typer.echo(text, err=True)


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


def _print_changes(changes: Sequence[FileChange], *, verbose: bool) -> dict[str, int]:
    counts = {"created": 0, "changed": 0, "unchanged": 0, "removed": 0}
    for c in changes:
        counts[c.status] += 1
        if c.status != "unchanged" or verbose:
            typer.echo(f"  {c.status:<9} {c.path}")
    return counts


def _summary(counts: dict[str, int], *, dry_run: bool = False) -> str:
    parts = ", ".join(f"{n} {k}" for k, n in counts.items())
    return f"summary: {parts}" + (" (would be written: dry run)" if dry_run else "")


@app.command()
def new(vendor: Annotated[str, typer.Option(help="Vendor name: C++ namespace and folder (e.g. unitree).")],
        robot: Annotated[str, typer.Option(help="Robot name: file stem (e.g. g1).")],
        urdf: Annotated[Path, typer.Option(help="The robot's URDF or .xacro file.")],
        transport: Annotated[str | None, typer.Option(
            help=f"{' | '.join(TRANSPORT_NAMES)} (default: the vendor's, else {DEFAULT_TRANSPORT}).")] = None,
        xacro_arg: XacroArgOpt = None,
        package_path: PackagePathOpt = None,
        force: Annotated[bool, typer.Option("--force", help="Overwrite an existing robot YAML.")] = False,
        class_prefix: Annotated[str | None, typer.Option(
            help="C++ class prefix (class NAMEHardwareInterface; default from --robot: my_arm -> MyArm), "
                 "written to the YAML as class_prefix:.")] = None,
        transport_option: Annotated[list[str] | None, typer.Option(
            "--transport-option", help="KEY=VALUE written under transport_options: (e.g. family=go for a "
                                       "Unitree robot rhi-gen does not know), repeatable.")] = None,
        project: ProjectOpt = None) -> None:
    """Create robots/VENDOR/ROBOT.yaml with a joint map suggested from the URDF, and generate it."""
    from .pipeline.new_robot import plan_new_robot
    from .write.transaction import apply

    proj = _project(project)
    plan = plan_new_robot(proj, vendor=vendor, robot=robot, urdf_path=urdf, transport=transport,
                          xacro_args=_parse_pairs(xacro_arg, "--xacro-arg"),
                          package_paths=_parse_pairs(package_path, "--package-path"), force=force,
                          class_prefix=class_prefix,
                          transport_options=_parse_pairs(transport_option, "--transport-option"))
    apply(proj.root, plan.changes)
    m = plan.robot.model
    typer.echo(f"wrote {plan.yaml_relpath}: {len(m.joints)} joints, {m.motor_count} motors, "
               f"transport {m.transport}, {m.float_type}")
    inputs = {plan.yaml_relpath}
    if plan.copy is not None:
        typer.echo(plan.copy.note(plan.yaml_relpath))
        inputs.add(plan.copy.rel)
    counts = _print_changes([c for c in plan.changes if c.path not in inputs], verbose=False)
    typer.echo(_summary(counts))
    typer.echo(f"next: review the joint_map in {plan.yaml_relpath}, then `rhi-gen generate`.")
    _warn(plan.warnings)


def _use_colour() -> bool:
    """Colour only for a person at a terminal: stdout is a TTY and NO_COLOR is not set."""
    return "NO_COLOR" not in os.environ and sys.stdout.isatty()


def _bold(text: str, colour: bool) -> str:
    return f"\x1b[1m{text}\x1b[0m" if colour else text


def _print_robot_diffs(diffs: Sequence[RobotDiff], colour: bool, prefix: str = "") -> None:
    for d in diffs:
        first, *rest = d.lines()
        typer.echo(_bold(prefix + first, colour))
        for line in rest:
            typer.echo(line)


def _print_file_diffs(changes: Sequence[FileChange], colour: bool) -> None:
    from .write.diff_text import colour_diff, unified_diff

    for c in changes:
        if c.status != "unchanged":
            text = unified_diff(c, prefix="generated/")
            sys.stdout.write(colour_diff(text) if colour else text)
    sys.stdout.flush()


FORCE_HELP = ("Overwrite generated files edited outside their user regions (or holding code in regions the "
              "templates dropped); each is first copied to generated/.rhi-gen-backup/<path>.N.")


def _version_line(old: str, new: str) -> str:
    return (f"generated/ was made by rhi-gen {old}, not by this rhi-gen {new}: `rhi-gen generate` records "
            "the new version and rewrites only files whose content changes")


@app.command()
def generate(robots: RobotsArg = None,
             dry_run: Annotated[bool, typer.Option("--dry-run", help="Show what would change, write nothing.")] = False,
             verbose: Annotated[bool, typer.Option(
                 "--verbose", "-v", help="Also list unchanged files and each robot YAML as it is loaded.")] = False,
             force: Annotated[bool, typer.Option("--force", help=FORCE_HELP)] = False,
             project: ProjectOpt = None) -> None:
    """(Re)generate generated/robot_hardware_interface from robots/*/*.yaml; writes only changed files.

    User-region contents are carried over byte for byte; a file edited outside its regions blocks
    the whole run (exit 2, nothing written) unless --force.
    """
    from .pipeline.existing_tags import existing_tag_warnings
    from .pipeline.generate import plan_generation
    from .pipeline.load import load_selected
    from .write.backups import BACKUP_DIR, BACKUP_MARKERS
    from .write.transaction import apply

    proj = _project(project)
    loaded, only = load_selected(proj, robots, progress=typer.echo if verbose else None)
    plan = plan_generation(proj, loaded, only, force=force)
    if plan.blocked and not force:
        if len(plan.blocked) > 1:  # the details on stdout; stderr gets the one error line
            for b in plan.blocked:
                typer.echo(f"blocked: {b.note()}")
        raise plan.blocked_error()
    counts = _print_changes([*plan.files, plan.manifest_change], verbose=verbose)
    if not dry_run:
        apply(proj.generated_dir, plan.changes)
    for c in plan.backups:
        if c.path not in BACKUP_MARKERS:
            original = c.path[len(BACKUP_DIR) + 1:].rsplit(".", 1)[0]
            typer.echo(f"  {'would keep' if dry_run else 'kept'} your version of {original} in generated/{c.path}")
    names = ", ".join(f"{r.model.vendor}/{r.model.robot} ({len(r.model.joints)} joints)" for r in loaded)
    typer.echo(f"robots: {names}")
    typer.echo(_summary(counts, dry_run=dry_run))
    _warn(existing_tag_warnings(loaded if only is None else only))


@app.command()
def diff(robots: RobotsArg = None, project: ProjectOpt = None) -> None:
    """Explain what `generate` would change: in robot terms first, then the unified file diff.

    Exit 0 when nothing would change, 1 when something would. Coloured on a terminal (unless NO_COLOR).
    """
    from .pipeline.generate import plan_generation
    from .pipeline.load import load_selected

    proj = _project(project)
    loaded, only = load_selected(proj, robots)
    plan = plan_generation(proj, loaded, only)
    colour = _use_colour()
    if plan.other_version:
        typer.echo(_version_line(plan.other_version, plan.generator_version))
    _print_robot_diffs(plan.robot_diffs, colour)
    files = [c for c in plan.files if c.status != "unchanged"]
    if files:
        typer.echo("")
    _print_file_diffs(files, colour)
    for b in plan.blocked:
        _err(f"note: `rhi-gen generate` would refuse: {b.note()} -> {b.fix}")
    if not plan.differs:
        _err("nothing to regenerate: generated/ matches the inputs")
        return
    extra = " and generated/.rhi-gen-manifest" if plan.manifest_change.status != "unchanged" else ""
    _err(f"{len(files)} file(s){extra} would change; run `rhi-gen generate"
         f"{' ' + ' '.join(robots) if robots else ''}` to write them")
    raise typer.Exit(1)


@app.command()
def check(project: ProjectOpt = None) -> None:
    """CI gate: exit 1 when generated/ is not what `generate` would write now.

    That is: a robot's inputs changed since the last generate (stale fingerprints in the manifest), a
    file differs, or another rhi-gen version wrote generated/. Prints why, then the unified diff.
    """
    from .pipeline.generate import plan_generation
    from .pipeline.load import load_robots

    proj = _project(project)
    loaded = load_robots(proj)
    if not loaded:
        raise ProjectError("no robots found", file=proj.relative(proj.robots_dir), fix="add one with `rhi-gen new`")
    plan = plan_generation(proj, loaded)
    colour = _use_colour()
    stale = plan.stale
    if plan.old_manifest is None:
        typer.echo(_bold("stale: generated/.rhi-gen-manifest is missing (never generated, or generated by an "
                         "older rhi-gen)", colour))
    else:
        if plan.other_version:
            typer.echo(_bold(_version_line(plan.other_version, plan.generator_version), colour))
        _print_robot_diffs(stale, colour, prefix="stale: ")
    files = [c for c in plan.files if c.status != "unchanged"]
    _print_file_diffs(files, colour)
    if plan.manifest_change.status != "unchanged" and not stale and plan.old_manifest is not None \
            and not plan.other_version:
        typer.echo("generated/.rhi-gen-manifest differs from what `rhi-gen generate` would write")
    for b in plan.blocked:
        typer.echo(f"hand edit: {b.note()}")
    if not plan.differs and not stale:
        typer.echo(f"generated/ is up to date ({len(loaded)} robots)")
        return
    _err(f"generated/ is stale: {len(stale)} robot(s) with changed inputs, {len(files)} file(s) differ; "
         "run `rhi-gen diff` to review, then `rhi-gen generate`")
    raise typer.Exit(1)


@app.command()
def inspect(urdf: Annotated[Path, typer.Option(help="URDF or .xacro file.")],
            vendor: Annotated[str | None, typer.Option(
                help="Suggest the map in this vendor's motor order.")] = None,
            robot: Annotated[str | None, typer.Option(help="Robot name for the vendor profile.")] = None,
            xacro_arg: XacroArgOpt = None,
            package_path: PackagePathOpt = None) -> None:
    """Show actuated joints, types, limits, mimic joints and the suggested joint map."""
    from .inputs import wording
    from .inputs.inspect_report import inspect_text
    from .inputs.urdf_loader import load_urdf

    robot_model = load_urdf(urdf, xacro_args=_parse_pairs(xacro_arg, "--xacro-arg"),
                            package_paths={k: Path(v) for k, v in _parse_pairs(package_path, "--package-path").items()},
                            display_path=str(urdf), wording=wording.CLI)
    sys.stdout.write(inspect_text(robot_model, vendor=vendor, robot=robot))


@app.command("list")
def list_robots(project: ProjectOpt = None) -> None:
    """List the robots of the project."""
    from .project import robot_yamls

    proj = _project(project)
    for path in robot_yamls(proj):
        typer.echo(f"{path.parent.name}/{path.stem}  ({proj.relative(path)})")


def _version(value: bool) -> None:
    if value:
        typer.echo(f"rhi-gen {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                                help="Print the version and exit.")] = False) -> None:
    """rhi-gen"""


def main(argv: list[str] | None = None) -> int:
    """Entry point: every RhiGenError is one line and exit 2; anything else is a bug (exit 3)."""
    try:
        # With standalone_mode=False click returns typer.Exit's code instead of raising it.
        code = app(args=argv, prog_name="rhi-gen", standalone_mode=False)
        return code if isinstance(code, int) else 0
    except typer.Exit as exc:
        return exc.exit_code
    except RhiGenError as exc:
        _err(f"error: {exc}")
        return exc.exit_code
    except KeyboardInterrupt:
        _err("interrupted; nothing half-written was left behind")
        return 130
    except Exception as exc:  # click usage errors and real bugs: both must end in an exit code
        # Typer ships click either as a dependency or vendored (typer._click): match by class name.
        names = {cls.__name__ for cls in type(exc).__mro__}
        if "Abort" in names:
            return 130
        if "NoArgsIsHelpError" in names:  # `rhi-gen` alone: the help was printed
            exc.show()  # type: ignore[attr-defined]
            return 2
        if "ClickException" in names:
            _err(_usage_line(exc))
            return 2
        if os.environ.get("RHI_GEN_DEBUG"):
            raise
        _err(f"internal error: {type(exc).__name__}: {exc} (a bug in rhi-gen; rerun with RHI_GEN_DEBUG=1 "
             "and report it)")
        return 3


def _usage_line(exc: Exception) -> str:
    """A usage error (missing or unknown option, no such command) as one line, like every other error."""
    message = " ".join(str(exc.format_message()).split()).rstrip(".")  # type: ignore[attr-defined]
    ctx = getattr(exc, "ctx", None)
    command = getattr(ctx, "command_path", None) or "rhi-gen"
    return f"error: {message} -> see `{command} --help`"


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
