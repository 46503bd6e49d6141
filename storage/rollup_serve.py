"""Roll-ups answered from the kept partials (:mod:`dggs.storage.rollup_keep`) instead of the rows.

A roll-up to a kept level reads that level's partials in key order; a
coarser one regroups the nearest finer kept level's in SQL (``GROUP BY`` the
id prefix over a few hundred thousand partials instead of every row).  The
stats are SQL's own: ``count`` the rows, ``sum``/``min``/``max`` of the
partials, ``mean`` as SQLite's ``avg`` computes it (the sum as a double over
the non-NULL count; a REAL column's sum the correctly rounded value of the
kept exact sums, added exactly where regrouped).  Only exact answers are given (see the rules in
:mod:`dggs.storage.rollup_keep`); anything else returns None and the caller
reads the rows.
"""

from __future__ import annotations

import json
import sqlite3
import warnings
from typing import Any

import numpy as np

from .connection import Connection
from .rollup_columns import Rolled, head
from .rollup_columns import order as order_rolled
from .rollup_exact import INEXACT
from .rollup_keep import exact_name, exact_sums, kept_levels, numeric, part_names
from .schema import quote

__all__ = ["from_kept"]

#: The partials are read only where a kept level has at most one cell for this many stored rows: else the
#: rows, read as columns (:mod:`dggs.storage.rollup_columns`), are cheaper (1M rows to level 10, 815k cells:
#: 0.27 s as columns against 1.8 s through the partials).
KEPT_GAIN = 2

#: Doubles hold integers exactly below this: SQLite's ``avg`` of integers is exact while every running sum is.
_EXACT = 2**53


def from_kept(
    store: Connection,
    level: int,
    column: str | None,
    stats: tuple[str, ...],
    cells: list[str] | None,
    order_by: str | None,
    descending: bool,
    limit: int | None,
) -> Rolled | None:
    """The roll-up to ``level`` from the kept partials (as columns), or None where they cannot give it exactly.

    ``cells`` (disjoint, none finer than ``level``), ``order_by``, ``descending`` and
    ``limit`` as :func:`dggs.storage.rollup_query.aggregate` takes them.
    """
    conn = store.conn
    finer = [k for k in kept_levels(conn) if k >= level]
    if not finer:
        return None
    kept = min(finer)
    partials = int(conn.execute("SELECT count(*) FROM rollups WHERE level = ?", (kept,)).fetchone()[0])
    stored = int(conn.execute("SELECT coalesce(sum(rows_inserted), 0) FROM sources").fetchone()[0])
    if partials * KEPT_GAIN > stored:
        return None  # about a cell a row: reading the rows as columns is cheaper than the partials as rows
    valued = column is not None and set(stats) != {"count"}
    summed = valued and bool({"sum", "mean"} & set(stats))
    kind = numeric(store.columns).get(str(column)) if valued else None
    if valued:
        if kind is None or (kind == "REAL" and summed and not exact_sums(conn)):
            return None  # text min/max, and REAL sums of partials kept before exact sums: from the rows
    params: dict[str, Any] = {"kept": kept, "n": level + 1}
    where = "level = :kept"
    if cells is not None:
        where += " AND EXISTS (SELECT 1 FROM json_each(:cells) q WHERE cell >= q.value AND cell < q.value || '~')"
        params["cells"] = json.dumps(cells)
    grouped = level < kept
    exprs = {"count": "sum(rows)" if grouped else "rows"}
    if valued:
        n, total, low, high = (quote(p) for p in part_names(str(column)))
        if grouped:
            exact = quote(exact_name(str(column)))  # REAL: the exact sums added, then rounded once
            summed_sql = f"dggs_xround(dggs_xmerge({exact}))" if kind == "REAL" else f"sum({total})"
            n, total, low, high = f"sum({n})", summed_sql, f"min({low})", f"max({high})"
        exprs.update({"sum": total, "mean": f"CAST({total} AS REAL) / {n}", "min": low, "max": high})
    picked = ", ".join(f"{exprs[s]} AS {quote(s)}" for s in stats)
    order = "1" if order_by is None else f"{quote(order_by)} {'DESC' if descending else 'ASC'}, 1"
    sql = (f"SELECT {'substr(cell, 1, :n)' if grouped else 'cell'}, {picked} FROM rollups WHERE {where} "
           f"{'GROUP BY 1 ' if grouped else ''}ORDER BY {order}")
    if limit is not None:
        sql += f" LIMIT {int(limit)}"
    with store.snapshot():
        if kind != "REAL" and (got := _as_columns(conn, level, column if valued else None, stats, where, params,
                                                  grouped)) is not None:
            got = got if order_by is None else order_rolled(got, order_by, descending)
            return head(got, limit)
        if summed and kind == "INTEGER" and not _exact(conn, str(column), where, params):
            return None
        if summed and kind == "REAL" and _inexact_reals(conn, str(column), where, params):
            return None
        try:
            rows = conn.execute(sql, params).fetchall()
        except sqlite3.OperationalError as exc:
            if "overflow" in str(exc):
                return None  # a regrouped integer sum past int64: SQL on the rows says so
            raise
    return Rolled.from_tuples(rows, stats)  # the columns selected: cell, then the stats in order


