"""The projection a store's cells were binned with: ``meta.projection``, ISEA or IVEA.

The same cell id names a place on :class:`dggs.Grid` ("ISEA") and another up to
56 km away on ``Grid("IVEA")`` (docs/grid.md, "The IVEA projection"), so a store
records which grid located its points and every later reader draws and
queries its cells with that grid.  Files written before the key existed, and
stores created without ``projection=``, are ISEA.

The projection is fixed when the store is created (or, for a store that holds
no cells yet, when it is first opened with ``projection=``).  Opening a store
with an explicit projection other than the recorded one is a
:class:`dggs.StorageError` naming both.

Examples
--------
>>> import dggs
>>> from dggs.storage import CellStore
>>> with CellStore(":memory:", projection="ivea") as store:
...     store.projection, store.grid
('IVEA', Grid('IVEA'))
>>> with CellStore(":memory:") as store:
...     store.projection
'ISEA'
"""

from __future__ import annotations

import sqlite3
from typing import Any

from dggs.errors import DggsValueError, StorageError

__all__ = ["DEFAULT_PROJECTION", "check_projection", "grid_locate", "recorded", "settle"]

#: The projection of a store that records none (all stores before ``meta.projection`` existed).
DEFAULT_PROJECTION = "ISEA"


def check_projection(projection: Any) -> str:
    """The projection's canonical name, ``"ISEA"`` or ``"IVEA"`` (case-insensitive).

    Raises
    ------
    DggsValueError
        Naming the value, if it is not one of the two.

    Examples
    --------
    >>> check_projection("ivea")
    'IVEA'
    """
    from dggs.index.projection import PROJECTIONS

    name = projection.upper() if isinstance(projection, str) else projection
    if name not in PROJECTIONS:
        raise DggsValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")
    return str(name)


def recorded(conn: sqlite3.Connection, path: str) -> str:
    """The projection ``meta`` records (``ISEA`` when it records none).

    Raises
    ------
    StorageError
        Naming the file and the value, if ``meta.projection`` is not a projection (a damaged file).
    """
    row = conn.execute("SELECT value FROM meta WHERE key = 'projection'").fetchone()
    if row is None:
        return DEFAULT_PROJECTION
    try:
        return check_projection(row[0])
    except DggsValueError:
        raise StorageError(
            f"{path} is damaged: meta.projection is {row[0]!r}, not ISEA or IVEA; restore it from a backup"
        ) from None


def settle(conn: sqlite3.Connection, path: str, requested: Any, readonly: bool) -> str:
    """The store's projection: the recorded one, checked against ``requested`` (None: take the file's).

    A writable store that holds no cells and records no projection takes ``requested`` (written to
    ``meta`` at once, so that two writers creating one store agree or the second one fails).

    Raises
    ------
    DggsValueError
        If ``requested`` is not a projection.
    StorageError
        If ``requested`` differs from the projection the file records, naming both.
    """
    want = None if requested is None else check_projection(requested)
    have = recorded(conn, path)
    if want is None or want == have:
        return have
    explicit = conn.execute("SELECT 1 FROM meta WHERE key = 'projection'").fetchone() is not None
    empty = conn.execute("SELECT 1 FROM meta WHERE key = 'level'").fetchone() is None
    if not explicit and empty and not readonly:
        conn.execute("INSERT OR IGNORE INTO meta (key, value) VALUES ('projection', ?)", (want,))  # autocommit
        have = recorded(conn, path)  # another writer may have recorded its own first
        if have == want:
            return have
    raise StorageError(
        f"{path} holds cells binned on {have}, but projection={want!r} was asked for; open it with "
        f"projection={have!r} (or none), or ingest into a new store created with projection={want!r}"
    )


def grid_locate(projection: str) -> Any:
    """The function that bins points on ``projection``: ``dggs.Grid(projection).latlng_to_cell``.

    Examples
    --------
    >>> import dggs
    >>> grid_locate("IVEA")(45.0, 10.0, 3) == dggs.Grid("IVEA").latlng_to_cell(45.0, 10.0, 3)
    True
    """
    import dggs

    return dggs.Grid(projection).latlng_to_cell
