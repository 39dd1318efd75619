"""Expand a xacro file with string args and ``$(find pkg)`` resolved from user-named directories.

xacro (2.1.x) is a library with process-wide state, so every expansion here:

- holds one module lock (xacro must never run in parallel: ``filestack``, ``macrostack``,
  ``substitution_args_context``, ``all_includes``, ``verbosity`` and ``root_dir`` are globals);
- resets those globals before and after the run (an exception inside xacro skips its own reset of
  the substitution args, and ``all_includes`` only ever grows);
- installs, for the duration of the run only, a stand-in ``ament_index_python.packages`` module in
  ``sys.modules`` that knows exactly the packages the user named (``package_paths`` in the vendor
  YAML), so ``$(find pkg)`` and ``${find('pkg')}`` never depend on a sourced ROS workspace;
- captures what xacro prints on stderr (warnings) and logs it at DEBUG level instead;
- restores ``yaml.SafeLoader``'s constructor table (``xacro.load_yaml`` registers ``!degrees`` etc.
  on the process-wide SafeLoader);
- turns every failure into a one-line :class:`UrdfError` naming the file (and the line when xacro
  knows it) and what to do.

Only ``xacro.process_file`` is used: ``xacro.process`` calls ``sys.exit`` and swaps ``sys.stdout``.
"""
from __future__ import annotations

import contextlib
import io
import logging
import os
import re
import sys
import threading
import types
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from ..errors import UrdfError

__all__ = ["expand_xacro"]

log = logging.getLogger(__name__)

_LOCK = threading.Lock()
_MISSING = object()
_AMENT_MODULES = ("ament_index_python", "ament_index_python.packages")


class _UnknownPackage(KeyError):
    """Raised by the stand-in ``get_package_share_directory`` (the real one raises a KeyError too)."""

    def __init__(self, package: str) -> None:
        super().__init__(package)
        self.package = package

    def __str__(self) -> str:
        return f"package '{self.package}' not found"


class _BadPackageDir(Exception):
    def __init__(self, package: str, directory: str) -> None:
        super().__init__(f"package '{package}' -> {directory} is not a directory")
        self.package = package
        self.directory = directory


@contextlib.contextmanager
def _ament_index_stand_in(packages: Mapping[str, str],
                          given: Mapping[str, str] | None = None) -> Iterator[None]:
    """Make ``from ament_index_python.packages import get_package_share_directory`` resolve
    exactly ``packages`` while the block runs; the previous ``sys.modules`` entries (a real
    ament_index_python, or none) are put back afterwards."""

    def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
        try:
            directory = packages[package_name]
        except KeyError:
            raise _UnknownPackage(package_name) from None
        if not os.path.isdir(directory):
            raise _BadPackageDir(package_name, (given or packages).get(package_name, directory))
        return directory

    top = types.ModuleType("ament_index_python")
    top.__path__ = []  # a package, so the dotted import is well-formed
    sub = types.ModuleType("ament_index_python.packages")
    sub.PackageNotFoundError = _UnknownPackage  # type: ignore[attr-defined]
    sub.get_package_share_directory = get_package_share_directory  # type: ignore[attr-defined]
    sub.get_package_prefix = get_package_share_directory  # type: ignore[attr-defined]
    top.packages = sub  # type: ignore[attr-defined]

    saved = {name: sys.modules.get(name, _MISSING) for name in _AMENT_MODULES}
    sys.modules["ament_index_python"] = top
    sys.modules["ament_index_python.packages"] = sub
    try:
        yield
    finally:
        for name, module in saved.items():
            if module is _MISSING:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = module  # type: ignore[assignment]


@contextlib.contextmanager
def _safe_loader_guard() -> Iterator[None]:
    """``xacro.load_yaml`` calls ``yaml.SafeLoader.add_constructor`` (process-wide): undo it."""
    try:
        import yaml
    except ImportError:  # pragma: no cover - PyYAML is a dependency of xacro and of rhi-gen
        yield
        return
    cls = yaml.SafeLoader
    had_own = "yaml_constructors" in cls.__dict__
    saved = dict(cls.__dict__["yaml_constructors"]) if had_own else None
    try:
        yield
    finally:
        if had_own:
            table = cls.__dict__["yaml_constructors"]
            table.clear()
            table.update(saved)
        elif "yaml_constructors" in cls.__dict__:
            delattr(cls, "yaml_constructors")


