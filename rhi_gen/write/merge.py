"""Regenerating over files already on disk: carry user-region bodies into the fresh render, and
decide which files must not be overwritten (or removed) without --force because they hold
hand-written code outside user regions, in regions the templates dropped, or broken markers.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import GenerationError, RegionError, WriteBlockedError
from .api_migration import ApiRename, migrate_region_bodies
from .manifest import MANIFEST_NAME, generated_hash
from .regions import FIX_MARKERS, OrphanedRegion, splice, user_code_regions

FIX_FORCE = "or rerun with --force to overwrite it (the current file is kept in generated/.rhi-gen-backup/)"
FIX_TEMPLATE_BUG = "this is a bug in rhi-gen's templates; please report it"

# Driver regions of rhi-gen before the shared driver core, and the SystemDriver hook their code moves to.
RETIRED_REGIONS = {
    "parameters": "on_init_hook(const hardware_interface::HardwareInfo & info)",
    "sdk_init": "on_init_hook(const hardware_interface::HardwareInfo & info)",
    "on_activate": "on_activate_hook()",
    "on_deactivate": "on_deactivate_hook()",
}


@dataclass(frozen=True)
class Blocked:
    """A file generate must not overwrite (or remove) without --force: it holds hand-written code."""
    path: str          # relative to generated/
    reason: str        # edited | unrecorded | orphaned | markers
    message: str       # what is wrong, one line, without the path
    fix: str
    line: int | None = None

    @property
    def error(self) -> WriteBlockedError:
        return WriteBlockedError(f"{self.message}; nothing was written", file=f"generated/{self.path}",
                                 line=self.line, fix=self.fix)

    def note(self) -> str:
        where = f"generated/{self.path}" + (f":{self.line}" if self.line else "")
        return f"{where}: {self.message}"


def blocked_error(blocked: list[Blocked]) -> WriteBlockedError:
    """One error for every blocked file (the file's own when there is one)."""
    if len(blocked) == 1:
        return blocked[0].error
    names = ", ".join(f"generated/{b.path}" for b in blocked)
    return WriteBlockedError(f"{len(blocked)} generated files hold hand-written code outside user regions "
                             f"or in regions the templates dropped ({names}); nothing was written",
                             fix="move the edits into user regions (`rhi-gen diff` shows them), or rerun with "
                                 "--force (the current files are kept in generated/.rhi-gen-backup/)")


def rendered_hash(rel: str, text: str) -> str:
    """The manifest hash of a freshly rendered file; broken markers there are a template bug."""
    try:
        return generated_hash(text, f"generated/{rel} (as rendered)")
    except RegionError as exc:
        raise GenerationError(f"templates produced broken user-region markers: {exc.message}", file=exc.file,
                              line=exc.line, fix=FIX_TEMPLATE_BUG) from exc


def _edit_problem(rel: str, old_text: str, recorded: dict[str, str], have_manifest: bool) -> Blocked | None:
    """Whether the file on disk differs, outside its user regions, from what rhi-gen last wrote."""
    on_disk = generated_hash(old_text, f"generated/{rel}")
    if rel not in recorded:
        where = "is not recorded in" if have_manifest else "has no record: there is no"
        return Blocked(rel, "unrecorded", f"{where} generated/{MANIFEST_NAME}, so a hand edit cannot be ruled out",
                       "check it with `rhi-gen diff`, then rerun `rhi-gen generate` with --force "
                       "(the current file is kept in generated/.rhi-gen-backup/)")
    if recorded[rel] != on_disk:
        return Blocked(rel, "edited", "edited outside its user regions since the last `rhi-gen generate`",
                       f"move the edit into a user region (`rhi-gen diff` shows it), {FIX_FORCE}")
    return None


def _orphan_problem(rel: str, orphans: list[OrphanedRegion], why: str) -> Blocked:
    names = ", ".join(f"{o.name!r} (line {o.line})" for o in orphans)
    plural = "s" if len(orphans) > 1 else ""
    retired = [o for o in orphans if o.name in RETIRED_REGIONS and rel.endswith(".cpp")]
    fix = f"move the code into another user region or empty the region, {FIX_FORCE}"
    if retired:
        hooks = "; ".join(f"{o.name!r} -> override {RETIRED_REGIONS[o.name]}" for o in retired)
        fix = (f"the driver logic moved into robot_hardware_interface::SystemDriver, whose hooks take this code "
               f"({hooks}): declare the override in the header's 'members' region, define it in this file's "
               f"'callbacks' region, empty the old region, then rerun; {FIX_FORCE}")
    return Blocked(rel, "orphaned", f"user region{plural} {names} hold{'' if plural else 's'} code but {why}",
                   fix, line=orphans[0].line)


@dataclass(frozen=True)
class Merged:
    """What regenerating one existing file gives: its bytes, what blocks writing them, what was renamed."""
    data: bytes
    problem: Blocked | None = None
    renames: tuple[ApiRename, ...] = ()


def merge_existing(rel: str, rendered: str, old_bytes: bytes, recorded: dict[str, str],
                   have_manifest: bool) -> Merged:
    """The bytes to write for ``rel`` (fresh render + the old region bodies, old API names renamed)
    and what blocks it, if anything."""
    shown = f"generated/{rel}"
    try:
        old_text = old_bytes.decode("utf-8")
    except UnicodeDecodeError:
        return Merged(rendered.encode("utf-8"), Blocked(rel, "edited", "is no longer UTF-8 text (edited outside "
                                                        "rhi-gen)", f"restore it from version control, {FIX_FORCE}"))
    try:
        bodies, renames = migrate_region_bodies(old_text, shown)
        merged, orphans = splice(rendered, bodies, shown)
    except RegionError as exc:
        if exc.file != shown:  # the fresh render itself: a template bug
            raise GenerationError(f"templates produced broken user-region markers: {exc.message}", file=exc.file,
                                  line=exc.line, fix=FIX_TEMPLATE_BUG) from exc
        return Merged(rendered.encode("utf-8"), Blocked(rel, "markers", exc.message, FIX_MARKERS, line=exc.line))
    data = merged.encode("utf-8")
    if data == old_bytes:
        return Merged(data)
    if orphans:
        return Merged(data, _orphan_problem(rel, orphans, "the new template has no such region"), tuple(renames))
    return Merged(data, _edit_problem(rel, old_text, recorded, have_manifest), tuple(renames))


def removal_problem(rel: str, old_bytes: bytes, recorded: dict[str, str], have_manifest: bool) -> Blocked | None:
    """What blocks removing ``rel`` (a file no longer generated), if anything."""
    shown = f"generated/{rel}"
    try:
        old_text = old_bytes.decode("utf-8")
        orphans = user_code_regions(old_text, shown)
    except UnicodeDecodeError:
        return Blocked(rel, "edited", "would be removed but is no longer UTF-8 text (edited outside rhi-gen)",
                       f"move it out of generated/, {FIX_FORCE}")
    except RegionError as exc:
        return Blocked(rel, "markers", f"would be removed; {exc.message}", FIX_MARKERS, line=exc.line)
    if orphans:
        return _orphan_problem(rel, orphans, "the file is no longer generated (its robot or transport is gone)")
    return _edit_problem(rel, old_text, recorded, have_manifest)
