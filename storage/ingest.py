"""Turn raw batches into checked rows and commit them, one batch per transaction.

The ingest loop guarantees:

* **Atomic batches.**  A batch's rows, its rejects and the source's progress
  counter (``sources.rows_done``) are written in one transaction, so a
  process killed at any moment leaves only whole batches behind.
* **Exactly once.**  Re-running the same ingest skips the ``rows_done``
  records already committed and carries on from there.
* **No silent loss.**  A bad row either stops the ingest
  (``on_error="fail"``, :class:`~dggs.storage.errors.BadRowError` naming the
  line, column and value) or is skipped *and* recorded in table ``rejects``
  (``on_error="skip"``, with a :class:`~dggs.storage.errors.RejectedRowsWarning`).
"""

from __future__ import annotations

import itertools
import json
import math
import queue
import sqlite3
import threading
import time
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

import dggs
from dggs.errors import DggsValueError, StorageError

from .errors import BadRowError, RejectedRowsWarning
from .readers import RawBatch
from .schema import add_columns, column_types, infer_type, now, quote, sql_type

if TYPE_CHECKING:  # pragma: no cover
    from .store import CellStore

__all__ = ["IngestResult", "prepare", "run_ingest", "make_transformer", "value_types"]

#: Pending rows that trigger a merge into the clustered table (at least; a
#: store of N merged rows merges every N / 4 rows, so that rewriting the
#: table's pages stays proportional to the data ingested).
MERGE_ROWS = 250_000

#: Batches the reader thread may prepare ahead of the writer.
READ_AHEAD = 8

_Bad = dict[int, tuple[str | None, Any, str]]


@dataclass
class IngestResult:
    """What an ingest did.

    Attributes
    ----------
    source : str
        The input's name (file path or stream name).
    rows_read : int
        Input records read by this run (not counting resumed ones).
    rows_inserted : int
        Rows stored by this run (a polygon feature stores one per cell).
    rows_rejected : int
        Records refused by ``on_error="skip"`` in this run.
    rows_resumed : int
        Records skipped because an earlier run had committed them already.
    already_complete : bool
        True if the source had been ingested completely before: nothing done.
    rejects : list of dict
        The first few rejected records (row, line, column, value, reason).
    seconds : float
        Wall time of this run.
    """

    source: str
    rows_read: int = 0
    rows_inserted: int = 0
    rows_rejected: int = 0
    rows_resumed: int = 0
    already_complete: bool = False
    rejects: list[dict] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def rows_per_second(self) -> float:
        """Input records read per second of wall time."""
        return self.rows_read / self.seconds if self.seconds > 0 else float("nan")

    def summary(self) -> str:
        """One line for people, e.g. for the CLI.

        Examples
        --------
        >>> IngestResult("a.csv", rows_read=10, rows_inserted=9, rows_rejected=1).summary()
        'a.csv: read 10 rows, stored 9, rejected 1'
        """
        if self.already_complete:
            return f"{self.source}: already ingested ({self.rows_resumed:,} rows), nothing to do"
        text = f"{self.source}: read {self.rows_read:,} rows, stored {self.rows_inserted:,}"
        if self.rows_rejected:
            text += f", rejected {self.rows_rejected:,}"
        if self.rows_resumed:
            text += f" (resumed after {self.rows_resumed:,} committed earlier)"
        return text


@dataclass
class Prepared:
    """Checked rows of one batch, ready for ``executemany``."""

    rows: list[tuple]
    rejects: list[dict]
    with_parts: bool = False


def make_transformer(crs: Any) -> Any:
    """Return a pyproj transformer from ``crs`` to WGS84 (x, y order), or None.

    Raises
    ------
    DggsValueError
        If pyproj does not know the CRS.

    Examples
    --------
    >>> make_transformer("EPSG:4326") is None
    True
    >>> t = make_transformer("EPSG:3857")
    >>> [round(v, 6) for v in t.transform(0.0, 0.0)]
    [0.0, 0.0]
    """
    if crs is None:
        return None
    from pyproj import CRS, Transformer
    from pyproj.exceptions import CRSError

    try:
        source = CRS.from_user_input(crs)
    except CRSError as exc:
        raise DggsValueError(f"unknown CRS {crs!r}: {exc}") from exc
    if source == CRS.from_epsg(4326):
        return None
    return Transformer.from_crs(source, CRS.from_epsg(4326), always_xy=True)


