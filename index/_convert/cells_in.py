"""Cell ids in any container in: one flat ``uint64`` array and the :class:`Kind` that came in.

:func:`cells_in` takes a ``str`` or ``int`` id, or a list, tuple, numpy array
(``U``, ``S``, object, ``StringDType``, integer), pandas Series or pyarrow
(Chunked)Array of them; :func:`is_valid_any` judges the same without
raising.  numpy and pyarrow
arrays are parsed from their buffers, Python strings in one pass over their
NUL-joined text.  The containers are rebuilt by :mod:`.cells_out` and :mod:`.values`.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .._kernel import codec
from . import strings
from .frames import is_polars_series, series_to_arrow
from .kind import OBJECT, SCALAR_INT, SCALAR_STR, U64, Kind, fail, value_id
from .values import values_out

__all__ = ["cells_in", "is_valid_any"]


# --------------------------------------------------------------------------
# Input
# --------------------------------------------------------------------------


@dataclass
class _Parsed:
    """Parsed ids (0, or the raw bad int, where invalid), the first bad index (or -1) and its value."""

    ids: np.ndarray
    kind: Kind
    bad: int
    value_at: Callable[[int], Any]

    def check(self) -> tuple[np.ndarray, Kind]:
        if self.bad >= 0:
            k = self.kind
            fail(self.value_at(self.bad), None if k.scalar else self.bad, k.form, k.shape)
        return self.ids, self.kind

    def mask(self) -> np.ndarray:
        valid: np.ndarray = codec.valid_ints(self.ids) if self.kind.form == "int" else self.ids != 0
        return valid


def _scan(items: Any, kind: Kind) -> _Parsed:
    """Element by element (mixed or odd types); the form is the first well-typed element's."""
    ids = np.zeros(len(items), dtype=np.uint64)
    form, bad = None, -1
    for i, x in enumerate(items):
        v, f = value_id(x)
        form = form or f
        if v and f == form:
            ids[i] = v
        elif bad < 0:
            bad = i
    return _Parsed(ids, replace(kind, form=form or kind.form), bad, items.__getitem__)


def _parse_strings(items: Any, kind: Kind) -> _Parsed | None:
    """Python str (or bytes) elements in one pass; None if one is of another type."""
    if len(items) and isinstance(items[0], bytes) and not all(isinstance(x, bytes) for x in items):
        return None  # b"".join would take any buffer (a numpy integer's raw bytes): judge one by one
    parsed = strings.parse_pystrings(items)
    return None if parsed is None else _Parsed(parsed[0], kind, parsed[1], items.__getitem__)


def _parse_numpy(arr: np.ndarray, kind: Kind) -> _Parsed:
    flat = arr.reshape(-1)
    k = arr.dtype.kind
    if k in "US":
        ids, bad = strings.parse_chars(flat)
        return _Parsed(ids, replace(kind, form="str"), bad, flat.__getitem__)
    if k in "iu":
        ids = np.ascontiguousarray(flat, dtype=np.int64 if k == "i" else np.uint64).view(np.uint64)
        return _Parsed(ids, replace(kind, form="int"), int(codec.check_ints(ids)), flat.__getitem__)
    items = flat.tolist()  # object, StringDType, floats, bools, ...: Python values
    kind = replace(kind, form="str")
    return (_parse_strings(items, kind) if k in "OT" else None) or _scan(items, kind)


def _parse_sequence(seq: Any, container: str) -> _Parsed:
    kind = Kind(container, "str", (len(seq),))
    parsed = _parse_strings(seq, kind)  # the common case: a flat list of str
    if parsed is not None:
        return parsed
    if any(isinstance(x, bytearray) or x is np.ma.masked for x in seq):  # numpy would read bytes as numbers, masked as NaN
        return _scan(seq, kind)
    try:
        arr = np.asarray(seq)
    except (ValueError, TypeError, OverflowError):  # ragged nesting: judge the top-level elements
        return _scan(seq, kind)
    kind = replace(kind, shape=arr.shape)
    if arr.dtype.kind in "iu":
        parsed = _parse_numpy(arr, kind)
        if parsed.bad < 0:
            return parsed
    if arr.ndim == 1:  # numpy coerced mixed elements (ints to str, bools to ints): judge the originals
        return _scan(seq, kind)
    objs = np.empty(arr.shape, dtype=object)
    objs[...] = seq
    items = objs.reshape(-1).tolist()
    return _parse_strings(items, kind) or _scan(items, kind)


