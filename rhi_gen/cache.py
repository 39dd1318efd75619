"""Where rhi-gen keeps what only ever saves time: compiled templates, the memo of the last passing check.

Nothing here changes output: a cache that is missing, unreadable or unwritable costs time, never a
different result. Kept apart from its users so `rhi-gen check` finds it without importing Jinja.
"""
from __future__ import annotations

import os
from pathlib import Path


def cache_root() -> Path:
    """``$RHI_GEN_CACHE``, else ``$XDG_CACHE_HOME/rhi-gen`` (``~/.cache/rhi-gen``)."""
    if os.environ.get("RHI_GEN_CACHE"):
        return Path(os.environ["RHI_GEN_CACHE"])
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "rhi-gen"
