"""Where numba caches the compiled functions of a registered source folder: a user cache folder, never the package.

numba's on-disk cache keys a compiled function on its own file only, so editing a function in one module would
leave stale machine code in the cache of every caller in another. A registered folder's functions are therefore
cached in ``<user cache>/alightsize/numba-<numba version>/<folder name>-<hash of its path>/<digest of its sources>``
(the user cache of platformdirs, e.g. ~/.cache on Linux), so different sources never share a folder; when numba
first saves a function for new sources, the caches of that folder's other sources that nothing has written to for
STALE seconds are removed (a run of other sources, e.g. one started before the checkout was edited, may still be
compiling into its own: removing that under it broke its compile). Nothing is written when a module is imported:
numba creates the folder when it saves its first compiled function. A NUMBA_CACHE_DIR set by the user (numba's
`config.CACHE_DIR`) wins: numba then caches everything there as it documents.

The redirection is a numba cache locator placed first in numba's list (numba internals, bound by the numba
versions in pyproject.toml); it answers only for the registered folders, so other numba users in the process are
left alone.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import time
from functools import cache
from pathlib import Path
from typing import Any

import numba
from numba.core import caching as _caching
from numba.core import config as _config
from platformdirs import user_cache_dir

_FOLDERS: set[Path] = set()
STALE = 86400.0     # s: a cache of other sources idle this long is removed (no run compiles for a day)


def _numba_class(name: str) -> Any:
    """A class of numba's caching module (earlier numba versions spell it with a leading underscore)."""
    return getattr(_caching, name, None) or getattr(_caching, f"_{name}")


_UserProvided: Any = _numba_class("UserProvidedCacheLocator")
_Impl: Any = _numba_class("CacheImpl")


def cache_root() -> Path:
    """The folder holding every registered folder's cache (for this numba version)."""
    return Path(user_cache_dir("alightsize")) / f"numba-{numba.__version__}"


@cache
def cache_dir(folder: Path) -> Path:
    """The cache folder of the functions defined in `folder`'s modules, for its present sources."""
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in sorted(folder.glob("*.py")))).hexdigest()[:16]
    checkout = hashlib.sha256(str(folder).encode()).hexdigest()[:12]
    return cache_root() / f"{folder.name}-{checkout}" / digest


def _last_written(folder: Path) -> float:
    """The latest modification time (s since the epoch) of `folder` and what it holds (0 if it is gone)."""
    try:
        times = [folder.stat().st_mtime]
        for p in folder.rglob("*"):
            try:
                times.append(p.stat().st_mtime)
            except OSError:                                # removed meanwhile
                pass
        return max(times)
    except OSError:
        return 0.0


def prune(path: Path, now: float) -> None:
    """Remove the caches beside `path` (its folder's other sources) that nothing has written to since now - STALE;
    never `path` itself."""
    for old in path.parent.glob("*"):
        if old != path and now - _last_written(old) > STALE:
            shutil.rmtree(old, ignore_errors=True)


def _writable(path: Path) -> bool:
    """Whether `path` exists writable or could be created (its nearest existing parent is writable)."""
    while not path.exists():
        if path.parent == path:
            return False
        path = path.parent
    return os.access(path, os.W_OK | os.X_OK)


class _Locator(_UserProvided):
    """numba cache locator for the functions of a registered folder."""

    def __init__(self, py_func, py_file: str, path: Path):
        self._py_file = py_file
        self._lineno = py_func.__code__.co_firstlineno
        self._cache_path = str(path)

    @classmethod
    def from_function(cls, py_func, py_file: str):
        if getattr(_config, "CACHE_DIR", None) or not os.path.exists(py_file):     # set at run time by numba
            return None
        folder = Path(py_file).resolve().parent
        if folder not in _FOLDERS:
            return None
        path = cache_dir(folder)
        return cls(py_func, py_file, path) if _writable(path) else None   # else numba's own locations

    def ensure_cache_path(self) -> None:
        path = Path(self._cache_path)
        if not path.is_dir():
            prune(path, time.time())
        super().ensure_cache_path()


def register(module_file: str) -> None:
    """Cache the numba functions of the modules in `module_file`'s folder in the user cache folder. Call it before
    the first `@njit(cache=True)` of those modules runs (numba picks a function's cache folder when decorating)."""
    _FOLDERS.add(Path(module_file).resolve().parent)
    if _Locator not in _Impl._locator_classes:
        _Impl._locator_classes.insert(0, _Locator)
