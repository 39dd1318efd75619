"""The documentation a newcomer walks holds together: every relative link names a file that exists, and
every #anchor a heading of that file (GitHub's heading slugs), in README.md, docs/ and tests/**/*.md."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.support.repo import REPO

LINK = re.compile(r"(?<!!)\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*$")
PAGES = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md")), *sorted((REPO / "tests").rglob("*.md"))]


def _prose(text: str) -> list[str]:
    """The page's lines with fenced code blocks blanked (line numbers kept)."""
    lines, fenced = [], False
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            lines.append("")
        else:
            lines.append("" if fenced else line)
    return lines


def _slug(heading: str) -> str:
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower().replace("`", ""))
    return text.replace(" ", "-")


def anchors(page: Path) -> set[str]:
    """GitHub's anchors of the page's headings: a repeated heading gets -1, -2, ..."""
    found: set[str] = set()
    repeats: dict[str, int] = {}
    for line in _prose(page.read_text(encoding="utf-8")):
        m = HEADING.match(line)
        if m:
            slug = _slug(m.group(2))
            n = repeats.get(slug, 0)
            repeats[slug] = n + 1
            found.add(slug if n == 0 else f"{slug}-{n}")
    return found


def broken_links(page: Path, root: Path = REPO) -> list[str]:
    problems = []
    for number, line in enumerate(_prose(page.read_text(encoding="utf-8")), 1):
        for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
            if re.match(r"^[a-z]+:", target):
                continue  # an address, not a file of the repository
            path, _, anchor = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            where = f"{page.relative_to(root)}:{number}"
            if not dest.exists():
                problems.append(f"{where}: no file {target}")
            elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
                problems.append(f"{where}: no heading for #{anchor} in {dest.relative_to(root)}")
    return problems


def test_the_pages_exist_and_link():
    assert len(PAGES) >= 8 and all(p.is_file() for p in PAGES)
    assert sum(len(LINK.findall(p.read_text(encoding="utf-8"))) for p in PAGES) > 50


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(REPO)))
def test_every_relative_link_resolves(page):
    assert not broken_links(page)


def test_a_broken_link_is_found(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("# Title\n\n## Step\n\n## Step\n\nSee [a](missing.md), [b](#title), [c](#step-1), [d](#nowhere).\n")
    assert broken_links(page, tmp_path) == ["page.md:7: no file missing.md",
                                            "page.md:7: no heading for #nowhere in page.md"]
