"""The vendor YAML's ``transmissions:`` and ``coupled_joints:``: motors that are not joints.

Convention (ros2_control's transmission_interface): joint = direction * motor / reduction + offset
for one joint; joint = matrix @ motor + offset for a coupled group, motor k being the SDK slot of its
k-th joint. Each bad value is one ConfigError naming file:line, the key and the fix; the joints are
those of joint_map (checked by inputs/vendor_config.py before these run).
"""
from __future__ import annotations

import math
import re
from typing import Any

from ..model.naming import suggest
from ..typed_yaml.validator import Validator
from ..typed_yaml.yaml_source import Scalar

TRANSMISSION_KEYS = ("direction", "reduction", "offset")
GROUP_KEYS = ("joints", "matrix")
MAX_OFFSET = 2.0 * math.pi  # rad: one turn; beyond it the zero is wrong, not far away
MAX_REDUCTION = 1e6
MAX_GROUP = 16              # joints of one coupled group: far above a wrist or an ankle
GROUP_NAME_RE = re.compile(r"^[A-Za-z_][A-Za-z0-9_.\-]{0,63}$")
MIN_CONDITION = 1e-9        # |det| / product of row norms below this: singular for double precision

# joint -> (direction, reduction, offset), as VendorConfig.transmissions holds it
Transmission = tuple[str, int, float, float]
# (name, joints, matrix), as VendorConfig.coupled_joints holds it
Group = tuple[str, tuple[str, ...], tuple[tuple[float, ...], ...]]


def read_transmissions(v: Validator, entries: dict[str, Any], coupled: dict[str, str]) -> tuple[Transmission, ...]:
    """``transmissions: {joint: {direction, reduction, offset}}``; ``coupled``: joint -> its coupled group."""
    out = []
    for name, item in entries.items():
        path = f"transmissions.{name}"
        m = v.mapping(item, path, TRANSMISSION_KEYS)
        group = coupled.get(name)
        for key in ("direction", "reduction"):
            if group is not None and key in m:
                raise v.error(f"{path}.{key}", f"joint {name!r} is coupled: its direction and reduction are in "
                              f"coupled_joints.{group}.matrix", fix=f"remove {key} here (offset may stay)")
        direction = 1
        if "direction" in m:
            raw = v.scalar(m["direction"], f"{path}.direction")
            if isinstance(raw, bool) or not isinstance(raw, int) or raw not in (1, -1):
                raise v.error(f"{path}.direction", f"must be 1 or -1, got {m['direction'].raw!r}",
                              fix="write -1 for a motor that turns the other way, else 1")
            direction = int(raw)
        reduction = 1.0
        if "reduction" in m:
            q = f"{path}.reduction"
            reduction = v.finite_number(m["reduction"], q, "write the motor turns per joint turn, e.g. 50.0")
            if reduction <= 0.0:
                raise v.error(q, f"must be above 0, got {m['reduction'].raw!r}",
                              fix="write the reduction's size (e.g. 50.0) and direction: -1 for a reversed motor")
            if reduction > MAX_REDUCTION:
                raise v.error(q, f"{reduction:g} is above {MAX_REDUCTION:g}", fix="write motor turns per joint turn")
        offset = 0.0
        if "offset" in m:
            q = f"{path}.offset"
            offset = v.finite_number(m["offset"], q, "write the joint position at motor zero in rad (m), e.g. 0.1")
            if abs(offset) > MAX_OFFSET:
                raise v.error(q, f"|{offset:g}| is above {MAX_OFFSET:.4f} (one turn): an offset beyond one turn "
                              "is a mistake", fix="write the joint position at motor zero within one turn, in rad")
        out.append((name, direction, reduction, offset))
    return tuple(out)


