"""Cell ids out: the container :func:`.cells_in.cells_in` saw, rebuilt around new ids.

:func:`cells_out` for results aligned with the input (optionally with
trailing dimensions per element), :func:`cells_out_flat` for results that are
not.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from math import prod
from typing import Any

import numpy as np

from . import strings
from .frames import polars_out
from .kind import I64, OBJECT, U64, Kind, fail

__all__ = ["cells_out", "cells_out_flat", "ids_array"]


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------


def _u_array(ids: np.ndarray) -> np.ndarray:
    """Ids as a flat ``U`` array (the null id 0 as "")."""
    codes, bad = strings.format_u32(ids)
    if bad >= 0:
        fail(int(ids.reshape(-1)[bad]), bad, "int")
    return codes.view(f"U{codes.shape[1]}").reshape(-1)


def _py_values(ids: np.ndarray, form: str) -> list[Any]:
    """Flat list of Python str / int."""
    values: list[Any] = _u_array(ids).tolist() if form == "str" else ids.reshape(-1).tolist()
    return values


def _nest(items: list[Any], dims: tuple[int, ...]) -> list[Any]:
    """Group a flat list into nested lists of the given dims."""
    if len(dims) <= 1:
        return items
    step = prod(dims[1:])
    return [_nest(items[i * step : (i + 1) * step], dims[1:]) for i in range(dims[0])]


def _pylist(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    """Nested lists shaped ``kind.shape + trailing``; nulls dropped from the innermost trailing lists."""
    if not trailing:
        return _nest(_py_values(ids, kind.form), kind.shape)
    rows = ids.reshape(prod(kind.shape) * prod(trailing[:-1]), trailing[-1])  # explicit: rows may be empty
    keep = rows != 0
    vals = _py_values(rows[keep], kind.form)
    ends = np.cumsum(keep.sum(axis=1)).tolist()
    lists = [vals[a:b] for a, b in zip([0, *ends][:-1], ends, strict=True)]
    outer = kind.shape + trailing[:-1]
    return _nest(lists, outer) if outer else lists[0]


def _numpy(ids: np.ndarray, kind: Kind, shape: tuple[int, ...]) -> np.ndarray:
    dt = kind.dtype
    if kind.form == "int":
        out = ids.view(np.int64) if dt is not None and dt.kind == "i" else ids
        if dt is not None and dt.kind in "iu" and out.dtype != dt:
            out = out.astype(dt)  # the input's byte order: '>i8' in, '>i8' out
        return np.ascontiguousarray(out).reshape(shape)
    if dt is not None and dt.kind == "S":
        codes, bad = strings.format_u8(ids)
        if bad >= 0:
            fail(int(ids.reshape(-1)[bad]), bad, "int")
        return codes.view(f"S{codes.shape[1]}").reshape(shape)
    u = _u_array(ids).reshape(shape)
    return u if dt is None or dt.kind == "U" else u.astype(dt)  # object or StringDType


def _arrow_values(ids: np.ndarray, kind: Kind, pa: Any) -> Any:
    """A flat pyarrow array of the kind's type (the null id 0 as a null)."""
    ids = np.ascontiguousarray(ids).reshape(-1)
    if kind.form == "str":
        out, bad = strings.arrow_strings(ids, pa, large=kind.dtype is not None and pa.types.is_large_string(kind.dtype))
        if bad >= 0:
            fail(int(ids[bad]), bad, "int")
        if kind.dtype is not None and out.type != kind.dtype:  # binary, string_view, dictionary in: the same out
            try:
                out = out.cast(kind.dtype)
            except (pa.ArrowException, NotImplementedError):  # a type strings cannot become: plain strings
                pass
        return out
    nulls = ids == 0
    return pa.array(ids.view(np.int64) if kind.dtype == pa.int64() else ids, mask=nulls if nulls.any() else None)


