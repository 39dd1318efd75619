"""Robot-independent C++ files: real .hpp files in rhi_gen, copied into the package as they are.

A source file starts with rhi-gen's own header comment (so editors, linters and compilers see a
complete C++ file where it lives); the copy swaps that comment for the package's banner and keeps
every other byte. Sources are read through the Jinja loader, never compiled as templates, so the
mutation tests can hand render_package a modified copy of the sources.
"""
from __future__ import annotations

import jinja2

from ..errors import GenerationError

SOURCE_HEADER_END = "\n\n"  # the source's own header comment ends at its first blank line


def copy_static(env: jinja2.Environment, source: str, banner: str, out: str) -> str:
    """``source`` (a path under the rhi_gen package) with ``banner`` in place of its header comment."""
    assert env.loader is not None
    try:
        text, _, _ = env.loader.get_source(env, source)
    except jinja2.TemplateNotFound as exc:
        raise GenerationError(f"{source} is missing from the rhi-gen installation", file=out) from exc
    if not text.startswith("//") or SOURCE_HEADER_END not in text:
        raise GenerationError(f"{source} does not start with its header comment and a blank line", file=out,
                              fix="this is a bug in rhi-gen's C++ sources; please report it")
    return banner + SOURCE_HEADER_END + text.split(SOURCE_HEADER_END, 1)[1]
