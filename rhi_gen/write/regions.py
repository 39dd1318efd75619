"""User regions: hand-written code that survives regeneration byte for byte.

A region is a pair of marker lines (render/markers.py REGION_BEGIN / REGION_END) with the same name::

      // rhi-gen:begin-user-region sdk_init
      ...kept byte for byte...
      // rhi-gen:end-user-region sdk_init

``#`` and ``<!-- ... -->`` comment styles are recognised as well. The *body* is everything between
the end of the begin line and the start of the end line. On regeneration the freshly rendered file
supplies the markers and everything around them; only the bodies come from the old file.

Rules (each violation is a RegionError naming file:line):
- markers stand alone on their line (indentation allowed), begin and end names match;
- regions do not nest and a name appears once per file;
- a non-empty region the new template no longer has is *refused* (OrphanedRegion), never dropped:
  C++/YAML pasted somewhere else would change meaning, so the user decides (move the code into
  another region, empty the region, or ``generate --force`` which keeps a backup of the file).

``strip_bodies`` gives the text with every body removed: its hash is what the manifest records, so
editing inside a region is never mistaken for a hand edit of the generated code.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..errors import RegionError
from ..render.markers import REGION_BEGIN, REGION_END

_NAME = r"[A-Za-z_][A-Za-z0-9_.\-]*"
_MARKER = re.compile(
    r"^[ \t]*(?://|#|<!--)[ \t]*(?P<kind>" + re.escape(REGION_BEGIN) + "|" + re.escape(REGION_END)
    + r")(?:[ \t]+(?P<name>\S+))?[ \t]*(?:-->)?[ \t]*\r?\n?$")
_NAME_RE = re.compile(_NAME + r"\Z")
# A line mentioning the marker words in any other shape: reported, so a mangled marker is never ignored.
_LOOSE = re.compile(re.escape(REGION_BEGIN) + "|" + re.escape(REGION_END))

FIX_MARKERS = ("restore the marker lines as generated (`rhi-gen diff` shows them), "
               "or rerun `rhi-gen generate --force` (keeps a backup)")


@dataclass(frozen=True)
class Region:
    name: str
    begin_line: int      # 1-based line of the begin marker
    end_line: int        # 1-based line of the end marker
    body_start: int      # character offsets of the body in the text
    body_end: int

    def body(self, text: str) -> str:
        return text[self.body_start:self.body_end]


def parse_regions(text: str, path: str = "<text>") -> list[Region]:
    """Every region of ``text`` in file order; RegionError (file:line) on broken markers."""
    regions: list[Region] = []
    seen: dict[str, int] = {}
    open_name: str | None = None
    open_line = 0
    body_start = 0
    offset = 0
    for lineno, line in enumerate(text.splitlines(keepends=True), start=1):
        start, offset = offset, offset + len(line)
        if not _LOOSE.search(line):
            continue
        m = _MARKER.match(line)
        if m is None:
            raise RegionError("user-region marker must stand alone on its line, as a comment",
                              file=path, line=lineno, fix=FIX_MARKERS)
        name = m.group("name")
        if not name or not _NAME_RE.match(name):
            raise RegionError(f"user-region marker has {'no' if not name else 'an invalid'} region name",
                              file=path, line=lineno, fix=FIX_MARKERS)
        if m.group("kind") == REGION_BEGIN:
            if open_name is not None:
                raise RegionError(f"region {name!r} begins inside region {open_name!r} (line {open_line}); "
                                  "regions cannot nest", file=path, line=lineno, fix=FIX_MARKERS)
            if name in seen:
                raise RegionError(f"region {name!r} appears twice (first at line {seen[name]})",
                                  file=path, line=lineno, fix=FIX_MARKERS)
            open_name, open_line, body_start = name, lineno, offset
            seen[name] = lineno
        else:
            if open_name is None:
                raise RegionError(f"end of region {name!r} without a begin", file=path, line=lineno,
                                  fix=FIX_MARKERS)
            if name != open_name:
                raise RegionError(f"end of region {name!r} while region {open_name!r} (line {open_line}) "
                                  "is open", file=path, line=lineno, fix=FIX_MARKERS)
            regions.append(Region(name, open_line, lineno, body_start, start))
            open_name = None
    if open_name is not None:
        raise RegionError(f"region {open_name!r} is never closed", file=path, line=open_line,
                          fix=FIX_MARKERS)
    return regions


def region_bodies(text: str, path: str = "<text>") -> dict[str, str]:
    return {r.name: r.body(text) for r in parse_regions(text, path)}


def strip_bodies(text: str, path: str = "<text>") -> str:
    """``text`` with every region body removed (markers kept): what "generated code" means."""
    out: list[str] = []
    pos = 0
    for r in parse_regions(text, path):
        out.append(text[pos:r.body_start])
        pos = r.body_end
    out.append(text[pos:])
    return "".join(out)


def has_content(body: str) -> bool:
    """Whitespace-only bodies carry no user code (a dropped one loses nothing)."""
    return bool(body.strip())


@dataclass(frozen=True)
class OrphanedRegion:
    path: str
    name: str
    line: int   # begin marker line in the old file


def splice(new_text: str, old_text: str, path: str) -> tuple[str, list[OrphanedRegion]]:
    """``new_text`` with each region body taken from ``old_text`` (by name).

    Returns the spliced text and the non-empty old regions ``new_text`` no longer has; the caller
    refuses to write (or, under --force, backs the old file up). Both texts must parse.
    """
    old = parse_regions(old_text, path)
    new = parse_regions(new_text, f"{path} (as rendered)")
    new_names = {r.name for r in new}
    orphans = [OrphanedRegion(path, r.name, r.begin_line) for r in old
               if r.name not in new_names and has_content(r.body(old_text))]
    bodies = {r.name: r.body(old_text) for r in old}
    out: list[str] = []
    pos = 0
    for r in new:
        out.append(new_text[pos:r.body_start])
        out.append(bodies.get(r.name, r.body(new_text)))
        pos = r.body_end
    out.append(new_text[pos:])
    return "".join(out), orphans


def user_code_regions(text: str, path: str) -> list[OrphanedRegion]:
    """Non-empty regions of a file about to be removed: removing it would lose them."""
    return [OrphanedRegion(path, r.name, r.begin_line) for r in parse_regions(text, path)
            if has_content(r.body(text))]
