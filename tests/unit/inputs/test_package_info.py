"""robots/package.yaml: the copyright, license and maintainer of the generated package come from the
robots_project (never invented); without the file, neutral defaults that name no one."""
from __future__ import annotations

from pathlib import Path

import pytest

from rhi_gen.cli import main

PKG = "generated/robot_hardware_interface"


def _generate(robots_project: Path, capsys) -> tuple[int, str]:
    code = main(["generate", "--project", str(robots_project)])
    return code, capsys.readouterr().err


def test_defaults_name_no_one(robots_project, capsys):
    assert _generate(robots_project, capsys)[0] == 0
    head = (robots_project / PKG / "src/unitree/g1.cpp").read_text().splitlines()[:2]
    assert head == ["// Copyright the robot_hardware_interface authors", "// SPDX-License-Identifier: Apache-2.0"]
    xml = (robots_project / PKG / "package.xml").read_text()
    assert "<license>Apache-2.0</license>" in xml and "robots/package.yaml" in xml


def test_project_file_owns_every_generated_file(robots_project, capsys):
    (robots_project / "robots/package.yaml").write_text(
        "# who owns the generated package\n"
        "copyright: 2026 Acme Robotics GmbH\n"
        "license: BSD-3-Clause\n"
        "maintainer: Ada Lovelace\n"
        "maintainer_email: ada@acme.example\n")
    assert _generate(robots_project, capsys)[0] == 0
    for path in (robots_project / PKG).rglob("*"):
        if path.suffix in (".hpp", ".cpp"):
            head = path.read_text().splitlines()[:2]
            assert head == ["// Copyright 2026 Acme Robotics GmbH", "// SPDX-License-Identifier: BSD-3-Clause"], path
    cmake = (robots_project / PKG / "CMakeLists.txt").read_text().splitlines()[:2]
    assert cmake == ["# Copyright 2026 Acme Robotics GmbH", "# SPDX-License-Identifier: BSD-3-Clause"]
    xml = (robots_project / PKG / "package.xml").read_text()
    assert '<maintainer email="ada@acme.example">Ada Lovelace</maintainer>' in xml
    assert "<license>BSD-3-Clause</license>" in xml and "robots/package.yaml" not in xml
    assert main(["check", "--project", str(robots_project)]) == 0
    # a new holder is a change `check` sees and `generate` writes everywhere
    (robots_project / "robots/package.yaml").write_text("copyright: 2027 Acme Robotics GmbH\n")
    assert main(["check", "--project", str(robots_project)]) == 1
    assert _generate(robots_project, capsys)[0] == 0
    g1 = (robots_project / PKG / "src/unitree/g1.cpp").read_text()
    assert g1.startswith("// Copyright 2027 Acme Robotics GmbH\n")


@pytest.mark.parametrize(("text", "words"), [
    ("copyright: [a, b]\n", ("robots/package.yaml:1", "copyright", "single value")),
    ("licence: MIT\n", ("robots/package.yaml:1", "did you mean 'license'")),
    ("maintainer_email: not-an-address\n", ("robots/package.yaml:1", "maintainer_email", "e-mail")),
    ("copyright: \"Acme\\nInjected\"\n", ("robots/package.yaml:1", "copyright")),
    ("license: 'MIT; rm -rf'\n", ("robots/package.yaml:1", "license", "SPDX")),
])
def test_bad_project_file_is_one_line_and_writes_nothing(robots_project, capsys, text, words):
    (robots_project / "robots/package.yaml").write_text(text)
    code, err = _generate(robots_project, capsys)
    assert code == 2 and len(err.splitlines()) == 1 and err.startswith("error: "), err
    for word in words:
        assert word in err, (word, err)
    assert not (robots_project / "generated").exists()
