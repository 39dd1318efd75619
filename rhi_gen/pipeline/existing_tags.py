"""A description that already drives the robot's joints through its own <ros2_control> tag.

Franka's description with ``ros2_control:=true``, UR's mocked one, xArm's and TIAGo's in
example-robot-data: each carries a <ros2_control> tag with another plugin for the very joints the
generated driver drives. That is a legitimate starting point (migrating a robot to rhi-gen), so it
is a warning, not an error: `new` and `generate` still write everything and exit 0, and say once per
robot what the tag is and what to do, so the include step of docs/adding-a-robot.md never silently adds a second tag
on the same joints. `check` (a CI gate) and `diff` say nothing about it.

Silent when there is nothing to choose: a tag whose plugin is the generated one (the description
already includes the generated macro), or tags on joints the generated driver leaves alone
(another hardware component for a gripper listed under unmapped_joints, a sensor-only tag).
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from ..errors import InputWarning
from ..inputs.urdf_loader import is_xacro
from ..model import RobotModel, UrdfRobot
from ..model.naming import legacy_plugin_name
from ..model.urdf import Ros2ControlBlock
from ..render.package import ROBOT_FILES
from .load import LoadedRobot

SHOWN_NAMES = 3  # joint names a warning lists before "and N more"


def _few(names: Sequence[str]) -> str:
    shown = ", ".join(names[:SHOWN_NAMES])
    return shown + (f" and {len(names) - SHOWN_NAMES} more" if len(names) > SHOWN_NAMES else "")


def _tags(blocks: Sequence[Ros2ControlBlock]) -> str:
    """The tags as a reader finds them in the file: name and plugin."""
    def plugin(block: Ros2ControlBlock) -> str:
        return f"plugin {block.plugin}" if block.plugin else "no <plugin>"

    if len(blocks) == 1:
        return f'<ros2_control name="{blocks[0].name}"> with {plugin(blocks[0])}'
    plugins = {b.plugin for b in blocks}
    names = ", ".join(f'"{b.name}"' for b in blocks)
    if len(plugins) == 1:
        return f"{len(blocks)} <ros2_control> tags ({names}) with {plugin(blocks[0])}"
    each = ", ".join(f'"{b.name}" with {plugin(b)}' for b in blocks)
    return f"{len(blocks)} <ros2_control> tags ({each})"


def description_macro(model: RobotModel) -> str:
    """The package path of the robot's generated ros2_control macro."""
    pattern = next(out for template, out in ROBOT_FILES if "ros2_control" in template)
    return pattern.format(vendor=model.vendor, robot=model.robot)


def existing_tag_warning(urdf: UrdfRobot, model: RobotModel, *, xacro: bool = False) -> InputWarning | None:
    """The one warning for ``model`` when ``urdf`` already drives some of its joints with another
    plugin, or None. ``xacro``: the description was expanded (its line numbers are not the file's)."""
    driven = {j.name for j in model.joints}
    blocks = [b for b in urdf.ros2_control
              if b.plugin != model.plugin_name and any(j.name in driven for j in b.joints)]
    if not blocks:
        return None
    old = legacy_plugin_name(model.vendor, model.class_name)
    renamed = next((b for b in blocks if b.plugin == old), None)
    if renamed is not None:
        return InputWarning(
            f'<ros2_control name="{renamed.name}"> names plugin {old}, which rhi-gen now generates as '
            f"{model.plugin_name} (C++ {model.qualified_class_name}): pluginlib cannot load the old name",
            file=urdf.source, line=None if xacro else renamed.line,
            fix=f"write <plugin>{model.plugin_name}</plugin> in that tag, or replace the tag with the generated "
                f"{description_macro(model)}")
    covered = list(dict.fromkeys(j.name for b in blocks for j in b.joints))
    shared = [name for name in covered if name in driven]
    which = "the same joints" if len(shared) == len(covered) else f"{len(shared)} of them ({_few(shared)})"
    where = " in the xacro-expanded description" if xacro else ""
    macro = description_macro(model)
    return InputWarning(
        f"already has {_tags(blocks)}{where} for {len(covered)} joint{'s' if len(covered) != 1 else ''} "
        f"({_few(covered)}); the generated {macro} drives {which} with plugin {model.plugin_name}",
        file=urdf.source, line=None if xacro else blocks[0].line,
        fix="replace that tag with the generated macro, or keep the tag and do not include the generated macro; "
            "never both (two plugins would claim the same joint interfaces)")


def existing_tag_warnings(robots: Sequence[LoadedRobot]) -> list[InputWarning]:
    """One warning per robot of ``robots`` whose description already drives its joints (`generate`)."""
    out = []
    for r in robots:
        warning = existing_tag_warning(r.urdf, r.model, xacro=is_xacro(Path(r.config.urdf)))
        if warning is not None:
            out.append(warning)
    return out
