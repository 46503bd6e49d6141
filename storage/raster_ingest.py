"""Rasters into a cell store, one block a transaction: the work of :meth:`CellStore.ingest_raster`.

The raster is read and cut block by block as :func:`dggs.raster.raster_to_cells`
cuts it (:func:`dggs.raster.block_results`).  The guarantees are the CSV
ingest's (:mod:`dggs.storage.ingest`), with blocks for batches:

* **Atomic blocks.**  A block's per-cell partials (covered area, weighted
  sums, min, max, pixel count; class areas) are upserted into table
  ``raster_partials`` (``raster_classes``), keyed by source and cell, in the
  transaction that adds the block to the source's progress
  (``sources.rows_done`` counts blocks for a raster).  A cell on a block's
  edge gets partials from each block it meets, added in block order, which
  is the order :func:`raster_to_cells` adds them in: the same float sums.
* **Exactly once.**  Running it again skips the blocks committed.  When the
  last block is in, the finished rows (one per cell, at its centre) go into
  ``points``, with the kept roll-ups, the partials are deleted and the source
  marked complete, in one transaction.
* A raster is identified by its content (the file's SHA-256; for a
  DataArray, or a remote raster, the hash of the pixels read, with its grid).
"""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, StorageError

from .bulk import insert_many, max_variables
from .connection import Connection
from .ingest import IngestResult
from .progress import Bar, check_progress
from .rollup_keep import add_partials, batch_partials, check_levels, kept_levels
from .schema import add_columns, column_types, now, quote
from .sources import delete_source, file_info, open_source

__all__ = ["ingest_raster", "RasterIngestResult", "PARTIALS_DDL"]

#: The tables of partials of the rasters being ingested (created on the first raster ingest).
PARTIALS_DDL = (
    "CREATE TABLE IF NOT EXISTS raster_partials (source_id INTEGER NOT NULL REFERENCES sources(id) "
    "ON DELETE CASCADE, cell INTEGER NOT NULL, band INTEGER NOT NULL, covered REAL NOT NULL, "
    "count INTEGER NOT NULL, total REAL, low REAL, high REAL, PRIMARY KEY (source_id, cell, band)) WITHOUT ROWID",
    "CREATE TABLE IF NOT EXISTS raster_classes (source_id INTEGER NOT NULL REFERENCES sources(id) "
    "ON DELETE CASCADE, cell INTEGER NOT NULL, class NOT NULL, area REAL NOT NULL, "
    "PRIMARY KEY (source_id, cell, class)) WITHOUT ROWID",
)
_UPSERT = (
    " ON CONFLICT (source_id, cell, band) DO UPDATE SET covered = covered + excluded.covered, "
    "count = count + excluded.count, total = total + excluded.total, low = min(low, excluded.low), "
    "high = max(high, excluded.high)"
)


@dataclass
class RasterIngestResult(IngestResult):
    """What a raster ingest did: ``rows_read`` and ``rows_resumed`` count blocks, ``rows_inserted`` cells."""

    blocks: int = 0

    def summary(self) -> str:
        """One line for people.

        Examples
        --------
        >>> RasterIngestResult("dem.tif", rows_read=4, rows_inserted=120, blocks=4).summary()
        'dem.tif: read 4 of 4 blocks, stored 120 cells'
        """
        if self.already_complete:
            return f"{self.source}: already ingested ({self.blocks:,} blocks), nothing to do"
        text = f"{self.source}: read {self.rows_read:,} of {self.blocks:,} blocks, stored {self.rows_inserted:,} cells"
        if self.rows_resumed:
            text += f" (resumed after {self.rows_resumed:,} committed earlier)"
        return text


