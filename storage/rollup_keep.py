"""Roll-ups kept in the file: per-cell partials at chosen levels, written with every batch.

A roll-up of a whole store reads every row (1.6M rows to level 10: about a
second in SQLite, where pandas groups an array in memory in a tenth of that).
A store told to keep roll-ups at some levels (:meth:`CellStore.keep_rollups`)
holds, in table ``rollups``, one row per non-empty cell of each such level:

* ``rows``: the rows under the cell;
* for each numeric value column ``c``: ``c:n`` (non-NULL values), ``c:sum``,
  ``c:min`` and ``c:max``.

Each ingest batch computes its partials in numpy in the reader thread
(:func:`batch_partials`) and adds them in the same transaction as its rows
(:func:`add_partials`), so they are exactly as current and as atomic as the
rows; deleting a source rebuilds them from the rows (:func:`rebuild`).  A
roll-up to a kept level then reads its cells, and a coarser one regroups
the nearest finer kept level's, in SQL (:mod:`dggs.storage.rollup_serve`).

Only what is exact is read from them: counts, min and max always; sums and
means of an INTEGER column while every partial sum is an integer and
``values x largest |value| < 2**53`` (where SQLite's own ``sum`` and ``avg``
are exact, as :mod:`dggs.storage.rollup_memo` rules); sums and means of a
REAL column always: a REAL column's partials also hold ``c:x``, the exact sum
as an expansion (:mod:`dggs.storage.rollup_exact`), and ``c:sum`` is its
correctly rounded value, the sum the rows give (:mod:`dggs.storage.rollup_columns`).
Stores whose kept roll-ups predate ``c:x`` (no ``meta.rollup_exact_sums``,
schema version 2) are read as they are, their REAL sums from the rows; their
first write (an ingest batch, ``keep_rollups``, ``delete_source``) rebuilds
the partials from the rows and marks them (schema version 3, which older
dggs do not open: they would add REAL sums inexactly).
Rows written with raw SQL, not through the store, are not seen: keep the
levels again (which rebuilds) after such writes; :meth:`CellStore.check`
compares the kept roll-ups with the rows.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

import dggs
from dggs.errors import LevelError, LevelMismatchError, StorageError

from .bulk import insert_many, max_variables
from .rollup_exact import of_groups
from .schema import column_types, quote

__all__ = [
    "KEPT_KEY",
    "EXACT_KEY",
    "exact_name",
    "exact_sums",
    "BatchPartials",
    "kept_levels",
    "check_levels",
    "keep",
    "rebuild",
    "batch_partials",
    "add_partials",
    "numeric",
    "parts_of",
    "part_names",
]

#: The ``meta`` key listing the kept levels, finest first ("10,8").
KEPT_KEY = "rollup_levels"
#: The ``meta`` key set ("1") when the REAL partials hold exact sums (``c:x``); absent in older stores.
EXACT_KEY = "rollup_exact_sums"
#: The schema version of a store keeping roll-ups with exact REAL sums (2: kept roll-ups without them).
KEPT_SCHEMA_VERSION = 3

_TABLE = "rollups"
#: SQLite's INTEGER range: a larger partial sum is stored as REAL (and so never served as exact).
_INT64 = (-(2**63), 2**63 - 1)


def numeric(types: Mapping[str, str]) -> dict[str, str]:
    """The value columns whose partials are kept: INTEGER and REAL ones."""
    return {name: kind for name, kind in types.items() if kind in ("INTEGER", "REAL")}


def part_names(column: str) -> tuple[str, str, str, str]:
    """The ``rollups`` columns of value column ``column``: non-NULL count, sum, min, max."""
    return (f"{column}:n", f"{column}:sum", f"{column}:min", f"{column}:max")


def exact_name(column: str) -> str:
    """The ``rollups`` column of a REAL value column's exact sum (an expansion BLOB)."""
    return f"{column}:x"


def parts_of(column: str, kind: str) -> tuple[str, ...]:
    """Every ``rollups`` column of value column ``column``: n, sum, min, max, and for REAL the exact sum."""
    return (*part_names(column), exact_name(column)) if kind == "REAL" else part_names(column)


def exact_sums(conn: sqlite3.Connection) -> bool:
    """Whether the kept REAL partials hold exact sums (stores keeping roll-ups before them do not)."""
    return conn.execute("SELECT 1 FROM meta WHERE key = ? AND value = '1'", (EXACT_KEY,)).fetchone() is not None


def kept_levels(conn: sqlite3.Connection) -> tuple[int, ...]:
    """The kept levels, finest first (none: an empty tuple)."""
    row = conn.execute("SELECT value FROM meta WHERE key = ?", (KEPT_KEY,)).fetchone()
    if row is None or not row[0]:
        return ()
    return tuple(sorted((int(v) for v in row[0].split(",")), reverse=True))


