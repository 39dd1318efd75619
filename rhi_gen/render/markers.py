"""The user-region marker syntax: templates emit it (``user_region``), write/regions.py parses it."""
from __future__ import annotations

REGION_BEGIN = "rhi-gen:begin-user-region"
REGION_END = "rhi-gen:end-user-region"


def user_region(name: str, style: str = "//", indent: str = "", body: str = "") -> str:
    """A named region (template global), empty unless ``body`` (its lines, each ending in a newline)
    gives the content a freshly generated file starts with; write/regions.py carries the body across
    regenerations, so once the file exists the body on disk wins."""
    if body and not body.endswith("\n"):
        raise ValueError(f"user region {name!r}: a default body must end with a newline")
    return f"{indent}{style} {REGION_BEGIN} {name}\n{body}{indent}{style} {REGION_END} {name}"
