"""Roll-ups computed over columns, with no Python object per row: the default path of ``aggregate``.

The rows of a store are read in key order as a few large values, not a
tuple each: SQLite concatenates the cell ids of a key range into one string
(``group_concat(cell, '')``, fixed-width ids, so numpy views it as an ``S``
array without a copy) and an INTEGER column into one decimal string that
numpy parses; a REAL column is read as floats straight into a numpy array.
The groups of a level are then the runs of equal id prefixes (rows come in
key order, so a level's cells are contiguous), and numpy reduces each run:
count, non-NULL count, sum, min and max.  Results stay columns
(:class:`Rolled`) until the caller asks for dicts.

The answers are SQL's, to the last bit, with one rule stated for floats:

* counts, min and max: exact;
* sums of an INTEGER column: exact (``int64``, where no group's sum can pass
  it; else the caller's SQL path answers, and raises SQLite's overflow);
* means of an INTEGER column: ``float(sum) / non-NULL count``, as SQLite's
  ``avg`` computes it, while no running sum reaches 2**53 (else SQL answers);
* **sums of a REAL column are the correctly rounded sum of the values** (the
  exact sum rounded once to the nearest double, ties to even: what
  ``math.fsum`` returns), whatever order the rows were added in, and means
  are that sum divided by the non-NULL count.  SQLite's own ``sum`` is
  order-dependent (a plain running sum in 3.40, Kahan-Babuska-Neumaier from
  3.43), so its last bits depend on the SQLite build and on how the rows were
  read; the correctly rounded sum is the one answer every path can give,
  kept roll-ups included (:mod:`dggs.storage.rollup_exact`).

Anything else (a value of another type than its column's, written with raw
SQL; cells of mixed levels; integer sums near the int64 range) returns None,
and the caller reads the rows with SQL as before.
"""

from __future__ import annotations

import itertools
import math
import sqlite3
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from dggs.errors import StorageError

from .dict_rows import dict_maker
from .schema import quote

__all__ = ["Rolled", "rolled_from_rows", "roll_up", "order", "head"]

#: The key order of ``points``: its primary key.
_KEY = "cell, source_id, row, part"
_INT64_MAX = 2**63 - 1
_EXACT = 2**53


@dataclass
class Rolled:
    """A roll-up as columns: ``cells`` (str ids, in output order) and one column per stat.

    Each stat is ``(values, valid)``: a numpy array or list, and a boolean mask of the non-NULL
    entries (None: all are).
    """

    cells: Any
    stats: dict[str, tuple[Any, Any]] = field(default_factory=dict)
    #: The same as SQL rows ``(cell, *stats)``, where it came as rows: dicts are made from them directly.
    tuples: list[tuple[Any, ...]] | None = None

    @classmethod
    def from_tuples(cls, rows: list[tuple[Any, ...]], stats: tuple[str, ...]) -> Rolled:
        """SQL rows ``(cell, *stats)`` as a roll-up."""
        columns = list(zip(*rows, strict=True)) if rows else [()] * (1 + len(stats))
        return cls(list(columns[0]), {s: (list(c), None) for s, c in zip(stats, columns[1:], strict=True)}, rows)

    def __len__(self) -> int:
        return len(self.cells)

    def lists(self) -> dict[str, list[Any]]:
        """Every column as a Python list, NULLs as None (``cell`` first)."""
        out: dict[str, list[Any]] = {"cell": _to_list(self.cells)}
        for name, (values, valid) in self.stats.items():
            out[name] = _with_nulls(_to_list(values), valid)
        return out

    def rows(self) -> list[dict[str, Any]]:
        """One dict per cell, as ``aggregate`` has always returned them."""
        if self.tuples is not None:
            keys = ("cell", *self.stats)
            return list(map(dict, map(zip, itertools.repeat(keys), self.tuples)))  # faster than dict(zip())
        cols = self.lists()
        made: list[dict[str, Any]] = dict_maker(tuple(cols))(*cols.values())
        return made

    def table(self, types: dict[str, Any]) -> Any:
        """A pyarrow Table: ``cell`` (string), then each stat typed by ``types`` (pyarrow types)."""
        import pyarrow as pa

        arrays = [_strings(self.cells)]
        for name, (values, valid) in self.stats.items():
            kind = types[name]
            if isinstance(values, np.ndarray) and values.dtype.kind in "if":
                mask = None if valid is None else ~np.asarray(valid, dtype=bool)
                arrays.append(pa.array(values, type=kind, mask=mask))
            else:
                listed = _with_nulls(_to_list(values), valid)
                try:
                    arrays.append(pa.array(listed, type=kind))
                except (pa.ArrowInvalid, pa.ArrowTypeError, OverflowError):
                    odd = next((v for v in listed if v is not None and not _fits(v, kind)), None)
                    raise StorageError(
                        f"the roll-up's {name!r} holds {odd!r}, not {kind}: its column holds values of another "
                        "type (written with raw SQL); ask for dicts (as_table=False)"
                    ) from None
        return pa.Table.from_arrays(arrays, names=["cell", *self.stats])


