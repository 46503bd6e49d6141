"""Every GeoParquet file dggs writes meets every MUST of GeoParquet 1.1.0, and readers filter it right.

The referee is :mod:`tests.storage.geoparquet_rules` (written from the specification's text, reading
the file with DuckDB, pyarrow and shapely).  The expected bounds come from every point of the cells'
polygons (``dggs.cell_to_polygon``), the smallest arc of longitude holding them found by brute force here;
the expected filter answers from those bounds and from geopandas' and DuckDB's readers.
"""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.arrow import cells_to_table, to_geodataframe, write_cells, write_geoparquet
from dggs.arrow.geoparquet import bbox_filter, bbox_sql, covering_bounds, lng_extent, split_box

from ..strategies import examples
from .geoparquet_rules import violations

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
geopandas = pytest.importorskip("geopandas")
duckdb = pytest.importorskip("duckdb")

LEVEL = 3
DENSIFY = 4
CELLS = np.asarray(dggs.uncompact_cells(dggs.get_base_cells(), LEVEL))  # 1,080 cells, 48 split at +-180
BOXES = [(-5.0, -5.0, 5.0, 5.0), (175.0, -5.0, 179.0, 5.0), (-179.0, 20.0, -175.0, 40.0), (170.0, 50.0, -170.0, 70.0),
         (0.0, 80.0, 30.0, 90.0), (100.0, -90.0, 180.0, -80.0), (-60.0, -30.0, -50.0, -20.0)]


