"""Rendering: RobotModel(s) -> {package path: text}, entirely in memory.

Nothing here touches the output folder: a template error halfway through leaves the disk as it was
because the writer only starts once the whole plan exists.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import PurePosixPath
from typing import Any

import jinja2

from .. import transports
from ..errors import GenerationError
from ..model import PackageInfo, RobotModel
from .banner import SHARED_INPUTS, banner_for, package_inputs, robot_inputs
from .bringup_views import description_view, launch_view, urdf_view
from .cpp_layout import fold_cpp
from .driver_views import driver_view
from .environment import make_environment
from .fake_robot_views import fake_robot_view, has_fake_robot
from .static_files import copy_static
from .views import controllers_view, package_view, test_view, xacro_view

DEFAULT_PACKAGE = PackageInfo()

# (source, output path): sources are paths under the rhi_gen package (render/environment.py), output
# paths are relative to generated/robot_hardware_interface/.
# Robot-independent C++, copied as it is below the package banner (render/static_files.py).
COMMON_FILES = tuple(
    (f"cpp/common/{name}", f"include/robot_hardware_interface/common/{name}")
    for name in ("data_buffer.hpp", "types.hpp", "motor_types.hpp", "monitor.hpp", "robot_spec.hpp",
                 "hardware_parameters.hpp", "ros2_control_compat.hpp", "slot_kernels.hpp", "slot_table.hpp",
                 "safe_start.hpp", "driver_health.hpp", "driver_diagnostics.hpp", "state_freshness.hpp",
                 "driver_monitor.hpp", "command_claims.hpp", "command_guard.hpp", "command_writer.hpp",
                 "joint_transmissions.hpp", "calibration_file.hpp", "driver_core.hpp", "system_driver.hpp"))
TEST_FILES = (("cpp/test/hardware_interface_test.hpp", "test/hardware_interface_test.hpp"),)
# The fake robot's robot-independent part, in a package where a robot has one.
FAKE_ROBOT_FILES = (
    *((f"cpp/common/{name}", f"include/robot_hardware_interface/common/{name}")
      for name in ("fake_joint_dynamics.hpp", "fake_physics.hpp", "fake_physics_mujoco.hpp", "fake_robot.hpp",
                   "fake_robot_main.hpp")),
    ("cpp/src/fake_robot_main.cpp", "src/fake_robot_main.cpp"),
)
# Templates: what depends on the robots.
PACKAGE_FILES = (
    ("templates/package/CMakeLists.txt.j2", "CMakeLists.txt"),
    ("templates/package/package.xml.j2", "package.xml"),
    ("templates/package/robot_hardware_interface.xml.j2", "robot_hardware_interface.xml"),
    ("templates/package/bringup.launch.py.j2", "launch/bringup.launch.py"),
)
ROBOT_FILES = (
    ("templates/robot/driver.hpp.j2", "include/robot_hardware_interface/{vendor}/{robot}.hpp"),
    ("templates/robot/driver.cpp.j2", "src/{vendor}/{robot}.cpp"),
    ("templates/robot/ros2_control.xacro.j2", "description/{robot}.ros2_control.xacro"),
    ("templates/robot/controllers.yaml.j2", "config/{robot}_controllers.yaml"),
    ("templates/robot/test.cpp.j2", "test/test_{robot}_hardware_interface.cpp"),
    ("templates/robot/description.urdf.xacro.j2", "description/{robot}.urdf.xacro"),
    ("templates/robot/urdf.j2", "urdf/{robot}.urdf"),
    ("templates/robot/launch.py.j2", "launch/{robot}.launch.py"),
)
# Only for a robot whose transport has a fake robot side (Transport.fake_robot_header).
FAKE_ROBOT_FILE = ("templates/robot/fake_robot.cpp.j2", "src/{vendor}/{robot}_fake_robot.cpp")


# The view-model (render/views.py) each robot template gets as ``view``, beside ``robot``.
ROBOT_VIEWS: dict[str, Callable[[RobotModel], object]] = {
    "templates/robot/driver.cpp.j2": driver_view,
    "templates/robot/controllers.yaml.j2": controllers_view,
    "templates/robot/ros2_control.xacro.j2": xacro_view,
    "templates/robot/test.cpp.j2": test_view,
    "templates/robot/description.urdf.xacro.j2": description_view,
    "templates/robot/urdf.j2": urdf_view,
    "templates/robot/launch.py.j2": launch_view,
    "templates/robot/fake_robot.cpp.j2": fake_robot_view,
}


def robot_paths(vendor: str, robot: str) -> tuple[str, ...]:
    """The package paths of one robot's own files (everything else is shared)."""
    return tuple(pattern.format(vendor=vendor, robot=robot) for _, pattern in (*ROBOT_FILES, FAKE_ROBOT_FILE))



