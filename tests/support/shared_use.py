"""Which tests read the project's shared vendor data (../shared/upstream), found while they run.

A fresh clone has no ../shared beside it. tests/cli/test_fresh_clone.py re-runs, in a clone, the tests whose
outcome can differ there: those that read the shared folder, directly or through something derived from it
(the AimDK headers rosidl generates from it), and the quick tier. Every other test of the C++ tier builds
from the clone's own files, which are the session's byte for byte, into objects whose keys hash their
contents: running it again there would repeat the same compiles and runs.

What counts as reading, for the test (or fixture) running at that moment:
* the interpreter's audit events "open", "os.listdir" and "os.scandir" (glob, iterdir, walk) of a path
  under a watched root, and "subprocess.Popen" with such a path in its arguments or working folder (a
  compiler's -I, a generator's job);
* os.stat of such a path (exists, is_file, is_dir: a test that skips because a file is missing reads it too);
* a cached value computed while one of those happened (``cached``, ``Recorded``): each later use counts.
A fixture's reads count for every test that uses it (tests/conftest.py).
"""
from __future__ import annotations

import functools
import os
import sys
import threading
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any, TypeVar

T = TypeVar("T")
V = TypeVar("V")

_roots: list[str] = []
_local = threading.local()
_main_stack: list[set[str]] = []   # the pytest thread's contexts; worker threads without their own add here
_lock = threading.Lock()
_installed = False


def watch(root: Path) -> None:
    """Count reads under ``root`` from now on (the shared folder; a folder generated from it)."""
    text = os.path.normpath(os.path.abspath(root))
    with _lock:
        if text not in _roots:
            _roots.append(text)


def unwatch(root: Path) -> None:
    text = os.path.normpath(os.path.abspath(root))
    with _lock:
        if text in _roots:
            _roots.remove(text)


def _text(value: object) -> str | None:
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if isinstance(value, bytes):
        value = value.decode(errors="replace")
    return value if isinstance(value, str) and value else None


def path_root(path: object) -> str | None:
    """The watched root a file path is under (or is), else None."""
    text = _text(path)
    if text is None:
        return None
    full = os.path.normpath(os.path.abspath(text))
    return next((r for r in _roots if full == r or full.startswith(r + os.sep)), None)


def argument_root(argument: object) -> str | None:
    """The watched root a command-line argument names (a path, -I<path>, a JSON job holding one), else None."""
    text = _text(argument)
    if text is None:
        return None
    return next((r for r in _roots if r in text), None) or path_root(text)


def _stack() -> list[set[str]]:
    stack = getattr(_local, "stack", None)
    return stack if stack else _main_stack


def note(root: str) -> None:
    """Record a read under ``root`` in the innermost recording of this thread (or of the pytest thread)."""
    stack = _stack()
    if stack:
        stack[-1].add(root)


@contextmanager
def recording(main: bool = False) -> Iterator[set[str]]:
    """Collect the roots read inside the block (this thread; ``main``: the pytest thread's own stack, which
    worker threads without a recording of their own report to)."""
    used: set[str] = set()
    if main:
        stack = _main_stack
    else:
        if not hasattr(_local, "stack"):
            _local.stack = []
        stack = _local.stack
    stack.append(used)
    try:
        yield used
    finally:
        stack.pop()


def replay(used: set[str]) -> None:
    for root in used:
        note(root)


def cached(fn: Callable[..., T]) -> Callable[..., T]:
    """functools.cache that remembers whether computing a value read a watched root, and says so on each use."""
    results: dict[Any, tuple[T, set[str]]] = {}

    @functools.wraps(fn)
    def wrapper(*args: Any) -> T:
        with _lock:
            hit = results.get(args)
        if hit is None:
            with recording() as used:
                value = fn(*args)
            hit = (value, set(used))
            with _lock:
                results.setdefault(args, hit)
        replay(hit[1])
        return hit[0]

    return wrapper


class Recorded(Mapping[Any, V]):
    """A fixture's per-item results, each with the roots its computation read: looking one up counts them for
    the test that does, so one robot's reads do not count for every test of the fixture."""

    def __init__(self, items: dict[Any, tuple[V, set[str]]]) -> None:
        self._items = items

    def __getitem__(self, key: Any) -> V:
        value, used = self._items[key]
        replay(used)
        return value

    def __contains__(self, key: object) -> bool:
        """Whether there is a result for ``key``: not a use of it (Mapping's own would look the value up)."""
        return key in self._items

    def __iter__(self) -> Iterator[Any]:
        return iter(self._items)

    def __len__(self) -> int:
        return len(self._items)

    def used(self, key: Any) -> set[str]:
        return self._items[key][1]

    def quietly(self, key: Any) -> V:
        """The value without counting its reads (for a fixture that passes them on with ``used``)."""
        return self._items[key][0]


def _audit(event: str, args: tuple[Any, ...]) -> None:
    if not _roots:
        return
    if event in ("open", "os.listdir", "os.scandir"):
        root = path_root(args[0]) if args else None
    elif event == "subprocess.Popen":
        _, argv, cwd, _ = args
        parts = [argv] if isinstance(argv, (str, bytes, os.PathLike)) else list(argv or ())
        root = next((r for r in map(argument_root, [*parts, cwd]) if r), None)
    else:
        return
    if root:
        note(root)


_real_stat = os.stat


def _stat(path: Any, *args: Any, **kwargs: Any) -> os.stat_result:
    if _roots and not isinstance(path, int):
        root = path_root(path)
        if root:
            note(root)
    return _real_stat(path, *args, **kwargs)


def install() -> None:
    """Start watching (once per process): the audit hook cannot be removed, so it stays cheap when idle."""
    global _installed
    if _installed:
        return
    _installed = True
    sys.addaudithook(_audit)
    os.stat = _stat  # pathlib and os.path look os.stat up on each call