def _parse_arrow(arr: Any, pa: Any) -> _Parsed:
    chunked = isinstance(arr, pa.ChunkedArray)
    form = "int" if pa.types.is_integer(arr.type) else "str"
    parts, bad, start = [], -1, 0
    for chunk in arr.chunks if chunked else [arr]:
        t = chunk.type
        if form == "int":
            vals = chunk.fill_null(0).to_numpy() if chunk.null_count else chunk.to_numpy(zero_copy_only=True)
            p = _parse_numpy(vals, SCALAR_INT)
            ids, b = p.ids, p.bad
        else:
            if pa.types.is_dictionary(t):
                chunk = chunk.dictionary_decode()
            if not any(f(chunk.type) for f in (pa.types.is_string, pa.types.is_large_string, pa.types.is_binary, pa.types.is_large_binary)):
                try:
                    chunk = chunk.cast(pa.large_string())
                except (pa.ArrowException, ValueError, TypeError, NotImplementedError):
                    chunk = pa.nulls(len(chunk), pa.string())
            ids, b = strings.parse_arrow_array(chunk, pa)
        if b >= 0 and bad < 0:
            bad = start + b
        parts.append(ids)
        start += len(chunk)
    ids = parts[0] if len(parts) == 1 else np.concatenate(parts) if parts else np.zeros(0, dtype=np.uint64)
    kind = Kind("arrow", form, (len(arr),), dtype=arr.type, chunked=chunked)
    return _Parsed(ids, kind, bad, lambda i: arr[i].as_py())


def _parse_pandas(s: Any, pd: Any) -> _Parsed:
    dt = s.dtype
    kind = Kind("pandas", "str", (len(s),), dtype=dt, index=s.index, name=s.name)
    if isinstance(dt, np.dtype):
        p = _parse_numpy(s.to_numpy(), kind)
    elif getattr(dt, "storage", "") == "pyarrow" or isinstance(dt, getattr(pd, "ArrowDtype", ())):
        p = _parse_arrow(sys.modules["pyarrow"].array(s.array), sys.modules["pyarrow"])
        p.kind = replace(kind, form=p.kind.form)
    elif dt.kind in "iu" and not s.hasnans:
        p = _parse_numpy(s.to_numpy(dtype=dt.numpy_dtype), kind)
    else:
        p = _parse_numpy(s.to_numpy(dtype=object), kind)
    if not isinstance(dt, np.dtype):  # keep pandas string / integer dtypes only (not categories, ...)
        keep = (isinstance(dt, pd.StringDtype) or dt.kind == "U") if p.kind.form == "str" else dt.kind in "iu"
        p.kind = replace(p.kind, dtype=dt if keep else OBJECT if p.kind.form == "str" else U64)
    p.value_at = lambda i: s.iloc[i]
    return p


def _parse_masked(arr: np.ma.MaskedArray) -> _Parsed:
    """A numpy masked array: its masked entries are missing values (None, as pandas NA), not their hidden data."""
    kind = Kind("numpy", "str", arr.shape, dtype=arr.dtype)
    data, mask = np.asarray(arr.data), np.ma.getmaskarray(arr)
    if not mask.any():
        return _parse_numpy(data, kind)
    objs = data.astype(object)
    objs[mask] = None
    return _parse_numpy(objs, kind)


