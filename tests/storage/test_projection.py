"""The projection a store records (meta.projection) and bins its points with (storage/projection.py).

The oracle of where a point belongs on IVEA is shapely: the point lies in (or on the edge of) the IVEA
polygon of its stored cell, and, for most random points, outside the ISEA polygon of that id (the grids
differ by up to 56 km, so at a fine level the two ids differ).
"""

from __future__ import annotations

import sqlite3

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import dggs
from dggs.errors import DggsValueError, StorageError
from dggs.storage import CellStore
from tests.strategies import examples, latlngs, special_points

IVEA = dggs.Grid("IVEA")


def _stored(store: CellStore) -> tuple[list[str], np.ndarray, np.ndarray]:
    rows = list(store.conn.execute("SELECT cell, lat, lng FROM all_points ORDER BY source_id, row"))
    return [r[0] for r in rows], np.array([r[1] for r in rows]), np.array([r[2] for r in rows])


def _inside(grid: dggs.Grid, cells: list[str], lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    polys = grid.cell_to_polygon(cells)
    # a point on a shared edge or corner may be given to either cell: 1e-7 degrees (1 cm) of tolerance
    inside = shapely.dwithin(polys, shapely.points(lng, lat), 1e-7)
    # a pole is every longitude at once: the cell holding it (or a point 1 cm from it) reaches that pole
    bounds = shapely.bounds(polys)
    pole = np.abs(lat) > 90 - 1e-7  # within 1 cm of it
    inside[pole] = np.where(lat[pole] > 0, bounds[pole, 3] == 90, bounds[pole, 1] == -90)
    return inside


def test_new_store_records_the_projection(tmp_path):
    path = tmp_path / "a.db"
    with CellStore(path, projection="ivea") as store:
        assert store.projection == "IVEA" and store.grid == IVEA
        assert store.info()["projection"] == "IVEA"
    conn = sqlite3.connect(path)
    assert conn.execute("SELECT value FROM meta WHERE key = 'projection'").fetchone() == ("IVEA",)
    conn.close()
    with CellStore(path) as store:  # read back from the file
        assert store.projection == "IVEA"
    with CellStore(path, readonly=True) as store:
        assert store.projection == "IVEA"
    with CellStore(path, projection="IVEA") as store:  # the same, explicitly: fine
        assert store.projection == "IVEA"


def test_default_and_old_files_are_isea(tmp_path):
    path = tmp_path / "old.db"
    with CellStore(path) as store:
        assert store.projection == "ISEA"
        store.ingest_points([1.0], [2.0], 5)
    conn = sqlite3.connect(path)  # a file written before the key existed
    conn.execute("DELETE FROM meta WHERE key = 'projection'")
    conn.commit()
    conn.close()
    with CellStore(path) as store:
        assert store.projection == "ISEA"
    with CellStore(path, projection="ISEA") as store:
        assert store.projection == "ISEA"


@pytest.mark.parametrize(("first", "second"), [("IVEA", "ISEA"), ("ISEA", "IVEA")])
def test_mismatch_names_both(tmp_path, first, second):
    path = tmp_path / "m.db"
    with CellStore(path, projection=first) as store:
        store.ingest_points([10.0], [20.0], 4)
    with pytest.raises(StorageError) as info:
        CellStore(path, projection=second)
    assert first in str(info.value) and second in str(info.value) and str(path) in str(info.value)
    with pytest.raises(StorageError):
        CellStore(path, projection=second, readonly=True)


def test_old_file_with_cells_refuses_ivea(tmp_path):
    path = tmp_path / "old.db"
    with CellStore(path) as store:
        store.ingest_points([1.0], [2.0], 5)
    with pytest.raises(StorageError, match="ISEA.*IVEA"):
        CellStore(path, projection="IVEA")


def test_empty_old_store_takes_the_projection(tmp_path):
    path = tmp_path / "empty.db"
    CellStore(path).close()  # created, nothing ingested, no projection asked for
    with CellStore(path, projection="IVEA") as store:
        assert store.projection == "IVEA"
    with CellStore(path) as store:
        assert store.projection == "IVEA"


@pytest.mark.parametrize("bad", ["HEALPix", "", 3, None.__class__])
def test_bad_projection_is_named(tmp_path, bad):
    with pytest.raises(DggsValueError, match="projection"):
        CellStore(tmp_path / "b.db", projection=bad)


def test_damaged_meta_is_named(tmp_path):
    path = tmp_path / "d.db"
    CellStore(path, projection="IVEA").close()
    conn = sqlite3.connect(path)
    conn.execute("UPDATE meta SET value = 'XYZ' WHERE key = 'projection'")
    conn.commit()
    conn.close()
    with pytest.raises(StorageError, match="XYZ"):
        CellStore(path)


def _ingest_and_check(points: list[tuple[float, float]], level: int) -> None:
    lat = np.array([p[0] for p in points])
    lng = np.array([p[1] for p in points])
    with CellStore(projection="IVEA") as store:
        store.ingest_points(lat, lng, level, {"v": np.arange(len(lat))})
        cells, slat, slng = _stored(store)
    assert len(cells) == len(lat)
    assert _inside(IVEA, cells, slat, slng).all()
    # the integer form of the same location gives the same ids
    as_int = IVEA.latlng_to_cell(slat, slng, level, as_int=True)
    assert [dggs.int_to_str(int(c)) for c in as_int] == cells


def test_ingest_bins_on_ivea_at_special_points():
    _ingest_and_check(special_points(), 9)


@settings(max_examples=examples(30), deadline=None)
@given(st.lists(latlngs(), min_size=2, max_size=40), st.integers(3, 16))
def test_ingest_bins_on_ivea(points, level):
    _ingest_and_check(points, level)


def test_ivea_and_isea_stores_differ(rng):
    lat, lng = rng.uniform(-80, 80, 300), rng.uniform(-180, 180, 300)
    with CellStore(projection="IVEA") as ivea, CellStore() as isea:
        ivea.ingest_points(lat, lng, 12)
        isea.ingest_points(lat, lng, 12)
        a, alat, alng = _stored(ivea)
        b, _, _ = _stored(isea)
    assert sorted(a) != sorted(b)
    # most IVEA ids hold their points on IVEA only (at level 12 a cell is ~2 km, the grids ~tens of km apart)
    assert (~_inside(dggs.Grid("ISEA"), a, alat, alng)).mean() > 0.5


def test_csv_ingest_bins_on_ivea(tmp_path):
    csv = tmp_path / "p.csv"
    csv.write_text("lat,lng,v\n51.05,-114.07,1\n-33.9,151.2,2\n0.0,180.0,3\n89.9,10.0,4\n")
    with CellStore(tmp_path / "c.db", projection="IVEA") as store:
        store.ingest_csv(csv, level=10)
        cells, lat, lng = _stored(store)
    assert _inside(IVEA, cells, lat, lng).all()


def test_exports_draw_the_store_grid():
    with CellStore(projection="IVEA") as store:
        store.ingest_points([51.05, -33.9], [-114.07, 151.2], 8, {"v": [1.0, 2.0]})
        fc = store.to_geojson(6, "v", tolerance="exact")
    for feature in fc["features"]:
        got = shapely.geometry.shape(feature["geometry"])
        want = IVEA.cell_to_polygon(feature["properties"]["cell"])
        assert got.symmetric_difference(want).area < 1e-9


def test_geoparquet_export_of_an_ivea_store(tmp_path, rng):
    import pyarrow.parquet as pq

    from tests.storage.geoparquet_rules import violations

    # the poles, the antimeridian (cells split there) and random points
    lat = np.concatenate([[90.0, -90.0, 10.0, -20.0, 65.0], rng.uniform(-90, 90, 300)])
    lng = np.concatenate([[0.0, 0.0, 180.0, -179.99, 179.9], rng.uniform(-180, 180, 300)])
    out = tmp_path / "cells.parquet"
    with CellStore(projection="IVEA") as store:
        store.ingest_points(lat, lng, 8, {"v": np.ones(len(lat))})
        assert store.export(out, 3, "v", densify=16) > 0
        counts = {r["cell"]: r["count"] for r in store.aggregate(3)}
    assert violations(out) == []  # every MUST of GeoParquet 1.1 (tests/storage/geoparquet_rules.py)
    table = pq.read_table(out)
    cells = table.column("cell").to_pylist()
    assert dict(zip(cells, table.column("count").to_pylist(), strict=True)) == counts
    got = shapely.from_wkb(table.column("geometry").to_pylist())
    want = IVEA.cell_to_polygon(np.asarray(cells), densify=16)
    assert (shapely.area(shapely.symmetric_difference(got, want)) <= 1e-9 * shapely.area(want)).all()
    isea = dggs.cell_to_polygon(np.asarray(cells), densify=16)  # not the ISEA shapes of the same ids
    assert (shapely.area(shapely.symmetric_difference(got, isea)) > 1e-4 * shapely.area(want)).mean() > 0.9


def test_polygons_filled_with_ivea_cells(tmp_path):
    import json

    ring = [[-179.0, 60.0], [179.0, 60.0], [179.0, 70.0], [-179.0, 70.0], [-179.0, 60.0]]  # across the antimeridian
    square = {"type": "Feature", "properties": {"v": 1},
              "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [5, 0], [5, 5], [0, 5], [0, 0]]]}}
    polar = {"type": "Feature", "properties": {"v": 2}, "geometry": {"type": "Polygon", "coordinates": [ring]}}
    path = tmp_path / "square.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [square, polar]}))
    with CellStore(projection="IVEA") as store:
        store.ingest_geojson(path, level=6)
        rows = list(store.conn.execute("SELECT cell, lat, lng, v FROM all_points"))
    box = shapely.box(0, 0, 5, 5)
    cells = [r[0] for r in rows if r[3] == 1]
    # brute force: every level-6 cell whose IVEA centre lies in the square, among the square's neighbourhood
    near = dggs.uncompact_cells(list(dict.fromkeys(dggs.Grid("IVEA").latlng_to_cell(
        np.repeat(np.linspace(-1, 6, 30), 30), np.tile(np.linspace(-1, 6, 30), 30), 3).tolist())), 6)
    clat, clng = IVEA.cell_to_latlng(np.asarray(near))
    want = {c for c, y, x in zip(near, clat, clng, strict=True) if box.contains(shapely.Point(x, y))}
    assert set(cells) == want
    # each row sits at its cell's IVEA centre, inside the polygons
    lat = np.array([r[1] for r in rows])
    lng = np.array([r[2] for r in rows])
    assert _inside(IVEA, [r[0] for r in rows], lat, lng).all()
    assert any(r[3] == 2 for r in rows)


def test_rasters_refused_on_ivea():
    with CellStore(projection="IVEA") as store, pytest.raises(DggsValueError, match="IVEA"):
        store.ingest_raster("no-such-raster.tif", 5)

def test_cli_bin_projection(tmp_path):
    from click.testing import CliRunner

    from dggs.cli import main

    csv = tmp_path / "p.csv"
    csv.write_text("lat,lng,v\n51.05,-114.07,1\n-33.9,151.2,2\n0.0,-180.0,3\n")
    db = tmp_path / "p.db"
    runner = CliRunner()
    done = runner.invoke(main, ["bin", str(csv), "--db", str(db), "--level", "9", "--projection", "ivea"])
    assert done.exit_code == 0, done.output
    assert "IVEA" in done.output
    with CellStore(db) as store:
        assert store.projection == "IVEA"
        cells, lat, lng = _stored(store)
    assert _inside(IVEA, cells, lat, lng).all()
    info = runner.invoke(main, ["info", str(db)])
    assert "projection  IVEA" in info.output
    again = runner.invoke(main, ["bin", str(csv), "--db", str(db), "--level", "9", "--projection", "ISEA"])
    assert again.exit_code != 0
    assert "IVEA" in again.output and "ISEA" in again.output
    bad = runner.invoke(main, ["bin", str(csv), "--db", str(tmp_path / "q.db"), "--projection", "HEALPIX"])
    assert bad.exit_code != 0 and "HEALPIX" in bad.output


def test_plot_draws_the_store_grid(monkeypatch, tmp_path):
    import dggs.storage.plot as plot

    drawn: list[str] = []
    real = dggs.Grid.cell_to_polygon

    def spy(self, cell, *args, **kwargs):
        drawn.append(self.projection)
        return real(self, cell, *args, **kwargs)

    monkeypatch.setattr(dggs.Grid, "cell_to_polygon", spy)
    plot.plot_cells(["C40", "A0"], [1.0, 2.0], tmp_path / "m.png", projection="IVEA")
    assert drawn == ["IVEA"]