def check_levels(levels: Any, stored: int | None) -> tuple[int, ...]:
    """``levels`` as distinct ints, finest first, each 0..MAX_LEVEL and no finer than ``stored``.

    Raises
    ------
    LevelError
        A level that is not a whole number 0..MAX_LEVEL (naming it).
    LevelMismatchError
        A level finer than the stored level.
    """
    if isinstance(levels, (int, np.integer)) and not isinstance(levels, bool):
        levels = [levels]
    out = set()
    for level in levels:
        if isinstance(level, bool) or not isinstance(level, (int, np.integer)) or not 0 <= level <= dggs.MAX_LEVEL:
            raise LevelError(f"roll-up level {level!r} is not a level 0..{dggs.MAX_LEVEL}")
        if stored is not None and level > stored:
            raise LevelMismatchError(
                f"roll-up level {int(level)} is finer than the stored level {stored}: keep levels 0..{stored}"
            )
        out.add(int(level))
    return tuple(sorted(out, reverse=True))


def _ensure_table(conn: sqlite3.Connection, types: Mapping[str, str]) -> None:
    """Create ``rollups`` and add the partial columns of numeric ``types`` it lacks (in a transaction)."""
    conn.execute(
        f"CREATE TABLE IF NOT EXISTS {_TABLE} (level INTEGER NOT NULL, cell TEXT NOT NULL, "
        "rows INTEGER NOT NULL, PRIMARY KEY (level, cell)) WITHOUT ROWID"
    )
    have = {row[1] for row in conn.execute(f"PRAGMA table_info({_TABLE})")}
    for column, kind in numeric(types).items():
        n, total, low, high = part_names(column)
        if kind == "REAL" and exact_name(column) not in have:
            conn.execute(f"ALTER TABLE {_TABLE} ADD COLUMN {quote(exact_name(column))} BLOB")
        if n in have:
            continue
        # min and max take the column's type, so SQLite stores them as it stores the values
        # (-0.0 as 0.0 in a REAL column, 2.0 as 2 in an INTEGER one); the sum has no type,
        # so a REAL sum (of fractions, or past the 64-bit range) stays REAL and is never served.
        conn.execute(f"ALTER TABLE {_TABLE} ADD COLUMN {quote(n)} INTEGER NOT NULL DEFAULT 0")
        conn.execute(f"ALTER TABLE {_TABLE} ADD COLUMN {quote(total)}")
        conn.execute(f"ALTER TABLE {_TABLE} ADD COLUMN {quote(low)} {kind}")
        conn.execute(f"ALTER TABLE {_TABLE} ADD COLUMN {quote(high)} {kind}")


def keep(conn: sqlite3.Connection, levels: tuple[int, ...]) -> None:
    """Keep roll-ups at ``levels`` (checked, finest first), built from the rows (inside a write transaction).

    No levels drop the table.  Keeping roll-ups marks the store schema version 2,
    so a dggs that does not know them (and would not keep them current) refuses to open it.
    """
    if not levels:
        conn.execute(f"DROP TABLE IF EXISTS {_TABLE}")
        conn.execute("DELETE FROM meta WHERE key IN (?, ?)", (KEPT_KEY, EXACT_KEY))
        conn.execute("UPDATE meta SET value = '1' WHERE key = 'schema_version'")
        return
    conn.execute("INSERT OR REPLACE INTO meta (key, value) VALUES (?, ?)", (KEPT_KEY, ",".join(map(str, levels))))
    rebuild(conn)


def _from_rows(level: int, table: str, columns: Mapping[str, str], summed: str = "sum") -> str:
    """SELECT of one level's partials from the rows: cell, rows, then n, sum, min, max per column.

    ``summed`` is ``sum``, or ``total`` (a REAL sum) where an integer sum overflows.  A REAL column's
    sum is NULL there and its exact sum follows its max (``dggs_xsum``): :func:`_round_sums` fills the sum.
    """
    parts = "".join(
        f", count({c}), {summed}({c}), min({c}), max({c})" if kind != "REAL"
        else f", count({c}), NULL, min({c}), max({c}), dggs_xsum({c})"  # the rounded sum: from the exact one
        for c, kind in ((quote(name), kind) for name, kind in columns.items())
    )
    return f"SELECT substr(cell, 1, {level + 1}) AS c, count(*){parts} FROM {table} GROUP BY c"


