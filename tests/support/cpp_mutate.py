"""Mutations of a generated package that do not depend on how its sources are laid out.

Two kinds (tests/cpp/test_cpp_mutations.py lists them, tests/unit/render/test_cpp_mutate.py tests this module):

- ``SwapSlots``: a data mutation. It changes the ``RobotModel`` (dataclasses.replace) before the
  package is rendered, so the driver is generated from a wrong model.
- ``TokenEdit``: a logic mutation. It changes one generated file, named by its package path, as C++
  tokens: the pattern is a C++ snippet, tokenized and searched for as a token sequence (comments and
  whitespace do not count), it must match exactly ``count`` times, and the replacement snippet is
  spliced in place of the characters the match covers; every other byte of the file is kept.
  Reformatting, re-indenting, wrapping or re-commenting the source cannot break or silently disable
  an edit; renaming an identifier it names makes it fail with "pattern not found in <file>".

The tokenizer knows identifiers, pp-numbers (``0x04C11DB7U``, ``1.5e-3f``, ``1'000``), string and
character literals (with encoding prefixes, raw strings), and punctuators by longest match (``::``,
``->``, ``&&``, ``<<=``...); ``>>`` stays one token, as the C++ lexer has it. In a pattern, ``$$`` is
a wildcard: the shortest non-empty run of tokens with balanced (), [] and {} after which the rest of
the pattern matches ("any expression", "any statement list").
"""
from __future__ import annotations

import dataclasses
import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass

WILDCARD = "$$"


class MutationError(AssertionError):
    """A mutation that cannot be applied as written (pattern missing, wrong count, no such file)."""


@dataclass(frozen=True)
class Token:
    kind: str    # "identifier" | "number" | "string" | "char" | "punct" | "wildcard"
    text: str
    start: int   # character offsets into the tokenized text
    end: int


# Longest first: the lexer takes the longest punctuator that fits.
_PUNCTUATORS = sorted((
    "<<=", ">>=", "<=>", "...", "->*",
    "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "+=", "-=", "*=", "/=",
    "%=", "&=", "|=", "^=", ".*", "##",
    *"{}[]()<>;:,.?+-*/%^&|~!=#",
), key=len, reverse=True)
_PREFIX = r"(?:u8|u|U|L)?"
_SUFFIX = r"(?:[A-Za-z_][A-Za-z0-9_]*)?"  # a user-defined-literal suffix ("abc"sv) is part of the token
# One alternative per kind of lexeme, tried in this order at each position.
_LEXEME_RE = re.compile("|".join((
    r"(?P<space>(?:\s|\\\n)+)",                          # a backslash-newline splices lines
    r"(?P<comment>//(?:[^\n\\]|\\[\s\S])*|/\*[\s\S]*?\*/)",
    r"(?P<open_comment>/\*)",                            # no */ after it: an error, not two punctuators
    rf"(?P<raw>{_PREFIX}R\")",                           # the rest of a raw string: _raw_string_end
    rf"(?P<string>{_PREFIX}\"(?:[^\"\\\n]|\\[\s\S])*\"{_SUFFIX})",
    rf"(?P<char>{_PREFIX}'(?:[^'\\\n]|\\[\s\S])*'{_SUFFIX})",
    # pp-number: a digit (or . digit), then digits, letters, _, ., digit separators, exponent signs
    r"(?P<number>\.?[0-9](?:[eEpP][+-]|'[0-9A-Za-z_]|[0-9A-Za-z_.])*)",
    r"(?P<identifier>[A-Za-z_][A-Za-z0-9_]*)",
    "(?P<punct>" + "|".join(re.escape(p) for p in _PUNCTUATORS) + ")",
)))
_RAW_DELIMITER_RE = re.compile(r'([^()\\\s"]{0,16})\(')


def _line_col(text: str, pos: int) -> str:
    line = text.count("\n", 0, pos) + 1
    return f"line {line}, column {pos - (text.rfind(chr(10), 0, pos) + 1) + 1}"


