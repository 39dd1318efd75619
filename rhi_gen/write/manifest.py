"""generated/.rhi-gen-manifest: what the last `generate` read and wrote, and which rhi-gen wrote it.

The generated files name only their inputs; every hash and the generator version live here.

- ``generator_version``: the rhi-gen that last wrote generated/. `check` reports in one line when it
  is another version; a new version changes this line only, never a package file whose content
  stays the same.
- Per robot: the vendor YAML and the URDF, each a project-relative path and a sha256 fingerprint of
  what rhi-gen reads from it: the YAML's parsed content (typed_yaml/yaml_source.content_sha256: comments,
  layout, quoting and key order do not count, so a comment-only edit changes nothing here), the
  URDF after xacro expansion without xacro's volatile header. `check` calls a robot stale when a
  fingerprint differs. Then the robot as the model saw it (motor_count, float_type, one row per
  joint: index, name, type, limits; ``transmissions`` per joint that is not its motor and
  ``coupled_groups``, both only when there are any, so a manifest without them means identity) so
  `rhi-gen diff` can explain the next regeneration in robot terms; and its ``body`` summed up (total
  mass, one [mass, digest] per link with an inertial, collisions and visuals by geometry kind, mesh
  references by pattern: write/manifest_body.py), absent in manifests written before it was recorded.
- Per generated file: the sha256 of its text with every user-region body removed, so a hand edit
  *outside* the regions is detected and an edit inside one is not; a mesh copied into meshes/<robot>/
  (inputs/urdf_meshes.py): the sha256 of its bytes.

The file is JSON with sorted keys, one joint or file per line, no timestamps and no absolute paths:
the same inputs always give the same bytes, and a reviewer reads its diff like any other.
Format 1 (rhi-gen 0.1.0 before this layout) is still read: its file hashes mean the same, its YAML
fingerprints were of the bytes, so its robots show as fingerprinted by an older rhi-gen once.
"""
from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import ManifestError
from ..model import RobotModel
from ..model.body import BodySummary
from .manifest_body import body_from_data, body_to_data
from .regions import strip_bodies

MANIFEST_NAME = ".rhi-gen-manifest"
FORMAT = 2
READABLE_FORMATS = (1, 2)
NOTE = ("Written by `rhi-gen generate`; do not edit. Inputs and generated files of the last generation: "
        "yaml sha256 is of the parsed vendor YAML (comments and layout do not count), urdf sha256 of the "
        "expanded URDF, file sha256 of the text with user-region bodies removed (a mesh: of its bytes).")
JOINT_COLUMNS = ("index", "name", "type", "lower", "upper", "velocity", "effort")
FIX_CORRUPT = ("restore it from version control, or rerun `rhi-gen generate --force` to rebuild it "
               "(files that would change are backed up)")


@dataclass(frozen=True)
class JointRecord:
    index: int
    name: str
    type: str
    lower: float | None = None
    upper: float | None = None
    velocity: float | None = None
    effort: float | None = None

    def limit_items(self) -> tuple[tuple[str, float | None], ...]:
        return (("lower", self.lower), ("upper", self.upper), ("velocity", self.velocity),
                ("effort", self.effort))


@dataclass(frozen=True)
class TransmissionRecord:
    """A joint whose motor is not the joint: joint = direction * motor / reduction + offset."""
    joint: str
    direction: int = 1
    reduction: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class GroupRecord:
    """A coupled group: joint = matrix @ motor + offset, motor k in the slot of joints[k]."""
    name: str
    joints: tuple[str, ...]
    matrix: tuple[tuple[float, ...], ...]


@dataclass(frozen=True)
class RobotRecord:
    key: str                # "vendor/robot"
    yaml_path: str
    yaml_sha256: str
    urdf_path: str
    urdf_sha256: str
    motor_count: int
    float_type: str
    joints: tuple[JointRecord, ...]   # sorted by index
    transmissions: tuple[TransmissionRecord, ...] = ()  # joints that are not their motor, by joint name
    coupled_groups: tuple[GroupRecord, ...] = ()        # by name
    # (joint, mode) of every joint not position-commanded ("velocity", "state"), by joint name; None: a
    # manifest from before rhi-gen recorded them (their changes cannot be told)
    command_modes: tuple[tuple[str, str], ...] | None = ()
    # the URDF's inertials and geometry summed up; None: a manifest from before rhi-gen recorded bodies
    body: BodySummary | None = None


@dataclass(frozen=True)
class Manifest:
    generator_version: str
    robots: dict[str, RobotRecord] = field(default_factory=dict)
    files: dict[str, str] = field(default_factory=dict)   # path relative to generated/ -> sha256
    format: int = FORMAT                                   # as read; dumps() always writes FORMAT

    @property
    def yaml_fingerprints_comparable(self) -> bool:
        """Format 1 fingerprinted the YAML bytes; only format 2 fingerprints its parsed content."""
        return self.format >= 2


