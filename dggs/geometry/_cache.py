"""The compiled cache: where numba keeps the kernels' machine code, keyed by the sources they inline.

Numba's own cache (``njit(cache=True)``) checks only the file of each function:
a kernel in ``dggs/index/_kernel/points.py`` that inlined ``dggs/geometry/kernel.py``
kept running the old code after an edit of ``kernel.py``.  It also raises at
decoration (``cannot cache function ...: no locator available``) when no
directory is writable, and a damaged ``.nbi``/``.nbc`` file raised
``UnpicklingError`` on every later run.  Its :func:`install`, called by
:mod:`dggs.geometry._parallel` before any kernel is decorated, gives every
``njit(cache=True)`` function of the package (``dggs.*``) its own cache:

- the directory is named by a hash of every compiled source (``dggs/geometry/*.py``,
  its ``*.npz`` tables and ``dggs/index/_kernel/*.py``), so any edit starts a new cache;
- the first writable of: ``NUMBA_CACHE_DIR/dggs-<hash>``, the package's
  ``__pycache__/numba-<hash>``, the user cache directory, a private temporary
  directory (one :class:`CacheWarning`), else no cache at all (one warning);
  a read-only package's shipped cache seeds the user or temporary one;
- an entry that fails to load, or holds another function, is deleted and compiled again.

Numba picks a cache per dispatcher in ``Dispatcher.enable_caching`` (numba/core/dispatcher.py);
:func:`install` wraps that method for the package's functions only.
"""

from __future__ import annotations

import functools
import glob
import hashlib
import importlib.util
import os
import shutil
import tempfile
import warnings
from pathlib import Path
from typing import Any

from numba.core import config, dispatcher
from numba.core.caching import (
    CompileResultCacheImpl,
    FunctionCache,
    NullCache,
    _CacheLocator,
    _SourceFileBackedLocatorMixin,
)
from numba.misc.appdirs import AppDirs

__all__ = ["CacheWarning", "cache_dirs", "install", "sources_hash"]

_PACKAGE = "dggs."
_warned = False


class CacheWarning(UserWarning):
    """The compiled kernels are cached in a temporary directory, or not at all."""


def _warn_once(message: str) -> None:
    global _warned
    if not _warned:
        _warned = True
        warnings.warn(message, CacheWarning, stacklevel=3)


def _source_dirs() -> list[Path]:
    spec = importlib.util.find_spec("dggs.index._kernel")
    kernel = [Path(p) for p in (spec.submodule_search_locations or [])] if spec else []
    return [Path(__file__).resolve().parent, *kernel]


@functools.lru_cache(maxsize=1)
def sources_hash() -> str:
    """Hash of every compiled source of the package, naming its cache directory.

    Returns
    -------
    str
        16 hex digits of the SHA-256 of the names and bytes of ``dggs/geometry/*.py``,
        ``dggs/geometry/*.npz`` and ``dggs/index/_kernel/*.py``.

    Raises
    ------
    OSError
        If a source file cannot be read.
    """
    digest = hashlib.sha256()
    for folder in _source_dirs():
        for path in sorted([*folder.glob("*.py"), *folder.glob("*.npz")]):
            digest.update(f"{folder.name}/{path.name}\0".encode())
            digest.update(path.read_bytes())
            digest.update(b"\0")
    return digest.hexdigest()[:16]


def _private_temp() -> Path | None:
    """``<tmp>/dggs-numba-<uid>``, made 0700; None if it exists and is not ours alone."""
    uid = os.getuid() if hasattr(os, "getuid") else None
    root = Path(tempfile.gettempdir()) / f"dggs-numba-{uid if uid is not None else 'user'}"
    try:
        root.mkdir(mode=0o700, exist_ok=True)
        st = root.lstat()
    except OSError:
        return None
    # a cache entry is a pickle: a directory someone else can write could run their code (CWE-377)
    if not root.is_dir() or root.is_symlink() or (uid is not None and st.st_uid != uid) or st.st_mode & 0o022:
        return None
    return root


def cache_dirs(py_file: str) -> list[tuple[str, Path]]:
    """The directories tried, in order, for the compiled code of the functions in ``py_file``.

    Parameters
    ----------
    py_file : str
        A source file of the package.

    Returns
    -------
    list of (str, Path)
        ``(kind, directory)``, kind one of ``"user-set"``, ``"in-tree"``, ``"user"``, ``"temp"``.

    Raises
    ------
    OSError
        If the package's sources cannot be read.
    """
    folder = Path(py_file).resolve().parent
    tag = sources_hash()
    dirs = []
    user_set = getattr(config, "CACHE_DIR", "")  # NUMBA_CACHE_DIR
    if user_set:
        dirs.append(("user-set", Path(user_set) / f"dggs-{tag}" / folder.name))
    dirs.append(("in-tree", folder / "__pycache__" / f"numba-{tag}"))
    dirs.append(("user", Path(AppDirs(appname="numba", appauthor=False).user_cache_dir) / f"dggs-{tag}" / folder.name))
    temp = _private_temp()
    if temp is not None:
        dirs.append(("temp", temp / tag / folder.name))
    return dirs


