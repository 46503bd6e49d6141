"""The path, line and circle SQL functions of :func:`dggs.duckdb.register`.

- ``dggs_grid_path_cells(a ID, b ID) -> ID[]``: :func:`dggs.grid_path_cells`
  for the batch's pairs in one compiled call (typed overloads ``_i64``,
  ``_u64``, ``_str`` under one macro, as the other functions taking ids);
- ``dggs_line_to_cells(wkb BLOB, level BIGINT) -> BIGINT[]`` and ``_str``:
  :func:`dggs.line_to_cells` of a (Multi)LineString's WKB in (lng, lat);
- ``dggs_circle_to_cells(lat DOUBLE, lng DOUBLE, radius_m DOUBLE, level BIGINT, mode VARCHAR) -> BIGINT[]``
  and ``_str``: :func:`dggs.circle_to_cells`.

Lines and circles are one set operation per row, so they call the Python
API once per row after parsing the batch's WKB (or reading its numbers) at
once.  NULL in any argument gives NULL; errors are those of the Python API,
named by the SQL function.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pyarrow as pa
import shapely

from dggs.duckdb.batches import _create, _ids, _numbers, _sql_errors, _valid
from dggs.duckdb.more import _id_lists, typed_macro
from dggs.errors import DggsValueError
from dggs.index.circles import circle_to_cells
from dggs.index.paths import grid_path_cells, line_to_cells

__all__ = ["PATH_FUNCTIONS", "register_paths"]

#: The functions :func:`register_paths` adds: (parameters, returns, what), as ``dggs.duckdb.FUNCTIONS``.
PATH_FUNCTIONS: dict[str, tuple[str, str, str]] = {
    "dggs_grid_path_cells": ("(a ID, b ID)", "ID[]", "a shortest path in the edge graph, both ends included"),
    "dggs_line_to_cells": ("(wkb BLOB, level BIGINT)", "BIGINT[]", "cells along a (Multi)LineString's geodesics"),
    "dggs_line_to_cells_str": ("(wkb BLOB, level BIGINT)", "VARCHAR[]", "the same as string ids"),
    "dggs_circle_to_cells": (
        "(lat DOUBLE, lng DOUBLE, radius_m DOUBLE, level BIGINT, mode VARCHAR)", "BIGINT[]", "cells within a geodesic distance",
    ),
    "dggs_circle_to_cells_str": (
        "(lat DOUBLE, lng DOUBLE, radius_m DOUBLE, level BIGINT, mode VARCHAR)", "VARCHAR[]", "the same as string ids",
    ),
}


def _rows_out(rows: list[np.ndarray], valid: np.ndarray, sql_type: str) -> Any:
    flat = np.concatenate(rows) if rows else np.zeros(0, np.uint64)
    return _id_lists(flat, np.array([r.size for r in rows], np.int64), valid, sql_type)


def _path(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(a: Any, b: Any) -> Any:
        valid = _valid(a, b)
        ia, ib = _ids(name, a, valid), _ids(name, b, valid)
        rows = [np.asarray(p, np.uint64) for p in grid_path_cells(ia, ib)] if ia.size else []
        return _rows_out(rows, valid, sql_type)

    return _sql_errors(name)(fn)


def _line(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(wkb: Any, level: Any) -> Any:
        valid = _valid(wkb, level)
        blobs = np.asarray(wkb.filter(pa.array(valid)).to_pylist(), dtype=object)
        try:
            lines = shapely.from_wkb(blobs)
        except shapely.errors.GEOSException as exc:
            raise DggsValueError(f"{name}: not a valid WKB geometry: {exc}") from None
        levels = _numbers(level, valid, np.int64)
        rows = [np.asarray(line_to_cells(g, int(lv), as_int=True), np.uint64) for g, lv in zip(lines, levels, strict=True)]
        return _rows_out(rows, valid, sql_type)

    return _sql_errors(name)(fn)


def _circle(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(lat: Any, lng: Any, radius: Any, level: Any, mode: Any) -> Any:
        valid = _valid(lat, lng, radius, level, mode)
        la, lo, r = (_numbers(x, valid, np.float64) for x in (lat, lng, radius))
        levels = _numbers(level, valid, np.int64)
        modes = mode.filter(pa.array(valid)).to_pylist()
        rows = [
            np.asarray(circle_to_cells(float(y), float(x), float(d), int(lv), mode=m, as_int=True), np.uint64)
            for y, x, d, lv, m in zip(la, lo, r, levels, modes, strict=True)
        ]
        return _rows_out(rows, valid, sql_type)

    return _sql_errors(name)(fn)


def register_paths(con: Any) -> set[str]:
    """Add :data:`PATH_FUNCTIONS` to DuckDB connection ``con``; the names added.

    Examples
    --------
    >>> import duckdb
    >>> import dggs.duckdb
    >>> con = dggs.duckdb.register(duckdb.connect())
    >>> con.sql("SELECT dggs_grid_path_cells('C401', 'C420')").fetchall()
    [(['C401', 'C411', 'C410', 'C420'],)]
    >>> con.sql("SELECT len(dggs_circle_to_cells(48.85, 2.35, 20000.0, 12, 'center'))").fetchall()
    [(50,)]
    """
    for sql_type, suffix in (("BIGINT", ""), ("VARCHAR", "_str")):
        _create(con, f"dggs_line_to_cells{suffix}", _line(f"dggs_line_to_cells{suffix}", sql_type),
                ["BLOB", "BIGINT"], f"{sql_type}[]")  # fmt: skip
        _create(con, f"dggs_circle_to_cells{suffix}", _circle(f"dggs_circle_to_cells{suffix}", sql_type),
                ["DOUBLE", "DOUBLE", "DOUBLE", "BIGINT", "VARCHAR"], f"{sql_type}[]")  # fmt: skip
    name = "dggs_grid_path_cells"
    typed_macro(con, name, lambda t: ([t, t], f"{t}[]", _path(name, t)), ("a", "b"))
    return set(PATH_FUNCTIONS)
