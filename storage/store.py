"""`CellStore`: points binned into equal-area cells, in one SQLite file.

A thin facade: the connection and its transactions live in
:mod:`~dggs.storage.connection`, ingest in :mod:`~dggs.storage.inputs` and
:mod:`~dggs.storage.ingest`, queries in :mod:`~dggs.storage.queries`.
Every public method turns raw SQLite and operating-system errors into a
:class:`dggs.StorageError` naming the file (:func:`~dggs.storage.connection.guarded`).

Examples
--------
>>> import dggs
>>> from dggs.storage import CellStore
>>> with CellStore(":memory:") as store:
...     result = store.ingest_points([48.85, 48.86, -33.9], [2.35, 2.34, 151.2], level=6,
...                                  values={"pop": [10, 20, 5]})
...     paris = dggs.latlng_to_cell(48.85, 2.35, 2)
...     store.count(), store.count(paris), store.count([paris, dggs.str_to_int(paris)])
(3, 2, 2)
"""

from __future__ import annotations

import os
import sqlite3
from collections.abc import Sequence
from typing import Any

import dggs
from dggs.errors import DggsValueError

from . import queries, rollup_query
from .connection import DEFAULT_LEVEL, Connection, guarded
from .ingest import MERGE_ROWS
from .progress import Bar, Progress
from .projection import ProjectionMethods, settle
from .queries import STATS
from .sources import delete_source, list_rejects, list_sources
from .store_export import ExportMethods
from .store_ingest import IngestMethods
from .store_raster import RasterMethods
from .store_rollups import RollupMethods

__all__ = ["CellStore", "STATS", "DEFAULT_LEVEL"]


