"""One error hierarchy for everything a user can get wrong.

Library code raises these; only the CLI turns them into exit codes, so a bad input is always one
clear line (file, line or key, what to do) and never a traceback.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


def one_line(message: str, *, file: str | None = None, line: int | None = None, key: str | None = None,
             fix: str | None = None) -> str:
    """``file:line: key: message -> fix``, the shape of every error and warning rhi-gen prints."""
    where = ""
    if file:
        where = file
        if line:
            where += f":{line}"
        where += ": "
    text = f"{where}{f'{key}: ' if key else ''}{message}"
    if fix:
        text += f" -> {fix}"
    # One line, always: a message built from hostile input must not break the terminal output.
    return " ".join(text.replace("\r", " ").split("\n"))


@dataclass(frozen=True)
class InputWarning:
    """Input rhi-gen accepts but the user must know about; ``str()`` is the one line shown (after
    ``warning: ``), in the shape of an error. Commands print it and still succeed (exit 0)."""
    message: str
    file: str | None = None
    line: int | None = None
    key: str | None = None
    fix: str | None = None

    def __str__(self) -> str:
        return one_line(self.message, file=self.file, line=self.line, key=self.key, fix=self.fix)


class RhiGenError(Exception):
    """Base class. ``str(err)`` is the single line shown to the user."""

    exit_code = 2

    def __init__(self, message: str, *, file: str | Path | None = None, line: int | None = None,
                 key: str | None = None, fix: str | None = None) -> None:
        self.message = message
        self.file = str(file) if file is not None else None
        self.line = line
        self.key = key
        self.fix = fix
        super().__init__(self.render())

    def render(self) -> str:
        return one_line(self.message, file=self.file, line=self.line, key=self.key, fix=self.fix)


class InputError(RhiGenError):
    """A URDF, xacro or vendor YAML the user gave us is wrong."""


class UrdfError(InputError):
    """The robot description cannot be read or is not a valid URDF."""


class ConfigError(InputError):
    """The vendor YAML is missing, malformed or inconsistent with the URDF."""


class ProjectError(InputError):
    """The project layout (robots/, generated/) is not what the command needs."""


class ManifestError(RhiGenError):
    """generated/.rhi-gen-manifest cannot be read."""


class RegionError(RhiGenError):
    """User-region markers of a file are broken (unbalanced, nested, duplicated or malformed)."""


class GenerationError(RhiGenError):
    """Rendering failed (a template bug); nothing was written."""


class WriteBlockedError(RhiGenError):
    """Writing would destroy a hand edit; nothing was written."""


class WriteError(RhiGenError):
    """The disk refused a write; every file was restored."""
