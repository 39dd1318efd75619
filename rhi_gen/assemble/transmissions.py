"""How each mapped joint follows its motor: the URDF's <transmission>s and the vendor YAML's keys, decided.

Order of precedence: the URDF's SimpleTransmission / DifferentialTransmission first (unless
``urdf_transmissions: false``), then the vendor YAML: a ``coupled_joints`` group replaces every URDF
transmission on its joints (a URDF group sharing a joint goes whole), and a ``transmissions`` entry
replaces the URDF's for its joint (on a coupled joint only its offset may be given). Only mapped
joints get a transmission; a transmission rhi-gen cannot apply is a warning, never an error (the URDF
is often third-party). An identity changes nothing: the joint keeps ``JointTransmission()``.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from ..errors import ConfigError, InputWarning
from ..model.config import VendorConfig
from ..model.robot import CoupledGroup, JointTransmission
from ..model.urdf import TRANSMISSION_KINDS, UrdfRobot, UrdfTransmission

__all__ = ["Decided", "decide_transmissions", "urdf_source"]

YAML_SOURCE = "vendor YAML"
SHOWN = 3  # transmission names a warning lists before "and N more"
FIX_KIND = ("if a motor is not its joint, write it in the vendor YAML: transmissions: {joint: {direction, "
            "reduction, offset}} or coupled_joints: {group: {joints, matrix}} (docs/transmissions.md)")
FIX_JOINT = "nothing to do if no motor of joint_map drives that joint; else map it in joint_map"
FIX_MALFORMED = ("fix the <transmission> in the URDF, or write the joint's transmission in the vendor YAML "
                 "(transmissions: or coupled_joints:) and set urdf_transmissions: false")


@dataclass(frozen=True)
class Decided:
    joints: dict[str, JointTransmission]    # mapped joint -> its transmission (identity joints absent)
    groups: tuple[CoupledGroup, ...]        # by the lowest SDK slot of their joints
    warnings: tuple[InputWarning, ...]      # URDF transmissions not applied, one line per kind of reason
    urdf_applied: int = 0                   # URDF transmissions applied (before the YAML's replace any)
    urdf_skipped: int = 0                   # URDF transmissions not applied (the warnings' subjects)


def urdf_source(t: UrdfTransmission) -> str:
    return f"URDF <transmission name='{t.name}'>" + (f" line {t.line}" if t.line else "")


def _category(t: UrdfTransmission) -> str:
    if t.short_kind not in TRANSMISSION_KINDS:
        return "kind"
    return "joint" if t.problem.startswith("names joint") else "malformed"


def _few(names: Sequence[str]) -> str:
    shown = ", ".join(names[:SHOWN])
    return shown + (f" and {len(names) - SHOWN} more" if len(names) > SHOWN else "")


def _warnings(skipped: list[UrdfTransmission], urdf: UrdfRobot) -> tuple[InputWarning, ...]:
    """One warning per (kind, reason) of the transmissions not applied, naming the first's line."""
    by_reason: dict[tuple[str, str], list[UrdfTransmission]] = {}
    for t in skipped:
        category = _category(t)
        by_reason.setdefault((t.kind, category if category != "malformed" else t.problem), []).append(t)
    out = []
    for (kind, reason), ts in by_reason.items():
        first = ts[0]
        count = f"{len(ts)} <transmission>s" if len(ts) > 1 else "<transmission>"
        names = _few([f"'{t.name}'" for t in ts])
        if reason == "kind":
            message = f"{count} {names} of kind {kind} not applied: {first.problem}"
            fix = FIX_KIND
        elif reason == "joint":
            message = f"{count} {names} ({first.short_kind}) not applied: {first.problem}" + (
                " (and the others alike)" if len(ts) > 1 else "")
            fix = FIX_JOINT
        else:
            message = f"{count} {names} ({first.short_kind}) not applied: {first.problem}"
            fix = FIX_MALFORMED
        out.append(InputWarning(message, file=urdf.source, line=first.line, fix=fix))
    return tuple(out)


