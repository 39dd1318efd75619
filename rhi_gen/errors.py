"""One error hierarchy for everything a user can get wrong.

Library code raises these; only the CLI turns them into exit codes, so a bad input is always one
clear line (file, line or key, what to do) and never a traceback.
"""
from __future__ import annotations

from pathlib import Path


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
        where = ""
        if self.file:
            where = self.file
            if self.line:
                where += f":{self.line}"
            where += ": "
        key = f"{self.key}: " if self.key else ""
        text = f"{where}{key}{self.message}"
        if self.fix:
            text += f" -> {self.fix}"
        # One line, always: a message built from hostile input must not break the terminal output.
        return " ".join(text.replace("\r", " ").split("\n"))


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
