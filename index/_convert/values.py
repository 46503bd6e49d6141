"""Values computed per id or per point, out in the container that came in.

Levels, faces, areas, validity flags, centres, boundaries and polygons are
not ids, but they go back in the kind of container the ids (or coordinates)
came in, as ids do (:mod:`.cells_out`): a Python scalar for a scalar, a list
for a list or tuple, a numpy array of the input's shape, a pandas Series on
the input's index, a pyarrow Array (or ChunkedArray) for pyarrow input, a
polars Series of the same name for a polars Series.
Trailing dimensions (the corners of a boundary) become nested lists, Series
of lists, or fixed-size list arrays.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from math import prod
from typing import Any

import numpy as np

from .frames import polars_out
from .kind import Kind

__all__ = ["values_out"]


def _nested_tuples(v: np.ndarray) -> Any:
    return tuple(_nested_tuples(x) for x in v) if v.ndim else v.item()


def _arrow(values: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    pa = sys.modules["pyarrow"]
    flat = values.reshape(-1)
    if flat.dtype == object:  # shapely geometries: WKB, as GeoArrow's geoarrow.wkb
        import shapely

        arr = pa.array(shapely.to_wkb(flat, byte_order=1, output_dimension=2).tolist(), type=pa.binary())
    else:
        arr = pa.array(flat)
    for d in reversed(trailing):
        arr = pa.FixedSizeListArray.from_arrays(arr, d)
    return pa.chunked_array([arr], type=arr.type) if kind.chunked else arr


def _pandas(values: np.ndarray, kind: Kind, trailing: tuple[int, ...]) -> Any:
    pd = sys.modules["pandas"]
    if trailing:
        rows = np.empty(kind.shape[0], dtype=object)
        rows[:] = values.reshape(kind.shape[0], *trailing).tolist() if kind.shape[0] else []
        values = rows
    return pd.Series(values.reshape(-1), index=kind.index, name=kind.name)


def values_out(values: np.ndarray, kind: Kind, trailing: tuple[int, ...] = (), rows: bool = False) -> Any:
    """Per-element ``values`` in the container described by ``kind``.

    Parameters
    ----------
    values : numpy.ndarray
        Of shape ``(N, *trailing)`` (or anything reshapeable to it), ``N`` the
        number of input elements, any dtype (object for geometries).
    kind : Kind
        What came in (:func:`.cells_in` or :func:`.coords.coords_in`).
    trailing : tuple of int
        Extra dimensions per element.
    rows : bool
        A scalar's trailing values as a list (a row, as a cell's vertex ids)
        rather than nested tuples (a boundary's points).

    Returns
    -------
    object
        A Python scalar (nested tuples with trailing dims) for a scalar; a
        (nested) list for a list or tuple; a numpy array shaped
        ``kind.shape + trailing``; a pandas Series on the input's index (of
        lists with trailing dims), a pandas Index for an Index; a pyarrow Array, fixed-size lists with
        trailing dims, WKB ``binary`` for geometries (a ChunkedArray for a
        ChunkedArray).

    Raises
    ------
    ValueError
        ``values`` do not hold ``N * prod(trailing)`` elements.

    Examples
    --------
    >>> from dggs.index._convert.kind import Kind
    >>> values_out(np.array([3, 4]), Kind("list", "str", (2,)))
    [3, 4]
    >>> values_out(np.array([[1.5, 2.5]]), Kind("scalar", "str", (), True), (2,))
    (1.5, 2.5)
    """
    trailing = tuple(trailing)
    values = np.asarray(values)
    if values.size != prod(kind.shape) * prod(trailing):
        raise ValueError(f"{values.size} values do not fit {kind.shape} + {trailing}")
    if kind.scalar:
        one = values.reshape((1, *trailing))[0]
        if trailing:
            return one.tolist() if rows else _nested_tuples(one)
        return one.item() if isinstance(one, np.generic) else one  # an object array gives the object itself
    shape = kind.shape + trailing
    c = kind.container
    if c == "numpy":
        return values.reshape(shape)
    if c == "pandas":
        return _pandas(values, kind, trailing)
    if c == "pandas-index":
        return sys.modules["pandas"].Index(_pandas(values, kind, trailing), name=kind.name)
    if c == "arrow":
        return _arrow(values, kind, trailing)
    if c == "polars":
        return polars_out(_arrow(values, replace(kind, chunked=False), trailing), kind.name)
    return values.reshape(shape).tolist()
