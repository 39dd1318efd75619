"""A FileChange as a unified diff, coloured for a person at a terminal."""
from __future__ import annotations

import difflib

from .changes import FileChange


def is_binary(data: bytes | None) -> bool:
    if data is None:
        return False
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return True
    return b"\0" in data


def unified_diff(change: FileChange, prefix: str = "") -> str:
    """The diff of ``change``; one line naming the file, as git words it, when either side is binary (a mesh)."""
    def lines(data: bytes | None) -> list[str]:
        return [] if data is None else data.decode("utf-8", "replace").splitlines(keepends=True)

    old_name = "/dev/null" if change.old is None else f"a/{prefix}{change.path}"
    new_name = "/dev/null" if change.new is None else f"b/{prefix}{change.path}"
    if is_binary(change.old) or is_binary(change.new):
        return f"Binary files {old_name} and {new_name} differ\n" if change.old != change.new else ""
    text = "".join(difflib.unified_diff(lines(change.old), lines(change.new), old_name, new_name))
    if not text and change.old != change.new:  # an empty file created or removed
        return f"Files {old_name} and {new_name} differ\n"
    if text and not text.endswith("\n"):
        text += "\n"
    return text


_ANSI = {"bold": "\x1b[1m", "red": "\x1b[31m", "green": "\x1b[32m", "cyan": "\x1b[36m", "reset": "\x1b[0m"}


def colour_diff(text: str) -> str:
    """ANSI colours for a unified diff (headers bold, hunks cyan, removals red, additions green)."""
    out = []
    for line in text.splitlines(keepends=True):
        body, nl = (line[:-1], "\n") if line.endswith("\n") else (line, "")
        if line.startswith(("+++ ", "--- ")):
            colour = "bold"
        elif line.startswith("@@"):
            colour = "cyan"
        elif line.startswith("+"):
            colour = "green"
        elif line.startswith("-"):
            colour = "red"
        else:
            out.append(line)
            continue
        out.append(f"{_ANSI[colour]}{body}{_ANSI['reset']}{nl}")
    return "".join(out)
