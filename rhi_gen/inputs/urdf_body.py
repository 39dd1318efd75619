"""The <link>s' inertials, collisions and visuals of a parsed <robot> -> :class:`~rhi_gen.model.body.BodySummary`.

Lenient by design: the generated driver does not depend on the body, so a value that is not a number
is kept as written (in the inertial's digest) rather than refused. Mesh references are summed up as
patterns, the file name replaced by ``*``: ``meshes/*.STL``, ``package://pkg/meshes/*.dae``; an
absolute path or file:// URI keeps only its extension (``file://*.stl``) so no machine path reaches
the manifest.
"""
from __future__ import annotations

import hashlib
import math
import posixpath
from collections import Counter
from collections.abc import Callable

from lxml import etree

from ..model.body import BodySummary, LinkInertial

__all__ = ["mesh_pattern", "read_body"]

_INERTIA = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")


def _number(text: str | None) -> float | None:
    try:
        value = float(text) if text is not None else None
    except ValueError:
        return None
    return value if value is not None and math.isfinite(value) else None


def _canon(text: str | None, default: str) -> str:
    """A value as the digest sees it: numbers normalised (``1`` = ``1.0`` = ``1e0``), anything else as written."""
    words = (text if text is not None else default).split()
    return " ".join(repr(float(w)) if _number(w) is not None else w for w in words)


def _inertial(link: str, el: etree._Element, q: Callable[[str], str]) -> LinkInertial:
    mass_el, origin_el, inertia_el = el.find(q("mass")), el.find(q("origin")), el.find(q("inertia"))
    mass_text = mass_el.get("value") if mass_el is not None else None
    parts = [_canon(mass_text, "-"),
             _canon(origin_el.get("xyz") if origin_el is not None else None, "0 0 0"),
             _canon(origin_el.get("rpy") if origin_el is not None else None, "0 0 0")]
    parts += [_canon(inertia_el.get(k) if inertia_el is not None else None, "-") for k in _INERTIA]
    digest = hashlib.sha256("|".join(parts).encode("utf-8")).hexdigest()[:12]
    return LinkInertial(link, _number(mass_text), digest)


def mesh_pattern(filename: str | None) -> str:
    """A mesh reference with its file name replaced by ``*`` (its extension kept as written)."""
    if not filename:
        return "(no filename)"
    folder, name = posixpath.split(filename.strip())
    ext = posixpath.splitext(name)[1]
    star = f"*{ext}" if ext else "*"
    if filename.startswith(("file://", "/")):
        return ("file://" if filename.startswith("file://") else "/") + star
    return f"{folder}/{star}" if folder else star


def read_body(root: etree._Element, q: Callable[[str], str]) -> BodySummary:
    inertials: list[LinkInertial] = []
    collisions: Counter[str] = Counter()
    visuals: Counter[str] = Counter()
    meshes: Counter[str] = Counter()
    links = 0
    for link in root.iter(q("link")):
        if link.getparent() is not root:
            continue
        links += 1
        name = link.get("name") or ""
        inertial = link.find(q("inertial"))
        if inertial is not None:
            inertials.append(_inertial(name, inertial, q))
        for tag, counts in (("collision", collisions), ("visual", visuals)):
            for el in link.findall(q(tag)):
                geometry = el.find(q("geometry"))
                shape = next((c for c in geometry if isinstance(c.tag, str)), None) if geometry is not None else None
                kind = etree.QName(shape).localname if shape is not None else "no geometry"
                counts[kind] += 1
                if kind == "mesh" and shape is not None:
                    meshes[mesh_pattern(shape.get("filename"))] += 1
    masses = [i.mass for i in inertials if i.mass is not None]
    return BodySummary(
        links=links,
        total_mass=round(math.fsum(masses), 6),
        inertials=tuple(sorted(inertials, key=lambda i: i.link)),
        collisions=tuple(sorted(collisions.items())),
        visuals=tuple(sorted(visuals.items())),
        mesh_files=tuple(sorted(meshes.items())),
    )