def _parse_any(obj: Any) -> _Parsed:
    """Everything but the ``str``/``int`` fast paths of :func:`cells_in`."""
    if isinstance(obj, np.ma.MaskedArray):
        return _parse_masked(obj)
    if isinstance(obj, np.ndarray):
        return _parse_numpy(obj, Kind("numpy", "str", obj.shape, dtype=obj.dtype))
    if isinstance(obj, (list, tuple)):
        return _parse_sequence(obj, "tuple" if isinstance(obj, tuple) else "list")
    if isinstance(obj, (str, bytes, bytearray, int, float, np.generic)) or obj is None:
        v, f = value_id(obj)
        return _Parsed(np.array([v], dtype=np.uint64), SCALAR_INT if f == "int" else SCALAR_STR, -1 if v else 0, lambda i: obj)
    pd, pa = sys.modules.get("pandas"), sys.modules.get("pyarrow")
    if pd is not None and isinstance(obj, pd.Series):
        return _parse_pandas(obj, pd)
    if pd is not None and isinstance(obj, pd.Index) and not isinstance(obj, pd.MultiIndex):
        p = _parse_pandas(pd.Series(obj, index=None, name=obj.name), pd)
        p.kind = replace(p.kind, container="pandas-index", index=None)
        return p
    if is_polars_series(obj):  # read as Arrow, answered as a Series of the same name (.frames)
        arr = series_to_arrow(obj)
        p = _parse_arrow(arr, sys.modules["pyarrow"])
        p.kind = replace(p.kind, container="polars", name=obj.name)
        return p
    if pa is not None and isinstance(obj, (pa.Array, pa.ChunkedArray)):
        return _parse_arrow(obj, pa)
    if pd is not None and isinstance(obj, pd.api.extensions.ExtensionArray) and obj.isna().any():
        # numpy reads pd.array([id, <NA>], dtype="Int64") as float64 (NaN, and every id a float): keep the NA, as a Series does
        objs = obj.to_numpy(dtype=object)
        return _parse_numpy(objs, Kind("numpy", "str", objs.shape, dtype=objs.dtype))
    if hasattr(obj, "__arrow_c_array__") or hasattr(obj, "__arrow_c_stream__"):
        # any Arrow producer (arro3, nanoarrow, ...) through the Arrow PyCapsule interface: pyarrow out
        import pyarrow

        arr = pyarrow.array(obj) if hasattr(obj, "__arrow_c_array__") else pyarrow.chunked_array(obj)
        return _parse_arrow(arr, pyarrow)
    if hasattr(obj, "__array__"):
        arr = np.asarray(obj)
        return _parse_numpy(arr, Kind("numpy", "str", arr.shape, dtype=arr.dtype))
    if hasattr(obj, "__iter__") and not isinstance(obj, dict):
        return _parse_sequence(list(obj), "list")
    return _Parsed(np.zeros(1, dtype=np.uint64), SCALAR_STR, 0, lambda i: obj)


def cells_in(obj: Any, nulls: bool = False) -> tuple[np.ndarray, Kind]:
    """Ids in any container as a flat uint64 array, and the :class:`Kind` that came in.

    Parameters
    ----------
    obj : str, int, sequence, numpy array, pandas Series, pyarrow (Chunked)Array, polars Series, or any
        object exporting an Arrow array or stream (``__arrow_c_array__`` / ``__arrow_c_stream__``; pyarrow out)
        String ids or 64-bit integer ids (not a mix).
    nulls : bool
        Accept the null id 0 in a numpy array of integer ids (it stays 0): the
        padding of the rows :func:`dggs.grid_disk` gives.

    Returns
    -------
    ids : numpy.ndarray
        uint64, 1-d, C-contiguous: every element, flattened in C order.
    kind : Kind
        What came in, for :func:`cells_out` and :func:`cells_out_flat`.

    Raises
    ------
    InvalidCellError
        Naming the first bad value and its index.
    """
    t = type(obj)
    if t is str:
        v, kind = strings.parse_str(obj), SCALAR_STR
    elif t is int:
        v, kind = (obj if strings.valid_int(obj) else 0), SCALAR_INT
    else:
        p = _parse_any(obj)
        if nulls and p.bad >= 0 and type(obj) is np.ndarray and obj.dtype.kind in "iu":  # raw ints kept in place
            p.bad = int(codec.max_level(p.ids)[1])  # the first bad id that is not the null id
        return p.check()
    if not v:
        fail(obj, None, kind.form)
    a = np.empty(1, dtype=np.uint64)
    a[0] = v
    return a, kind


def is_valid_any(obj: Any) -> Any:
    """Whether ids are valid, never raising: bools in the container that came in.

    A bool for a scalar, a list for a list, a numpy array of the input's
    shape, a bool Series on the input's index, a pyarrow bool array; input
    that is no container of ids at all gives False (or a numpy array judging
    its top-level elements).
    """
    t = type(obj)
    if t is str:
        return strings.parse_str(obj) != 0
    if t is int:
        return strings.valid_int(obj)
    try:
        p = _parse_any(obj)
        return values_out(p.mask(), p.kind)
    except Exception:  # noqa: BLE001  (never raises: judge the top-level elements alone)
        try:
            flags = [is_valid_any(x) is True for x in obj]
            return flags if isinstance(obj, (list, tuple)) else np.array(flags, dtype=bool)
        except Exception:  # noqa: BLE001
            return False
