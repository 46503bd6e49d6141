"""Cell ids in any container, the same kind out (h3-py's thin converters around one kernel).

:func:`cells_in` takes a ``str`` or ``int`` id, or a list, tuple, numpy array
(``U``, ``S``, object, ``StringDType``, integer), pandas Series or pyarrow
(Chunked)Array of them, and gives one flat ``uint64`` array plus a
:class:`Kind`; the compiled kernel works on the array; :func:`cells_out`
(results aligned with the input) or :func:`cells_out_flat` (results that are
not) rebuild the same kind of container.  numpy and pyarrow arrays are parsed
from their buffers, Python strings in one pass over their NUL-joined text, a
lone ``str`` or ``int`` on a pure-Python fast path.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from math import prod
from typing import Any, NoReturn

import numpy as np

from dggs.errors import InvalidCellError

from . import _codec
from ._bits import MAX_LEVEL

__all__ = ["Kind", "cells_in", "cells_out", "cells_out_flat", "int_to_str", "is_valid_any", "str_to_int"]

_STR_REASON = f"expected a face letter A-T, a digit 0-5, then up to {MAX_LEVEL - 1} digits 0-2"
_INT_REASON = "not a well-formed 64-bit id (the integer form of a string id, see dggs.str_to_int)"
_TYPE_REASON = "expected a string id such as 'C401' or its 64-bit integer form"
_MISSING_REASON = "a missing value is not a cell id"
_NESTED_REASON = "a sequence here, but nested sequences must all have the same length"
_MIX_REASON = "a container must hold only string ids or only integer ids"
_OBJECT, _U64, _I64 = np.dtype(object), np.dtype(np.uint64), np.dtype(np.int64)
_NESTED = (list, tuple, set, frozenset, np.ndarray)


@dataclass(frozen=True)
class Kind:
    """What came into :func:`cells_in`, and what :func:`cells_out` rebuilds.

    ``container`` is ``'scalar'``, ``'list'``, ``'tuple'``, ``'numpy'``,
    ``'pandas'`` or ``'arrow'``; ``form`` is ``'str'`` or ``'int'``;
    ``shape`` is the input's shape (``()`` for a scalar); ``dtype`` the numpy
    dtype, pandas dtype or pyarrow type; ``index`` and ``name`` a pandas
    Series' own; ``chunked`` whether a pyarrow ChunkedArray came in.
    """

    container: str
    form: str
    shape: tuple[int, ...]
    scalar: bool = False
    dtype: Any = None
    index: Any = field(default=None, compare=False, repr=False)
    name: Any = None
    chunked: bool = False


_SCALAR_STR = Kind("scalar", "str", (), True)
_SCALAR_INT = Kind("scalar", "int", (), True)


# --------------------------------------------------------------------------
# Input
# --------------------------------------------------------------------------


def _scalar_id(x: Any) -> tuple[int, str | None]:
    """(id or 0, form) of a value of any type; form None for a wrong type."""
    if isinstance(x, str):
        return _codec.parse_str(x), "str"
    if isinstance(x, (bytes, bytearray, np.bytes_)):
        try:
            return _codec.parse_str(x.decode("ascii")), "str"
        except UnicodeDecodeError:
            return 0, "str"
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        return 0, None
    x = int(x)
    return (x if _codec.valid_int(x) else 0), "int"


def _fail(value: Any, index: int | None, form: str | None, shape: tuple[int, ...] = ()) -> NoReturn:
    """Raise InvalidCellError naming ``value`` (at ``index``), with the reason it is not an id."""
    value = value.item() if isinstance(value, np.generic) else value
    f = _scalar_id(value)[1]
    if f is None:
        missing = value is None or (isinstance(value, float) and math.isnan(value)) or type(value).__name__ == "NAType"
        reason = _MISSING_REASON if missing else _NESTED_REASON if isinstance(value, _NESTED) else _TYPE_REASON
    else:
        reason = _MIX_REASON if form and f != form else _STR_REASON if f == "str" else _INT_REASON
    where = ""
    if index is not None:
        at = index if len(shape) <= 1 else tuple(int(i) for i in np.unravel_index(index, shape))
        where = f" at index {at}"
    raise InvalidCellError(f"{value!r}{where} is not a valid cell id: {reason}")


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
            _fail(self.value_at(self.bad), None if k.scalar else self.bad, k.form, k.shape)
        return self.ids, self.kind

    def mask(self) -> np.ndarray:
        return _codec.valid_ints(self.ids) if self.kind.form == "int" else self.ids != 0


def _scan(items: Any, kind: Kind) -> _Parsed:
    """Element by element (mixed or odd types); the form is the first well-typed element's."""
    ids = np.zeros(len(items), dtype=np.uint64)
    form, bad = None, -1
    for i, x in enumerate(items):
        v, f = _scalar_id(x)
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
    parsed = _codec.parse_pystrings(items)
    return None if parsed is None else _Parsed(parsed[0], kind, parsed[1], items.__getitem__)


