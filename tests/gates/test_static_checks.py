"""The gates: ruff and mypy (configured in pyproject.toml) are clean, so `.ci/run` enforces them."""
from __future__ import annotations

import subprocess
import sys

from tests.support.repo import REPO


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", *args], cwd=REPO, capture_output=True, text=True, timeout=600)


def test_ruff_is_clean():
    result = _run("ruff", "check", "--no-cache", "rhi_gen", "benchmarks", "scripts", "tests")
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_is_clean():
    # files and flags: pyproject.toml (rhi_gen strict; tests, benchmarks and scripts through an override)
    result = _run("mypy", "--no-incremental", "--cache-dir", "/dev/null")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Success: no issues found" in result.stdout