def _binary_open(file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
    """xacro opens its inputs with ``open(filename)``, i.e. in the locale's encoding (ASCII under
    a plain C locale). Reading bytes instead lets expat honour the XML encoding declaration
    (default UTF-8) and lets PyYAML detect the encoding of ``load_yaml`` files."""
    if mode in ("r", "rt") and not args and not kwargs:
        return open(file, "rb")
    return open(file, mode, *args, **kwargs)


@contextlib.contextmanager
def _xacro_reads_bytes(xacro: Any) -> Iterator[None]:
    saved = xacro.__dict__.get("open", _MISSING)
    xacro.open = _binary_open
    try:
        yield
    finally:
        if saved is _MISSING:
            del xacro.open
        else:
            xacro.open = saved


def _reset_xacro_state(xacro: Any) -> None:
    xacro.filestack = None
    xacro.macrostack = None
    xacro.substitution_args_context.clear()
    xacro.all_includes.clear()
    xacro.root_dir = os.curdir
    xacro.verbosity = 1


def _is_under(path: str, directory: str) -> str | None:
    """``path`` relative to ``directory`` (POSIX) if it lies inside it, else None."""
    try:
        rel = os.path.relpath(path, directory)
    except ValueError:  # different drives (Windows)
        return None
    if rel == os.pardir or rel.startswith(os.pardir + os.sep) or os.path.isabs(rel):
        return None
    return rel.replace(os.sep, "/")


class _Displayer:
    """Shows files the way the user knows them: the top file as ``display_path``, files next to it
    relative to it, package files as ``$(find pkg)/...``, anything else absolute."""

    def __init__(self, top_abs: str, shown: str, packages: Mapping[str, str]) -> None:
        self.top_abs = os.path.normpath(top_abs)
        self.top_dir = os.path.dirname(self.top_abs)
        self.shown = shown
        self.shown_dir = os.path.dirname(shown)
        self.packages = packages

    def __call__(self, file: str | None) -> str:
        if not file:
            return self.shown
        path = os.path.normpath(os.path.abspath(file))
        if path == self.top_abs:
            return self.shown
        # Package files first: they are the ones a user names in package_paths.
        for pkg, directory in self.packages.items():
            rel = _is_under(path, os.path.normpath(directory))
            if rel is not None:
                return f"$(find {pkg})/{rel}"
        rel = _is_under(path, self.top_dir)
        if rel is not None:
            return f"{self.shown_dir}/{rel}" if self.shown_dir else rel
        return path


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


def _convert(exc: Exception, xacro: Any, show: _Displayer, path_shown: str) -> UrdfError:
    """Turn anything xacro raised into a one-line UrdfError."""
    from xml.parsers.expat import ExpatError

    filestack = [f for f in (xacro.filestack or []) if f]
    macrostack = list(xacro.macrostack or [])
    current = show(filestack[-1] if filestack else None)
    rerun = f"run `xacro {path_shown}` to see xacro's own report"

    macro_note = ""
    if macrostack:
        try:
            macro_note = f" (in macro '{macrostack[-1].body.getAttribute('name')}')"
        except Exception:  # noqa: BLE001 (defensive: the DOM is xacro's, any failure just drops the note)
            macro_note = ""

    for cause in _causes(exc):
        if isinstance(cause, _UnknownPackage):
            pkg = cause.package
            return UrdfError(
                f"$(find {pkg}): unknown package '{pkg}'{macro_note}", file=current,
                fix=f"add package_paths: {{{pkg}: <dir>}} to the vendor YAML")
        if isinstance(cause, _BadPackageDir):
            return UrdfError(
                f"$(find {cause.package}): package_paths gives {cause.directory}, "
                "which is not a directory", file=current,
                fix=f"fix package_paths: {{{cause.package}: <dir>}} in the vendor YAML")
        if type(cause).__name__ == "ArgException":
            name = _one_line(str(cause))
            return UrdfError(
                f"xacro arg '{name}' is not set{macro_note}", file=current,
                fix=f"add xacro_args: {{{name}: <value>}} to the vendor YAML "
                    f"(or declare <xacro:arg name=\"{name}\" default=\"...\"/>)")
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
                return UrdfError(
                    f"cannot include '{url.group(0)}': xacro does not resolve package:// URLs"
                    f"{macro_note}", file=current,
                    fix="write $(find pkg)/... instead and add package_paths: {pkg: <dir>} to "
                        "the vendor YAML")
            what = show(os.fspath(missing)) if missing else "a file"
            reason = cause.strerror or type(cause).__name__
            return UrdfError(
                f"cannot open {what} ({reason}){macro_note}", file=current,
                fix="check the <xacro:include filename=...> (relative paths are relative to the "
                    "including file; use $(find pkg) and package_paths for package files)")
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


def expand_xacro(path: str | Path, args: Mapping[str, str] | None,
                 package_paths: Mapping[str, str | Path] | None, *,
                 display_path: str | None = None) -> bytes:
    """Run xacro on ``path`` and return the expanded URDF as UTF-8 bytes.

    ``args`` are xacro args (``name:=value``), strings only. ``package_paths`` maps ROS package
    names to the directory ``$(find name)`` should give. ``display_path`` is how the top file is
    shown in error messages (default: ``path`` as given). The output is what the ``xacro`` command
    prints (including its "autogenerated by xacro from <abs path>" banner; strip it with
    ``urdf_loader.canonical_urdf_bytes`` before hashing).
    """
    shown = display_path if display_path is not None else str(path)
    mappings: dict[str, str] = {}
    for key, value in (args or {}).items():
        if not isinstance(key, str) or not isinstance(value, str):
            raise UrdfError(
                f"xacro arg {key!r} must be a string, got {type(value).__name__} {value!r}",
                file=shown, key="xacro_args",
                fix="quote the value in the vendor YAML (xacro args are strings)")
        mappings[key] = value
    packages: dict[str, str] = {}
    given: dict[str, str] = {}  # as the user wrote them, for messages
    for pkg, directory in (package_paths or {}).items():
        packages[str(pkg)] = os.path.normpath(os.path.abspath(os.fspath(directory)))
        given[str(pkg)] = os.fspath(directory)

    top_abs = os.path.normpath(os.path.abspath(os.fspath(path)))
    if not os.path.isfile(top_abs):
        what = "is a directory, not a xacro file" if os.path.isdir(top_abs) else "file not found"
        raise UrdfError(what, file=shown, fix="check the urdf: path in the vendor YAML")
    show = _Displayer(top_abs, shown, packages)

    try:
        import xacro
    except ImportError as e:  # pragma: no cover - xacro is a dependency
        raise UrdfError(f"cannot import xacro ({e})", file=shown,
                        fix="install rhi-gen with its dependencies (pip install xacro)") from None

    captured = io.StringIO()
    with _LOCK, _ament_index_stand_in(packages, given), _safe_loader_guard(), \
            contextlib.redirect_stderr(captured), _xacro_reads_bytes(xacro):
        _reset_xacro_state(xacro)
        try:
            doc = xacro.process_file(top_abs, mappings=mappings, verbosity=1)
            text: str = doc.toprettyxml(indent="  ")
            doc.unlink()
        except UrdfError:
            raise
        except Exception as e:  # noqa: BLE001 (xacro raises anything; every failure becomes one clear line)
            raise _convert(e, xacro, show, shown) from None
        finally:
            _reset_xacro_state(xacro)

    warnings = captured.getvalue().strip()
    if warnings:
        log.debug("xacro %s: %s", shown, warnings)
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as e:
        raise UrdfError(f"xacro produced text that is not valid Unicode ({e.reason})", file=shown,
                        fix="remove the offending character from the xacro") from None