def _as_columns(
    conn: sqlite3.Connection, level: int, column: str | None, stats: tuple[str, ...], where: str,
    params: dict[str, Any], grouped: bool,
) -> Rolled | None:
    """The partials of a count or an INTEGER column's roll-up as columns, no Python object per cell; or None.

    One statement concatenates each column of the (regrouped) partials in key order into one string,
    as :mod:`dggs.storage.rollup_columns` reads the rows: the ids (fixed width at a level) viewed by numpy,
    the integers parsed by it (174k kept cells, count and sum: 0.03 s in SQLite, where fetching the same
    as tuples and transposing them took 0.28 s).  The stats are then computed as the SQL of :func:`from_kept` does:
    ``sum``, ``min`` and ``max`` of the partials, NULL where no value was given (``n`` 0), and ``mean`` as
    ``CAST(sum AS REAL) / n``.  None (the caller's SQL answers) where a partial is not an integer (raw SQL
    writes), an id is not of the level, the ids do not come in order, a regrouped sum overflows, or a sum
    or mean may pass 2**53 (:func:`_exact`'s rule, on the same statement's sums; a partial's min or max is
    REAL only where its sum is, and a REAL sum stops the integer parse).
    """
    exprs = {"c": "cell", "k": "rows"}
    listed = ["k"]  # the columns read whole, beside the ids; the others only summed up
    checks = ["0", "NULL", "NULL", "0"]  # values given, largest max, smallest min, cells without a value
    summed = column is not None and bool({"sum", "mean"} & set(stats))
    if column is not None:
        exprs.update(zip(("n", "sum", "min", "max"), (quote(p) for p in part_names(column)), strict=True))
        listed += [s for s in ("sum", "min", "max") if s in stats or (s == "sum" and summed)]
        if "mean" in stats:
            listed.append("n")
    source = f"rollups WHERE {where}"  # read in key order: (level, cell) is the primary key
    if grouped:  # the regrouped partials, named as the kept ones
        aggs = {"c": "substr(cell, 1, :n)", "k": "sum(rows)", "n": "sum({})", "sum": "sum({})", "min": "min({})",
                "max": "max({})"}
        picked = ", ".join(f"{aggs[a].format(e)} AS {e}" for a, e in exprs.items())
        source = f"(SELECT {picked} FROM {source} GROUP BY 1 ORDER BY 1)"
    if column is not None:
        n, low, high = exprs["n"], exprs["min"], exprs["max"]
        checks = [f"sum({n})", f"max({high})", f"min({low})", f"sum({n} = 0)"]
    outer = ", ".join(["count(*)", f"group_concat({exprs['c']}, '')", *checks,
                       *(f"group_concat(ifnull({exprs[a]}, 0), ',')" for a in listed)])
    sql = f"SELECT {outer} FROM {source}"
    try:
        got = conn.execute(sql, params).fetchone()
    except sqlite3.OperationalError as exc:
        if "overflow" in str(exc):
            return None
        raise
    count, width = int(got[0]), level + 1
    valued, largest, smallest, empty = got[2:6]
    if summed and valued and (not isinstance(largest, int) or not isinstance(smallest, int)
                              or valued * max(largest, -smallest) >= _EXACT):
        return None  # _exact's rule: a running sum may pass 2**53, where SQLite's avg rounds
    raw = (got[1] or "").encode("ascii", "replace")
    if len(raw) != count * width:
        return None  # ids of another level (raw SQL)
    keys = np.frombuffer(raw, dtype=f"S{width}")
    if count > 1 and not bool(np.all(keys[1:] > keys[:-1])):
        return None
    columns = {}
    for name, text in zip(listed, got[6:], strict=True):
        if (values := _integers(text, count)) is None:
            return None
        columns[name] = values
    out = Rolled(keys, {"count": (columns["k"], None)})
    if column is not None:
        some: np.ndarray | None = None
        if empty:  # cells whose rows hold no value: their sum, min, max and mean are NULL
            again = conn.execute(f"SELECT group_concat({exprs['n']} > 0, '') FROM {source}", params).fetchone()[0]
            again = again or ""
            some = np.frombuffer(again.encode("ascii"), dtype=np.uint8) == ord("1")
            if some.shape[0] != count:
                return None
        if "sum" in columns:
            out.stats["sum"] = (columns["sum"], some)
        if "mean" in stats:
            out.stats["mean"] = (columns["sum"].astype(np.float64) / np.maximum(columns["n"], 1), some)
        for name in ("min", "max"):
            if name in columns:
                out.stats[name] = (columns[name], some)
    out.stats = {name: out.stats[name] for name in stats}
    return out


