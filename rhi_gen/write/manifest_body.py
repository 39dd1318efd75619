"""A robot's body (model/body.BodySummary) as the manifest writes and reads it.

    "body": {
      "collisions": {"mesh": 24, "sphere": 8},   # by geometry kind, only kinds present
      "inertials": {"pelvis": [3.813, "a1b2c3d4e5f6"], ...},   # link: [mass kg, digest of the inertial]
      "links": 36,
      "mesh_files": {"meshes/*.STL": 71},       # reference pattern: count (visual and collision)
      "total_mass_kg": 33.34,
      "visuals": {"mesh": 35}
    }

A manifest written before rhi-gen recorded bodies has no "body": the record is None and nothing is told.
"""
from __future__ import annotations

from typing import Any

from ..model.body import BodySummary, LinkInertial


def body_to_data(body: BodySummary) -> dict[str, Any]:
    return {
        "links": body.links,
        "total_mass_kg": body.total_mass,
        "inertials": {i.link: [i.mass, i.digest] for i in body.inertials},
        "collisions": dict(body.collisions),
        "visuals": dict(body.visuals),
        "mesh_files": dict(body.mesh_files),
    }


def _count(value: Any, where: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise ValueError(f"{where}: expected a count")
    return value


def _mass(value: Any, where: str) -> float | None:
    if value is None:
        return None
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise ValueError(f"{where}: expected a mass in kg")
    return float(value)


def _counts(data: Any, where: str) -> tuple[tuple[str, int], ...]:
    if not isinstance(data, dict):
        raise ValueError(f"{where}: expected {{kind: count}}")
    return tuple(sorted((str(k), _count(v, f"{where}.{k}")) for k, v in data.items()))


def body_from_data(data: Any, where: str) -> BodySummary:
    if not isinstance(data, dict) or not isinstance(data.get("inertials"), dict):
        raise ValueError(f"{where}: expected {{links, total_mass_kg, inertials, collisions, visuals, mesh_files}}")
    inertials = []
    for link, row in data["inertials"].items():
        if not isinstance(row, list) or len(row) != 2 or not isinstance(row[1], str):
            raise ValueError(f"{where}.inertials.{link}: expected [mass, digest]")
        inertials.append(LinkInertial(str(link), _mass(row[0], f"{where}.inertials.{link}"), row[1]))
    total = _mass(data["total_mass_kg"], f"{where}.total_mass_kg")
    return BodySummary(
        links=_count(data["links"], f"{where}.links"),
        total_mass=total if total is not None else 0.0,
        inertials=tuple(sorted(inertials, key=lambda i: i.link)),
        collisions=_counts(data["collisions"], f"{where}.collisions"),
        visuals=_counts(data["visuals"], f"{where}.visuals"),
        mesh_files=_counts(data["mesh_files"], f"{where}.mesh_files"),
    )