def _floats(raw: Sequence[Any], name: str, bad: _Bad, text: bool) -> np.ndarray:
    """Parse coordinates to float64; mark unparsable or non-finite entries bad."""
    try:
        arr = np.asarray(raw, dtype=np.float64)
        if arr.ndim != 1:
            raise ValueError
    except (ValueError, TypeError):
        arr = np.empty(len(raw), dtype=np.float64)
        for i, value in enumerate(raw):
            try:
                if isinstance(value, (str, bytes)) and not value.strip():
                    raise ValueError
                arr[i] = float(value)
            except (ValueError, TypeError):
                arr[i] = np.nan
                bad.setdefault(i, (name, value, "is not a number"))
    notfinite = ~np.isfinite(arr)
    if notfinite.any():
        for i in np.flatnonzero(notfinite).tolist():
            bad.setdefault(i, (name, raw[i], "is missing or not finite"))
    return arr


def _convert(raw: Sequence[Any], kind: str, name: str, bad: _Bad, text: bool) -> list[Any]:
    """Convert a raw value column to Python values of SQL type ``kind``.

    Empty text, ``None`` and NaN become NULL; infinities and unparsable
    numbers are bad.
    """
    if kind == "TEXT":
        if text:
            return [value if value != "" else None for value in raw]
        texts: list[Any] = []
        for value in (raw.tolist() if isinstance(raw, np.ndarray) else raw):
            if value is None or (isinstance(value, float) and math.isnan(value)):
                texts.append(None)
            else:
                texts.append(value if isinstance(value, str) else str(value))
        return texts
    arr = raw if isinstance(raw, np.ndarray) else None
    if arr is not None and arr.dtype.kind in "iub":
        return arr.tolist()
    try:
        if text and kind == "INTEGER":
            try:
                return np.asarray(raw, dtype=np.int64).tolist()
            except (ValueError, OverflowError):
                pass
        values = np.asarray(raw, dtype=np.float64)
        if values.ndim != 1:
            raise ValueError
        if np.isfinite(values).all():
            return values.tolist()
        if not np.isinf(values).any():
            return [None if v != v else v for v in values.tolist()]
    except (ValueError, TypeError, OverflowError):
        pass
    out: list[Any] = []
    for i, value in enumerate(raw.tolist() if isinstance(raw, np.ndarray) else raw):
        try:
            if value is None:
                out.append(None)
                continue
            if isinstance(value, (bool, np.bool_)):
                out.append(int(value))
                continue
            if isinstance(value, (str, bytes)):
                value_s = value.strip()
                if not value_s:
                    out.append(None)
                    continue
                if kind == "INTEGER":
                    try:
                        out.append(int(value_s))
                        continue
                    except ValueError:
                        pass
                number = float(value_s)
            elif isinstance(value, int):
                out.append(value)
                continue
            else:
                number = float(value)
            if math.isnan(number):
                out.append(None)
            elif math.isinf(number):
                bad.setdefault(i, (name, value, "is not finite"))
                out.append(None)
            else:
                out.append(number)
        except (ValueError, TypeError, OverflowError):
            bad.setdefault(i, (name, value, f"is not a number (column type {kind})"))
            out.append(None)
    return out


def value_types(
    batch: RawBatch, existing: Mapping[str, str], declared: Mapping[str, str]
) -> dict[str, str]:
    """Return the SQL types of value columns that ``points`` does not have yet."""
    new: dict[str, str] = {}
    for name, raw in batch.values.items():
        if name in existing:
            continue
        if name in declared:
            new[name] = declared[name]
        elif isinstance(raw, np.ndarray) and raw.dtype.kind in "iub":
            new[name] = "INTEGER"
        elif isinstance(raw, np.ndarray) and raw.dtype.kind == "f":
            new[name] = "REAL"
        elif isinstance(raw, np.ndarray) and raw.dtype.kind in "US":
            new[name] = "TEXT"
        else:
            sample = raw.tolist() if isinstance(raw, np.ndarray) else list(raw)
            new[name] = infer_type(sample, batch.text)
    return new


