"""DuckDB SQL functions: the native extension (``dggs.duckdb.load(con)``) or Python UDFs (``register(con)``).

:func:`load` loads the native DuckDB extension built from the C core
(``make duckdb-extension``, docs/duckdb.md), which answers the same names in
C on DuckDB's own threads, into a Python connection, if its file is found.
The Python UDFs below remain for where it is not (no C compiler, a wheel
without it, a DuckDB older than 1.2) and for what it does not have yet
(dissolve, polygon fill, lines, circles, vertexes).

Optional extra: ``pip install 'dggs[duckdb]'``.  :func:`register` adds
vectorized scalar functions to a DuckDB connection.  DuckDB hands each
function a whole batch of rows (about 2,048) as Arrow arrays and dggs's
compiled kernel runs once per batch, not once per row::

    import duckdb, dggs.duckdb
    con = dggs.duckdb.register(duckdb.connect())
    con.sql("SELECT dggs_cell_to_parent(cell, 6) AS p, sum(pop) FROM 'points.parquet' GROUP BY 1")

Cell ids are ``BIGINT`` (every id is a positive int64, numeric order is the
string order), ``UBIGINT`` (what a numpy/pyarrow ``uint64`` column becomes)
or ``VARCHAR`` (``'C401'``).  A function that returns ids returns the kind it
was given.  Each overloaded name is a temporary SQL macro that dispatches on
the argument's type to a typed Python function named with a suffix
(``_i64``, ``_u64``, ``_str``), which can also be called directly.

NULL in any argument gives NULL.  Invalid ids, coordinates or levels raise a
DuckDB ``InvalidInputException`` whose message names the function and the
bad value, e.g. ``InvalidCellError: dggs_get_level: 'X9' is not a valid cell
id: ...``.  The full list of functions is in ``docs/duckdb.md``; the
hierarchy, grid, region and vertex functions are in ``dggs/_duckdb_more.py``.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import shapely

from dggs.errors import DggsValueError, InvalidCellError
from dggs.index.hierarchy import cell_to_parent, get_level, is_valid_cell
from dggs.index.ids import int_to_str, str_to_int
from dggs.index.measure import cell_area
from dggs.index.points import cell_to_latlng, cell_to_polygon, latlng_to_cell

try:  # the optional extra
    import duckdb
    import pyarrow as pa
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.duckdb needs the 'duckdb' extra: pip install 'dggs[duckdb]'") from exc

from dggs._duckdb_load import extension_path, load  # the native extension

__all__ = ["register", "load", "extension_path", "FUNCTIONS"]

# SQL type of an id argument -> (suffix of the typed function, Arrow type of ids of that kind)
_ID_KINDS: dict[str, tuple[str, Any]] = {
    "BIGINT": ("i64", pa.int64()),
    "UBIGINT": ("u64", pa.uint64()),
    "VARCHAR": ("str", pa.string()),
}
_LATLNG = "STRUCT(lat DOUBLE, lng DOUBLE)"
_LATLNG_ARROW = pa.struct([("lat", pa.float64()), ("lng", pa.float64())])
_INDEX = re.compile(r" at index \d+")

# the hierarchy, grid, region and vertex functions (dggs/_duckdb_more.py)
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


# ---------------------------------------------------------------------------------------------- Arrow <-> numpy


def _array(col: Any) -> Any:
    """A (Chunked)Array as one Array."""
    return col.combine_chunks() if isinstance(col, pa.ChunkedArray) else col


def _valid(*arrays: Any) -> np.ndarray:
    """Rows where no argument is NULL."""
    valid = np.ones(len(arrays[0]), dtype=bool)
    for a in arrays:
        if a.null_count:
            valid &= ~a.is_null().to_numpy(zero_copy_only=False)
    return valid


def _ids(name: str, a: Any, valid: np.ndarray) -> np.ndarray:
    """The non-NULL ids of Arrow array ``a`` (rows ``valid``) as checked uint64 ids."""
    if not pa.types.is_integer(a.type):  # string, large_string or string_view
        strings = a if valid.all() else a.filter(pa.array(valid))
        return np.asarray(str_to_int(strings.cast(pa.string())).to_numpy(), dtype=np.uint64)  # names a bad id
    values = a.fill_null(0).to_numpy()
    ids = values.view(np.uint64) if values.dtype == np.int64 else values.astype(np.uint64)
    ids = ids if valid.all() else ids[valid]
    ok = is_valid_cell(ids)
    if not np.all(ok):
        bad = values[valid][~np.asarray(ok)][0]
        try:
            get_level(int(bad))  # raises with the reason, naming the id as SQL shows it
        except InvalidCellError as exc:
            raise InvalidCellError(f"{name}: {exc}") from None
        raise InvalidCellError(f"{name}: {int(bad)} is not a valid cell id")  # pragma: no cover
    checked: np.ndarray = ids
    return checked


def _numbers(a: Any, valid: np.ndarray, dtype: Any) -> np.ndarray:
    values = np.asarray(a.fill_null(0).to_numpy(zero_copy_only=False), dtype=dtype)
    return values if valid.all() else values[valid]


def _out(values: np.ndarray, valid: np.ndarray, typ: Any) -> Any:
    """An Arrow array of ``typ`` with ``values`` at the ``valid`` rows and NULL elsewhere."""
    if valid.all():
        return pa.array(values, type=typ)
    full = np.zeros(len(valid), dtype=values.dtype) if values.dtype != object else np.empty(len(valid), dtype=object)
    full[valid] = values
    return pa.array(full, type=typ, mask=~valid)


def _ids_out(ids: np.ndarray, valid: np.ndarray, sql_type: str) -> Any:
    """uint64 ids as an Arrow array of the id kind ``sql_type``."""
    if sql_type == "VARCHAR":
        return _out(np.asarray(int_to_str(ids), dtype=object), valid, pa.string())
    if sql_type == "BIGINT":
        return _out(ids.view(np.int64), valid, pa.int64())
    return _out(ids, valid, pa.uint64())


def _by_level(levels: np.ndarray, compute: Callable[[np.ndarray | slice, int], np.ndarray], dtype: Any) -> np.ndarray:
    """``compute(rows, level)`` over groups of rows with one level: one call if the level is constant."""
    if levels.size == 0:
        return np.zeros(0, dtype=dtype)
    lo, hi = int(levels.min()), int(levels.max())
    if lo == hi:
        return np.asarray(compute(slice(None), lo), dtype=dtype)
    out = np.zeros(levels.size, dtype=dtype)
    for level in np.unique(levels):
        rows = levels == level
        out[rows] = compute(rows, int(level))
    return out


def _sql_errors(name: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Re-raise dggs's errors with the SQL function's name and without batch-relative indices."""

    def wrap(fn: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(fn)
        def udf(*args: Any) -> Any:
            try:
                return fn(*[_array(a) for a in args])
            except DggsValueError as exc:
                message = str(exc)
                if not message.startswith(name + ":"):
                    message = f"{name}: {_INDEX.sub('', message)}"
                raise type(exc)(message) from None

        return udf

    return wrap


# ---------------------------------------------------------------------------------------------- the functions


def _latlng_to_cell(name: str, out_type: str) -> Callable[..., Any]:
    def fn(lat: Any, lng: Any, level: Any) -> Any:
        valid = _valid(lat, lng, level)
        la, ln = _numbers(lat, valid, np.float64), _numbers(lng, valid, np.float64)
        levels = _numbers(level, valid, np.int64)
        ids = _by_level(levels, lambda rows, lv: latlng_to_cell(la[rows], ln[rows], lv, as_int=True), np.uint64)
        return _ids_out(ids, valid, out_type)

    return _sql_errors(name)(fn)


def _cell_at_level(name: str, sql_type: str, kernel: Callable[[np.ndarray, int], Any]) -> Callable[..., Any]:
    """``name(cell, level)``: one cell per row, ``kernel(ids, level)`` run once per distinct level."""
    def fn(cell: Any, level: Any) -> Any:
        valid = _valid(cell, level)
        ids, levels = _ids(name, cell, valid), _numbers(level, valid, np.int64)
        found = _by_level(levels, lambda rows, lv: kernel(ids[rows], lv), np.uint64)
        return _ids_out(found, valid, sql_type)

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


def _create(con: Any, name: str, fn: Callable[..., Any], params: list[str], returns: str) -> None:
    try:  # registering twice replaces the functions
        con.remove_function(name)
    except duckdb.Error:
        pass
    con.create_function(name, fn, params, returns, type="arrow", null_handling="special")


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
    from dggs._duckdb_more import register_more  # imports this module's helpers

    more = register_more(con)
    from dggs._duckdb_paths import register_paths  # paths, lines, circles

    register_paths(con)
    from dggs._duckdb_edges import register_edges  # child positions, local (i, j), directed edges

    register_edges(con)
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
