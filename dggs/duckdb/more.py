"""The hierarchy, grid, region and vertex SQL functions of :func:`dggs.duckdb.register`.

Split from :mod:`dggs.duckdb` (which holds the Arrow <-> numpy helpers and
the point/cell functions).  Every function here takes whole Arrow batches:
functions of one id per row (children, disks, distances, corners) call the
compiled kernel once per batch (once per distinct level or ``k``), and
functions of one *set* of ids per row (compact, uncompact, dissolve,
polygon fill) convert and check the whole batch's ids at once, then call the
Python API once per row, since each row is its own set operation.

NULL in any argument gives NULL; NULL elements inside a list of ids are
skipped.  Errors are those of the Python API, named by the SQL function.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any

import duckdb
import numpy as np
import pyarrow as pa
import shapely

from dggs.duckdb.batches import (
    _ID_KINDS,
    _LATLNG_ARROW,
    _cell_at_level,
    _create,
    _ids,
    _ids_out,
    _numbers,
    _out,
    _sql_errors,
    _valid,
)
from dggs.errors import DggsValueError
from dggs.index.dissolve import cells_to_polygons
from dggs.index.grid import grid_disk, grid_distance, grid_ring
from dggs.index.hierarchy import cell_to_center_child, cell_to_children, compact_cells, get_level, uncompact_cells
from dggs.index.points import cell_to_boundary
from dggs.index.polyfill import polygon_to_cells
from dggs.index.vertex import cell_to_vertexes

__all__ = ["register_more"]

# the hierarchy, grid, region and vertex functions: name -> (SQL signature, return type, description)
_MORE_FUNCTIONS: dict[str, tuple[str, str, str]] = {
    "dggs_cell_to_children": ("(cell ID, level BIGINT)", "ID[]", "descendants at level, in id order"),
    "dggs_cell_to_center_child": ("(cell ID, level BIGINT)", "ID", "descendant at level holding the centre"),
    "dggs_grid_disk": ("(cell ID, k BIGINT)", "ID[]", "cells within k edge steps, sorted"),
    "dggs_grid_ring": ("(cell ID, k BIGINT)", "ID[]", "cells exactly k edge steps away, sorted"),
    "dggs_grid_distance": ("(a ID, b ID)", "BIGINT", "edge steps between cells of one level"),
    "dggs_compact_cells": ("(cells ID[])", "ID[]", "fewest cells covering the same area, sorted"),
    "dggs_uncompact_cells": ("(cells ID[], level BIGINT)", "ID[]", "descendants at level, sorted"),
    "dggs_cell_to_vertexes": ("(cell ID)", "VARCHAR[]", "ids of the 3 corners"),
    "dggs_cell_to_boundary": ("(cell ID)", "STRUCT(lat DOUBLE, lng DOUBLE)[]", "the 3 corners"),
    "dggs_cells_to_polygon_wkb": ("(cells ID[])", "BLOB", "WKB of the cells' union, lng/lat"),
    "dggs_polygon_to_cells": ("(wkb BLOB, level BIGINT, mode VARCHAR)", "BIGINT[]", "polygon fill"),
    "dggs_polygon_to_cells_str": ("(wkb BLOB, level BIGINT, mode VARCHAR)", "VARCHAR[]", "the same as string ids"),
}


# ---------------------------------------------------------------------------------------------- ragged results


def _lists(values: Any, counts: np.ndarray, valid: np.ndarray) -> Any:
    """A ListArray of ``values`` (an Arrow array) split by ``counts`` (one per valid row), NULL elsewhere."""
    full = np.zeros(len(valid), dtype=np.int64)
    full[valid] = counts
    offsets = pa.array(np.concatenate([[0], np.cumsum(full)]).astype(np.int32))
    mask = None if valid.all() else pa.array(~valid)
    return pa.ListArray.from_arrays(offsets, values, mask=mask)


def _id_lists(flat: np.ndarray, counts: np.ndarray, valid: np.ndarray, sql_type: str) -> Any:
    return _lists(_ids_out(flat, np.ones(flat.size, dtype=bool), sql_type), counts, valid)


def _ragged_by(
    groups: np.ndarray, compute: Callable[[np.ndarray, int], tuple[np.ndarray, np.ndarray]]
) -> tuple[np.ndarray, np.ndarray]:
    """Row-ordered (flat ids, counts) of ``compute(ids_rows, value) -> (flat, counts)`` over rows of one group value."""
    counts = np.zeros(groups.size, dtype=np.int64)
    parts = []
    for value in np.unique(groups):
        rows = np.flatnonzero(groups == value)
        flat, n = compute(rows, int(value))
        counts[rows] = n
        parts.append((rows, flat, n))
    out = np.zeros(int(counts.sum()), dtype=np.uint64)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64)
    for rows, flat, n in parts:
        local = np.concatenate([[0], np.cumsum(n)[:-1]]).astype(np.int64)
        out[np.repeat(starts[rows] - local, n) + np.arange(flat.size)] = flat
    return out, counts


def _padded(table: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(flat ids, counts) of a (N, M) uint64 table padded with 0."""
    table = np.asarray(table, dtype=np.uint64).reshape(table.shape[0], -1)
    keep = table != 0
    return table[keep], keep.sum(axis=1)


