"""`CellStore`: points binned into equal-area cells, in one SQLite file.

Examples
--------
>>> import dggs
>>> from dggs.storage import CellStore
>>> with CellStore(":memory:") as store:
...     result = store.ingest_points([48.85, 48.86, -33.9], [2.35, 2.34, 151.2], level=6,
...                                  values={"pop": [10, 20, 5]})
...     paris = dggs.latlng_to_cell(48.85, 2.35, 2)
...     store.count(), store.count(paris)
(3, 2)
"""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import uuid
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import sqlite_utils

import dggs
from dggs.errors import (
    DggsValueError,
    InvalidCellError,
    LevelError,
    LevelMismatchError,
    StorageError,
)

from . import readers
from .ingest import MERGE_ROWS, IngestResult, run_ingest
from .schema import (
    BASE_COLUMNS,
    CRS,
    check_column_name,
    check_schema,
    column_types,
    create_schema,
    now,
    quote,
)

__all__ = ["CellStore", "STATS", "DEFAULT_LEVEL"]

#: Statistics :meth:`CellStore.aggregate` computes, and their SQL.
STATS = {
    "count": "count(*)",
    "sum": "sum({c})",
    "mean": "avg({c})",
    "min": "min({c})",
    "max": "max({c})",
}

#: Level used by a new store when none is given.
DEFAULT_LEVEL = 12

_SQLITE_MAGIC = b"SQLite format 3\x00"

Progress = Callable[[int], Any]


def _dggs_version() -> str:
    try:
        from importlib.metadata import version

        return version("dggs")
    except Exception:  # noqa: BLE001 - not installed: fall back to the module
        return str(getattr(dggs, "__version__", "unknown"))