def _points(n: int = 4000) -> tuple[np.ndarray, np.ndarray]:
    """Points over the sphere, a fifth of them within 3 degrees of the antimeridian."""
    rng = np.random.default_rng(7)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    lng[: n // 5] = np.where(rng.random(n // 5) < 0.5, 1, -1) * rng.uniform(177, 180, n // 5)
    return lat, lng


def _arrow(tmp_path):
    path = tmp_path / "arrow.parquet"
    write_geoparquet(cells_to_table(CELLS, {"n": np.arange(CELLS.size)}, densify=DENSIFY), path)
    other = tmp_path / "cells.parquet"
    write_cells(cells_to_table(CELLS[::3], densify=DENSIFY), other)
    return [path, other]


def _store(tmp_path):
    lat, lng = _points()
    path = tmp_path / "store.parquet"
    with dggs.storage.CellStore() as store:
        store.ingest_points(lat, lng, 6, {"v": np.arange(lat.size, dtype=float)})
        store.export(path, LEVEL, "v", densify=DENSIFY)
    return [path]


def _cli(tmp_path):
    from click.testing import CliRunner

    from dggs.cli import main

    lat, lng = _points()
    db = tmp_path / "cli.db"
    with dggs.storage.CellStore(db) as store:
        store.ingest_points(lat, lng, 6)
    out = tmp_path / "cli.parquet"
    result = CliRunner().invoke(main, ["export", str(db), "--level", str(LEVEL), "-o", str(out), "--densify", str(DENSIFY)])
    assert result.exit_code == 0, result.output
    return [out]


def _dask(tmp_path):
    dd = pytest.importorskip("dask.dataframe")
    import pandas as pd

    from dggs.dask import add_cells, aggregate, to_parquet

    lat, lng = _points()
    ddf = add_cells(dd.from_pandas(pd.DataFrame({"lat": lat, "lng": lng, "v": 1.0}), npartitions=2), level=6)
    to_parquet(aggregate(ddf, LEVEL, "v", stats=("count", "sum")), str(tmp_path / "dask"), densify=DENSIFY)
    return sorted((tmp_path / "dask").glob("face=*/*.parquet"))


def _raster(tmp_path):
    import pandas as pd

    from dggs.raster.parquet import write_partitioned

    ids = np.asarray(dggs.str_to_int(CELLS))
    write_partitioned(pd.DataFrame({"cell_id": ids, "value": np.arange(ids.size, dtype=float)}), tmp_path / "raster",
                      densify=DENSIFY)
    return sorted((tmp_path / "raster").glob("parent=*/*.parquet"))


WRITERS = {"arrow": _arrow, "store": _store, "cli": _cli, "dask": _dask, "raster": _raster}


@pytest.fixture(scope="module", params=sorted(WRITERS))
def files(request, tmp_path_factory):
    paths = WRITERS[request.param](tmp_path_factory.mktemp(request.param))
    assert paths
    return paths


def _arc(lng: np.ndarray) -> tuple[float, float]:
    """The smallest arc of longitude holding every point, by brute force: leave out the widest gap."""
    x = np.sort(lng)
    gaps = np.append(np.diff(x), x[0] + 360.0 - x[-1])
    k = int(np.argmax(gaps))
    return (float(x[0]), float(x[-1])) if k == x.size - 1 else (float(x[k + 1]), float(x[k]))


def _brute_bounds(cells: np.ndarray, widen: bool = False) -> np.ndarray:
    """(N, 4) bounds of the cells' polygons from all their points (RFC 7946 §5: xmin > xmax across +-180).

    ``widen``: as the files have them, an arc across +-180 as every longitude, -180..180.
    """
    xy, row = shapely.get_coordinates(dggs.cell_to_polygon(cells, DENSIFY), return_index=True)
    out = np.empty((cells.size, 4))
    for i in range(cells.size):
        lng, lat = xy[row == i].T
        out[i, 0], out[i, 2] = _arc(lng)
        out[i, 1], out[i, 3] = lat.min(), lat.max()
        if widen and out[i, 0] > out[i, 2]:
            out[i, 0], out[i, 2] = -180.0, 180.0
    return out


def _meets(bounds: np.ndarray, box: tuple, pad: float) -> np.ndarray:
    """Rows whose bounds (xmin > xmax wraps) meet ``box`` grown by ``pad`` (negative: shrunk)."""
    x0, y0, x1, y1 = box

    def arcs(lo, hi):  # [lo, hi] on the circle as up to two plain ranges
        return [(lo, hi)] if lo <= hi else [(lo, 180.0), (-180.0, hi)]

    hit = np.zeros(bounds.shape[0], dtype=bool)
    for i, (a, b, c, d) in enumerate(bounds):
        lng = any(p <= s + pad and q >= r - pad for p, q in arcs(a, c) for r, s in arcs(x0, x1))
        hit[i] = lng and b <= y1 + pad and d >= y0 - pad
    return hit


def test_every_file_meets_every_must(files):
    for path in files:
        assert violations(path) == [], path
        schema = str(pq.ParquetFile(path).schema)
        assert "required group field_id=-1 bbox" in schema and "required binary field_id=-1 geometry" in schema


def test_geopandas_and_duckdb_read_every_file(files):
    con = duckdb.connect()
    for path in files:
        frame = geopandas.read_parquet(path)
        rows = con.execute("SELECT cell, bbox.xmin, bbox.ymin, bbox.xmax, bbox.ymax, geometry::BLOB FROM read_parquet(?)"
                           " ORDER BY cell_id", [str(path)]).fetchall()
        assert frame.crs.to_string() == "OGC:CRS84" and len(frame) == len(rows) > 0
        table = pq.read_table(path).sort_by("cell_id")
        assert [r[0] for r in rows] == table.column("cell").to_pylist()
        assert [bytes(r[5]) for r in rows] == table.column("geometry").to_pylist()  # DuckDB sees the same WKB
        cells = np.asarray(table.column("cell").to_pylist())
        got = np.array([r[1:5] for r in rows])
        want = _brute_bounds(cells, widen=True)  # bounds from the boundary points, not from the file
        np.testing.assert_allclose(got, want, atol=1e-7)
        assert (got[:, 0] <= got[:, 2]).all()  # every row a plain box: readers comparing fields lose none


def test_bbox_filters_return_no_far_away_cell(files):
    con = duckdb.connect()
    for path in files:
        cells = np.asarray(pq.read_table(path, columns=["cell"]).column("cell").to_pylist())
        bounds = _brute_bounds(cells, widen=True)
        for box in BOXES:
            outer, inner = set(cells[_meets(bounds, box, 1e-6)]), set(cells[_meets(bounds, box, -1e-6)])
            ours = set(geopandas.read_parquet(path, filters=bbox_filter(box))["cell"])
            assert inner <= ours <= outer, (path, box)
            sql = f"SELECT cell FROM read_parquet('{path}') WHERE {bbox_sql(box)}"
            assert {r[0] for r in con.execute(sql).fetchall()} == ours, (path, box)
            if box[0] <= box[2]:  # geopandas' own filter compares the fields as they are: the same rows
                assert set(geopandas.read_parquet(path, bbox=box)["cell"]) == ours, (path, box)


def _naive_reads(path, box, con) -> dict[str, set]:
    """The rows of ``path`` three generic readers give for a plain ``box``, each comparing the bbox fields as they are.

    geopandas' ``read_parquet(bbox=...)``; a pyarrow dataset filter and a DuckDB ``WHERE`` as GeoParquet 1.1's
    §"Bounding Box Columns" writes its example (``bbox.xmin <= box_xmax AND bbox.xmax >= box_xmin AND ...``).
    """
    import pyarrow.compute as pc
    import pyarrow.dataset as ds

    x0, y0, x1, y1 = box
    f = {k: pc.field(("bbox", k)) for k in ("xmin", "ymin", "xmax", "ymax")}
    expr = (f["xmin"] <= x1) & (f["xmax"] >= x0) & (f["ymin"] <= y1) & (f["ymax"] >= y0)
    sql = (f"SELECT cell FROM read_parquet('{path}') WHERE bbox.xmin <= {x1} AND bbox.xmax >= {x0} "
           f"AND bbox.ymin <= {y1} AND bbox.ymax >= {y0}")
    return {"geopandas": set(geopandas.read_parquet(path, bbox=box)["cell"]),
            "pyarrow": set(ds.dataset(str(path)).to_table(columns=["cell"], filter=expr).column("cell").to_pylist()),
            "duckdb": {r[0] for r in con.execute(sql).fetchall()}}


#: Query boxes at the antimeridian (the last two across it, read as split_box's two sides) and one far from it.
AM_BOXES = [(170.0, -20.0, 180.0, 20.0), (-180.0, -20.0, -170.0, 20.0), (175.0, 50.0, 179.0, 70.0),
            (-179.5, -70.0, -178.0, -40.0), (-5.0, -5.0, 5.0, 5.0), (170.0, -20.0, -170.0, 20.0), (160.0, 60.0, -160.0, 89.0)]


def test_generic_readers_lose_no_cell_at_the_antimeridian(files):
    """Issue 36: geopandas' ``read_parquet(bbox=(170, -20, -170, 20))`` returned none of the cells there.

    The truth is brute force on the cells' own polygons (shapely), a box across +-180 as its two sides; every
    reader must return all of it, and nothing whose polygon's bounds are far from the box other than a split
    cell at the box's latitudes (a widened row)."""
    con = duckdb.connect()
    for path in files:
        cells = np.asarray(pq.read_table(path, columns=["cell"]).column("cell").to_pylist())
        polys = dggs.cell_to_polygon(cells, DENSIFY)
        split = shapely.get_type_id(polys) == 6
        lat = shapely.bounds(polys)[:, [1, 3]]
        for box in AM_BOXES:
            sides = split_box(box)
            truth = set(cells[np.any([shapely.intersects(polys, shapely.box(*side)) for side in sides], axis=0)])
            near = np.any([_meets(_brute_bounds(cells), side, 1e-6) for side in sides], axis=0)
            wide = split & (lat[:, 0] <= box[3] + 1e-9) & (lat[:, 1] >= box[1] - 1e-9)
            reads = [_naive_reads(path, side, con) for side in sides]
            for reader in ("geopandas", "pyarrow", "duckdb"):
                got = set().union(*(read[reader] for read in reads))
                assert truth <= got, (path, box, reader, sorted(truth - got)[:5])
                assert got <= set(cells[near | wide]), (path, box, reader)


def test_geopandas_box_at_the_origin_returns_cells_near_it():
    table = cells_to_table(CELLS, densify=DENSIFY)
    frame = to_geodataframe(table)
    bounds = np.column_stack([table.column("bbox").combine_chunks().field(k).to_numpy() for k in ("xmin", "ymin", "xmax", "ymax")])
    near = frame.geometry.intersects(shapely.box(-5, -5, 5, 5)).to_numpy()
    hit = _meets(bounds, (-5, -5, 5, 5), 0.0)
    assert near.sum() > 0 and (near <= hit).all()
    split = shapely.get_type_id(frame.geometry.values) == 6  # widened rows: -180..180 at their latitudes
    assert shapely.distance(frame.geometry.values[hit & ~split], shapely.box(-5, -5, 5, 5)).max() < 15.0  # ~10 deg cells
    assert 0 < (hit & split).sum() < split.sum()


def test_split_cells_wrap_and_pole_cells_hold_their_sector():
    table = cells_to_table(CELLS, densify=DENSIFY)
    box = table.column("bbox").combine_chunks()
    x0, x1 = box.field("xmin").to_numpy(), box.field("xmax").to_numpy()
    geoms = shapely.from_wkb(table.column("geometry").to_numpy(zero_copy_only=False))
    split = shapely.get_type_id(geoms) == 6
    assert split.sum() == 48 and (x0[split] == -180.0).all() and (x1[split] == 180.0).all()
    assert (x0[~split] <= x1[~split]).all()
    at_pole = (box.field("ymax").to_numpy() == 90.0) | (box.field("ymin").to_numpy() == -90.0)
    xy, row = shapely.get_coordinates(dggs.cell_to_polygon(CELLS, DENSIFY), return_index=True)
    touching = np.isin(np.arange(CELLS.size), row[np.abs(xy[:, 1]) == 90.0])
    assert at_pole.sum() > 0 and np.array_equal(at_pole, touching)  # cells with a corner at a pole: a sector each
    assert not ((x0 == -180.0) & (x1 == 180.0) & ~split).any()
    geo = json.loads(table.schema.metadata[b"geo"])["columns"]["geometry"]
    assert geo["bbox"] == [-180.0, -90.0, 180.0, 90.0]  # all cells: every longitude


def test_a_cell_round_a_pole_spans_every_longitude():
    """RFC 7946 §5.3: the bbox of a cap round the North Pole is [-180, minlat, 180, 90]."""
    lng = np.linspace(-180.0, 180.0, 13)  # a cell round the pole, closed over it as dggs closes one
    cap = shapely.Polygon(np.column_stack([np.append(lng, [180.0, -180.0]), np.append(np.full(13, 80.0), [90.0, 90.0])]))
    assert cap.is_valid and cap.exterior.is_ccw
    blob = pa.array([shapely.to_wkb(cap)], type=pa.binary())
    np.testing.assert_allclose(covering_bounds(blob, shapely.bounds(np.array([cap]))), [[-180.0, 80.0, 180.0, 90.0]])
    # a cap off the antimeridian and one across it are narrower
    assert lng_extent(np.array([-10.0]), np.array([10.0])) == (-10.0, 10.0)
    assert lng_extent(np.array([170.0, -180.0, 175.0]), np.array([180.0, -160.0, 178.0])) == (170.0, -160.0)
    assert lng_extent(np.array([170.0, -20.0]), np.array([-170.0, 20.0])) == (-20.0, -170.0)


def test_the_file_bbox_wraps_when_its_cells_do(tmp_path):
    cells = np.asarray(dggs.uncompact_cells(["O31"], 5))  # cells on both sides of +-180
    path = tmp_path / "fiji.parquet"
    write_geoparquet(cells_to_table(cells, densify=DENSIFY), path)
    geo = json.loads(pq.read_schema(path).metadata[b"geo"])["columns"]["geometry"]
    x0, _, x1, _ = geo["bbox"]
    assert 160.0 < x0 < 180.0 and -180.0 < x1 < -160.0
    assert violations(path) == []


def _rewrite(table, path, schema=None, geo=None):
    meta = dict(table.schema.metadata)
    if geo is not None:
        meta[b"geo"] = json.dumps(geo).encode()
    pq.write_table(table.cast(schema or table.schema).replace_schema_metadata(meta), path)
    return violations(path)


def test_the_referee_catches_each_broken_rule(tmp_path):
    table = cells_to_table(CELLS[:200], densify=DENSIFY)
    geo = json.loads(table.schema.metadata[b"geo"])
    path = tmp_path / "bad.parquet"
    # the layout dggs wrote before: an optional bbox group beside a required geometry
    fields = [f.with_nullable(True) if f.name == "bbox" else f for f in table.schema]
    assert any("repetition of 'bbox'" in v for v in _rewrite(table, path, pa.schema(fields, table.schema.metadata)))
    wrong = json.loads(json.dumps(geo))
    wrong["columns"]["geometry"]["geometry_types"] = ["MultiPolygon"]  # the first 200 cells are Polygons
    assert any("§geometry_types" in v for v in _rewrite(table, path, geo=wrong))
    wrong = json.loads(json.dumps(geo))
    wrong["columns"]["geometry"]["covering"]["bbox"]["xmin"] = ["box", "xmin"]
    assert any("same column name" in v for v in _rewrite(table, path, geo=wrong))
    wrong = json.loads(json.dumps(geo))
    wrong["columns"]["geometry"]["covering"]["bbox"]["ymin"] = ["bbox", "xmin"]
    assert any("(schema)" in v for v in _rewrite(table, path, geo=wrong))
    wrong = json.loads(json.dumps(geo))
    wrong["version"], wrong["columns"]["geometry"]["edges"] = "1.1", "flat"
    assert sum("(schema)" in v for v in _rewrite(table, path, geo=wrong)) == 2
    wrong = json.loads(json.dumps(geo))
    wrong["columns"]["geometry"]["bbox"] = [0.0, 0.0, 1.0, 1.0]
    assert any("§bbox" in v for v in _rewrite(table, path, geo=wrong))
    reversed_wkb = pa.array(shapely.to_wkb(shapely.reverse(shapely.from_wkb(table.column("geometry").to_numpy(zero_copy_only=False)))))
    flipped = table.set_column(table.num_columns - 1, table.schema.field("geometry"), reversed_wkb)
    assert any("§orientation" in v for v in _rewrite(flipped, path))
    full = np.column_stack([np.full(200, -180.0), np.full(200, -90.0), np.full(200, -170.0), np.full(200, 90.0)])
    narrow = pa.StructArray.from_arrays([pa.array(full[:, i]) for i in range(4)], fields=list(table.schema.field("bbox").type))
    shrunk = table.set_column(table.num_columns - 2, table.schema.field("bbox"), narrow)
    assert any("outside their bbox" in v for v in _rewrite(shrunk, path))
    pq.write_table(table.replace_schema_metadata({}), path)
    assert violations(path) == ["§Metadata: a GeoParquet file MUST include a 'geo' key in the Parquet metadata"]


@pytest.mark.parametrize("box", [(0, 0, 1), (0, 0, 1, float("nan")), (0, 10, 1, 5), (0, 0, 200, 1)])
def test_bad_filter_boxes_raise(box):
    with pytest.raises(dggs.DggsValueError, match="bbox"):
        bbox_filter(box)
    with pytest.raises(dggs.DggsValueError, match="bbox"):
        bbox_sql(box)


def test_lng_extent_needs_a_range():
    with pytest.raises(dggs.DggsValueError, match="at least one"):
        lng_extent(np.empty(0), np.empty(0))


_LEVEL4 = np.asarray(dggs.uncompact_cells(dggs.get_base_cells(), 4))  # 3,240 cells: poles and +-180 included
_POLYS4 = dggs.cell_to_polygon(_LEVEL4, DENSIFY)


@st.composite
def _plain_boxes(draw):
    """Plain query boxes (xmin <= xmax), often touching +-180 or a pole."""
    x = sorted([draw(st.one_of(st.floats(-180.0, 180.0), st.sampled_from([-180.0, 180.0, -179.9, 179.9]))) for _ in range(2)])
    y = sorted([draw(st.one_of(st.floats(-90.0, 90.0), st.sampled_from([-90.0, 90.0, 89.5, -89.5]))) for _ in range(2)])
    return (x[0], y[0], x[1], y[1])


@settings(max_examples=examples(60), deadline=None)
@given(box=_plain_boxes())
@example(box=(170.0, -20.0, 180.0, 20.0))
@example(box=(-180.0, 80.0, -179.0, 90.0))
@example(box=(179.999, -90.0, 180.0, 90.0))
def test_comparing_the_bbox_fields_as_they_are_loses_no_cell(box):
    """Any plain box: the rows whose ``bbox`` fields meet it, compared as they are (what generic readers do),
    hold every cell whose polygon meets it (shapely, brute force)."""
    import pyarrow.compute as pc

    table = _TABLE4()
    x0, y0, x1, y1 = box
    f = {k: pc.field(("bbox", k)) for k in ("xmin", "ymin", "xmax", "ymax")}
    expr = (f["xmin"] <= x1) & (f["xmax"] >= x0) & (f["ymin"] <= y1) & (f["ymax"] >= y0)
    import pyarrow.dataset as ds

    got = set(ds.dataset(table).to_table(columns=["cell"], filter=expr).column("cell").to_pylist())
    truth = set(_LEVEL4[shapely.intersects(_POLYS4, shapely.box(*box))])
    assert truth <= got, sorted(truth - got)[:5]


@functools.lru_cache(maxsize=1)
def _TABLE4():  # noqa: N802
    return cells_to_table(_LEVEL4, densify=DENSIFY)
