"""Vertex ids in any container: what the vertex verbs (:mod:`dggs.index.vertex`) read.

A vertex id is ``"<cell>:<i>"`` (:func:`dggs.index._corners.parse_vertex`); the verbs take one, or any
container of them that the cell verbs take (a list or tuple, nested lists of one shape, a numpy ``U``,
``S`` or object array, a pandas Series or Index, a pyarrow (Chunked)Array), and give back the kind they
got (issue 32: ``vertex_to_latlng(cell_to_vertexes(c))`` refused the list).  ASCII bytes are read as the
text they spell, as cell ids are.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from ._convert.frames import is_polars_series
from ._convert.kind import Kind
from ._corners import check_canonical, parse_vertex, vertex_keys

__all__ = ["vertex_args", "parse_vertexes", "vertex_flags"]


def _container(obj: Any) -> tuple[list[Any], Kind] | None:
    """The elements of a container of vertex ids (flat) and its :class:`Kind`; None for one vertex id.

    A container is what :func:`cell_to_vertexes` gives and what the cell verbs take: a list or
    tuple (nested lists of one shape), a numpy array (``U``, ``S`` or object), a pandas Series or
    Index, a pyarrow (Chunked)Array, a polars Series.  Anything else is one vertex id (checked by the verb).
    """
    mod = type(obj).__module__
    if mod.startswith("pandas"):
        import pandas as pd

        if isinstance(obj, pd.Series):
            return list(obj.tolist()), Kind("pandas", "str", (len(obj),), index=obj.index, name=obj.name)
        if isinstance(obj, pd.Index):
            return list(obj.tolist()), Kind("pandas-index", "str", (len(obj),), name=obj.name)
        return None
    if mod.startswith("pyarrow"):
        import pyarrow as pa

        if isinstance(obj, (pa.Array, pa.ChunkedArray)):
            return obj.to_pylist(), Kind("arrow", "str", (len(obj),), chunked=isinstance(obj, pa.ChunkedArray))
        return None
    if is_polars_series(obj):
        return obj.to_list(), Kind("polars", "str", (len(obj),), name=obj.name)
    if isinstance(obj, np.ndarray):
        if obj.ndim == 0:
            return None
        return obj.reshape(-1).tolist(), Kind("numpy", "str", obj.shape)
    if isinstance(obj, (list, tuple)):
        try:
            arr = np.empty(0, dtype=object) if len(obj) == 0 else np.array(obj, dtype=object)
        except ValueError:  # ragged
            raise DggsValueError(f"vertex ids must be one id or a regular (non-ragged) container of them, not {obj!r:.100}") from None
        if arr.ndim and any(isinstance(v, (list, tuple)) for v in arr.reshape(-1)):
            raise DggsValueError(f"vertex ids must be one id or a regular (non-ragged) container of them, not {obj!r:.100}")
        return arr.reshape(-1).tolist(), Kind("list", "str", arr.shape)
    return None


def _as_text(vertex: Any) -> Any:
    """A vertex id element as a plain ``str`` (``np.str_`` and ASCII bytes included); anything else as is."""
    if isinstance(vertex, (bytes, bytearray, np.bytes_)):
        try:
            return bytes(vertex).decode("ascii")
        except UnicodeDecodeError:
            return vertex
    return str(vertex) if isinstance(vertex, str) else vertex


def parse_vertexes(items: list[Any], many: bool) -> tuple[np.ndarray, np.ndarray]:
    """(owners, corner indexes) of vertex ids, each checked canonical; the error names the id (and its index)."""
    owners = np.zeros(len(items), dtype=np.uint64)
    index = np.zeros(len(items), dtype=np.int64)
    for i, v in enumerate(items):
        try:
            owners[i], index[i] = parse_vertex(_as_text(v))
        except DggsValueError as e:
            raise DggsValueError(f"{e} (at index {i})" if many else str(e)) from None
    if owners.size:
        o, k = vertex_keys(owners)
        rows = np.arange(owners.size)
        bad = np.flatnonzero((o[rows, index] != owners) | (k[rows, index] != index))
        if bad.size:
            i = int(bad[0])
            try:
                check_canonical(_as_text(items[i]), int(owners[i]), int(index[i]))
            except DggsValueError as e:
                raise DggsValueError(f"{e} (at index {i})" if many else str(e)) from None
    return owners, index


def vertex_args(vertex: Any) -> tuple[list[Any], Kind]:
    found = _container(vertex)
    return found if found is not None else ([vertex], Kind("scalar", "str", (), True))


def vertex_flags(items: list[Any]) -> np.ndarray:
    """Whether each element is a canonical vertex id (never raises)."""
    owners = np.zeros(len(items), dtype=np.uint64)
    index = np.zeros(len(items), dtype=np.int64)
    for i, v in enumerate(items):
        try:
            owners[i], index[i] = parse_vertex(_as_text(v))
        except DggsValueError:
            continue  # owner 0: not a vertex id
    flags: np.ndarray = owners != 0
    ok = np.flatnonzero(flags)
    if ok.size:
        o, k = vertex_keys(owners[ok])
        rows = np.arange(ok.size)
        flags[ok] = (o[rows, index[ok]] == owners[ok]) & (k[rows, index[ok]] == index[ok])
    return flags
