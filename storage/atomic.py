"""Write files whole or not at all.

Every file the storage layer writes (``dggs export``'s GeoJSON, ``dggs
plot``'s PNG, the demo's outputs) goes through :func:`atomic_write`: the
content is written to a temporary file in the same folder, flushed to disk,
and renamed over the target with :func:`os.replace`.  A full disk, a crash
or an error half-way leaves the old file (or none), never a truncated one.

Examples
--------
>>> import os, tempfile
>>> path = os.path.join(tempfile.mkdtemp(), "out.txt")
>>> with atomic_write(path) as fh:
...     _ = fh.write("whole")
>>> open(path).read()
'whole'
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

from dggs.errors import StorageError

__all__ = ["atomic_write", "atomic_path", "refuse_store", "remove_stale", "writer_error"]

#: The files of a SQLite store in WAL mode: the database, its log and its shared-memory index.
STORE_FILES = ("", "-wal", "-shm")

#: Free space below which a failed write is put down to a full disk (a writer's buffers, GDAL's included, are smaller).
FULL_DISK_BYTES = 1024 * 1024


def _same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` name one file: by inode if both exist, else by resolved path."""
    try:
        return os.path.samefile(a, b)  # follows symlinks; hard links too
    except OSError:
        return a.resolve() == b.resolve()


def refuse_store(target: str | os.PathLike[str], store: str | os.PathLike[str]) -> None:
    """Refuse to write ``target`` if it is the store file ``store`` or its ``-wal``/``-shm``.

    Compared by device and inode (:func:`os.path.samefile`), so a relative
    path, a symlink or a hard link to the store is caught; a ``-wal`` or
    ``-shm`` that does not exist yet is compared by its resolved path.

    Raises
    ------
    StorageError
        Naming ``target``, if writing it would overwrite the store.
    """
    if str(store) == ":memory:":
        return
    out = Path(target)
    for suffix in STORE_FILES:
        if _same_file(out, Path(str(store) + suffix)):
            raise StorageError(
                f"cannot write {target}: it is the store {store}{suffix} being read; "
                "choose another output file"
            )


def _mode_for(target: Path) -> int:
    """The permission bits ``target`` gets: its own if it exists, else 0o666 less the umask (as ``open``)."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        pass
    mask = os.umask(0o022)  # the only portable way to read the umask is to set it
    os.umask(mask)
    return 0o666 & ~mask


def _prefix(target: Path) -> str:
    """Temporary names: ``.NAME.PID-RANDOM.tmp``, so a later run can tell a dead writer's leftovers."""
    return f".{target.name}.{os.getpid()}-"


def _writer_alive(name: str, target: Path) -> bool:
    """Whether the temporary file ``name`` of ``target`` belongs to a running process."""
    middle = name[len(target.name) + 2 : -len(".tmp")]
    pid = middle.split("-", 1)[0]
    if "-" not in middle or not pid.isdigit():
        return False  # an older run's name (no pid): its writer has gone
    try:
        os.kill(int(pid), 0)
    except ProcessLookupError:
        return False
    except OSError:  # exists, owned by someone else
        return True
    return True


def remove_stale(target: str | os.PathLike[str]) -> list[str]:
    """Remove the temporary files (or folders) a killed writer of ``target`` left; return their names.

    Only names this module makes for ``target`` (``.NAME.*.tmp`` beside it)
    whose process is gone; a running writer's file is kept.
    """
    path = Path(target)
    folder = path.parent if str(path.parent) else Path(".")
    removed: list[str] = []
    try:
        names = os.listdir(folder)
    except OSError:
        return removed
    for name in names:
        if not (name.startswith(f".{path.name}.") and name.endswith(".tmp")) or _writer_alive(name, path):
            continue
        stale = folder / name
        with contextlib.suppress(OSError):
            if stale.is_dir() and not stale.is_symlink():
                shutil.rmtree(stale)
            else:
                stale.unlink()
            removed.append(name)
    return removed


def _free_bytes(folder: str | os.PathLike[str]) -> int | None:
    """The bytes an unprivileged writer may still use in ``folder``'s file system, or None if unknown."""
    try:
        vfs = os.statvfs(folder)
    except (OSError, AttributeError):  # AttributeError: no statvfs (Windows)
        return None
    return vfs.f_bavail * vfs.f_frsize