def _seed(shipped: Path, target: Path) -> None:
    """Copy a read-only shipped cache into a new writable one (entries already there are kept)."""
    if not shipped.is_dir():
        return
    for entry in shipped.iterdir():
        if entry.suffix in (".nbi", ".nbc") and not (target / entry.name).exists():
            try:
                shutil.copyfile(entry, target / entry.name)
            except OSError:
                return


class _Locator(_SourceFileBackedLocatorMixin, _CacheLocator):  # type: ignore[misc]
    """The first writable directory of :func:`cache_dirs`; the stamp is numba's hash of the file."""

    def __init__(self, py_func: Any, py_file: str, path: Path) -> None:
        self._py_file = py_file
        self._lineno = py_func.__code__.co_firstlineno
        self._cache_path = str(path)

    def get_cache_path(self) -> str:
        return self._cache_path

    @classmethod
    def from_function(cls, py_func: Any, py_file: str) -> _Locator | None:
        if not os.path.exists(py_file):
            return None
        dirs = cache_dirs(py_file)
        shipped = dict(dirs)["in-tree"]
        for kind, path in dirs:
            self = cls(py_func, py_file, path)
            try:
                self.ensure_cache_path()
            except OSError:
                continue
            if kind in ("user", "temp"):
                _seed(shipped, path)
            if kind == "temp":
                _warn_once(f"no writable cache directory for dggs's compiled kernels: caching them in {path}")
            return self
        return None


class _Impl(CompileResultCacheImpl):  # type: ignore[misc]
    _locator_classes: list[Any] = [_Locator]


class _Cache(FunctionCache):  # type: ignore[misc]
    """numba's function cache, which deletes and recompiles an entry it cannot load."""

    _impl_class = _Impl

    def _load_overload(self, sig: Any, target_context: Any) -> Any:
        # numba's Cache._load_overload, with the checks numba leaves out: a file may be damaged or swapped
        if not self._enabled:
            return None
        try:
            key = self._index_key(sig, target_context.codegen())
            data = self._cache_file.load(key)
            if data is None:
                return None
            fndesc, signature = data[1], data[3]
            func = self._py_func
            if (fndesc.modname, fndesc.qualname) != (func.__module__, func.__qualname__) or (
                isinstance(sig, tuple) and tuple(signature.args) != sig
            ):
                raise ValueError(f"cache entry of {fndesc.qualname}{signature} found for {func.__qualname__}{sig}")
            return self._impl.rebuild(target_context, data)
        except Exception:  # any damage: drop the entry, compile again
            self._discard()
            return None

    def save_overload(self, sig: Any, data: Any) -> None:
        try:
            super().save_overload(sig, data)
        except OSError as exc:  # the directory went read-only or full: the code compiled is still good
            self.disable()
            _warn_once(f"cannot save dggs's compiled kernels in {self._cache_path} ({exc}); compiling without a cache")
        except Exception:  # a damaged index met while saving: drop it, save next time
            self._discard()

    def _discard(self) -> None:
        base = glob.escape(os.path.join(self._cache_path, self._impl.filename_base))
        for path in glob.glob(base + ".nbi") + glob.glob(base + ".*.nbc"):
            try:
                os.unlink(path)
            except OSError:
                pass


_numba_enable_caching = dispatcher.Dispatcher.enable_caching


def _enable_caching(self: Any) -> None:
    if not str(getattr(self.py_func, "__module__", "")).startswith(_PACKAGE):
        _numba_enable_caching(self)
        return
    try:
        self._cache = _Cache(self.py_func)
    except (RuntimeError, OSError) as exc:  # no writable directory anywhere
        _warn_once(f"dggs's compiled kernels are not cached ({exc})")
        self._cache = NullCache()


def install() -> None:
    """Give every ``njit(cache=True)`` function of ``dggs`` decorated from now on the cache above.

    Notes
    -----
    Raises nothing; functions outside ``dggs`` keep numba's own cache.
    """
    dispatcher.Dispatcher.enable_caching = _enable_caching  # type: ignore[method-assign]
