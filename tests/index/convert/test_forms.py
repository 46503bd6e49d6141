"""String and integer ids give the same answers from every public function, in every container.

The integer results are turned back into strings with ``int_to_str`` and
compared with the string results; the string results themselves are
checked against geometry and oracles in the other test files.  Pinned at the
poles, the antimeridian and the icosahedron vertices.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pyarrow as pa
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from shapely.geometry import box

import dggs
from dggs.errors import TooManyCellsError

from ...strategies import cells, examples, latlngs, special_points

SPECIAL_CELLS = [dggs.latlng_to_cell(lat, lng, lv) for lat, lng in special_points()[:20] for lv in (0, 1, 9, 28)]


def both(cell):
    return cell, dggs.str_to_int(cell)


@given(cells())
@example("A")
@example("T5" + "2" * 27)
@example(SPECIAL_CELLS[0])
@example(SPECIAL_CELLS[-1])
def test_every_single_id_function_agrees_across_forms(cell):
    s, i = both(cell)
    assert isinstance(i, int) and dggs.int_to_str(i) == s
    assert dggs.get_level(s) == dggs.get_level(i) == len(s) - 1
    assert dggs.get_face(s) == dggs.get_face(i)
    assert dggs.is_valid_cell(s) and dggs.is_valid_cell(i)
    assert dggs.cell_to_latlng(s) == dggs.cell_to_latlng(i)
    assert dggs.cell_to_boundary(s) == dggs.cell_to_boundary(i)
    assert dggs.cell_area(s) == dggs.cell_area(i)
    assert dggs.int_to_str(dggs.edge_neighbors(i)) == dggs.edge_neighbors(s)
    assert dggs.int_to_str(dggs.grid_disk(i, 2)) == dggs.grid_disk(s, 2)
    assert dggs.int_to_str(dggs.grid_ring(i, 2)) == dggs.grid_ring(s, 2)
    if len(s) > 1:
        assert dggs.int_to_str(dggs.cell_to_parent(i)) == dggs.cell_to_parent(s) == s[:-1]
        assert dggs.int_to_str(dggs.cell_to_parent(i, 0)) == s[0]
    if len(s) <= dggs.MAX_LEVEL:
        assert dggs.int_to_str(dggs.cell_to_children(i)) == dggs.cell_to_children(s)
        assert dggs.int_to_str(dggs.cell_to_center_child(i)) == dggs.cell_to_center_child(s)
    lat, lng = dggs.cell_to_latlng(s)
    level = len(s) - 1
    assert dggs.int_to_str(dggs.latlng_to_cell(lat, lng, level, as_int=True)) == dggs.latlng_to_cell(lat, lng, level) == s
    n = dggs.edge_neighbors(s)[0]
    assert dggs.grid_distance(s, n) == dggs.grid_distance(i, dggs.str_to_int(n)) == 1
    assert dggs.are_neighbor_cells(s, n) and dggs.are_neighbor_cells(i, dggs.str_to_int(n))


@settings(max_examples=examples(30))
@given(st.lists(latlngs(), min_size=1, max_size=40), st.integers(0, dggs.MAX_LEVEL))
def test_points_agree_across_forms_and_keep_shape(points, level):
    lat = np.array([p[0] for p in points])
    lng = np.array([p[1] for p in points])
    s = dggs.latlng_to_cell(lat, lng, level)
    i = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    assert i.dtype == np.uint64 and s.dtype.kind == "U"
    assert np.array_equal(dggs.int_to_str(i), s)
    assert all(dggs.latlng_to_cell(a, b, level) == c for a, b, c in zip(lat, lng, s, strict=True))
    if len(points) % 2 == 0:  # a 2-D input gives a 2-D output
        grid = dggs.latlng_to_cell(lat.reshape(2, -1), lng.reshape(2, -1), level, as_int=True)
        assert grid.shape == (2, len(points) // 2) and np.array_equal(grid.ravel(), i)


@settings(max_examples=examples(30))
@given(st.lists(cells(max_level=12), min_size=1, max_size=30))
def test_array_functions_agree_across_forms(cell_list):
    s = np.array(cell_list)
    i = dggs.str_to_int(s)
    assert i.dtype == np.uint64
    for fn in (dggs.edge_neighbors, dggs.cell_to_center_child, lambda c: dggs.grid_disk(c, 2), dggs.compact_cells):
        assert np.array_equal(dggs.int_to_str(fn(i)), fn(s))
    lv = dggs.get_level(s)
    assert np.array_equal(lv, dggs.get_level(i))
    assert np.array_equal(np.asarray(dggs.cell_to_latlng(s)), np.asarray(dggs.cell_to_latlng(i)))
    assert np.array_equal(dggs.cell_to_boundary(s, 2), dggs.cell_to_boundary(i, 2))
    assert np.array_equal(dggs.int_to_str(dggs.uncompact_cells(i, 13)), dggs.uncompact_cells(s, 13))
    assert np.array_equal(dggs.int_to_str(dggs.cell_to_children(i, 13)), dggs.cell_to_children(s, 13))
    polys_s, polys_i = dggs.cell_to_polygon(s, densify=4), dggs.cell_to_polygon(i, densify=4)
    assert all(a.equals_exact(b, 0.0) for a, b in zip(polys_s, polys_i, strict=True))


def test_polygon_fill_agrees_across_forms():
    poly = box(170, -10, 190, 10)  # across the antimeridian
    s = dggs.polygon_to_cells(poly, 6)
    i = dggs.polygon_to_cells(poly, 6, as_int=True)
    assert i.dtype == np.uint64 and np.array_equal(dggs.int_to_str(i), s)
    assert np.all(np.diff(i.astype(np.float64)) > 0)  # sorted, unique


CONTAINERS = [
    ("list", lambda v: list(v), list),
    ("tuple", lambda v: tuple(v), list),
    ("numpy U", lambda v: np.array(v), np.ndarray),
    ("numpy S", lambda v: np.array(v, dtype="S"), np.ndarray),
    ("numpy object", lambda v: np.array(v, dtype=object), np.ndarray),
    ("numpy StringDType", lambda v: np.array(v, dtype=np.dtypes.StringDType()), np.ndarray),
    ("pandas", lambda v: pd.Series(v, index=list(range(10, 10 + len(v)))), pd.Series),
    ("arrow", lambda v: pa.array(v), pa.Array),
    ("arrow chunked", lambda v: pa.chunked_array([v[:1], v[1:]]), pa.ChunkedArray),
]


# bytes and StringDType arrays hold strings only
CASES = [(c, form) for c in CONTAINERS for form in ("str", "int") if form == "str" or c[0] not in ("numpy S", "numpy StringDType")]


@pytest.mark.parametrize("container,form", CASES, ids=[f"{c[0]}-{f}" for c, f in CASES])
def test_containers_come_back_as_they_went_in(container, form):
    name, make, kind = container
    ref = ["C401", "A", "T5" + "2" * 27, SPECIAL_CELLS[5]]
    values = ref if form == "str" else [dggs.str_to_int(c) for c in ref]
    given_ = make(values)
    parents = dggs.cell_to_parent(given_, 0)
    assert isinstance(parents, kind)
    got = [v.decode() if isinstance(v, bytes) else v for v in _as_list(parents)]
    expected = [c[0] for c in ref] if form == "str" else [dggs.str_to_int(c[0]) for c in ref]
    assert got == expected
    if name == "pandas":
        assert parents.index.tolist() == given_.index.tolist()
    nb = dggs.edge_neighbors(given_)
    assert len(_as_list(nb)) == len(ref)


def _as_list(obj):
    if isinstance(obj, (pa.Array, pa.ChunkedArray)):
        return obj.to_pylist()
    if isinstance(obj, pd.Series):
        return obj.tolist()
    return [x.item() if isinstance(x, np.generic) else x for x in (obj.tolist() if isinstance(obj, np.ndarray) else obj)]


def test_int64_in_gives_int64_out():
    ids = dggs.str_to_int(np.array(["C401", "C402"])).astype(np.int64)
    out = dggs.cell_to_parent(ids)
    assert out.dtype == np.int64 and dggs.int_to_str(out).tolist() == ["C40", "C40"]


def test_several_cells_per_id_gives_a_list_for_one_id():
    assert dggs.cell_to_children("C401") == ["C4010", "C4011", "C4012"]
    assert dggs.grid_disk(dggs.str_to_int("C401"), 1) == dggs.str_to_int(["C400", "C401", "C402", "C411"])


def test_explosive_outputs_are_refused_before_allocation():
    with pytest.raises(TooManyCellsError, match=r"387,420,489 cells, over the limit of 50,000,000"):
        dggs.cell_to_children("C401", 21)  # 3**18
    with pytest.raises(TooManyCellsError, match="over the limit of 10"):
        dggs.uncompact_cells(["C4"], 5, max_cells=10)
    with pytest.raises(TooManyCellsError, match="with k=1000 would return 100 rows"):
        dggs.grid_disk(np.array(["C4010000000000"] * 100), 1000)  # level 14: no disk covers the level
    with pytest.raises(TooManyCellsError, match="grid_ring"):
        dggs.grid_ring(np.array(["C401"] * 10), 5000, max_cells=1000)
    with pytest.raises(TooManyCellsError, match="polygon_to_cells"):
        dggs.polygon_to_cells(box(-10, -10, 10, 10), 12, max_cells=1000)
    assert len(dggs.cell_to_children("C401", 6, max_cells=27)) == 27