def ingest_raster(
    store: Connection, source: Any, level: int | None, *, mode: str, band: Any, nodata: Any, window: Any,
    density: bool, block_size: int, replace: bool, progress: Any,
) -> RasterIngestResult:
    """Ingest a raster into ``store`` (see :meth:`dggs.storage.CellStore.ingest_raster`).

    Raises
    ------
    RasterError, LevelError, DggsValueError
        As :func:`dggs.raster.raster_to_cells`, before the store is touched.
    LevelMismatchError
        The store holds another level (or keeps a finer roll-up level).
    StorageError
        Read-only store, a changed file, other settings before, or another process ingesting it too.
    """
    from dggs.raster import open_checked, windows

    if store.readonly:
        raise StorageError(f"{store.path} is open read-only")
    if not isinstance(replace, bool):
        raise DggsValueError(f"replace must be True or False, not {replace!r}")
    check_progress(progress, "a block count")
    level, src = open_checked(source, store.resolve_level(level), mode, band, nodata, window, block_size)
    store.check_level_for_ingest(level)
    check_levels(kept_levels(store.conn), level)
    start = time.perf_counter()
    total = len(windows(src, block_size))
    name, key, info = _identity(store, source, src, block_size, replace)
    params = {"format": "raster", "mode": mode, "bands": src.bands, "nodata": [str(v) for v in src.nodata],
              "window": None if window is None else [src.row0, src.col0, src.height, src.width],
              "density": bool(density), "block_size": block_size, "level": level, "crs": src.crs.to_string()}
    row = open_source(store, key, "raster", name, params, info, replace)
    result = RasterIngestResult(source=name, rows_resumed=row["rows_done"], blocks=total)
    if row["complete"]:
        result.already_complete = True
        return result
    with store.transaction():
        for ddl in PARTIALS_DDL:
            store.conn.execute(ddl)
    with Bar(progress, total=total, unit="blocks", desc="binning raster") as bar:
        if row["rows_done"]:
            bar.update(row["rows_done"])
        _blocks(store, src, row, level, mode, bool(density), block_size, total, name, bar.update, result)
        bar.stage("summing into cells")
        with bar.heartbeat():
            result.rows_inserted = _finish(store, row["id"], src.bands, level, mode, total, name)
    result.seconds = time.perf_counter() - start
    return result


def _identity(store: Connection, source: Any, src: Any, block_size: int, replace: bool) -> tuple[str, str, dict[str, Any]]:
    """The source's name, key and file info; an earlier, different version of a file is refused or replaced."""
    path = Path(src.name) if isinstance(source, (str, os.PathLike)) else None
    if path is None or not path.is_file():  # a DataArray or a remote raster: the pixels read, with their grid
        from dggs.raster import windows

        digest = hashlib.sha256(json.dumps([str(src.transform), src.crs.to_wkt(), src.height, src.width, src.bands,
                                            str(src.dtype), [str(v) for v in src.nodata]]).encode())
        for r, c, rows, cols in windows(src, block_size):
            data, mask = src.reader(src.row0 + r, src.col0 + c, rows, cols)
            digest.update(np.ascontiguousarray(data).tobytes())
            digest.update(np.ascontiguousarray(mask).tobytes())
        return src.name, f"raster:{digest.hexdigest()}", {"sha256": digest.hexdigest()}
    info = file_info(path)
    name, key = str(source), f"file:{info['sha256']}"
    earlier = store.conn.execute(
        "SELECT id, size FROM sources WHERE kind = 'raster' AND name = ? AND key != ? ORDER BY id DESC",
        (name, key),
    ).fetchall()
    if earlier and not replace:
        raise StorageError(
            f"{name} changed since it was ingested into {store.path} (was {earlier[0][1] or 0:,} bytes, now "
            f"{info['size']:,}); pass replace=True (--replace) to replace the rows of the old version, "
            "or rename the file to keep both"
        )
    for old in earlier:
        delete_source(store, old[0])
    return name, key, info


def _blocks(store: Connection, src: Any, row: dict[str, Any], level: int, mode: str, density: bool, block_size: int,
            total: int, name: str, tick: Callable[[int], Any], result: RasterIngestResult) -> None:
    """Commit each block's partials with the progress; blocks without data ride along with the next commit."""
    from dggs.raster import block_results

    done, waiting = row["rows_done"], 0
    for part in block_results(src, level, mode, density, block_size, skip=done):
        waiting += 1
        if part is None and done + waiting < total:
            continue
        _commit(store, row["id"], part, mode, waiting, done, name, level)
        done += waiting
        result.rows_read += waiting
        tick(waiting)
        waiting = 0


