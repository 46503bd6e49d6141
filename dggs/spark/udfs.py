"""The Arrow batch functions behind :mod:`dggs.spark`: Arrow arrays in, one Arrow array out.

Each function of :data:`FUNCTIONS` takes whole Arrow batches (what Spark's
Arrow UDFs pass: about 10,000 rows, ``spark.sql.execution.arrow.maxRecordsPerBatch``)
and runs dggs's compiled kernel once per batch (once per distinct level or ``k``).
Nothing here imports pyspark, so the functions run, and are tested, without a JVM.

* A NULL in any argument gives NULL.
* A bad value (an id that is not a cell, a coordinate out of range, a level
  out of ``0..MAX_LEVEL``, a parent finer than its cell, a WKB that is not a
  polygon) raises the :class:`dggs.DggsValueError` subclass of the Python API,
  its message naming the SQL function, the row of the batch, the row's values
  and the partition; with ``on_invalid="null"`` that row gives NULL instead.
  The bad rows are found by running the batch's rows one at a time, which
  only happens in a batch that failed.

Examples
--------
>>> import pyarrow as pa
>>> fn = batch_function("dggs_latlng_to_cell_str")
>>> fn(pa.array([51.05, None]), pa.array([-114.07, 0.0]), pa.array([9, 9])).to_pylist()
['F200021102', None]
>>> batch_function("dggs_cell_to_parent_str", "null")(pa.array(["F200021102", "Q9"]), pa.array([3, 3])).to_pylist()
['F200', None]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pyarrow as pa
import shapely

from dggs.errors import CoordinateError, DggsValueError, InvalidCellError
from dggs.index._checks import is_choice
from dggs.index.dissolve import cells_to_polygons
from dggs.index.grid import grid_disk
from dggs.index.hierarchy import cell_to_children, cell_to_parent, get_level, is_valid_cell
from dggs.index.ids import int_to_str, str_to_int
from dggs.index.measure import cell_area
from dggs.index.paths import grid_path_cells
from dggs.index.points import cell_to_latlng, cell_to_polygon, latlng_to_cell
from dggs.index.polyfill import polygon_to_cells

__all__ = ["FUNCTIONS", "ON_INVALID", "batch_function", "ColumnTypeError"]

ON_INVALID = ("raise", "null")
_LATLNG = "struct<lat:double,lng:double>"

# SQL name -> (arguments, Spark return type, description): what dggs.spark.register adds
FUNCTIONS: dict[str, tuple[str, str, str]] = {
    "dggs_latlng_to_cell": ("(lat, lng, level)", "bigint", "cell holding each point (WGS84 degrees)"),
    "dggs_latlng_to_cell_str": ("(lat, lng, level)", "string", "the same as a string id"),
    "dggs_cell_to_parent": ("(cell, level)", "bigint", "ancestor at level"),
    "dggs_cell_to_parent_str": ("(cell, level)", "string", "the same as a string id"),
    "dggs_cell_to_children": ("(cell, level)", "array<bigint>", "descendants at level, in id order"),
    "dggs_cell_to_latlng": ("(cell)", _LATLNG, "centre"),
    "dggs_cell_to_boundary_wkb": ("(cell)", "binary", "WKB (Multi)Polygon, lng/lat"),
    "dggs_grid_disk": ("(cell, k)", "array<bigint>", "cells within k edge steps, sorted"),
    "dggs_grid_path_cells": ("(a, b)", "array<bigint>", "a shortest path of edge neighbours from a to b"),
    "dggs_cells_to_polygons_wkb": ("(cells)", "binary", "WKB outline of an array of cells' union, lng/lat"),
    "dggs_polygon_to_cells": ("(wkb, level, mode)", "array<bigint>", "polygon fill: center, contains, overlaps"),
    "dggs_cell_area": ("(cell)", "double", "area in m^2 on WGS84"),
    "dggs_get_level": ("(cell)", "int", "level 0..28"),
    "dggs_is_valid_cell": ("(cell)", "boolean", "well-formed id (never raises)"),
    "dggs_str_to_int": ("(cell)", "bigint", "integer id"),
    "dggs_int_to_str": ("(cell)", "string", "string id"),
}


# ---------------------------------------------------------------------------------------------- Arrow -> numpy


def _ids(a: Any) -> np.ndarray:
    """Checked uint64 ids of a NULL-free Arrow array of int64 or string ids; raises naming a bad id."""
    if not pa.types.is_integer(a.type):
        return np.asarray(str_to_int(a.cast(pa.string())).to_numpy(), dtype=np.uint64)
    values = a.to_numpy()
    ids = values.view(np.uint64) if values.dtype == np.int64 else values.astype(np.uint64)
    ok = np.asarray(is_valid_cell(ids), dtype=bool)
    if not ok.all():
        bad = int(values[~ok][0])
        get_level(bad)  # raises InvalidCellError with the reason
        raise InvalidCellError(f"{bad} is not a valid cell id")  # pragma: no cover
    return ids


class ColumnTypeError(DggsValueError):
    """A column of a type the function cannot take (not a bad value: ``on_invalid="null"`` does not hide it)."""


def _nums(a: Any, dtype: Any) -> np.ndarray:
    """A NULL-free Arrow array of numbers (or of strings spelling them) as ``dtype``; raises naming a bad value."""
    if pa.types.is_integer(a.type):
        return np.asarray(a.to_numpy(zero_copy_only=False), dtype=dtype)
    if pa.types.is_floating(a.type) or pa.types.is_decimal(a.type):
        values = np.asarray(a.to_numpy(zero_copy_only=False), dtype=np.float64)
        if np.dtype(dtype).kind in "iu":  # a level or k given as doubles: whole numbers only
            whole = np.isfinite(values) & (np.floor(values) == values) & (np.abs(values) < 2.0**62)
            if not whole.all():
                raise DggsValueError(f"{float(values[~whole][0])!r} is not a whole number")
        return values.astype(dtype)
    if not (pa.types.is_string(a.type) or pa.types.is_large_string(a.type)):
        raise ColumnTypeError(f"expected a column of numbers, not {a.type}")
    out = np.zeros(len(a), dtype=dtype)
    for i, v in enumerate(a.to_pylist()):  # a string column: each value a number ('n/a' is a bad value of its row)
        try:
            out[i] = float(v) if np.dtype(dtype).kind == "f" else int(v)
        except (TypeError, ValueError, OverflowError):
            raise CoordinateError(f"{v!r} is not a number") from None
    return out


def _by_value(groups: np.ndarray, compute: Callable[[Any, int], Any]) -> list[tuple[Any, Any]]:
    """``[(rows, compute(rows, value))]`` over the distinct values of ``groups`` (one call if constant)."""
    if groups.size and groups.min() == groups.max():
        return [(slice(None), compute(slice(None), int(groups[0])))]
    return [(rows, compute(rows, int(v))) for v in np.unique(groups) for rows in [groups == v]]


def _per_value(groups: np.ndarray, compute: Callable[[Any, int], Any], dtype: Any) -> np.ndarray:
    out = np.zeros(groups.size, dtype=dtype)
    for rows, values in _by_value(groups, compute):
        out[rows] = values
    return out


def _ragged(groups: np.ndarray, compute: Callable[[Any, int], tuple[np.ndarray, np.ndarray]]) -> Any:
    """A list<int64> array, row by row, of ``compute(rows, value) -> (flat ids, counts)``."""
    counts = np.zeros(groups.size, dtype=np.int64)
    pieces = []
    for rows, (flat, n) in _by_value(groups, compute):
        counts[rows] = n
        pieces.append((np.arange(groups.size)[rows], flat, n))
    starts = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
    out = np.zeros(int(starts[-1]), dtype=np.uint64)
    for rows, flat, n in pieces:
        local = np.concatenate([[0], np.cumsum(n)[:-1]]).astype(np.int64)
        out[np.repeat(starts[rows] - local, n) + np.arange(flat.size)] = flat
    return pa.ListArray.from_arrays(pa.array(starts.astype(np.int32)), pa.array(out.view(np.int64)))


def _padded(table: Any) -> tuple[np.ndarray, np.ndarray]:
    table = np.asarray(table, dtype=np.uint64)
    table = table.reshape(table.shape[0], -1)
    keep = table != 0
    return table[keep], keep.sum(axis=1)


def _children_counts(ids: np.ndarray, level: int) -> np.ndarray:
    levels = np.asarray(get_level(ids), dtype=np.int64)
    below = np.maximum(level - levels, 0)
    return np.where((levels == 0) & (below > 0), 2 * 3**below, 3**below).astype(np.int64)


def _id_array(ids: np.ndarray, typ: str) -> Any:
    if typ == "string":
        return pa.array(np.asarray(int_to_str(ids), dtype=object) if ids.size else [], type=pa.string())
    return pa.array(np.asarray(ids, dtype=np.uint64).view(np.int64), type=pa.int64())


# ---------------------------------------------------------------------------------------------- the computations
# each takes NULL-free Arrow arrays of one length and returns an Arrow array of that length


def _latlng_to_cell(typ: str) -> Callable[..., Any]:
    def compute(lat: Any, lng: Any, level: Any) -> Any:
        la, ln = _nums(lat, np.float64), _nums(lng, np.float64)
        ids = _per_value(_nums(level, np.int64), lambda r, lv: latlng_to_cell(la[r], ln[r], lv, as_int=True), np.int64)
        return _id_array(ids.view(np.uint64), typ)

    return compute


def _cell_to_parent(typ: str) -> Callable[..., Any]:
    def compute(cell: Any, level: Any) -> Any:
        ids = _ids(cell)
        found = _per_value(_nums(level, np.int64), lambda r, lv: cell_to_parent(ids[r], lv), np.uint64)
        return _id_array(found, typ)

    return compute


def _children(cell: Any, level: Any) -> Any:
    ids = _ids(cell)
    return _ragged(_nums(level, np.int64),
                   lambda r, lv: (np.asarray(cell_to_children(ids[r], lv), np.uint64), _children_counts(ids[r], lv)))


def _disk(cell: Any, k: Any) -> Any:
    ids = _ids(cell)
    return _ragged(_nums(k, np.int64), lambda r, kk: _padded(grid_disk(ids[r], kk)))


def _path(a: Any, b: Any) -> Any:
    ia, ib = _ids(a), _ids(b)
    rows = [np.asarray(p, np.uint64) for p in grid_path_cells(ia, ib)] if ia.size else []
    flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
    offsets = np.concatenate([[0], np.cumsum([r.size for r in rows])]).astype(np.int32)
    return pa.ListArray.from_arrays(pa.array(offsets), pa.array(flat.view(np.int64)))


def _dissolve(cells: Any) -> Any:
    """One WKB outline per row of a list<id> array (NULL elements skipped): each row is its own set."""
    if not (pa.types.is_list(cells.type) or pa.types.is_large_list(cells.type) or pa.types.is_fixed_size_list(cells.type)):
        raise ColumnTypeError(f"expected an array of cell ids a row (array<string> or array<bigint>), not {cells.type}: "
                              "collect them first (collect_list)")
    out = []
    for i in range(len(cells)):
        values = cells[i].values
        ids = _ids(values.drop_null()) if values is not None and len(values) else np.zeros(0, np.uint64)
        out.append(shapely.to_wkb(cells_to_polygons(ids)))
    return pa.array(out, type=pa.binary())


def _centre(cell: Any) -> Any:
    ids = _ids(cell)
    lat, lng = cell_to_latlng(ids) if ids.size else (np.zeros(0), np.zeros(0))
    return pa.StructArray.from_arrays([pa.array(np.asarray(lat, np.float64)), pa.array(np.asarray(lng, np.float64))],
                                      names=["lat", "lng"])


def _wkb(cell: Any) -> Any:
    ids = _ids(cell)
    polygons = np.atleast_1d(cell_to_polygon(ids)) if ids.size else np.zeros(0, dtype=object)
    return pa.array(list(shapely.to_wkb(polygons)), type=pa.binary())


def _polyfill(wkb: Any, level: Any, mode: Any) -> Any:
    try:
        shapes = shapely.from_wkb(np.asarray(wkb.to_pylist(), dtype=object))
    except shapely.errors.GEOSException as exc:
        raise DggsValueError(f"not a valid WKB geometry: {exc}") from None
    levels, modes = _nums(level, np.int64), mode.to_pylist()
    rows = [np.asarray(polygon_to_cells(s, int(lv), mode=m, as_int=True), np.int64).view(np.uint64)
            for s, lv, m in zip(np.atleast_1d(shapes), levels, modes, strict=True)]
    flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
    offsets = np.concatenate([[0], np.cumsum([r.size for r in rows])]).astype(np.int32)
    return pa.ListArray.from_arrays(pa.array(offsets), pa.array(flat.view(np.int64)))


def _area(cell: Any) -> Any:
    ids = _ids(cell)
    return pa.array(np.asarray(cell_area(ids), np.float64) if ids.size else np.zeros(0), type=pa.float64())


def _level(cell: Any) -> Any:
    ids = _ids(cell)
    return pa.array(np.asarray(get_level(ids), np.int32) if ids.size else np.zeros(0, np.int32), type=pa.int32())


def _is_valid(cell: Any) -> Any:
    """Never raises: a column of any other type than ids (numbers, strings, bytes) is all False."""
    try:
        return _is_valid_ids(cell)
    except (pa.ArrowException, TypeError, ValueError, OverflowError):
        return pa.array(np.zeros(len(cell), dtype=bool), type=pa.bool_())


def _is_valid_ids(cell: Any) -> Any:
    if pa.types.is_integer(cell.type):
        values = cell.to_numpy()
        ids = values.view(np.uint64) if values.dtype == np.int64 else values.astype(np.uint64)
        return pa.array(np.asarray(is_valid_cell(ids), dtype=bool).reshape(-1), type=pa.bool_())
    strings = np.asarray(cell.cast(pa.string()).to_pylist(), dtype=object)
    return pa.array(np.asarray(is_valid_cell(strings), dtype=bool).reshape(-1), type=pa.bool_())


_COMPUTE: dict[str, Callable[..., Any]] = {
    "dggs_latlng_to_cell": _latlng_to_cell("bigint"),
    "dggs_latlng_to_cell_str": _latlng_to_cell("string"),
    "dggs_cell_to_parent": _cell_to_parent("bigint"),
    "dggs_cell_to_parent_str": _cell_to_parent("string"),
    "dggs_cell_to_children": _children,
    "dggs_cell_to_latlng": _centre,
    "dggs_cell_to_boundary_wkb": _wkb,
    "dggs_grid_disk": _disk,
    "dggs_grid_path_cells": _path,
    "dggs_cells_to_polygons_wkb": _dissolve,
    "dggs_polygon_to_cells": _polyfill,
    "dggs_cell_area": _area,
    "dggs_get_level": _level,
    "dggs_is_valid_cell": _is_valid,
    "dggs_str_to_int": lambda cell: _id_array(_ids(cell), "bigint"),
    "dggs_int_to_str": lambda cell: _id_array(_ids(cell), "string"),
}


# ---------------------------------------------------------------------------------------------- NULLs and bad rows


def _array(col: Any) -> Any:
    return col.combine_chunks() if isinstance(col, pa.ChunkedArray) else col


def _partition() -> str:
    try:
        from pyspark import TaskContext

        ctx = TaskContext.get()
    except ImportError:  # pragma: no cover - the extra is installed wherever Spark runs this
        ctx = None
    return f", partition {ctx.partitionId()}" if ctx is not None else ""


def _describe(name: str, args: list[Any], i: int) -> str:
    """``lat=95.0, lng=0.0, level=9``: the values of row ``i`` of ``args``, named as in :data:`FUNCTIONS`."""
    names = [n.strip() for n in FUNCTIONS[name][0].strip("()").split(",")]
    shown = []
    for arg_name, a in zip(names, args, strict=True):
        v = a[i].as_py()
        shown.append(f"{arg_name}={v[:16]!r}{'...' if len(v) > 16 else ''}" if isinstance(v, bytes) else f"{arg_name}={v!r}")
    return ", ".join(shown)


def batch_function(name: str, on_invalid: str = "raise") -> Callable[..., Any]:
    """The Arrow batch function of SQL function ``name``: Arrow arrays in, one Arrow array out.

    Parameters
    ----------
    name : str
        A key of :data:`FUNCTIONS`.
    on_invalid : {"raise", "null"}, default "raise"
        What a bad value does: raise the :class:`dggs.DggsValueError` subclass
        naming the function, the row and its values, or give NULL.

    Returns
    -------
    callable
        ``fn(*arrays) -> pyarrow.Array``, NULL wherever an argument is NULL.

    Raises
    ------
    DggsValueError
        If ``name`` is unknown or ``on_invalid`` is not ``"raise"`` or ``"null"``.

    Examples
    --------
    >>> import pyarrow as pa
    >>> batch_function("dggs_get_level")(pa.array([None, "C401"])).to_pylist()
    [None, 3]
    """
    if not is_choice(name, _COMPUTE):
        raise DggsValueError(f"{name!r} is not a dggs Spark function (one of {', '.join(FUNCTIONS)})")
    if not is_choice(on_invalid, ON_INVALID):
        raise DggsValueError(f"on_invalid={on_invalid!r} is not one of {ON_INVALID}")
    compute = _COMPUTE[name]
    typ = FUNCTIONS[name][1]

    def fn(*columns: Any) -> Any:
        args = [_array(c) for c in columns]
        n = len(args[0])
        valid = np.ones(n, dtype=bool)
        for a in args:
            if a.null_count:
                valid &= ~a.is_null().to_numpy(zero_copy_only=False)
        rows = np.flatnonzero(valid)
        sub = args if rows.size == n else [a.take(pa.array(rows)) for a in args]
        try:
            result = compute(*sub)
        except ColumnTypeError as exc:  # the column, not a value: whatever on_invalid says
            raise ColumnTypeError(f"{name}: {exc}") from None
        except DggsValueError as exc:
            result, rows = _bad_rows(name, compute, sub, rows, on_invalid, exc)
        except (pa.ArrowException, TypeError, ValueError, AttributeError, OverflowError) as exc:
            raise ColumnTypeError(f"{name} cannot take columns of type ({', '.join(str(a.type) for a in args)}): {exc}") from None
        return _spread(result, rows, n, typ)

    fn.__name__ = fn.__qualname__ = name
    return fn


def _bad_rows(name: str, compute: Callable[..., Any], sub: list[Any], rows: np.ndarray, on_invalid: str,
              exc: DggsValueError) -> tuple[Any, np.ndarray]:
    """Find the rows ``compute`` fails on: raise naming the first, or leave them all out (NULL)."""
    good = np.ones(rows.size, dtype=bool)
    for i in range(rows.size):
        try:
            compute(*[a.slice(i, 1) for a in sub])
        except DggsValueError as row_exc:
            if on_invalid == "raise":
                where = f"row {int(rows[i])} of the batch ({_describe(name, sub, i)}){_partition()}"
                raise type(row_exc)(f"{name}: {where}: {row_exc}") from None
            good[i] = False
    if good.all():  # the batch failed but no row alone does: report the batch's error
        raise type(exc)(f"{name}: {exc}") from None
    keep = np.flatnonzero(good)
    return compute(*[a.take(pa.array(keep)) for a in sub]), rows[keep]


def _spread(result: Any, rows: np.ndarray, n: int, typ: str) -> Any:
    """``result`` (one value per row of ``rows``) at those rows of an array of ``n``, NULL elsewhere."""
    if rows.size == n:
        return result
    where = np.full(n, len(result), dtype=np.int64)
    where[rows] = np.arange(rows.size)
    return pa.concat_arrays([result, pa.nulls(1, result.type)]).take(pa.array(where))