def _list_ids(name: str, a: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(row validity, checked uint64 ids of all non-NULL elements, element count per valid row) of a ListArray."""
    valid = _valid(a)
    values = a.flatten()  # the elements of non-NULL rows, in order
    lengths = a.value_lengths().fill_null(0).to_numpy(zero_copy_only=False).astype(np.int64)[valid]
    present = _valid(values)
    if not present.all():  # NULL elements are skipped
        row = np.repeat(np.arange(lengths.size), lengths)
        lengths = np.bincount(row[present], minlength=lengths.size).astype(np.int64)
    return valid, _ids(name, values, present), lengths


def _splits(lengths: np.ndarray) -> list[tuple[int, int]]:
    ends = np.cumsum(lengths)
    return list(zip((ends - lengths).tolist(), ends.tolist(), strict=True))


# ---------------------------------------------------------------------------------------------- one id per row


def _children_counts(ids: np.ndarray, level: int) -> np.ndarray:
    levels = np.asarray(get_level(ids), dtype=np.int64)
    below = np.maximum(level - levels, 0)
    return np.where((levels == 0) & (below > 0), 2 * 3**below, 3**below).astype(np.int64)


def _children(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(cell: Any, level: Any) -> Any:
        valid = _valid(cell, level)
        ids, levels = _ids(name, cell, valid), _numbers(level, valid, np.int64)

        def compute(rows: np.ndarray, lv: int) -> tuple[np.ndarray, np.ndarray]:
            return np.asarray(cell_to_children(ids[rows], lv), np.uint64), _children_counts(ids[rows], lv)

        return _id_lists(*_ragged_by(levels, compute), valid, sql_type)

    return _sql_errors(name)(fn)


def _disk(name: str, sql_type: str, kernel: Callable[..., Any]) -> Callable[..., Any]:
    def fn(cell: Any, k: Any) -> Any:
        valid = _valid(cell, k)
        ids, ks = _ids(name, cell, valid), _numbers(k, valid, np.int64)
        return _id_lists(*_ragged_by(ks, lambda rows, kk: _padded(kernel(ids[rows], kk))), valid, sql_type)

    return _sql_errors(name)(fn)


def _distance(name: str) -> Callable[..., Any]:
    def fn(a: Any, b: Any) -> Any:
        valid = _valid(a, b)
        ia, ib = _ids(name, a, valid), _ids(name, b, valid)
        steps = np.asarray(grid_distance(ia, ib), np.int64) if ia.size else np.zeros(0, np.int64)
        return _out(steps, valid, pa.int64())

    return _sql_errors(name)(fn)


def _vertexes(name: str) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:
        valid = _valid(cell)
        ids = _ids(name, cell, valid)
        names = np.asarray(cell_to_vertexes(ids), dtype=object).reshape(-1) if ids.size else np.zeros(0, object)
        return _lists(pa.array(names, pa.string()), np.full(ids.size, 3), valid)

    return _sql_errors(name)(fn)


def _boundary(name: str) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:
        valid = _valid(cell)
        ids = _ids(name, cell, valid)
        corners = np.asarray(cell_to_boundary(ids), np.float64).reshape(-1, 2) if ids.size else np.zeros((0, 2))
        points = pa.StructArray.from_arrays(
            [pa.array(corners[:, 0]), pa.array(corners[:, 1])], fields=list(_LATLNG_ARROW)
        )
        return _lists(points, np.full(ids.size, 3), valid)

    return _sql_errors(name)(fn)


# ---------------------------------------------------------------------------------------------- one set of ids per row


def _compact(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(cells: Any) -> Any:
        valid, ids, lengths = _list_ids(name, cells)
        rows = [np.asarray(compact_cells(ids[s:e]), np.uint64) for s, e in _splits(lengths)]
        flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
        return _id_lists(flat, np.array([r.size for r in rows], np.int64), valid, sql_type)

    return _sql_errors(name)(fn)


def _uncompact(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(cells: Any, level: Any) -> Any:
        valid = _valid(cells, level)
        cells = cells.filter(pa.array(valid))
        levels = _numbers(level, valid, np.int64)
        _, ids, lengths = _list_ids(name, cells)
        split = _splits(lengths)
        rows = [
            np.asarray(uncompact_cells(ids[s:e], int(lv)), np.uint64) for (s, e), lv in zip(split, levels, strict=True)
        ]
        flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
        return _id_lists(flat, np.array([r.size for r in rows], np.int64), valid, sql_type)

    return _sql_errors(name)(fn)


def _dissolve(name: str) -> Callable[..., Any]:
    def fn(cells: Any) -> Any:
        valid, ids, lengths = _list_ids(name, cells)
        unions = [cells_to_polygons(ids[s:e]) for s, e in _splits(lengths)]  # outlines by edge identity
        return _out(np.asarray(shapely.to_wkb(unions), dtype=object).reshape(-1), valid, pa.binary())

    return _sql_errors(name)(fn)


def _polyfill(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(wkb: Any, level: Any, mode: Any) -> Any:
        valid = _valid(wkb, level, mode)
        blobs = np.asarray(wkb.filter(pa.array(valid)).to_pylist(), dtype=object)
        try:
            shapes = shapely.from_wkb(blobs)
        except shapely.errors.GEOSException as exc:
            raise DggsValueError(f"{name}: not a valid WKB geometry: {exc}") from None
        levels = _numbers(level, valid, np.int64)
        modes = mode.filter(pa.array(valid)).to_pylist()
        rows = [
            np.asarray(polygon_to_cells(shape, int(lv), mode=m, as_int=True), np.uint64)
            for shape, lv, m in zip(shapes, levels, modes, strict=True)
        ]
        flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
        return _id_lists(flat, np.array([r.size for r in rows], np.int64), valid, sql_type)

    return _sql_errors(name)(fn)


# ---------------------------------------------------------------------------------------------- registration


def _per_kind(name: str, sql_type: str) -> tuple[list[str], str, Callable[..., Any]]:
    """Parameters, return type and implementation of ``name`` for ids of SQL type ``sql_type``."""
    ids, level = [sql_type], [sql_type, "BIGINT"]
    id_list = f"{sql_type}[]"
    table: dict[str, tuple[list[str], str, Callable[[], Callable[..., Any]]]] = {
        "dggs_cell_to_children": (level, id_list, lambda: _children(name, sql_type)),
        "dggs_cell_to_center_child": (level, sql_type, lambda: _cell_at_level(name, sql_type, cell_to_center_child)),
        "dggs_grid_disk": (level, id_list, lambda: _disk(name, sql_type, grid_disk)),
        "dggs_grid_ring": (level, id_list, lambda: _disk(name, sql_type, grid_ring)),
        "dggs_grid_distance": ([sql_type, sql_type], "BIGINT", lambda: _distance(name)),
        "dggs_compact_cells": ([id_list], id_list, lambda: _compact(name, sql_type)),
        "dggs_uncompact_cells": ([id_list, "BIGINT"], id_list, lambda: _uncompact(name, sql_type)),
        "dggs_cell_to_vertexes": (ids, "VARCHAR[]", lambda: _vertexes(name)),
        "dggs_cell_to_boundary": (ids, "STRUCT(lat DOUBLE, lng DOUBLE)[]", lambda: _boundary(name)),
        "dggs_cells_to_polygon_wkb": ([id_list], "BLOB", lambda: _dissolve(name)),
    }
    params, returns, make = table[name]
    return params, returns, make()


_ARGS = {"dggs_grid_distance": ("a", "b"), "dggs_compact_cells": ("cells",), "dggs_uncompact_cells": ("cells", "level"),
         "dggs_cells_to_polygon_wkb": ("cells",), "dggs_grid_disk": ("cell", "k"), "dggs_grid_ring": ("cell", "k")}  # fmt: skip


def typed_macro(con: Any, name: str, per_kind: Callable[[str], tuple[list[str], str, Callable[..., Any]]],
                args: tuple[str, ...] | None = None) -> None:
    """Add one UDF per id kind (``{name}_i64``, ...) and the macro ``name`` that picks one by argument types.

    ``per_kind(sql_type)`` gives the UDF's SQL parameter types, return type and Python function; ``args`` the
    macro's argument names (default ``cell, level``, as many as parameters).  Used by the edge and path
    functions too.
    """
    overloads = []
    for sql_type, (suffix, _) in _ID_KINDS.items():
        params, returns, fn = per_kind(sql_type)
        _create(con, f"{name}_{suffix}", fn, params, returns)
        names = args or ("cell", "level")[: len(params)]
        typed = ", ".join(f"{arg} {typ}" for arg, typ in zip(names, params, strict=True))
        overloads.append(f"({typed}) AS {name}_{suffix}({', '.join(names)})")
    try:
        con.execute(f"CREATE OR REPLACE TEMPORARY MACRO {name}{', '.join(overloads)}")
    except duckdb.ParserException as exc:  # typed macro parameters came in DuckDB 1.4
        raise RuntimeError(f"dggs.duckdb needs DuckDB >= 1.4 (this is {duckdb.__version__}): {exc}") from exc


def register_more(con: Any) -> set[str]:
    """Add the functions of ``dggs.duckdb._MORE_FUNCTIONS`` to ``con``; the names added."""
    for name, sql_type in (("dggs_polygon_to_cells", "BIGINT"), ("dggs_polygon_to_cells_str", "VARCHAR")):
        _create(con, name, _polyfill(name, sql_type), ["BLOB", "BIGINT", "VARCHAR"], f"{sql_type}[]")
    for name in _MORE_FUNCTIONS:
        if name.startswith("dggs_polygon_to_cells"):
            continue
        typed_macro(con, name, partial(_per_kind, name), _ARGS.get(name))
    return set(_MORE_FUNCTIONS)