def read_coupled_joints(v: Validator, raw: Any, mapped: dict[str, int]) -> tuple[Group, ...]:
    """``coupled_joints: {group: {joints: [j1, j2, ...], matrix: [[...], ...]}}``."""
    if isinstance(raw, Scalar) and raw.value is None:
        return ()
    if not isinstance(raw, dict):
        raise v.error("coupled_joints", "must be a mapping of group name: {joints, matrix}",
                      fix="e.g. {wrist: {joints: [wrist_pitch, wrist_roll], matrix: [[0.5, 0.5], [0.5, -0.5]]}}")
    owner: dict[str, str] = {}
    out = []
    for name, item in raw.items():
        path = f"coupled_joints.{name}"
        if not GROUP_NAME_RE.match(name):
            raise v.error(path, f"{name!r} is not a group name (a letter or _, then letters, digits, _ . -; "
                          "at most 64)", fix="name the group, e.g. left_wrist")
        m = v.mapping(item, path, GROUP_KEYS)
        for key in GROUP_KEYS:
            if key not in m:
                raise v.error(path, f"{key!r} is missing", fix="write both joints: [...] and matrix: [[...], ...]")
        joints = _group_joints(v, m["joints"], f"{path}.joints", mapped, owner, name)
        matrix = _matrix(v, m["matrix"], f"{path}.matrix", len(joints))
        out.append((name, joints, matrix))
    return tuple(out)


def _group_joints(v: Validator, raw: Any, path: str, mapped: dict[str, int], owner: dict[str, str],
                  group: str) -> tuple[str, ...]:
    if not isinstance(raw, list) or not 2 <= len(raw) <= MAX_GROUP:
        raise v.error(path, f"must be a list of 2 to {MAX_GROUP} joints of joint_map",
                      fix="e.g. [wrist_pitch, wrist_roll]")
    names: list[str] = []
    for i, item in enumerate(raw):
        q = f"{path}[{i}]"
        name = v.string(item, q)
        if name not in mapped:
            hint = suggest(name, list(mapped))
            raise v.error(q, f"{name!r} is not a joint of joint_map",
                          fix=f"did you mean {hint!r}?" if hint else "list joints of joint_map only")
        if name in names:
            raise v.error(q, f"{name!r} is listed twice", fix="list each joint of the group once")
        if name in owner:
            raise v.error(q, f"{name!r} is already in coupled_joints.{owner[name]}",
                          fix="a joint belongs to one coupled group at most: merge the two groups")
        names.append(name)
    for name in names:
        owner[name] = group
    return tuple(names)


def _matrix(v: Validator, raw: Any, path: str, n: int) -> tuple[tuple[float, ...], ...]:
    fix = f"write {n} rows of {n} numbers, row k for joint k, column k for the motor of joint k"
    if not isinstance(raw, list) or len(raw) != n:
        raise v.error(path, f"must be a list of {n} rows (one per joint)", fix=fix)
    rows = []
    for i, row in enumerate(raw):
        q = f"{path}[{i}]"
        if not isinstance(row, list) or len(row) != n:
            raise v.error(q, f"must be a list of {n} numbers (one per motor)", fix=fix)
        rows.append(tuple(v.finite_number(x, f"{q}[{k}]", fix) for k, x in enumerate(row)))
    if condition(rows) < MIN_CONDITION:
        raise v.error(path, "matrix is singular: the motors cannot reach every joint position",
                      fix="check the rows: no row may be a multiple or a sum of the others")
    return tuple(rows)


def condition(rows: list[tuple[float, ...]]) -> float:
    """|det| / product of the row norms: 1 for orthogonal rows, 0 for a singular matrix."""
    norms = math.prod(math.sqrt(sum(x * x for x in row)) for row in rows)
    if norms == 0.0 or not math.isfinite(norms):
        return 0.0
    a = [list(row) for row in rows]
    n = len(a)
    det = 1.0
    for c in range(n):  # Gaussian elimination with partial pivoting
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        if a[p][c] == 0.0:
            return 0.0
        if p != c:
            a[c], a[p] = a[p], a[c]
            det = -det
        det *= a[c][c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            for k in range(c, n):
                a[r][k] -= f * a[c][k]
    ratio = abs(det) / norms
    return ratio if math.isfinite(ratio) else 0.0