def _integers(text: str | None, count: int) -> np.ndarray | None:
    """``count`` comma-separated integers parsed exactly as int64, or None if one is not an integer."""
    if not count:
        return np.zeros(0, dtype=np.int64)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:  # a REAL ("2.5", "1.0e+20") stops the parse
            values = np.fromstring(text or "", dtype=np.int64, sep=",")
        except (ValueError, DeprecationWarning):
            return None
    return values if values.shape[0] == count else None


def _inexact_reals(conn: sqlite3.Connection, column: str, where: str, params: dict[str, Any]) -> bool:
    """Whether a REAL column's kept exact sums include one past the double range (:data:`INEXACT`)."""
    exact = quote(exact_name(column))
    row = conn.execute(
        f"SELECT 1 FROM rollups WHERE {where} AND {exact} = :inexact LIMIT 1", {**params, "inexact": INEXACT}
    ).fetchone()
    return row is not None


def _exact(conn: sqlite3.Connection, column: str, where: str, params: dict[str, Any]) -> bool:
    """Whether every sum and mean of ``column`` the partials give is SQL's exactly.

    True when every partial sum, min and max is an integer and (non-NULL values) x
    (largest |value|) < 2**53, over every partial in the roll-up: then no running sum
    of any cell, kept or regrouped, reaches 2**53, where SQLite's ``avg`` sums in doubles
    (the rule of :mod:`dggs.storage.rollup_memo`).  Otherwise the rows answer.
    """
    n, total, low, high = (quote(p) for p in part_names(column))
    valued, largest, inexact = conn.execute(
        f"SELECT sum({n}), max(max({high}), -min({low})), "
        f"sum(typeof({total}) = 'real' OR typeof({low}) = 'real' OR typeof({high}) = 'real') "
        f"FROM rollups WHERE {where}",
        params,
    ).fetchone()
    if inexact:
        return False
    return not valued or valued * largest < _EXACT  # a float largest (-min past int64) fails too