def _parse_numpy(arr: np.ndarray, kind: Kind) -> _Parsed:
    flat = arr.reshape(-1)
    k = arr.dtype.kind
    if k in "US":
        ids, bad = _codec.parse_chars(flat)
        return _Parsed(ids, replace(kind, form="str"), bad, flat.__getitem__)
    if k in "iu":
        ids = np.ascontiguousarray(flat, dtype=np.int64 if k == "i" else np.uint64).view(np.uint64)
        return _Parsed(ids, replace(kind, form="int"), int(_codec.check_ints(ids)), flat.__getitem__)
    items = flat.tolist()  # object, StringDType, floats, bools, ...: Python values
    kind = replace(kind, form="str")
    return (_parse_strings(items, kind) if k in "OT" else None) or _scan(items, kind)


def _parse_sequence(seq: Any, container: str) -> _Parsed:
    kind = Kind(container, "str", (len(seq),))
    parsed = _parse_strings(seq, kind)  # the common case: a flat list of str
    if parsed is not None:
        return parsed
    if any(isinstance(x, bytearray) for x in seq):  # numpy would read its bytes as numbers
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
            p = _parse_numpy(vals, _SCALAR_INT)
            ids, b = p.ids, p.bad
        else:
            if pa.types.is_dictionary(t):
                chunk = chunk.dictionary_decode()
            if not any(f(chunk.type) for f in (pa.types.is_string, pa.types.is_large_string, pa.types.is_binary, pa.types.is_large_binary)):
                try:
                    chunk = chunk.cast(pa.large_string())
                except (pa.ArrowException, ValueError, TypeError, NotImplementedError):
                    chunk = pa.nulls(len(chunk), pa.string())
            ids, b = _codec.parse_arrow_array(chunk, pa)
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
        p.kind = replace(p.kind, dtype=dt if keep else _OBJECT if p.kind.form == "str" else _U64)
    p.value_at = lambda i: s.iloc[i]
    return p


def _parse_any(obj: Any) -> _Parsed:
    """Everything but the ``str``/``int`` fast paths of :func:`cells_in`."""
    if isinstance(obj, np.ndarray):
        return _parse_numpy(obj, Kind("numpy", "str", obj.shape, dtype=obj.dtype))
    if isinstance(obj, (list, tuple)):
        return _parse_sequence(obj, "tuple" if isinstance(obj, tuple) else "list")
    if isinstance(obj, (str, bytes, bytearray, int, float, np.generic)) or obj is None:
        v, f = _scalar_id(obj)
        return _Parsed(np.array([v], dtype=np.uint64), _SCALAR_INT if f == "int" else _SCALAR_STR, -1 if v else 0, lambda i: obj)
    pd, pa = sys.modules.get("pandas"), sys.modules.get("pyarrow")
    if pd is not None and isinstance(obj, pd.Series):
        return _parse_pandas(obj, pd)
    if pa is not None and isinstance(obj, (pa.Array, pa.ChunkedArray)):
        return _parse_arrow(obj, pa)
    if hasattr(obj, "__array__"):
        arr = np.asarray(obj)
        return _parse_numpy(arr, Kind("numpy", "str", arr.shape, dtype=arr.dtype))
    if hasattr(obj, "__iter__") and not isinstance(obj, dict):
        return _parse_sequence(list(obj), "list")
    return _Parsed(np.zeros(1, dtype=np.uint64), _SCALAR_STR, 0, lambda i: obj)


