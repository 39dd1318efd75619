"""Command line: parse arguments, run the command (commands.py), map errors to exit codes.

Exit codes: 0 ok, 1 differences found (check/diff), 2 bad input (one line on stderr, nothing written),
3 internal error (a bug in rhi-gen; set RHI_GEN_DEBUG=1 for the traceback).

The parser is typer: its help layout, `rhi-gen COMMAND --help`, and shell completion
(`--install-completion`, `--show-completion`). Each command here only parses: it hands back the
commands.py function with its values, and main() runs it outside click, so every error reaches the
one mapping below. Click's usage errors become one line in the shape of every other error.
`rhi-gen check` runs as a pre-commit hook, so start-up stays short: help is plain text (rich is
never imported) and options are converted here rather than by typer's pydantic validators.
"""
# No `from __future__ import annotations` here, unlike every other module: typer reads these signatures,
# and annotations evaluated once at definition spare it evaluating their strings on every call (~5 ms).

import functools
import os
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Annotated, Any

import typer
from typer._click.exceptions import NoArgsIsHelpError, UsageError
from typer.core import TyperGroup

from . import __version__, commands
from .errors import RhiGenError
from .transports import DEFAULT as DEFAULT_TRANSPORT
from .transports import NAMES as TRANSPORT_NAMES

PROG = "rhi-gen"
DESCRIPTION = "Generate complete ros2_control hardware interfaces from a URDF and a vendor YAML."
FORCE_HELP = ("Overwrite generated files edited outside their user regions (or holding code in regions the "
              "templates dropped); each is first copied to generated/.rhi-gen-backup/<path>.N.")

Run = Callable[[], int]  # a command with its parsed values: main() runs it and returns its exit code

app = typer.Typer(name=PROG, help=DESCRIPTION, no_args_is_help=True, rich_markup_mode=None,
                  pretty_exceptions_enable=False, context_settings={"help_option_names": ["-h", "--help"]})

ProjectOpt = Annotated[Path | None, typer.Option(
    "--project", "-C", help="Project folder holding robots/ and generated/ (default: the current folder or its "
                            "nearest parent with robots/).", show_default=False)]
XacroArgOpt = Annotated[list[str] | None, typer.Option(
    "--xacro-arg", metavar="NAME=VALUE", help="A xacro argument, repeatable.", show_default=False)]
PackagePathOpt = Annotated[list[str] | None, typer.Option(
    "--package-path", metavar="PKG=DIR", help="PKG=DIR for $(find PKG), repeatable.", show_default=False)]
RobotsArg = Annotated[list[str] | None, typer.Argument(
    metavar="ROBOT", help="Robots (name or vendor/name); default: all.", show_default=False)]


