"""Arrow batches <-> numpy for :mod:`dggs.duckdb`'s Python UDFs: NULL masks, checked ids, typed results, errors.

DuckDB hands each Python UDF whole Arrow batches (about 2,048 rows); these helpers turn an argument into the
numpy values of its non-NULL rows (ids checked, naming a bad one), run a kernel once per distinct level, put
the answers back as an Arrow array with NULL where an argument was NULL, and re-raise dggs's errors under the
SQL function's name.  The functions themselves are in :mod:`dggs.duckdb.udfs`, :mod:`dggs.duckdb.more`,
:mod:`dggs.duckdb.paths` and :mod:`dggs.duckdb.edges`.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, InvalidCellError
from dggs.index.hierarchy import get_level, is_valid_cell
from dggs.index.ids import int_to_str, str_to_int

try:  # the optional extra
    import duckdb
    import pyarrow as pa
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.duckdb needs the 'duckdb' extra: pip install 'dggs[duckdb]'") from exc

# SQL type of an id argument -> (suffix of the typed function, Arrow type of ids of that kind)
_ID_KINDS: dict[str, tuple[str, Any]] = {
    "BIGINT": ("i64", pa.int64()),
    "UBIGINT": ("u64", pa.uint64()),
    "VARCHAR": ("str", pa.string()),
}
_LATLNG = "STRUCT(lat DOUBLE, lng DOUBLE)"
_LATLNG_ARROW = pa.struct([("lat", pa.float64()), ("lng", pa.float64())])
_INDEX = re.compile(r" at index \d+")

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


def _cell_at_level(name: str, sql_type: str, kernel: Callable[[np.ndarray, int], Any]) -> Callable[..., Any]:
    """``name(cell, level)``: one cell per row, ``kernel(ids, level)`` run once per distinct level."""
    def fn(cell: Any, level: Any) -> Any:
        valid = _valid(cell, level)
        ids, levels = _ids(name, cell, valid), _numbers(level, valid, np.int64)
        found = _by_level(levels, lambda rows, lv: kernel(ids[rows], lv), np.uint64)
        return _ids_out(found, valid, sql_type)

    return _sql_errors(name)(fn)


def _create(con: Any, name: str, fn: Callable[..., Any], params: list[str], returns: str) -> None:
    try:  # registering twice replaces the functions
        con.remove_function(name)
    except duckdb.Error:
        pass
    con.create_function(name, fn, params, returns, type="arrow", null_handling="special")
