"""GeoArrow output (geoarrow-pyarrow reading dggs's WKB) against shapely's own ragged arrays of the same polygons.

The oracle is ``shapely.to_ragged_array`` of ``dggs.cell_to_polygon``: shapely's encoding of the polygons,
not geoarrow-pyarrow's, so the two paths share nothing past the polygons themselves.
"""

from __future__ import annotations

import numpy as np
import pyarrow as pa
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.arrow import cells_to_geoarrow, geoarrow_field

from ..strategies import cells, examples, special_points

POINT = pa.struct([("x", pa.float64()), ("y", pa.float64())])

#: Cells at the poles, on the antimeridian, at the icosahedron's vertices and edge midpoints, levels 0-9.
SPECIAL = sorted({str(dggs.latlng_to_cell(lat, lng, level)) for lat, lng in special_points() for level in (0, 3, 9)})


def _reference(ids: list[str], densify: int) -> tuple[pa.DataType, np.ndarray, list[np.ndarray]]:
    """(arrow type, coords, offsets) that shapely's ragged arrays of the cells' polygons give."""
    polys = np.asarray(dggs.cell_to_polygon(np.array(ids), densify), dtype=object).reshape(-1)
    kind, coords, offsets = shapely.to_ragged_array(polys)
    typ = pa.list_(pa.list_(POINT))
    return (pa.list_(typ) if kind == shapely.GeometryType.MULTIPOLYGON else typ), coords, list(offsets)


def _decoded(arr: pa.Array) -> tuple[np.ndarray, list[np.ndarray]]:
    """Coordinates and offsets (innermost first, as shapely gives them) of a nested list array."""
    offsets = []
    while pa.types.is_list(arr.type):
        offsets.append(arr.offsets.to_numpy())
        arr = arr.flatten()
    return np.column_stack([arr.field("x").to_numpy(), arr.field("y").to_numpy()]), offsets[::-1]


def _check(ids: list[str], densify: int) -> None:
    typ, coords, offsets = _reference(ids, densify)
    for given_ids in (ids, [int(dggs.str_to_int(i)) for i in ids], pa.array(ids)):
        arr = cells_to_geoarrow(given_ids, densify, encoding="geoarrow")
        assert arr.type == typ and arr.null_count == 0 and len(arr) == len(ids)
        got_coords, got_offsets = _decoded(arr)
        np.testing.assert_array_equal(got_coords, coords)  # bit for bit
        assert len(got_offsets) == len(offsets)
        for got, ref in zip(got_offsets, offsets, strict=True):
            np.testing.assert_array_equal(got, ref)


@settings(max_examples=examples(60), deadline=None)
@given(st.lists(cells(max_level=12), min_size=1, max_size=12), st.sampled_from([0, 1, 4]))
@example(["A"], 0)
@example(["C401", "C402"], 2)
def test_geoarrow_is_shapelys_ragged_arrays(ids, densify):
    _check(ids, densify)


@pytest.mark.parametrize("densify", [0, 3, 16])
def test_poles_antimeridian_vertices_and_edges(densify):
    assert any(dggs.cell_to_polygon(c, densify).geom_type == "MultiPolygon" for c in SPECIAL)
    _check(SPECIAL, densify)
    plain = [c for c in SPECIAL if dggs.cell_to_polygon(c, densify).geom_type == "Polygon"]
    _check(plain, densify)  # only Polygons: geoarrow.polygon, one list level less


def test_the_field_names_the_extension_the_array_holds():
    split = next(c for c in SPECIAL if dggs.cell_to_polygon(c, 0).geom_type == "MultiPolygon")
    assert geoarrow_field("g", "geoarrow", [split], 0).metadata[b"ARROW:extension:name"] == b"geoarrow.multipolygon"
    assert geoarrow_field("g", "geoarrow", ["C401"], 0).metadata[b"ARROW:extension:name"] == b"geoarrow.polygon"
    empty = cells_to_geoarrow([], encoding="geoarrow")
    assert len(empty) == 0 and empty.type == pa.list_(pa.list_(POINT))
