"""Strict XML parsing of a robot description, exact line numbers, and the file:line errors about it.

- The XML is parsed with lxml without recovery, entity expansion or network access, so a broken
  file is one ``file:line: malformed XML: ...`` line, never a silently repaired robot.
- Line numbers stay exact past line 65535, where libxml2's own give out.
- :class:`UrdfContext` turns a problem at an element into a :class:`UrdfError` naming the file as
  the user knows it, the element's line and a fix; :func:`quoted` and :func:`did_you_mean` word
  the names in those messages.
- :func:`declares_xacro` tells a xacro document by its namespace.
"""
from __future__ import annotations

import bisect
import difflib
import re
from collections.abc import Callable, Iterable

from lxml import etree

from ..errors import UrdfError
from .wording import YAML, Wording

__all__ = ["Tag", "UrdfContext", "declares_xacro", "did_you_mean", "first_xacro_element", "parse_strict",
           "quoted", "strict_parser"]

Tag = Callable[[str], str]  # a local tag name -> the tag in the document's namespace

_XACRO_NS_MARK = "ros.org/wiki/xacro"
_LXML_POSITION = re.compile(r",? line (\d+), column (\d+)\s*$")
# libxml2 keeps element line numbers in 16 bits; at and above this, sourceline is unreliable.
_BIG_LINE = 65535


# ---------------------------------------------------------------- line numbers
_SCAN = re.compile(
    rb"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<!DOCTYPE(?:[^\[>]|\[.*?\])*>|<(?=[^/!?])", re.S)


class SourceLines:
    """``sourceline`` of an element, exact even beyond line 65535.

    libxml2 stores element lines in 16 bits; past that lxml reports the line of a nearby text node
    (often off by one or more). Only when a document is that long, the start tags are located in
    the raw bytes (skipping comments, CDATA, processing instructions and the DOCTYPE) and paired
    with the elements in document order.
    """

    def __init__(self, data: bytes, root: etree._Element) -> None:
        self._data = data
        self._root = root
        self._exact: dict[etree._Element, int] | None = None

    def __call__(self, el: etree._Element) -> int | None:
        line = el.sourceline
        if line is None or line < _BIG_LINE:
            return line
        if self._exact is None:
            self._exact = self._scan()
        return self._exact.get(el, line)

    def _scan(self) -> dict[etree._Element, int]:
        data = self._data
        if data[:2] in (b"\xff\xfe", b"\xfe\xff") or b"\x00" in data[:4]:
            return {}  # UTF-16/32: not byte-scannable, keep libxml2's numbers
        offsets = [m.start() for m in _SCAN.finditer(data) if m.end() - m.start() == 1]
        elements = [e for e in self._root.iter() if isinstance(e.tag, str)]
        if len(offsets) != len(elements):
            return {}
        if b"\r" in data:  # XML line ends: CRLF, CR and LF each end one line
            data = data.replace(b"\r\n", b"\n").replace(b"\r", b"\n")
            offsets = [m.start() for m in _SCAN.finditer(data) if m.end() - m.start() == 1]
        newlines = [m.start() for m in re.finditer(b"\n", data)]
        return {el: bisect.bisect_left(newlines, off) + 1 for el, off in zip(elements, offsets, strict=True)}


# ---------------------------------------------------------------- errors
class UrdfContext:
    """The document being read: how errors name it, and the exact line of its elements."""

    def __init__(self, source: str, expanded: bool, wording: Wording = YAML) -> None:
        self.source = source
        self.expanded = expanded
        self.wording = wording
        self.lines: SourceLines | None = None

    def line(self, el: etree._Element | None) -> int | None:
        if el is None:
            return None
        return self.lines(el) if self.lines is not None else el.sourceline

    def err(self, message: str, el: etree._Element | None = None, *, fix: str | None = None,
            line: int | None = None) -> UrdfError:
        if line is None:
            line = self.line(el)
        if self.expanded and line:
            message += " (line of the xacro-expanded URDF)"
        return UrdfError(message, file=self.source, line=line, fix=fix)


def did_you_mean(name: str, choices: Iterable[str]) -> str:
    close = difflib.get_close_matches(name, list(choices), n=1, cutoff=0.75)
    return f" (did you mean '{close[0]}'?)" if close else ""


def quoted(text: str) -> str:
    """A name quoted for a message (repr-like, so control characters stay visible)."""
    return repr(text) if any(not c.isprintable() for c in text) else f"'{text}'"


# ---------------------------------------------------------------- XML parsing
def strict_parser() -> etree.XMLParser:
    return etree.XMLParser(
        resolve_entities=False, no_network=True, huge_tree=False, load_dtd=False,
        dtd_validation=False, recover=False, collect_ids=False, remove_blank_text=False)


def parse_strict(data: bytes, ctx: UrdfContext) -> etree._Element:
    if not data.strip():
        raise ctx.err("file is empty", fix=f"point {ctx.wording.urdf_key} at a URDF or xacro file with content")
    try:
        root = etree.fromstring(data, strict_parser())
    except etree.XMLSyntaxError as e:
        raw = (e.msg or str(e)).strip()
        m = _LXML_POSITION.search(raw)
        message = _LXML_POSITION.sub("", raw)
        if m:
            message += f" (column {m.group(2)})"
        line = e.lineno or (int(m.group(1)) if m else None)
        if b"\x00" in data and not data.startswith((b"\xff\xfe", b"\xfe\xff")):
            raise ctx.err("not a text file (binary data), so not a URDF", line=None,
                          fix=f"point {ctx.wording.urdf_key} at the .urdf or .xacro file") from None
        if "encoding" in message.lower() or "utf-8" in message.lower():
            fix = ("save the file as UTF-8 (or declare its real encoding in "
                   "<?xml version=\"1.0\" encoding=\"...\"?>)")
        elif "Namespace prefix xacro" in message:
            fix = "declare xmlns:xacro=\"http://www.ros.org/wiki/xacro\" on the root element"
        else:
            fix = "fix the XML syntax at that line"
        raise ctx.err(f"malformed XML: {message}", line=line, fix=fix) from None
    except ValueError as e:  # e.g. unicode strings with an encoding declaration
        raise ctx.err(f"malformed XML: {e}", fix="fix the XML syntax") from None
    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None and any(True for _ in dtd.iterentities()):
        off = data.find(b"<!ENTITY")
        line = data.count(b"\n", 0, off) + 1 if off >= 0 else None
        raise ctx.err("<!ENTITY> declarations are not supported in a URDF", line=line,
                      fix="write the values out and remove the <!DOCTYPE> block")
    ctx.lines = SourceLines(data, root)  # scans the bytes only if an element is past line 65534
    return root


def first_xacro_element(root: etree._Element) -> etree._Element | None:
    for el in root.iter():
        tag = el.tag
        if isinstance(tag, str) and tag.startswith("{") and _XACRO_NS_MARK in tag:
            return el
    return None


def declares_xacro(root: etree._Element) -> bool:
    if any(_XACRO_NS_MARK in (uri or "") for uri in root.nsmap.values()):
        return True
    if any(_XACRO_NS_MARK in name for name in root.attrib):
        return True
    return first_xacro_element(root) is not None
