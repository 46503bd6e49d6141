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

import json
import sqlite3
import time
import warnings
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

from dggs.errors import DggsValueError, StorageError

from .bulk import insert_many, max_variables
from .connection import Connection
from .convert import Prepared, jsonable
from .crs import make_transformer
from .errors import BadRowError, RejectedRowsWarning
from .producer import Producer
from .progress import Bar, check_progress, shows
from .projection import grid_locate
from .readers import RawBatch
from .rollup_keep import add_partials, check_levels, kept_levels
from .schema import add_columns, column_types, now, quote, sql_type
from .sources import open_source

__all__ = ["IngestOptions", "IngestResult", "run_ingest", "MERGE_ROWS"]

#: Pending rows that trigger a merge into the clustered table (at least; a
#: store of N merged rows merges every N / 4 rows, so that rewriting the
#: table's pages stays proportional to the data ingested).
MERGE_ROWS = 250_000

@dataclass(frozen=True)
class IngestOptions:
    """Settings shared by every ``ingest_*`` method, checked before the store is touched.

    Attributes
    ----------
    batch_size : int
        Input records per transaction, at least 1.
    on_error : {"fail", "skip"}
        Stop at the first bad row, or skip (and record) bad rows.
    replace : bool
        Delete what an earlier ingest of the same source stored first.
    crs : str or pyproj.CRS, optional
        CRS of the coordinates (default WGS84 lat/lng).
    progress : bool or callable, optional
        A bar on stderr (``True``; ``None``: on a terminal, after a moment;
        ``False``: none), or called with the number of input records after each
        batch (see :mod:`dggs.storage.progress`).
    source : str, optional
        Name that makes an iterable or arrays resumable.

    Raises
    ------
    DggsValueError
        For a batch size that is not a positive integer or an unknown
        ``on_error``.

    Examples
    --------
    >>> IngestOptions(batch_size=0)
    Traceback (most recent call last):
    ...
    dggs.errors.DggsValueError: batch_size must be a whole number of rows >= 1, not 0
    """

    batch_size: int = 10_000
    on_error: str = "fail"
    replace: bool = False
    crs: Any = None
    progress: Callable[[int], Any] | bool | None = None
    source: str | None = None

    def __post_init__(self) -> None:
        size = self.batch_size
        if isinstance(size, bool) or not isinstance(size, int) or size < 1:
            if not (hasattr(size, "__index__") and not isinstance(size, bool) and int(size) >= 1):
                raise DggsValueError(f"batch_size must be a whole number of rows >= 1, not {size!r}")
            object.__setattr__(self, "batch_size", int(size))
        if self.on_error not in ("fail", "skip"):
            raise DggsValueError(f"on_error must be 'fail' or 'skip', not {self.on_error!r}")
        if not isinstance(self.replace, bool):
            raise DggsValueError(f"replace must be True or False, not {self.replace!r}")
        check_progress(self.progress, "a row count")
        if self.source is not None and not isinstance(self.source, str):
            raise DggsValueError(f"source must be a name (str), not {self.source!r}")


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


def run_ingest(
    store: Connection,
    *,
    key: str,
    kind: str,
    name: str,
    params: dict[str, Any],
    batches: Callable[[int, dict[str, str]], Iterator[RawBatch]],
    level: int,
    declared: Mapping[str, str],
    options: IngestOptions,
    merge_rows: int = 250_000,
    file_info: Mapping[str, Any] | None = None,
    threaded: bool = True,
    ordered: bool = False,
    total: Callable[[], int | None] | None = None,
) -> IngestResult:
    """Ingest batches into ``store`` with per-batch transactions and resume.

    ``total()``, when given, counts the input's records for the progress bar's
    total and ETA (asked only when a bar is drawn).

    ``batches(skip, types)`` must yield the input's batches after its first
    ``skip`` records, the same way on every call; ``types`` is the live
    mapping of value column types, filled in as they become known.  With
    ``threaded``, batches are read in a background thread (not for user
    iterables, which may be tied to their thread, like sqlite3 cursors).
    With ``ordered``, the batches come in cell id order, as one sorted run:
    their rows go straight into the clustered ``points`` table, each batch
    touching only its own key range, instead of through ``points_pending``
    and a merge that sorts in SQLite.

    Raises
    ------
    BadRowError
        On the first bad row with ``on_error="fail"`` (earlier batches stay committed).
    StorageError
        If another process ingests the same source at the same time.
    """
    declared = {name_: sql_type(t) for name_, t in declared.items()}
    store.check_level_for_ingest(level)
    rollups = check_levels(kept_levels(store.conn), level)  # kept roll-ups no finer than the ingest's level
    _check_case(store, name, [*declared, *params.get("values", ())])
    transformer = make_transformer(options.crs)
    crs = options.crs
    params = {**params, "level": level, "crs": None if crs is None else str(crs)}
    start = time.perf_counter()
    source = open_source(store, key, kind, name, params, file_info or {}, options.replace)
    result = IngestResult(source=name, rows_resumed=source["rows_done"])
    if source["complete"]:
        result.already_complete = True
        if callable(options.progress) and source["rows_done"]:
            options.progress(source["rows_done"])
        return result
    count = total() if total is not None and shows(options.progress) else None  # counted only for a bar
    with Bar(options.progress, total=count, unit="rows", desc="binning") as bar:
        if source["rows_done"]:
            bar.update(source["rows_done"])
        _ingest_batches(store, source, level, declared, options, merge_rows, batches, threaded, ordered, rollups,
                        transformer, name, result, bar)
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
            stacklevel=5,
        )
    return result