def prepare(
    batch: RawBatch,
    level: int,
    types: Mapping[str, str],
    transformer: Any,
) -> Prepared:
    """Convert and check one batch; compute the cells of its good rows.

    Returns the rows to insert (cell, lat, lng, row, [part,] then value
    columns in ``types`` order) and the rejects.
    """
    n = len(batch)
    bad: _Bad = dict(batch.bad)
    lat_bad: _Bad = {}
    lng_bad: _Bad = {}
    lat = _floats(batch.lat, "lat", lat_bad, batch.text)
    lng = _floats(batch.lng, "lng", lng_bad, batch.text)
    if transformer is not None:
        ok = np.isfinite(lat) & np.isfinite(lng)
        x, y = transformer.transform(np.where(ok, lng, 0.0), np.where(ok, lat, 0.0))
        lng, lat = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
        failed = ok & ~(np.isfinite(lat) & np.isfinite(lng))
        for i in np.flatnonzero(failed).tolist():
            lat_bad.setdefault(i, ("lat", (batch.lat[i], batch.lng[i]), "cannot be transformed to WGS84"))
    with np.errstate(invalid="ignore"):
        for i in np.flatnonzero(np.abs(lat) > 90).tolist():
            lat_bad.setdefault(i, ("lat", batch.lat[i], "is out of range -90..90"))
        for i in np.flatnonzero(np.abs(lng) > 180).tolist():
            lng_bad.setdefault(i, ("lng", batch.lng[i], "is out of range -180..180"))
    for found in (lat_bad, lng_bad):  # report the first bad column, left to right
        for i, problem in found.items():
            bad.setdefault(i, problem)
    columns = [_convert(batch.values[name], kind, name, bad, batch.text) for name, kind in types.items()]

    good = np.ones(n, dtype=bool)
    if bad:
        good[list(bad)] = False
    keep = np.flatnonzero(good)
    all_good = len(keep) == n
    known = np.asarray(batch.cells, dtype=object) if batch.cells is not None else None
    if all_good and known is None:  # the common case: every row good, no cell given
        cells: Any = dggs.latlng_to_cell(lat, lng, level) if n else np.empty(0, dtype=object)
    else:
        cells = np.empty(n, dtype=object)
        todo = keep if known is None else keep[known[keep] == ""]
        if len(todo):
            cells[todo] = dggs.latlng_to_cell(lat[todo], lng[todo], level)
        if known is not None:
            given = keep[known[keep] != ""]
            cells[given] = known[given]
    # source_id is bound in the SQL text, and part only when there are parts:
    # fewer parameters per row make the inserts faster.
    with_parts = batch.parts is not None
    if all_good:
        parts = [cells.tolist(), lat.tolist(), lng.tolist(), batch.rows, *columns]
        if with_parts:
            parts.insert(4, batch.parts)
    else:
        idx = keep.tolist()
        parts = [
            cells[keep].tolist(),
            lat[keep].tolist(),
            lng[keep].tolist(),
            [batch.rows[i] for i in idx],
            *[[col[i] for i in idx] for col in columns],
        ]
        if with_parts:
            parts.insert(4, [batch.parts[i] for i in idx])  # type: ignore[index]
    rows = list(zip(*parts))
    rejects = []
    for i in sorted(bad):
        column, value, reason = bad[i]
        rejects.append(
            {
                "row": batch.rows[i],
                "line": batch.lines[i] if batch.lines is not None else None,
                "column": column,
                "value": value,
                "reason": reason,
                "index": i,
            }
        )
    return Prepared(rows=rows, rejects=rejects, with_parts=with_parts)


def _jsonable(value: Any) -> Any:
    if hasattr(value, "item") and not isinstance(value, (str, bytes)):
        try:
            return value.item()
        except (ValueError, AttributeError):
            return str(value)
    return value


