"""The vendor data the repository carries (tests/data): licence and provenance beside it, and, when the
project's shared vendor data is there (../shared/upstream or $RHI_UPSTREAM, as in CI), byte for byte the
same as it (the provenance holds: one copy, one source)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.support import upstream_urdf, vendor_msgs
from tests.support.repo import REPO

DATA = REPO / "tests" / "data"
MSG_PACKAGES = ("unitree_hg", "unitree_go", "interface_protocol")
COPYRIGHT = {
    "unitree_hg": 'Copyright (c) 2016-2024 HangZhou YuShu TECHNOLOGY CO.,LTD. ("Unitree Robotics")',
    "unitree_go": 'Copyright (c) 2016-2024 HangZhou YuShu TECHNOLOGY CO.,LTD. ("Unitree Robotics")',
    "interface_protocol": 'Copyright (c) 2025- Shenzhen Zhongqing Robot Technology Co., Ltd. ("EngineAI")',
}


def _copies() -> list[Path]:
    """Every carried data file, relative to its data folder's root (the shared folder's layout)."""
    msgs = [p.relative_to(vendor_msgs.IN_REPO_MSGS) for p in sorted(vendor_msgs.IN_REPO_MSGS.rglob("*.msg"))]
    urdfs = [p.relative_to(upstream_urdf.IN_REPO) for p in upstream_urdf.in_repo()]
    return [Path("msgs") / p for p in msgs] + [Path("urdf") / p for p in urdfs]


def _bsd3(text: str) -> bool:
    return (text.startswith("BSD 3-Clause License\n") and "Redistribution and use in source and binary forms" in text
            and "Neither the name of the copyright holder" in text)


@pytest.mark.parametrize("package", MSG_PACKAGES)
def test_each_message_package_has_its_licence_and_provenance(package):
    folder = vendor_msgs.IN_REPO_MSGS / package
    licence = (folder / "LICENSE").read_text(encoding="utf-8")
    assert _bsd3(licence) and COPYRIGHT[package] in licence
    provenance = (folder / "PROVENANCE.md").read_text(encoding="utf-8")
    assert "https://github.com/" in provenance and "BSD-3-Clause" in provenance
    assert re.search(r"\b[0-9a-f]{40}\b", provenance), "no commit in PROVENANCE.md"
    assert list(folder.rglob("*.msg")), f"no .msg under {folder}"
    # a package carried in several releases (interface_protocol: one folder per upstream repository) says
    # where each comes from
    for release in (d for d in folder.iterdir() if d.is_dir() and d.name != "msg"):
        assert f"`{release.name}/msg/`" in provenance, release.name
        assert re.search(rf"https://github\.com/[\w.-]+/{re.escape(release.name)}\b", provenance), release.name


def test_the_urdf_copies_have_their_licences_and_provenance():
    provenance = (upstream_urdf.IN_REPO / "PROVENANCE.md").read_text(encoding="utf-8")
    for urdf in upstream_urdf.in_repo():
        assert f"`{urdf.name}`" in provenance, urdf.name
    for name in ("LICENSE.unitree_ros", "LICENSE.engineai_ros2_workspace"):
        assert _bsd3((upstream_urdf.IN_REPO / name).read_text(encoding="utf-8")), name


def test_only_licensed_packages_are_carried():
    """AimDK's messages state no licence: never copied (the tests read them from ../shared)."""
    assert sorted(p.name for p in vendor_msgs.IN_REPO_MSGS.iterdir() if p.is_dir()) == sorted(MSG_PACKAGES)
    assert {p.name for p in vendor_msgs.PACKAGES if p.in_repo} == {"interface_protocol"}
    assert {(p.name, p.in_repo) for p in vendor_msgs.VARIANTS} == {("interface_protocol", True)}
    assert {p.name for p in vendor_msgs.PACKAGES if not p.in_repo} == {"aimdk_msgs"}
    assert not list(DATA.rglob("*aimdk*")) and not (upstream_urdf.IN_REPO / "agibot_x2.urdf").exists()


def test_the_copies_are_byte_identical_to_the_shared_vendor_data():
    if not vendor_msgs.UPSTREAM.is_dir():
        pytest.skip(f"{vendor_msgs.UPSTREAM} is missing (nothing to compare the repository's copies with): "
                    f"put the project's shared folder beside the clone or set RHI_UPSTREAM=<its upstream/ folder>")
    roots = {"msgs": vendor_msgs.IN_REPO_MSGS, "urdf": upstream_urdf.IN_REPO}
    differ = []
    for rel in _copies():
        ours = roots[rel.parts[0]] / Path(*rel.parts[1:])
        theirs = vendor_msgs.UPSTREAM / rel
        if not theirs.is_file() or theirs.read_bytes() != ours.read_bytes():
            differ.append(str(rel))
    assert not differ, f"differ from {vendor_msgs.UPSTREAM}: {differ}"
    # every file a carried package (each release of it) is generated from is among those compared
    compared = {vendor_msgs.IN_REPO_MSGS / Path(*rel.parts[1:]) for rel in _copies() if rel.parts[0] == "msgs"}
    carried = [f for p in (*vendor_msgs.PACKAGES, *vendor_msgs.VARIANTS) if p.in_repo for f in p.files()]
    assert len(carried) == 10 and set(carried) <= compared, sorted(set(carried) - compared)
    # the unitree folders are whole copies
    for family in ("unitree_hg", "unitree_go"):
        shared = {p.name for p in (vendor_msgs.UPSTREAM / "msgs" / family / "msg").glob("*.msg")}
        assert shared == {p.name for p in (vendor_msgs.IN_REPO_MSGS / family / "msg").glob("*.msg")}, family
