"""Inputs -> model for every robot of a project: YAML + URDF loaded, cross-checked, names unique."""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from ..errors import ConfigError, ProjectError
from ..inputs.urdf_loader import load_urdf
from ..inputs.vendor_config import load_config
from ..model import RobotModel, UrdfRobot, VendorConfig
from ..model.build import build_model
from ..project import Project, check_layout, robot_yamls, select_yamls


@dataclass(frozen=True)
class LoadedRobot:
    yaml_path: Path
    config: VendorConfig
    urdf: UrdfRobot
    model: RobotModel


def load_robot(project: Project, yaml_path: Path) -> LoadedRobot:
    """One robot: its vendor YAML, the URDF it names, and the model built from both."""
    shown = project.relative(yaml_path)
    config = load_config(yaml_path, display_path=shown)
    if yaml_path.resolve().is_relative_to(project.robots_dir.resolve()):
        check_layout(project, yaml_path, config.vendor, config.robot)
    urdf_path = Path(config.urdf)
    if not urdf_path.is_file():
        what = "is a directory" if urdf_path.is_dir() else "does not exist"
        raise ConfigError(f"{config.urdf_relative!r} {what}", file=shown, line=config.key_lines.get("urdf"),
                          key="urdf", fix="give the URDF or xacro path relative to this YAML")
    urdf = load_urdf(urdf_path, xacro_args=dict(config.xacro_args),
                     package_paths={k: Path(v) for k, v in config.package_paths},
                     display_path=project.relative(urdf_path))
    model = build_model(config, urdf, yaml_path=yaml_path, project_root=project.root)
    return LoadedRobot(yaml_path, config, urdf, model)


def load_robots(project: Project, yaml_paths: Sequence[Path] | None = None) -> list[LoadedRobot]:
    """Load every robot (or those given); names must be unique across the package."""
    paths = list(yaml_paths) if yaml_paths is not None else robot_yamls(project)
    robots = [load_robot(project, p) for p in paths]
    check_unique(project, robots)
    return robots


def check_unique(project: Project, robots: Sequence[LoadedRobot]) -> None:
    """Robot names share description/ and config/, class names share a plugin file: both must be unique."""
    seen: dict[str, LoadedRobot] = {}
    classes: dict[str, LoadedRobot] = {}
    for r in robots:
        other = seen.get(r.model.robot)
        if other is not None:
            raise ProjectError(f"robot name {r.model.robot!r} is also used by {project.relative(other.yaml_path)}",
                               file=project.relative(r.yaml_path), key="robot",
                               fix="robot names share description/ and config/ folders; make them unique")
        seen[r.model.robot] = r
        key = f"{r.model.vendor}::{r.model.class_name}"
        if key in classes:
            raise ProjectError(f"class {key} is also generated for {project.relative(classes[key].yaml_path)}",
                               file=project.relative(r.yaml_path), key="class_prefix",
                               fix="set a distinct class_prefix")
        classes[key] = r


def load_selected(project: Project, names: Sequence[str] | None, progress: Callable[[str], None] | None = None,
                  ) -> tuple[list[LoadedRobot], list[LoadedRobot] | None]:
    """Every robot (shared files need them all) and, when ``names`` are given, the chosen ones.

    ``progress`` (``generate --verbose``) hears of each YAML as it is loaded; by default nothing is said.
    """
    every = robot_yamls(project)
    if not every:
        raise ProjectError("no robots found", file=project.relative(project.robots_dir),
                           fix="add one with `rhi-gen new --vendor V --robot R --urdf FILE`")
    chosen = set(select_yamls(project, list(names) if names else None))
    loaded = []
    for path in every:
        if progress is not None:
            progress(f"loading {project.relative(path)}")
        loaded.append(load_robot(project, path))
    check_unique(project, loaded)
    only = [r for r in loaded if r.yaml_path in chosen] if names else None
    return loaded, only