def _from_urdf(urdf: UrdfRobot, mapped: dict[str, int], skipped: list[UrdfTransmission],
               ) -> tuple[dict[str, JointTransmission], dict[str, CoupledGroup]]:
    """The URDF's applicable transmissions on mapped joints: per joint, and the groups by name."""
    joints: dict[str, JointTransmission] = {}
    groups: dict[str, CoupledGroup] = {}
    taken: dict[str, str] = {}  # joint -> the transmission that set it
    for t in urdf.transmissions:
        if not t.problem:
            unmapped = next((j for j in t.joints if j not in mapped), None)
            twice = next((j for j in t.joints if j in taken), None)
            if unmapped is not None:
                t = replace(t, problem=f"names joint {unmapped!r}, which has no motor in joint_map")
            elif twice is not None:
                t = replace(t, problem=f"joint {twice!r} already follows <transmission name='{taken[twice]}'>")
        if t.problem:
            skipped.append(t)
            continue
        source = urdf_source(t)
        for joint in t.joints:
            taken[joint] = t.name
        if t.matrix:
            groups[t.name] = CoupledGroup(t.name, t.joints, t.matrix, source)
            for joint, offset in zip(t.joints, t.offsets, strict=True):
                joints[joint] = JointTransmission(offset=offset, source=source)
        else:
            joints[t.joints[0]] = JointTransmission(direction=-1 if t.reduction < 0 else 1,
                                                    reduction=abs(t.reduction), offset=t.offsets[0], source=source)
    return joints, groups


def decide_transmissions(config: VendorConfig, urdf: UrdfRobot) -> Decided:
    """Each mapped joint's transmission and the coupled groups (see the module docstring)."""
    mapped = dict(config.joint_map)
    skipped: list[UrdfTransmission] = []
    joints: dict[str, JointTransmission] = {}
    groups: dict[str, CoupledGroup] = {}
    if config.urdf_transmissions:
        joints, groups = _from_urdf(urdf, mapped, skipped)

    for name, members, matrix in config.coupled_joints:
        for other in [g for g in groups.values() if set(g.joints) & set(members)]:
            del groups[other.name]
            for joint in other.joints:
                joints.pop(joint, None)
        for joint in members:
            joints.pop(joint, None)
        groups[name] = CoupledGroup(name, members, matrix, YAML_SOURCE)

    in_group = {joint: g for g in groups.values() for joint in g.joints}
    for name, direction, reduction, offset in config.transmissions:
        group = in_group.get(name)
        if group is not None and (direction, reduction) != (1, 1.0):
            key = next((f"transmissions.{name}.{k}" for k in ("direction", "reduction")
                        if f"transmissions.{name}.{k}" in config.key_lines), f"transmissions.{name}")
            raise ConfigError(f"joint {name!r} is coupled by {group.source}: its direction and reduction are in "
                              "that transmission", file=config.source, line=config.key_lines.get(key), key=key,
                              fix=f"keep only offset here, or write the group under coupled_joints: (it then "
                                  f"replaces <transmission name='{group.name}'>), or set urdf_transmissions: false")
        joints[name] = JointTransmission(direction, reduction, offset, YAML_SOURCE)

    decided = {name: t for name, t in joints.items() if not t.is_identity}
    ordered = sorted((g for g in groups.values() if not _identity(g.matrix)),
                     key=lambda g: min(mapped[j] for j in g.joints))
    applied = len(urdf.transmissions) - len(skipped) if config.urdf_transmissions else 0
    return Decided(decided, tuple(ordered), _warnings(skipped, urdf), applied, len(skipped))


def _identity(matrix: tuple[tuple[float, ...], ...]) -> bool:
    return all(x == (1.0 if r == c else 0.0) for r, row in enumerate(matrix) for c, x in enumerate(row))
