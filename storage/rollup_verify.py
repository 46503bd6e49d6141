"""The check of kept roll-ups against the rows (:meth:`CellStore.check`).

Rows written with raw SQL are not seen by the kept partials
(:mod:`dggs.storage.rollup_keep`); this recomputes every kept level from the
rows and names the first cell that differs.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Sequence
from typing import Any

from dggs.errors import StorageError

from .rollup_exact import rounded
from .rollup_keep import _TABLE, _from_rows, exact_sums, kept_levels, numeric, part_names, parts_of
from .schema import column_types, quote

__all__ = ["verify"]


def verify(conn: sqlite3.Connection, path: str) -> None:
    """Raise StorageError unless every kept partial equals the one computed from the rows.

    REAL sums are compared as their correctly rounded values (the exact sums' expansions are not
    unique); in a store kept before exact sums, not at all.

    Raises
    ------
    StorageError
        Naming the level, cell and values of the first difference.
    """
    levels = kept_levels(conn)
    if not levels:
        return
    types = numeric(column_types(conn))
    exact = exact_sums(conn)
    pending = conn.execute("SELECT 1 FROM points_pending LIMIT 1").fetchone() is not None
    table = "all_points" if pending else "points"
    kept_parts = [p for c, kind in types.items() for p in (parts_of(c, kind) if exact else part_names(c))]
    names = ", ".join(["cell", "rows", *(quote(p) for p in kept_parts)])
    for level in levels:
        kept = conn.execute(f"SELECT {names} FROM {_TABLE} WHERE level = ? ORDER BY cell", (level,)).fetchall()
        int_sums = True
        try:
            fresh = conn.execute(_from_rows(level, table, types) + " ORDER BY c").fetchall()
        except sqlite3.OperationalError as exc:  # an integer sum past int64: compare all but those sums
            if "overflow" not in str(exc):
                raise
            fresh = conn.execute(_from_rows(level, table, types, "total") + " ORDER BY c").fetchall()
            int_sums = False
        kinds = list(types.values())
        _compare(path, level, [_comparable(r, kinds, exact, False, exact, int_sums) for r in kept],
                 [_comparable(r, kinds, True, True, exact, int_sums) for r in fresh])


def _comparable(row: Sequence[Any], kinds: list[str], with_x: bool, use_x: bool, real_sums: bool,
                int_sums: bool) -> tuple:
    """``cell, rows``, then n, sum, min, max per column (``with_x``: a REAL column's exact sum follows).

    With ``use_x`` a REAL sum is the exact sum rounded; REAL sums are left out unless ``real_sums``,
    integer sums unless ``int_sums``.
    """
    out: list[Any] = list(row[:2])
    k = 2
    for kind in kinds:
        n, total, low, high = row[k : k + 4]
        if kind == "REAL" and with_x:
            total = rounded(row[k + 4]) if use_x else total
            k += 5
        else:
            k += 4
        if (kind == "REAL" and not real_sums) or (kind != "REAL" and not int_sums):
            total = None
        out += [n, total, low, high]
    return tuple(out)


def _compare(path: str, level: int, kept: list[tuple], rows: list[tuple]) -> None:
    if kept == rows:
        return
    first = next((k for k, (a, b) in enumerate(zip(kept, rows, strict=False)) if a != b), min(len(kept), len(rows)))
    a = kept[first] if first < len(kept) else None
    b = rows[first] if first < len(rows) else None
    raise StorageError(
        f"{path}: the kept roll-up of level {level} differs from the rows (kept {a}, from the rows {b}); "
        "rows were changed outside the store: keep_rollups() again rebuilds it"
    )
