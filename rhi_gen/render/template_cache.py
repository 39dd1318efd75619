"""Compiled templates kept between runs, so `rhi-gen check` (a pre-commit hook) answers at once.

Compiling every template is most of what an unchanged project's check costs. Jinja's bytecode
cache keys each entry by the template's name and a checksum of its source; the folder name adds
what else decides the compiled code: the Jinja and Python versions and this package's Environment
settings (render/environment.py's bytes). A cache that cannot be read or written (read-only home,
no space) is skipped silently: it only ever saves time, it never changes output.
"""
from __future__ import annotations

import contextlib
import hashlib
import sys
from pathlib import Path

import jinja2
from jinja2.bccache import Bucket

from ..cache import cache_root

ENVIRONMENT_SOURCE = Path(__file__).with_name("environment.py")


class _ForgivingCache(jinja2.FileSystemBytecodeCache):
    """A FileSystemBytecodeCache whose failures cost a recompilation, never an error."""

    def load_bytecode(self, bucket: Bucket) -> None:
        try:
            super().load_bytecode(bucket)
        except (OSError, EOFError, ValueError):
            bucket.reset()

    def dump_bytecode(self, bucket: Bucket) -> None:
        with contextlib.suppress(OSError):
            super().dump_bytecode(bucket)


def cache_folder() -> Path:
    """``$RHI_GEN_CACHE`` or ``$XDG_CACHE_HOME/rhi-gen`` (``~/.cache/rhi-gen``), then the key folder."""
    key = hashlib.sha256(ENVIRONMENT_SOURCE.read_bytes())
    key.update(f"{jinja2.__version__} {sys.implementation.cache_tag}".encode())
    return cache_root() / "templates" / key.hexdigest()[:16]


def compiled_template_cache() -> jinja2.BytecodeCache | None:
    """The cache, or None (compile every time) when its folder cannot be made."""
    folder = cache_folder()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        return None
    return _ForgivingCache(str(folder))