def run_ingest(
    store: CellStore,
    *,
    key: str,
    kind: str,
    name: str,
    params: dict[str, Any],
    batches: Callable[[int, dict[str, str]], Iterator[RawBatch]],
    level: int,
    declared: Mapping[str, str],
    crs: Any,
    on_error: str,
    replace: bool,
    progress: Callable[[int], Any] | None,
    file_info: Mapping[str, Any] | None = None,
    threaded: bool = True,
) -> IngestResult:
    """Ingest batches into ``store`` with per-batch transactions and resume.

    ``batches(skip, types)`` must yield the input's batches after its first
    ``skip`` records, the same way on every call; ``types`` is the live
    mapping of value column types, filled in as they become known.  With
    ``threaded``, batches are read in a background thread (not for user
    iterables, which may be tied to their thread, like sqlite3 cursors).
    """
    if on_error not in ("fail", "skip"):
        raise DggsValueError(f"on_error must be 'fail' or 'skip', not {on_error!r}")
    declared = {name_: sql_type(t) for name_, t in declared.items()}
    store._check_level_for_ingest(level)
    transformer = make_transformer(crs)
    params = {**params, "level": level, "crs": None if crs is None else str(crs)}
    start = time.perf_counter()
    source = store._open_source(key, kind, name, params, file_info or {}, replace)
    result = IngestResult(source=name, rows_resumed=source["rows_done"])
    if source["complete"]:
        result.already_complete = True
        if progress is not None and source["rows_done"]:
            progress(source["rows_done"])
        return result
    if progress is not None and source["rows_done"]:
        progress(source["rows_done"])
    conn = store.conn
    source_id = source["id"]
    pending = store._pending_count()
    merged = int(conn.execute("SELECT count(*) FROM points").fetchone()[0])
    missing = {k: v for k, v in declared.items() if k not in column_types(conn)}
    if missing:  # declared columns exist even if no row arrives
        with store._transaction():
            add_columns(conn, missing)
    done = source["rows_done"]
    known = column_types(conn)  # shared with the reader, which may parse faster once typed
    work = _Producer(
        batches(source["rows_done"], known), level, known, declared, transformer, threaded
    )
    try:
        for batch, prepared, types, new in work:
            if prepared.rejects and on_error == "fail":
                first = prepared.rejects[0]
                raise BadRowError(
                    name, first["row"], first["line"], first["column"],
                    _jsonable(first["value"]), first["reason"],
                )
            _write_batch(store, source_id, level, batch, prepared, types, new, done, name)
            done += batch.consumed
            result.rows_read += batch.consumed
            result.rows_inserted += len(prepared.rows)
            result.rows_rejected += len(prepared.rejects)
            for r in prepared.rejects[: max(0, 5 - len(result.rejects))]:
                result.rejects.append({k: _jsonable(v) for k, v in r.items() if k != "index"})
            pending += len(prepared.rows)
            if progress is not None:
                progress(batch.consumed)
            if pending >= max(store.merge_rows, merged // 4):
                store.merge()
                merged += pending
                pending = 0
    finally:
        work.stop()
    with store._transaction():
        store._merge_pending()
        conn.execute("UPDATE sources SET complete = 1, updated = ? WHERE id = ?", (now(), source_id))
        store._touch()
    result.seconds = time.perf_counter() - start
    if result.rows_rejected:
        shown = "; ".join(
            f"row {r['row']}" + (f" (line {r['line']})" if r["line"] else "")
            + (f" column {r['column']!r} {r['value']!r}" if r["column"] else "")
            + f" {r['reason']}"
            for r in result.rejects[:3]
        )
        warnings.warn(
            f"{name}: skipped {result.rows_rejected:,} bad row(s), kept in table rejects; "
            f"first: {shown}",
            RejectedRowsWarning,
            stacklevel=3,
        )
    return result


class _Producer:
    """Read and prepare batches in a background thread, a few ahead.

    Parsing, checking and binning (Python and numpy) overlap with SQLite
    writing, which releases the GIL.  Only the calling thread touches the
    database; errors in the thread are re-raised in the caller.  With
    ``threaded=False`` the batches are prepared in the caller's thread.
    """

    _DONE = object()

    def __init__(
        self,
        batches: Iterator[RawBatch],
        level: int,
        existing: dict[str, str],
        declared: Mapping[str, str],
        transformer: Any,
        threaded: bool = True,
    ) -> None:
        self._batches = batches
        self._threaded = threaded
        self._args = (level, transformer)
        self._types = existing  # the same dict the reader sees
        self._declared = declared
        self._queue: queue.Queue = queue.Queue(maxsize=READ_AHEAD)
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._run, name="dggs-ingest-reader", daemon=True)
        if threaded:
            self._thread.start()

    def _put(self, item: Any) -> bool:
        while not self._stopped.is_set():
            try:
                self._queue.put(item, timeout=0.1)
                return True
            except queue.Full:
                continue
        return False

    def _prepared(self) -> Iterator[tuple[RawBatch, Prepared, dict[str, str], dict[str, str]]]:
        level, transformer = self._args
        for batch in self._batches:
            new = value_types(batch, self._types, self._declared)
            self._types.update(new)
            types = {name: self._types[name] for name in batch.values}
            yield batch, prepare(batch, level, types, transformer), types, new

    def _run(self) -> None:
        try:
            for item in self._prepared():
                if not self._put(item):
                    return
            self._put(self._DONE)
        except BaseException as exc:  # noqa: BLE001 - handed to the caller
            self._put(exc)

    def __iter__(self) -> Iterator[tuple[RawBatch, Prepared, dict[str, str], dict[str, str]]]:
        if not self._threaded:
            yield from self._prepared()
            return
        while True:
            item = self._queue.get()
            if item is self._DONE:
                return
            if isinstance(item, BaseException):
                raise item
            yield item

    def stop(self) -> None:
        """Ask the thread to finish and wait for it."""
        self._stopped.set()
        if self._threaded:
            self._thread.join(timeout=10)


