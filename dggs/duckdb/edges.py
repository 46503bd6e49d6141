"""The child position, local coordinate and directed edge SQL functions of :func:`dggs.duckdb.register`.

Each takes whole Arrow batches and calls the Python API once per batch, with
the batch's non-NULL rows as one numpy array of the column's own kind
(``BIGINT``, ``UBIGINT`` or ``VARCHAR`` ids), so ids come back in that kind:
a directed edge is ``VARCHAR`` (``'C401.2'``), ``UBIGINT`` or ``BIGINT``
(where its sign bit makes it negative; docs/grid.md, "Directed edges").
Every name taking an id is a temporary macro over typed functions ``_i64``,
``_u64`` and ``_str``, as the other functions.  NULL in any argument gives
NULL; errors are those of the Python API, named by the SQL function
(``dggs_is_valid_directed_edge`` never raises).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np
import pyarrow as pa

from dggs.duckdb.batches import _ID_KINDS, _LATLNG_ARROW, _numbers, _out, _sql_errors, _valid
from dggs.duckdb.more import _lists, typed_macro
from dggs.index.edges import (
    cells_to_directed_edge,
    directed_edge_to_boundary,
    directed_edge_to_cells,
    edge_length,
    get_directed_edge_destination,
    get_directed_edge_origin,
    is_valid_directed_edge,
    origin_to_directed_edges,
    reverse_directed_edge,
)
from dggs.index.local import cell_to_child_pos, cell_to_local_ij, child_pos_to_cell, local_ij_to_cell

__all__ = ["EDGE_FUNCTIONS", "register_edges"]

_IJ = "STRUCT(i BIGINT, j BIGINT)"
_IJ_ARROW = pa.struct([("i", pa.int64()), ("j", pa.int64())])

#: The functions :func:`register_edges` adds: (parameters, returns, what), as ``dggs.duckdb.FUNCTIONS``.
EDGE_FUNCTIONS: dict[str, tuple[str, str, str]] = {
    "dggs_cell_to_child_pos": ("(cell ID, parent_level BIGINT)", "BIGINT", "position among the ancestor's descendants"),
    "dggs_child_pos_to_cell": ("(pos BIGINT, parent ID, level BIGINT)", "ID", "the descendant at a position"),
    "dggs_cell_to_local_ij": ("(anchor ID, cell ID)", _IJ, "lattice coordinates around an anchor"),
    "dggs_local_ij_to_cell": ("(anchor ID, i BIGINT, j BIGINT)", "ID", "the cell at lattice coordinates"),
    "dggs_cells_to_directed_edge": ("(origin ID, destination ID)", "EDGE", "the edge between neighbours"),
    "dggs_origin_to_directed_edges": ("(cell ID)", "EDGE[]", "the 3 edges from a cell"),
    "dggs_directed_edge_to_cells": ("(edge EDGE)", "ID[]", "[origin, destination]"),
    "dggs_get_directed_edge_origin": ("(edge EDGE)", "ID", "the cell an edge starts from"),
    "dggs_get_directed_edge_destination": ("(edge EDGE)", "ID", "the cell an edge leads to"),
    "dggs_reverse_directed_edge": ("(edge EDGE)", "EDGE", "the edge back"),
    "dggs_is_valid_directed_edge": ("(edge EDGE)", "BOOLEAN", "well-formed edge id (never raises)"),
    "dggs_directed_edge_to_boundary": ("(edge EDGE)", "STRUCT(lat DOUBLE, lng DOUBLE)[]", "the edge's 2 corners"),
    "dggs_edge_length": ("(edge EDGE, unit VARCHAR)", "DOUBLE", "length of the edge curve: 'm', 'km' or 'rads'"),
}


def _col(a: Any, valid: np.ndarray) -> np.ndarray:
    """The non-NULL rows of an id column as numpy: int64, uint64 or an object array of str."""
    rows = a if valid.all() else a.filter(pa.array(valid))
    if pa.types.is_integer(rows.type):
        values = rows.to_numpy(zero_copy_only=False)
        return values if values.dtype in (np.int64, np.uint64) else values.astype(np.int64)
    return np.asarray(rows.cast(pa.string()).to_pylist(), dtype=object)


def _typed(values: Any, valid: np.ndarray, sql_type: str) -> Any:
    typ = _ID_KINDS[sql_type][1]
    return _out(np.asarray(values, dtype=object if sql_type == "VARCHAR" else typ.to_pandas_dtype()), valid, typ)


def _ids_to_ids(name: str, sql_type: str, verb: Callable[[np.ndarray], Any]) -> Callable[..., Any]:
    def fn(x: Any) -> Any:
        valid = _valid(x)
        values = _col(x, valid)
        return _typed(verb(values) if values.size else values, valid, sql_type)

    return _sql_errors(name)(fn)


def _ids_to_rows(name: str, sql_type: str, verb: Callable[[np.ndarray], Any], width: int) -> Callable[..., Any]:
    def fn(x: Any) -> Any:
        valid = _valid(x)
        values = _col(x, valid)
        flat = np.asarray(verb(values)).reshape(-1) if values.size else values
        return _lists(_typed(flat, np.ones(flat.size, dtype=bool), sql_type), np.full(values.size, width), valid)

    return _sql_errors(name)(fn)


def _pair_to_ids(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(a: Any, b: Any) -> Any:
        valid = _valid(a, b)
        va, vb = _col(a, valid), _col(b, valid)
        return _typed(cells_to_directed_edge(va, vb) if va.size else va, valid, sql_type)

    return _sql_errors(name)(fn)


def _child_pos(name: str) -> Callable[..., Any]:
    def fn(cell: Any, level: Any) -> Any:
        valid = _valid(cell, level)
        ids, levels = _col(cell, valid), _numbers(level, valid, np.int64)
        out = np.zeros(ids.size, dtype=np.int64)
        for lv in np.unique(levels):
            rows = levels == lv
            out[rows] = cell_to_child_pos(ids[rows], int(lv))
        return _out(out, valid, pa.int64())

    return _sql_errors(name)(fn)


def _child_cell(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(pos: Any, parent: Any, level: Any) -> Any:
        valid = _valid(pos, parent, level)
        p, ids, levels = _numbers(pos, valid, np.int64), _col(parent, valid), _numbers(level, valid, np.int64)
        out = np.empty(ids.size, dtype=ids.dtype)
        for lv in np.unique(levels):
            rows = levels == lv
            out[rows] = child_pos_to_cell(p[rows], ids[rows], int(lv))
        return _typed(out, valid, sql_type)

    return _sql_errors(name)(fn)


def _local_ij(name: str) -> Callable[..., Any]:
    def fn(anchor: Any, cell: Any) -> Any:
        valid = _valid(anchor, cell)
        a, c = _col(anchor, valid), _col(cell, valid)
        i, j = cell_to_local_ij(a, c) if a.size else (np.zeros(0, np.int64), np.zeros(0, np.int64))
        full_i, full_j = np.zeros(valid.size, np.int64), np.zeros(valid.size, np.int64)
        full_i[valid], full_j[valid] = i, j
        return pa.StructArray.from_arrays([pa.array(full_i), pa.array(full_j)], fields=list(_IJ_ARROW), mask=pa.array(~valid))

    return _sql_errors(name)(fn)


def _local_cell(name: str, sql_type: str) -> Callable[..., Any]:
    def fn(anchor: Any, i: Any, j: Any) -> Any:
        valid = _valid(anchor, i, j)
        a = _col(anchor, valid)
        ii, jj = _numbers(i, valid, np.int64), _numbers(j, valid, np.int64)
        return _typed(local_ij_to_cell(a, ii, jj) if a.size else a, valid, sql_type)

    return _sql_errors(name)(fn)


def _is_valid(name: str) -> Callable[..., Any]:
    def fn(edge: Any) -> Any:
        valid = _valid(edge)
        values = _col(edge, valid)
        return _out(np.asarray(is_valid_directed_edge(values), dtype=bool).reshape(-1), valid, pa.bool_())

    return _sql_errors(name)(fn)


def _boundary(name: str) -> Callable[..., Any]:
    def fn(edge: Any) -> Any:
        valid = _valid(edge)
        values = _col(edge, valid)
        ends = np.asarray(directed_edge_to_boundary(values), np.float64).reshape(-1, 2) if values.size else np.zeros((0, 2))
        points = pa.StructArray.from_arrays([pa.array(ends[:, 0]), pa.array(ends[:, 1])], fields=list(_LATLNG_ARROW))
        return _lists(points, np.full(values.size, 2), valid)

    return _sql_errors(name)(fn)


def _length(name: str) -> Callable[..., Any]:
    def fn(edge: Any, unit: Any) -> Any:
        valid = _valid(edge, unit)
        values = _col(edge, valid)
        units = np.asarray(unit.filter(pa.array(valid)).to_pylist() if not valid.all() else unit.to_pylist(), dtype=object)
        out = np.zeros(values.size)
        for u in set(units.tolist()):
            rows = units == u
            out[rows] = edge_length(values[rows], unit=u)
        return _out(out, valid, pa.float64())

    return _sql_errors(name)(fn)


def _per_kind(name: str, sql_type: str) -> tuple[list[str], str, Callable[..., Any]]:
    """Parameters, return type and implementation of ``name`` for ids (and edges) of SQL type ``sql_type``."""
    one, listed = [sql_type], f"{sql_type}[]"
    table: dict[str, tuple[list[str], str, Callable[[], Callable[..., Any]]]] = {
        "dggs_cell_to_child_pos": ([sql_type, "BIGINT"], "BIGINT", lambda: _child_pos(name)),
        "dggs_child_pos_to_cell": (["BIGINT", sql_type, "BIGINT"], sql_type, lambda: _child_cell(name, sql_type)),
        "dggs_cell_to_local_ij": ([sql_type, sql_type], _IJ, lambda: _local_ij(name)),
        "dggs_local_ij_to_cell": ([sql_type, "BIGINT", "BIGINT"], sql_type, lambda: _local_cell(name, sql_type)),
        "dggs_cells_to_directed_edge": ([sql_type, sql_type], sql_type, lambda: _pair_to_ids(name, sql_type)),
        "dggs_origin_to_directed_edges": (one, listed, lambda: _ids_to_rows(name, sql_type, origin_to_directed_edges, 3)),
        "dggs_directed_edge_to_cells": (one, listed, lambda: _ids_to_rows(name, sql_type, directed_edge_to_cells, 2)),
        "dggs_get_directed_edge_origin": (one, sql_type, lambda: _ids_to_ids(name, sql_type, get_directed_edge_origin)),
        "dggs_get_directed_edge_destination": (
            one, sql_type, lambda: _ids_to_ids(name, sql_type, get_directed_edge_destination)),
        "dggs_reverse_directed_edge": (one, sql_type, lambda: _ids_to_ids(name, sql_type, reverse_directed_edge)),
        "dggs_is_valid_directed_edge": (one, "BOOLEAN", lambda: _is_valid(name)),
        "dggs_directed_edge_to_boundary": (one, "STRUCT(lat DOUBLE, lng DOUBLE)[]", lambda: _boundary(name)),
        "dggs_edge_length": ([sql_type, "VARCHAR"], "DOUBLE", lambda: _length(name)),
    }  # fmt: skip
    params, returns, make = table[name]
    return params, returns, make()


_ARGS: dict[str, tuple[str, ...]] = {
    "dggs_cell_to_child_pos": ("cell", "parent_level"),
    "dggs_child_pos_to_cell": ("pos", "parent", "level"),
    "dggs_cell_to_local_ij": ("anchor", "cell"),
    "dggs_local_ij_to_cell": ("anchor", "i", "j"),
    "dggs_cells_to_directed_edge": ("origin", "destination"),
    "dggs_origin_to_directed_edges": ("cell",),
    "dggs_edge_length": ("edge", "unit"),
}


def register_edges(con: Any) -> set[str]:
    """Add :data:`EDGE_FUNCTIONS` to DuckDB connection ``con``; the names added.

    Examples
    --------
    >>> import duckdb
    >>> import dggs.duckdb
    >>> con = dggs.duckdb.register(duckdb.connect())
    >>> con.sql("SELECT dggs_cells_to_directed_edge('C401', 'C402'), dggs_cell_to_child_pos('C421', 1)").fetchall()
    [('C401.1', 7)]
    >>> con.sql("SELECT dggs_cell_to_local_ij('C401', 'C402'), dggs_local_ij_to_cell('C401', 4, 2)").fetchall()
    [({'i': 4, 'j': 2}, 'C402')]
    """
    for name in EDGE_FUNCTIONS:
        typed_macro(con, name, partial(_per_kind, name), _ARGS.get(name, ("edge",)))
    return set(EDGE_FUNCTIONS)
