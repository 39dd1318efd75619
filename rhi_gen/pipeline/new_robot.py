"""`rhi-gen new`: the suggested vendor YAML and the files it generates, planned before anything is written."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..assemble.robot_model import build_model
from ..errors import ConfigError, InputWarning, ProjectError, WriteBlockedError
from ..inputs import wording
from ..inputs.scaffold import relative_urdf_path, suggest_yaml
from ..inputs.urdf_loader import is_xacro, load_urdf
from ..inputs.vendor_config import config_from_data
from ..model import UrdfRobot
from ..project import PACKAGE_NAME, Project, robot_yamls, validate_names
from ..typed_yaml.yaml_source import parse_yaml_text
from ..write.changes import FileChange, compare
from .existing_tags import existing_tag_warning
from .generate import plan_generation
from .load import Clash, LoadedRobot, find_clash, load_robots, path_owner
from .outside_description import DescriptionCopy, plan_copy


@dataclass(frozen=True)
class NewRobotPlan:
    yaml_relpath: str
    yaml_text: str
    robot: LoadedRobot
    changes: list[FileChange]  # relative to the project root: the YAML, the description's copy, generated/ files
    warnings: tuple[InputWarning, ...] = ()  # accepted, but the user must know (printed after success)
    copy: DescriptionCopy | None = None      # the description lay (or read files) outside the project


def bringup_commands(robot: str, *, fake_robot: bool) -> tuple[tuple[str, str], ...]:
    """(label, command) of each way to start the robot once the package is built: mock hardware, the
    generated fake robot where the robot has one, then the robot."""
    launch = f"ros2 launch {PACKAGE_NAME} {robot}.launch.py"
    fake = (("with a fake robot", f"{launch} use_fake_robot:=true"),) if fake_robot else ()
    return (("without the robot", f"{launch} use_mock_hardware:=true"), *fake, ("on the robot", launch))


def clash_error(project: Project, clash: Clash, *, class_prefix: str | None) -> ProjectError:
    """The new robot clashes with one already in the project: in the words of `rhi-gen new`."""
    m = clash.robot.model
    others = project.relative(clash.other.yaml_path) if clash.other is not None else "rhi-gen"
    if clash.kind == "robot name":
        return ProjectError(f"robot name {m.robot!r} is already used by {others} (robot names share "
                            "description/, config/ and test/)", key="--robot", fix="choose another --robot name")
    if clash.kind == "plugin class":
        if class_prefix is not None:
            return ProjectError(f"plugin class {clash.value} is already generated for {others}",
                                key="--class-prefix", fix="choose another --class-prefix")
        return ProjectError(f"robot {m.robot!r} would generate plugin class {clash.value}, which {others} "
                            "already generates", key="--robot",
                            fix="choose another --robot name, or keep it and give this robot its own class with "
                                "--class-prefix NAME (written to its YAML as class_prefix:)")
    return ProjectError(f"robot {m.vendor}/{m.robot} would write generated/{PACKAGE_NAME}/{clash.value}, "
                        f"{path_owner(project, clash)}", key="--robot", fix="choose another --robot name")


def _yaml_text(*, vendor: str, robot: str, urdf: UrdfRobot, urdf_path: Path, yaml_dir: Path,
               copy: DescriptionCopy | None, transport: str | None, xacro_args: dict[str, str],
               package_paths: dict[str, str], class_prefix: str | None, transport_options: dict[str, str]) -> str:
    """The suggested YAML: naming the description where it is (paths relative to the YAML), or its copy."""
    if copy is not None:  # already expanded: no xacro_args or package_paths to record
        return suggest_yaml(vendor=vendor, robot=robot, urdf=urdf, urdf_relative=copy.file_name, transport=transport,
                            class_prefix=class_prefix, urdf_comment=copy.yaml_comment(),
                            transport_options=transport_options)
    return suggest_yaml(vendor=vendor, robot=robot, urdf=urdf, urdf_relative=relative_urdf_path(urdf_path, yaml_dir),
                        transport=transport, xacro_args=xacro_args, class_prefix=class_prefix,
                        transport_options=transport_options,
                        package_paths={k: relative_urdf_path(Path(v), yaml_dir) for k, v in package_paths.items()})


def _in_command_words(exc: ConfigError, given: dict[str, str]) -> ConfigError:
    """A bad ``--transport-option`` value, named as the option (the YAML it would go to is not written)."""
    key = (exc.key or "").removeprefix("transport_options.").split(".")[0]
    if key not in given:
        return exc
    return ConfigError(f"{key}={given[key]}: {exc.message}", key="--transport-option", fix=exc.fix)


def plan_new_robot(project: Project, *, vendor: str, robot: str, urdf_path: Path, transport: str | None,
                   xacro_args: dict[str, str], package_paths: dict[str, str], force: bool,
                   class_prefix: str | None = None,
                   transport_options: dict[str, str] | None = None) -> NewRobotPlan:
    """Everything `rhi-gen new` will write, computed before anything is written.

    Refuses (ProjectError, nothing written) a robot that clashes with one of the project: same robot
    name, same plugin class, or a generated file another robot writes (pipeline.load.find_clash).
    """
    validate_names(vendor, robot, class_prefix)
    yaml_path = project.yaml_path(vendor, robot)
    yaml_rel = project.relative(yaml_path)
    if yaml_path.exists() and not force:
        raise ProjectError("already exists", file=yaml_rel,
                           fix="run `rhi-gen generate` to regenerate it, or `rhi-gen new --force` to start over")
    if not urdf_path.is_file():
        raise ProjectError("URDF not found" if not urdf_path.exists() else "is not a file", file=str(urdf_path),
                           key="--urdf", fix="give the path of a .urdf or .xacro file")
    urdf = load_urdf(urdf_path, xacro_args=xacro_args,
                     package_paths={k: Path(v) for k, v in package_paths.items()},
                     display_path=str(urdf_path), wording=wording.CLI)
    copy = plan_copy(project, vendor=vendor, robot=robot, urdf_path=urdf_path, urdf=urdf, xacro_args=xacro_args,
                     package_paths=package_paths, force=force)
    text = _yaml_text(vendor=vendor, robot=robot, urdf=urdf, urdf_path=urdf_path, yaml_dir=yaml_path.parent,
                      copy=copy, transport=transport, xacro_args=xacro_args, package_paths=package_paths,
                      class_prefix=class_prefix, transport_options=transport_options or {})
    # The model is built from the in-memory YAML, through the normal validator: nothing is on disk yet.
    data, lines = parse_yaml_text(text, yaml_rel)
    try:
        config = config_from_data(data, lines, yaml_rel, yaml_path.parent)
    except ConfigError as exc:
        raise _in_command_words(exc, transport_options or {}) from None
    model = build_model(config, urdf, yaml_path=yaml_path, project_root=project.root)
    new = LoadedRobot(yaml_path, config, urdf, model)
    others = load_robots(project, [p for p in robot_yamls(project) if p.resolve() != yaml_path.resolve()])
    clash = find_clash([*others, new])
    if clash is not None:
        raise clash_error(project, clash, class_prefix=class_prefix)
    # Only the new robot's files and the shared ones: other drivers stay as they are, user regions of
    # the shared files (CMakeLists.txt) are carried over and hand edits block as in `generate`.
    generation = plan_generation(project, [*others, new], only=[new])
    if generation.blocked:
        err = generation.blocked_error()
        raise WriteBlockedError(err.message, file=err.file, line=err.line,
                                fix="move the edits into user regions, or run `rhi-gen generate --force` first "
                                    "(keeps a backup), then rerun `rhi-gen new`")
    prefixed = [FileChange(f"generated/{c.path}", c.status, c.old, c.new) for c in generation.changes]
    warning = existing_tag_warning(urdf, model, xacro=is_xacro(urdf_path))
    inputs = {yaml_rel: text.encode("utf-8"), **({copy.rel: copy.data} if copy is not None else {})}
    return NewRobotPlan(yaml_rel, text, new, [*compare(project.root, inputs), *prefixed],
                        warnings=(*((warning,) if warning is not None else ()), *new.transmission_warnings),
                        copy=copy)