def _commit(store: Connection, source_id: int, part: Any, mode: str, blocks: int, done: int, name: str,
            level: int) -> None:
    """One block's partials and the source's progress, in one transaction (a compare-and-set on the progress)."""
    conn = store.conn
    limit = max_variables(conn)
    with store.transaction():
        store.set_level(level)
        if part is not None and mode == "center":  # each cell from one block only: a second one would be a bug
            cells, values = part
            flat = _rows(source_id, cells, [np.zeros(cells.shape[0]), np.zeros(cells.shape[0], np.int64)],
                         [values[b] for b in range(values.shape[0])])
            insert_many(conn, "INSERT INTO raster_partials (source_id, cell, band, covered, count, total) VALUES ",
                        "(?, ?, ?, ?, ?, ?)", flat, 6, limit)
        elif part is not None:
            bands = part.sums.shape[0]
            flat = _rows(source_id, part.cells, [part.covered, part.count],
                         [np.stack([part.sums[b], part.low[b], part.high[b]]) for b in range(bands)])
            insert_many(conn, "INSERT INTO raster_partials (source_id, cell, band, covered, count, total, low, high) "
                        "VALUES ", "(?, ?, ?, ?, ?, ?, ?, ?)", flat, 8, limit, _UPSERT)
            if part.classes:
                c = part.classes
                flat = [None] * (4 * c["cell"].shape[0])
                flat[0::4] = [source_id] * c["cell"].shape[0]
                flat[1::4] = c["cell"].astype(np.int64).tolist()
                flat[2::4] = c["value"].tolist()
                flat[3::4] = c["area"].tolist()
                insert_many(conn, "INSERT INTO raster_classes (source_id, cell, class, area) VALUES ",
                            "(?, ?, ?, ?)", flat, 4, limit, " ON CONFLICT (source_id, cell, class) DO UPDATE "
                            "SET area = area + excluded.area")
        updated = conn.execute(
            "UPDATE sources SET rows_done = rows_done + ?, updated = ? WHERE id = ? AND rows_done = ? AND complete = 0",
            (blocks, now(), source_id, done),
        ).rowcount
        if updated != 1:
            raise StorageError(f"{name} is being ingested into {store.path} by another process too; this one "
                               "stopped (nothing stored twice): let the other finish")
        store.touch()


def _rows(source_id: int, cells: np.ndarray, shared: list[np.ndarray], per_band: list[np.ndarray]) -> list[Any]:
    """Flat parameters, a row per (cell, band): source, cell, band, the shared columns, the band's columns."""
    n = cells.shape[0]
    ids = cells.astype(np.int64).tolist()
    out: list[Any] = []
    for b, own in enumerate(per_band):
        own = np.atleast_2d(own)
        parts = [[source_id] * n, ids, [b] * n, *(a.tolist() for a in shared), *(a.tolist() for a in own)]
        flat: list[Any] = [None] * (len(parts) * n)
        for k, part in enumerate(parts):
            flat[k :: len(parts)] = part
        out.extend(flat)
    return out


def _read_partials(conn: sqlite3.Connection, source_id: int, bands: int, mode: str) -> Any:
    """The partials committed, added up over the blocks, as ``raster_to_cells`` holds them before finishing."""
    from dggs.raster.stats import Partials

    rows = conn.execute("SELECT cell, covered, count, total, low, high FROM raster_partials WHERE source_id = ? "
                        "ORDER BY cell, band", (source_id,)).fetchall()
    cols = list(zip(*rows, strict=True)) if rows else [()] * 6
    cells = np.array(cols[0][::bands], dtype=np.int64).astype(np.uint64)
    n = cells.shape[0]

    def per_band(k: int) -> np.ndarray:
        out: np.ndarray = np.array(cols[k], dtype=np.float64).reshape(n, bands).T  # None (NULL) is NaN
        return out

    if mode == "center":
        return cells, per_band(3)
    classes = {}
    if mode in ("mode", "fractions"):
        found = conn.execute("SELECT cell, class, area FROM raster_classes WHERE source_id = ? ORDER BY cell, class",
                             (source_id,)).fetchall()
        cell, value, area = (list(c) for c in zip(*found, strict=True)) if found else ([], [], [])
        classes = {"cell": np.array(cell, dtype=np.int64).astype(np.uint64), "value": np.array(value),
                   "area": np.array(area, dtype=np.float64)}
    covered = np.array(cols[1][::bands], dtype=np.float64)
    count = np.array(cols[2][::bands], dtype=np.int64)
    return Partials(cells, covered, per_band(3), per_band(4), per_band(5), count, classes)