def _fits(value: Any, kind: Any) -> bool:
    """Whether ``value`` is of the Python type a pyarrow column of ``kind`` holds."""
    import pyarrow as pa

    if pa.types.is_integer(kind):
        return type(value) is int
    if pa.types.is_floating(kind):
        return type(value) is float
    return isinstance(value, str)


def _strings(cells: Any) -> Any:
    """Ids as a pyarrow string array: fixed-width ASCII ids wrap their bytes (no copy, no Python str)."""
    import pyarrow as pa

    if isinstance(cells, np.ndarray) and cells.dtype.kind == "S" and cells.size:
        width = cells.dtype.itemsize
        data = np.ascontiguousarray(cells).view(np.uint8)
        offsets = np.arange(0, (cells.shape[0] + 1) * width, width, dtype=np.int64)
        return pa.LargeStringArray.from_buffers(cells.shape[0], pa.py_buffer(offsets), pa.py_buffer(data)).cast(
            pa.string()
        )
    return pa.array(_to_list(cells), type=pa.string())


def _to_list(values: Any) -> list[Any]:
    if isinstance(values, np.ndarray):
        listed: list[Any] = (values.astype(str) if values.dtype.kind == "S" else values).tolist()
        return listed
    return list(values)


def _with_nulls(values: list[Any], valid: Any) -> list[Any]:
    if valid is None:
        return values
    for i in np.flatnonzero(~np.asarray(valid, dtype=bool)).tolist():
        values[i] = None
    return values


def rolled_from_rows(rows: list[dict[str, Any]], stats: tuple[str, ...]) -> Rolled:
    """The columns of rows as the SQL paths give them."""
    out = Rolled([r["cell"] for r in rows])
    for s in stats:
        values = [r[s] for r in rows]
        out.stats[s] = (values, None)
    return out


# -- reading -------------------------------------------------------------------------------------------


@dataclass
class _Read:
    keys: np.ndarray  # S(level + 1) ids of the stored level, key order
    values: np.ndarray | None  # int64 or float64 (0 where NULL)
    valid: np.ndarray | None  # non-NULL mask


def _ranges(cells: list[str] | None) -> list[tuple[str, dict[str, Any]]]:
    """WHERE clauses for the whole table or each disjoint cell's key range, in key order."""
    if cells is None:
        return [("1", {})]
    return [("cell >= :c AND cell < :c || '~'", {"c": c}) for c in sorted(cells)]


