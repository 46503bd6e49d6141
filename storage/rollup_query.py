"""Roll-ups of a store: :meth:`dggs.storage.CellStore.aggregate`, choosing where the grouping is done.

In order: the kept partials (:mod:`dggs.storage.rollup_serve`), the partials
remembered for this file state (:mod:`dggs.storage.rollup_memo`), columns
grouped in numpy (:mod:`dggs.storage.rollup_columns`: many small groups, and
every REAL sum), then SQL: one key range per coarse cell, the group starts
streamed (:mod:`dggs.storage.rollup`) or a sorting ``GROUP BY``.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

import dggs
from dggs.errors import DggsValueError, LevelMismatchError

from .connection import Connection
from .queries import STATS, _where, check_cells, check_query_level, disjoint, normalise_cells
from .rollup import add_partials, remembered, streamed
from .rollup_columns import Rolled, head, roll_up, rolled_from_rows
from .rollup_columns import order as order_rolled
from .rollup_memo import MEMO_CELLS, Partials, state
from .rollup_serve import from_kept
from .schema import quote

__all__ = ["aggregate", "table_types", "RANGE_CELLS", "RANGE_ROWS_PER_CELL", "COLUMN_ROWS_PER_CELL"]


#: A roll-up reads one id range per possible cell (no sort) when there are at most this many
#: cells and at least RANGE_ROWS_PER_CELL stored rows a cell; else it groups in one sorted pass.
RANGE_CELLS = 40_000
RANGE_ROWS_PER_CELL = 8


def _rollup_by_ranges(
    store: Connection,
    level: int,
    under: list[str] | None,
    column: str | None,
    stats: tuple[str, ...],
    limit: int | None,
    pending: bool,
) -> list[dict[str, Any]] | None:
    """The roll-up to ``level`` as one range query per possible cell, or None where grouping is faster.

    ``points`` is clustered by cell, so the rows of a cell and its descendants
    are one key range (``cell >= id AND cell < id || '~'``): reading the ranges
    in id order gives the groups in order without the sort that
    ``GROUP BY substr(cell, ...)`` needs (3-5x faster at levels 0-5 of a
    million rows).  Rows still pending a merge (no index) are grouped apart, in
    one pass, and added in: count, sum, min, max and the non-NULL count, from
    which the mean is ``sum / count(column)``, as SQL's ``avg`` computes it.
    """
    roots = disjoint(under) if under is not None else [chr(ord("A") + f) for f in range(20)]
    cells = sum(dggs.get_num_cells(level) // dggs.get_num_cells(len(c) - 1) for c in roots)
    if cells > RANGE_CELLS:
        return None
    rows = store.conn.execute("SELECT coalesce(sum(rows_inserted), 0) FROM sources").fetchone()[0]
    if rows < RANGE_ROWS_PER_CELL * cells:
        return None
    c = quote(column) if column else ""
    parts = "count(*)" + (f", sum({c}), min({c}), max({c}), count({c})" if column else "")
    extra: dict[str, tuple] = {}
    if pending:
        clause, params = ("1", {}) if under is None else _where(roots)
        params["n"] = level + 1
        sql = f"SELECT substr(cell, 1, :n), {parts} FROM points_pending WHERE {clause} GROUP BY 1"
        extra = {r[0]: tuple(r[1:]) for r in store.conn.execute(sql, params)}
    sql = f"SELECT {parts} FROM points WHERE cell >= ?1 AND cell < ?1 || '~'"
    cursor = store.conn.cursor()
    out: list[dict[str, Any]] = []
    for cell in sorted(str(x) for x in dggs.uncompact_cells(roots, level)):
        if limit is not None and len(out) >= limit:
            break
        row = tuple(cursor.execute(sql, (cell,)).fetchone())
        if cell in extra:
            try:
                row = add_partials(row, extra[cell])
            except TypeError:  # values of unlike types: leave the comparison to SQL
                return None
        if row[0]:  # only non-empty cells, as GROUP BY gives
            out.append({"cell": cell, **_stats_of(row, stats)})
    return out


#: Where coarse cells hold this many stored rows each or more, SQL aggregates as it scans (few groups come
#: out) faster than the rows can be read out as columns; below it the columns win (many groups).
COLUMN_ROWS_PER_CELL = 8


def _by_columns(store: Connection, level: int, under: list[str] | None, kind: str | None,
                stats: tuple[str, ...]) -> bool:
    """Whether a roll-up is computed over columns (:mod:`dggs.storage.rollup_columns`) rather than in SQL.

    Always for sums and means of a REAL column (their rule, the correctly rounded sum, is computed there);
    else where the groups are small (fewer than :data:`COLUMN_ROWS_PER_CELL` rows a cell).
    """
    if kind == "REAL" and {"sum", "mean"} & set(stats):
        return True
    if kind == "TEXT":
        return False
    roots = under if under is not None else [chr(ord("A") + f) for f in range(20)]
    cells = sum(dggs.get_num_cells(level) // dggs.get_num_cells(len(c) - 1) for c in roots)
    rows = int(store.conn.execute("SELECT coalesce(sum(rows_inserted), 0) FROM sources").fetchone()[0])
    return bool(rows < COLUMN_ROWS_PER_CELL * min(cells, max(rows, 1)))


def _stats_of(row: tuple, stats: tuple[str, ...]) -> dict[str, Any]:
    if len(row) == 1:
        return {s: row[0] for s in stats}  # count only
    n, total, low, high, valued = row
    values = {"count": n, "sum": total, "min": low, "max": high,
              "mean": total / valued if valued else None}
    return {s: values[s] for s in stats}


def aggregate(
    store: Connection,
    level: int,
    column: str | None,
    stats: Sequence[str],
    cell: Any,
    order_by: str | None,
    descending: bool,
    limit: int | None,
    as_table: bool = False,
) -> Any:
    """Roll the rows up to the cells of ``level`` (the work of :meth:`dggs.storage.CellStore.aggregate`).

    Returns a list of dicts, or with ``as_table`` a pyarrow Table (:func:`table_types` gives its types).

    Raises
    ------
    LevelError
        If ``level`` is outside ``0..MAX_LEVEL``.
    LevelMismatchError
        If ``level`` is finer than the stored level, or ``cell`` is finer than ``level``.
    DggsValueError
        If a stat is unknown, needs a column that is missing or holds text, ``order_by`` is not one of
        the stats, ``limit`` is not a whole number >= 0, or ``descending`` or ``as_table`` is not a bool.
    """
    stored = check_query_level(store, level)
    if column is not None and not isinstance(column, str):
        raise DggsValueError(f"column must be the name of a value column (str), not {column!r}")
    for flag, name in ((descending, "descending"), (as_table, "as_table")):
        if not isinstance(flag, (bool, np.bool_)):  # issue 32: a truthy "no" or an array was read as a flag
            raise DggsValueError(f"{name} must be True or False, not {flag!r:.100}")
    if not isinstance(stats, str) and not (isinstance(stats, Iterable) and not isinstance(stats, (bytes, dict))):
        raise DggsValueError(f"stats must be a stat's name or a sequence of them, not {stats!r:.100}")
    stats = (stats,) if isinstance(stats, str) else tuple(stats)
    unknown = [s for s in stats if not isinstance(s, str) or s not in STATS]
    if unknown or not stats:
        raise DggsValueError(f"unknown stat(s) {unknown or stats!r}; choose from {', '.join(STATS)}")
    columns = store.columns
    if column is None:
        if any(s != "count" for s in stats):
            if stats != ("count", "sum", "mean", "min", "max"):
                raise DggsValueError("stats other than 'count' need a column")
            stats = ("count",)
    else:
        if column not in columns:
            raise DggsValueError(
                f"no value column {column!r} in {store.path}; columns are: {', '.join(columns) or '(none)'}"
            )
        if columns[column] == "TEXT" and {"sum", "mean"} & set(stats):
            raise DggsValueError(f"column {column!r} holds text: sum and mean make no sense")
    if order_by is not None and order_by not in stats:
        raise DggsValueError(f"order_by must be one of the stats {stats}, not {order_by!r}")
    if limit is not None and (isinstance(limit, bool) or not isinstance(limit, int) or limit < 0):
        raise DggsValueError(f"limit must be a whole number >= 0, not {limit!r}")
    params: dict[str, Any] = {"n": level + 1}
    where = ""
    if cell is not None:
        found = normalise_cells(cell)
        for c, cell_level in zip(found, check_cells(store, found), strict=True):
            if cell_level > level:
                raise LevelMismatchError(
                    f"cell {c!r} is at level {cell_level}, finer than the roll-up level {level}"
                )
        if not found:
            return _shaped(Rolled([], {s: ([], None) for s in stats}), store, column, stats, as_table)
        clause, extra = _where(disjoint(found))
        where = f"WHERE {clause}"
        params.update(extra)
    if stored is None:
        return _shaped(Rolled([], {s: ([], None) for s in stats}), store, column, stats, as_table)
    exprs = ", ".join(f"{STATS[s].format(c=quote(column) if column else '')} AS {quote(s)}" for s in stats)
    order = "1" if order_by is None else f"{quote(order_by)} {'DESC' if descending else 'ASC'}, 1"
    out = []
    under = disjoint(found) if cell is not None else None  # partials kept in the file (rollup_keep):
    if (kept := from_kept(store, level, column, stats, under, order_by, descending, limit)) is not None:
        return _shaped(kept, store, column, stats, as_table)
    before = state(store.conn) if cell is None else None  # whole-store roll-ups are remembered (rollup_memo)
    if (before is not None and order_by is None
            and (answer := remembered(store, before, level, column, stats, limit)) is not None):
        return _shaped(answer, store, column, stats, as_table)
    with store.snapshot() as table:
        kind = columns.get(column) if column is not None else None
        got = None
        if _by_columns(store, level, under, kind, stats):  # columns, no row in Python (rollup_columns)
            got = roll_up(store.conn, table, stored, level, column, kind, stats, under)
        if got is not None:
            rolled, partials = got
            if before is not None:
                _remember(store, before, level, column, rolled, partials)
            if order_by is not None:
                rolled = order_rolled(rolled, order_by, descending)
            return _shaped(head(rolled, limit), store, column, stats, as_table)
        if order_by is None:
            under = found if cell is not None else None
            ranged = _rollup_by_ranges(store, level, under, column, stats, limit, table != "points")
            if ranged is not None:
                return _shaped(ranged, store, column, stats, as_table)
        if before is not None and order_by is None and table == "points":  # stream the groups, no sort
            if (answer := streamed(store, before, level, column, stats, limit)) is not None:
                return _shaped(answer, store, column, stats, as_table)
        sql = f"SELECT substr(cell, 1, :n) AS cell_, {exprs} FROM {table} {where} GROUP BY cell_ ORDER BY {order}"
        if limit is not None:
            sql += " LIMIT :limit"
            params["limit"] = limit
        keys = ("cell", *stats)  # the columns in order: cell_, then one per stat
        out = [dict(zip(keys, row, strict=True)) for row in store.conn.execute(sql, params)]
    return _shaped(out, store, column, stats, as_table)


def _shaped(
    answer: list[dict[str, Any]] | Rolled, store: Connection, column: str | None, stats: tuple[str, ...], as_table: bool
) -> Any:
    """The roll-up as the caller asked for it: a list of dicts, or a pyarrow Table."""
    if not as_table:
        return answer.rows() if isinstance(answer, Rolled) else answer
    rolled = answer if isinstance(answer, Rolled) else rolled_from_rows(answer, stats)
    return rolled.table(table_types(store.columns.get(column) if column else None, stats))


def table_types(kind: str | None, stats: Sequence[str]) -> dict[str, Any]:
    """The pyarrow type of each stat of a roll-up of a column of SQL type ``kind``."""
    import pyarrow as pa

    value = {"INTEGER": pa.int64(), "REAL": pa.float64(), "TEXT": pa.string()}.get(kind or "", pa.int64())
    types = {"count": pa.int64(), "sum": value, "min": value, "max": value, "mean": pa.float64()}
    return {s: types[s] for s in stats}


def _remember(store: Connection, before: Any, level: int, column: str | None, rolled: Rolled,
              partials: dict[str, Any]) -> None:
    """Keep a whole-store roll-up's partials for later calls (:mod:`dggs.storage.rollup_memo`)."""
    n = len(rolled)
    if n > MEMO_CELLS or (column is not None and partials.get("total") is None):
        return
    cells = [str(c) for c in rolled.lists()["cell"]] if n else []
    if column is None:
        kept = Partials(cells, partials["count"].tolist(), [None] * n, [None] * n, [None] * n, [0] * n)
    else:
        some = partials["some"]

        def listed(name: str) -> list[Any]:
            values: list[Any] = partials[name].tolist()
            for i in np.flatnonzero(~some).tolist():
                values[i] = None
            return values

        kept = Partials(cells, partials["count"].tolist(), listed("total"), listed("low"), listed("high"),
                        partials["valued"].tolist())
    store.memo.keep((store.conn, before[1], store.conn.total_changes), column, level, kept)