def tokenize(text: str, *, pattern: bool = False) -> list[Token]:
    """The C++ tokens of ``text``; comments and whitespace are skipped. ``pattern``: ``$$`` is the
    wildcard token. Unterminated comments and literals raise ValueError."""
    tokens: list[Token] = []
    pos, n = 0, len(text)
    while pos < n:
        if pattern and text.startswith(WILDCARD, pos):
            tokens.append(Token("wildcard", WILDCARD, pos, pos + 2))
            pos += 2
            continue
        m = _LEXEME_RE.match(text, pos)
        if m is None or m.lastgroup == "open_comment":
            raise ValueError(_lexing_error(text, pos))
        kind, end = m.lastgroup, m.end()
        assert kind is not None, "every alternative of _LEXEME_RE is a named group"
        if kind == "raw":
            kind, end = "string", _raw_string_end(text, pos, end)
        if kind not in ("space", "comment"):
            tokens.append(Token(kind, text[pos:end], pos, end))
        pos = end
    return tokens


def _raw_string_end(text: str, pos: int, body: int) -> int:
    """End of the raw string R"delim( ... )delim" that starts at ``pos``, its delimiter at ``body``."""
    delimiter = _RAW_DELIMITER_RE.match(text, body)
    if delimiter is None:
        raise ValueError(f"malformed raw string at {_line_col(text, pos)}")
    close = ")" + delimiter.group(1) + '"'
    end = text.find(close, delimiter.end())
    if end == -1:
        raise ValueError(f"unterminated raw string at {_line_col(text, pos)}")
    suffix = re.compile(_SUFFIX).match(text, end + len(close))
    return suffix.end() if suffix else end + len(close)


def _lexing_error(text: str, pos: int) -> str:
    where = _line_col(text, pos)
    if text.startswith("/*", pos):
        return f"unterminated /* comment at {where}"
    quote = re.compile(_PREFIX + "([\"'])").match(text, pos)
    if quote:
        return f"unterminated {'string' if quote.group(1) == chr(34) else 'character'} literal at {where}"
    return f"character {text[pos]!r} is not C++ at {where}"


# ------------------------------------------------------------------------------------ matching
_OPEN = {"(": ")", "[": "]", "{": "}"}
_CLOSE = set(_OPEN.values())


def _same(a: Token, b: Token) -> bool:
    return a.kind == b.kind and a.text == b.text


def _match_at(pattern: Sequence[Token], p: int, tokens: Sequence[Token], t: int) -> int | None:
    """Index just past the tokens that ``pattern[p:]`` matches from ``tokens[t]``, else None."""
    while p < len(pattern):
        want = pattern[p]
        if want.kind == "wildcard":
            stack: list[str] = []
            for k in range(t, len(tokens)):  # the wildcard takes tokens[t:k + 1], shortest first
                text = tokens[k].text if tokens[k].kind == "punct" else ""
                if text in _OPEN:
                    stack.append(_OPEN[text])
                elif text in _CLOSE and (not stack or stack.pop() != text):
                    return None  # it would close a bracket opened before the wildcard
                if not stack:
                    end = _match_at(pattern, p + 1, tokens, k + 1)
                    if end is not None:
                        return end
            return None
        if t >= len(tokens) or not _same(want, tokens[t]):
            return None
        p, t = p + 1, t + 1
    return t


def _pattern_tokens(pattern: str) -> list[Token]:
    wanted = tokenize(pattern, pattern=True)
    if not wanted:
        raise ValueError(f"pattern {pattern!r} has no C++ tokens")
    if wanted[0].kind == "wildcard" or wanted[-1].kind == "wildcard":
        raise ValueError(f"pattern {pattern!r}: a wildcard needs tokens on both sides")
    return wanted


def _find(wanted: Sequence[Token], tokens: Sequence[Token]) -> list[tuple[int, int]]:
    spans = []
    t = 0
    while t < len(tokens):
        end = _match_at(wanted, 0, tokens, t)
        if end is None:
            t += 1
            continue
        spans.append((tokens[t].start, tokens[end - 1].end))
        t = end
    return spans


def find(pattern: str, text: str) -> list[tuple[int, int]]:
    """Character spans (start, end) of the non-overlapping matches of ``pattern`` in ``text``, left to
    right; a span runs from the first matched token's first character to the last one's end."""
    return _find(_pattern_tokens(pattern), tokenize(text))


