"""Vendor YAML text -> a tree of plain values that remembers the line of every key.

Every key path ("imu.frame_id", "transport_options.groups[2].name") keeps its line, so validation
errors can name file:line. Scalars keep their raw text next to their YAML 1.1 meaning, because a few
values (xacro arguments) are passed on as written. ``content_sha256`` fingerprints what the tree
says, not how the file spells it: comments, blank lines, indentation, quoting and key order do
not count, so a comment-only edit changes no generated file and no manifest entry. The way back
is here too: ``yaml_string`` writes a scalar that reads back as exactly the text it was given
(`rhi-gen new`'s YAML, the controllers YAML's joint names).
"""
from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import yaml

from ..errors import ConfigError

MAX_YAML_BYTES = 5 * 1024 * 1024
MAX_NODES = 200_000


class Scalar:
    """A scalar with its raw text, its resolved YAML tag and its YAML 1.1 meaning."""
    __slots__ = ("raw", "tag", "value")

    def __init__(self, node: yaml.ScalarNode) -> None:
        self.raw: str = node.value
        self.tag: str = node.tag
        loader = yaml.SafeLoader("")
        try:
            self.value: Any = loader.construct_object(node, deep=True)
        finally:
            loader.dispose()


class _Loader:
    """YAML nodes -> dict / list / Scalar, remembering the line of every key path ("a.b[2].c")."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.lines: dict[str, int] = {}
        self._count = 0
        self._active: set[int] = set()  # nodes being converted: an alias back to one is a cycle

    def error(self, message: str, path: str = "", fix: str | None = None, line: int | None = None) -> ConfigError:
        return ConfigError(message, file=self.source, line=line or self.lines.get(path), key=path or None, fix=fix)

    def convert(self, node: yaml.Node, path: str) -> Any:
        self._count += 1
        if self._count > MAX_NODES:
            raise self.error("the YAML is too large or expands too many aliases", fix="write a plain vendor YAML")
        self.lines.setdefault(path, node.start_mark.line + 1)
        if id(node) in self._active or len(self._active) > 64:
            raise self.error("the YAML refers to itself through an alias or nests too deeply", path,
                             fix="write the values out instead of using recursive anchors")
        if isinstance(node, yaml.MappingNode):
            self._active.add(id(node))
            try:
                return self._mapping(node, path)
            finally:
                self._active.discard(id(node))
        if isinstance(node, yaml.SequenceNode):
            self._active.add(id(node))
            try:
                return [self.convert(item, f"{path}[{i}]") for i, item in enumerate(node.value)]
            finally:
                self._active.discard(id(node))
        assert isinstance(node, yaml.ScalarNode)
        try:
            return Scalar(node)
        except yaml.YAMLError as exc:
            raise self.error(f"cannot read this value: {getattr(exc, 'problem', None) or exc}", path,
                             fix="use plain strings, numbers and true/false") from exc

    def _mapping(self, node: yaml.MappingNode, path: str) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise self.error("keys must be plain strings", path, line=key_node.start_mark.line + 1,
                                 fix="write each key as plain text (no '?', lists or mappings as keys)")
            key = key_node.value  # raw text: 'on'/'yes' stay names, not booleans
            sub = f"{path}.{key}" if path else key
            if key in out:
                raise self.error(f"duplicate key {key!r}", sub, fix="keep one entry per key",
                                 line=key_node.start_mark.line + 1)
            self.lines[sub] = key_node.start_mark.line + 1
            out[key] = self.convert(value_node, sub)
        return out


def read_text(path: Path, shown: str) -> str:
    """The YAML file as text, with a one-line error for every way reading it can fail."""
    if not path.exists():
        raise ConfigError("file not found", file=shown, fix="check the path (rhi-gen list shows the robots)")
    if path.is_dir():
        raise ConfigError("is a directory, not a vendor YAML", file=shown, fix="give the path of the .yaml file")
    try:
        size = path.stat().st_size
        if size > MAX_YAML_BYTES:
            raise ConfigError(f"file is {size} bytes; a vendor YAML is a few kB", file=shown,
                              fix="start from `rhi-gen new` or the YAML reference (docs/vendor-yaml.md)")
        data = path.read_bytes()
    except OSError as exc:
        raise ConfigError(f"cannot read: {exc.strerror}", file=shown,
                          fix="check the file's permissions (chmod a+r)") from exc
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ConfigError("is not UTF-8 text", file=shown, fix="save the YAML as UTF-8") from exc


def parse_yaml_text(text: str, shown: str) -> tuple[dict[str, Any], dict[str, int]]:
    """Parse YAML text to a mapping of plain values (scalars as Scalar) plus key path -> line."""
    if not text.strip():
        raise ConfigError("file is empty", file=shown,
                          fix="start from `rhi-gen new` or the YAML reference (docs/vendor-yaml.md)")
    try:
        docs = list(yaml.compose_all(text, Loader=yaml.SafeLoader))
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else None
        problem = f"{exc.problem or exc.context}"
        fix = ("indent with spaces, not tabs" if "\\t" in problem or "\t" in problem else
               "fix the YAML syntax at that line (quote values that contain ': ' or ' #')")
        raise ConfigError(f"invalid YAML: {problem}", file=shown, line=line, fix=fix) from exc
    except yaml.YAMLError as exc:
        raise ConfigError(f"invalid YAML: {exc}", file=shown, fix="fix the YAML syntax") from exc
    docs = [d for d in docs if d is not None]
    if not docs:
        raise ConfigError("file is empty (only comments)", file=shown,
                          fix="start from `rhi-gen new` or the YAML reference (docs/vendor-yaml.md)")
    if len(docs) > 1:
        raise ConfigError("holds several YAML documents; a vendor YAML is one mapping", file=shown,
                          line=docs[1].start_mark.line + 1, fix="remove the '---' and everything after it")
    root = docs[0]
    if not isinstance(root, yaml.MappingNode):
        kind = "a list" if isinstance(root, yaml.SequenceNode) else "a single value"
        raise ConfigError(f"top level is {kind}, not a mapping of keys", file=shown,
                          line=root.start_mark.line + 1, fix="write `vendor: ...`, `robot: ...` etc. as keys")
    loader = _Loader(shown)
    data = loader.convert(root, "")
    return data, loader.lines


def _canonical(value: Any) -> Any:
    if isinstance(value, dict):
        return {key: _canonical(item) for key, item in value.items()}  # json.dumps sorts the keys
    if isinstance(value, list):
        return [_canonical(item) for item in value]
    assert isinstance(value, Scalar)
    # Tag and raw text together decide every value the validator reads (the meaning and, for xacro
    # arguments, the text passed on): "1" and 1 differ, 'lo' and "lo" do not.
    return [value.tag, value.raw]


def content_sha256(data: dict[str, Any]) -> str:
    """sha256 of what a parsed YAML tree says (see the module docstring); stable across machines."""
    text = json.dumps(_canonical(data), sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("ascii")).hexdigest()


def yaml_string(text: str) -> str:
    """A double-quoted, ASCII-only YAML scalar that reads back as exactly ``text``."""
    out = ['"']
    for ch in str(text):
        code = ord(ch)
        if ch in ('"', "\\"):
            out.append("\\" + ch)
        elif 0x20 <= code < 0x7F:
            out.append(ch)
        elif code <= 0xFF:
            out.append(f"\\x{code:02x}")
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    out.append('"')
    return "".join(out)