def sha256_hex(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def generated_hash(text: str, path: str = "<text>") -> str:
    """sha256 of ``text`` with user-region bodies removed (RegionError if its markers are broken)."""
    return sha256_hex(strip_bodies(text, path).encode("utf-8"))


def robot_key(model: RobotModel) -> str:
    return f"{model.vendor}/{model.robot}"


def robot_record(model: RobotModel) -> RobotRecord:
    p = model.provenance
    joints = []
    for j in sorted(model.joints, key=lambda j: j.index):
        lim = j.limits
        joints.append(JointRecord(j.index, j.name, j.type,
                                  lim.lower if lim else None, lim.upper if lim else None,
                                  lim.velocity if lim else None, lim.effort if lim else None))
    transmissions = tuple(sorted(
        (TransmissionRecord(j.name, j.transmission.direction, j.transmission.reduction, j.transmission.offset)
         for j in model.joints if not j.transmission.is_identity), key=lambda t: t.joint))
    groups = tuple(sorted((GroupRecord(g.name, g.joints, g.matrix) for g in model.coupled_groups),
                          key=lambda g: g.name))
    modes = tuple(sorted((j.name, j.command_mode) for j in model.joints if j.command_mode != "position"))
    return RobotRecord(robot_key(model), p.yaml_path, p.yaml_sha256, p.urdf_path, p.urdf_sha256,
                       model.motor_count, model.float_type, tuple(joints), transmissions, groups, modes, model.body)


# ---------------------------------------------------------------- text form
def _num(value: float | None) -> Any:
    if value is None:
        return None
    value = float(value)
    if math.isfinite(value):
        return value
    return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")


def _unnum(value: Any, where: str) -> float | None:
    if value is None:
        return None
    if isinstance(value, bool):
        raise ValueError(f"{where}: expected a number")
    if isinstance(value, (int, float)):
        return float(value)
    if value in ("inf", "-inf", "nan"):
        return float(value)
    raise ValueError(f"{where}: expected a number")


def _to_data(manifest: Manifest) -> dict[str, Any]:
    robots = {}
    for key, r in sorted(manifest.robots.items()):
        robots[key] = {
            "yaml": {"path": r.yaml_path, "sha256": r.yaml_sha256},
            "urdf": {"path": r.urdf_path, "sha256": r.urdf_sha256},
            "motor_count": r.motor_count,
            "float_type": r.float_type,
            "joint_columns": list(JOINT_COLUMNS),
            "joints": [[j.index, j.name, j.type, _num(j.lower), _num(j.upper), _num(j.velocity), _num(j.effort)]
                       for j in sorted(r.joints, key=lambda j: j.index)],
        }
        # Only robots with transmissions carry these keys: a manifest without them means identity.
        if r.transmissions:
            robots[key]["transmissions"] = {t.joint: [t.direction, _num(t.reduction), _num(t.offset)]
                                            for t in r.transmissions}
        robots[key]["command_modes"] = dict(r.command_modes or ())  # joints not position-commanded
        if r.body is not None:
            robots[key]["body"] = body_to_data(r.body)
        if r.coupled_groups:
            robots[key]["coupled_groups"] = {g.name: {"joints": list(g.joints),
                                                      "matrix": [[_num(x) for x in row] for row in g.matrix]}
                                             for g in r.coupled_groups}
    return {
        "format": FORMAT,
        "note": NOTE,
        "generator_version": manifest.generator_version,
        "robots": robots,
        "files": dict(sorted(manifest.files.items())),
    }


def _scalar(value: Any) -> bool:
    return not isinstance(value, (dict, list))


def _emit(value: Any, indent: int) -> str:
    """JSON, sorted keys; a container of scalars on one line, anything else one item per line."""
    if _scalar(value):
        return json.dumps(value, ensure_ascii=True, allow_nan=False)
    items = sorted(value.items()) if isinstance(value, dict) else list(value)
    open_, close = ("{", "}") if isinstance(value, dict) else ("[", "]")
    if not items:
        return open_ + close

    def one(item: Any, nested: int) -> str:
        if isinstance(value, dict):
            k, v = item
            return f"{json.dumps(k, ensure_ascii=True)}: {_emit(v, nested)}"
        return _emit(item, nested)

    inline = (all(_scalar(v) for v in value) if isinstance(value, list)
              else set(value) <= {"path", "sha256"} and all(_scalar(v) for v in value.values()))
    if inline:
        return open_ + ", ".join(one(i, indent) for i in items) + close
    pad = "  " * (indent + 1)
    body = ",\n".join(pad + one(i, indent + 1) for i in items)
    return f"{open_}\n{body}\n{'  ' * indent}{close}"


def dumps(manifest: Manifest) -> str:
    return _emit(_to_data(manifest), 0) + "\n"


def loads(text: str, shown: str = f"generated/{MANIFEST_NAME}") -> Manifest:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ManifestError(f"is not valid JSON: {exc.msg}", file=shown, line=exc.lineno, fix=FIX_CORRUPT) from exc
    try:
        return _from_data(data)
    except (ValueError, TypeError, KeyError, AttributeError) as exc:
        raise ManifestError(f"unexpected content: {exc}", file=shown, fix=FIX_CORRUPT) from exc


def _str(value: Any, where: str) -> str:
    if not isinstance(value, str):
        raise ValueError(f"{where}: expected a string")
    return value


def _from_data(data: Any) -> Manifest:
    if not isinstance(data, dict):
        raise ValueError("top level: expected an object")
    fmt = data.get("format")
    if fmt not in READABLE_FORMATS or isinstance(fmt, bool):
        raise ValueError(f"format {fmt!r} (this rhi-gen reads formats {', '.join(map(str, READABLE_FORMATS))})")
    robots: dict[str, RobotRecord] = {}
    for key, r in data["robots"].items():
        joints = []
        for row in r["joints"]:
            if not isinstance(row, list) or len(row) != len(JOINT_COLUMNS):
                raise ValueError(f"robots.{key}.joints: expected rows of {len(JOINT_COLUMNS)} values")
            index, name, jtype, *limits = row
            if not isinstance(index, int) or isinstance(index, bool):
                raise ValueError(f"robots.{key}.joints: index must be an integer")
            lower, upper, velocity, effort = (_unnum(v, f"robots.{key}.joints") for v in limits)
            joints.append(JointRecord(index, _str(name, "joint name"), _str(jtype, "joint type"),
                                      lower, upper, velocity, effort))
        motor_count = r["motor_count"]
        if not isinstance(motor_count, int) or isinstance(motor_count, bool):
            raise ValueError(f"robots.{key}.motor_count: expected an integer")
        robots[_str(key, "robot")] = RobotRecord(
            key, _str(r["yaml"]["path"], "yaml.path"), _str(r["yaml"]["sha256"], "yaml.sha256"),
            _str(r["urdf"]["path"], "urdf.path"), _str(r["urdf"]["sha256"], "urdf.sha256"), motor_count,
            _str(r["float_type"], "float_type"), tuple(sorted(joints, key=lambda j: j.index)),
            _transmissions(r.get("transmissions", {}), f"robots.{key}.transmissions"),
            _groups(r.get("coupled_groups", {}), f"robots.{key}.coupled_groups"),
            _modes(r["command_modes"], f"robots.{key}.command_modes") if "command_modes" in r else None,
            body_from_data(r["body"], f"robots.{key}.body") if "body" in r else None)
    files = {_str(k, "files"): _str(v, f"files.{k}") for k, v in data["files"].items()}
    return Manifest(_str(data["generator_version"], "generator_version"), robots, files, fmt)


def _float(value: Any, where: str) -> float:
    number = _unnum(value, where)
    if number is None:
        raise ValueError(f"{where}: expected a number")
    return number


def _transmissions(data: Any, where: str) -> tuple[TransmissionRecord, ...]:
    """{joint: [direction, reduction, offset]} (absent in manifests of robots without transmissions)."""
    out = []
    for joint, row in data.items():
        if not isinstance(row, list) or len(row) != 3 or row[0] not in (1, -1) or isinstance(row[0], bool):
            raise ValueError(f"{where}.{joint}: expected [direction, reduction, offset]")
        out.append(TransmissionRecord(_str(joint, where), int(row[0]), _float(row[1], where), _float(row[2], where)))
    return tuple(sorted(out, key=lambda t: t.joint))


def _modes(data: Any, where: str) -> tuple[tuple[str, str], ...]:
    """{joint: mode} of the joints that are not position-commanded."""
    if not isinstance(data, dict):
        raise ValueError(f"{where}: expected {{joint: mode}}")
    return tuple(sorted((_str(joint, where), _str(mode, f"{where}.{joint}")) for joint, mode in data.items()))


def _groups(data: Any, where: str) -> tuple[GroupRecord, ...]:
    """{group: {joints: [...], matrix: [[...], ...]}} (absent in manifests of robots without coupled groups)."""
    out = []
    for name, g in data.items():
        if not isinstance(g, dict) or not isinstance(g["joints"], list) or not isinstance(g["matrix"], list) \
                or not all(isinstance(row, list) for row in g["matrix"]):
            raise ValueError(f"{where}.{name}: expected {{joints: [...], matrix: [[...], ...]}}")
        joints = tuple(_str(j, f"{where}.{name}.joints") for j in g["joints"])
        matrix = tuple(tuple(_float(x, f"{where}.{name}.matrix") for x in row) for row in g["matrix"])
        out.append(GroupRecord(_str(name, where), joints, matrix))
    return tuple(sorted(out, key=lambda g: g.name))


def path(generated_dir: Path) -> Path:
    """Where the manifest of ``generated_dir`` lives."""
    return generated_dir / MANIFEST_NAME


def read_bytes(generated_dir: Path) -> bytes | None:
    target = path(generated_dir)
    return target.read_bytes() if target.is_file() else None


def parse(data: bytes | None, shown: str = f"generated/{MANIFEST_NAME}") -> Manifest | None:
    if data is None:
        return None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ManifestError("is not UTF-8 text", file=shown, fix=FIX_CORRUPT) from exc
    return loads(text, shown)
