"""Driving rhi-gen as a user does, and the contract every rejection must keep.

``run_cli`` runs the console script's own entry point (main()) in this process; ``assert_rejected`` is
the whole contract of bad input (exit 2, exactly one ``error: <file>[:<line>]: [<key>: ]<what> -> <fix>``
line); ``snapshot`` hashes a tree, so equal snapshots mean a rejected command touched nothing.
"""
from __future__ import annotations

import contextlib
import hashlib
import io
import os
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

from rhi_gen.cli import main
from tests.support.repo import HOSTILE

YAML_REL = "robots/acme/arm.yaml"
URDF_REL = "robots/acme/arm.urdf"


@dataclass(frozen=True)
class CliResult:
    code: int
    out: str
    err: str

    @property
    def error_lines(self) -> list[str]:
        """Every line on stderr: for bad input that must be exactly the one error line (no progress lines)."""
        return [line for line in self.err.splitlines() if line.strip()]


def run_cli(*args: str | os.PathLike) -> CliResult:
    """``rhi-gen ARGS`` in this process (the console script's own entry point, main())."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([str(a) for a in args])
    return CliResult(code, out.getvalue(), err.getvalue())


def snapshot(root: Path) -> dict[str, str]:
    """Every file (sha256) and folder under ``root``: equal snapshots mean nothing was touched."""
    state: dict[str, str] = {}
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root).as_posix()
        if path.is_symlink():
            state[rel] = f"link:{os.readlink(path)}"
        elif path.is_dir():
            state[rel + "/"] = "dir"
        else:
            state[rel] = hashlib.sha256(path.read_bytes()).hexdigest()
    return state


ANY_LINE = -1  # for assert_rejected(line=...): some line number, whichever


def assert_rejected(result: CliResult, *, file: str, line: int | None = None, key: str | None = None,
                    words: tuple[str, ...] = ()) -> str:
    """The rejection contract; returns the error line for further checks.

    ``line=None`` asserts the message has no line number, ``line=ANY_LINE`` that it has one.
    """
    assert result.code == 2, f"expected exit 2, got {result.code}\nstdout: {result.out}\nstderr: {result.err}"
    assert "Traceback" not in result.err + result.out
    lines = result.error_lines
    assert len(lines) == 1, f"expected one error line, got {lines!r}"
    message = lines[0]
    where = re.escape(file) + (r":\d+" if line == ANY_LINE else f":{line}" if line is not None else "")
    head = re.match(rf"error: {where}: ", message)
    assert head, f"{message!r} does not start with 'error: {file}{'' if line is None else f':{line}'}: '"
    rest = message[head.end():]
    if line is None:
        assert not re.match(r"\d+: ", rest), f"unexpected line number in {message!r}"
    if key is not None:
        assert rest.startswith(f"{key}: "), f"{message!r} does not name key {key!r}"
    assert " -> " in rest and rest.rsplit(" -> ", 1)[1].strip(), f"no fix in {message!r}"
    for word in words:
        assert word in message, f"{word!r} not in {message!r}"
    return message


def write_project(root: Path, urdf_text: str | None = None, yaml_text: str | None = None,
                  urdf_name: str = "arm.urdf") -> Path:
    robots = root / "robots" / "acme"
    robots.mkdir(parents=True, exist_ok=True)
    (robots / urdf_name).write_text(urdf_text if urdf_text is not None else (HOSTILE / "arm.urdf").read_text())
    (robots / "arm.yaml").write_text(yaml_text if yaml_text is not None else (HOSTILE / "arm.yaml").read_text())
    return root


def generate_rejected(root: Path, **expect) -> str:
    """Run `generate` on ``root`` (inputs already broken) and check the rejection contract."""
    before = snapshot(root)
    outside = snapshot(root.parent)
    message = assert_rejected(run_cli("generate", "--project", root), **expect)
    assert snapshot(root) == before, "a rejected `generate` changed files in the project"
    assert snapshot(root.parent) == outside
    return message


def new_rejected(root: Path, *args: str | os.PathLike, **expect) -> str:
    """Run `rhi-gen new ARGS --project root` and check the rejection contract."""
    root.mkdir(parents=True, exist_ok=True)
    before = snapshot(root)
    outside = snapshot(root.parent)
    message = assert_rejected(run_cli("new", *args, "--project", root), **expect)
    assert snapshot(root) == before, "a rejected `new` changed files in the project"
    assert snapshot(root.parent) == outside, "a rejected `new` wrote outside the project"
    return message


def replace_once(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def edit_yaml(root: Path, old: str, new: str) -> None:
    path = root / YAML_REL
    path.write_text(replace_once(path.read_text(), old, new))


def cli(capsys: pytest.CaptureFixture[str], root: Path, *args: str) -> tuple[int, str, str]:
    """``rhi-gen ARGS --project root`` through main(), its output read from ``capsys``: (exit, stdout, stderr)."""
    capsys.readouterr()
    code = main([*args, "--project", str(root)])
    out = capsys.readouterr()
    return code, out.out, out.err


def tree(root: Path) -> dict[str, bytes]:
    """Every file under root (inputs, outputs, backups, temp files): the whole state, byte for byte."""
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}