def rebuild(conn: sqlite3.Connection) -> None:
    """Compute every kept level's partials from the rows again (inside a write transaction)."""
    levels = kept_levels(conn)
    if not levels:
        return
    types = numeric(column_types(conn))
    _ensure_table(conn, types)
    conn.execute(f"DELETE FROM {_TABLE}")
    pending = conn.execute("SELECT 1 FROM points_pending LIMIT 1").fetchone() is not None
    table = "all_points" if pending else "points"
    names = ", ".join(["cell", "rows", *(quote(p) for c, kind in types.items() for p in parts_of(c, kind))])
    conn.execute("INSERT OR REPLACE INTO meta (key, value) VALUES (?, '1')", (EXACT_KEY,))
    conn.execute("UPDATE meta SET value = ? WHERE key = 'schema_version'", (str(KEPT_SCHEMA_VERSION),))
    for level in levels:
        insert = f"INSERT INTO {_TABLE} (level, {names}) SELECT {level}, * FROM ({{}})"
        try:
            conn.execute(insert.format(_from_rows(level, table, types)))
        except sqlite3.OperationalError as exc:  # an integer sum past int64: those sums kept as REAL
            if "overflow" not in str(exc):
                raise
            conn.execute(insert.format(_from_rows(level, table, types, "total")))
            for column, kind in types.items():
                if kind == "INTEGER":
                    try:  # the columns whose sums fit are kept exact
                        _exact_sums(conn, level, table, column)
                    except sqlite3.OperationalError as again:
                        if "overflow" not in str(again):
                            raise
    _round_sums(conn, types)


def _round_sums(conn: sqlite3.Connection, types: Mapping[str, str]) -> None:
    """Set each REAL column's kept sum to the correctly rounded value of its exact sum."""
    for column, kind in types.items():
        if kind == "REAL":
            total, exact = quote(part_names(column)[1]), quote(exact_name(column))
            conn.execute(f"UPDATE {_TABLE} SET {total} = dggs_xround({exact})")


def _exact_sums(conn: sqlite3.Connection, level: int, table: str, column: str) -> None:
    total = quote(part_names(column)[1])
    c = quote(column)
    conn.execute(
        f"UPDATE {_TABLE} SET {total} = p.s FROM (SELECT substr(cell, 1, {level + 1}) AS k, sum({c}) AS s "
        f"FROM {table} GROUP BY k) AS p WHERE level = {level} AND cell = p.k"
    )


@dataclass
class BatchPartials:
    """One batch's partials per kept level: flat parameters ``level, cell, rows, (n, sum, min, max) per column``."""

    levels: tuple[int, ...]
    columns: tuple[str, ...]
    params: list[Any]
    kinds: tuple[str, ...] = ()

    @property
    def width(self) -> int:
        """Parameters a cell: level, cell, rows, then n, sum, min, max (and a REAL column's exact sum)."""
        return 3 + sum(5 if kind == "REAL" else 4 for kind in self.kinds)


def batch_partials(
    values: list[Any], width: int, types: Mapping[str, str], levels: tuple[int, ...], ids: Any = None
) -> BatchPartials | None:
    """The partials of one prepared batch (flat rows of ``width``, value columns last, in ``types`` order).

    ``ids``: the rows' cells as integer ids, where known (``Prepared.ids``): the string ids are not parsed.
    """
    if not levels:
        return None
    columns = tuple(numeric(types))
    out = BatchPartials(levels, columns, [], tuple(types[c] for c in columns))
    if not values:
        return out
    offset = width - len(types)
    where = {name: offset + k for k, name in enumerate(types)}
    if ids is None:
        ids = np.asarray(dggs.str_to_int(np.asarray(values[0::width])), dtype=np.uint64)
    order = None
    if ids.shape[0] > 1 and not bool(np.all(ids[1:] >= ids[:-1])):  # ordered ingests come sorted already
        order = np.argsort(ids, kind="stable")
        ids = ids[order]
    cols = [_sorted_column(values[where[c] :: width], types[c], order) for c in columns]
    for level in levels:
        keys = np.asarray(dggs.cell_to_parent(ids, level), dtype=np.uint64)
        starts = np.flatnonzero(np.concatenate([[True], keys[1:] != keys[:-1]]))
        rows = np.diff(np.append(starts, keys.shape[0])).tolist()
        parts: list[list[Any]] = [[level] * len(rows), dggs.int_to_str(keys[starts]).tolist(), rows]
        for col in cols:
            parts.extend(_reduce(col, starts))
        flat: list[Any] = [None] * (len(parts) * len(rows))
        for k, part in enumerate(parts):
            flat[k :: len(parts)] = part
        out.params.extend(flat)
    return out


