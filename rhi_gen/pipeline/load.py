"""Inputs -> model for every robot of a project: YAML + URDF loaded, cross-checked, names unique."""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from .. import transports
from ..assemble.robot_model import build_model
from ..assemble.transmissions import decide_transmissions
from ..errors import ConfigError, InputWarning, ProjectError
from ..inputs import package_info
from ..inputs.urdf_loader import load_urdf
from ..inputs.vendor_config import load_config
from ..model import PackageInfo, RobotModel, UrdfRobot, VendorConfig
from ..project import PACKAGE_NAME, Project, check_layout, robot_yamls, select_yamls
from ..render.package import COMMON_FILES, FAKE_ROBOT_FILES, PACKAGE_FILES, TEST_FILES, robot_paths


@dataclass(frozen=True)
class LoadedRobot:
    yaml_path: Path
    config: VendorConfig
    urdf: UrdfRobot
    model: RobotModel

    @property
    def transmission_warnings(self) -> tuple[InputWarning, ...]:
        """The URDF <transmission>s rhi-gen does not apply to this robot, one warning per kind of reason."""
        return decide_transmissions(self.config, self.urdf).warnings


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


def load_package_info(project: Project) -> PackageInfo:
    """robots/package.yaml (copyright, license, maintainer), or the neutral defaults."""
    return package_info.load_package_info(
        project.robots_dir, project.relative(project.robots_dir / package_info.FILE_NAME))


def load_robots(project: Project, yaml_paths: Sequence[Path] | None = None) -> list[LoadedRobot]:
    """Load every robot (or those given); names must be unique across the package."""
    paths = list(yaml_paths) if yaml_paths is not None else robot_yamls(project)
    robots = [load_robot(project, p) for p in paths]
    check_unique(project, robots)
    return robots


@dataclass(frozen=True)
class Clash:
    """Two robots (or a robot and rhi-gen's shared files) that would generate the same thing."""
    kind: str                   # "robot name" | "plugin class" | "path"
    value: str                  # 'arm' | 'unitree::H12HardwareInterface' | a package path
    robot: LoadedRobot          # the robot that clashes (the later one)
    other: LoadedRobot | None   # the robot it clashes with; None: rhi-gen's shared files


def shared_paths() -> frozenset[str]:
    """Package paths rhi-gen writes once for all robots (a robot's own file must never be one)."""
    paths = {out for _, out in (*COMMON_FILES, *TEST_FILES, *FAKE_ROBOT_FILES, *PACKAGE_FILES)}
    for transport in transports.TRANSPORTS.values():
        paths |= {out for _, out in transport.shared_files}
    return frozenset(paths)


def find_clash(robots: Sequence[LoadedRobot]) -> Clash | None:
    """The first clash in ``robots`` order: a robot name used twice (description/, config/ and test/
    are per robot name), a plugin class generated twice (one plugin file lists them all), or a
    package file written twice. None when every robot can live in the one package."""
    names: dict[str, LoadedRobot] = {}
    classes: dict[str, LoadedRobot] = {}
    paths: dict[str, LoadedRobot | None] = dict.fromkeys(shared_paths())
    for r in robots:
        m = r.model
        if m.robot in names:
            return Clash("robot name", m.robot, r, names[m.robot])
        names[m.robot] = r
        cls = m.qualified_class_name
        if cls in classes:
            return Clash("plugin class", cls, r, classes[cls])
        classes[cls] = r
        for path in robot_paths(m.vendor, m.robot):
            if path in paths:
                return Clash("path", path, r, paths[path])
            paths[path] = r
    return None


def clash_error(project: Project, clash: Clash) -> ProjectError:
    """A clash between robots of the project, in the words of their vendor YAMLs."""
    r, other = clash.robot, clash.other
    shown = project.relative(r.yaml_path)
    lines = r.config.key_lines
    others = project.relative(other.yaml_path) if other is not None else "rhi-gen"
    if clash.kind == "robot name":
        return ProjectError(f"robot name {clash.value!r} is also used by {others}", file=shown,
                            line=lines.get("robot"), key="robot",
                            fix="rename one of the two robots (robot: and the file name): robot names share "
                                "description/, config/ and test/")
    if clash.kind == "plugin class":
        key = "class_prefix" if "class_prefix" in lines else "robot"
        return ProjectError(f"plugin class {clash.value} is also generated for {others}", file=shown,
                            line=lines.get(key), key=key,
                            fix="set class_prefix: <Name> in one of the two YAMLs so each robot has its own class")
    return ProjectError(f"would write generated/{PACKAGE_NAME}/{clash.value}, {path_owner(project, clash)}",
                        file=shown, line=lines.get("robot"), key="robot", fix="rename the robot (or its vendor)")


def path_owner(project: Project, clash: Clash) -> str:
    """Who else writes the clashing file, as the end of a sentence."""
    if clash.other is None:
        return "which is one of rhi-gen's shared files"
    return f"which {project.relative(clash.other.yaml_path)} also writes"


def check_unique(project: Project, robots: Sequence[LoadedRobot]) -> None:
    """Every robot must fit in the one package next to the others (see find_clash)."""
    clash = find_clash(robots)
    if clash is not None:
        raise clash_error(project, clash)


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
