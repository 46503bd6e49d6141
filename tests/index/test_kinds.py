"""Every public function gives back the kind of container it was given (README "Use").

The contract, for ids (and for coordinates into ``latlng_to_cell`` and
``great_circle_distance``):

- a Python ``str`` or ``int`` id (a Python float for a coordinate) gives a
  Python scalar of the type the docstring names: ``str``/``int`` ids,
  ``bool`` (``is_valid_cell``, ``are_neighbor_cells``), ``int``
  (``get_level``, ``get_face``, ``grid_distance``), ``float``
  (``cell_area``, distances), a ``tuple`` (``cell_to_latlng``,
  ``cell_to_boundary``), a shapely geometry (``cell_to_polygon``), and a
  ``list`` where a function gives several cells (or vertex ids) for one id;
- a ``list`` gives a ``list``, and so does a ``tuple`` (tests/test_forms.py
  already holds tuple -> list; a tuple is read as a sequence of ids, and
  lists are what the converters build for Python sequences);
- a numpy array gives a numpy array with the same leading shape;
- a pandas Series gives a pandas Series on the same index;
- a pyarrow Array gives a pyarrow Array, a ChunkedArray a ChunkedArray.

Where the README leaves the element type open, the rule is **the same
container as the input, holding the element type of the result**:
``get_level(pa.array(ids))`` is a pyarrow integer Array, ``is_valid_cell``
of a Series a bool Series on its index, ``cell_to_latlng`` of a list a pair
of lists, of a Series **a pair of Series on the input's index** ("gives back
the kind it was given": one Series per value, not a DataFrame), of a pyarrow
Array a pair of pyarrow Arrays; ``cell_to_polygon`` of a Series a Series of
geometries on its index and of a pyarrow Array a pyarrow Array (of WKB, the
encoding ``dggs.arrow`` writes); functions with several values per cell
(``edge_neighbors``, ``grid_disk``, ``cell_to_boundary``,
``cell_to_vertexes``, ...) give one row per cell: a list of lists, an
``(N, M)`` array, a Series of rows on the input's index, a pyarrow
(List)Array.  Functions whose output is one flat set of cells not aligned
with the input (``cell_to_children``, ``compact_cells``,
``uncompact_cells``) keep the container but not the index.  Two-id
functions get the same container twice.  ``cells_to_geojson`` gives a dict
whatever it is given (its docstring).

Only kinds are checked here; values are tests/test_drift.py's and
tests/test_forms.py's.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import polars as pl
import pyarrow as pa
import pytest
import shapely

import dggs

CELLS = ["C401", "B100"]
INTS = [dggs.str_to_int(c) for c in CELLS]
INDEX = [10, 20]
HAS_STRINGDTYPE = hasattr(np, "dtypes") and hasattr(np.dtypes, "StringDType")


def _series(values, dtype=None):
    return pd.Series(values, index=INDEX, name="cells", dtype=dtype)


# name -> (maker, kind): kind is "str", "int" (a scalar), "list", "numpy", "pandas", "arrow", "chunked"
ID_KINDS = {
    "str": (lambda: CELLS[0], "scalar"),
    "int": (lambda: INTS[0], "scalar"),
    "list-str": (lambda: list(CELLS), "list"),
    "list-int": (lambda: list(INTS), "list"),
    "tuple-str": (lambda: tuple(CELLS), "list"),
    "tuple-int": (lambda: tuple(INTS), "list"),
    "numpy-U": (lambda: np.array(CELLS), "numpy"),
    "numpy-S": (lambda: np.array(CELLS, dtype="S"), "numpy"),
    "numpy-object": (lambda: np.array(CELLS, dtype=object), "numpy"),
    "numpy-StringDType": (lambda: np.array(CELLS, dtype=np.dtypes.StringDType()), "numpy"),
    "numpy-uint64": (lambda: np.array(INTS, dtype=np.uint64), "numpy"),
    "numpy-int64": (lambda: np.array(INTS, dtype=np.int64), "numpy"),
    "pandas-object": (lambda: _series(CELLS, object), "pandas"),
    "pandas-string": (lambda: _series(CELLS, "string"), "pandas"),
    "pandas-uint64": (lambda: _series(INTS, "uint64"), "pandas"),
    "pandas-int64": (lambda: _series(INTS, "int64"), "pandas"),
    "arrow-string": (lambda: pa.array(CELLS, pa.string()), "arrow"),
    "arrow-large_string": (lambda: pa.array(CELLS, pa.large_string()), "arrow"),
    "arrow-uint64": (lambda: pa.array(INTS, pa.uint64()), "arrow"),
    "arrow-int64": (lambda: pa.array(INTS, pa.int64()), "arrow"),
    "chunked-string": (lambda: pa.chunked_array([CELLS[:1], CELLS[1:]]), "chunked"),
    "chunked-uint64": (lambda: pa.chunked_array([INTS[:1], INTS[1:]], pa.uint64()), "chunked"),
    "numpy-int64-big-endian": (lambda: np.array(INTS, dtype=">i8"), "numpy"),
    "pandas-index-object": (lambda: pd.Index(CELLS, name="cells"), "index"),
    "pandas-index-uint64": (lambda: pd.Index(INTS, dtype="uint64"), "index"),
    "arrow-string_view": (lambda: pa.array(CELLS, pa.string_view()), "arrow"),
    "arrow-binary": (lambda: pa.array([c.encode() for c in CELLS], pa.binary()), "arrow"),
    "arrow-large_binary": (lambda: pa.array([c.encode() for c in CELLS], pa.large_binary()), "arrow"),
    "arrow-dictionary": (lambda: pa.array(CELLS).dictionary_encode(), "arrow"),
    # issue 36: polars in, polars out
    "polars-string": (lambda: pl.Series("cells", CELLS), "polars"),
    "polars-uint64": (lambda: pl.Series("cells", INTS, dtype=pl.UInt64), "polars"),
    "polars-int64": (lambda: pl.Series("cells", INTS, dtype=pl.Int64), "polars"),
    "polars-categorical": (lambda: pl.Series("cells", CELLS, dtype=pl.Categorical), "polars"),
}

# name -> (call, scalar type, shape): "aligned" (one value per id), "rows" (several values per id),
# "pair" (two values per id: two containers), "flat" (one flat set of cells), "dict"
ID_FUNCS = {
    "str_to_int": (dggs.str_to_int, int, "aligned"),
    "int_to_str": (dggs.int_to_str, str, "aligned"),
    "is_valid_cell": (dggs.is_valid_cell, bool, "aligned"),
    "get_level": (dggs.get_level, int, "aligned"),
    "get_face": (dggs.get_face, int, "aligned"),
    "cell_area": (dggs.cell_area, float, "aligned"),
    "cell_to_latlng": (dggs.cell_to_latlng, tuple, "pair"),
    "cell_to_boundary": (dggs.cell_to_boundary, tuple, "rows"),
    "cell_to_polygon": (lambda c: dggs.cell_to_polygon(c, densify=1), shapely.Geometry, "aligned"),
    "cells_to_geojson": (lambda c: dggs.cells_to_geojson(c, densify=0), dict, "dict"),
    "cell_to_parent": (dggs.cell_to_parent, "id", "aligned"),
    "cell_to_center_child": (dggs.cell_to_center_child, "id", "aligned"),
    "cell_to_children": (dggs.cell_to_children, list, "flat"),
    "compact_cells": (dggs.compact_cells, list, "flat"),
    "uncompact_cells": (lambda c: dggs.uncompact_cells(c, 5), list, "flat"),
    "edge_neighbors": (dggs.edge_neighbors, list, "rows"),
    "grid_disk": (lambda c: dggs.grid_disk(c, 1), list, "rows"),
    "grid_ring": (lambda c: dggs.grid_ring(c, 1), list, "rows"),
    "cell_to_vertexes": (dggs.cell_to_vertexes, list, "rows"),
    "vertex_neighbors": (dggs.vertex_neighbors, list, "rows"),
    "grid_disk_vertex": (lambda c: dggs.grid_disk_vertex(c, 1), list, "rows"),
    "are_neighbor_cells": (lambda c: dggs.are_neighbor_cells(c, c), bool, "aligned"),
    "grid_distance": (lambda c: dggs.grid_distance(c, c), int, "aligned"),
    "cell_centers_distance": (lambda c: dggs.cell_centers_distance(c, c), float, "aligned"),
    "cell_to_child_pos": (lambda c: dggs.cell_to_child_pos(c, 1), int, "aligned"),
    "cell_to_local_ij": (lambda c: dggs.cell_to_local_ij(c, c), tuple, "pair"),
    "origin_to_directed_edges": (dggs.origin_to_directed_edges, list, "rows"),
}


def _scalar_ok(value, want, given) -> bool:
    if want == "id":  # the form given: str for str, int for int
        want = type(given)
    if want is int:
        return type(value) is int
    if want is bool:
        return type(value) is bool
    if want is float:
        return type(value) is float
    return isinstance(value, want)


def _same_kind(out, kind: str, given, shape: str) -> str | None:
    """None when ``out`` is the kind ``given`` asks for, else what is wrong."""
    if shape == "dict":
        return None if isinstance(out, dict) else f"expected a dict, got {type(out).__name__}"
    if shape == "pair":
        if not (isinstance(out, tuple) and len(out) == 2):
            return f"expected a pair, got {type(out).__name__}"
        problems = [_same_kind(part, kind, given, "aligned") for part in out]
        return "; ".join(f"part {i}: {p}" for i, p in enumerate(problems) if p) or None
    if kind == "list":
        if type(out) is not list:
            return f"expected a list, got {type(out).__name__}"
        if shape != "flat" and len(out) != len(given):
            return f"expected {len(given)} rows, got {len(out)}"
        if any(isinstance(x, np.generic) for x in out):
            return "list of numpy scalars, not Python values"
        return None
    if kind == "numpy":
        if not isinstance(out, np.ndarray):
            return f"expected a numpy array, got {type(out).__name__}"
        if shape != "flat" and out.shape[: given.ndim] != given.shape:
            return f"expected leading shape {given.shape}, got {out.shape}"
        return None
    if kind == "pandas":
        if not isinstance(out, pd.Series):
            return f"expected a pandas Series, got {type(out).__name__}"
        if shape != "flat" and out.index.tolist() != given.index.tolist():
            return f"expected index {given.index.tolist()}, got {out.index.tolist()}"
        return None
    if kind == "index":
        if not isinstance(out, pd.Index):
            return f"expected a pandas Index, got {type(out).__name__}"
        return None if shape == "flat" or len(out) == len(given) else f"expected {len(given)} rows, got {len(out)}"
    if kind == "arrow":
        if not isinstance(out, pa.Array):
            return f"expected a pyarrow Array, got {type(out).__name__}"
        return None if shape == "flat" or len(out) == len(given) else f"expected {len(given)} rows, got {len(out)}"
    if kind == "polars":
        if not isinstance(out, pl.Series):
            return f"expected a polars Series, got {type(out).__name__}"
        if shape != "flat" and out.name != given.name:
            return f"expected the name {given.name!r}, got {out.name!r}"
        return None if shape == "flat" or len(out) == len(given) else f"expected {len(given)} rows, got {len(out)}"
    if kind == "chunked":
        if not isinstance(out, pa.ChunkedArray):
            return f"expected a pyarrow ChunkedArray, got {type(out).__name__}"
        return None if shape == "flat" or len(out) == len(given) else f"expected {len(given)} rows, got {len(out)}"
    raise AssertionError(kind)


def _cases():
    for fname in ID_FUNCS:
        for kname in ID_KINDS:
            marks = []
            if kname == "numpy-StringDType" and not HAS_STRINGDTYPE:
                marks = [pytest.mark.skip(reason="numpy < 2 has no StringDType")]
            yield pytest.param(fname, kname, id=f"{fname}-{kname}", marks=marks)


@pytest.mark.parametrize("fname,kname", list(_cases()))
def test_ids_come_back_in_the_kind_given(fname, kname):
    fn, scalar_type, shape = ID_FUNCS[fname]
    make, kind = ID_KINDS[kname]
    given = make()
    out = fn(given)
    if kind == "scalar":
        if shape == "dict":
            assert isinstance(out, dict)
        else:
            assert _scalar_ok(out, scalar_type, given), f"{fname}({given!r}) gave {type(out).__name__}: {out!r:.100}"
        return
    problem = _same_kind(out, kind, given, shape)
    assert problem is None, f"{fname}({kname}): {problem}"


LATS, LNGS = [51.05, -89.0], [-114.07, 179.5]
COORD_KINDS = {
    "float": (lambda v: v[0], "scalar"),
    "list": (lambda v: list(v), "list"),
    "tuple": (lambda v: tuple(v), "list"),
    "numpy": (lambda v: np.array(v), "numpy"),
    "numpy-2d": (lambda v: np.array(v).reshape(1, 2), "numpy"),
    "pandas": (lambda v: pd.Series(v, index=INDEX, name="coord"), "pandas"),
    "pandas-index": (lambda v: pd.Index(v, name="coord"), "index"),
    "arrow-float64": (lambda v: pa.array(v, pa.float64()), "arrow"),
    "chunked-float64": (lambda v: pa.chunked_array([v[:1], v[1:]], pa.float64()), "chunked"),
    "polars-float64": (lambda v: pl.Series("coord", v), "polars"),
}
COORD_FUNCS = {
    "latlng_to_cell": (lambda a, b: dggs.latlng_to_cell(a, b, 9), str),
    "latlng_to_cell-as_int": (lambda a, b: dggs.latlng_to_cell(a, b, 9, as_int=True), int),
    "great_circle_distance": (lambda a, b: dggs.great_circle_distance(a, b, a, b), float),
}


@pytest.mark.parametrize("kname", list(COORD_KINDS))
@pytest.mark.parametrize("fname", list(COORD_FUNCS))
def test_coordinates_come_back_in_the_kind_given(fname, kname):
    fn, scalar_type = COORD_FUNCS[fname]
    make, kind = COORD_KINDS[kname]
    lat, lng = make(LATS), make(LNGS)
    out = fn(lat, lng)
    if kind == "scalar":
        assert type(out) is scalar_type, f"{fname}({lat!r}, {lng!r}) gave {type(out).__name__}"
        return
    problem = _same_kind(out, kind, lat, "aligned")
    assert problem is None, f"{fname}({kname}): {problem}"


# The element type comes back too where the container has one: the same dtype for numpy integers (byte order
# included) and the same pyarrow type for string-like arrays.
@pytest.mark.parametrize("dtype", ["<i8", ">i8", "<u8", ">u8"])
def test_numpy_integer_ids_keep_their_dtype(dtype):
    ids = np.array(INTS, dtype=dtype)
    assert dggs.cell_to_parent(ids).dtype == np.dtype(dtype)
    assert dggs.grid_disk(ids, 1).dtype == np.dtype(dtype)


@pytest.mark.parametrize("arrow_type", [pa.string(), pa.large_string(), pa.string_view(), pa.binary(), pa.large_binary()])
def test_arrow_string_ids_keep_their_type(arrow_type):
    ids = pa.array(CELLS).cast(arrow_type)
    assert dggs.cell_to_parent(ids).type == arrow_type
    assert dggs.compact_cells(ids).type == arrow_type


def test_dictionary_ids_come_back_dictionary_encoded():
    ids = pa.array(CELLS * 3).dictionary_encode()
    out = dggs.cell_to_parent(ids)
    assert pa.types.is_dictionary(out.type) and out.dictionary_decode().to_pylist() == [c[:-1] for c in CELLS * 3]


# Vertex ids, directed edge ids and end points of lines are fed in every container too (issue 32: the
# vertex verbs refused the list cell_to_vertexes gives, and geodesic_to_cells refused containers).
VERTEXES = dggs.cell_to_vertexes("C401")[:2]
EDGES = dggs.origin_to_directed_edges("C401")[:2]
EDGE_INTS = [dggs.str_to_int(e.replace(".", "")) | 1 << 63 for e in EDGES]
TEXT_KINDS = {
    "str": (lambda v: v[0], "scalar"),
    "list": (lambda v: list(v), "list"),
    "tuple": (lambda v: tuple(v), "list"),
    "numpy-U": (lambda v: np.array(v), "numpy"),
    "numpy-S": (lambda v: np.array(v, dtype="S"), "numpy"),
    "numpy-object": (lambda v: np.array(v, dtype=object), "numpy"),
    "pandas-object": (lambda v: _series(v, object), "pandas"),
    "pandas-string": (lambda v: _series(v, "string"), "pandas"),
    "pandas-index": (lambda v: pd.Index(v, name="v"), "index"),
    "arrow-string": (lambda v: pa.array(v, pa.string()), "arrow"),
    "chunked-string": (lambda v: pa.chunked_array([v[:1], v[1:]]), "chunked"),
    "polars-string": (lambda v: pl.Series("v", v), "polars"),
}
VERTEX_FUNCS = {
    "is_valid_vertex": (dggs.is_valid_vertex, bool, "aligned"),
    "vertex_to_latlng": (dggs.vertex_to_latlng, tuple, "pair"),
    "ivea_vertex_to_latlng": (dggs.Grid("IVEA").vertex_to_latlng, tuple, "pair"),
    "vertex_to_cells": (dggs.vertex_to_cells, list, "rows"),
}
EDGE_FUNCS = {
    "is_valid_directed_edge": (dggs.is_valid_directed_edge, bool, "aligned"),
    "get_directed_edge_origin": (dggs.get_directed_edge_origin, "id", "aligned"),
    "get_directed_edge_destination": (dggs.get_directed_edge_destination, "id", "aligned"),
    "reverse_directed_edge": (dggs.reverse_directed_edge, "id", "aligned"),
    "directed_edge_to_cells": (dggs.directed_edge_to_cells, list, "rows"),
    "edge_length": (dggs.edge_length, float, "aligned"),
}


def _text_cases(funcs):
    return [pytest.param(f, k, id=f"{f}-{k}") for f in funcs for k in TEXT_KINDS]


@pytest.mark.parametrize("fname,kname", _text_cases(VERTEX_FUNCS))
def test_vertex_ids_come_back_in_the_kind_given(fname, kname):
    fn, scalar_type, shape = VERTEX_FUNCS[fname]
    make, kind = TEXT_KINDS[kname]
    given = make(VERTEXES)
    out = fn(given)
    if kind == "scalar":
        assert _scalar_ok(out, scalar_type, given), f"{fname}({given!r}) gave {type(out).__name__}"
        return
    problem = _same_kind(out, kind, given, shape)
    assert problem is None, f"{fname}({kname}): {problem}"


@pytest.mark.parametrize("fname,kname", _text_cases(EDGE_FUNCS) + [pytest.param(f, "int", id=f"{f}-int") for f in EDGE_FUNCS])
def test_edge_ids_come_back_in_the_kind_given(fname, kname):
    fn, scalar_type, shape = EDGE_FUNCS[fname]
    if kname == "int":
        given, kind = EDGE_INTS[0], "scalar"
    else:
        make, kind = TEXT_KINDS[kname]
        given = make(EDGES)
    out = fn(given)
    if kind == "scalar":
        assert _scalar_ok(out, scalar_type, given), f"{fname}({given!r}) gave {type(out).__name__}"
        return
    problem = _same_kind(out, kind, given, shape)
    assert problem is None, f"{fname}({kname}): {problem}"


@pytest.mark.parametrize("kname", list(COORD_KINDS))
def test_line_end_points_come_back_in_the_kind_given(kname):
    """geodesic_to_cells: one array of cells per line, in the container the end points came in."""
    make, kind = COORD_KINDS[kname]
    lat, lng = make(LATS), make(LNGS)
    out = dggs.geodesic_to_cells(lat, lng, make([51.0, -88.9]), make([-114.0, 179.6]), 5)
    if kind == "scalar":
        assert type(out) is np.ndarray, f"geodesic_to_cells({lat!r}, ...) gave {type(out).__name__}"
        return
    problem = _same_kind(out, kind, lat, "aligned")
    assert problem is None, f"geodesic_to_cells({kname}): {problem}"
