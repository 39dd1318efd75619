"""example-robot-data (the test extra's wheel): real robots' descriptions and meshes, installed where a ROS
user's package:// would be resolved."""
from __future__ import annotations

import importlib.metadata
from pathlib import Path

import pytest


def example_robot_data_prefix() -> Path:
    """The prefix under which example-robot-data (test extra) installs share/example-robot-data/: what
    package:// is resolved under, as a ROS user's AMENT_PREFIX_PATH would be."""
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        pytest.fail("example-robot-data is not installed: pip install -e '.[test]' (it is a test dependency)")
    for f in dist.files or []:
        path = Path(str(dist.locate_file(f)))
        for parent in path.parents:
            if parent.name == "share" and (parent / "example-robot-data").is_dir():
                return parent.parent
    pytest.fail("example-robot-data installs no share/example-robot-data/ folder")
