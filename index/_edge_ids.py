"""Directed edge ids in any container: to their shadow cells and back.

An edge's integer id with the sign bit cleared is a valid cell id one level
finer than its origin, its "shadow" (:mod:`dggs.index._kernel.edges`), and its
string id is the origin's string, a dot and the direction (``"C401.2"``),
whose shadow is the string without the dot (``"C4012"``).  So edges go through
the cell converters (:mod:`dggs.index._convert`) as their shadows: these
functions map every leaf of a container (a str or int, lists and tuples,
numpy arrays, pandas Series and Index, pyarrow arrays, list arrays and
ChunkedArrays) between the two forms, keeping the container.  A leaf that is
no edge becomes an invalid shadow ("" or 0), which the cell converter refuses;
:func:`first_bad` then finds it to name it.
"""

from __future__ import annotations

import sys
from typing import Any

import numpy as np

from dggs.errors import InvalidCellError

from ._convert import Kind, cells_in, cells_out, values_out
from ._convert.frames import is_polars_series, polars_out, series_to_arrow
from ._convert.kind import SCALAR_INT, SCALAR_STR
from ._convert.strings import format_int, parse_str, valid_int

__all__ = ["EDGE", "SEP", "CELL", "CELL_PAIR", "EDGE_OUT", "VALUE", "apply_edge", "edges_in", "edges_out", "to_shadow", "is_edge"]

#: The sign bit: set in every directed edge id.
EDGE = 1 << 63
#: Between the origin's string id and the direction digit.
SEP = "."
_LOW54 = (1 << 54) - 1
_L1_SHIFT = 54
_U_EDGE = np.uint64(EDGE)
#: What :func:`apply_edge` gives back: cells, edges, or values.
CELL, EDGE_OUT, VALUE, CELL_PAIR = "cell", "edge", "value", "cell pair"


def _str_shadow(s: str) -> str:
    if len(s) >= 3 and s[-2] == SEP and s[-1] in "012":
        return s[:-2] + s[-1]
    return ""


def _int_shadow(v: int) -> int:
    if v >> 63 != 1:
        return 0
    v ^= EDGE
    if not v & _LOW54 and (v >> _L1_SHIFT) & 7 > 3:  # a level-0 origin: directions 0-2 only
        return 0
    return v


def _leaf(x: Any, back: bool) -> Any:
    """One leaf to its shadow (``back``: a shadow to its edge); anything else unchanged.

    ASCII bytes are read as the string they spell and given back as bytes (as the cell
    converters read them), so ``b"C401"`` is no edge and ``b"C40.1"`` is the edge ``"C40.1"``.
    """
    if isinstance(x, (bytes, bytearray)):  # np.bytes_ too
        try:
            text = bytes(x).decode("ascii")
        except UnicodeDecodeError:
            return x if back else b""
        return _leaf(text, back).encode("ascii")
    if isinstance(x, str):
        if back:
            return x[:-1] + SEP + x[-1] if x else x
        return _str_shadow(x)
    if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
        x = int(x) & ((1 << 64) - 1)  # int64 edges are negative
        return (x | EDGE if x else 0) if back else _int_shadow(x)
    return x


def _ints(a: np.ndarray, back: bool) -> np.ndarray:
    u = a.view(np.uint64) if a.dtype.kind == "i" and a.dtype.itemsize == 8 else a.astype(np.uint64)
    if back:
        out = np.where(u != 0, u | _U_EDGE, u)
    else:
        low = (u & np.uint64(_LOW54)) == 0
        bad = ((u >> np.uint64(63)) != 1) | (low & (((u >> np.uint64(_L1_SHIFT)) & np.uint64(7)) > 3))
        out = np.where(bad, np.uint64(0), u ^ _U_EDGE)
    if back:  # edges are above 2**63 - 1: uint64 whatever signed type came in
        return out
    return out.view(a.dtype) if a.dtype.kind == "i" and a.dtype.itemsize == 8 else out.astype(a.dtype)


