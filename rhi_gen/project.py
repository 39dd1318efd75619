"""Where a project's inputs and outputs live: robots/<vendor>/<robot>.yaml and generated/."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .errors import ProjectError

PACKAGE_NAME = "robot_hardware_interface"


@dataclass(frozen=True)
class Project:
    root: Path

    @property
    def robots_dir(self) -> Path:
        return self.root / "robots"

    @property
    def generated_dir(self) -> Path:
        return self.root / "generated"

    @property
    def package_dir(self) -> Path:
        return self.generated_dir / PACKAGE_NAME

    def relative(self, path: Path) -> str:
        """``path`` relative to the project root (POSIX), or its absolute path when it lies outside."""
        try:
            return path.resolve().relative_to(self.root.resolve()).as_posix()
        except ValueError:
            return str(path.resolve())

    def yaml_path(self, vendor: str, robot: str) -> Path:
        return self.robots_dir / vendor / f"{robot}.yaml"


def find_project(explicit: Path | None = None) -> Project:
    """The folder holding robots/: the one named, else the current folder or its nearest parent."""
    if explicit is not None:
        if not explicit.is_dir():
            raise ProjectError("project folder does not exist", file=str(explicit),
                               fix="create it first (mkdir), or give the folder that holds robots/")
        return Project(explicit.resolve())
    here = Path.cwd().resolve()
    for folder in (here, *here.parents):
        if (folder / "robots").is_dir():
            return Project(folder)
    return Project(here)


def robot_yamls(project: Project) -> list[Path]:
    """Every robots/<vendor>/<robot>.yaml, sorted (deterministic order)."""
    if not project.robots_dir.is_dir():
        return []
    found = []
    for vendor_dir in sorted(p for p in project.robots_dir.iterdir() if p.is_dir()):
        for yml in sorted(vendor_dir.glob("*.yaml")):
            if yml.is_file():
                found.append(yml)
    return found


def check_layout(project: Project, yaml_path: Path, vendor: str, robot: str) -> None:
    """robots/<vendor>/<robot>.yaml must say vendor: <vendor>, robot: <robot> (one name, one place)."""
    shown = project.relative(yaml_path)
    if yaml_path.parent.name != vendor:
        raise ProjectError(f"says vendor {vendor!r} but lies in robots/{yaml_path.parent.name}/",
                           file=shown, key="vendor", fix=f"move it to robots/{vendor}/{robot}.yaml")
    if yaml_path.stem != robot:
        raise ProjectError(f"says robot {robot!r} but is named {yaml_path.name}", file=shown, key="robot",
                           fix=f"rename it to {robot}.yaml")


def select_yamls(project: Project, names: list[str] | None) -> list[Path]:
    """Filter robot YAMLs by 'robot' or 'vendor/robot'; unknown names are an error."""
    every = robot_yamls(project)
    if not names:
        return every
    chosen: list[Path] = []
    for name in names:
        hits = [p for p in every if name in (p.stem, f"{p.parent.name}/{p.stem}")]
        if not hits:
            known = ", ".join(f"{p.parent.name}/{p.stem}" for p in every) or "none"
            raise ProjectError(f"no robot named {name!r}", file="robots/",
                               fix=f"known robots: {known}; add one with `rhi-gen new`")
        chosen.extend(h for h in hits if h not in chosen)
    return chosen


def validate_names(vendor: str, robot: str, class_prefix: str | None = None) -> None:
    """For `new`: refuse names that would escape robots/ or break C++ before touching disk."""
    # imported here: rhi_gen.model (40 ms) is not needed to find a project (`rhi-gen check`'s first step)
    from .model.naming import CLASS_PREFIX_RE, CPP_KEYWORDS, identifier_problem, vendor_problem

    for problem, key in ((vendor_problem(vendor), "--vendor"), (identifier_problem(robot, "robot"), "--robot")):
        if problem:
            raise ProjectError(problem, key=key, fix="choose another name: lowercase letters, digits and "
                               "underscores, not a C++ keyword or a reserved name (e.g. my_company, my_arm)")
    if class_prefix is not None and (not CLASS_PREFIX_RE.match(class_prefix) or class_prefix.lower() in CPP_KEYWORDS):
        # the rule vendor_config applies to class_prefix:, checked here so the error names the option
        raise ProjectError(f"{class_prefix!r} must be a C++ identifier starting with an uppercase letter "
                           "(letters and digits only)", key="--class-prefix", fix="e.g. H12 or MyArm")