def replace(text: str, pattern: str, replacement: str, count: int = 1, *, where: str = "the text") -> str:
    """``text`` with each of the ``count`` matches of ``pattern`` replaced by ``replacement`` (exactly
    ``count``: otherwise MutationError naming ``where``). Bytes outside the matches are unchanged."""
    wanted = _pattern_tokens(pattern)
    tokenize(replacement)  # a replacement must be lexically C++ itself (no unterminated literal)
    try:
        tokens = tokenize(text)
    except ValueError as err:
        raise MutationError(f"{where} does not tokenize: {err}") from err
    spans = _find(wanted, tokens)
    if not spans:
        raise MutationError(f"pattern not found in {where}: {pattern!r}; update the mutation")
    if len(spans) != count:
        raise MutationError(f"pattern matched {len(spans)} times in {where}, expected {count}: {pattern!r}; "
                            "update the mutation")
    out, last = [], 0
    for start, end in spans:
        out += [text[last:start], replacement]
        last = end
    out.append(text[last:])
    return "".join(out)


def code_of(text: str) -> str:
    """``text`` from its first token to its last: leading and trailing comments and space dropped."""
    tokens = tokenize(text)
    return text[tokens[0].start:tokens[-1].end] if tokens else ""


# ------------------------------------------------------------------------------------ mutations
@dataclass(frozen=True)
class TokenEdit:
    """Replace ``pattern`` (exactly ``count`` matches) by ``replacement`` in the generated file ``file``
    (its path in the package, e.g. include/robot_hardware_interface/common/driver_core.hpp). ``switch``: how a
    mutation schema switches it at run time ("statements" or "operand", see SWITCH_FORMS); "" builds it alone."""
    file: str
    pattern: str
    replacement: str
    count: int = 1
    switch: str = ""

    def apply_to_plan(self, plan: dict[str, str], label: str = "") -> None:
        where = f"{self.file}" + (f" ({label})" if label else "")
        if self.file not in plan:
            raise MutationError(f"{where}: the package has no such file; it has "
                                f"{', '.join(p for p in plan if p.endswith(('.hpp', '.cpp')))}")
        plan[self.file] = replace(plan[self.file], self.pattern, self.replacement, self.count, where=where)


@dataclass(frozen=True)
class SwapSlots:
    """Swap the SDK slots of the joints in slots ``first`` and ``second`` of the RobotModel."""
    first: int
    second: int

    def apply_to_model(self, model):
        by_slot = {j.index: j for j in model.joints}
        missing = [s for s in (self.first, self.second) if s not in by_slot]
        if missing:
            raise MutationError(f"{model.vendor}/{model.robot}: no joint in SDK slot(s) {missing}; "
                                "pick mapped slots")
        swap = {self.first: self.second, self.second: self.first}
        joints = tuple(dataclasses.replace(j, index=swap[j.index]) if j.index in swap else j
                       for j in model.joints)
        return dataclasses.replace(model, joints=joints)


# ------------------------------------------------------------------------------------ mutation schemata
# Many TokenEdits of one robot compiled into one driver, each switched on at run time (a mutation schema,
# Untch et al. 1993): the harness binary is built once and run once per mutant (--mutant=N), instead of one
# driver build per mutant. With every switch off the code does what the unmutated code does; with switch N on,
# what TokenEdit N's code does. A TokenEdit says how it is switched (``switch``):
# - "statements": the match and the replacement are whole statements (declaring nothing used after them);
#   switched as ``if (on(N)) { replacement } else { match }``;
# - "operand": after the tokens both begin and end with, what is left of each is one expression in the same
#   place (an operand, an argument, a condition, an initializer); switched as ``(on(N) ? (new) : (old))``.
# A constant expression cannot be switched at run time: such an edit (and SwapSlots) is built on its own.
SWITCH_FORMS = ("statements", "operand")
SWITCH_FUNCTION = "rhi_mutant_on"
SWITCH_DECLARATION = (f'extern "C" bool {SWITCH_FUNCTION}(int mutant) noexcept;  '
                      "// a mutation schema's switch (tests/support/cpp_mutate.py)\n")


def _balanced(tokens: Sequence[Token]) -> bool:
    stack: list[str] = []
    for t in tokens:
        if t.kind != "punct":
            continue
        if t.text in _OPEN:
            stack.append(_OPEN[t.text])
        elif t.text in _CLOSE and (not stack or stack.pop() != t.text):
            return False
    return not stack