def _numpy(a: np.ndarray, back: bool) -> np.ndarray:
    if a.dtype.kind in "iu":
        return _ints(a, back)
    if a.dtype.kind == "S":
        flat = [_leaf(x.decode("ascii", "replace"), back).encode("ascii") for x in a.reshape(-1).tolist()]
        return np.array(flat, dtype="S").reshape(a.shape)
    flat = [_leaf(x, back) for x in a.reshape(-1).tolist()]
    if a.dtype.kind == "U":
        return np.array(flat, dtype=str).reshape(a.shape) if flat else a
    out = np.empty(a.shape, dtype=a.dtype if a.dtype.kind == "O" else object)
    out.reshape(-1)[:] = flat
    return out if a.dtype.kind == "O" else out.astype(a.dtype)


def _arrow(arr: Any, back: bool, pa: Any) -> Any:
    if isinstance(arr, pa.ChunkedArray):
        return pa.chunked_array([_arrow(c, back, pa) for c in arr.chunks], type=arr.type)
    t = arr.type
    if pa.types.is_list(t) or pa.types.is_large_list(t):
        return type(arr).from_arrays(arr.offsets, _arrow(arr.values, back, pa))
    if pa.types.is_fixed_size_list(t):
        return pa.FixedSizeListArray.from_arrays(_arrow(arr.values, back, pa), t.list_size)
    if pa.types.is_integer(t):
        values = arr.to_numpy(zero_copy_only=False)
        if values.dtype.kind not in "iu":  # nulls: the converter names them
            return arr
        mask = arr.is_null().to_numpy(zero_copy_only=False) if arr.null_count else None
        return pa.array(_ints(values, back), type=pa.uint64() if back else t, mask=mask)
    return pa.array([_leaf(x, back) if x is not None else None for x in arr.to_pylist()], type=t)


def _map(obj: Any, back: bool) -> Any:
    """``obj`` with every leaf mapped, in the same container."""
    if isinstance(obj, (list, tuple)):
        return type(obj)(_map(x, back) for x in obj)
    if isinstance(obj, np.ndarray):
        return _numpy(obj, back)
    pd, pa = sys.modules.get("pandas"), sys.modules.get("pyarrow")
    if pd is not None and isinstance(obj, (pd.Series, pd.Index)):
        values = obj.to_numpy()
        dtype = obj.dtype
        if values.dtype.kind in "iu":
            new: Any = _ints(values, back)
            dtype = new.dtype if back else dtype
        else:
            new = np.empty(len(values), dtype=object)
            new[:] = [_map(x, back) for x in values.tolist()]
        if isinstance(obj, pd.Index):
            return pd.Index(new, name=obj.name, dtype=dtype)
        return pd.Series(new, index=obj.index, name=obj.name, dtype=dtype)
    if pa is not None and isinstance(obj, (pa.Array, pa.ChunkedArray)):
        return _arrow(obj, back, pa)
    if is_polars_series(obj):
        return polars_out(_arrow(series_to_arrow(obj), back, sys.modules["pyarrow"]), obj.name)
    return _leaf(obj, back)


def to_shadow(obj: Any) -> Any:
    """Edges in any container to their shadow cells, in the same container (no edge: "" or 0)."""
    return _map(obj, False)


def is_edge(x: Any) -> bool:
    """Whether one leaf is a well-formed edge id of either form (its shadow is a valid cell)."""
    s = _leaf(x, False) if isinstance(x, (str, bytes, bytearray, int, np.integer)) else None
    if isinstance(s, bytes):
        s = s.decode("ascii")
    if isinstance(s, str):
        return bool(s) and parse_str(s) != 0
    return isinstance(s, int) and s != 0 and valid_int(s)


def _leaves(obj: Any) -> list[Any]:
    if isinstance(obj, np.generic):  # a numpy scalar has tolist() too, giving one value
        return [obj.item()]
    if isinstance(obj, (list, tuple)):
        return [y for x in obj for y in _leaves(x)]
    if isinstance(obj, np.ndarray):
        return obj.reshape(-1).tolist()
    if hasattr(obj, "to_pylist"):
        return list(obj.to_pylist())
    if is_polars_series(obj):
        return list(obj.to_list())
    if hasattr(obj, "tolist"):
        return list(obj.tolist())
    return [obj]