def _finish(store: Connection, source_id: int, bands: list[int], level: int, mode: str, total: int, name: str) -> int:
    """The finished rows into ``points`` (and the kept roll-ups), the partials deleted, the source complete: at once."""
    import dggs
    from dggs.raster import finish

    conn = store.conn
    with store.transaction():
        state = conn.execute("SELECT rows_done, complete FROM sources WHERE id = ?", (source_id,)).fetchone()
        if state is None or state[1] or state[0] != total:
            raise StorageError(f"{name} is being ingested into {store.path} by another process too; this one "
                               "stopped (nothing stored twice): let the other finish")
        frame = finish([_read_partials(conn, source_id, len(bands), mode)], bands, level, mode, False)
        names = {column: _column_name(column) for column in frame.columns if column != "cell_id"}
        types = {names[c]: ("INTEGER" if frame[c].dtype.kind in "iub" else "REAL") for c in names}
        _claim(conn, types, store.path)
        store.set_level(level)
        ids = frame["cell_id"].to_numpy().astype(np.uint64)
        lat, lng = dggs.cell_to_latlng(ids) if ids.size else (np.empty(0), np.empty(0))
        parts: list[list[Any]] = [list(dggs.int_to_str(ids)) if ids.size else [], np.asarray(lat).tolist(),
                                  np.asarray(lng).tolist(), list(range(1, ids.size + 1))]
        for column in names:
            values = frame[column].to_numpy()
            parts.append([None if v != v else v for v in values.tolist()])  # NaN is NULL, as every ingest stores it
        width = len(parts)
        flat: list[Any] = [None] * (width * ids.size)
        for k, part in enumerate(parts):
            flat[k::width] = part
        head = (f"INSERT INTO points (cell, lat, lng, source_id, row, part{''.join(', ' + quote(c) for c in types)}) "
                "VALUES ")
        insert_many(conn, head, f"(?, ?, ?, {int(source_id)}, ?, 0{', ?' * len(types)})", flat, width,
                    max_variables(conn))
        levels = kept_levels(conn)
        add_partials(conn, batch_partials(flat, width, types, levels), column_types(conn), store.path)
        conn.execute("DELETE FROM raster_partials WHERE source_id = ?", (source_id,))
        conn.execute("DELETE FROM raster_classes WHERE source_id = ?", (source_id,))
        conn.execute("UPDATE sources SET complete = 1, rows_inserted = ?, updated = ? WHERE id = ?",
                     (int(ids.size), now(), source_id))
        store.touch()
    return int(ids.size)


def _column_name(column: str) -> str:
    """A table column as a store column: ``class_-1.5`` (not an SQL identifier) becomes ``class_m1_5``.

    Examples
    --------
    >>> [_column_name(c) for c in ("value", "band_2", "class_3", "class_-1.5")]
    ['value', 'band_2', 'class_3', 'class_m1_5']
    """
    return column.replace("-", "m").replace(".", "_").replace("+", "")


def _claim(conn: sqlite3.Connection, wanted: dict[str, str], path: str) -> None:
    """Add the value columns ``points`` lacks; refuse one stored with another type (inside the transaction)."""
    have = column_types(conn)
    for column, kind in wanted.items():
        if column in have and have[column] != kind:
            raise DggsValueError(f"{path}: value column {column!r} is stored as {have[column]}, and this raster "
                                 f"gives {kind}; ingest it into another store")
    add_columns(conn, {k: v for k, v in wanted.items() if k not in have})
