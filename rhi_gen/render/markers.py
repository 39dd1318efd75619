"""The user-region marker syntax: templates emit it (``user_region``), write/regions.py parses it."""
from __future__ import annotations

REGION_BEGIN = "rhi-gen:begin-user-region"
REGION_END = "rhi-gen:end-user-region"


def user_region(name: str, style: str = "//", indent: str = "") -> str:
    """An empty named region (template global); write/regions.py carries its body across regenerations."""
    return f"{indent}{style} {REGION_BEGIN} {name}\n{indent}{style} {REGION_END} {name}"