def first_bad(obj: Any) -> InvalidCellError:
    """The error naming the first leaf of ``obj`` that is no edge id."""
    leaves = _leaves(obj)
    for i, x in enumerate(leaves):
        if not is_edge(x):
            where = "" if len(leaves) == 1 and not isinstance(obj, (list, tuple, np.ndarray)) else f" at index {i}"
            return InvalidCellError(
                f"{x!r}{where} is not a valid directed edge id: expected a cell's string id, '{SEP}' and a direction "
                "0-2 (such as 'C401.2'), or its 64-bit integer form (sign bit set)"
            )
    return InvalidCellError(f"{obj!r} is not a valid directed edge id")


def edges_in(obj: Any) -> tuple[np.ndarray, Kind]:
    """Edge ids in any container as a flat uint64 array (sign bit set), and the container's kind (of the shadows).

    Raises
    ------
    InvalidCellError
        A leaf that is no directed edge id (the message names it and its index).
    """
    if type(obj) is str:  # a lone id: no containers
        s = _str_shadow(obj)
        v = parse_str(s) if s else 0
        if v:
            return np.array([v | EDGE], dtype=np.uint64), SCALAR_STR
    elif type(obj) is int:
        v = _int_shadow(obj)
        if v and valid_int(v):
            return np.array([v | EDGE], dtype=np.uint64), SCALAR_INT
    try:
        ids, kind = cells_in(to_shadow(obj))
    except InvalidCellError:
        raise first_bad(obj) from None
    return ids | _U_EDGE, kind


def _one_edge(v: int, form: str) -> Any:
    if form == "int":
        return v
    s = format_int(v ^ EDGE) or ""
    return s[:-1] + SEP + s[-1]


def edges_out(edges: np.ndarray, kind: Kind, trailing: tuple[int, ...] = ()) -> Any:
    """Edge ids (uint64, sign bit set; 0 for none) in the container of ``kind`` (as :func:`cells_out` does cells)."""
    if kind.scalar and len(trailing) <= 1 and edges.all():  # a lone edge, or one row of them
        values = [_one_edge(v, kind.form) for v in edges.reshape(-1).tolist()]
        return values if trailing else values[0]
    shadows = np.where(edges != 0, edges & ~_U_EDGE, edges)
    return _map(cells_out(shadows, kind, trailing), True)


def _lone(obj: Any) -> tuple[int, str]:
    """(edge id, form) of a plain ``str`` or ``int`` that is a valid edge, else (0, "")."""
    if type(obj) is str:
        s = _str_shadow(obj)
        v = parse_str(s) if s else 0
        return (v | EDGE, "str") if v else (0, "")
    if type(obj) is int:
        v = _int_shadow(obj)
        return (v | EDGE, "int") if v and valid_int(v) else (0, "")
    return 0, ""


def apply_edge(many: Any, one: Any, edge: Any, out: str) -> Any:
    """Run ``many`` over edges in any container (``one``, compiled, over a lone valid edge), giving back the same kind.

    ``out`` is :data:`CELL` (one cell per edge), :data:`CELL_PAIR` (two: a list
    for one edge, rows for containers), :data:`EDGE_OUT` (one edge per edge) or
    :data:`VALUE` (one value per edge).  ``one`` takes the edge as a
    Python int (above 2**63 - 1: a compiled entry of signature ``(uint64)``).

    Raises
    ------
    InvalidCellError
        An edge id is malformed (the message names it and its index).
    """
    v, form = _lone(edge)
    if v:  # the single-id fast path: no containers, no arrays, a compiled entry (an Entry's ``call``)
        r = one(v)
        if out == CELL:
            return format_int(int(r)) if form == "str" else int(r)
        if out == EDGE_OUT:
            return _one_edge(int(r), form)
        if out == CELL_PAIR:
            return [format_int(int(c)) for c in r] if form == "str" else [int(c) for c in r]
        return r
    ids, kind = edges_in(edge)
    res = many(ids)
    if out == CELL:
        return cells_out(res, kind)
    if out == CELL_PAIR:
        return cells_out(res, kind, (2,))
    if out == EDGE_OUT:
        return edges_out(res, kind)
    return values_out(res, kind)
