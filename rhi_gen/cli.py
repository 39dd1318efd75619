"""Command line: parse arguments, run the command (commands.py), map errors to exit codes.

Exit codes: 0 ok, 1 differences found (check/diff), 2 bad input (one line on stderr, nothing written),
3 internal error (a bug in rhi-gen; set RHI_GEN_DEBUG=1 for the traceback).

The parser is typer, used through its public names only (typer.Typer, typer.Option, typer.Context,
typer.main.get_command, typer.core's command classes, typer.TyperException; no private module of typer, no
private attribute): its help layout, `rhi-gen COMMAND --help`, and shell completion
(`--install-completion`, `--show-completion`, which also take the shell's name: `--show-completion bash`).
Each command here only parses: it hands back the commands.py function with its values, and main() runs
it outside click, so every error reaches the one mapping below. Click's usage errors (typer.TyperException
and its kin) become one line in the shape of every other error. `rhi-gen check` runs as a pre-commit
hook, so start-up stays short: help is plain text (rich is never imported) and the transport registry
is imported only to show `rhi-gen new --help`. typer converts every option value through pydantic
(about 0.09 s of start-up) and offers no public way around it.
"""
# No `from __future__ import annotations` here, unlike every other module: typer reads these signatures,
# and annotations evaluated once at definition spare it evaluating their strings on every call (~5 ms).

import contextlib
import functools
import itertools
import os
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Annotated, Any

import typer
import typer.completion
from typer.core import TyperCommand, TyperGroup

from . import __version__, commands
from .errors import RhiGenError

PROG = "rhi-gen"
DESCRIPTION = "Generate complete ros2_control hardware interfaces from a URDF and a vendor YAML."
FORCE_HELP = ("Overwrite generated files edited outside their user regions (or holding code in regions the "
              "templates dropped); each is first copied to generated/.rhi-gen-backup/<path>.N.")

Run = Callable[[], int]  # a command with its parsed values: main() runs it and returns its exit code

app = typer.Typer(name=PROG, help=DESCRIPTION, rich_markup_mode=None,
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


class _NewCommand(TyperCommand):
    """`rhi-gen new`, whose --transport help lists the transports: the registry (rhi_gen.transports, which
    imports every transport, the model and the validator, 60 ms) is read only when that help is shown."""

    def format_help(self, ctx: Any, formatter: Any) -> None:  # click's Context and HelpFormatter
        from .transports import DEFAULT, NAMES

        for param in self.params:
            if param.name == "transport":
                param.help = f"{' | '.join(NAMES)} (default: the vendor's, else {DEFAULT})."  # type: ignore[attr-defined]
        super().format_help(ctx, formatter)


@app.command(cls=_NewCommand)
def new(vendor: Annotated[str, typer.Option(help="Vendor name: C++ namespace and folder (e.g. unitree).")],
        robot: Annotated[str, typer.Option(help="Robot name: file stem (e.g. g1).")],
        urdf: Annotated[Path, typer.Option(help="The robot's URDF or .xacro file.")],
        transport: Annotated[str | None, typer.Option(
            help="The transport (docs/transports.md; default: the vendor's).", show_default=False)] = None,
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


SHELLS = ("bash", "zsh", "fish", "powershell", "pwsh")  # what typer's completion scripts are written for


def _completion_with_named_shell(typer_callback: Callable[..., Any], ctx: typer.Context, param: Any,
                                 value: Any) -> Any:
    """typer's --install-completion / --show-completion, given the shell named right after the flag.

    typer's flags take no value: they ask shellingham which shell is the parent process, and ignore
    the `bash` of `rhi-gen --show-completion bash`. Without a shell above rhi-gen (nohup, setsid, cron,
    an IDE, `bash -c` exec'ing its one command) that fails ("Shell  not supported."). typer's callbacks take
    a shell name as their value (they do for the flag's non-detecting form), so the named one is handed
    on; a flag alone still asks shellingham. Should a typer release rename these options, the flags
    work as typer's own again (tests/cli/test_cli.py's detached completion test then fails).
    """
    if value and not ctx.resilient_parsing:
        words = list(ctx.find_root().obj or ())
        named = [after for flag, after in itertools.pairwise(words) if flag in param.opts and after in SHELLS]
        value = named[0] if named else value
    return typer_callback(ctx, param, value)


@functools.cache
def _click_command() -> TyperGroup:
    """The click command typer builds from `app` (public typer.main.get_command), with the completion
    options honouring a named shell."""
    command = typer.main.get_command(app)
    assert isinstance(command, TyperGroup)
    for param in command.params:
        if param.name in ("install_completion", "show_completion") and param.callback is not None:
            param.callback = functools.partial(_completion_with_named_shell, param.callback)
    return command


def _usage_line(exc: typer.TyperException, argv: Sequence[str]) -> str:
    """A click usage error (missing or unknown option, no such command) as one line, like every other error.

    Click leaves out the command of an option that lacks its value (or has one it takes none): that is
    the command named first on the line.
    """
    message = " ".join(exc.format_message().split()).rstrip(".")
    ctx = getattr(exc, "ctx", None)  # click's UsageError carries the context of the command it was parsing
    if ctx is not None:
        command = ctx.command_path
    else:
        first = next((a for a in argv if not a.startswith("-")), "")
        command = f"{PROG} {first}" if first in _click_command().commands else PROG
    return f"error: {message} -> see `{command} --help`"


def _parse(argv: Sequence[str]) -> Run | int:
    """The command to run with its values, or the exit code of what click already did (help, version).

    The words are handed to the root context (ctx.obj) for the completion flags' shell name.
    """
    parsed: Run | int | None = _click_command().main(args=list(argv), prog_name=PROG, standalone_mode=False,
                                                      obj=tuple(argv))
    return 0 if parsed is None else parsed


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: every RhiGenError is one line and exit 2; anything else is a bug (exit 3)."""
    args = sys.argv[1:] if argv is None else list(argv)
    if not args:  # `rhi-gen` alone: the help on stdout, and the exit code of a usage error
        _parse(["--help"])
        return 2
    try:
        run = _parse(args)
        return run if isinstance(run, int) else run()
    except SystemExit as exc:  # --install-completion and --show-completion print and exit 0
        return exc.code if isinstance(exc.code, int) else 0
    except typer.TyperException as exc:  # only click raises these: a usage error (run() is outside click)
        sys.stderr.write(_usage_line(exc, args) + "\n")
        return 2
    except RhiGenError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return exc.exit_code
    except KeyboardInterrupt:
        sys.stderr.write("interrupted; nothing half-written was left behind\n")
        return 130
    except BrokenPipeError:  # the reader went away (`rhi-gen diff | head`): stop quietly, as on SIGPIPE
        _silence_stdout()
        return 141
    except Exception as exc:  # a bug: one line, the traceback only on request
        if os.environ.get("RHI_GEN_DEBUG"):
            raise
        sys.stderr.write(f"internal error: {type(exc).__name__}: {exc} (a bug in rhi-gen; rerun with "
                         "RHI_GEN_DEBUG=1 and report it)\n")
        return 3


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so the interpreter's last flush into the closed pipe raises nothing."""
    with contextlib.suppress(OSError, ValueError, AttributeError):
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