def _render_one(env: jinja2.Environment, template: str, context: dict[str, Any], out: str) -> str:
    try:
        return env.get_template(template).render(**context)
    except GenerationError:
        raise
    except jinja2.TemplateNotFound as exc:
        raise GenerationError(f"template {exc.name} is missing from the rhi-gen installation",
                              file=out) from exc
    except jinja2.TemplateError as exc:
        line = getattr(exc, "lineno", None)
        raise GenerationError(f"template {template} failed: {exc}", file=out, line=line,
                              fix="this is a bug in rhi-gen's templates; please report it") from exc
    except (TypeError, ValueError, AttributeError) as exc:
        raise GenerationError(f"template {template} failed: {exc}", file=out,
                              fix="this is a bug in rhi-gen's templates; please report it") from exc


def render_package(models: Sequence[RobotModel],
                   env_factory: Callable[[], jinja2.Environment] = make_environment,
                   package: PackageInfo = DEFAULT_PACKAGE) -> dict[str, str]:
    """Render the whole robot_hardware_interface package for ``models``, owned by ``package``.

    Returns paths relative to the package folder (POSIX), in a deterministic order.
    """
    env = env_factory()
    robots = sorted(models, key=lambda m: (m.vendor, m.robot))
    plan: dict[str, str] = {}

    shared_banner = banner_for(SHARED_INPUTS, package)("//")
    static = [*COMMON_FILES, *(TEST_FILES if robots else ())]
    if any(has_fake_robot(r) for r in robots):
        static += FAKE_ROBOT_FILES
    elif any(r.transport == "custom" for r in robots):
        # a custom bus rhi-gen does not know: the joints, the loop and the interface a bus implements
        static += [f for f in FAKE_ROBOT_FILES if f[1].endswith(".hpp")]
    for name in sorted({r.transport for r in robots}):
        static += transports.TRANSPORTS[name].shared_files
    for source, out in static:
        plan[out] = copy_static(env, source, shared_banner, out)

    package_banner = banner_for(package_inputs(robots), package)
    view = package_view(robots)
    for template, out in PACKAGE_FILES:
        plan[out] = _render_one(env, template, {"banner": package_banner, "robots": robots, "package": package,
                                                "view": view}, out)

    for robot in robots:
        banner = banner_for(robot_inputs(robot), package)
        for template, pattern in (*ROBOT_FILES, *((FAKE_ROBOT_FILE,) if has_fake_robot(robot) else ())):
            out = pattern.format(vendor=robot.vendor, robot=robot.robot)
            if out in plan:  # e.g. vendor "common" + robot "types": never overwrite silently
                raise GenerationError(f"{robot.vendor}/{robot.robot} would overwrite {out}, which another part "
                                      "of the package already generates", fix="rename the robot or vendor")
            context = {"banner": banner, "robot": robot, "robots": robots,
                       "transport": transports.get(robot.transport)}
            if template in ROBOT_VIEWS:
                context["view"] = ROBOT_VIEWS[template](robot)
            plan[out] = _render_one(env, template, context, out)

    copied = {out for _, out in static}  # byte for byte: their sources are already folded (a test keeps them so)
    for path in plan:
        assert not PurePosixPath(path).is_absolute() and ".." not in PurePosixPath(path).parts
        if path.endswith((".hpp", ".cpp")) and path not in copied:
            plan[path] = fold_cpp(plan[path])
    return dict(sorted(plan.items()))