def _read(
    conn: sqlite3.Connection, table: str, where: str, params: dict[str, Any], width: int, column: str | None,
    kind: str | None,
) -> _Read | None:
    """One key range of ``table`` as columns, or None if a value is not of its column's type.

    A plain scan of ``points`` visits its clustered key in order; the order is checked (the ids must
    come sorted), and a REAL column is read with ``ORDER BY`` the key, so that its i-th value belongs
    to a row of the i-th id's cell.  ``points_pending`` is read in rowid order both times.
    """
    c = quote(column) if column is not None else None
    order = f" ORDER BY {_KEY}" if table == "points" else " ORDER BY rowid"
    parts = ["count(*)", "group_concat(cell, '')"]
    if c is not None:
        want = "integer" if kind == "INTEGER" else "real"
        parts += [f"count({c})", f"sum(typeof({c}) = '{want}')"]
        if kind == "INTEGER":
            parts.append(f"group_concat(ifnull({c}, 0), ',')")
    source = f"{table} WHERE {where}" + ("" if table == "points" else order)
    if table != "points":
        source = f"(SELECT * FROM {source})"
    got = conn.execute(f"SELECT {', '.join(parts)} FROM {source}", params).fetchone()
    n = int(got[0])
    if n == 0:
        empty = np.zeros(0, dtype=np.int64 if kind == "INTEGER" else np.float64)
        return _Read(np.zeros(0, dtype=f"S{width}"), empty if c else None, np.zeros(0, bool) if c else None)
    raw = got[1].encode("ascii", "replace")
    if len(raw) != n * width:
        return None  # cells of another level than the store's (raw SQL): SQL answers
    keys = np.frombuffer(raw, dtype=f"S{width}")
    if table == "points" and n > 1 and not bool(np.all(keys[1:] >= keys[:-1])):
        return None  # not in key order after all: SQL answers
    if c is None:
        return _Read(keys, None, None)
    given, typed = int(got[2]), int(got[3] or 0)
    if typed != given:
        return None  # a value of another type (raw SQL): SQL answers, as it always has
    if given == n:
        valid = np.ones(n, dtype=bool)
    else:  # NULLs among the values: where they are, in one pass with the ids (and the integers) again
        extra = f", group_concat(ifnull({c}, 0), ',')" if kind == "INTEGER" else ""
        again = conn.execute(f"SELECT group_concat(cell, ''), group_concat({c} IS NULL, ''){extra} FROM {source}",
                             params).fetchone()
        if again[0] != got[1]:
            return None
        valid = np.frombuffer(again[1].encode("ascii"), dtype=np.uint8) == ord("0")
        got = (*got[:4], *again[2:])  # the integers beside their NULL flags
    if kind == "INTEGER":
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                values = np.fromstring(got[4], dtype=np.int64, sep=",")  # exact: parsed as integers
            except (ValueError, DeprecationWarning):
                return None
    else:
        cursor = conn.execute(f"SELECT {c} FROM {table} WHERE ({where}) AND {c} IS NOT NULL{order}", params)
        values = np.zeros(n, dtype=np.float64)
        values[valid] = np.fromiter(itertools.chain.from_iterable(cursor), dtype=np.float64, count=given)
    if values.shape[0] != n or valid.shape[0] != n or int(valid.sum()) != given:
        return None
    return _Read(keys, values, valid)


def _gather(
    conn: sqlite3.Connection, table: str, cells: list[str] | None, width: int, column: str | None, kind: str | None
) -> _Read | None:
    """Every row under ``cells`` (None: all) of ``points`` and, if pending, ``points_pending``, in key order."""
    pieces: list[_Read] = []
    tables = ["points"] if table == "points" else ["points", "points_pending"]
    for name in tables:
        for where, params in _ranges(cells):
            got = _read(conn, name, where, params, width, column, kind)
            if got is None:
                return None
            pieces.append(got)
    keys = np.concatenate([p.keys for p in pieces])
    values = np.concatenate([p.values for p in pieces if p.values is not None]) if column is not None else None
    valid = np.concatenate([p.valid for p in pieces if p.valid is not None]) if column is not None else None
    if len(tables) > 1:  # pending rows come in no order: sort by cell (only the cell decides a group)
        order = np.argsort(keys, kind="stable")
        keys = keys[order]
        if values is not None and valid is not None:
            values, valid = values[order], valid[order]
    return _Read(keys, values, valid)


# -- grouping ------------------------------------------------------------------------------------------


def _exact_float_sums(values: np.ndarray, valid: np.ndarray, starts: np.ndarray, valued: np.ndarray) -> np.ndarray | None:
    """The correctly rounded sum of each group's non-NULL floats (NaN where it has none); None on overflow."""
    given = values[valid]
    first = np.concatenate([[0], np.cumsum(valued)[:-1]]).astype(np.int64)  # each group's start in ``given``
    out = np.full(valued.shape[0], np.nan)
    one = valued == 1
    out[one] = given[first[one]]
    two = valued == 2
    out[two] = given[first[two]] + given[first[two] + 1]  # one IEEE addition: correctly rounded
    many = np.flatnonzero(valued > 2)
    if many.size:
        flat = given.tolist()
        fsum = math.fsum
        try:
            sums = [fsum(flat[a : a + k]) for a, k in zip(first[many].tolist(), valued[many].tolist(), strict=True)]
        except OverflowError:
            return None
        out[many] = sums
    if not bool(np.all(np.isfinite(out[valued > 0]))):
        return None  # past the double range: SQL says what it says
    return out


