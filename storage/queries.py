"""Queries on a store: counts, rows under cells, roll-ups, GeoJSON.

Cells may be given in any container the grid API accepts: a string or
64-bit integer id, a list, a numpy array, a pandas Series...
(:func:`dggs.index._convert.cells_in`).  A container means *every row under
any of the cells*, each row once even if the cells overlap.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from typing import Any

import dggs
from dggs.errors import DggsValueError, InvalidCellError, LevelError, LevelMismatchError

from .connection import Connection
from .schema import quote

__all__ = ["STATS", "normalise_cells", "count", "get", "descendants", "rows_under"]

#: Statistics :meth:`CellStore.aggregate` computes, and their SQL.
STATS = {
    "count": "count(*)",
    "sum": "sum({c})",
    "mean": "avg({c})",
    "min": "min({c})",
    "max": "max({c})",
}


def normalise_cells(cells: Any) -> list[str]:
    """Return the string ids of ``cells`` (any container of str or int ids), in order.

    Raises
    ------
    InvalidCellError
        Naming the first bad id.

    Examples
    --------
    >>> normalise_cells(["A0", dggs.str_to_int("B1")])
    ['A0', 'B1']
    """
    from dggs.index._convert import cells_in

    if type(cells) is str and dggs.is_valid_cell(cells):  # the common case, fast
        return [cells]
    if isinstance(cells, (list, tuple)) and any(isinstance(c, int) for c in cells):
        cells = [c if isinstance(c, str) else dggs.int_to_str(c) for c in cells]
    try:
        ids, _ = cells_in(cells)
    except DggsValueError:
        raise
    except (TypeError, ValueError, OverflowError) as exc:
        raise InvalidCellError(f"{cells!r} are not cell ids ({exc})") from None
    return [str(c) for c in dggs.int_to_str(ids).tolist()] if len(ids) else []


def one_cell(cell: Any) -> str:
    """A single cell id as a string (str or int id).

    Raises
    ------
    InvalidCellError
        If ``cell`` is not one valid cell id.
    """
    if isinstance(cell, str):
        if not dggs.is_valid_cell(cell):
            raise InvalidCellError(f"{cell!r} is not a valid cell id")
        return cell
    found = normalise_cells(cell)
    if len(found) != 1:
        raise InvalidCellError(f"expected one cell id, got {len(found)}: {cell!r}")
    return found[0]


def check_cells(store: Connection, cells: list[str]) -> list[int]:
    """Levels of ``cells``; none may be finer than the stored level.

    Raises
    ------
    LevelMismatchError
        If a cell is finer than the stored level.
    """
    stored = store.level
    levels = []
    for cell in cells:
        level = len(cell) - 1
        if stored is not None and level > stored:
            raise LevelMismatchError(f"cell {cell!r} is at level {level}, finer than the stored level {stored}")
        levels.append(level)
    return levels


def disjoint(cells: list[str]) -> list[str]:
    """Drop repeats and cells under another cell of the list (each row counted once)."""
    out: list[str] = []
    for cell in sorted(set(cells)):
        if out and cell.startswith(out[-1]):
            continue
        out.append(cell)
    return out


def check_query_level(store: Connection, level: Any) -> int | None:
    """Validate a roll-up level; return the stored level (None if empty).

    Raises
    ------
    LevelError
        If ``level`` is not an int in ``0..MAX_LEVEL``.
    LevelMismatchError
        If ``level`` is finer than the stored level.
    """
    if isinstance(level, bool) or not isinstance(level, int) or not 0 <= level <= dggs.MAX_LEVEL:
        raise LevelError(f"level {level!r} is out of range 0..{dggs.MAX_LEVEL}")
    stored = store.level
    if stored is not None and level > stored:
        raise LevelMismatchError(
            f"level {level} is finer than the stored level {stored}; "
            f"data can only be rolled up to levels 0..{stored}"
        )
    return stored


def select_list(store: Connection, prefix: str = "") -> str:
    return ", ".join(prefix + quote(c) for c in ("cell", "lat", "lng", *store.columns, "source_id", "row"))


def _where(cells: list[str]) -> tuple[str, dict[str, Any]]:
    if len(cells) == 1:
        return "cell >= :c AND cell < :c || '~'", {"c": cells[0]}
    return (
        "EXISTS (SELECT 1 FROM json_each(:cells) q WHERE cell >= q.value AND cell < q.value || '~')",
        {"cells": json.dumps(cells)},
    )


def count(store: Connection, cells: Any = None) -> int:
    """Count the rows under any of ``cells``, or all rows when ``cells`` is None.

    Raises
    ------
    InvalidCellError
        If ``cells`` holds something that is not a cell id.
    LevelMismatchError
        If a cell is finer than the stored level.
    """
    if cells is None:
        row = store.conn.execute(
            "SELECT (SELECT count(*) FROM points) + (SELECT count(*) FROM points_pending)"
        ).fetchone()
        return int(row[0])
    found = normalise_cells(cells)
    check_cells(store, found)
    total = 0
    with store.snapshot() as table:
        for cell in disjoint(found):
            row = store.conn.execute(
                f"SELECT count(*) FROM {table} WHERE cell >= ?1 AND cell < ?1 || '~'", (cell,)
            ).fetchone()
            total += int(row[0])
    return total


def get(store: Connection, cells: Any) -> list[dict[str, Any]]:
    """Return the rows stored in exactly ``cells`` (cells at the stored level).

    Raises
    ------
    InvalidCellError
        If ``cells`` holds something that is not a cell id.
    LevelMismatchError
        If a cell is not at the stored level (coarser cells: :func:`descendants`).
    """
    found = normalise_cells(cells)
    levels = check_cells(store, found)
    stored = store.level
    if stored is None or not found:
        return []
    for cell, level in zip(found, levels, strict=True):
        if level != stored:
            raise LevelMismatchError(
                f"cell {cell!r} is at level {level}, not the stored level {stored}; "
                "use descendants() for coarser cells"
            )
    with store.snapshot() as table:
        sql = (
            f"SELECT {select_list(store)} FROM {table} WHERE cell IN (SELECT value FROM json_each(?)) "
            "ORDER BY cell, source_id, row"
        )
        return list(store.query(sql, (json.dumps(sorted(set(found))),)))


def descendants(store: Connection, cells: Any) -> list[dict[str, Any]]:
    """Return the rows under any of ``cells``, each once, ordered by cell.

    Raises
    ------
    InvalidCellError
        If ``cells`` holds something that is not a cell id.
    LevelMismatchError
        If a cell is finer than the stored level.
    """
    found = normalise_cells(cells)
    check_cells(store, found)
    if not found:
        return []
    where, params = _where(disjoint(found))
    with store.snapshot() as table:
        sql = f"SELECT {select_list(store)} FROM {table} WHERE {where} ORDER BY cell, source_id, row"
        return list(store.query(sql, params))


def rows_under(store: Connection, cells: Sequence[str], level: int) -> list[dict[str, Any]]:
    """Rows under any of ``cells`` (all at ``level``): index range per cell."""
    if not len(cells):
        return []
    sql = (
        f"SELECT {select_list(store, 'p.')} FROM json_each(?1) q JOIN points p "
        "ON p.cell >= q.value AND p.cell < q.value || '~' "
        f"UNION ALL SELECT {select_list(store)} FROM points_pending "
        "WHERE substr(cell, 1, ?2) IN (SELECT value FROM json_each(?1)) "
        "ORDER BY 1, source_id, row"
    )
    with store.snapshot():
        return list(store.query(sql, (json.dumps([str(c) for c in cells]), level + 1)))


def export_stats(column: str | None, stats: Sequence[str] | None) -> tuple[str, ...]:
    """The stats an export writes: all five of ``column`` by default, the count alone without one."""
    if stats is None:
        return ("count", "sum", "mean", "min", "max") if column else ("count",)
    return tuple(stats)


def stat_columns(rows: list[dict[str, Any]], stats: Sequence[str]) -> dict[str, list[Any]]:
    """Rows of :func:`aggregate` as one list per stat (the columns of an export table)."""
    return {s: [row[s] for row in rows] for s in stats}

