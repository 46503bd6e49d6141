"""The point and cell SQL functions of :func:`dggs.duckdb.register` (Python UDFs), and ``register`` itself.

:func:`register` adds these and those of :mod:`dggs.duckdb.more` (hierarchy, grid, regions, vertices),
:mod:`dggs.duckdb.paths` (paths, lines, circles) and :mod:`dggs.duckdb.edges` (child positions, local (i, j),
directed edges); :data:`FUNCTIONS` lists them for the docs and tests.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import duckdb
import numpy as np
import pyarrow as pa
import shapely

from dggs.duckdb.batches import (
    _ID_KINDS,
    _LATLNG,
    _LATLNG_ARROW,
    _by_level,
    _cell_at_level,
    _create,
    _ids,
    _ids_out,
    _numbers,
    _out,
    _sql_errors,
    _valid,
)
from dggs.duckdb.edges import register_edges
from dggs.duckdb.more import _MORE_FUNCTIONS, register_more
from dggs.duckdb.paths import register_paths
from dggs.index.hierarchy import cell_to_parent, get_level, is_valid_cell
from dggs.index.measure import cell_area
from dggs.index.points import cell_to_latlng, cell_to_polygon, latlng_to_cell

__all__ = ["FUNCTIONS", "register"]

# name -> (SQL signature, return type, description): what register() adds, for the docs and tests
FUNCTIONS: dict[str, tuple[str, str, str]] = {
    "dggs_latlng_to_cell": ("(lat DOUBLE, lng DOUBLE, level BIGINT)", "BIGINT", "cell holding each point"),
    "dggs_latlng_to_cell_str": ("(lat DOUBLE, lng DOUBLE, level BIGINT)", "VARCHAR", "the same as a string id"),
    "dggs_cell_to_parent": ("(cell ID, level BIGINT)", "ID", "ancestor at level"),
    "dggs_cell_to_latlng": ("(cell ID)", _LATLNG, "centre"),
    "dggs_cell_to_latlng_lat": ("(cell ID)", "DOUBLE", "latitude of the centre"),
    "dggs_cell_to_latlng_lng": ("(cell ID)", "DOUBLE", "longitude of the centre"),
    "dggs_cell_to_boundary_wkb": ("(cell ID)", "BLOB", "WKB (Multi)Polygon, lng/lat"),
    "dggs_cell_area": ("(cell ID)", "DOUBLE", "area in m^2 on WGS84"),
    "dggs_get_level": ("(cell ID)", "INTEGER", "level 0..28"),
    "dggs_is_valid_cell": ("(cell ID)", "BOOLEAN", "well-formed id (never raises)"),
    "dggs_str_to_int": ("(cell ID)", "BIGINT", "integer id"),
    "dggs_int_to_str": ("(cell ID)", "VARCHAR", "string id"),
    **_MORE_FUNCTIONS,
}


# ---------------------------------------------------------------------------------------------- the functions


def _latlng_to_cell(name: str, out_type: str) -> Callable[..., Any]:
    def fn(lat: Any, lng: Any, level: Any) -> Any:
        valid = _valid(lat, lng, level)
        la, ln = _numbers(lat, valid, np.float64), _numbers(lng, valid, np.float64)
        levels = _numbers(level, valid, np.int64)
        ids = _by_level(levels, lambda rows, lv: latlng_to_cell(la[rows], ln[rows], lv, as_int=True), np.uint64)
        return _ids_out(ids, valid, out_type)

    return _sql_errors(name)(fn)


def _unary(name: str, compute: Callable[[np.ndarray], Any], typ: Any) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:
        valid = _valid(cell)
        return _out(compute(_ids(name, cell, valid)), valid, typ)

    return _sql_errors(name)(fn)


def _centre(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    if ids.size == 0:
        return np.zeros(0), np.zeros(0)
    lat, lng = cell_to_latlng(ids)
    return np.asarray(lat, np.float64), np.asarray(lng, np.float64)


def _cell_to_latlng(name: str) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:
        valid = _valid(cell)
        centre = _centre(_ids(name, cell, valid))
        lat, lng = _out(centre[0], valid, pa.float64()), _out(centre[1], valid, pa.float64())
        return pa.StructArray.from_arrays([lat, lng], fields=list(_LATLNG_ARROW), mask=pa.array(~valid))

    return _sql_errors(name)(fn)


def _wkb(ids: np.ndarray) -> np.ndarray:
    if ids.size == 0:
        return np.zeros(0, dtype=object)
    return np.asarray(shapely.to_wkb(np.atleast_1d(cell_to_polygon(ids))), dtype=object)


def _is_valid(name: str) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:  # never raises: no _ids check
        valid = _valid(cell)
        if pa.types.is_integer(cell.type):
            values = cell.fill_null(0).to_numpy()
            ids = values.view(np.uint64) if values.dtype == np.int64 else values.astype(np.uint64)
            ok = np.asarray(is_valid_cell(ids[valid]), dtype=bool)
        else:
            strings = cell.filter(pa.array(valid)).cast(pa.string()).to_numpy(zero_copy_only=False)
            ok = np.asarray(is_valid_cell(np.asarray(strings, dtype=object)), dtype=bool).reshape(-1)
        return _out(ok, valid, pa.bool_())

    return _sql_errors(name)(fn)


def _unary_ids(name: str, out_type: str) -> Callable[..., Any]:
    def fn(cell: Any) -> Any:
        valid = _valid(cell)
        return _ids_out(_ids(name, cell, valid), valid, out_type)

    return _sql_errors(name)(fn)


def _per_kind(name: str, sql_type: str) -> tuple[list[str], str, Callable[..., Any]]:
    """Parameters, return type and implementation of ``name`` for ids of SQL type ``sql_type``."""
    ident = [sql_type]
    if name == "dggs_cell_to_parent":
        return [sql_type, "BIGINT"], sql_type, _cell_at_level(name, sql_type, cell_to_parent)
    if name == "dggs_cell_to_latlng":
        return ident, _LATLNG, _cell_to_latlng(name)
    if name == "dggs_cell_to_latlng_lat":
        return ident, "DOUBLE", _unary(name, lambda ids: _centre(ids)[0], pa.float64())
    if name == "dggs_cell_to_latlng_lng":
        return ident, "DOUBLE", _unary(name, lambda ids: _centre(ids)[1], pa.float64())
    if name == "dggs_cell_to_boundary_wkb":
        return ident, "BLOB", _unary(name, _wkb, pa.binary())
    if name == "dggs_cell_area":
        return ident, "DOUBLE", _unary(name, lambda ids: np.asarray(cell_area(ids), np.float64), pa.float64())
    if name == "dggs_get_level":
        return ident, "INTEGER", _unary(name, lambda ids: np.asarray(get_level(ids), np.int32), pa.int32())
    if name == "dggs_is_valid_cell":
        return ident, "BOOLEAN", _is_valid(name)
    if name == "dggs_str_to_int":
        return ident, "BIGINT", _unary_ids(name, "BIGINT")
    if name == "dggs_int_to_str":
        return ident, "VARCHAR", _unary_ids(name, "VARCHAR")
    raise KeyError(name)  # pragma: no cover


def register(con: Any) -> Any:
    """Add the ``dggs_*`` SQL functions to DuckDB connection ``con`` and return it.

    Functions taking a cell id are overloaded for ``BIGINT``, ``UBIGINT``
    and ``VARCHAR`` ids (temporary macros over the typed functions
    ``<name>_i64``, ``<name>_u64``, ``<name>_str``); see :data:`FUNCTIONS`
    and ``docs/duckdb.md``.  Calling it again on the same connection
    replaces the functions.

    Raises
    ------
    RuntimeError
        If the installed DuckDB is older than 1.4 (it lacks the function API used).

    Examples
    --------
    >>> import duckdb
    >>> con = register(duckdb.connect())
    >>> con.sql("SELECT dggs_latlng_to_cell_str(51.05, -114.07, 9) AS c").fetchall()
    [('F200021102',)]
    >>> con.sql("SELECT dggs_cell_to_parent('F200021102', 3), dggs_get_level(5392473139689029632)").fetchall()
    [('F200', 9)]
    """
    _create(con, "dggs_latlng_to_cell", _latlng_to_cell("dggs_latlng_to_cell", "BIGINT"),
            ["DOUBLE", "DOUBLE", "BIGINT"], "BIGINT")  # fmt: skip
    _create(con, "dggs_latlng_to_cell_str", _latlng_to_cell("dggs_latlng_to_cell_str", "VARCHAR"),
            ["DOUBLE", "DOUBLE", "BIGINT"], "VARCHAR")  # fmt: skip
    more = register_more(con)  # hierarchy, grid, regions, vertices
    register_paths(con)  # paths, lines, circles
    register_edges(con)  # child positions, local (i, j), directed edges
    for name in FUNCTIONS:
        if name.startswith("dggs_latlng_to_cell") or name in more:
            continue
        overloads = []
        for sql_type, (suffix, _) in _ID_KINDS.items():
            params, returns, fn = _per_kind(name, sql_type)
            _create(con, f"{name}_{suffix}", fn, params, returns)
            if len(params) == 2:
                overloads.append(f"(cell {sql_type}, level BIGINT) AS {name}_{suffix}(cell, level)")
            else:
                overloads.append(f"(cell {sql_type}) AS {name}_{suffix}(cell)")
        try:
            con.execute(f"CREATE OR REPLACE TEMPORARY MACRO {name}{', '.join(overloads)}")
        except duckdb.ParserException as exc:  # typed macro parameters came in DuckDB 1.4
            raise RuntimeError(f"dggs.duckdb needs DuckDB >= 1.4 (this is {duckdb.__version__}): {exc}") from exc
    return con
