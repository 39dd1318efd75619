"""The custom transport ("bring your own SDK") on the Python side: `rhi-gen new --transport custom`
writes a driver whose SDK glue is user regions, each function region marked "not filled in"; filled
regions survive a regeneration after a URDF change byte for byte, and `check` accepts them.

The C++ side (the unfilled driver refuses activation in one line; the toy bus filled in runs the
whole harness on every distro and sanitizer) is in tests/cpp/test_cpp_drivers.py."""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from rhi_gen.cli import main
from rhi_gen.render.markers import user_region
from rhi_gen.transports import custom
from rhi_gen.write.regions import region_bodies, splice
from tests.support.cpp_build import HARNESS_ROBOTS, TOY_BUS_REGIONS

SOLO12_URDF = HARNESS_ROBOTS / "odri" / "solo12.urdf"  # example-robot-data 6.0.0
SOURCE = Path("generated/robot_hardware_interface/src/odri/solo12.cpp")


def _new_project(tmp_path: Path) -> Path:
    (tmp_path / "robots" / "odri").mkdir(parents=True)
    shutil.copy2(SOLO12_URDF, tmp_path / "robots" / "odri" / "solo12.urdf")
    assert main(["new", "--project", str(tmp_path), "--vendor", "odri", "--robot", "solo12",
                 "--urdf", str(tmp_path / "robots" / "odri" / "solo12.urdf"), "--transport", "custom"]) == 0
    return tmp_path


def test_user_region_with_a_default_body():
    text = user_region("send", indent="  ", body="#define X\n")
    assert text == "  // rhi-gen:begin-user-region send\n#define X\n  // rhi-gen:end-user-region send"
    assert region_bodies(text + "\n", "x") == {"send": "#define X\n"}


def test_new_writes_marked_regions_and_no_options(tmp_path):
    project = _new_project(tmp_path)
    yaml_text = (project / "robots" / "odri" / "solo12.yaml").read_text()
    assert "transport: custom" in yaml_text and re.search(r"^transport_options:\n  \{\}", yaml_text, re.M)
    source = (project / SOURCE).read_text()
    bodies = region_bodies(source, str(SOURCE))
    assert set(bodies) >= {"includes", custom.MEMBER_REGION, *custom.FUNCTION_REGIONS, "callbacks"}
    for region in custom.FUNCTION_REGIONS:
        assert f"#define {custom.not_filled_macro(region)}\n" in bodies[region], region
        assert f"#if defined({custom.not_filled_macro(region)})" in source or \
            f"#elif defined({custom.not_filled_macro(region)})" in source
    assert bodies[custom.MEMBER_REGION] == "" and bodies["includes"] == ""
    assert '"src/odri/solo12.cpp", kUnfilledRegion' in source
    header = project / "generated/robot_hardware_interface/include/robot_hardware_interface/transport/custom.hpp"
    assert "is not filled in: refusing to activate" in header.read_text()


def test_filled_regions_survive_a_urdf_change_byte_for_byte(tmp_path, capsys):
    project = _new_project(tmp_path)
    path = project / SOURCE
    filled, orphans = splice(path.read_text(), TOY_BUS_REGIONS.read_text(), str(path))
    assert orphans == []
    path.write_text(filled)
    before = region_bodies(filled, str(path))
    assert all("RHI_CUSTOM_NOT_FILLED_IN" not in before[r] for r in custom.FUNCTION_REGIONS)
    assert main(["check", "--project", str(project)]) == 0, "filling regions is not a hand edit"

    urdf = project / "robots" / "odri" / "solo12.urdf"
    text = urdf.read_text()
    changed = text.replace('<limit effort="1000" lower="-10" upper="10" velocity="1000"/>',
                           '<limit effort="1000" lower="-3" upper="3" velocity="1000"/>', 1)
    assert changed != text, "the URDF fixture changed: pick another limit to edit"
    urdf.write_text(changed)
    capsys.readouterr()
    assert main(["generate", "--project", str(project)]) == 0
    after_text = path.read_text()
    assert region_bodies(after_text, str(path)) == before
    assert after_text != filled and '{"FL_HAA", 0, kPosition, -3.0, 3.0,' in after_text
    assert main(["check", "--project", str(project)]) == 0
