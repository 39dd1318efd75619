"""An include xacro could not open: the path it tried, and the line of the ``<xacro:include>`` that asked.

xacro's DOM has no line numbers, so the including file is parsed again and each include's
``filename`` resolved (:func:`.xacro_substitutions.resolve_spec`) until one names the path tried.
The fix says whether the path lies in a package the user named.
"""
from __future__ import annotations

import os
from typing import Any

from lxml import etree

from ..errors import UrdfError
from .xacro_run import XacroRun
from .xacro_substitutions import resolve_spec

__all__ = ["cannot_open"]


def _is_under(path: str, directory: str) -> str | None:
    """``path`` relative to ``directory`` (POSIX) if it lies inside it, else None."""
    try:
        rel = os.path.relpath(path, directory)
    except ValueError:  # different drives (Windows)
        return None
    if rel == os.pardir or rel.startswith(os.pardir + os.sep) or os.path.isabs(rel):
        return None
    return rel.replace(os.sep, "/")


def _include_line(including: str, tried: str, run: XacroRun) -> int | None:
    """The line of the ``<xacro:include>`` in ``including`` that asked for ``tried``, if it can be told."""
    try:
        root = etree.parse(including, etree.XMLParser(resolve_entities=False, no_network=True)).getroot()
    except (OSError, etree.LxmlError):
        return None
    includes: list[tuple[int, str]] = []
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        name = etree.QName(el)
        if name.localname == "include" and (name.namespace is None or "ros.org/wiki/xacro" in name.namespace) \
                and el.get("filename") is not None:
            includes.append((el.sourceline or 0, el.get("filename", "")))
    target = os.path.normpath(tried)
    base = os.path.dirname(including)
    for line, spec in includes:
        if resolve_spec(spec, base, run) == target:
            return line or None
    same_name = [line for line, spec in includes if spec.strip().endswith(os.path.basename(target))]
    if len(same_name) == 1 and same_name[0]:
        return same_name[0]
    return None


def _package_of(path: str, run: XacroRun) -> str | None:
    for pkg, directory in run.packages.items():
        if _is_under(path, directory) is not None:
            return pkg
    return None


def cannot_open(cause: OSError, xacro: Any, run: XacroRun, current: str, macro_note: str) -> UrdfError:
    """An include (or a ``load_yaml`` file) that could not be read: the path tried, the include's line."""
    tried = os.path.normpath(os.path.abspath(os.fspath(cause.filename)))
    filestack = [f for f in (xacro.filestack or []) if f]
    including = os.path.abspath(filestack[-1]) if filestack else None
    line = _include_line(including, tried, run) if including else None
    reason = cause.strerror or type(cause).__name__
    message = f"cannot open {run.show(tried)} ({reason}){macro_note}"
    if isinstance(cause, PermissionError):
        return UrdfError(message, file=current, line=line, fix="make the file readable (chmod a+r)")
    pkg = _package_of(tried, run)
    if pkg is not None:
        fix = (f"package '{pkg}' is {run.given.get(pkg, run.packages[pkg])} (given by "
               f"{run.wording.package_path_given(pkg)}) and has no such file: check the include's path, "
               f"or {run.wording.fix_package_path(pkg)}")
    else:
        fix = ("check the <xacro:include filename=...> (a relative path is relative to the including file; "
               f"for a file of another package write $(find pkg)/... and give {run.wording.packages_option})")
    return UrdfError(message, file=current, line=line, fix=fix)
