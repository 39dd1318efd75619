"""Fold generated C++ lines longer than the ROS 2 limit (100 columns, ament_cpplint) the way the
ROS 2 uncrustify style accepts them.

The templates write one line per statement or table entry; long robot, joint and topic names can
push such a line past the limit. Folding here keeps the templates readable and every generated file
lint-clean whatever the names are. Lines are broken after ", ", "(", "<", "{" or " =" outside string
literals, continuation lines indented two more columns; a string literal longer than the space left
is split into adjacent literals (the compiler joins them); a comment is word-wrapped with its own
prefix. Preprocessor lines are left alone: cpplint exempts #include lines and header guards.
"""
from __future__ import annotations

import re

WIDTH = 100
_COMMENT_RE = re.compile(r"^(\s*// ?)(.*)$")


def fold_cpp(text: str, width: int = WIDTH) -> str:
    """``text`` with every line longer than ``width`` folded (other lines unchanged)."""
    lines = text.split("\n")
    out: list[str] = []
    for line in lines:
        out.extend(_fold_line(line, width))
    return "\n".join(out)


def _fold_line(line: str, width: int) -> list[str]:
    if len(line) <= width or line.lstrip().startswith("#"):
        return [line]
    comment = _COMMENT_RE.match(line)
    if comment:
        return _wrap_comment(comment.group(1), comment.group(2), width)
    indent = len(line) - len(line.lstrip(" "))
    pieces: list[str] = []
    rest = line
    while len(rest) > width:
        head, (tail, tail_indent) = _split(rest, width, indent + 2)
        if head is None:
            break  # nothing to break at: leave the line as it is
        pieces.append(head)
        rest = " " * tail_indent + tail
    pieces.append(rest)
    return pieces


def _wrap_comment(prefix: str, text: str, width: int) -> list[str]:
    words = text.split(" ")
    lines = [prefix + words[0]]
    for word in words[1:]:
        if len(lines[-1]) + 1 + len(word) <= width:
            lines[-1] += " " + word
        else:
            lines.append(prefix + word)
    return lines


def _literal_spans(line: str) -> list[tuple[int, int]]:
    """(start, end) of each string or character literal: end is the index of the closing quote."""
    spans: list[tuple[int, int]] = []
    i = 0
    while i < len(line):
        ch = line[i]
        if line.startswith("//", i):
            break
        if ch in "\"'":
            start = i
            i += 1
            while i < len(line) and line[i] != ch:
                i += 2 if line[i] == "\\" else 1
            spans.append((start, i))
        i += 1
    return spans


def _split(line: str, width: int, continuation: int) -> tuple[str | None, tuple[str, int]]:
    """Break ``line`` within ``width`` columns: (head, (rest without leading spaces, its indent))."""
    spans = _literal_spans(line)

    def in_literal(pos: int) -> bool:
        return any(start <= pos <= end for start, end in spans)

    indent = len(line) - len(line.lstrip(" "))
    base = line.find(" : public ")
    if line.lstrip().startswith("class ") and base > indent:  # the base class goes on its own line
        return line[:base].rstrip(), (line[base + 1:], continuation)
    best = -1
    for pos in range(min(width, len(line)) - 1, indent, -1):
        if in_literal(pos):
            continue
        ch = line[pos]
        # "<" only as a template's opening bracket (Name<...), never inside "<=" or "<<"
        template_open = ch == "<" and line[pos - 1:pos].isidentifier() and line[pos + 1:pos + 2] not in ("=", "<")
        # a comma between template arguments: uncrustify indents what follows it twice, so break
        # at the template's "<" instead (found further left)
        template_comma = ch == "," and _innermost_open(line[:pos], spans) == "<"
        if ch in "({" or template_open or (ch == "," and line[pos + 1:pos + 2] == " " and not template_comma) or \
                (ch == "=" and line[pos - 1:pos] == " " and line[pos + 1:pos + 2] == " "):
            best = pos
            break
    if best > indent + 1:
        head = line[:best + 1].rstrip()
        tail = line[best + 1:].lstrip(" ")
        # a break that leaves a head of only an opening token gains nothing
        if tail and head.strip() not in ("{", "(", "<"):
            # elements of a list opened on an earlier line continue at the line's own indent
            top_level_comma = line[best] == "," and _depth(line[:best], spans) == 0
            return head, (tail, indent if top_level_comma else continuation)
    # a string literal running into the limit (or followed by what does): split it into adjacent
    # literals, the second one where the ROS 2 style aligns it (under the first one when that
    # begins the line)
    for start, end in reversed(spans):
        if line[start] == '"' and start < width - 3:
            cut = _literal_cut(line, start, min(end, width - 1))
            if cut is not None and cut > start + 1:
                at_line_start = not line[:start].strip()
                return line[:cut] + '"', ('"' + line[cut:], start if at_line_start else continuation)
    return None, (line, 0)


def _innermost_open(text: str, spans: list[tuple[int, int]]) -> str:
    """The innermost bracket ``text`` leaves open (outside string literals), "" for none."""
    stack: list[str] = []
    for pos, ch in enumerate(text):
        if any(start <= pos <= end for start, end in spans):
            continue
        if ch in "({<[" and not (ch == "<" and not text[pos - 1:pos].isidentifier()):
            stack.append(ch)
        elif ch in ")}]>" and stack and not (ch == ">" and stack[-1] != "<"):
            stack.pop()
    return stack[-1] if stack else ""


def _depth(text: str, spans: list[tuple[int, int]]) -> int:
    """How many brackets ``text`` leaves open (outside string literals)."""
    depth = 0
    for pos, ch in enumerate(text):
        if any(start <= pos <= end for start, end in spans):
            continue
        depth += 1 if ch in "({<[" else -1 if ch in ")}>]" else 0
    return depth


def _literal_cut(line: str, start: int, limit: int) -> int | None:
    """The last index at or before ``limit`` inside the literal opening at ``start`` where it can be
    cut without splitting an escape sequence (the cut goes before that index)."""
    i = start + 1
    last = None
    while i < limit:
        last = i
        if line[i] == "\\":
            i += 1
            if line[i:i + 1].isdigit():  # octal escape: up to three digits
                j = i
                while j < i + 3 and line[j:j + 1].isdigit():
                    j += 1
                i = j
            else:
                i += 1
        else:
            i += 1
    return last
