"""Exports sized to need (issue 38 item 3): ``tolerance=`` in metres by default, ``"exact"`` one keyword away,
the choice in the file's metadata; the exact export's areas checked with pyproj.Geod, the default's distance
bound with it too."""

from __future__ import annotations

import json

import numpy as np
import pyarrow.parquet as pq
import pytest
import shapely
from click.testing import CliRunner
from pyproj import Geod

import dggs
from dggs.cli import main
from dggs.errors import DggsValueError
from dggs.storage import CellStore

GEOD = Geod(ellps="WGS84")


@pytest.fixture
def points_db(tmp_path, rng):
    path = tmp_path / "p.db"
    lat = np.degrees(np.arcsin(rng.uniform(-0.95, 0.95, 3000)))
    lng = rng.uniform(-180, 180, 3000)
    with CellStore(path) as store:
        store.ingest_points(lat, lng, 8, {"v": rng.uniform(0, 1, 3000)})
    return path


def _areas(geoms):
    out = []
    for g in geoms:
        out.append(sum(abs(GEOD.polygon_area_perimeter(*np.asarray(p.exterior.coords).T)[0]) for p in getattr(g, "geoms", [g])))
    return np.array(out)


def test_default_geoparquet_is_light_and_exact_keeps_areas(points_db, tmp_path):
    light, exact = tmp_path / "light.parquet", tmp_path / "exact.parquet"
    with CellStore(points_db) as store:
        n = store.export(light, 6, "v")
        assert store.export(exact, 6, "v", tolerance="exact") == n
    meta_light = json.loads(pq.read_schema(light).metadata[b"dggs"])
    meta_exact = json.loads(pq.read_schema(exact).metadata[b"dggs"])
    assert meta_light == {"edge_points": "tolerance", "tolerance_m": 10.0}
    assert meta_exact == {"edge_points": "exact", "area_tolerance": 1e-6}
    t_light, t_exact = pq.read_table(light), pq.read_table(exact)
    g_light = shapely.from_wkb(t_light.column("geometry").to_numpy(zero_copy_only=False))
    g_exact = shapely.from_wkb(t_exact.column("geometry").to_numpy(zero_copy_only=False))
    assert shapely.get_num_coordinates(g_light).sum() < shapely.get_num_coordinates(g_exact).sum() / 4
    cells = t_exact.column("cell").to_pylist()
    keep = np.array([abs(shapely.bounds(g)[1]) < 89 and abs(shapely.bounds(g)[3]) < 89 for g in g_exact])
    want = np.array([dggs.cell_area(c) for c in cells])
    err = np.abs(_areas(g_exact[keep]) / want[keep] - 1)
    assert err.max() <= 1e-6
    # the light file's polygons differ from the exact ones by under 10 m of edge: its area by under 10 m x perimeter
    light_err = np.abs(_areas(g_light[keep]) - want[keep])
    assert (light_err <= 10.0 * 3 * np.sqrt(want[keep]) * 3).all()


def test_geojson_carries_the_choice_and_densify_still_fixes_the_count(points_db, tmp_path):
    with CellStore(points_db) as store:
        fc = store.to_geojson(5, "v", tmp_path / "a.geojson")
        fixed = store.to_geojson(5, "v", densify=2)
        exact = store.to_geojson(5, "v", tolerance="exact")
    assert json.loads((tmp_path / "a.geojson").read_text())["dggs"] == fc["dggs"] == {
        "edge_points": "tolerance", "tolerance_m": 10.0}
    assert fixed["dggs"] == {"edge_points": "densify", "densify": 2}
    assert all(len(f["geometry"]["coordinates"][0]) == 10 for f in fixed["features"] if f["geometry"]["type"] == "Polygon")
    assert exact["dggs"]["edge_points"] == "exact"


@pytest.mark.parametrize("bad", [0, -5, "precise", float("nan")])
def test_a_bad_tolerance_is_named_and_nothing_is_written(points_db, tmp_path, bad):
    out = tmp_path / "x.parquet"
    with CellStore(points_db) as store, pytest.raises(DggsValueError, match="tolerance"):
        store.export(out, 5, tolerance=bad)
    assert not out.exists()


def test_cli_export_tolerance(points_db, tmp_path):
    out = tmp_path / "c.parquet"
    result = CliRunner().invoke(main, ["export", str(points_db), "--level", "5", "-o", str(out), "--tolerance", "exact"])
    assert result.exit_code == 0, result.output
    assert json.loads(pq.read_schema(out).metadata[b"dggs"])["edge_points"] == "exact"
    result = CliRunner().invoke(main, ["export", str(points_db), "--level", "5", "-o", str(out), "--tolerance", "huge"])
    assert result.exit_code != 0 and "huge" in result.output


def test_the_stores_default_tolerance_is_the_grids():
    """storage writes the default down so that opening a store loads no grid; it must be the grid's."""
    from dggs.index._densify import DRAW_TOLERANCE
    from dggs.storage import exporter

    assert exporter.DRAW_TOLERANCE == DRAW_TOLERANCE