def cells_in(obj: Any) -> tuple[np.ndarray, Kind]:
    """Ids in any container as a flat uint64 array, and the :class:`Kind` that came in.

    Parameters
    ----------
    obj : str, int, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        String ids or 64-bit integer ids (not a mix).

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
        v, kind = _codec.parse_str(obj), _SCALAR_STR
    elif t is int:
        v, kind = (obj if _codec.valid_int(obj) else 0), _SCALAR_INT
    else:
        return _parse_any(obj).check()
    if not v:
        _fail(obj, None, kind.form)
    a = np.empty(1, dtype=np.uint64)
    a[0] = v
    return a, kind


def is_valid_any(obj: Any) -> Any:
    """Whether ids are valid, never raising.

    A bool for a scalar; a bool Series (same index) for a pandas Series; a
    numpy bool array shaped like the input for anything else.
    """
    t = type(obj)
    if t is str:
        return _codec.parse_str(obj) != 0
    if t is int:
        return _codec.valid_int(obj)
    try:
        p = _parse_any(obj)
        mask = p.mask()
        if p.kind.scalar:
            return bool(mask[0])
        if p.kind.container == "pandas":
            return sys.modules["pandas"].Series(mask, index=p.kind.index, name=p.kind.name)
        return mask.reshape(p.kind.shape)
    except Exception:  # noqa: BLE001  (never raises: judge the top-level elements alone)
        try:
            return np.array([is_valid_any(x) is True for x in obj], dtype=bool)
        except Exception:  # noqa: BLE001
            return False


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------


def _u_array(ids: np.ndarray) -> np.ndarray:
    """Ids as a flat ``U`` array (the null id 0 as "")."""
    codes, bad = _codec.format_u32(ids)
    if bad >= 0:
        _fail(int(ids.reshape(-1)[bad]), bad, "int")
    return codes.view(f"U{codes.shape[1]}").reshape(-1)


def _py_values(ids: np.ndarray, form: str) -> list:
    """Flat list of Python str / int."""
    return _u_array(ids).tolist() if form == "str" else ids.reshape(-1).tolist()


def _nest(items: list, dims: tuple[int, ...]) -> list:
    """Group a flat list into nested lists of the given dims."""
    if len(dims) <= 1:
        return items
    step = prod(dims[1:])
    return [_nest(items[i * step : (i + 1) * step], dims[1:]) for i in range(dims[0])]


def _pylist(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    """Nested lists shaped ``kind.shape + trailing``; nulls dropped from the innermost trailing lists."""
    if not trailing:
        return _nest(_py_values(ids, kind.form), kind.shape)
    rows = ids.reshape(-1, trailing[-1])
    keep = rows != 0
    vals = _py_values(rows[keep], kind.form)
    ends = np.cumsum(keep.sum(axis=1)).tolist()
    lists = [vals[a:b] for a, b in zip([0, *ends[:-1]], ends)]
    outer = kind.shape + trailing[:-1]
    return _nest(lists, outer) if outer else lists[0]


def _numpy(ids: np.ndarray, kind: Kind, shape: tuple[int, ...]) -> np.ndarray:
    dt = kind.dtype
    if kind.form == "int":
        return np.ascontiguousarray(ids.view(np.int64) if dt == _I64 else ids).reshape(shape)
    if dt is not None and dt.kind == "S":
        codes, bad = _codec.format_u8(ids)
        if bad >= 0:
            _fail(int(ids.reshape(-1)[bad]), bad, "int")
        return codes.view(f"S{codes.shape[1]}").reshape(shape)
    u = _u_array(ids).reshape(shape)
    return u if dt is None or dt.kind == "U" else u.astype(dt)  # object or StringDType


def _arrow_values(ids: np.ndarray, kind: Kind, pa: Any) -> Any:
    """A flat pyarrow array of the kind's type (the null id 0 as a null)."""
    ids = np.ascontiguousarray(ids).reshape(-1)
    if kind.form == "str":
        out, bad = _codec.arrow_strings(ids, pa, large=kind.dtype is not None and pa.types.is_large_string(kind.dtype))
        if bad >= 0:
            _fail(int(ids[bad]), bad, "int")
        return out
    nulls = ids == 0
    return pa.array(ids.view(np.int64) if kind.dtype == pa.int64() else ids, mask=nulls if nulls.any() else None)