class CellStore(IngestMethods, RasterMethods, ExportMethods, RollupMethods, ProjectionMethods):
    """Points binned into cells at one level, stored in SQLite.

    Parameters
    ----------
    path : str or Path
        The database file; ``":memory:"`` for a throwaway store.  A missing
        file is created (unless ``create=False``), an empty SQLite file gets
        the schema.
    create : bool, default True
        Create the file if it does not exist.
    readonly : bool, default False
        Open read-only (queries only).  Works on read-only media too (see
        ``docs/storage.md``).
    timeout : float, default 30
        Seconds to wait for a lock held by another connection.
    merge_rows : int, default 250000
        Pending rows that trigger a merge into the clustered table during
        ingest (or a quarter of the rows already merged, if more).
    projection : {"ISEA", "IVEA"}, optional
        The grid whose cells the points are binned into (:class:`dggs.Grid`),
        recorded in the file when it is created.  None (the default): the
        file's own (ISEA for a new store and for files that record none).
    check_same_thread : bool, default True
        sqlite3's; False: a pool lends it to one thread after another (dggs/server/pool.py).

    Raises
    ------
    StorageError
        Naming the file, if it is not a SQLite database, not a cell store, or
        missing with ``create=False``; naming both projections, if
        ``projection`` differs from the one the file records.

    Examples
    --------
    >>> with CellStore(":memory:") as store:
    ...     store.level is None
    True
    """

    def __init__(
        self,
        path: str | os.PathLike[str] = ":memory:",
        *,
        create: bool = True,
        readonly: bool = False,
        timeout: float = 30.0,
        merge_rows: int = MERGE_ROWS,
        projection: str | None = None,
        check_same_thread: bool = True,
    ) -> None:
        if isinstance(merge_rows, bool) or not isinstance(merge_rows, int) or merge_rows < 1:
            raise DggsValueError(f"merge_rows must be a whole number >= 1, not {merge_rows!r}")
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) or not timeout >= 0:
            raise DggsValueError(f"timeout must be a number of seconds >= 0, not {timeout!r}")
        self.path = str(path)
        self.merge_rows = merge_rows
        self.readonly = readonly
        self.timeout = float(timeout)
        self._store = Connection(self.path, create=create, readonly=readonly, timeout=self.timeout,
                                 check_same_thread=bool(check_same_thread))
        try:
            self._store.projection = settle(self._store.conn, self.path, projection, readonly)
        except BaseException:
            self._store.close()
            raise

    @property
    def conn(self) -> sqlite3.Connection:
        """The store's SQLite connection (a read-only store's, opened again when a writer appeared)."""
        return self._store.conn

    @property
    def db(self) -> Any:
        """The store as a :class:`sqlite_utils.Database`, for ad-hoc queries (``store.db.query(sql)``)."""
        return self._store.db

    # -- life cycle ---------------------------------------------------------

    def close(self) -> None:
        """Close the connection (the store is unusable afterwards)."""
        self._store.close()

    def __enter__(self) -> CellStore:
        return self

    def __exit__(self, error: object, *exc: object) -> None:
        self._store.close(discard_unused=error is not None)  # a failed first ingest leaves no empty file

    def __repr__(self) -> str:
        return f"<CellStore {self.path} level={self.level}>"

    # -- metadata -----------------------------------------------------------

    @property
    @guarded
    def meta(self) -> dict[str, str]:
        """The ``meta`` table as a dict (schema_version, dggs_version, level, crs...)."""
        return self._store.meta

    @property
    @guarded
    def level(self) -> int | None:
        """The stored level, or None before the first ingest (StorageError if ``meta`` is damaged)."""
        return self._store.level

    @property
    @guarded
    def columns(self) -> dict[str, str]:
        """Value columns and their SQL types, e.g. ``{"population": "INTEGER"}``."""
        return self._store.columns

    @guarded
    def delete_source(self, source: int | str) -> int:
        """Delete a source (by id or name) with all its rows and rejects.

        Returns
        -------
        int
            The number of rows deleted.

        Raises
        ------
        StorageError
            If there is no such source.
        """
        return delete_source(self._store, source)

    @guarded
    def sources(self) -> list[dict[str, Any]]:
        """List the ingested sources with their progress, oldest first."""
        return list_sources(self._store)

    @guarded
    def rejects(self, limit: int | None = None) -> list[dict[str, Any]]:
        """Rows refused by ``on_error="skip"``, with source name, row, line, column, value, reason."""
        return list_rejects(self._store, limit)

    @guarded
    def check(self) -> None:
        """Run SQLite's ``PRAGMA integrity_check`` on the whole file.

        Raises
        ------
        StorageError
            Naming the file and the first problems, unless it passes.

        Examples
        --------
        >>> with CellStore() as store:
        ...     store.check()
        """
        self._store.check()

    # -- queries ------------------------------------------------------------

    @guarded
    def count(self, cell: Any = None) -> int:
        """Count stored rows, all of them or those in ``cell`` (at any level).

        Raises
        ------
        InvalidCellError, LevelMismatchError
            For a bad cell or one finer than the stored level.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.0], [2.0, 2.0], 3)
        ...     store.count(), store.count(dggs.latlng_to_cell(1.0, 2.0, 0))
        (2, 2)
        """
        return queries.count(self._store, cell)

    @guarded
    def get(self, cell: Any) -> list[dict[str, Any]]:
        """Return the rows stored in one cell at the stored level.

        Raises
        ------
        LevelMismatchError
            If ``cell`` is not at the stored level (see :meth:`descendants`).

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 3, {"v": [7]})
        ...     [row["v"] for row in store.get(dggs.latlng_to_cell(1.0, 2.0, 3))]
        [7]
        """
        return queries.get(self._store, cell)

    @guarded
    def descendants(self, cell: Any) -> list[dict[str, Any]]:
        """Return the rows in ``cell`` and all its descendants, in id order.

        A range scan on the cell index (``cell >= c AND cell < c || '~'``).

        Raises
        ------
        InvalidCellError, LevelMismatchError
            For a bad cell or one finer than the stored level.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, -40.0], [2.0, 100.0], 3)
        ...     len(store.descendants(dggs.latlng_to_cell(1.0, 2.0, 1)))
        1
        """
        return queries.descendants(self._store, cell)

    @guarded
    def aggregate(
        self,
        level: int,
        column: str | None = None,
        stats: Sequence[str] = ("count", "sum", "mean", "min", "max"),
        *, cell: Any = None, order_by: str | None = None, descending: bool = True, limit: int | None = None,
        as_table: bool = False, progress: Progress = None,
    ) -> Any:
        """Roll stored rows up to ``level`` (the stored level or coarser).

        Exact as SQL gives it, but a REAL sum is the correctly rounded sum (``math.fsum``'s), a mean that
        over the non-NULL count; read from kept roll-ups or columns (:mod:`dggs.storage.rollup_query`).

        Parameters
        ----------
        level : int
            Target level, ``0..store.level``.
        column : str, optional
            Value column for sum/mean/min/max; without it only ``count``.
        stats : sequence of str
            Any of ``count`` (rows), ``sum``, ``mean``, ``min``, ``max``
            (NULLs ignored, as SQL does).
        cell : str, optional
            Only roll up rows under this cell.
        order_by, descending, limit : str, bool, int, optional
            A stat to sort by (default the cell id), largest first (default); at most ``limit`` cells.
        as_table : bool, default False
            Columns (a pyarrow Table) instead of dicts: cheaper.
        progress : bool or callable, optional
            Its running time on stderr, as :mod:`dggs.storage.progress` says (default: on a terminal after 2 s).

        Returns
        -------
        list of dict or pyarrow.Table
            ``{"cell": id, "count": n, "sum": ..., ...}`` per non-empty cell, or as columns
            (``count`` int64, ``mean`` float64, the others the column's type).

        Raises
        ------
        LevelMismatchError
            If ``level`` is finer than the stored level.
        DggsValueError
            An unknown column or stat, sum/mean of a text column, a non-bool ``descending``/``as_table``.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 6,
        ...                             {"pop": [5, 7, 1]})
        ...     top = store.aggregate(1, "pop", ("count", "sum"), order_by="sum", limit=1)
        ...     top[0]["count"], top[0]["sum"]
        (2, 12)
        """
        with Bar(progress, unit="", desc=f"rolling up to level {level}") as bar, bar.heartbeat():
            return rollup_query.aggregate(self._store, level, column, stats, cell, order_by, descending, limit, as_table)

    @guarded
    def within(self, polygon: Any, level: int) -> list[dict[str, Any]]:
        """Return rows in the cells at ``level`` whose centres lie in ``polygon``.

        The polygon (shapely, lng/lat) is covered with cells by
        :func:`dggs.polygon_to_cells`; a finer ``level`` follows its outline
        more closely.

        Raises
        ------
        LevelError, LevelMismatchError
            If ``level`` is out of range or finer than the stored level.
        DggsValueError
            If ``polygon`` is not a shapely (Multi)Polygon.

        Examples
        --------
        >>> from shapely.geometry import box
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 50.0], [2.0, 60.0], 5)
        ...     [round(r["lat"]) for r in store.within(box(-10, -10, 10, 10), 3)]
        [1]
        """
        queries.check_query_level(self._store, level)
        cells = self.grid.polygon_to_cells(polygon, level)
        return queries.rows_under(self._store, list(cells), level)

    @guarded
    def disk(self, cell: Any, k: int) -> list[dict[str, Any]]:
        """Return rows in the cells within ``k`` steps of ``cell`` (:func:`dggs.grid_disk`).

        Raises
        ------
        InvalidCellError
            If ``cell`` is not one valid cell id.
        LevelMismatchError
            If ``cell`` is finer than the stored level.
        DggsValueError
            If ``k`` is not a whole number >= 0.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 5)
        ...     len(store.disk(dggs.latlng_to_cell(1.0, 2.0, 5), 1))
        1
        """
        cell = queries.one_cell(cell)
        (level,) = queries.check_cells(self._store, [cell])
        return queries.rows_under(self._store, list(dggs.grid_disk(cell, k)), level)

    @guarded
    def info(self) -> dict[str, Any]:
        """Describe the store: metadata, level, counts, columns, sources.

        Examples
        --------
        >>> with CellStore() as store:
        ...     sorted(store.info())[:4]
        ['cell_area_km2', 'columns', 'count', 'created']
        """
        meta = self.meta
        level = self.level
        size = None
        if self.path != ":memory:":
            size = sum(
                os.path.getsize(self.path + s) for s in ("", "-wal") if os.path.exists(self.path + s)
            )
        return {
            "path": self.path,
            "level": level,
            "cell_area_km2": float(dggs.cell_area(level, unit="km^2")) if level is not None else None,
            "crs": meta.get("crs"),
            "projection": self.projection,
            "schema_version": int(meta["schema_version"]),
            "dggs_version": meta.get("dggs_version"),
            "created": meta.get("created"),
            "updated": meta.get("updated"),
            "count": self.count(),
            "pending": self._store.pending_count(),
            "columns": self.columns,
            "rollup_levels": list(self.rollup_levels),
            "sources": self.sources(),
            "rejects": int(self.conn.execute("SELECT count(*) FROM rejects").fetchone()[0]),
            "size_bytes": size,
        }
