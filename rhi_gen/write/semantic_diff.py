"""A pending regeneration in robot terms: what the manifest recorded vs. the model built now.

Only the current inputs are on disk, so the "old robot" is the joint table the manifest stored at
the last `generate` (manifest.RobotRecord). Definitions:

- renamed:  same SDK index, a different name, and the old name is gone while the new name is new;
- remapped: same name, a different index;
- added / removed: a name only in the new / old table (not part of a rename);
- limits / type: a joint present in both (by name, or a renamed pair) whose limits or type differ;
- motor_count / float_type: the MotorCommand<N, T> parameters;
- transmission: a joint of the new table whose direction, reduction or offset differs (a joint the
  manifest has no transmission for is the identity: manifests before transmissions, and every
  joint that is its own motor);
- coupled group: added, removed (by name), or its joints or matrix changed;
- mode: a joint present in both whose command mode differs (position, velocity, or state: a leg the
  robot's own controller keeps under authority upper_body); not told against a manifest that did not
  record modes;
- body: the URDF's inertials, collisions, visuals and mesh references (write/body_diff.py). The driver's
  tables do not depend on them, so a body change alone leaves ``robot_changed`` False; it is told on
  ``body`` lines, and not against a manifest that did not record the body.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from .body_diff import body_changes
from .manifest import GroupRecord, JointRecord, Manifest, RobotRecord, TransmissionRecord


@dataclass(frozen=True)
class RobotDiff:
    key: str                      # "vendor/robot"
    status: str                   # new | removed | changed | unchanged
    inputs: tuple[str, ...] = ()  # which inputs changed, in words
    renamed: tuple[tuple[int, str, str], ...] = ()            # (index, old name, new name)
    remapped: tuple[tuple[str, int, int], ...] = ()           # (name, old index, new index)
    added: tuple[JointRecord, ...] = ()
    removed: tuple[JointRecord, ...] = ()
    limits: tuple[tuple[str, int, tuple[tuple[str, float | None, float | None], ...]], ...] = ()
    types: tuple[tuple[str, int, str, str], ...] = ()         # (name, index, old type, new type)
    motor_count: tuple[int, int] | None = None
    float_type: tuple[str, str] | None = None
    transmissions: tuple[tuple[str, str], ...] = ()           # (joint, what changed, in words)
    coupled_groups: tuple[tuple[str, str], ...] = ()          # (group, what changed, in words)
    modes: tuple[tuple[str, int, str, str], ...] = ()         # (name, index, old mode, new mode)
    body: tuple[str, ...] = ()                                # what changed in the body, one text per line
    new_record: RobotRecord | None = field(default=None, compare=False)
    old_record: RobotRecord | None = field(default=None, compare=False)

    @property
    def robot_changed(self) -> bool:
        return bool(self.renamed or self.remapped or self.added or self.removed or self.limits or self.types
                    or self.motor_count or self.float_type or self.transmissions or self.coupled_groups
                    or self.modes)

    @property
    def stale(self) -> bool:
        """The inputs differ from those of the last generation (or it never happened)."""
        return self.status != "unchanged"

    def lines(self) -> list[str]:
        if self.status == "new":
            r = self.new_record
            assert r is not None
            return [(f"{self.key}: new robot ({len(r.joints)} joints, {r.motor_count} motors, {r.float_type}; "
                     f"{r.yaml_path}, {r.urdf_path})")]
        if self.status == "removed":
            r = self.old_record
            assert r is not None
            return [f"{self.key}: robot removed ({r.yaml_path} is gone; its files are deleted)"]
        if self.status == "unchanged":
            return [f"{self.key}: inputs unchanged"]
        out = [f"{self.key}: {', '.join(self.inputs)}"]
        for index, old, new in self.renamed:
            out.append(f"  renamed     joint {index}: {old} -> {new}")
        for name, old_i, new_i in self.remapped:
            out.append(f"  remapped    joint {name}: index {old_i} -> {new_i}")
        for j in self.added:
            out.append(f"  added       joint {j.index}: {j.name} ({j.type}{_limits_text(j)})")
        for j in self.removed:
            out.append(f"  removed     joint {j.index}: {j.name}")
        for name, index, old_t, new_t in self.types:
            out.append(f"  type        joint {index} {name}: {old_t} -> {new_t}")
        for name, index, old_m, new_m in self.modes:
            out.append(f"  mode        joint {index} {name}: {old_m} -> {new_m}")
        for name, index, fields in self.limits:
            what = ", ".join(f"{k} {_num(a)} -> {_num(b)}" for k, a, b in fields)
            out.append(f"  limits      joint {index} {name}: {what}")
        if self.motor_count:
            out.append(f"  motor_count {self.motor_count[0]} -> {self.motor_count[1]}")
        if self.float_type:
            out.append(f"  float_type  {self.float_type[0]} -> {self.float_type[1]}")
        for name, what in self.transmissions:
            out.append(f"  {name}: transmission {what}")
        for name, what in self.coupled_groups:
            out.append(f"  coupled group {name}: {what}")
        for what in self.body:
            out.append(f"  body        {what}")
        if not self.robot_changed and self.body:
            out.append("  no joint, limit, command mode, transmission, motor count or float type change: the "
                       "driver's tables are the same, only the body changed")
        elif not self.robot_changed:
            out.append("  no joint, limit, command mode, transmission, motor count or float type change (see the "
                       "file diff)")
        return out


def _num(value: float | None) -> str:
    if value is None:
        return "none"
    if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return repr(value)


def _limits_text(j: JointRecord) -> str:
    parts = [f"{k} {_num(v)}" for k, v in j.limit_items() if v is not None]
    return (", " + ", ".join(parts)) if parts else ""


def _same(a: float | None, b: float | None) -> bool:
    if a is None or b is None:
        return a is b
    return a == b or (math.isnan(a) and math.isnan(b))


def _transmission_changes(old: RobotRecord, new: RobotRecord) -> tuple[tuple[str, str], ...]:
    """Per joint of the new table: its direction, reduction and offset against the old (identity when absent)."""
    before = {t.joint: t for t in old.transmissions}
    after = {t.joint: t for t in new.transmissions}
    out = []
    for j in new.joints:
        o, n = before.get(j.name, TransmissionRecord(j.name)), after.get(j.name, TransmissionRecord(j.name))
        parts = [f"{what} {a} -> {b}" for what, a, b in (
            ("reduction", _num(o.reduction), _num(n.reduction)),
            ("direction", f"{o.direction:+d}", f"{n.direction:+d}"),
            ("offset", _num(o.offset), _num(n.offset))) if a != b]
        if parts:
            out.append((j.name, ", ".join(parts)))
    return tuple(out)


def _matrix_text(g: GroupRecord) -> str:
    return "[" + ", ".join("[" + ", ".join(_num(x) for x in row) + "]" for row in g.matrix) + "]"


def _group_changes(old: RobotRecord, new: RobotRecord) -> tuple[tuple[str, str], ...]:
    before = {g.name: g for g in old.coupled_groups}
    after = {g.name: g for g in new.coupled_groups}
    out = []
    for name in sorted(before.keys() | after.keys()):
        o, n = before.get(name), after.get(name)
        if o is None and n is not None:
            out.append((name, f"added ({', '.join(n.joints)}), matrix {_matrix_text(n)}"))
        elif n is None and o is not None:
            out.append((name, f"removed ({', '.join(o.joints)})"))
        elif o is not None and n is not None and o != n:
            what = [f"joints ({', '.join(o.joints)}) -> ({', '.join(n.joints)})"] if o.joints != n.joints else []
            if o.matrix != n.matrix:
                what.append(f"matrix {_matrix_text(o)} -> {_matrix_text(n)}")
            out.append((name, ", ".join(what)))
    return tuple(out)


def _inputs(old: RobotRecord, new: RobotRecord, yaml_comparable: bool) -> tuple[str, ...]:
    what = []
    if old.yaml_path != new.yaml_path:
        what.append(f"vendor YAML moved {old.yaml_path} -> {new.yaml_path}")
    elif not yaml_comparable:
        what.append(f"{new.yaml_path} was fingerprinted by an older rhi-gen (its bytes, not its content)")
    elif old.yaml_sha256 != new.yaml_sha256:
        what.append(f"{new.yaml_path} changed")
    if old.urdf_path != new.urdf_path:
        what.append(f"URDF moved {old.urdf_path} -> {new.urdf_path}")
    elif old.urdf_sha256 != new.urdf_sha256:
        what.append(f"{new.urdf_path} changed")
    return tuple(what)


def diff_robot(old: RobotRecord | None, new: RobotRecord | None, *, yaml_comparable: bool = True) -> RobotDiff:
    """``old`` (from the manifest) against ``new`` (from the current inputs); one of them may be None.

    ``yaml_comparable`` is False when ``old`` comes from a manifest whose YAML fingerprints mean
    something else (format 1).
    """
    if old is None and new is None:
        raise ValueError("nothing to compare")
    if old is None:
        assert new is not None
        return RobotDiff(new.key, "new", ("not generated yet",), new_record=new)
    if new is None:
        return RobotDiff(old.key, "removed", (f"{old.yaml_path} removed",), old_record=old)

    old_by_index = {j.index: j for j in old.joints}
    new_by_index = {j.index: j for j in new.joints}
    old_by_name = {j.name: j for j in old.joints}
    new_by_name = {j.name: j for j in new.joints}

    renamed = []
    for index in sorted(old_by_index.keys() & new_by_index.keys()):
        o, n = old_by_index[index], new_by_index[index]
        if o.name != n.name and o.name not in new_by_name and n.name not in old_by_name:
            renamed.append((index, o.name, n.name))
    renamed_old = {r[1] for r in renamed}
    renamed_new = {r[2] for r in renamed}

    common = [n for n in (j.name for j in new.joints) if n in old_by_name]  # new table's index order
    remapped = [(name, old_by_name[name].index, new_by_name[name].index) for name in common
                if old_by_name[name].index != new_by_name[name].index]
    added = tuple(j for j in new.joints if j.name not in old_by_name and j.name not in renamed_new)
    removed = tuple(j for j in old.joints if j.name not in new_by_name and j.name not in renamed_old)

    pairs = [(old_by_name[name], new_by_name[name]) for name in common]
    pairs += [(old_by_index[i], new_by_index[i]) for i, _, _ in renamed]
    pairs.sort(key=lambda p: p[1].index)
    limits = []
    types = []
    for o, n in pairs:
        if o.type != n.type:
            types.append((n.name, n.index, o.type, n.type))
        fields = tuple((k, a, b) for (k, a), (_, b) in zip(o.limit_items(), n.limit_items(), strict=True)
                       if not _same(a, b))
        if fields:
            limits.append((n.name, n.index, fields))

    modes = []
    if old.command_modes is not None:  # recorded: a joint absent from the map is position-commanded
        old_modes, new_modes = dict(old.command_modes), dict(new.command_modes or ())
        for o, n in pairs:
            before, after = old_modes.get(o.name, "position"), new_modes.get(n.name, "position")
            if before != after:
                modes.append((n.name, n.index, before, after))

    inputs = _inputs(old, new, yaml_comparable)
    diff = RobotDiff(
        new.key, "changed" if inputs else "unchanged", inputs,
        renamed=tuple(renamed), remapped=tuple(remapped), added=added, removed=removed,
        limits=tuple(limits), types=tuple(types),
        motor_count=(old.motor_count, new.motor_count) if old.motor_count != new.motor_count else None,
        float_type=(old.float_type, new.float_type) if old.float_type != new.float_type else None,
        transmissions=_transmission_changes(old, new), coupled_groups=_group_changes(old, new),
        modes=tuple(modes), body=body_changes(old.body, new.body), new_record=new, old_record=old)
    if diff.status == "unchanged" and diff.robot_changed:  # the same hashes cannot give a new table
        diff = replace(diff, status="changed", inputs=("manifest out of date",))
    return diff


def diff_manifest(old: Manifest | None, new_records: Sequence[RobotRecord], *,
                  removed_keys: Sequence[str] = ()) -> list[RobotDiff]:
    """One RobotDiff per robot in ``new_records`` (sorted), then one per ``removed_keys`` robot."""
    old_robots = old.robots if old is not None else {}
    comparable = old is None or old.yaml_fingerprints_comparable
    out = [diff_robot(old_robots.get(r.key), r, yaml_comparable=comparable)
           for r in sorted(new_records, key=lambda r: r.key)]
    out += [diff_robot(old_robots[k], None) for k in sorted(removed_keys) if k in old_robots]
    return out
