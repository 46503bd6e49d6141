"""`CellStore`: points binned into equal-area cells, in one SQLite file.

A thin facade over collaborators it owns, each made in ``__init__`` over the open
file (:class:`~dggs.storage.connection.Connection`) and testable alone: the
:class:`~dggs.storage.querier.Querier`, :class:`~dggs.storage.ingester.Ingester`,
:class:`~dggs.storage.raster_ingester.RasterIngester`, :class:`~dggs.storage.exporter.Exporter`
and :class:`~dggs.storage.rollup_keeper.RollupKeeper`.  Their public methods here delegate in one
line with the collaborator's docstring (:func:`_documented_by`).  Every public method turns raw
SQLite and OS errors into a :class:`dggs.StorageError` naming the file (:func:`~dggs.storage.connection.guarded`).

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
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar

import dggs
from dggs.errors import DggsValueError

from .connection import DEFAULT_LEVEL, Connection, guarded
from .datasets import describe_datasets
from .exporter import DRAW_TOLERANCE, Exporter
from .ingest import MERGE_ROWS, IngestResult
from .ingester import Ingester, Values
from .ingester import Progress as IngestProgress
from .progress import Progress
from .projection import settle
from .querier import Querier
from .queries import STATS
from .raster_ingester import RasterIngester
from .rollup_keeper import RollupKeeper
from .sources import delete_source, list_rejects, list_sources

if TYPE_CHECKING:  # pragma: no cover
    from .raster_ingest import RasterIngestResult

__all__ = ["CellStore", "STATS", "DEFAULT_LEVEL"]

F = TypeVar("F", bound=Callable[..., Any])


def _documented_by(method: Any) -> Callable[[F], F]:
    """Give the decorated public method the docstring (examples included) of ``method``, the one doing the work."""

    def give(face: F) -> F:
        face.__doc__ = method.__doc__
        return face

    return give


class CellStore:
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
    dataset : str, optional
        A named dataset of the file (its own level, projection, columns, sources and kept roll-ups),
        made on first use unless ``readonly`` or ``create=False``; None (the default): the file's
        default dataset, the one every store written before datasets holds.  Letters, digits, ``_``
        and ``-``, starting with a letter.  Everything this store does (ingest, queries, roll-ups,
        export, ``store.conn``'s ad-hoc SQL) acts on that dataset alone.  A dataset made by this
        store and left empty by an error inside its ``with`` block is taken back.

    Raises
    ------
    StorageError
        Naming the file, if it is not a SQLite database, not a cell store, or
        missing with ``create=False``; naming both projections, if
        ``projection`` differs from the one the file records.
    DatasetError
        (a :class:`DggsValueError`) naming it, for a dataset name that is not allowed, or one the file
        lacks when the store may not make it.

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
        dataset: str | None = None,
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
                                 check_same_thread=bool(check_same_thread), dataset=dataset)
        try:
            self._store.projection = settle(self._store.conn, self.path, projection, readonly)
        except BaseException:
            self._store.close()
            raise
        self._querier = Querier(self._store)
        self._ingester = Ingester(self._store, merge_rows)
        self._raster_ingester = RasterIngester(self._store)
        self._exporter = Exporter(self._store)
        self._rollup_keeper = RollupKeeper(self._store)

    @property
    def conn(self) -> sqlite3.Connection:
        """The store's SQLite connection (a read-only store's, opened again when a writer appeared)."""
        return self._store.conn

    @property
    def db(self) -> Any:
        """The store as a :class:`sqlite_utils.Database`, for ad-hoc queries (``store.db.query(sql)``)."""
        return self._store.db

    def close(self) -> None:
        """Close the connection (the store is unusable afterwards)."""
        self._store.close()

    def __enter__(self) -> CellStore:
        return self

    def __exit__(self, error: object, *exc: object) -> None:
        self._store.close(discard_unused=error is not None)  # a failed first ingest leaves no empty file

    def __repr__(self) -> str:
        named = "" if self.dataset is None else f" dataset={self.dataset!r}"
        return f"<CellStore {self.path}{named} level={self.level}>"

    @property
    def dataset(self) -> str | None:
        """The dataset this store reads and writes: its name, or None for the file's default dataset."""
        return self._store.dataset

    @property
    def made_dataset(self) -> bool:
        """Whether this store made its named dataset when it opened (it was not in the file before)."""
        return bool(self._store.created_dataset)

    @guarded
    def datasets(self) -> list[dict[str, Any]]:
        """Every dataset of the file, the default one (name None) first, with level, projection, rows, columns.

        ``rollup_levels`` gives each one's kept roll-ups.  :func:`dggs.storage.list_datasets` does the same
        for a path.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([48.85], [2.35], 9)
        ...     [(d["name"], d["level"], d["rows"]) for d in store.datasets()]
        [(None, 9, 1)]
        """
        return describe_datasets(self._store.conn)

    @property
    def projection(self) -> str:
        """The projection the cells were binned with, ``"ISEA"`` or ``"IVEA"`` (``meta.projection``)."""
        return str(self._store.projection)

    @property
    def grid(self) -> Any:
        """The :class:`dggs.Grid` of the stored cells (locates points, draws and queries cells)."""
        return dggs.Grid(self._store.projection)

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

    @_documented_by(Querier.count)
    def count(self, cell: Any = None) -> int:  # noqa: D102
        return self._querier.count(cell)

    @_documented_by(Querier.get)
    def get(self, cell: Any) -> list[dict[str, Any]]:  # noqa: D102
        return self._querier.get(cell)

    @_documented_by(Querier.descendants)
    def descendants(self, cell: Any) -> list[dict[str, Any]]:  # noqa: D102
        return self._querier.descendants(cell)

    @_documented_by(Querier.aggregate)
    def aggregate(  # noqa: D102
        self, level: int, column: str | None = None, stats: Sequence[str] = ("count", "sum", "mean", "min", "max"),
        *, cell: Any = None, order_by: str | None = None, descending: bool = True, limit: int | None = None,
        as_table: bool = False, progress: Progress = None,
    ) -> Any:
        return self._querier.aggregate(level, column, stats, cell=cell, order_by=order_by, descending=descending,
                                       limit=limit, as_table=as_table, progress=progress)

    @_documented_by(Querier.within)
    def within(self, polygon: Any, level: int) -> list[dict[str, Any]]:  # noqa: D102
        return self._querier.within(polygon, level)

    @_documented_by(Querier.disk)
    def disk(self, cell: Any, k: int) -> list[dict[str, Any]]:  # noqa: D102
        return self._querier.disk(cell, k)

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
            "dataset": self.dataset,
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


    @_documented_by(Ingester.ingest)
    def ingest(self, source: Any, **kwargs: Any) -> IngestResult:  # noqa: D102
        return self._ingester.ingest(source, **kwargs)

    @_documented_by(Ingester.ingest_csv)
    def ingest_csv(  # noqa: D102
        self, path: str | os.PathLike[str], lat: str = "lat", lng: str = "lng", values: Values = (),
        level: int | None = None, *, crs: Any = None, batch_size: int = 10_000, on_error: str = "fail",
        replace: bool = False, delimiter: str = ",", encoding: str = "utf-8", progress: IngestProgress | None = None,
    ) -> IngestResult:
        return self._ingester.ingest_csv(path, lat, lng, values, level, crs=crs, batch_size=batch_size,
                                         on_error=on_error, replace=replace, delimiter=delimiter, encoding=encoding,
                                         progress=progress)

    @_documented_by(Ingester.ingest_geojson)
    def ingest_geojson(  # noqa: D102
        self, path: str | os.PathLike[str], values: Values | None = None, level: int | None = None, *,
        batch_size: int = 10_000, on_error: str = "fail", replace: bool = False, progress: IngestProgress | None = None,
    ) -> IngestResult:
        return self._ingester.ingest_geojson(path, values, level, batch_size=batch_size, on_error=on_error,
                                             replace=replace, progress=progress)

    @_documented_by(Ingester.ingest_vector)
    def ingest_vector(  # noqa: D102
        self, path: str | os.PathLike[str], layer: str | int | None = None, values: Values | None = None,
        level: int | None = None, *, crs: Any = None, batch_size: int = 10_000, on_error: str = "fail",
        replace: bool = False, progress: IngestProgress | None = None,
    ) -> IngestResult:
        return self._ingester.ingest_vector(path, layer, values, level, crs=crs, batch_size=batch_size,
                                            on_error=on_error, replace=replace, progress=progress)

    @_documented_by(Ingester.ingest_records)
    def ingest_records(  # noqa: D102
        self, records: Iterable[Mapping[str, Any]], lat: str = "lat", lng: str = "lng", values: Values = (),
        level: int | None = None, *, source: str | None = None, crs: Any = None, batch_size: int = 10_000,
        on_error: str = "fail", replace: bool = False, progress: IngestProgress | None = None,
    ) -> IngestResult:
        return self._ingester.ingest_records(records, lat, lng, values, level, source=source, crs=crs,
                                             batch_size=batch_size, on_error=on_error, replace=replace,
                                             progress=progress)

    @_documented_by(Ingester.ingest_points)
    def ingest_points(  # noqa: D102
        self, lat: Any, lng: Any, level: int | None = None, values: Mapping[str, Any] | None = None, *,
        types: Mapping[str, Any] | None = None, source: str | None = None, crs: Any = None,
        batch_size: int = 100_000, on_error: str = "fail", replace: bool = False, progress: IngestProgress | None = None,
        cells: Any = None,
    ) -> IngestResult:
        return self._ingester.ingest_points(lat, lng, level, values, types=types, source=source, crs=crs,
                                            batch_size=batch_size, on_error=on_error, replace=replace,
                                            progress=progress, cells=cells)

    @_documented_by(Ingester.ingest_dataframe)
    def ingest_dataframe(  # noqa: D102
        self, df: Any, lat: str = "lat", lng: str = "lng", values: Values | None = None, level: int | None = None,
        *, types: Mapping[str, Any] | None = None, source: str | None = None, crs: Any = None,
        batch_size: int = 100_000, on_error: str = "fail", replace: bool = False, progress: IngestProgress | None = None,
        cells: str | None = None,
    ) -> IngestResult:
        return self._ingester.ingest_dataframe(df, lat, lng, values, level, types=types, source=source, crs=crs,
                                               batch_size=batch_size, on_error=on_error, replace=replace,
                                               progress=progress, cells=cells)

    @_documented_by(Ingester.merge)
    def merge(self) -> None:  # noqa: D102
        self._ingester.merge()

    @_documented_by(RasterIngester.ingest_raster)
    def ingest_raster(  # noqa: D102
        self, source: Any, level: int | None = None, *, mode: str = "mean", band: int | list[int] | None = None,
        nodata: Any = None, window: Any = None, density: bool = False, block_size: int = 512, replace: bool = False,
        progress: bool | Callable[[int], Any] | None = None,
    ) -> RasterIngestResult:
        return self._raster_ingester.ingest_raster(source, level, mode=mode, band=band, nodata=nodata, window=window,
                                                   density=density, block_size=block_size, replace=replace,
                                                   progress=progress)

    @property
    @_documented_by(RollupKeeper.rollup_levels)
    def rollup_levels(self) -> tuple[int, ...]:  # noqa: D102
        return self._rollup_keeper.rollup_levels

    @_documented_by(RollupKeeper.keep_rollups)
    def keep_rollups(self, levels: int | Iterable[int]) -> tuple[int, ...]:  # noqa: D102
        return self._rollup_keeper.keep_rollups(levels)

    @_documented_by(Exporter.to_geojson)
    def to_geojson(  # noqa: D102
        self, level: int, column: str | None = None, path: str | os.PathLike[str] | None = None,
        stats: Sequence[str] | None = None, densify: int | None = None, *, tolerance: Any = DRAW_TOLERANCE,
    ) -> dict[str, Any]:
        return self._exporter.to_geojson(level, column, path, stats, densify, tolerance=tolerance)

    @_documented_by(Exporter.to_arrow)
    def to_arrow(  # noqa: D102
        self, level: int, column: str | None = None, stats: Sequence[str] | None = None, densify: int | None = None,
        *, tolerance: Any = DRAW_TOLERANCE, rows: list[dict[str, Any]] | None = None,
    ) -> Any:
        return self._exporter.to_arrow(level, column, stats, densify, tolerance=tolerance, rows=rows)

    @_documented_by(Exporter.export)
    def export(  # noqa: D102
        self, path: str | os.PathLike[str], level: int, column: str | None = None, stats: Sequence[str] | None = None,
        *, format: str | None = None, densify: int | None = None, tolerance: Any = DRAW_TOLERANCE,
        progress: Progress = None,
    ) -> int:
        return self._exporter.export(path, level, column, stats, format=format, densify=densify, tolerance=tolerance,
                                     progress=progress)

