"""Finding and running g++ for tests: a missing compiler fails the test, it never skips it."""
from __future__ import annotations

import os
import shutil

import pytest


def require_compiler() -> str:
    """Path of g++ (or $CXX). A test that needs it fails loudly when it is missing."""
    cxx = os.environ.get("CXX", "g++")
    path = shutil.which(cxx)
    if path is None:
        pytest.fail(f"C++ compiler {cxx!r} not found: install g++ (CI installs it in .ci/run); "
                    "C++ checks are never skipped")
    return path
