"""What `generate`, `check` and `diff` share: model -> render -> plan against the disk, nothing written.

plan_generation() strings the stages together so all three commands see exactly the same plan: the
rendered package, user-region bodies carried over from the files on disk, hand-edit detection
against generated/.rhi-gen-manifest, the new manifest, the robot-terms diff and (under --force)
backups. Applying it is write/transaction.apply's job.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import PurePosixPath

import rhi_gen

from ..errors import ManifestError, ProjectError, WriteBlockedError
from ..model import PackageInfo, RobotModel
from ..project import PACKAGE_NAME, Project
from ..render.banner import GENERATOR_MARK
from ..render.package import render_package, robot_paths
from ..write.api_migration import ApiRename
from ..write.backups import backup_changes
from ..write.changes import CHANGED, CREATED, REMOVED, UNCHANGED, FileChange
from ..write.manifest import MANIFEST_NAME, Manifest, RobotRecord, robot_key, robot_record, sha256_hex
from ..write.manifest import dumps as dump_manifest
from ..write.manifest import parse as parse_manifest
from ..write.manifest import read_bytes as read_manifest_bytes
from ..write.merge import Blocked, blocked_error, merge_existing, removal_problem, rendered_hash
from ..write.semantic_diff import RobotDiff, diff_manifest
from .load import LoadedRobot, load_package_info

OWNED_MARK = GENERATOR_MARK.encode("utf-8")


MESH_DIR = f"{PACKAGE_NAME}/meshes/"  # copies of the robots' meshes (inputs/urdf_meshes.py): bytes, no banner


def render_plan(models: Sequence[RobotModel], package: PackageInfo) -> dict[str, bytes]:
    """Paths relative to generated/ -> bytes."""
    rendered = render_package(models, package=package)
    return {f"{PACKAGE_NAME}/{rel}": text.encode("utf-8") for rel, text in rendered.items()}


def mesh_plan(project: Project, models: Sequence[RobotModel]) -> dict[str, bytes]:
    """Paths relative to generated/ -> the bytes of each mesh copied into the package, byte for byte."""
    plan: dict[str, bytes] = {}
    for model in models:
        for mesh in model.meshes:
            rel = f"{PACKAGE_NAME}/{mesh.path}"
            if rel in plan:
                continue
            try:
                plan[rel] = (project.root / mesh.source).read_bytes()
            except OSError as exc:
                raise ProjectError(f"cannot read mesh: {exc.strerror}", file=mesh.source,
                                   fix="fix its permissions, or remove it (meshes are optional)") from exc
    return plan


def is_mesh(rel: str) -> bool:
    return rel.startswith(MESH_DIR)


def meshes_on_disk(project: Project) -> list[str]:
    """Every file in generated/robot_hardware_interface/meshes: rhi-gen owns that folder whole."""
    folder = project.generated_dir / MESH_DIR
    if not folder.is_dir():
        return []
    return sorted(p.relative_to(project.generated_dir).as_posix() for p in folder.rglob("*")
                  if p.is_file() and not p.name.endswith((".rhi-tmp", ".rhi-bak")))


def robot_files(plan: dict[str, bytes], model: RobotModel) -> set[str]:
    """The plan entries that belong to one robot (everything else is shared)."""
    own = {f"{PACKAGE_NAME}/{p}" for p in robot_paths(model.vendor, model.robot)}
    own |= {f"{PACKAGE_NAME}/{m.path}" for m in model.meshes}
    return {p for p in plan if p in own}


def owned_files_on_disk(project: Project) -> list[str]:
    """Files under generated/robot_hardware_interface that rhi-gen wrote (they carry its banner)."""
    root = project.package_dir
    if not root.is_dir():
        return []
    owned = []
    for path in sorted(root.rglob("*")):
        if path.is_file() and not path.name.endswith((".rhi-tmp", ".rhi-bak")):
            try:
                with path.open("rb") as handle:
                    head = handle.read(2048)
            except OSError:
                continue
            if OWNED_MARK in head:
                owned.append(path.relative_to(project.generated_dir).as_posix())
    return owned


@dataclass(frozen=True)
class GenerationPlan:
    """Everything `generate` would do, computed before anything is written."""
    files: list[FileChange]          # package files, relative to generated/
    manifest_change: FileChange      # generated/.rhi-gen-manifest
    backups: list[FileChange]        # --force only: .rhi-gen-backup/<path>.N of each blocked file
    blocked: list[Blocked]
    robot_diffs: list[RobotDiff]     # in robot terms, per robot in scope (and removed robots)
    old_manifest: Manifest | None
    generator_version: str           # the rhi-gen making this plan
    renames: tuple[ApiRename, ...] = ()  # old API names rewritten in user regions

    @property
    def changes(self) -> list[FileChange]:
        """One transaction for write.transaction.apply(generated_dir, ...): files, manifest and backups."""
        return [*self.files, self.manifest_change, *self.backups]

    @property
    def differs(self) -> bool:
        return any(c.status != UNCHANGED for c in (*self.files, self.manifest_change))

    @property
    def stale(self) -> list[RobotDiff]:
        return [d for d in self.robot_diffs if d.stale]

    @property
    def other_version(self) -> str | None:
        """The rhi-gen version that wrote generated/, when it is not this one."""
        old = self.old_manifest
        return old.generator_version if old is not None and old.generator_version != self.generator_version else None

    def blocked_error(self) -> WriteBlockedError:
        return blocked_error(self.blocked)


def _read(project: Project, rel: str) -> bytes:
    try:
        return (project.generated_dir / rel).read_bytes()
    except OSError as exc:
        raise ProjectError(f"cannot read: {exc.strerror}", file=f"generated/{rel}",
                           fix="fix its permissions; nothing was written") from exc


def _safe_rel(rel: str) -> bool:
    parts = PurePosixPath(rel).parts
    return (not PurePosixPath(rel).is_absolute() and ".." not in parts and len(parts) > 1
            and parts[0] == PACKAGE_NAME)


def plan_generation(project: Project, robots: Sequence[LoadedRobot], only: Sequence[LoadedRobot] | None = None,
                    *, force: bool = False) -> GenerationPlan:
    """What `generate` would write: rendered files with user regions carried over, the new manifest,
    hand-edit checks against the old manifest and, under ``force``, backups of the blocked files.

    ``only`` restricts per-robot files to those robots; shared files always follow every robot. Reads
    the disk, writes nothing; raises only for bad input (RhiGenError).
    """
    version = rhi_gen.__version__  # read now, not at import: tests stand in for an upgrade
    gen = project.generated_dir
    rendered = render_plan([r.model for r in robots], load_package_info(project))
    rendered.update(mesh_plan(project, [r.model for r in robots]))
    rendered = dict(sorted(rendered.items()))
    scope = list(robots) if only is None else [r for r in robots if r in only]
    if only is not None:
        skip: set[str] = set()
        for r in robots:
            if r not in only:
                skip |= robot_files(rendered, r.model)
        rendered = {k: v for k, v in rendered.items() if k not in skip}

    manifest_bytes = read_manifest_bytes(gen)
    corrupt = False
    try:
        old_manifest = parse_manifest(manifest_bytes)
    except ManifestError:
        if not force:
            raise
        old_manifest, corrupt = None, True
    have_manifest = old_manifest is not None
    recorded = old_manifest.files if old_manifest else {}

    files: list[FileChange] = []
    blocked: list[Blocked] = []
    renames: list[ApiRename] = []
    new_hashes: dict[str, str] = {}
    for rel, data in rendered.items():
        if is_mesh(rel):  # a copy of an input: rewritten whenever it differs, never a hand edit to keep
            new_hashes[rel] = sha256_hex(data)
            old = _read(project, rel) if (gen / rel).is_file() else None
            files.append(FileChange(rel, CREATED if old is None else UNCHANGED if old == data else CHANGED, old, data))
            continue
        text = data.decode("utf-8")
        new_hashes[rel] = rendered_hash(rel, text)
        if not (gen / rel).is_file():
            files.append(FileChange(rel, CREATED, None, data))
            continue
        old_bytes = _read(project, rel)
        merged = merge_existing(rel, text, old_bytes, recorded, have_manifest)
        if merged.problem:
            blocked.append(merged.problem)
        renames.extend(merged.renames)
        files.append(FileChange(rel, UNCHANGED if merged.data == old_bytes else CHANGED, old_bytes, merged.data))

    if only is None:
        candidates = set(recorded) if have_manifest else set(owned_files_on_disk(project))
        candidates |= set(meshes_on_disk(project))
        for rel in sorted(c for c in candidates - set(rendered) if _safe_rel(c)):
            if not (gen / rel).is_file():
                continue
            old_bytes = _read(project, rel)
            if is_mesh(rel):
                files.append(FileChange(rel, REMOVED, old_bytes, None))
                continue
            problem = removal_problem(rel, old_bytes, recorded, have_manifest)
            if problem:
                blocked.append(problem)
            files.append(FileChange(rel, REMOVED, old_bytes, None))

    records = {robot_key(r.model): robot_record(r.model) for r in scope}
    robots_map: dict[str, RobotRecord] = {}
    files_map: dict[str, str] = {}
    if only is not None and old_manifest is not None:
        robots_map.update(old_manifest.robots)
        files_map.update({k: v for k, v in old_manifest.files.items() if k not in rendered})
    robots_map.update(records)
    files_map.update(new_hashes)
    new_manifest_bytes = dump_manifest(Manifest(version, robots_map, files_map)).encode("utf-8")
    manifest_change = FileChange(
        MANIFEST_NAME,
        CREATED if manifest_bytes is None else (UNCHANGED if manifest_bytes == new_manifest_bytes else CHANGED),
        manifest_bytes, new_manifest_bytes)

    removed_keys = [] if only is not None or old_manifest is None else \
        sorted(set(old_manifest.robots) - {robot_key(r.model) for r in robots})
    robot_diffs = diff_manifest(old_manifest, list(records.values()), removed_keys=removed_keys)

    backups: list[FileChange] = []
    if force:
        originals = {b.path: _read(project, b.path) for b in blocked}
        if corrupt and manifest_bytes is not None and manifest_change.status != UNCHANGED:
            originals[MANIFEST_NAME] = manifest_bytes
        backups = backup_changes(gen, originals)
    return GenerationPlan(files, manifest_change, backups, blocked, robot_diffs, old_manifest, version,
                          tuple(renames))