def operand_split(old: Sequence[Token], new: Sequence[Token]) -> tuple[int, int]:
    """(leading, trailing): how many tokens ``old`` and ``new`` share at their start and end such that what is
    left of each is non-empty and balanced; the longest shared start first, then the longest shared end."""
    def shared(a: Sequence[Token], b: Sequence[Token]) -> int:
        n = 0
        while n < min(len(a), len(b)) and _same(a[n], b[n]):
            n += 1
        return n

    for lead in range(shared(old, new), -1, -1):
        rest_old, rest_new = old[lead:], new[lead:]
        for trail in range(shared(rest_old[::-1], rest_new[::-1]), -1, -1):
            mid_old, mid_new = rest_old[:len(rest_old) - trail], rest_new[:len(rest_new) - trail]
            if mid_old and mid_new and _balanced(mid_old) and _balanced(mid_new):
                return lead, trail
    raise MutationError("no operand: the match and the replacement share no balanced frame")


def _switched_text(edit: TokenEdit, number: int, text: str, start: int, end: int) -> str:
    """The switched form of ``edit``'s match text[start:end] (see SWITCH_FORMS)."""
    on = f"::{SWITCH_FUNCTION}({number})"
    old = text[start:end]
    if edit.switch == "statements":
        if not tokenize(edit.replacement):
            return f"if (!{on}) {{ {old} }}"
        return f"if ({on}) {{ {edit.replacement} }} else {{ {old} }}"
    old_tokens, new_tokens = tokenize(old), tokenize(edit.replacement)
    lead, trail = operand_split(old_tokens, new_tokens)
    o0, o1 = old_tokens[lead].start, old_tokens[len(old_tokens) - trail - 1].end
    n0, n1 = new_tokens[lead].start, new_tokens[len(new_tokens) - trail - 1].end
    return f"{old[:o0]}({on} ? ({edit.replacement[n0:n1]}) : ({old[o0:o1]})){old[o1:]}"


def edit_spans(edit: TokenEdit, plan: dict[str, str], label: str = "") -> list[tuple[int, int]]:
    """The character spans of ``edit``'s matches in its file (exactly ``count``: otherwise MutationError)."""
    where = f"{edit.file}" + (f" ({label})" if label else "")
    if edit.file not in plan:
        raise MutationError(f"{where}: the package has no such file")
    spans = _find(_pattern_tokens(edit.pattern), tokenize(plan[edit.file]))
    if len(spans) != edit.count:
        raise MutationError(f"pattern matched {len(spans)} times in {where}, expected {edit.count}: "
                            f"{edit.pattern!r}; update the mutation")
    return spans


def apply_schema(plan: dict[str, str], edits: Sequence[tuple[TokenEdit, int]]) -> None:
    """Every (edit, number) of ``edits`` switched into ``plan`` at once; their matches must not overlap
    (MutationError otherwise: put them in different schemata, see ``disjoint_groups``)."""
    by_file: dict[str, list[tuple[int, int, TokenEdit, int]]] = {}
    for edit, number in edits:
        if edit.switch not in SWITCH_FORMS:
            raise MutationError(f"{edit.file}: {edit.pattern!r} is not switchable (switch={edit.switch!r})")
        for start, end in edit_spans(edit, plan, f"mutant {number}"):
            by_file.setdefault(edit.file, []).append((start, end, edit, number))
    for file, spans in by_file.items():
        text = plan[file]
        spans.sort(key=lambda s: s[0])
        for (_, end, _, a), (start, _, _, b) in itertools.pairwise(spans):
            if start < end:
                raise MutationError(f"{file}: the matches of mutants {a} and {b} overlap")
        out, last = [SWITCH_DECLARATION], 0
        for start, end, edit, number in spans:
            out += [text[last:start], _switched_text(edit, number, text, start, end)]
            last = end
        out.append(text[last:])
        plan[file] = "".join(out)


def disjoint_groups(plan: dict[str, str], edits: Sequence[tuple[TokenEdit, int]]) -> list[list[tuple[TokenEdit, int]]]:
    """``edits`` in as few groups as greedily found whose matches do not overlap (each group: one schema)."""
    groups: list[tuple[list[tuple[TokenEdit, int]], list[tuple[str, int, int]]]] = []
    for edit, number in edits:
        spans = [(edit.file, s, e) for s, e in edit_spans(edit, plan, f"mutant {number}")]
        for members, taken in groups:
            if not any(f == g and s < e2 and s2 < e for f, s, e in spans for g, s2, e2 in taken):
                members.append((edit, number))
                taken.extend(spans)
                break
        else:
            groups.append(([(edit, number)], spans))
    return [members for members, _ in groups]