def writer_error(path: str | os.PathLike[str], tmp: str, exc: BaseException) -> StorageError:
    """The :class:`StorageError` for a library writer (GDAL through pyogrio) that failed on ``tmp``.

    Such writers report a full disk in their own words, without errno: on
    a full tmpfs GDAL 3.12.4 (pyogrio 0.13) says ``no such table:
    gpkg_contents`` for a GeoPackage and ``Unexpected I/O failure`` for a
    FlatGeobuf (pyogrio raises them as ``FeatureError``/``DataSourceError``).
    So the file system is asked: with less than :data:`FULL_DISK_BYTES`
    free, the message says what ``os.strerror(errno.ENOSPC)`` says, as the
    other formats' messages do; otherwise it gives the writer's words, with
    ``path`` in place of the temporary name.  Call it while ``tmp`` still
    exists (inside :func:`atomic_path`), so the space it took is counted.
    """
    free = _free_bytes(Path(tmp).parent)
    if free is not None and free < FULL_DISK_BYTES:
        reason = f"{os.strerror(errno.ENOSPC)} ({free:,} bytes free)"
    else:
        reason = " ".join(str(exc).replace(tmp, os.fspath(path)).split()) or type(exc).__name__
    return StorageError(
        f"cannot write {path}: {reason}; nothing was written (an existing file is unchanged): "
        "free space or choose another place"
    )


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str], suffix: str = "", keep_name: bool = False) -> Iterator[str]:
    """Yield a temporary path next to ``path``; rename it over ``path`` on success.

    For writers that want a file name (e.g. ``matplotlib.savefig``).  With
    ``keep_name`` the temporary file has ``path``'s own name, in a fresh
    hidden folder beside it (for writers such as GDAL that choose the format
    from the extension and refuse an existing empty file); the folder and
    anything the writer left in it are removed afterwards.  The file gets
    the mode an existing ``path`` has, else the one ``open`` would give it
    (0o666 less the umask), whatever mode the writer chose.  Temporary files
    of an earlier writer of ``path`` that was killed are removed first
    (:func:`remove_stale`).

    Raises
    ------
    StorageError
        Naming ``path``, if the file cannot be written (disk full, no
        permission...); the target is then untouched and no temporary file
        is left behind.
    """
    target = Path(path)
    folder = None
    remove_stale(target)
    try:
        mode = _mode_for(target)
        if keep_name:
            folder = tempfile.mkdtemp(prefix=_prefix(target), suffix=".tmp", dir=target.parent or ".")
            tmp = os.path.join(folder, target.name)
        else:
            fd, tmp = tempfile.mkstemp(prefix=_prefix(target), suffix=suffix + ".tmp", dir=target.parent or ".")
            os.close(fd)
    except OSError as exc:
        raise StorageError(f"cannot write {path}: {exc.strerror or exc}") from exc
    try:
        yield tmp
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
            os.fchmod(fh.fileno(), mode)
        os.replace(tmp, target)
    except OSError as exc:
        raise StorageError(
            f"cannot write {path}: {exc.strerror or exc}; nothing was written "
            "(an existing file is unchanged): free space or choose another place"
        ) from exc
    finally:
        if folder is not None:
            shutil.rmtree(folder, ignore_errors=True)
        else:
            with contextlib.suppress(OSError):
                os.unlink(tmp)


@contextlib.contextmanager
def atomic_write(path: str | os.PathLike[str], mode: str = "w", encoding: str | None = "utf-8") -> Iterator[IO[Any]]:
    """Open a temporary file for writing; it replaces ``path`` only when complete.

    ``mode`` is ``"w"`` (text, ``encoding``) or ``"wb"``.

    Raises
    ------
    StorageError
        As :func:`atomic_path`.
    """
    with atomic_path(path) as tmp:
        try:
            fh = open(tmp, mode, encoding=None if "b" in mode else encoding)  # noqa: SIM115
        except OSError as exc:
            raise StorageError(f"cannot write {path}: {exc.strerror or exc}") from exc
        with fh:
            yield fh
