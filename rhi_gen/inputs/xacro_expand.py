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
  knows it, or the line of the ``<xacro:include>`` that failed) and what to do, in the words of
  the command used (:mod:`.wording`: ``--xacro-arg``/``--package-path`` on the command line,
  ``xacro_args``/``package_paths`` in the vendor YAML). Files are shown by their real (expanded)
  path, never as ``$(find pkg)/...``, so the path in a message is the path that was tried.

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
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from lxml import etree

from ..errors import UrdfError
from .wording import YAML, Wording

__all__ = ["expand_xacro", "xacro_files"]

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
    """Shows files by their real path, the way the user names the top file: the top file as
    ``display_path``; any other file relative to the same base as ``display_path`` (so
    ``robots/acme/parts/leg.xacro`` next to ``robots/acme/arm.urdf.xacro``, a package folder in
    the project as ``pkgs/mypkg/urdf/leg.xacro``) unless that climbs out of the base, then absolute."""

    def __init__(self, top_abs: str, shown: str) -> None:
        self.top_abs = os.path.normpath(top_abs)
        self.top_dir = os.path.dirname(self.top_abs)
        self.shown = shown
        self.shown_dir = os.path.dirname(shown)

    def __call__(self, file: str | None) -> str:
        if not file:
            return self.shown
        path = os.path.normpath(os.path.abspath(file))
        if path == self.top_abs:
            return self.shown
        if os.path.isabs(self.shown):
            return path
        try:
            rel = os.path.relpath(path, self.top_dir)
        except ValueError:  # different drives (Windows)
            return path
        joined = os.path.normpath(os.path.join(self.shown_dir, rel))
        if joined == os.pardir or joined.startswith(os.pardir + os.sep):
            return path
        return joined.replace(os.sep, "/")


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


@dataclass(frozen=True)
class _Run:
    """What one expansion was asked to do: for messages about what went wrong."""
    shown: str                      # the top file as the user names it
    show: _Displayer
    wording: Wording
    args: Mapping[str, str]
    packages: Mapping[str, str]     # package -> absolute directory
    given: Mapping[str, str]        # package -> directory as the user wrote it


_SUBSTITUTION = re.compile(r"\$\((\w+)(?:\s+([^)\s]*))?\s*\)")


def _resolve_spec(spec: str, including_dir: str, run: _Run) -> str | None:
    """The path an include's ``filename`` names, for the substitutions rhi-gen can resolve
    (``$(find pkg)``, ``$(arg name)``, ``$(dirname)``); None when it holds anything else."""
    unresolved = False

    def substitute(m: re.Match[str]) -> str:
        nonlocal unresolved
        command, value = m.group(1), m.group(2) or ""
        if command == "find" and value in run.packages:
            return run.packages[value]
        if command == "arg" and value in run.args:
            return run.args[value]
        if command == "dirname":
            return including_dir
        unresolved = True
        return ""

    text = _SUBSTITUTION.sub(substitute, spec.strip())
    if unresolved or "$" in text:
        return None
    return os.path.normpath(text if os.path.isabs(text) else os.path.join(including_dir, text))


def _include_line(including: str, tried: str, run: _Run) -> int | None:
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
        if _resolve_spec(spec, base, run) == target:
            return line or None
    same_name = [line for line, spec in includes if spec.strip().endswith(os.path.basename(target))]
    if len(same_name) == 1 and same_name[0]:
        return same_name[0]
    return None


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


def _package_of(path: str, run: _Run) -> str | None:
    for pkg, directory in run.packages.items():
        if _is_under(path, directory) is not None:
            return pkg
    return None


def _cannot_open(cause: OSError, xacro: Any, run: _Run, current: str, macro_note: str) -> UrdfError:
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


def _convert(exc: Exception, xacro: Any, run: _Run) -> UrdfError:
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
        if isinstance(cause, _UnknownPackage):
            pkg = cause.package
            return UrdfError(
                f"$(find {pkg}): unknown package '{pkg}'{macro_note}", file=current,
                line=_text_line(current_abs, _find_texts(pkg)), fix=wording.package_path(pkg))
        if isinstance(cause, _BadPackageDir):
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
                return _cannot_open(cause, xacro, run, current, macro_note)
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


def _run_xacro(path: str | Path, args: Mapping[str, str] | None,
               package_paths: Mapping[str, str | Path] | None, display_path: str | None,
               wording: Wording) -> tuple[str, tuple[str, ...]]:
    """Expand ``path``: the document as text, and every file xacro read besides the top one."""
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
        raise UrdfError(what, file=shown, fix=f"check {wording.urdf_path}")
    run = _Run(shown, _Displayer(top_abs, shown), wording, mappings, packages, given)

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
            read = tuple(dict.fromkeys(os.path.normpath(os.path.abspath(f)) for f in xacro.all_includes))
        except UrdfError:
            raise
        except Exception as e:  # noqa: BLE001 (xacro raises anything; every failure becomes one clear line)
            raise _convert(e, xacro, run) from None
        finally:
            _reset_xacro_state(xacro)

    warnings = captured.getvalue().strip()
    if warnings:
        log.debug("xacro %s: %s", shown, warnings)
    return text, read


def expand_xacro(path: str | Path, args: Mapping[str, str] | None,
                 package_paths: Mapping[str, str | Path] | None, *,
                 display_path: str | None = None, wording: Wording = YAML) -> bytes:
    """Run xacro on ``path`` and return the expanded URDF as UTF-8 bytes.

    ``args`` are xacro args (``name:=value``), strings only. ``package_paths`` maps ROS package
    names to the directory ``$(find name)`` should give. ``display_path`` is how the top file is
    shown in error messages (default: ``path`` as given); ``wording`` whether a fix names vendor
    YAML keys (the default) or command-line options. The output is what the ``xacro`` command
    prints (including its "autogenerated by xacro from <abs path>" banner; strip it with
    ``urdf_loader.canonical_urdf_bytes`` before hashing).
    """
    text, _ = _run_xacro(path, args, package_paths, display_path, wording)
    return _utf8(text, display_path if display_path is not None else str(path))


def xacro_files(path: str | Path, args: Mapping[str, str] | None,
                package_paths: Mapping[str, str | Path] | None, *,
                display_path: str | None = None, wording: Wording = YAML) -> tuple[Path, ...]:
    """Every file an expansion of ``path`` reads besides ``path`` itself (``<xacro:include>`` files
    and ``xacro.load_yaml`` files), absolute, in the order xacro first read them."""
    _, read = _run_xacro(path, args, package_paths, display_path, wording)
    return tuple(Path(f) for f in read)


def _utf8(text: str, shown: str) -> bytes:
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as e:
        raise UrdfError(f"xacro produced text that is not valid Unicode ({e.reason})", file=shown,
                        fix="remove the offending character from the xacro") from None
