"""README.md is a front page (issue 48): short, its detail in docs/, and what the tests and CI read from the
user documentation still there. The fresh-clone test (tests/cli/test_fresh_clone.py, C++ tier) runs the
README's test command and the hot-path benchmark's, and checks the skip count docs/testing.md states; these
checks fail in the quick tier already when a move of the text would break it."""
from __future__ import annotations

import re
import shlex

from tests.support.fresh_clone import (
    BENCHMARKS_PAGE,
    README,
    benchmark_command,
    documented_skip_count,
    readme_test_command,
)
from tests.support.repo import REPO

MAX_README_LINES = 220  # the front page's hard limit; detail goes to docs/


def test_the_readme_is_a_front_page():
    lines = (REPO / README).read_text(encoding="utf-8").splitlines()
    assert len(lines) <= MAX_README_LINES, (
        f"README.md has {len(lines)} lines, more than {MAX_README_LINES}: move detail to a docs/ page and link it")


def test_ci_runs_exactly_the_readme_test_command():
    script = (REPO / ".ci" / "run").read_text(encoding="utf-8")
    commands = [line for line in script.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    assert commands[-1] == readme_test_command(), f".ci/run's last line is not README's test command: {commands[-1]!r}"


def test_the_benchmark_command_names_a_script_of_the_repository():
    words = shlex.split(benchmark_command())
    assert words[:1] == [".venv/bin/python"] and (REPO / words[1]).is_file(), (BENCHMARKS_PAGE, words)


def test_the_testing_page_states_the_fresh_clone_skip_count():
    assert documented_skip_count() > 0
    assert re.search(r"without the AimDK message definitions \d+ tests skip", (REPO / README).read_text()) is None, \
        "README.md repeats the skip count: keep it in docs/testing.md only, where the fresh-clone test reads it"


DOC_PAGE = re.compile(r"\bdocs/([\w-]+\.md)\b")
README_SECTION = re.compile(r"\bREADME(?:'s)?[:,]?\s+[\"']?[A-Z]")  # README: Hands, README "See ...", ...
TOOL_SOURCES = (".py", ".j2", ".hpp", ".cpp")


def test_the_tool_points_users_at_pages_that_exist():
    """rhi-gen's messages, the YAML comments it writes and the generated files name docs/ pages, never a README
    section (README.md stays a front page, its detail moves); every page they name exists."""
    named: dict[str, list[str]] = {}
    sections = []
    for path in sorted((REPO / "rhi_gen").rglob("*")):
        if path.suffix not in TOOL_SOURCES or not path.is_file():
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            where = f"{path.relative_to(REPO)}:{number}"
            for page in DOC_PAGE.findall(line):
                named.setdefault(page, []).append(where)
            if README_SECTION.search(line):
                sections.append(f"{where}: {line.strip()}")
    assert {"transmissions.md", "hands.md", "health-and-faults.md"} <= set(named), sorted(named)
    assert not {page: where for page, where in named.items() if not (REPO / "docs" / page).is_file()}
    assert not sections, "name the docs/ page instead of a README section:\n" + "\n".join(sections)
