"""dggs.arrow: WKB / GeoArrow arrays of cells and GeoParquet 1.1, read back by geopandas and DuckDB."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np
import pytest
import shapely

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

import dggs  # noqa: E402
from dggs.arrow import (  # noqa: E402
    cells_to_geoarrow,
    cells_to_table,
    geo_metadata,
    geoarrow_field,
    write_cells,
    write_geoparquet,
)

ROOT = Path(__file__).resolve().parents[2]

# every level-3 cell: the pole cells and the antimeridian cells included
LEVEL3 = dggs.uncompact_cells(dggs.get_base_cells(), 3)


def _ref_wkb(cells, densify):
    return shapely.to_wkb(dggs.cell_to_polygon(np.asarray(cells), densify), byte_order=1, output_dimension=2).tolist()


@pytest.mark.parametrize("densify", [0, 3, None])
def test_wkb_is_shapelys_bytes(densify):
    got = cells_to_geoarrow(LEVEL3, densify)
    assert got.type == pa.binary() and len(got) == len(LEVEL3) and got.null_count == 0
    assert got.to_pylist() == _ref_wkb(LEVEL3, densify)


def test_mixed_levels_and_int_ids_and_pyarrow_in():
    cells = np.concatenate([LEVEL3[::7], dggs.uncompact_cells(["A0", "O31"], 9)[::5], ["T", "C401"]])
    ids = pa.array(dggs.str_to_int(cells))
    for densify in (0, None):
        assert cells_to_geoarrow(ids, densify).to_pylist() == _ref_wkb(cells, densify)
        assert cells_to_geoarrow(pa.array(cells), densify).equals(cells_to_geoarrow(cells.tolist(), densify))


def test_empty_and_scalar():
    assert len(cells_to_geoarrow([])) == 0
    assert cells_to_geoarrow("C401").to_pylist() == _ref_wkb(["C401"], 0)
    assert cells_to_table([]).num_rows == 0
    assert len(cells_to_geoarrow([], encoding="geoarrow")) == 0


def test_geoarrow_encoding_round_trips():
    plain = [c for c in LEVEL3 if dggs.cell_to_polygon(c, 2).geom_type == "Polygon"]
    arr = cells_to_geoarrow(plain, 2, encoding="geoarrow")
    assert arr.type == pa.list_(pa.list_(pa.struct([("x", pa.float64()), ("y", pa.float64())])))
    rings = arr.flatten()
    xy = rings.flatten()
    coords = np.column_stack([xy.field("x").to_numpy(), xy.field("y").to_numpy()])
    back = shapely.from_ragged_array(
        shapely.GeometryType.POLYGON, coords, (rings.offsets.to_numpy(), arr.offsets.to_numpy())
    )
    assert shapely.equals_exact(back, dggs.cell_to_polygon(np.array(plain), 2), 0).all()
    mixed = cells_to_geoarrow(LEVEL3, 2, encoding="geoarrow")  # some cells are split: multipolygons
    assert mixed.type == pa.list_(arr.type)
    field = geoarrow_field("g", "geoarrow", LEVEL3, 2)
    assert field.metadata[b"ARROW:extension:name"] == b"geoarrow.multipolygon" and field.type == mixed.type
    assert geoarrow_field("g", "geoarrow", plain, 2).metadata[b"ARROW:extension:name"] == b"geoarrow.polygon"
    assert geoarrow_field().metadata[b"ARROW:extension:name"] == b"geoarrow.wkb"


def test_bad_arguments():
    with pytest.raises(dggs.DggsValueError, match="encoding"):
        cells_to_geoarrow(["C4"], encoding="wkt")
    with pytest.raises(dggs.DggsValueError, match="densify"):
        cells_to_geoarrow(["C4"], densify=-1)
    with pytest.raises(dggs.InvalidCellError):
        cells_to_geoarrow(["C9"])
    with pytest.raises(dggs.DggsValueError, match="3 values for 2 cells"):
        cells_to_table(["C4", "C3"], {"n": [1, 2, 3]})
    with pytest.raises(dggs.DggsValueError, match="clashes"):
        cells_to_table(["C4"], {"geometry": [1]})
    with pytest.raises(dggs.DggsValueError, match="needs the cells"):
        geoarrow_field(encoding="geoarrow")
    with pytest.raises(dggs.DggsValueError, match="extension"):
        write_cells(cells_to_table(["C4"]), "cells.xyz")


def test_table_columns_bbox_and_geo_metadata():
    table = cells_to_table(LEVEL3, {"n": np.arange(len(LEVEL3))}, 16)
    assert table.column_names == ["cell", "cell_id", "n", "bbox", "geometry"]
    assert table.column("cell").to_pylist() == list(LEVEL3)
    assert table.column("cell_id").type == pa.int64()
    assert table.column("cell_id").to_pylist() == [int(i) for i in dggs.str_to_int(LEVEL3)]
    geo = json.loads(table.schema.metadata[b"geo"])
    col = geo["columns"]["geometry"]
    assert geo["version"] == "1.1.0" and geo["primary_column"] == "geometry" and "crs" not in col
    assert col["encoding"] == "WKB" and col["geometry_types"] == ["MultiPolygon", "Polygon"]
    assert col["covering"] == {"bbox": {k: ["bbox", k] for k in ("xmin", "ymin", "xmax", "ymax")}}
    assert col["bbox"] == [-180.0, -90.0, 180.0, 90.0]
    polys = dggs.cell_to_polygon(np.asarray(LEVEL3), 16)
    bbox = table.column("bbox").combine_chunks()
    got = np.column_stack([bbox.field(k).to_numpy() for k in ("xmin", "ymin", "xmax", "ymax")])
    split = shapely.get_type_id(polys) == 6  # across the antimeridian: every longitude, so naive readers keep them
    np.testing.assert_array_equal(got, shapely.bounds(polys))  # shapely's planar bounds, split cells' -180..180
    assert split.any() and (got[split, 0] == -180.0).all() and (got[split, 2] == 180.0).all()
    assert geo_metadata(["Polygon"], covering=None)["columns"]["geometry"].keys() == {
        "encoding", "geometry_types", "edges", "orientation"}


@pytest.fixture
def parquet_file(tmp_path):
    cells = np.sort(np.concatenate([LEVEL3, dggs.uncompact_cells(["O31"], 8)]))  # antimeridian cells at level 8
    values = np.arange(len(cells), dtype=float) / 7
    path = tmp_path / "cells.parquet"
    write_geoparquet(cells_to_table(cells, {"v": values}, densify=8), path)
    return path, cells, values


def test_geopandas_reads_it_back_identically(parquet_file):
    geopandas = pytest.importorskip("geopandas")
    path, cells, values = parquet_file
    frame = geopandas.read_parquet(path)
    assert frame.crs.to_string() == "OGC:CRS84"
    assert list(frame.columns) == ["cell", "cell_id", "v", "geometry"]  # the covering column is dropped
    assert frame["cell"].tolist() == list(cells)
    assert frame["cell_id"].tolist() == [int(i) for i in dggs.str_to_int(cells)]
    assert frame["v"].tolist() == values.tolist()
    assert shapely.equals_exact(frame.geometry.values, dggs.cell_to_polygon(cells, 8), 0).all()
    box = (10.0, 10.0, 20.0, 20.0)  # the bbox covering filters rows
    some = geopandas.read_parquet(path, bbox=box)
    assert 0 < len(some) < len(frame)
    bounds = shapely.bounds(frame.geometry.values)
    boxes = shapely.box(*bounds.T)  # the covering: one box per row, split cells' -180..180
    assert set(some["cell"]) == set(frame["cell"][shapely.intersects(boxes, shapely.box(*box))])
    assert set(some["cell"]) >= set(frame["cell"][frame.intersects(shapely.box(*box))])


def test_duckdb_reads_it_back_identically(parquet_file):
    duckdb = pytest.importorskip("duckdb")
    path, cells, values = parquet_file
    con = duckdb.connect()
    rel = con.sql(f"SELECT * FROM read_parquet('{path}') ORDER BY cell_id")
    assert rel.columns == ["cell", "cell_id", "v", "bbox", "geometry"]
    assert str(rel.types[1]) == "BIGINT" and "GEOMETRY" in str(rel.types[4])
    rows = con.sql(
        f"SELECT cell, cell_id, v, bbox.xmin, bbox.ymax, ST_AsWKB(geometry) FROM read_parquet('{path}') ORDER BY cell_id"
    ).fetchall()
    assert [r[0] for r in rows] == list(cells)  # int order is string order
    assert [r[1] for r in rows] == [int(i) for i in dggs.str_to_int(cells)]
    assert [r[2] for r in rows] == values.tolist()
    polys = dggs.cell_to_polygon(cells, 8)
    bounds = shapely.bounds(polys)  # split cells: -180..180
    assert [r[3] for r in rows] == bounds[:, 0].tolist() and [r[4] for r in rows] == bounds[:, 3].tolist()
    back = shapely.from_wkb([bytes(r[5]) for r in rows])
    assert shapely.equals_exact(back, polys, 0).all()
    n = con.sql(f"SELECT count(*) FROM read_parquet('{path}') WHERE bbox.xmax < -170").fetchall()[0][0]
    assert n == int((bounds[:, 2] < -170).sum())


def test_row_groups_let_a_bbox_filter_skip_most_of_the_file(tmp_path):
    """Issue 36: a file under a million cells was one row group, so the bbox covering's statistics pruned nothing.
    pyarrow is the referee: each row group's bbox statistics bound its cells, and a dataset filter on the bbox
    columns reads only the groups that can hold a match, the same rows as filtering every row."""
    import pyarrow.compute as pc
    import pyarrow.dataset as ds
    import pyarrow.parquet as pq

    from dggs.arrow import ROW_GROUP_CELLS

    cells = dggs.uncompact_cells(dggs.get_base_cells(), 5)  # 29,160 cells in id order, every face
    path = tmp_path / "cells.parquet"
    write_geoparquet(cells_to_table(cells), path)
    meta = pq.ParquetFile(path).metadata
    assert meta.num_row_groups == -(-len(cells) // ROW_GROUP_CELLS) > 1
    names = [meta.schema.column(i).path for i in range(meta.num_columns)]
    xmin, xmax = names.index("bbox.xmin"), names.index("bbox.xmax")
    table = pq.read_table(path)
    start = 0
    for g in range(meta.num_row_groups):
        group = meta.row_group(g)
        rows = table.slice(start, group.num_rows)
        lo, hi = group.column(xmin).statistics, group.column(xmax).statistics
        assert lo.has_min_max and hi.has_min_max
        assert lo.min == pc.min(rows["bbox"].combine_chunks().field("xmin")).as_py()
        assert hi.max == pc.max(rows["bbox"].combine_chunks().field("xmax")).as_py()
        start += group.num_rows
    where = (ds.field("bbox", "xmax") >= 10.0) & (ds.field("bbox", "xmin") <= 20.0) & \
        (ds.field("bbox", "ymax") >= 10.0) & (ds.field("bbox", "ymin") <= 20.0)
    fragment = next(ds.dataset(path).get_fragments())
    kept = fragment.split_by_row_group(filter=where)
    assert 0 < len(kept) < meta.num_row_groups  # the statistics skip groups
    got = ds.dataset(path).to_table(filter=where)["cell"].to_pylist()
    box = table["bbox"].combine_chunks()
    mask = (pc.greater_equal(box.field("xmax"), 10.0).to_numpy(zero_copy_only=False)
            & pc.less_equal(box.field("xmin"), 20.0).to_numpy(zero_copy_only=False)
            & pc.greater_equal(box.field("ymax"), 10.0).to_numpy(zero_copy_only=False)
            & pc.less_equal(box.field("ymin"), 20.0).to_numpy(zero_copy_only=False))
    assert got == [c for c, m in zip(table["cell"].to_pylist(), mask, strict=True) if m] and got


def test_write_is_atomic(tmp_path, monkeypatch):
    path = tmp_path / "cells.parquet"
    write_geoparquet(cells_to_table(["C4"]), path)
    before = path.read_bytes()

    def broken(table, where, **kwargs):
        Path(where).write_bytes(b"PAR1 half a file")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(pq, "write_table", broken)
    with pytest.raises(dggs.StorageError, match="No space left"):
        write_geoparquet(cells_to_table(["C3"]), path)
    assert path.read_bytes() == before and os.listdir(tmp_path) == ["cells.parquet"]
    with pytest.raises(dggs.DggsValueError, match="geo"):
        write_geoparquet(pa.table({"a": [1]}), path)


@pytest.mark.parametrize("fmt", ["gpkg", "fgb", "geojson"])
def test_gdal_formats_through_pyogrio(tmp_path, fmt):
    pyogrio = pytest.importorskip("pyogrio")
    cells = LEVEL3[::5]
    path = tmp_path / f"cells.{fmt}"
    assert write_cells(cells_to_table(cells, {"n": np.arange(len(cells))}, densify=4), path) == fmt
    assert os.listdir(tmp_path) == [path.name]  # the temporary folder is gone
    frame = pyogrio.read_dataframe(path)
    frame = frame.sort_values("cell_id", ignore_index=True)  # FlatGeobuf's spatial index orders features
    assert frame["cell"].tolist() == list(cells) and frame["n"].tolist() == list(range(len(cells)))
    assert frame["cell_id"].tolist() == [int(i) for i in dggs.str_to_int(cells)]
    assert frame.crs.equals("OGC:CRS84") or frame.crs.to_epsg() == 4326
    want = dggs.cell_to_polygon(np.asarray(cells), 4)
    tolerance = 1e-6 if fmt == "geojson" else 0  # GDAL's GeoJSON keeps 7 decimals (1 cm)
    assert (shapely.hausdorff_distance(frame.geometry.values, want) <= tolerance).all()
    if fmt != "geojson":  # one layer type: the cells split at the antimeridian make every cell a MultiPolygon
        assert (frame.geom_type == "MultiPolygon").all()


@pytest.mark.parametrize("fmt", ["gpkg", "fgb"])
@pytest.mark.parametrize("east", [170.0, 180.0])
def test_tables_go_to_gdal_as_arrow_and_read_back_as_geopandas_writes_them(tmp_path, fmt, east):
    """The WKB goes straight to pyogrio.write_arrow; geopandas' own file (promote_to_multi) is the oracle.

    Up to 170 E every cell is a Polygon; up to 180 some are split at the antimeridian, so all are written
    as MultiPolygons, the Polygons wrapped as one-part MultiPolygons.
    """
    pyogrio = pytest.importorskip("pyogrio")
    geopandas = pytest.importorskip("geopandas")
    lat, lng = np.linspace(-60, 60, 400), np.linspace(-170, east, 400)
    cells = np.unique(dggs.latlng_to_cell(lat, lng, 6))
    props = {"n": np.arange(len(cells)), "x": np.linspace(0.0, 1.0, len(cells)), "s": [f"v{i}" for i in range(len(cells))]}
    table = cells_to_table(cells, props, densify=4)
    fast, slow = tmp_path / f"fast.{fmt}", tmp_path / f"slow.{fmt}"
    write_cells(table, fast)
    frame = geopandas.GeoDataFrame(
        table.drop_columns(["bbox", "geometry"]).to_pandas(),
        geometry=shapely.from_wkb(table.column("geometry").to_numpy(zero_copy_only=False)), crs="OGC:CRS84",
    )
    split = bool((frame.geom_type == "MultiPolygon").any())
    assert split == (east == 180.0)
    frame.to_file(slow, driver={"gpkg": "GPKG", "fgb": "FlatGeobuf"}[fmt], engine="pyogrio", layer="fast",
                  promote_to_multi=split)
    a = pyogrio.read_dataframe(slow).sort_values("cell_id", ignore_index=True)
    b = pyogrio.read_dataframe(fast).sort_values("cell_id", ignore_index=True)
    kind = "MultiPolygon" if split else "Polygon"
    assert pyogrio.read_info(fast)["geometry_type"] == pyogrio.read_info(slow)["geometry_type"] == kind
    assert (b.geom_type == kind).all()
    assert list(b.columns) == list(a.columns) and b.dtypes.to_dict() == a.dtypes.to_dict() and b.crs == a.crs
    assert b.drop(columns="geometry").equals(a.drop(columns="geometry"))
    assert b.geometry.geom_equals_exact(a.geometry, 0).all()
    assert (shapely.hausdorff_distance(b.geometry.values, dggs.cell_to_polygon(cells, 4)) == 0).all()


def test_gdal_write_failure_leaves_nothing(tmp_path):
    pytest.importorskip("pyogrio")
    with pytest.raises(dggs.StorageError):
        write_cells(cells_to_table(["C4"]), tmp_path / "missing" / "cells.gpkg")
    assert os.listdir(tmp_path) == []


def test_export_formats_agree_with_the_store(tmp_path):
    from dggs import arrow
    from dggs.arrow import formats as _formats
    from dggs.storage import CellStore

    # one table for both: the writers here and CellStore.export / dggs export
    assert arrow.export_format is _formats.export_format
    assert arrow.EXPORT_FORMATS == ("geojson", "geoparquet", "gpkg", "fgb")
    assert arrow.export_format("a.GPKG") == "gpkg"
    with pytest.raises(dggs.DggsValueError) as by_arrow:
        arrow.export_format(tmp_path / "cells.xyz")
    with CellStore() as store, pytest.raises(dggs.DggsValueError) as by_store:
        store.ingest_points([1.0], [2.0], 4)
        store.export(tmp_path / "cells.xyz", 1)
    assert str(by_store.value) == str(by_arrow.value)


def _doc_blocks():
    text = (ROOT / "docs" / "arrow.md").read_text()
    return [m.group(1) for m in re.finditer(r"^```python\n(.*?)^```", text, re.M | re.S)]


@pytest.mark.parametrize("i", range(len(_doc_blocks())))
def test_docs_python_blocks_run(i, tmp_path, monkeypatch):
    pytest.importorskip("geopandas")
    pytest.importorskip("duckdb")
    (tmp_path / "examples").mkdir()
    (tmp_path / "examples" / "data").symlink_to(ROOT / "examples" / "data", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    exec(compile(_doc_blocks()[i], f"docs/arrow.md block {i}", "exec"), {"__name__": "__doc_block__"})  # noqa: S102


def test_docs_have_python_blocks():
    assert len(_doc_blocks()) >= 2
