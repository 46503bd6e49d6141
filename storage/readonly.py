"""Opening a store read-only: immutable when no writer has it open, a WAL reader beside a writer.

A reader of a WAL-mode database with ``?mode=ro`` creates its
``-wal`` and ``-shm`` files beside it (and leaves them there: a read-only
connection may not delete them).  So a read-only open of a store that no
writer has open (no ``-wal`` or ``-shm`` file beside it) uses
``?mode=ro&immutable=1``, which touches nothing (SQLite's URI documentation,
https://www.sqlite.org/uri.html, "immutable").  An immutable reader takes no
locks and trusts its page cache, so :attr:`Connection.conn` checks before
each read whether a writer has appeared (:meth:`Connection.behind`) and then
opens the store again, as a WAL reader beside the writer's ``-wal`` (whose side
files the writer has made already): consistent while the ingest writes.  The
file's identity, size and modification time (:meth:`Connection.stale`) are
checked after each read too: a file changed during an immutable read is a
:class:`StorageError` naming it ("read again"), never a mixed answer.

Read-only media: a WAL-mode database with side files needs its ``-shm`` file,
which SQLite cannot create in a folder it may not write.  ``readonly=True``
then opens the file immutable as well (nothing can change it anyway), unless a
non-empty ``-wal`` file is there: its rows would be invisible, so that is a
:class:`StorageError` instead of a wrong answer.
"""

from __future__ import annotations

import os
import sqlite3
from pathlib import Path

from dggs.errors import StorageError

from .scoped import ScopedConnection

__all__ = ["connect", "connect_immutable", "quiet", "signature"]


def _writable(path: Path) -> bool:
    folder = path.parent if str(path.parent) else Path(".")
    return os.access(folder, os.W_OK) and (not path.exists() or os.access(path, os.W_OK))


def signature(file: Path) -> tuple[int, int, int, int]:
    """What changes when the file is written, replaced or truncated: device, inode, size, mtime."""
    st = file.stat()
    return (st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns)


def quiet(file: Path) -> bool:
    """No writer has the store open: neither its ``-wal`` nor its ``-shm`` file exists."""
    return not any(Path(f"{file}{tail}").exists() for tail in ("-wal", "-shm"))


def connect(path: str, readonly: bool, timeout: float, check_same_thread: bool = True) -> tuple[sqlite3.Connection, bool]:
    """Open the SQLite connection and say whether it is immutable (read-only and quiet, or read-only media).

    See the module doc.  ``check_same_thread`` is sqlite3's: False lets a pool hand the
    connection to one thread after another (never to two at once).

    Raises
    ------
    StorageError
        On read-only media with a non-empty ``-wal`` file (:func:`connect_immutable`).
    sqlite3.Error
        If SQLite cannot open the file (the caller translates it, naming the file).
    """
    if path == ":memory:" or not readonly:
        return sqlite3.connect(path, isolation_level=None, timeout=timeout, check_same_thread=check_same_thread,
                           factory=ScopedConnection), False
    file = Path(path).resolve()
    if quiet(file):
        return connect_immutable(file, timeout, check_same_thread), True
    uri = file.as_uri() + "?mode=ro"
    conn = sqlite3.connect(uri, uri=True, isolation_level=None, timeout=timeout, check_same_thread=check_same_thread,
                           factory=ScopedConnection)
    try:
        conn.execute("SELECT count(*) FROM sqlite_master").fetchone()
        return conn, False
    except sqlite3.OperationalError:
        conn.close()
        if _writable(file):
            raise
    except BaseException:
        conn.close()
        raise
    return connect_immutable(file, timeout, check_same_thread), True


def connect_immutable(file: Path, timeout: float = 30.0, check_same_thread: bool = True) -> sqlite3.Connection:
    """Open a store on read-only media with ``?mode=ro&immutable=1``.

    Raises
    ------
    StorageError
        If a non-empty ``-wal`` file holds committed rows that an immutable
        reader would not see.
    """
    wal = Path(str(file) + "-wal")
    if wal.exists() and wal.stat().st_size > 0:
        raise StorageError(
            f"{file} is on read-only media with an unmerged write-ahead log ({wal.name}); "
            "its latest rows cannot be read there: copy the store and its -wal file to a writable folder"
        )
    uri = file.as_uri() + "?mode=ro&immutable=1"
    return sqlite3.connect(uri, uri=True, isolation_level=None, timeout=timeout, check_same_thread=check_same_thread,
                           factory=ScopedConnection)