def _arrow(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    pa = sys.modules["pyarrow"]
    if not trailing:
        out = _arrow_values(ids, kind, pa)
    else:  # list arrays: nulls dropped from the innermost lists
        rows = ids.reshape(prod(kind.shape) * prod(trailing[:-1]), trailing[-1])  # explicit: rows may be empty
        keep = rows != 0
        offsets = np.zeros(rows.shape[0] + 1, dtype=np.int32)
        np.cumsum(keep.sum(axis=1), out=offsets[1:])
        out = pa.ListArray.from_arrays(offsets, _arrow_values(rows[keep], kind, pa))
        for d in reversed(trailing[:-1]):  # regular outer levels
            out = pa.ListArray.from_arrays(np.arange(0, len(out) + 1, d, dtype=np.int32), out)
    return pa.chunked_array([out], type=out.type) if kind.chunked else out


def _pandas(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    pd = sys.modules["pandas"]
    n, dt = kind.shape[0], kind.dtype
    if trailing:  # a Series of lists
        vals, dt = np.empty(n, dtype=object), OBJECT
        vals[:] = _pylist(ids, replace(kind, shape=(n,)), trailing) if n else []
    elif kind.form == "str" and isinstance(dt, np.dtype):
        vals = _u_array(ids).astype(object)
    elif kind.form == "str":  # a pandas string dtype: straight from Arrow buffers
        pa = sys.modules.get("pyarrow")
        vals = _arrow_values(ids, replace(kind, dtype=None), pa).fill_null("") if pa else _u_array(ids).astype(object)
    else:
        base = np.dtype(getattr(dt, "numpy_dtype", dt))
        vals = ids.view(np.int64) if base == I64 else ids
        dt = dt if base in (I64, U64) else U64
    return pd.Series(vals, index=kind.index, name=kind.name, dtype=dt)


def cells_out(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...] = ()) -> Any:
    """Rebuild the container :func:`cells_in` saw, holding ``ids``.

    Parameters
    ----------
    ids : numpy.ndarray
        uint64 ids of shape ``(N, *trailing)``, ``N`` the number of input elements.
    kind : Kind
        From :func:`cells_in`.
    trailing : tuple of int
        Extra dimensions per input element (e.g. ``(7,)`` for a disk around each cell).

    Returns
    -------
    object
        Shaped ``kind.shape + trailing``: a Python str/int for a scalar (a
        list, nested for two trailing dims, if there are trailing dims); a
        list for a list or tuple; a numpy array of the same dtype family
        (``U``, ``S``, object, StringDType, int64, else uint64); a pandas
        Series with the same index and name (of lists with trailing dims); a
        pyarrow (Chunked)Array of the same string or integer type (a list
        array with trailing dims); a polars Series of the same name (of lists
        with trailing dims).  The null id 0 is ``""`` or ``0`` in numpy,
        pandas and list outputs, a null in Arrow outputs, and is dropped from
        the lists made for trailing dims.

    Raises
    ------
    ValueError
        If ``ids`` does not have the shape ``(N, *trailing)``.
    """
    if kind.scalar and not trailing and ids.shape == (1,):  # the fast path
        v = int(ids[0])
        return (strings.format_int(v) or "") if kind.form == "str" else v
    ids = np.asarray(ids, dtype=np.uint64)
    trailing = tuple(trailing)
    if ids.shape != (prod(kind.shape), *trailing):
        raise ValueError(f"ids of shape {ids.shape} do not fit {kind.shape} + {trailing}")
    c = kind.container
    if c == "numpy":
        return _numpy(ids, kind, kind.shape + trailing)
    if c == "pandas":
        return _pandas(ids, kind, trailing)
    if c == "pandas-index":
        return sys.modules["pandas"].Index(_pandas(ids, replace(kind, index=None), trailing), name=kind.name)
    if c == "arrow":
        return _arrow(ids, kind, trailing)
    if c == "polars":
        return polars_out(_arrow(ids, replace(kind, container="arrow", chunked=False), trailing), kind.name)
    return _pylist(ids, kind, trailing)


def cells_out_flat(ids: np.ndarray, kind: Kind) -> Any:
    """A 1-d container of the input's kind holding ``ids`` (not aligned with the input).

    For the children of several cells, compacted sets, polyfills: the null id
    0 is dropped; a scalar input gives a Python list; a pandas Series gets a
    default index (and keeps its name).
    """
    ids = np.asarray(ids, dtype=np.uint64).reshape(-1)
    if not ids.all():  # a pass without a copy in the common case
        ids = ids[ids != 0]
    container = "list" if kind.scalar else kind.container
    return cells_out(ids, replace(kind, container=container, scalar=False, shape=(ids.shape[0],), index=None))


def ids_array(ids: np.ndarray, as_int: bool) -> np.ndarray:
    """A numpy array of made ids (a polygon fill, cells along a line): uint64, or ``U`` strings.

    For functions that make ids rather than take them, so no container came in.
    """
    ids = np.asarray(ids, dtype=np.uint64).reshape(-1)
    return ids if as_int else _u_array(ids) if ids.size else np.zeros(0, dtype="<U1")
