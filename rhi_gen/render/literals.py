"""Turn untrusted text and numbers into C++, XML and YAML literals.

A URDF joint name ends up inside C++ string literals, XML attributes and YAML lists; escaping is
decided here, in one tested place, never inside templates.
"""
from __future__ import annotations

import math
import re

from ..typed_yaml.yaml_source import yaml_string

_CPP_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\r": "\\r", "\t": "\\t", "?": "\\?"}


def cpp_string(text: str) -> str:
    """A complete C++ string literal (with quotes) holding exactly ``text`` as UTF-8.

    Non-ASCII and control characters become octal escapes (at most three digits, so the next
    character can never extend the escape); ``?`` is escaped so no trigraph can form.
    """
    if not isinstance(text, str):
        raise TypeError(f"cpp_string expects str, got {type(text).__name__}")
    out = ['"']
    for ch in text:
        if ch in _CPP_ESCAPES:
            out.append(_CPP_ESCAPES[ch])
        elif 0x20 <= ord(ch) < 0x7F:
            out.append(ch)
        else:
            out.extend(f"\\{b:03o}" for b in ch.encode("utf-8"))
    out.append('"')
    return "".join(out)


def cpp_double(value: float) -> str:
    """A C++ double literal that round-trips exactly (repr gives the shortest such form)."""
    value = float(value)
    if math.isnan(value):
        return "std::numeric_limits<double>::quiet_NaN()"
    if math.isinf(value):
        return ("-" if value < 0 else "") + "std::numeric_limits<double>::infinity()"
    text = repr(value)
    if "e" not in text and "." not in text:
        text += ".0"
    return text


def cpp_limit(value: float) -> str:
    """A limit as the joint tables write it: kNoLimit (robot_spec.hpp) for an infinite one."""
    return ("-kNoLimit" if value < 0 else "kNoLimit") if math.isinf(value) else cpp_double(value)


def header_guard(relpath: str) -> str:
    """The ROS 2 include guard of a header below include/, as ament_cpplint expects it:
    folders joined by ``__``, e.g. ROBOT_HARDWARE_INTERFACE__UNITREE__G1_HPP_."""
    return "__".join(re.sub(r"[^A-Za-z0-9]", "_", part).upper() for part in relpath.split("/")) + "_"


def xml_escape(text: str) -> str:
    """Escape for XML text and attribute values (used where autoescape is off)."""
    return (str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;").replace("'", "&apos;"))


FILTERS = {  # the Jinja filters: {{ joint.name | cpp_string }}
    "header_guard": header_guard,
    "cpp_string": cpp_string,
    "cpp_double": cpp_double,
    "cpp_limit": cpp_limit,
    "yaml_string": yaml_string,
    "xml": xml_escape,
}
