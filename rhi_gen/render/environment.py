"""The one Jinja environment every template renders in, and what it offers templates.

Settings (docs/ARCHITECTURE.md "Template context"): StrictUndefined, trim/lstrip blocks, keep the
trailing newline, autoescape only for XML templates, and a finalize that refuses to print None.
Escaping is decided in Python (render/literals.py filters), never in templates.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

import jinja2

from ..errors import GenerationError
from .literals import FILTERS
from .markers import user_region
from .template_cache import compiled_template_cache


def _finalize(value: Any) -> Any:
    if value is None:
        raise GenerationError("a template printed None (a model field is missing)")
    return value


# Every source the package is made from, named by its path under the rhi_gen package: templates
# (templates/...), the robot-independent C++ copied as it is (cpp/...) and each transport's folder
# (transports/<name>/: its C++ headers and its glue template).
SOURCE_ROOT = Path(__file__).resolve().parents[1]


def make_environment(root: Path = SOURCE_ROOT) -> jinja2.Environment:
    """The Environment over the sources under ``root`` (a copy of the package's, for the mutation tests)."""
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(root)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=jinja2.select_autoescape(enabled_extensions=("xml.j2", "xacro.j2"),
                                            default_for_string=False, default=False),
        finalize=_finalize,
        bytecode_cache=compiled_template_cache(),
    )
    env.filters.update(FILTERS)
    env.globals["user_region"] = user_region
    return env