def _arrow(ids: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    pa = sys.modules["pyarrow"]
    if not trailing:
        out = _arrow_values(ids, kind, pa)
    else:  # list arrays: nulls dropped from the innermost lists
        rows = ids.reshape(-1, trailing[-1])
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
        vals, dt = np.empty(n, dtype=object), _OBJECT
        vals[:] = _pylist(ids, replace(kind, shape=(n,)), trailing) if n else []
    elif kind.form == "str" and isinstance(dt, np.dtype):
        vals = _u_array(ids).astype(object)
    elif kind.form == "str":  # a pandas string dtype: straight from Arrow buffers
        pa = sys.modules.get("pyarrow")
        vals = _arrow_values(ids, replace(kind, dtype=None), pa).fill_null("") if pa else _u_array(ids).astype(object)
    else:
        base = np.dtype(getattr(dt, "numpy_dtype", dt))
        vals = ids.view(np.int64) if base == _I64 else ids
        dt = dt if base in (_I64, _U64) else _U64
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
        array with trailing dims).  The null id 0 is ``""`` or ``0`` in numpy,
        pandas and list outputs, a null in Arrow outputs, and is dropped from
        the lists made for trailing dims.

    Raises
    ------
    ValueError
        If ``ids`` does not have the shape ``(N, *trailing)``.
    """
    if kind.scalar and not trailing and ids.shape == (1,):  # the fast path
        v = int(ids[0])
        return (_codec.format_int(v) or "") if kind.form == "str" else v
    ids = np.asarray(ids, dtype=np.uint64)
    trailing = tuple(trailing)
    if ids.shape != (prod(kind.shape), *trailing):
        raise ValueError(f"ids of shape {ids.shape} do not fit {kind.shape} + {trailing}")
    c = kind.container
    if c == "numpy":
        return _numpy(ids, kind, kind.shape + trailing)
    if c == "pandas":
        return _pandas(ids, kind, trailing)
    if c == "arrow":
        return _arrow(ids, kind, trailing)
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


# --------------------------------------------------------------------------
# Public converters
# --------------------------------------------------------------------------


def _as_form(kind: Kind, form: str) -> Kind:
    """The kind holding the same container in the other form (uint64 / ``U`` / object / ``string``)."""
    if kind.form == form:
        return kind
    if kind.scalar:
        return _SCALAR_INT if form == "int" else _SCALAR_STR
    dt: Any = {"numpy": _U64 if form == "int" else np.dtype("U1"), "pandas": _U64 if form == "int" else _OBJECT}.get(kind.container)
    if kind.container == "arrow":
        pa = sys.modules["pyarrow"]
        dt = pa.uint64() if form == "int" else pa.string()
    return replace(kind, form=form, dtype=dt)


def str_to_int(ids: Any) -> Any:
    """Convert string ids to 64-bit integer ids, keeping the container and shape.

    Parameters
    ----------
    ids : str, int, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        String ids (integer ids are checked and returned unchanged).

    Returns
    -------
    int, list, numpy.ndarray, pandas.Series or pyarrow (Chunked)Array
        A Python int for a scalar, lists for lists; numpy, pandas and pyarrow
        outputs are uint64.  Numeric order is the string order.

    Raises
    ------
    InvalidCellError
        Naming the first invalid id and its index.

    Examples
    --------
    >>> import dggs
    >>> hex(dggs.str_to_int("C401"))
    '0x4558000000000000'
    >>> dggs.str_to_int(["A", "A0"]) == [1 << 62, (1 << 62) | (1 << 54)]
    True
    >>> import numpy as np
    >>> dggs.str_to_int(np.array(["A", "T5"])).dtype
    dtype('uint64')
    """
    if type(ids) is str:  # the fast path
        v = _codec.parse_str(ids)
        return v if v else _fail(ids, None, "str")
    arr, kind = cells_in(ids)
    return cells_out(arr, _as_form(kind, "int"))


def int_to_str(ids: Any) -> Any:
    """Convert 64-bit integer ids to string ids, keeping the container and shape.

    Parameters
    ----------
    ids : int, str, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        Integer ids (string ids are checked and returned unchanged).  In a
        numpy array the null id 0 (the padding of :func:`dggs.grid_disk` rows)
        becomes ``""``.

    Returns
    -------
    str, list, numpy.ndarray, pandas.Series or pyarrow (Chunked)Array
        A Python str for a scalar, lists for lists, a ``U`` array for numpy,
        an object Series for pandas, a ``string`` array for pyarrow.

    Raises
    ------
    InvalidCellError
        Naming the first invalid id and its index.

    Examples
    --------
    >>> import dggs
    >>> dggs.int_to_str(0x4558000000000000)
    'C401'
    >>> import numpy as np
    >>> dggs.int_to_str(dggs.str_to_int(np.array([["A", "T5"], ["C401", "B0"]])))
    array([['A', 'T5'],
           ['C401', 'B0']], dtype='<U4')
    """
    if type(ids) is int:  # the fast path
        return _codec.format_int(ids) or _fail(ids, None, "int")
    if isinstance(ids, np.ndarray) and ids.dtype.kind in "iu" and ids.size and not ids.all():
        # the null id 0 (the padding of grid_disk rows) becomes ""
        cells_in(ids[ids != 0])  # raises naming a bad id
        codes, _ = _codec.format_u32(ids.astype(np.uint64).reshape(-1))
        return codes.view(f"<U{codes.shape[1]}").reshape(ids.shape)
    arr, kind = cells_in(ids)
    return cells_out(arr, _as_form(kind, "str"))


_INT64_END = 1 << 63


def scalar_id(obj: Any) -> int:
    """The id of a plain ``str`` that is a valid id, or a plain positive int64 (not yet validated), else 0.

    The caller passes it to a scalar kernel that validates ints, or takes the general path.

    The single-id fast path: a few hundred nanoseconds, no numpy.
    """
    t = type(obj)
    if t is str:
        return _codec.parse_str(obj)
    if t is int and 0 < obj < _INT64_END:  # validated by the kernel that takes it
        return obj
    return 0