def _version(value: bool) -> None:
    if value:
        typer.echo(f"{PROG} {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                                help="Print the version and exit.")] = False) -> None:
    """Only for --version: the commands below do the work."""


@app.command()
def new(vendor: Annotated[str, typer.Option(help="Vendor name: C++ namespace and folder (e.g. unitree).")],
        robot: Annotated[str, typer.Option(help="Robot name: file stem (e.g. g1).")],
        urdf: Annotated[Path, typer.Option(help="The robot's URDF or .xacro file.")],
        transport: Annotated[str | None, typer.Option(
            help=f"{' | '.join(TRANSPORT_NAMES)} (default: the vendor's, else {DEFAULT_TRANSPORT}).",
            show_default=False)] = None,
        xacro_arg: XacroArgOpt = None,
        package_path: PackagePathOpt = None,
        force: Annotated[bool, typer.Option("--force", help="Overwrite an existing robot YAML.")] = False,
        class_prefix: Annotated[str | None, typer.Option(
            help="C++ class prefix (class NAMEHardwareInterface; default from --robot: my_arm -> MyArm), "
                 "written to the YAML as class_prefix:.", show_default=False)] = None,
        transport_option: Annotated[list[str] | None, typer.Option(
            "--transport-option", metavar="KEY=VALUE", show_default=False,
            help="Written under transport_options: (e.g. family=go for a Unitree robot rhi-gen does not know), "
                 "repeatable.")] = None,
        project: ProjectOpt = None) -> Run:
    """Create robots/VENDOR/ROBOT.yaml with a joint map suggested from the URDF, and generate it."""
    return functools.partial(commands.new, vendor=vendor, robot=robot, urdf=urdf, transport=transport,
                             xacro_arg=xacro_arg, package_path=package_path, force=force,
                             class_prefix=class_prefix, transport_option=transport_option, project=project)


@app.command()
def generate(robots: RobotsArg = None,
             dry_run: Annotated[bool, typer.Option("--dry-run", help="Show what would change, write nothing.")] = False,
             verbose: Annotated[bool, typer.Option(
                 "--verbose", "-v", help="Also list unchanged files and each robot YAML as it is loaded.")] = False,
             force: Annotated[bool, typer.Option("--force", help=FORCE_HELP)] = False,
             project: ProjectOpt = None) -> Run:
    """(Re)generate generated/robot_hardware_interface from robots/*/*.yaml; writes only changed files.

    User-region contents are carried over byte for byte; a file edited outside its regions blocks
    the whole run (exit 2, nothing written) unless --force.
    """
    return functools.partial(commands.generate, robots=robots or None, dry_run=dry_run, verbose=verbose,
                             force=force, project=project)


@app.command()
def diff(robots: RobotsArg = None, project: ProjectOpt = None) -> Run:
    """Explain what `generate` would change: in robot terms first, then the unified file diff.

    Exit 0 when nothing would change, 1 when something would. Coloured on a terminal (unless NO_COLOR).
    """
    return functools.partial(commands.diff, robots=robots or None, project=project)


@app.command()
def check(project: ProjectOpt = None) -> Run:
    """CI gate: exit 1 when generated/ is not what `generate` would write now.

    That is: a robot's inputs changed since the last generate (stale fingerprints in the manifest), a
    file differs, or another rhi-gen version wrote generated/. Prints why, then the unified diff.
    """
    return functools.partial(commands.check, project=project)


@app.command()
def inspect(urdf: Annotated[Path, typer.Option(help="URDF or .xacro file.")],
            vendor: Annotated[str | None, typer.Option(
                help="Suggest the map in this vendor's motor order.", show_default=False)] = None,
            robot: Annotated[str | None, typer.Option(
                help="Robot name for the vendor profile.", show_default=False)] = None,
            xacro_arg: XacroArgOpt = None,
            package_path: PackagePathOpt = None) -> Run:
    """Show actuated joints, types, limits, mimic joints and the suggested joint map."""
    return functools.partial(commands.inspect, urdf=urdf, vendor=vendor, robot=robot, xacro_arg=xacro_arg,
                             package_path=package_path)


@app.command("list")
def list_robots(project: ProjectOpt = None) -> Run:
    """List the robots of the project."""
    return functools.partial(commands.list_robots, project=project)


class _PlainValue:
    """Converts an option's text to str or Path as typer would, without the pydantic validator typer
    builds for every option it converts (pydantic's import alone is about 0.1 s on each call)."""

    def __init__(self, convert: Callable[[str], Any]) -> None:
        self.convert = convert

    def coerce(self, value: Any, param: Any, ctx: Any) -> Any:
        if param.multiple or param.nargs == -1:
            return tuple(self.convert(v) for v in value or ())
        return None if value is None else self.convert(value)


_PLAIN = {str: _PlainValue(str), Path: _PlainValue(Path), bool: _PlainValue(bool)}


def _plain_values(command: typer.core.TyperCommand | TyperGroup, ctx: typer.Context) -> None:
    """Give every option of ``command`` and its subcommands, --help included, the plain conversion of its type.

    Sets typer's lazily built `_runtime_param`; should a typer release drop it, typer's own conversion runs.
    """
    for param in command.get_params(ctx):
        item = _one_value_type(getattr(getattr(param, "type_descriptor", None), "annotation", None))
        if item in _PLAIN and getattr(param, "_runtime_param", ...) is None:
            param._runtime_param = _PLAIN[item]  # type: ignore[attr-defined]
    for name, sub in getattr(command, "commands", {}).items():
        _plain_values(sub, typer.Context(sub, parent=ctx, info_name=name))


def _one_value_type(annotation: Any) -> Any:
    """str for str, list[str] and str | None: the type of one value."""
    args = [a for a in getattr(annotation, "__args__", ()) if a is not type(None)]
    return args[0] if len(args) == 1 else annotation


@functools.cache
def _click_command() -> TyperGroup:
    """The click command typer builds from `app` (with the completion options), its options made plain."""
    command = typer.main.get_command(app)
    assert isinstance(command, TyperGroup)
    _plain_values(command, typer.Context(command, info_name=PROG, **command.context_settings))
    return command


def _usage_line(exc: UsageError, argv: Sequence[str]) -> str:
    """A click usage error (missing or unknown option, no such command) as one line, like every other error.

    Click leaves out the command of an option that lacks its value (or has one it takes none): that is
    the command named first on the line.
    """
    message = " ".join(exc.format_message().split()).rstrip(".")
    if exc.ctx is not None:
        command = exc.ctx.command_path
    else:
        first = next((a for a in argv if not a.startswith("-")), "")
        command = f"{PROG} {first}" if first in _click_command().commands else PROG
    return f"error: {message} -> see `{command} --help`"


def _parse(argv: Sequence[str]) -> Run | int:
    """The command to run with its values, or the exit code of what click already did (help, version)."""
    try:
        parsed: Run | int | None = _click_command().main(args=argv, prog_name=PROG, standalone_mode=False)
    except NoArgsIsHelpError as exc:  # `rhi-gen` alone: the help on stdout, and the exit code of a usage error
        typer.echo(exc.format_message())
        return 2
    return 0 if parsed is None else parsed


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: every RhiGenError is one line and exit 2; anything else is a bug (exit 3)."""
    args = sys.argv[1:] if argv is None else list(argv)
    try:
        run = _parse(args)
        return run if isinstance(run, int) else run()
    except SystemExit as exc:  # --install-completion and --show-completion print and exit 0
        return exc.code if isinstance(exc.code, int) else 0
    except UsageError as exc:
        sys.stderr.write(_usage_line(exc, args) + "\n")
        return 2
    except RhiGenError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return exc.exit_code
    except KeyboardInterrupt:
        sys.stderr.write("interrupted; nothing half-written was left behind\n")
        return 130
    except Exception as exc:  # a bug: one line, the traceback only on request
        if os.environ.get("RHI_GEN_DEBUG"):
            raise
        sys.stderr.write(f"internal error: {type(exc).__name__}: {exc} (a bug in rhi-gen; rerun with "
                         "RHI_GEN_DEBUG=1 and report it)\n")
        return 3


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