def _file_info(path: Path) -> dict[str, Any]:
    """Return size, mtime and SHA-256 of a file (its identity as a source)."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        while block := fh.read(1 << 20):
            digest.update(block)
    stat = path.stat()
    return {"size": stat.st_size, "mtime": stat.st_mtime, "sha256": digest.hexdigest()}


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
        Open read-only (queries only).
    timeout : float, default 30
        Seconds to wait for a lock held by another connection.
    merge_rows : int, default 250000
        Pending rows that trigger a merge into the clustered table during
        ingest (or a quarter of the rows already merged, if more).

    Raises
    ------
    StorageError
        Naming the file, if it is not a SQLite database, not a cell store, or
        missing with ``create=False``.

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
    ) -> None:
        self.path = str(path)
        self.merge_rows = merge_rows
        self.readonly = readonly
        memory = self.path == ":memory:"
        if not memory:
            file = Path(self.path)
            if file.is_dir():
                raise StorageError(f"{self.path} is a directory, not a cell store file")
            if not file.exists() and (readonly or not create):
                raise StorageError(f"no cell store at {self.path}")
            if file.exists() and file.stat().st_size > 0:
                with open(file, "rb") as fh:
                    if fh.read(16) != _SQLITE_MAGIC:
                        raise StorageError(f"{self.path} is not a SQLite database")
        try:
            if readonly and not memory:
                uri = Path(self.path).resolve().as_uri() + "?mode=ro"
                self.conn = sqlite3.connect(uri, uri=True, isolation_level=None, timeout=timeout)
            else:
                self.conn = sqlite3.connect(self.path, isolation_level=None, timeout=timeout)
        except sqlite3.Error as exc:
            raise StorageError(f"cannot open {self.path}: {exc}") from exc
        try:
            self._setup()
        except sqlite3.DatabaseError as exc:
            self.conn.close()
            raise StorageError(f"{self.path} is not a usable SQLite database ({exc})") from exc
        except BaseException:
            self.conn.close()
            raise
        self.db = sqlite_utils.Database(self.conn)

    def _setup(self) -> None:
        conn = self.conn
        conn.execute("PRAGMA foreign_keys = ON")
        if not self.readonly:
            conn.execute("PRAGMA journal_mode = WAL")
            conn.execute("PRAGMA synchronous = NORMAL")
        conn.execute("PRAGMA cache_size = -65536")
        conn.execute("PRAGMA temp_store = MEMORY")
        conn.execute("PRAGMA threads = 2")  # helper thread for the merge's sort
        if not self.readonly:
            # Fewer, larger checkpoints: ingest writes tens of MB per merge.
            conn.execute("PRAGMA wal_autocheckpoint = 16384")
        if not check_schema(conn, self.path):
            if self.readonly:
                raise StorageError(f"{self.path} is an empty database, not a cell store")
            create_schema(conn, _dggs_version())
            check_schema(conn, self.path)  # whoever created it, it must be ours

    # -- life cycle ---------------------------------------------------------

    def close(self) -> None:
        """Close the connection (the store is unusable afterwards)."""
        self.conn.close()

    def __enter__(self) -> CellStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        return f"<CellStore {self.path} level={self.level}>"

    @contextmanager
    def _transaction(self) -> Iterator[None]:
        self.conn.execute("BEGIN IMMEDIATE")
        try:
            yield
        except BaseException:
            self.conn.execute("ROLLBACK")
            raise
        self.conn.execute("COMMIT")

    # -- metadata -----------------------------------------------------------

    @property
    def meta(self) -> dict[str, str]:
        """The ``meta`` table as a dict (schema_version, dggs_version, level, crs...)."""
        return dict(self.conn.execute("SELECT key, value FROM meta"))

    @property
    def level(self) -> int | None:
        """The stored level, or None before the first ingest."""
        row = self.conn.execute("SELECT value FROM meta WHERE key = 'level'").fetchone()
        return int(row[0]) if row else None

    @property
    def columns(self) -> dict[str, str]:
        """Value columns and their SQL types, e.g. ``{"population": "INTEGER"}``."""
        return column_types(self.conn)

    def _touch(self) -> None:
        self.conn.execute("UPDATE meta SET value = ? WHERE key = 'updated'", (now(),))

    def _set_level(self, level: int) -> None:
        self.conn.execute("INSERT OR IGNORE INTO meta (key, value) VALUES ('level', ?)", (str(level),))

    def _check_level_for_ingest(self, level: int) -> None:
        if isinstance(level, bool) or not isinstance(level, int) or not 0 <= level <= dggs.MAX_LEVEL:
            raise LevelError(f"level {level!r} is out of range 0..{dggs.MAX_LEVEL}")
        stored = self.level
        if stored is not None and stored != level:
            raise LevelMismatchError(
                f"{self.path} stores cells at level {stored}; cannot ingest at level {level} "
                f"(use level={stored} or another store)"
            )

    def _resolve_level(self, level: int | None) -> int:
        if level is not None:
            return level
        stored = self.level
        return DEFAULT_LEVEL if stored is None else stored

    # -- sources ------------------------------------------------------------

    def _open_source(
        self,
        key: str,
        kind: str,
        name: str,
        params: dict[str, Any],
        file_info: Mapping[str, Any],
        replace: bool,
    ) -> dict[str, Any]:
        """Find or register a source; with ``replace``, forget its rows first."""
        if self.readonly:
            raise StorageError(f"{self.path} is open read-only")
        params_json = json.dumps(params, sort_keys=True, default=str)
        found = self.conn.execute("SELECT id, params FROM sources WHERE key = ?", (key,)).fetchone()
        if found and replace:
            self.delete_source(found[0])
            found = None
        if found:
            if found[1] != params_json:
                raise StorageError(
                    f"{name} was ingested into {self.path} before with other settings "
                    f"({found[1]}, now {params_json}); pass replace=True to ingest it afresh"
                )
        else:
            stamp = now()
            with self._transaction():
                self.conn.execute(
                    "INSERT OR IGNORE INTO sources (key, kind, name, size, mtime, sha256, params, crs, started, updated) "
                    "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                    (
                        key,
                        kind,
                        name,
                        file_info.get("size"),
                        file_info.get("mtime"),
                        file_info.get("sha256"),
                        params_json,
                        str(params.get("crs") or CRS),
                        stamp,
                        stamp,
                    ),
                )
        row = self.conn.execute(
            "SELECT id, rows_done, complete FROM sources WHERE key = ?", (key,)
        ).fetchone()
        return {"id": row[0], "rows_done": row[1], "complete": bool(row[2])}

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
        row = self.conn.execute(
            "SELECT id FROM sources WHERE id = ? OR name = ? ORDER BY id DESC LIMIT 1",
            (source if isinstance(source, int) else -1, str(source)),
        ).fetchone()
        if row is None:
            raise StorageError(f"no source {source!r} in {self.path}")
        with self._transaction():
            deleted = 0
            for table in ("points", "points_pending"):
                deleted += self.conn.execute(f"DELETE FROM {table} WHERE source_id = ?", (row[0],)).rowcount
            self.conn.execute("DELETE FROM rejects WHERE source_id = ?", (row[0],))
            self.conn.execute("DELETE FROM sources WHERE id = ?", (row[0],))
            self._touch()
        return deleted

    def sources(self) -> list[dict[str, Any]]:
        """List the ingested sources with their progress, oldest first."""
        return list(
            self.db.query(
                "SELECT id, kind, name, size, sha256, crs, rows_done, rows_inserted, rows_rejected, "
                "complete, started, updated FROM sources ORDER BY id"
            )
        )

    def rejects(self, limit: int | None = None) -> list[dict[str, Any]]:
        """Rows refused by ``on_error="skip"``, with source name, row, line, column, value, reason."""
        sql = (
            'SELECT s.name AS source, r.row, r.line, r."column", r.value, r.reason, r.record '
            "FROM rejects r JOIN sources s ON s.id = r.source_id ORDER BY r.source_id, r.row"
        )
        params: list[Any] = []
        if limit is not None:
            sql += " LIMIT ?"
            params.append(int(limit))
        out = []
        for row in self.db.query(sql, params):
            row["value"] = json.loads(row["value"]) if row["value"] is not None else None
            row["record"] = json.loads(row["record"]) if row["record"] is not None else None
            out.append(row)
        return out

    # -- ingest -------------------------------------------------------------

    def ingest(self, source: Any, **kwargs: Any) -> IngestResult:
        """Ingest a file path (CSV or GeoJSON), DataFrame or iterable of dicts.

        Dispatches to :meth:`ingest_csv`, :meth:`ingest_geojson`,
        :meth:`ingest_dataframe` or :meth:`ingest_records`.

        Examples
        --------
        >>> with CellStore() as store:
        ...     store.ingest([{"lat": 1.0, "lng": 2.0}], level=3).rows_inserted
        1
        """
        if isinstance(source, (str, os.PathLike)):
            if readers.sniff_kind(source) == "csv":
                return self.ingest_csv(source, **kwargs)
            return self.ingest_geojson(source, **kwargs)
        if type(source).__name__ == "DataFrame" and hasattr(source, "columns"):
            return self.ingest_dataframe(source, **kwargs)
        return self.ingest_records(source, **kwargs)

    def ingest_csv(
        self,
        path: str | os.PathLike[str],
        lat: str = "lat",
        lng: str = "lng",
        values: Sequence[str] | Mapping[str, Any] = (),
        level: int | None = None,
        *,
        crs: Any = None,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        delimiter: str = ",",
        encoding: str = "utf-8",
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin the rows of a CSV file (with a header row), streaming it in batches.

        Each batch of ``batch_size`` rows is committed whole or not at all.
        The file is identified by its content (SHA-256): ingesting it again
        resumes after the rows already committed, or does nothing if it was
        ingested completely.

        Parameters
        ----------
        path : str or Path
            CSV file with a header row.
        lat, lng : str
            Names of the coordinate columns (latitude and longitude, degrees);
            with a projected ``crs``, the northing (y) and easting (x).
        values : list of str or dict
            Value columns to keep; a dict gives their types (``int``,
            ``float``, ``str`` or SQL ``"INTEGER"``, ``"REAL"``, ``"TEXT"``),
            otherwise they are guessed from the first batch.  Empty fields are
            stored as NULL.
        level : int, optional
            Level to bin at; default the store's level, or 12 for a new store.
        crs : str or pyproj.CRS, optional
            CRS of the coordinates (default WGS84 lat/lng), e.g. ``"EPSG:3857"``.
        batch_size : int, default 10000
            Rows per transaction.
        on_error : {"fail", "skip"}, default "fail"
            ``"fail"`` stops at the first bad row with a :class:`BadRowError`
            (earlier batches stay committed); ``"skip"`` stores the good rows,
            keeps the bad ones in table ``rejects`` and warns.
        replace : bool, default False
            Delete what an earlier ingest of this file stored, then ingest it.
        delimiter : str, default ","
            Field separator.
        encoding : str, default "utf-8"
            Text encoding of the file (a UTF-8 byte-order mark is skipped).
        progress : callable, optional
            Called with the number of input rows after each batch.

        Returns
        -------
        IngestResult

        Raises
        ------
        BadRowError
            On a bad row with ``on_error="fail"``.
        LevelMismatchError
            If the store holds another level.
        DggsValueError
            If a column is missing or named badly.

        Examples
        --------
        >>> import os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "pts.csv")
        >>> with open(path, "w") as fh:
        ...     _ = fh.write("lat,lng,pop\\n51.5,-0.12,9000000\\n40.7,-74.0,8000000\\n")
        >>> with CellStore() as store:
        ...     store.ingest_csv(path, values=["pop"], level=5).rows_inserted
        2
        """
        file = Path(path)
        if not file.is_file():
            raise StorageError(f"no such file: {path}")
        level = self._resolve_level(level)
        names, declared = _value_spec(values)
        info = _file_info(file)
        params = {"format": "csv", "lat": lat, "lng": lng, "values": names, "delimiter": delimiter}
        return run_ingest(
            self,
            key=f"file:{info['sha256']}",
            kind="csv",
            name=str(path),
            params=params,
            batches=lambda skip, types: readers.csv_batches(
                file, lat, lng, names, batch_size, skip, delimiter, types, encoding
            ),
            level=level,
            declared=declared,
            crs=crs,
            on_error=on_error,
            replace=replace,
            progress=progress,
            file_info=info,
        )

    def ingest_geojson(
        self,
        path: str | os.PathLike[str],
        values: Sequence[str] | Mapping[str, Any] | None = None,
        level: int | None = None,
        *,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin the features of a GeoJSON file (WGS84 lng/lat, RFC 7946).

        Points are stored as they are; a Polygon or MultiPolygon is stored
        as one row per cell at ``level`` whose centre lies inside it, each
        carrying the feature's properties (so sum a per-area value with care:
        every cell gets the whole value).  ``values=None`` keeps every
        property seen in the first batch.  Other parameters as
        :meth:`ingest_csv`; progress counts features.

        Examples
        --------
        >>> import json, os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "p.geojson")
        >>> fc = {"type": "FeatureCollection", "features": [{"type": "Feature",
        ...       "geometry": {"type": "Point", "coordinates": [2.35, 48.85]},
        ...       "properties": {"name": "Paris"}}]}
        >>> with open(path, "w") as fh:
        ...     json.dump(fc, fh)
        >>> with CellStore() as store:
        ...     _ = store.ingest_geojson(path, level=4)
        ...     store.descendants(dggs.latlng_to_cell(48.85, 2.35, 1))[0]["name"]
        'Paris'
        """
        file = Path(path)
        if not file.is_file():
            raise StorageError(f"no such file: {path}")
        level = self._resolve_level(level)
        features = readers.load_geojson(file)
        if values is None:
            seen: dict[str, None] = {}
            for feature in features[:batch_size]:
                if isinstance(feature, dict):
                    for key in feature.get("properties") or {}:
                        if key.lower() not in BASE_COLUMNS:
                            seen.setdefault(key, None)
            values = list(seen)
        names, declared = _value_spec(values)
        info = _file_info(file)
        return run_ingest(
            self,
            key=f"file:{info['sha256']}",
            kind="geojson",
            name=str(path),
            params={"format": "geojson", "values": names},
            batches=lambda skip, types: readers.geojson_batches(features, names, level, batch_size, skip),
            level=level,
            declared=declared,
            crs=None,
            on_error=on_error,
            replace=replace,
            progress=progress,
            file_info=info,
        )

    def ingest_records(
        self,
        records: Iterable[Mapping[str, Any]],
        lat: str = "lat",
        lng: str = "lng",
        values: Sequence[str] | Mapping[str, Any] = (),
        level: int | None = None,
        *,
        source: str | None = None,
        crs: Any = None,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin an iterable of dicts (e.g. rows from a database or JSON lines).

        Without ``source`` each call is a new, independent ingest.  Give a
        ``source`` name to make it resumable: calling again with the same
        name and the same records skips those already committed.  Other
        parameters as :meth:`ingest_csv`.

        Examples
        --------
        >>> with CellStore() as store:
        ...     rows = [{"lat": 0.5, "lng": 0.5, "v": 1}, {"lat": 0.6, "lng": 0.5, "v": 2}]
        ...     store.ingest_records(rows, values=["v"], level=3, source="demo").rows_inserted
        ...     store.ingest_records(rows, values=["v"], level=3, source="demo").already_complete
        2
        True
        """
        level = self._resolve_level(level)
        names, declared = _value_spec(values)
        return run_ingest(
            self,
            key=f"records:{source}" if source is not None else f"records:{uuid.uuid4().hex}",
            kind="records",
            name=source if source is not None else "<records>",
            params={"format": "records", "lat": lat, "lng": lng, "values": names},
            batches=lambda skip, types: readers.records_batches(records, lat, lng, names, batch_size, skip),
            threaded=False,  # the iterable may belong to this thread (a sqlite3 cursor...)
            level=level,
            declared=declared,
            crs=crs,
            on_error=on_error,
            replace=replace,
            progress=progress,
        )

    def ingest_points(
        self,
        lat: Any,
        lng: Any,
        level: int | None = None,
        values: Mapping[str, Any] | None = None,
        *,
        types: Mapping[str, Any] | None = None,
        source: str | None = None,
        crs: Any = None,
        batch_size: int = 100_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin points given as arrays (numpy, lists): the fastest way in.

        Parameters
        ----------
        lat, lng : array_like
            Latitudes and longitudes in degrees (or y and x in ``crs``).
        level : int, optional
            As in :meth:`ingest_csv`.
        values : dict of array_like, optional
            Value columns, each as long as ``lat``; types follow the dtypes
            unless given in ``types``.
        types : dict, optional
            SQL types of value columns, overriding the dtypes.
        source : str, optional
            Name that makes the ingest resumable (see :meth:`ingest_records`).
        crs, batch_size, on_error, replace, progress
            As in :meth:`ingest_csv` (default batch 100,000 rows).

        Examples
        --------
        >>> import numpy as np
        >>> with CellStore() as store:
        ...     r = store.ingest_points(np.array([10.0, 20.0]), np.array([30.0, 40.0]), 4,
        ...                             values={"temp": np.array([21.5, 19.0])})
        ...     store.columns, store.count()
        ({'temp': 'REAL'}, 2)
        """
        level = self._resolve_level(level)
        values = dict(values or {})
        for name in values:
            check_column_name(name)
        declared: dict[str, Any] = {}
        for name, col in values.items():
            implied = _dtype_type(col)
            if implied is not None:
                declared[name] = implied
        declared.update(types or {})
        return run_ingest(
            self,
            key=f"arrays:{source}" if source is not None else f"arrays:{uuid.uuid4().hex}",
            kind="arrays",
            name=source if source is not None else "<arrays>",
            params={"format": "arrays", "values": list(values)},
            batches=lambda skip, types: readers.array_batches(lat, lng, values, batch_size, skip),
            level=level,
            declared=declared,
            crs=crs,
            on_error=on_error,
            replace=replace,
            progress=progress,
        )

    def ingest_dataframe(
        self,
        df: Any,
        lat: str = "lat",
        lng: str = "lng",
        values: Sequence[str] | Mapping[str, Any] | None = None,
        level: int | None = None,
        **kwargs: Any,
    ) -> IngestResult:
        """Bin the rows of a pandas DataFrame (``values=None``: every other column).

        Keyword arguments are those of :meth:`ingest_points`.

        Examples
        --------
        >>> import pandas as pd  # doctest: +SKIP
        >>> df = pd.DataFrame({"lat": [1.0], "lng": [2.0], "v": [3]})  # doctest: +SKIP
        >>> CellStore().ingest_dataframe(df, level=3).rows_inserted  # doctest: +SKIP
        1
        """
        missing = [c for c in (lat, lng) if c not in df.columns]
        if missing:
            raise DggsValueError(
                f"DataFrame has no column(s) {', '.join(map(repr, missing))}; "
                f"its columns are {', '.join(map(repr, map(str, df.columns)))}"
            )
        if values is None:
            values = [str(c) for c in df.columns if c not in (lat, lng)]
        names, declared = _value_spec(values)
        declared = {**declared, **dict(kwargs.pop("types", None) or {})}
        return self.ingest_points(
            df[lat].to_numpy(),
            df[lng].to_numpy(),
            level,
            {name: df[name].to_numpy() for name in names},
            types=declared,
            **kwargs,
        )

    # -- maintenance --------------------------------------------------------

    def _pending_count(self) -> int:
        return int(self.conn.execute("SELECT count(*) FROM points_pending").fetchone()[0])

    def _merge_pending(self) -> None:
        cols = ", ".join(quote(c) for c in (*BASE_COLUMNS, *self.columns))
        try:
            self.conn.execute(
                f"INSERT INTO points ({cols}) SELECT {cols} FROM points_pending "
                "ORDER BY cell, source_id, row, part"
            )
        except sqlite3.IntegrityError as exc:  # pragma: no cover - would be a bug
            raise StorageError(f"{self.path}: a row would be stored twice ({exc})") from exc
        self.conn.execute("DELETE FROM points_pending")

    def merge(self) -> None:
        """Move pending rows into the indexed ``points`` table (one transaction).

        Ingest does this by itself; call it after an interrupted ingest you
        will not resume, to make queries as fast as they can be.
        """
        with self._transaction():
            self._merge_pending()

    # -- queries ------------------------------------------------------------

    def _cell_level(self, cell: Any) -> int:
        """Validate a query cell against the store; return its level."""
        if not dggs.is_valid_cell(cell):
            raise InvalidCellError(f"{cell!r} is not a valid cell id")
        level = dggs.get_level(cell)
        stored = self.level
        if stored is not None and level > stored:
            raise LevelMismatchError(
                f"cell {cell!r} is at level {level}, finer than the stored level {stored}"
            )
        return level

    def _check_query_level(self, level: Any) -> int | None:
        """Validate a roll-up level; return the stored level (None if empty)."""
        if isinstance(level, bool) or not isinstance(level, int) or not 0 <= level <= dggs.MAX_LEVEL:
            raise LevelError(f"level {level!r} is out of range 0..{dggs.MAX_LEVEL}")
        stored = self.level
        if stored is not None and level > stored:
            raise LevelMismatchError(
                f"level {level} is finer than the stored level {stored}; "
                f"data can only be rolled up to levels 0..{stored}"
            )
        return stored

    def _check_column(self, column: Any) -> str:
        columns = self.columns
        if column not in columns:
            raise DggsValueError(
                f"no value column {column!r} in {self.path}; "
                f"columns are: {', '.join(columns) or '(none)'}"
            )
        return column

    @contextmanager
    def _snapshot(self) -> Iterator[str]:
        """Read in one snapshot; yield the table to read from.

        That is ``points`` alone when nothing is pending (the common case,
        and a plain clustered scan), else the ``all_points`` view.
        """
        own = not self.conn.in_transaction
        if own:
            self.conn.execute("BEGIN")
        try:
            pending = self.conn.execute("SELECT 1 FROM points_pending LIMIT 1").fetchone()
            yield "all_points" if pending else "points"
        finally:
            if own:
                self.conn.execute("COMMIT")

    def _select_list(self) -> str:
        return ", ".join(quote(c) for c in ("cell", "lat", "lng", *self.columns, "source_id", "row"))

    def count(self, cell: str | None = None) -> int:
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
        if cell is None:
            row = self.conn.execute(
                "SELECT (SELECT count(*) FROM points) + (SELECT count(*) FROM points_pending)"
            ).fetchone()
            return int(row[0])
        self._cell_level(cell)
        with self._snapshot() as table:
            row = self.conn.execute(
                f"SELECT count(*) FROM {table} WHERE cell >= ?1 AND cell < ?1 || '~'", (cell,)
            ).fetchone()
        return int(row[0])

    def get(self, cell: str) -> list[dict[str, Any]]:
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
        level = self._cell_level(cell)
        stored = self.level
        if stored is None:
            return []
        if level != stored:
            raise LevelMismatchError(
                f"cell {cell!r} is at level {level}, not the stored level {stored}; "
                "use descendants() for coarser cells"
            )
        with self._snapshot() as table:
            sql = f"SELECT {self._select_list()} FROM {table} WHERE cell = ? ORDER BY source_id, row"
            return list(self.db.query(sql, (cell,)))

    def descendants(self, cell: str) -> list[dict[str, Any]]:
        """Return the rows in ``cell`` and all its descendants, in id order.

        A range scan on the cell index (``cell >= c AND cell < c || '~'``).

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, -40.0], [2.0, 100.0], 3)
        ...     len(store.descendants(dggs.latlng_to_cell(1.0, 2.0, 1)))
        1
        """
        self._cell_level(cell)
        with self._snapshot() as table:
            sql = (
                f"SELECT {self._select_list()} FROM {table} "
                "WHERE cell >= ?1 AND cell < ?1 || '~' ORDER BY cell, source_id, row"
            )
            return list(self.db.query(sql, (cell,)))

    def aggregate(
        self,
        level: int,
        column: str | None = None,
        stats: Sequence[str] = ("count", "sum", "mean", "min", "max"),
        *,
        cell: str | None = None,
        order_by: str | None = None,
        descending: bool = True,
        limit: int | None = None,
    ) -> list[dict[str, Any]]:
        """Roll stored rows up to ``level`` (the stored level or coarser).

        Computed in SQL by id-prefix arithmetic:
        ``GROUP BY substr(cell, 1, level + 1)``.

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
        order_by : str, optional
            A stat to sort by; default the cell id.
        descending : bool, default True
            Sort ``order_by`` largest first.
        limit : int, optional
            Return at most this many cells.

        Returns
        -------
        list of dict
            ``{"cell": id, "count": n, "sum": ..., ...}`` per non-empty cell.

        Raises
        ------
        LevelMismatchError
            If ``level`` is finer than the stored level.
        DggsValueError
            For an unknown column or stat, or sum/mean of a text column.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 6,
        ...                             {"pop": [5, 7, 1]})
        ...     top = store.aggregate(1, "pop", ("count", "sum"), order_by="sum", limit=1)
        ...     top[0]["count"], top[0]["sum"]
        (2, 12)
        """
        stored = self._check_query_level(level)
        stats = tuple(stats)
        unknown = [s for s in stats if s not in STATS]
        if unknown or not stats:
            raise DggsValueError(
                f"unknown stat(s) {unknown or stats!r}; choose from {', '.join(STATS)}"
            )
        if column is None:
            if any(s != "count" for s in stats):
                if stats == ("count", "sum", "mean", "min", "max"):
                    stats = ("count",)
                else:
                    raise DggsValueError("stats other than 'count' need a column")
        else:
            self._check_column(column)
            if self.columns[column] == "TEXT" and {"sum", "mean"} & set(stats):
                raise DggsValueError(f"column {column!r} holds text: sum and mean make no sense")
        if order_by is not None and order_by not in stats:
            raise DggsValueError(f"order_by must be one of the stats {stats}, not {order_by!r}")
        if stored is None:
            return []
        exprs = ", ".join(
            f"{STATS[s].format(c=quote(column) if column else '')} AS {quote(s)}" for s in stats
        )
        params: dict[str, Any] = {"n": level + 1}
        where = ""
        if cell is not None:
            cell_level = self._cell_level(cell)
            if cell_level > level:
                raise LevelMismatchError(
                    f"cell {cell!r} is at level {cell_level}, finer than the roll-up level {level}"
                )
            where = "WHERE cell >= :cell AND cell < :cell || '~'"
            params["cell"] = cell
        order = "1"
        if order_by is not None:
            order = f"{quote(order_by)} {'DESC' if descending else 'ASC'}, 1"
        out = []
        with self._snapshot() as table:
            sql = (
                f"SELECT substr(cell, 1, :n) AS cell_, {exprs} FROM {table} {where} "
                f"GROUP BY cell_ ORDER BY {order}"
            )
            if limit is not None:
                sql += " LIMIT :limit"
                params["limit"] = int(limit)
            for row in self.db.query(sql, params):
                out.append({"cell": row.pop("cell_"), **row})
        return out

    def _rows_under(self, cells: Sequence[str], level: int) -> list[dict[str, Any]]:
        """Rows under any of ``cells`` (all at ``level``): index range per cell."""
        if not len(cells):
            return []
        select = self._select_list()
        prefixed = ", ".join(f"p.{quote(c)}" for c in ("cell", "lat", "lng", *self.columns, "source_id", "row"))
        sql = (
            f"SELECT {prefixed} FROM json_each(?1) q JOIN points p "
            "ON p.cell >= q.value AND p.cell < q.value || '~' "
            f"UNION ALL SELECT {select} FROM points_pending "
            "WHERE substr(cell, 1, ?2) IN (SELECT value FROM json_each(?1)) "
            "ORDER BY 1, source_id, row"
        )
        return list(self.db.query(sql, (json.dumps([str(c) for c in cells]), level + 1)))

    def within(self, polygon: Any, level: int) -> list[dict[str, Any]]:
        """Return rows in the cells at ``level`` whose centres lie in ``polygon``.

        The polygon (shapely, lng/lat) is covered with cells by
        :func:`dggs.polygon_to_cells`; a finer ``level`` follows its outline
        more closely.

        Examples
        --------
        >>> from shapely.geometry import box
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 50.0], [2.0, 60.0], 5)
        ...     [round(r["lat"]) for r in store.within(box(-10, -10, 10, 10), 3)]
        [1]
        """
        self._check_query_level(level)
        cells = dggs.polygon_to_cells(polygon, level)
        return self._rows_under(list(cells), level)

    def disk(self, cell: str, k: int) -> list[dict[str, Any]]:
        """Return rows in the cells within ``k`` steps of ``cell`` (:func:`dggs.grid_disk`).

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 5)
        ...     len(store.disk(dggs.latlng_to_cell(1.0, 2.0, 5), 1))
        1
        """
        level = self._cell_level(cell)
        return self._rows_under(list(dggs.grid_disk(cell, k)), level)

    def to_geojson(
        self,
        level: int,
        column: str | None = None,
        path: str | os.PathLike[str] | None = None,
        stats: Sequence[str] | None = None,
    ) -> dict[str, Any]:
        """Roll up to ``level`` and return (and write) a GeoJSON FeatureCollection.

        One Polygon feature per non-empty cell, with properties ``cell`` and
        the stats (default count, sum, mean, min, max of ``column``).

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 4, {"v": [3.0]})
        ...     fc = store.to_geojson(2, "v")
        ...     fc["features"][0]["properties"]["sum"]
        3.0
        """
        if stats is None:
            stats = ("count", "sum", "mean", "min", "max") if column else ("count",)
        rows = self.aggregate(level, column, stats)
        cells = [row["cell"] for row in rows]
        props = [{k: v for k, v in row.items() if k != "cell"} for row in rows]
        collection = dggs.cells_to_geojson(cells, properties=props)
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                json.dump(collection, fh)
        return collection

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
            "schema_version": int(meta["schema_version"]),
            "dggs_version": meta.get("dggs_version"),
            "created": meta.get("created"),
            "updated": meta.get("updated"),
            "count": self.count(),
            "pending": self._pending_count(),
            "columns": self.columns,
            "sources": self.sources(),
            "rejects": int(self.conn.execute("SELECT count(*) FROM rejects").fetchone()[0]),
            "size_bytes": size,
        }


def _dtype_type(column: Any) -> str | None:
    """Return the SQL type implied by an array's dtype, or None (object arrays, lists)."""
    kind = getattr(column, "dtype", None)
    kind = kind.kind if kind is not None else None
    return {"i": "INTEGER", "u": "INTEGER", "b": "INTEGER", "f": "REAL", "U": "TEXT", "S": "TEXT"}.get(kind or "")


def _value_spec(values: Sequence[str] | Mapping[str, Any] | None) -> tuple[list[str], dict[str, Any]]:
    """Split ``values`` into names (validated) and declared types."""
    if values is None:
        return [], {}
    if isinstance(values, str):
        values = [values]
    if isinstance(values, Mapping):
        names = [check_column_name(n) for n in values]
        return names, dict(values)
    names = [check_column_name(n) for n in values]
    if len(set(names)) != len(names):
        raise DggsValueError(f"value columns repeat: {names}")
    return names, {}
