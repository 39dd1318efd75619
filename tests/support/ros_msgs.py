"""Where the real ROS 2 message headers come from: the ROS 2 Jazzy wheels of the `test` extra.

The wheels (pyproject.toml, `pip install -e '.[test]'`) install the ROS 2 layout into the venv's
prefix: headers under `<prefix>/include/<pkg>/<pkg>/...`, interface files under
`<prefix>/share/<pkg>/msg/`. A generated driver is compiled against these headers exactly as a colcon
build would (one include folder per package). Vendor messages are generated from them by
tests/support/vendor_msgs.py.

A missing wheel fails the test that needs it: it is never a reason to skip.
"""
from __future__ import annotations

import functools
import hashlib
from importlib import metadata
from pathlib import Path

import pytest

# distribution -> the package folder its wheel installs under include/, in include order. The
# message packages and everything their C++ headers include (checked with g++ -H).
HEADER_WHEELS = {
    "ros-builtin-interfaces": "builtin_interfaces",
    "ros-std-msgs": "std_msgs",
    "ros-geometry-msgs": "geometry_msgs",
    "ros-sensor-msgs": "sensor_msgs",
    "ros-diagnostic-msgs": "diagnostic_msgs",
    "ros-lifecycle-msgs": "lifecycle_msgs",
    "ros-rcl-interfaces": "rcl_interfaces",  # the parameter API's messages (rclcpp/parameter*.hpp)
    "ros-service-msgs": "service_msgs",  # ServiceEventInfo, in the Event message of every generated service
    "ros-rosidl-runtime-cpp": "rosidl_runtime_cpp",
    "ros-rosidl-runtime-c": "rosidl_runtime_c",
    "ros-rosidl-typesupport-interface": "rosidl_typesupport_interface",
    "ros-rcutils": "rcutils",
}
INSTALL_HINT = "install the test extra: .venv/bin/pip install -e '.[test]' (see README, 'Run the tests')"


def installed_dir(dist: str, kind: str, package: str) -> Path | None:
    """`<prefix>/<kind>/<package>` as installed by the wheel ``dist`` (None when it is not installed)."""
    try:
        found = metadata.distribution(dist)
    except metadata.PackageNotFoundError:
        return None
    for f in found.files or ():
        parts = f.parts
        if kind in parts:
            i = parts.index(kind)
            if parts[i + 1:i + 2] == (package,):
                path = Path(str(found.locate_file(Path(*parts[:i + 2])))).resolve()
                return path if path.is_dir() else None
    return None


def require_dir(dist: str, kind: str, package: str) -> Path:
    path = installed_dir(dist, kind, package)
    if path is None:
        pytest.fail(f"{kind}/{package} of the wheel {dist} is not installed: {INSTALL_HINT}")
    return path


@functools.cache
def _wheel_include_dirs() -> tuple[Path, ...] | str:
    dirs, missing = [], []
    for dist, package in HEADER_WHEELS.items():
        path = installed_dir(dist, "include", package)
        if path is None:
            missing.append(dist)
        else:
            dirs.append(path)
    return f"missing ROS 2 wheels {missing}: {INSTALL_HINT}" if missing else tuple(dirs)


def wheel_include_dirs() -> list[Path]:
    """Include folders of the standard messages and the rosidl runtime headers (fails if missing)."""
    found = _wheel_include_dirs()
    if isinstance(found, str):
        pytest.fail(found)
    return list(found)


def wheel_versions(dists) -> str:
    """"name==version" lines of installed distributions, for cache keys."""
    out = []
    for dist in dists:
        try:
            out.append(f"{dist}=={metadata.version(dist)}")
        except metadata.PackageNotFoundError:
            out.append(f"{dist} missing")
    return "\n".join(out)


def wheels_digest() -> str:
    return hashlib.sha256(wheel_versions(HEADER_WHEELS).encode()).hexdigest()[:16]