def _write_batch(
    store: CellStore,
    source_id: int,
    level: int,
    batch: RawBatch,
    prepared: Prepared,
    types: Mapping[str, str],
    new: Mapping[str, str],
    done: int,
    name: str,
) -> None:
    """Commit one batch: its rows, its rejects and the source's progress, atomically.

    The progress update is a compare-and-set on ``rows_done``: if another
    process is ingesting the same source, this one stops instead of storing
    rows twice.
    """
    conn = store.conn
    part = "?" if prepared.with_parts else "0"
    head = (
        f"INSERT INTO points_pending (cell, lat, lng, source_id, row, part"
        f"{''.join(', ' + quote(c) for c in types)}) VALUES "
    )
    one = f"(?, ?, ?, {int(source_id)}, ?, {part}{', ?' * len(types)})"
    with store._transaction():
        if new:
            have = column_types(conn)
            add_columns(conn, {k: v for k, v in new.items() if k not in have})
        store._set_level(level)
        _insert_many(conn, head, one, prepared.rows, _max_variables(conn))
        if prepared.rejects:
            conn.executemany(
                'INSERT INTO rejects (source_id, row, line, "column", value, reason, record) '
                "VALUES (?, ?, ?, ?, ?, ?, ?)",
                [
                    (
                        source_id,
                        r["row"],
                        r["line"],
                        r["column"],
                        json.dumps(_jsonable(r["value"]), default=str),
                        r["reason"],
                        json.dumps(
                            {k: _jsonable(v) for k, v in batch.record(r["index"]).items()}, default=str
                        ),
                    )
                    for r in prepared.rejects
                ],
            )
        updated = conn.execute(
            "UPDATE sources SET rows_done = rows_done + ?, rows_inserted = rows_inserted + ?, "
            "rows_rejected = rows_rejected + ?, updated = ? WHERE id = ? AND rows_done = ?",
            (batch.consumed, len(prepared.rows), len(prepared.rejects), now(), source_id, done),
        ).rowcount
        if updated != 1:
            raise StorageError(
                f"{name} is being ingested into {store.path} by another process too; "
                "this one stopped (nothing stored twice): let the other finish"
            )
        store._touch()


def _max_variables(conn: sqlite3.Connection) -> int:
    """Return how many ``?`` parameters one statement may hold."""
    try:
        return int(conn.getlimit(sqlite3.SQLITE_LIMIT_VARIABLE_NUMBER))
    except (AttributeError, sqlite3.Error):  # Python < 3.11
        return 999


def _insert_many(conn: sqlite3.Connection, head: str, one: str, rows: list[tuple], limit: int) -> None:
    """Insert ``rows`` with multi-row ``VALUES`` statements, as few as the limit allows.

    Twice as fast as ``executemany`` (one statement step per few thousand
    rows), and the GIL is released for the whole step, so the reader thread
    can work meanwhile.
    """
    if not rows:
        return
    width = len(rows[0])
    per = max(1, limit // max(width, 1))
    full = None
    for start in range(0, len(rows), per):
        chunk = rows[start : start + per]
        if len(chunk) == per:
            full = full or head + ",".join([one] * per)
            sql = full
        else:
            sql = head + ",".join([one] * len(chunk))
        conn.execute(sql, list(itertools.chain.from_iterable(chunk)))