def _sorted_column(raw: list[Any], kind: str, order: np.ndarray | None) -> Any:
    """A value column in cell order: int64 or float64 (NaN for NULL) where numpy can, else a list."""
    if kind == "REAL":
        arr = np.array(raw, dtype=np.float64)  # None -> NaN (REAL values are never NaN: NaN is stored as NULL)
        return arr if order is None else arr[order]
    arr = np.array(raw)
    if arr.dtype.kind == "b":
        arr = arr.astype(np.int64)
    if arr.dtype == np.int64 and (not arr.size or int(arr.min()) > _INT64[0]):
        return arr if order is None else arr[order]
    return list(raw) if order is None else [raw[i] for i in order.tolist()]  # NULLs, fractions: exact Python


def _reduce(col: Any, starts: np.ndarray) -> list[list[Any]]:
    """Non-NULL count, sum, min and max of each group of ``col`` (groups start at ``starts``)."""
    if isinstance(col, np.ndarray) and col.dtype == np.float64:  # REAL: the sum exact (rollup_exact)
        valued = ~np.isnan(col)
        n = np.add.reduceat(valued.astype(np.int64), starts)
        low, high = np.fmin.reduceat(col, starts), np.fmax.reduceat(col, starts)
        empty = n == 0
        exact, total = of_groups(col[valued], n)
        return [n.tolist(), total, *([None if e else v for v, e in zip(a.tolist(), empty.tolist(), strict=True)]
                                     for a in (low, high)), exact]
    if isinstance(col, np.ndarray):
        span = float(np.abs(col).max()) * col.shape[0] if col.size else 0.0
        if span < 2.0**62:  # no group's sum can overflow int64
            n = np.diff(np.append(starts, col.shape[0]))
            sums = np.add.reduceat(col, starts)
            return [n.tolist(), sums.tolist(), np.minimum.reduceat(col, starts).tolist(),
                    np.maximum.reduceat(col, starts).tolist()]
        col = col.tolist()
    ends = [*starts[1:].tolist(), len(col)]
    out: list[list[Any]] = [[], [], [], []]
    for a, b in zip(starts.tolist(), ends, strict=True):
        given = [v for v in col[a:b] if v is not None]
        summed = sum(given) if given else None
        if isinstance(summed, int) and not _INT64[0] <= summed <= _INT64[1]:
            summed = float(summed)  # as SQLite does past the 64-bit range: REAL, so never served as exact
        out[0].append(len(given))
        out[1].append(summed)
        out[2].append(min(given) if given else None)
        out[3].append(max(given) if given else None)
    return out


def add_partials(conn: sqlite3.Connection, partials: BatchPartials | None, types: Mapping[str, str], path: str) -> None:
    """Add a batch's partials to ``rollups`` (inside the batch's write transaction).

    Raises
    ------
    StorageError
        If the kept levels changed since the batch was prepared (another process kept others):
        nothing of the batch is stored, and running the ingest again resumes.
    """
    levels = kept_levels(conn)
    if partials is None and not levels:
        return
    if partials is None or partials.levels != levels:
        raise StorageError(
            f"{path}: the kept roll-up levels changed during this ingest (now {list(levels)}); "
            "run it again: it resumes after the rows already stored"
        )
    if not exact_sums(conn):  # kept before exact REAL sums: rebuilt from the rows, this batch's included
        rebuild(conn)
        return
    _ensure_table(conn, types)
    names = ["level", "cell", "rows"]
    sets = ["rows = rows + excluded.rows"]
    for column, kind in zip(partials.columns, partials.kinds, strict=True):
        names += parts_of(column, kind)
        n, total, low, high = (quote(p) for p in part_names(column))
        if kind == "REAL":  # the exact sums added, the kept sum their rounded value
            exact = quote(exact_name(column))
            sets += [f"{exact} = dggs_xadd({exact}, excluded.{exact})",
                     f"{total} = dggs_xround(dggs_xadd({exact}, excluded.{exact}))"]
        else:
            sets.append(
                f"{total} = CASE WHEN excluded.{total} IS NULL THEN {total} WHEN {total} IS NULL "
                f"THEN excluded.{total} ELSE {total} + excluded.{total} END"  # + past int64 gives a REAL
            )
        sets += [
            f"{n} = {n} + excluded.{n}",
            f"{low} = coalesce(min({low}, excluded.{low}), {low}, excluded.{low})",
            f"{high} = coalesce(max({high}, excluded.{high}), {high}, excluded.{high})",
        ]
    head = f"INSERT INTO {_TABLE} ({', '.join(quote(c) for c in names)}) VALUES "
    one = "(" + ", ".join("?" * len(names)) + ")"
    tail = " ON CONFLICT (level, cell) DO UPDATE SET " + ", ".join(sets)
    insert_many(conn, head, one, partials.params, partials.width, max_variables(conn), tail)
