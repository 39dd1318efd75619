"""Finding and running g++ for tests: a missing compiler fails the test, it never skips it."""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path
from typing import Iterable, Sequence

import pytest

REPO = Path(__file__).resolve().parents[1]
STANDINS_INCLUDE = REPO / "tests" / "cpp" / "standins" / "include"
WARNING_FLAGS = ("-std=c++17", "-Wall", "-Wextra", "-Werror")


def require_compiler() -> str:
    """Path of g++ (or $CXX). A test that needs it fails loudly when it is missing."""
    cxx = os.environ.get("CXX", "g++")
    path = shutil.which(cxx)
    if path is None:
        pytest.fail(f"C++ compiler {cxx!r} not found: install g++ (CI installs it in .ci/run); "
                    "C++ checks are never skipped")
    return path


def run_compiler(args: Sequence[str], *, what: str) -> subprocess.CompletedProcess:
    """Run g++ with ``args``; on failure the assertion message carries the compiler's first errors."""
    cmd = [require_compiler(), *args]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        errors = "\n".join(proc.stderr.splitlines()[:40])
        raise AssertionError(f"{what} does not compile:\n{' '.join(cmd)}\n{errors}")
    return proc


def driver_source(package_dir: Path, vendor: str, robot: str) -> Path:
    return package_dir / "src" / vendor / f"{robot}.cpp"


def include_flags(package_dir: Path, extra: Iterable[Path] = ()) -> list[str]:
    return [f"-I{package_dir / 'include'}", f"-I{STANDINS_INCLUDE}", *(f"-I{p}" for p in extra)]


def syntax_check_driver(package_dir: Path, vendor: str, robot: str, flags: Sequence[str] = ()) -> None:
    """Compile one generated driver against the stand-in headers with -Werror (no linking)."""
    source = driver_source(package_dir, vendor, robot)
    run_compiler([*WARNING_FLAGS, *flags, "-fsyntax-only", *include_flags(package_dir), str(source)],
                 what=f"{vendor}/{robot} driver")
