"""Anything xacro raised -> one line: a :class:`UrdfError` naming the file, the line when it can be told, and a fix.

The fix is in the words of the command used (:mod:`.wording`: ``--xacro-arg``/``--package-path``
on the command line, ``xacro_args``/``package_paths`` in the vendor YAML). The cause is looked for
in everything the exception wraps; a failure inside a macro names the macro.
"""
from __future__ import annotations

import os
import re
from collections.abc import Iterator
from typing import Any

from ..errors import UrdfError
from .xacro_includes import cannot_open
from .xacro_run import XacroRun
from .xacro_substitutions import BadPackageDir, UnknownPackage

__all__ = ["to_urdf_error"]


def _causes(exc: BaseException) -> Iterator[BaseException]:
    """``exc`` and everything it wraps (xacro's ``.exc``, ``__cause__``, ``__context__``)."""
    seen: set[int] = set()
    todo: list[BaseException] = [exc]
    while todo:
        e = todo.pop(0)
        if id(e) in seen:
            continue
        seen.add(id(e))
        yield e
        for nxt in (getattr(e, "exc", None), e.__cause__, e.__context__):
            if isinstance(nxt, BaseException):
                todo.append(nxt)


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def _text_line(file: str | None, needles: tuple[str, ...]) -> int | None:
    """The first line of ``file`` holding one of ``needles`` (the ``$(find pkg)`` or ``$(arg name)`` that
    failed: xacro's DOM has no line numbers), or None."""
    if not file:
        return None
    try:
        with open(file, "rb") as handle:
            for number, raw in enumerate(handle, start=1):
                text = raw.decode("utf-8", "replace")
                if any(n in text for n in needles):
                    return number
    except OSError:
        return None
    return None


def _find_texts(pkg: str) -> tuple[str, ...]:
    return (f"$(find {pkg})", f"find('{pkg}')", f'find("{pkg}")')


def to_urdf_error(exc: Exception, xacro: Any, run: XacroRun) -> UrdfError:
    """Turn anything xacro raised into a one-line UrdfError."""
    from xml.parsers.expat import ExpatError

    filestack = [f for f in (xacro.filestack or []) if f]
    macrostack = list(xacro.macrostack or [])
    current_abs = os.path.abspath(filestack[-1]) if filestack else None
    current = run.show(current_abs)
    rerun = f"run `xacro {run.shown}` to see xacro's own report"
    wording = run.wording

    macro_note = ""
    if macrostack:
        try:
            macro_note = f" (in macro '{macrostack[-1].body.getAttribute('name')}')"
        except Exception:  # noqa: BLE001 (defensive: the DOM is xacro's, any failure just drops the note)
            macro_note = ""

    for cause in _causes(exc):
        if isinstance(cause, UnknownPackage):
            pkg = cause.package
            return UrdfError(
                f"$(find {pkg}): unknown package '{pkg}'{macro_note}", file=current,
                line=_text_line(current_abs, _find_texts(pkg)), fix=wording.package_path(pkg))
        if isinstance(cause, BadPackageDir):
            pkg = cause.package
            return UrdfError(
                f"$(find {pkg}): {cause.directory} (given by {wording.package_path_given(pkg)}) is not a "
                "directory", file=current, line=_text_line(current_abs, _find_texts(pkg)),
                fix=wording.fix_package_path(pkg))
        if type(cause).__name__ == "ArgException":
            name = _one_line(str(cause))
            return UrdfError(
                f"xacro arg '{name}' is not set{macro_note}", file=current,
                line=_text_line(current_abs, (f"$(arg {name})", f"xacro.arg('{name}')", f'xacro.arg("{name}")')),
                fix=f"{wording.xacro_arg(name)} (or declare <xacro:arg name=\"{name}\" default=\"...\"/>)")
        if isinstance(cause, ExpatError):
            message = _one_line(str(cause)).split(": line ")[0]
            return UrdfError(
                f"malformed XML: {message}", file=current, line=getattr(cause, "lineno", None),
                fix="fix the XML syntax (every xacro file must be well-formed XML with "
                    "xmlns:xacro=\"http://www.ros.org/wiki/xacro\")")
        if isinstance(cause, OSError):
            missing = getattr(cause, "filename", None)
            url = re.search(r"package:/+\S+", os.fspath(missing)) if missing else None
            if url:
                pkg, _, rest = url.group(0).split("://", 1)[1].lstrip("/").partition("/")
                return UrdfError(
                    f"cannot include '{url.group(0)}': xacro does not resolve package:// URLs"
                    f"{macro_note}", file=current, line=_text_line(current_abs, (url.group(0),)),
                    fix=f"write $(find {pkg})/{rest} instead and {wording.package_path(pkg)}")
            if missing:
                return cannot_open(cause, xacro, run, current, macro_note)
            return UrdfError(
                f"cannot open a file ({cause.strerror or type(cause).__name__}){macro_note}", file=current,
                fix="check the <xacro:include filename=...> paths; " + rerun)
        if isinstance(cause, RecursionError):
            return UrdfError(
                f"xacro recursion too deep{macro_note}", file=current,
                fix="a macro or property refers to itself; " + rerun)
        if isinstance(cause, UnicodeError):
            return UrdfError(
                f"xacro cannot decode a file: {_one_line(str(cause))}", file=current,
                fix="save every xacro/URDF file as UTF-8")

    detail = _one_line(str(exc)) or type(exc).__name__
    return UrdfError(f"xacro: {detail}{macro_note}", file=current, fix="fix the xacro; " + rerun)
