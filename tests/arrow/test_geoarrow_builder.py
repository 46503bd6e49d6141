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


def test_pyarrow_is_left_without_geoarrow_extension_types(tmp_path):
    # geoarrow-pyarrow registers extension types for the whole process on import; dggs must not do that
    # behind its caller's back: a field tagged geoarrow.* still comes back from pyarrow as plain storage.
    import subprocess
    import sys

    code = (
        "import sys, pyarrow as pa\n"
        "from dggs.arrow import cells_to_geoarrow, geoarrow_field\n"
        "arr = cells_to_geoarrow(['C401', 'A'], 2, encoding='geoarrow')\n"
        "field = geoarrow_field('g', 'geoarrow', ['C401', 'A'], 2)\n"
        "batch = pa.RecordBatch.from_arrays([arr], schema=pa.schema([field]))\n"
        "back = pa.RecordBatch._import_from_c_capsule(*batch.__arrow_c_array__())\n"
        "assert 'geoarrow.pyarrow' not in sys.modules\n"
        "assert not isinstance(back.schema.field('g').type, pa.ExtensionType), back.schema\n"
    )
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr


@pytest.mark.parametrize("densify", [0, 4, None])
def test_xdggs_geoarrow_is_shapelys_ragged_arrays_interleaved(densify):
    pytest.importorskip("xdggs")
    from dggs.xdggs import Split26Info

    for level in (0, 3, 9):
        ids = np.array(sorted({c for c in SPECIAL if dggs.get_level(c) == level}))
        arr = pa.array(Split26Info(level=level).cell_boundaries(ids, backend="geoarrow", densify=densify))
        polys = np.asarray(dggs.cell_to_polygon(ids, 16 if densify is None else densify), dtype=object)
        kind, coords, offsets = shapely.to_ragged_array(polys)
        got = []
        while pa.types.is_list(arr.type):
            got.append(arr.offsets.to_numpy())
            arr = arr.flatten()
        assert pa.types.is_fixed_size_list(arr.type) and arr.type.list_size == 2
        np.testing.assert_array_equal(arr.flatten().to_numpy().reshape(-1, 2), coords)
        assert len(got) == len(offsets) == (3 if kind == shapely.GeometryType.MULTIPOLYGON else 2)
        for g, ref in zip(got[::-1], offsets, strict=True):
            np.testing.assert_array_equal(g, ref)


def test_xdggs_geoarrow_of_no_cells_is_an_empty_polygon_array():
    pytest.importorskip("xdggs")
    from dggs.xdggs import Split26Info

    arr = Split26Info(level=3).cell_boundaries(np.array([], dtype=np.uint64), backend="geoarrow")
    assert len(arr) == 0 and arr.field.metadata[b"ARROW:extension:name"] == b"geoarrow.polygon"


def test_large_binary_wkb_gives_the_same_arrays():
    # past 2 GiB the WKB column is large_binary; geoarrow-c reads it alike
    from dggs.index._shapes import wkb_to_geoarrow

    blobs = cells_to_geoarrow(SPECIAL, 2)
    assert wkb_to_geoarrow(blobs.cast(pa.large_binary()), True).equals(wkb_to_geoarrow(blobs, True))
    assert wkb_to_geoarrow(blobs, True, interleaved=True, name="").type == pa.list_(
        pa.field("", pa.list_(pa.field("", pa.list_(pa.field("", pa.list_(pa.field("item", pa.float64(), nullable=False), 2))))))
    )
