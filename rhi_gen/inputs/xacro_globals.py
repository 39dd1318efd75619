"""xacro (2.1.x) keeps process-wide state: the lock and the guards that put it back after a run.

- :data:`XACRO_LOCK`: xacro must never run in parallel (``filestack``, ``macrostack``,
  ``substitution_args_context``, ``all_includes``, ``verbosity`` and ``root_dir`` are globals);
- :func:`reset_xacro_state` resets those globals before and after the run (an exception inside
  xacro skips its own reset of the substitution args, and ``all_includes`` only ever grows);
- :func:`safe_loader_guard` restores ``yaml.SafeLoader``'s constructor table (``xacro.load_yaml``
  registers ``!degrees`` etc. on the process-wide SafeLoader);
- :func:`xacro_reads_bytes` makes xacro open its inputs as bytes, whatever the locale.
"""
from __future__ import annotations

import contextlib
import os
import threading
from collections.abc import Iterator
from typing import Any

__all__ = ["XACRO_LOCK", "reset_xacro_state", "safe_loader_guard", "xacro_reads_bytes"]

XACRO_LOCK = threading.Lock()
_MISSING = object()


@contextlib.contextmanager
def safe_loader_guard() -> Iterator[None]:
    """``xacro.load_yaml`` calls ``yaml.SafeLoader.add_constructor`` (process-wide): undo it."""
    try:
        import yaml
    except ImportError:  # pragma: no cover - PyYAML is a dependency of xacro and of rhi-gen
        yield
        return
    cls = yaml.SafeLoader
    had_own = "yaml_constructors" in cls.__dict__
    saved = dict(cls.__dict__["yaml_constructors"]) if had_own else None
    try:
        yield
    finally:
        if had_own:
            table = cls.__dict__["yaml_constructors"]
            table.clear()
            table.update(saved)
        elif "yaml_constructors" in cls.__dict__:
            delattr(cls, "yaml_constructors")


def _binary_open(file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
    """xacro opens its inputs with ``open(filename)``, i.e. in the locale's encoding (ASCII under
    a plain C locale). Reading bytes instead lets expat honour the XML encoding declaration
    (default UTF-8) and lets PyYAML detect the encoding of ``load_yaml`` files."""
    if mode in ("r", "rt") and not args and not kwargs:
        return open(file, "rb")
    return open(file, mode, *args, **kwargs)


@contextlib.contextmanager
def xacro_reads_bytes(xacro: Any) -> Iterator[None]:
    saved = xacro.__dict__.get("open", _MISSING)
    xacro.open = _binary_open
    try:
        yield
    finally:
        if saved is _MISSING:
            del xacro.open
        else:
            xacro.open = saved


def reset_xacro_state(xacro: Any) -> None:
    xacro.filestack = None
    xacro.macrostack = None
    xacro.substitution_args_context.clear()
    xacro.all_includes.clear()
    xacro.root_dir = os.curdir
    xacro.verbosity = 1
