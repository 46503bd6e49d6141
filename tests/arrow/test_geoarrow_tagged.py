"""Issue 36: ``dggs.arrow.cells_to_table`` is tagged as GeoArrow, so generic Arrow consumers find its geometry.

Referees: geopandas' ``GeoDataFrame.from_arrow`` (which reads the ``geoarrow.wkb`` extension metadata),
DuckDB's Arrow scan (which maps the tag to its GEOMETRY type), lonboard's ``viz``, and pyproj for the CRS.
Each is also fed the table through nothing but the Arrow PyCapsule stream (``__arrow_c_stream__``).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import shapely

import dggs
from dggs.arrow import cells_to_table, geoarrow_field

pa = pytest.importorskip("pyarrow")

# the pole cells and those split at the antimeridian included
CELLS = np.asarray(dggs.uncompact_cells(["A0", "O3", "T5"], 3))


class _StreamOnly:
    """An object that gives its table only as an Arrow C stream, as a non-pyarrow producer would."""

    def __init__(self, table):
        self._table = table

    def __arrow_c_stream__(self, requested_schema=None):
        return self._table.__arrow_c_stream__(requested_schema)


@pytest.fixture(scope="module")
def table():
    return cells_to_table(CELLS, {"n": np.arange(CELLS.size)}, densify=4)


def test_the_geometry_field_says_geoarrow_wkb_with_crs84_as_projjson(table):
    pyproj = pytest.importorskip("pyproj")
    for field in (table.schema.field("geometry"), geoarrow_field()):
        assert field.metadata[b"ARROW:extension:name"] == b"geoarrow.wkb"
        meta = json.loads(field.metadata[b"ARROW:extension:metadata"])
        assert meta["crs_type"] == "projjson" and isinstance(meta["crs"], dict)  # GeoArrow: PROJJSON as an object
        assert pyproj.CRS.from_json_dict(meta["crs"]) == pyproj.CRS.from_user_input("OGC:CRS84")


@pytest.mark.parametrize("wrap", [False, True], ids=["table", "capsule"])
def test_geopandas_from_arrow_finds_the_geometry(table, wrap):
    geopandas = pytest.importorskip("geopandas")
    frame = geopandas.GeoDataFrame.from_arrow(_StreamOnly(table) if wrap else table)
    assert frame.geometry.name == "geometry" and frame.crs.to_string() == "OGC:CRS84"
    assert frame["cell"].tolist() == CELLS.tolist() and frame["n"].tolist() == list(range(CELLS.size))
    assert shapely.equals_exact(frame.geometry.values, dggs.cell_to_polygon(CELLS, 4), 0).all()


@pytest.mark.parametrize("wrap", [False, True], ids=["table", "capsule"])
def test_duckdb_reads_a_geometry_not_a_blob(table, wrap):
    duckdb = pytest.importorskip("duckdb")
    source = _StreamOnly(table) if wrap else table  # noqa: F841 (DuckDB scans the Python variable by name)
    rel = duckdb.sql("SELECT cell, geometry FROM source")
    assert str(rel.types[1]) == "GEOMETRY('OGC:CRS84')"
    rows = duckdb.sql("SELECT cell, ST_AsWKB(geometry) FROM source").fetchall()
    assert [r[0] for r in rows] == CELLS.tolist()
    assert shapely.equals_exact(shapely.from_wkb([bytes(r[1]) for r in rows]), dggs.cell_to_polygon(CELLS, 4), 0).all()


def test_lonboard_draws_it_directly(table):
    lonboard = pytest.importorskip("lonboard")
    layer = lonboard.viz(table).layers[0]
    assert type(layer).__name__ == "PolygonLayer" and len(layer.table) == CELLS.size


class _ArrayOnly:
    """An Arrow producer that is not pyarrow: only ``__arrow_c_array__``."""

    def __init__(self, arr):
        self._arr = arr

    def __arrow_c_array__(self, requested_schema=None):
        return self._arr.__arrow_c_array__(requested_schema)


@pytest.mark.parametrize("wrap", [_ArrayOnly, _StreamOnly], ids=["array-capsule", "stream-capsule"])
@pytest.mark.parametrize("ids", [["C401", "O311", "A0"], [int(i) for i in dggs.str_to_int(["C401", "O311", "A0"])]],
                         ids=["str", "int"])
def test_any_arrow_producer_goes_in_and_pyarrow_comes_out(wrap, ids):
    source = pa.array(ids, type=pa.uint64() if isinstance(ids[0], int) else pa.string())
    given = wrap(source if wrap is _ArrayOnly else pa.chunked_array([source]))
    parents = dggs.cell_to_parent(given)
    assert isinstance(parents, (pa.Array, pa.ChunkedArray))
    assert parents.to_pylist() == [dggs.cell_to_parent(c) for c in ids]  # each id alone, the referee
    table = cells_to_table(given, densify=0)
    assert table.column("cell").to_pylist() == ["C401", "O311", "A0"]