def roll_up(
    conn: sqlite3.Connection,
    table: str,
    stored: int,
    level: int,
    column: str | None,
    kind: str | None,
    stats: tuple[str, ...],
    cells: list[str] | None,
) -> tuple[Rolled, dict[str, Any]] | None:
    """The roll-up to ``level`` in cell order (inside a read snapshot), with its partials; or None.

    ``cells`` are disjoint cells no finer than ``level`` (None: the whole store); ``kind`` the column's
    SQL type (INTEGER or REAL; a TEXT column is not rolled up here).  Returns the roll-up of ``stats``
    and the partials (``count``, ``valued``, ``total``, ``low``, ``high`` as lists; ``total`` None
    where not computed).
    """
    if column is not None and kind not in ("INTEGER", "REAL"):
        return None
    got = _gather(conn, table, cells, stored + 1, column, kind)
    if got is None:
        return None
    n = got.keys.shape[0]
    prefix = got.keys if level == stored else got.keys.astype(f"S{level + 1}")
    if n:
        new = np.empty(n, dtype=bool)
        new[0] = True
        np.not_equal(prefix[1:], prefix[:-1], out=new[1:])
        starts = np.flatnonzero(new)
    else:
        starts = np.zeros(0, dtype=np.intp)
    count = np.diff(np.append(starts, n)).astype(np.int64)
    out = Rolled(prefix[starts])
    cols: dict[str, tuple[Any, Any]] = {"count": (count, None)}
    partials: dict[str, Any] = {"count": count}
    if column is not None and got.values is not None and got.valid is not None:
        values, valid = got.values, got.valid
        valued = np.add.reduceat(valid.astype(np.int64), starts) if n else np.zeros(0, np.int64)
        some = valued > 0
        total: np.ndarray | None = None
        if kind == "INTEGER":
            low = np.minimum.reduceat(np.where(valid, values, np.int64(_INT64_MAX)), starts) if n else values[:0]
            high = np.maximum.reduceat(np.where(valid, values, np.int64(-_INT64_MAX - 1)), starts) if n else values[:0]
            largest = max(int(values.max()), -int(values.min())) if n else 0
            if largest * n <= _INT64_MAX:  # no sum, running or whole, can leave int64
                total = np.add.reduceat(values, starts) if n else values[:0]
            if "mean" in stats and largest * n >= _EXACT:
                return None  # SQLite's avg sums in doubles: past 2**53 its rounding is SQL's to give
            mean = total / np.maximum(valued, 1) if total is not None else None  # exact below 2**53
        else:
            low = np.fmin.reduceat(np.where(valid, values, np.nan), starts) if n else values[:0]
            high = np.fmax.reduceat(np.where(valid, values, np.nan), starts) if n else values[:0]
            total = _exact_float_sums(values, valid, starts, valued) if {"sum", "mean"} & set(stats) else None
            if total is None and {"sum", "mean"} & set(stats):
                return None
            mean = total / np.maximum(valued, 1) if total is not None else None
        if total is None and {"sum", "mean"} & set(stats):
            return None
        cols.update({"sum": (total, some), "min": (low, some), "max": (high, some), "mean": (mean, some)})
        partials.update({"valued": valued, "total": total, "low": low, "high": high, "some": some})
    out.stats = {s: cols[s] for s in stats}
    return out, partials


def order(rolled: Rolled, by: str, descending: bool) -> Rolled:
    """``rolled`` sorted by stat ``by`` (NULLs first ascending, last descending), ties by cell, as SQL does."""
    values, valid = rolled.stats[by]
    arr = np.asarray(values)
    if valid is not None:
        mask = np.asarray(valid, dtype=bool)
        arr = np.where(mask, arr, arr[mask][0] if mask.any() else 0)
    else:
        mask = np.ones(len(rolled), dtype=bool)
    rank = np.unique(arr, return_inverse=True)[1].ravel() if len(rolled) else np.zeros(0, np.intp)
    position = np.arange(len(rolled))
    nulls = mask if not descending else ~mask  # False sorts first: NULLs first ascending, last descending
    keys = (position, -rank if descending else rank, nulls)
    picked = np.lexsort(keys)
    return _take(rolled, picked)


def _take(rolled: Rolled, index: Any) -> Rolled:
    def take(values: Any) -> Any:
        if values is None:
            return None
        if isinstance(values, np.ndarray) or isinstance(index, slice):
            return values[index]
        return [values[i] for i in np.asarray(index).tolist()]

    return Rolled(take(rolled.cells), {s: (take(v), take(m)) for s, (v, m) in rolled.stats.items()})


def head(rolled: Rolled, limit: int | None) -> Rolled:
    """The first ``limit`` cells (all: None)."""
    return rolled if limit is None or limit >= len(rolled) else _take(rolled, slice(0, limit))
