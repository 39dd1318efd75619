"""User code written against the lowerCamel C++ API keeps compiling after a regeneration: the old
names in user-region bodies become the snake_case ones, and only there."""
from __future__ import annotations

import re

from rhi_gen.write.api_migration import RENAMED_API, migrate_region_bodies
from tests.support.cpp_build import TOY_BUS_REGIONS
from tests.support.repo import REPO

NEW_TO_OLD = {new: old for old, new in RENAMED_API.items()}


def _with_old_names(text: str) -> str:
    pattern = re.compile(r"\b(" + "|".join(sorted(NEW_TO_OLD, key=len, reverse=True)) + r")\b")
    return pattern.sub(lambda m: NEW_TO_OLD[m.group(1)], text)


def test_toy_bus_regions_written_for_the_old_api_become_the_ones_that_compile():
    """The toy bus regions (compiled and run by tests/cpp) as a user wrote them before the rename."""
    current = TOY_BUS_REGIONS.read_text(encoding="utf-8")
    old = _with_old_names(current)
    assert "receiveState" in old and "networkInterface" in old  # the fixture exercises the rename
    migrated, renames = migrate_region_bodies(old, "generated/robot_hardware_interface/src/acme/arm.cpp")
    assert migrated == current
    found = {(r.region, r.old, r.new) for r in renames}
    assert ("transport_connect", "networkInterface", "network_interface") in found
    assert any(r.old == "receiveState" and r.region == "transport_members" for r in renames)
    lines = old.splitlines()
    for r in renames:  # each report names the line the old name stood on
        assert r.old in lines[r.line - 1], r
        assert r.note().startswith(f"generated/robot_hardware_interface/src/acme/arm.cpp:{r.line}: ")


def test_text_outside_regions_and_generic_names_are_left_alone():
    text = ("receiveState();  // template text, not the user's\n"
            "// rhi-gen:begin-user-region callbacks\n"
            "void f() { sdk.getData(); core().stateFrame(); my_receiveState(); }\n"
            "// rhi-gen:end-user-region callbacks\n")
    migrated, renames = migrate_region_bodies(text, "generated/robot_hardware_interface/src/a/b.cpp")
    assert migrated.splitlines()[0] == "receiveState();  // template text, not the user's"
    assert "sdk.getData(); core().state_frame(); my_receiveState();" in migrated
    assert [(r.line, r.old) for r in renames] == [(3, "stateFrame")]


def test_only_cpp_files_are_migrated():
    text = "# rhi-gen:begin-user-region targets\n# receiveState\n# rhi-gen:end-user-region targets\n"
    assert migrate_region_bodies(text, "generated/robot_hardware_interface/CMakeLists.txt") == (text, [])


def test_every_new_name_exists_in_the_shared_cpp():
    """A rename into a name the headers do not declare would turn compiling code into broken code."""
    sources = "".join(p.read_text(encoding="utf-8") for p in [
        *(REPO / "rhi_gen/cpp/common").glob("*.hpp"), *(REPO / "rhi_gen/transports").glob("*/*.hpp")])
    for old, new in RENAMED_API.items():
        assert re.search(rf"\b{new}\b", sources), f"{old} -> {new}: no {new} in the shared headers"
        assert not re.search(rf"\b{re.escape(old)}(?!\w)", sources), f"the headers still declare {old}"