def _ingest_batches(
    store: Connection, source: Mapping[str, Any], level: int, declared: Mapping[str, str], options: IngestOptions,
    merge_rows: int, batches: Callable[[int, dict[str, str]], Iterator[RawBatch]], threaded: bool, ordered: bool,
    rollups: Any, transformer: Any, name: str, result: IngestResult, bar: Bar,
) -> None:
    """The batch loop of :func:`run_ingest`, then the final merge and the source marked complete."""
    on_error = options.on_error
    conn = store.conn
    source_id = source["id"]
    pending = store.pending_count()
    merged = int(conn.execute("SELECT count(*) FROM points").fetchone()[0])
    if any(k not in column_types(conn) for k in declared):  # declared columns exist even if no row arrives
        with store.transaction():
            _claim_columns(conn, declared, store.path)
    done = source["rows_done"]
    known = column_types(conn)  # shared with the reader, which may parse faster once typed
    work = Producer(
        batches(source["rows_done"], known), level, known, declared, transformer, threaded, name,
        options.batch_size, rollups, grid_locate(store.projection),
    )
    try:
        for batch, prepared, types, new in work:
            if prepared.rejects and on_error == "fail":
                first = prepared.rejects[0]
                raise BadRowError(
                    name, first["row"], first["line"], first["column"],
                    jsonable(first["value"]), first["reason"],
                )
            _write_batch(store, source_id, level, batch, prepared, types, new, done, name, ordered)
            done += batch.consumed
            result.rows_read += batch.consumed
            result.rows_inserted += len(prepared)
            result.rows_rejected += len(prepared.rejects)
            for r in prepared.rejects[: max(0, 5 - len(result.rejects))]:
                result.rejects.append({k: jsonable(v) for k, v in r.items() if k != "index"})
            pending += len(prepared)
            bar.update(batch.consumed)
            if pending >= max(merge_rows, merged // 4):
                with store.transaction(), bar.heartbeat():
                    store.merge_pending()
                merged += pending
                pending = 0
    finally:
        work.stop()
    bar.stage("sorting into the store")
    with store.transaction(), bar.heartbeat():
        store.merge_pending()
        conn.execute("UPDATE sources SET complete = 1, updated = ? WHERE id = ?", (now(), source_id))
        store.touch()


def _check_case(store: Connection, name: str, columns: list[str]) -> None:
    """Refuse value columns that differ from a stored one only in case."""
    have = {c.lower(): c for c in store.columns}
    for column in columns:
        other = have.get(column.lower())
        if other is not None and other != column:
            raise DggsValueError(
                f"{name}: value column {column!r} differs only in case from {other!r} "
                "(SQLite column names ignore case); rename one of them"
            )


def _write_batch(
    store: Connection,
    source_id: int,
    level: int,
    batch: RawBatch,
    prepared: Prepared,
    types: Mapping[str, str],
    new: Mapping[str, str],
    done: int,
    name: str,
    ordered: bool = False,
) -> None:
    """Commit one batch: its rows, its rejects and the source's progress, atomically.

    The rows go to ``points_pending``, or with ``ordered`` (rows in key
    order) straight into ``points``.

    The progress update is a compare-and-set on ``rows_done``: if another
    process is ingesting the same source, this one stops instead of storing
    rows twice.
    """
    conn = store.conn
    part = "?" if prepared.with_parts else "0"
    head = (
        f"INSERT INTO {'points' if ordered else 'points_pending'} (cell, lat, lng, source_id, row, part"
        f"{''.join(', ' + quote(c) for c in types)}) VALUES "
    )
    one = f"(?, ?, ?, {int(source_id)}, ?, {part}{', ?' * len(types)})"
    with store.transaction():
        _claim_columns(conn, {**types, **new}, store.path)
        store.set_level(level)
        insert_many(conn, head, one, prepared.values, prepared.width, max_variables(conn))
        add_partials(conn, prepared.partials, column_types(conn), store.path)
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
                        json.dumps(jsonable(r["value"]), default=str),
                        r["reason"],
                        json.dumps(
                            {k: jsonable(v) for k, v in batch.record(r["index"]).items()}, default=str
                        ),
                    )
                    for r in prepared.rejects
                ],
            )
        updated = conn.execute(
            "UPDATE sources SET rows_done = rows_done + ?, rows_inserted = rows_inserted + ?, "
            "rows_rejected = rows_rejected + ?, updated = ? WHERE id = ? AND rows_done = ?",
            (batch.consumed, len(prepared), len(prepared.rejects), now(), source_id, done),
        ).rowcount
        if updated != 1:
            raise StorageError(
                f"{name} is being ingested into {store.path} by another process too; "
                "this one stopped (nothing stored twice): let the other finish"
            )
        store.touch()


def _claim_columns(conn: sqlite3.Connection, wanted: Mapping[str, str], path: str) -> None:
    """Add the missing value columns, checking the stored ones (inside a write transaction).

    The types were read before the transaction: another writer may have
    created a column since, with another type, which would silently convert
    this batch's values (SQLite's type affinity); so they are read again here.

    Raises
    ------
    DggsValueError
        If a stored column has another type than this ingest's.
    """
    have = column_types(conn)
    for name, kind in wanted.items():
        if name in have and have[name] != sql_type(kind):
            raise DggsValueError(
                f"{path}: value column {name!r} is stored as {have[name]}, not {sql_type(kind)} "
                "(another ingest created it meanwhile); declare its type to match, or use another store"
            )
    add_columns(conn, {k: v for k, v in wanted.items() if k not in have})
