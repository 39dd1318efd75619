"""Command line: parse arguments, run the command (commands.py), map errors to exit codes.

Exit codes: 0 ok, 1 differences found (check/diff), 2 bad input (one line on stderr, nothing written),
3 internal error (a bug in rhi-gen; set RHI_GEN_DEBUG=1 for the traceback).

The parser is the standard library's argparse: `rhi-gen check` runs as a pre-commit hook, and a
command-line framework's import time (typer with click and pydantic: about 0.3 s) would be most of
its cost. Usage errors are reworded into one line in the shape of every other error.
"""
from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, NoReturn

from . import __version__, commands
from .errors import RhiGenError
from .transports import DEFAULT as DEFAULT_TRANSPORT
from .transports import NAMES as TRANSPORT_NAMES

PROG = "rhi-gen"
DESCRIPTION = "Generate complete ros2_control hardware interfaces from a URDF and a vendor YAML."
FORCE_HELP = ("Overwrite generated files edited outside their user regions (or holding code in regions the "
              "templates dropped); each is first copied to generated/.rhi-gen-backup/<path>.N.")


class UsageError(Exception):
    """A command line argparse refused, in click's familiar words, with the command whose help to read."""

    def __init__(self, message: str, command: str) -> None:
        super().__init__(message)
        self.command = command

    def line(self) -> str:
        return f"error: {self} -> see `{self.command} --help`"


def _reword(message: str) -> str:
    """argparse's message as one short sentence ("Missing option '--robot'", "No such option: --bogus")."""
    if message.startswith("the following arguments are required: "):
        first = message.split(": ", 1)[1].split(", ")[0]
        return f"Missing option '{first}'" if first.startswith("-") else f"Missing argument '{first.upper()}'"
    if message.startswith("argument COMMAND: invalid choice: "):
        return f"No such command {message.split(': ')[2].split(' ')[0]}"
    if message.startswith("argument ") and message.endswith(": expected one argument"):
        return f"Option '{message[len('argument '):].split(':')[0].split('/')[0]}' requires an argument"
    return message[:1].upper() + message[1:]


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        raise UsageError(_reword(message), self.prog)


def _add_project(p: argparse.ArgumentParser) -> None:
    p.add_argument("--project", "-C", type=Path, help="Project folder holding robots/ and generated/ (default: the "
                   "current folder or its nearest parent with robots/).")


def _add_xacro(p: argparse.ArgumentParser) -> None:
    p.add_argument("--xacro-arg", action="append", metavar="NAME=VALUE", help="A xacro argument, repeatable.")
    p.add_argument("--package-path", action="append", metavar="PKG=DIR", help="PKG=DIR for $(find PKG), repeatable.")


def _add_robots(p: argparse.ArgumentParser) -> None:
    p.add_argument("robots", nargs="*", metavar="ROBOT", help="Robots (name or vendor/name); default: all.")


def _command(sub: Any, name: str, run: Callable[..., int], summary: str, details: str = "") -> argparse.ArgumentParser:
    p: argparse.ArgumentParser = sub.add_parser(name, help=summary, description=f"{summary}\n\n{details}".strip(),
                                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                                allow_abbrev=False)
    p.set_defaults(run=run)
    return p


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=PROG, description=DESCRIPTION, allow_abbrev=False)
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}",
                        help="Print the version and exit.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    p = _command(sub, "new", commands.new,
                 "Create robots/VENDOR/ROBOT.yaml with a joint map suggested from the URDF, and generate it.")
    p.add_argument("--vendor", required=True, help="Vendor name: C++ namespace and folder (e.g. unitree).")
    p.add_argument("--robot", required=True, help="Robot name: file stem (e.g. g1).")
    p.add_argument("--urdf", required=True, type=Path, help="The robot's URDF or .xacro file.")
    p.add_argument("--transport", help=f"{' | '.join(TRANSPORT_NAMES)} (default: the vendor's, else "
                   f"{DEFAULT_TRANSPORT}).")
    _add_xacro(p)
    p.add_argument("--force", action="store_true", help="Overwrite an existing robot YAML.")
    p.add_argument("--class-prefix", help="C++ class prefix (class NAMEHardwareInterface; default from --robot: "
                   "my_arm -> MyArm), written to the YAML as class_prefix:.")
    p.add_argument("--transport-option", action="append", metavar="KEY=VALUE",
                   help="Written under transport_options: (e.g. family=go for a Unitree robot rhi-gen does not "
                        "know), repeatable.")
    _add_project(p)

    p = _command(sub, "generate", commands.generate,
                 "(Re)generate generated/robot_hardware_interface from robots/*/*.yaml; writes only changed files.",
                 "User-region contents are carried over byte for byte; a file edited outside its regions blocks\n"
                 "the whole run (exit 2, nothing written) unless --force.")
    _add_robots(p)
    p.add_argument("--dry-run", action="store_true", help="Show what would change, write nothing.")
    p.add_argument("--verbose", "-v", action="store_true",
                   help="Also list unchanged files and each robot YAML as it is loaded.")
    p.add_argument("--force", action="store_true", help=FORCE_HELP)
    _add_project(p)

    p = _command(sub, "diff", commands.diff,
                 "Explain what `generate` would change: in robot terms first, then the unified file diff.",
                 "Exit 0 when nothing would change, 1 when something would. Coloured on a terminal (unless\n"
                 "NO_COLOR).")
    _add_robots(p)
    _add_project(p)

    p = _command(sub, "check", commands.check,
                 "CI gate: exit 1 when generated/ is not what `generate` would write now.",
                 "That is: a robot's inputs changed since the last generate (stale fingerprints in the\n"
                 "manifest), a file differs, or another rhi-gen version wrote generated/. Prints why, then the\n"
                 "unified diff.")
    _add_project(p)

    p = _command(sub, "inspect", commands.inspect,
                 "Show actuated joints, types, limits, mimic joints and the suggested joint map.")
    p.add_argument("--urdf", required=True, type=Path, help="URDF or .xacro file.")
    p.add_argument("--vendor", help="Suggest the map in this vendor's motor order.")
    p.add_argument("--robot", help="Robot name for the vendor profile.")
    _add_xacro(p)

    p = _command(sub, "list", commands.list_robots, "List the robots of the project.")
    _add_project(p)
    return parser


def _run(argv: Sequence[str]) -> int:
    parser = build_parser()
    if not argv:  # `rhi-gen` alone: the help, and the exit code of a usage error
        parser.print_help()
        return 2
    args, extra = parser.parse_known_args(argv)
    command = f"{PROG} {args.command}" if args.command else PROG
    if extra:
        unknown = next((a for a in extra if a.startswith("-")), None)
        raise UsageError(f"No such option: {unknown}" if unknown else f"Got unexpected extra argument ({extra[0]})",
                         command)
    if args.command is None:
        raise UsageError("Missing command", PROG)
    values = {k: v for k, v in vars(args).items() if k not in ("command", "run")}
    if "robots" in values:
        values["robots"] = values["robots"] or None
    code: int = args.run(**values)
    return code


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: every RhiGenError is one line and exit 2; anything else is a bug (exit 3)."""
    try:
        return _run(sys.argv[1:] if argv is None else list(argv))
    except SystemExit as exc:  # --help and --version print and exit 0
        return exc.code if isinstance(exc.code, int) else 0
    except UsageError as exc:
        sys.stderr.write(exc.line() + "\n")
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
