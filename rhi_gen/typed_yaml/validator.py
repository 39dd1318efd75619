"""Typed reads from a parsed vendor YAML tree, each failure a ConfigError naming file:line: key and a fix.

Shared by the top-level schema (inputs/vendor_config.py) and every transport's ``transport_options``
(transports/<name>/), so all of them word their errors the same way.
"""
from __future__ import annotations

import contextlib
import math
import re
from collections.abc import Callable
from typing import Any, TypeVar

from ..errors import ConfigError
from ..model.naming import suggest
from .yaml_source import Scalar

T = TypeVar("T")

TOPIC_RE = re.compile(r"^/?[A-Za-z_~][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$")


class Validator:
    def __init__(self, source: str, lines: dict[str, int]) -> None:
        self.source = source
        self.lines = lines

    def error(self, path: str, message: str, fix: str | None = None) -> ConfigError:
        return ConfigError(message, file=self.source, line=self.lines.get(path), key=path, fix=fix)

    def mapping(self, value: Any, path: str, allowed: tuple[str, ...]) -> dict[str, Any]:
        if isinstance(value, Scalar) and value.raw in ("", "~", "null") and value.value is None:
            return {}
        if not isinstance(value, dict):
            raise self.error(path, "must be a mapping of keys", fix=f"allowed keys: {', '.join(allowed)}")
        for key in value:
            if key not in allowed:
                sub = f"{path}.{key}" if path else key
                hint = suggest(key, allowed)
                fix = f"did you mean {hint!r}?" if hint else f"allowed keys: {', '.join(allowed)}"
                raise self.error(sub, "unknown key", fix=fix)
        return value

    def optional(self, mapping: dict[str, Any], path: str, key: str, read: Callable[[Any, str], T],
                 default: T) -> T:
        """``read(mapping[key], "path.key")`` when the key is present, else ``default``."""
        return read(mapping[key], f"{path}.{key}" if path else key) if key in mapping else default

    def scalar(self, value: Any, path: str) -> Any:
        if not isinstance(value, Scalar):
            raise self.error(path, "must be a single value, not a list or mapping",
                             fix="write one value after the colon")
        return value.value

    def string(self, value: Any, path: str, pattern: re.Pattern[str] | None = None, what: str = "") -> str:
        v = self.scalar(value, path)
        if not isinstance(v, str) or not v:
            raise self.error(path, f"must be a non-empty string, got {value.raw!r}",
                             fix="write the text in quotes, e.g. \"name\"")
        if pattern is not None and not pattern.match(v):
            raise self.error(path, f"{v!r} is not a valid {what}", fix=f"write a valid {what}")
        return v

    def integer(self, value: Any, path: str, low: int, high: int) -> int:
        v = self.scalar(value, path)
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.error(path, f"must be a whole number, got {value.raw!r}",
                             fix=f"write a whole number from {low} to {high}, without quotes")
        if not low <= v <= high:
            raise self.error(path, f"{v} is out of range {low}..{high}",
                             fix=f"write a whole number from {low} to {high}")
        return v

    def finite_number(self, value: Any, path: str, fix: str, what: str = "a finite number") -> float:
        """A finite float (an int too big for a float, .nan, .inf, true and '1.0' are refused)."""
        v = self.scalar(value, path)
        number = math.nan
        if not isinstance(v, bool) and isinstance(v, (int, float)):
            with contextlib.suppress(OverflowError):  # an int too large for a float
                number = float(v)
        if not math.isfinite(number):
            raise self.error(path, f"must be {what}, got {getattr(value, 'raw', v)!r}", fix=fix)
        return number

    def seconds_in(self, low: float, high: float, what: str, example: float) -> Callable[[Any, str], float]:
        """A reader for ``optional``: a number of seconds from ``low`` to ``high`` (``what`` they measure)."""
        def read(value: Any, path: str) -> float:
            fix = f"write {what} in seconds, from {low:g} to {high:g}, e.g. {example:g}"
            seconds = self.finite_number(value, path, fix, "a number of seconds")
            if not low <= seconds <= high:
                raise self.error(path, f"must be from {low:g} to {high:g} seconds, got {seconds:g}", fix=fix)
            return seconds
        return read

    def integer_in(self, low: int, high: int) -> Callable[[Any, str], int]:
        """A reader for ``optional``: a whole number from ``low`` to ``high``."""
        return lambda value, path: self.integer(value, path, low, high)

    def boolean(self, value: Any, path: str) -> bool:
        v = self.scalar(value, path)
        if not isinstance(v, bool):
            raise self.error(path, f"must be true or false, got {value.raw!r}", fix="write true or false")
        return v

    def choice(self, value: Any, path: str, choices: tuple[str, ...]) -> str:
        v = self.scalar(value, path)
        if not isinstance(v, str) or v not in choices:
            raw = value.raw if isinstance(value, Scalar) else str(v)
            hint = suggest(str(raw), choices)
            fix = (f"did you mean {hint!r}? " if hint else "") + f"use one of: {', '.join(choices)}"
            raise self.error(path, f"{raw!r} is not supported", fix=fix)
        return v

    def string_map(self, value: Any, path: str) -> tuple[tuple[str, str], ...]:
        if isinstance(value, Scalar) and value.value is None:
            return ()
        if not isinstance(value, dict):
            raise self.error(path, "must be a mapping of name: value", fix="write one `name: value` per line")
        out = []
        for key, item in value.items():
            if not isinstance(item, Scalar) or item.value is None:
                raise self.error(f"{path}.{key}", "must be a single value", fix="write one value after the colon")
            out.append((key, item.raw))
        return tuple(out)

    def topic(self, value: Any, path: str) -> str:
        return self.string(value, path, TOPIC_RE, "ROS topic name (letters, digits, _ and / separators)")
