"""What one xacro expansion was asked to do, and how its messages name files.

Every message about a failed expansion names the file the user knows: the top file as they named
it (``display_path``), any other file by its real path relative to the same base, never as
``$(find pkg)/...``, so the path in a message is the path that was tried.
"""
from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass

from .wording import Wording

__all__ = ["Displayer", "XacroRun"]


class Displayer:
    """Shows files by their real path, the way the user names the top file: the top file as
    ``display_path``; any other file relative to the same base as ``display_path`` (so
    ``robots/acme/parts/leg.xacro`` next to ``robots/acme/arm.urdf.xacro``, a package folder in
    the project as ``pkgs/mypkg/urdf/leg.xacro``) unless that climbs out of the base, then absolute."""

    def __init__(self, top_abs: str, shown: str) -> None:
        self.top_abs = os.path.normpath(top_abs)
        self.top_dir = os.path.dirname(self.top_abs)
        self.shown = shown
        self.shown_dir = os.path.dirname(shown)

    def __call__(self, file: str | None) -> str:
        if not file:
            return self.shown
        path = os.path.normpath(os.path.abspath(file))
        if path == self.top_abs:
            return self.shown
        if os.path.isabs(self.shown):
            return path
        try:
            rel = os.path.relpath(path, self.top_dir)
        except ValueError:  # different drives (Windows)
            return path
        joined = os.path.normpath(os.path.join(self.shown_dir, rel))
        if joined == os.pardir or joined.startswith(os.pardir + os.sep):
            return path
        return joined.replace(os.sep, "/")


@dataclass(frozen=True)
class XacroRun:
    """What one expansion was asked to do: for messages about what went wrong."""
    shown: str                      # the top file as the user names it
    show: Displayer
    wording: Wording
    args: Mapping[str, str]
    packages: Mapping[str, str]     # package -> absolute directory
    given: Mapping[str, str]        # package -> directory as the user wrote it
