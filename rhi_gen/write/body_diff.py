"""What changed in a robot's body (model/body.BodySummary) between the manifest and the current URDF, in words.

One phrase list per topic, each the text of one ``body`` line of `rhi-gen diff`:

- mass, links, inertials: the total mass; the number of links; the links whose inertial (mass, origin or
  inertia tensor) changed, was added or removed: named with their masses when at most
  ``NAMED_LINKS``, else counted;
- collisions: counts by geometry kind, old -> new;
- visuals and mesh references: counts by geometry kind, and the mesh file patterns (``meshes/*.STL``).

Nothing is told when either side is None (a manifest from before rhi-gen recorded bodies).
"""
from __future__ import annotations

from ..model.body import GEOMETRY_KINDS, BodySummary, LinkInertial, mesh_form

NAMED_LINKS = 5
_PLURAL = {"mesh": "meshes", "box": "boxes"}


def kg(value: float | None) -> str:
    if value is None:
        return "? kg"
    return f"{round(value, 3):g} kg"


def _kinds(counts: tuple[tuple[str, int], ...]) -> str:
    if not counts:
        return "none"
    ordered = sorted(counts, key=lambda c: (GEOMETRY_KINDS.index(c[0]) if c[0] in GEOMETRY_KINDS else 99, c[0]))
    return ", ".join(f"{n} {kind if n == 1 else _PLURAL.get(kind, kind + 's')}" for kind, n in ordered)


def _meshes(counts: tuple[tuple[str, int], ...]) -> str:
    if not counts:
        return "none"
    out = []
    for pattern, n in counts:
        form = mesh_form(pattern)
        note = f" ({form}{'s' if n != 1 else ''})" if form in ("relative path", "absolute path") else ""
        out.append(f"{n} {pattern}{note}")
    return ", ".join(out)


def _inertial_changes(old: BodySummary, new: BodySummary) -> str:
    before = {i.link: i for i in old.inertials}
    after = {i.link: i for i in new.inertials}
    changed = sorted(link for link in before.keys() | after.keys() if before.get(link) != after.get(link))
    if not changed:
        return ""
    if len(changed) > NAMED_LINKS:
        added = sum(1 for link in changed if link not in before)
        removed = sum(1 for link in changed if link not in after)
        extra = ([f"{added} added"] if added else []) + ([f"{removed} removed"] if removed else [])
        return f"{len(changed)} links' inertials changed" + (f" ({', '.join(extra)})" if extra else "")
    return "inertials: " + ", ".join(_one_link(before.get(link), after.get(link), link) for link in changed)


def _one_link(o: LinkInertial | None, n: LinkInertial | None, link: str) -> str:
    if o is None and n is not None:
        return f"{link} added ({kg(n.mass)})"
    if n is None and o is not None:
        return f"{link} removed (was {kg(o.mass)})"
    assert o is not None and n is not None
    if o.mass != n.mass:
        return f"{link} {kg(o.mass)} -> {kg(n.mass)}"
    return f"{link} origin or inertia tensor"


def body_changes(old: BodySummary | None, new: BodySummary | None) -> tuple[str, ...]:
    if old is None or new is None or old == new:
        return ()
    first = []
    if old.total_mass != new.total_mass:
        first.append(f"mass {kg(old.total_mass)} -> {kg(new.total_mass)}")
    if old.links != new.links:
        first.append(f"links {old.links} -> {new.links}")
    inertials = _inertial_changes(old, new)
    if inertials:
        first.append(inertials)
    lines = ["; ".join(first)] if first else []
    if old.collisions != new.collisions:
        lines.append(f"collisions: {_kinds(old.collisions)} -> {_kinds(new.collisions)}")
    visuals = []
    if old.visuals != new.visuals:
        visuals.append(f"visuals: {_kinds(old.visuals)} -> {_kinds(new.visuals)}")
    if old.mesh_files != new.mesh_files:
        visuals.append(f"mesh files: {_meshes(old.mesh_files)} -> {_meshes(new.mesh_files)}")
    if visuals:
        lines.append("; ".join(visuals))
    return tuple(lines)
