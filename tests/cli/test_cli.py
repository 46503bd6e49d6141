"""The dggs command line (click's CliRunner)."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

import dggs
from dggs.cli import main


def run(*args):
    return CliRunner().invoke(main, list(args))


def test_help_lists_commands():
    res = run("--help")
    assert res.exit_code == 0
    for name in ("cell", "experiments"):
        assert name in res.output


def test_cell_from_latlng_with_negative_longitude():
    res = run("cell", "from-latlng", "51.05", "-114.07", "--level", "9")
    assert res.exit_code == 0
    assert res.output.strip() == dggs.latlng_to_cell(51.05, -114.07, 9)


def test_cell_info_json():
    res = run("cell", "info", "C401", "--json")
    assert res.exit_code == 0
    data = json.loads(res.output)
    assert data["level"] == 3 and data["parent"] == "C40" and len(data["neighbors"]) == 3


def test_cell_boundary_geojson():
    res = run("cell", "boundary", "C401", "--geojson")
    assert res.exit_code == 0
    feature = json.loads(res.output)
    assert feature["geometry"]["type"] == "Polygon"


def test_errors_are_clean_messages_with_exit_1():
    res = run("cell", "info", "C9")
    assert res.exit_code == 1
    assert "'C9'" in res.output and "Traceback" not in res.output
    res = run("cell", "from-latlng", "91", "0", "--level", "3")
    assert res.exit_code == 1 and "latitude 91.0" in res.output


def test_levels_table():
    res = run("cell", "levels", "--max-level", "28")
    assert res.exit_code == 0
    assert "0.5574 m^2" in res.output.splitlines()[-1]  # 510,065,621,724,088 m^2 / 915,071,698,198,440 cells


def test_a_bad_level_prints_only_the_error():
    res = run("cell", "levels", "--max-level", "29")
    assert res.exit_code == 1
    assert res.output.strip().splitlines() == ["Error: level 29 is out of range 0..28"]


# -- a failed `dggs bin` creates no store (nor -wal/-shm) -----------------------------

_POINT = {"type": "Feature", "geometry": {"type": "Point", "coordinates": [2.0, 1.0]}, "properties": {"a": 1}}
_LINE = {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[1, 2], [3, 4]]}, "properties": {}}
_GEOJSON_FAILURES = {
    "broken JSON": ('{"type": "FeatureCollection", "features": [', [], "is not valid JSON"),
    "not GeoJSON": ('{"type": "Topology"}', [], "is not GeoJSON"),
    "no points": (json.dumps({"type": "FeatureCollection", "features": [_LINE, _POINT]}), [], "row 1: geometry is not"),
    "bad level": (json.dumps(_POINT), ["--level", "29"], "level 29 is out of range"),
}


def _bin_leaves_nothing(folder, before, args, named):
    db = folder / "new.db"
    res = run("bin", *args, "--db", str(db), "--no-progress")
    assert res.exit_code == 1, res.output
    assert "Traceback" not in res.output and len(res.output.strip().splitlines()) == 1, res.output
    assert named in res.output, res.output
    assert sorted(p.name for p in folder.iterdir()) == before  # no new.db, new.db-wal or new.db-shm


@pytest.mark.parametrize("case", list(_GEOJSON_FAILURES))
def test_a_failed_bin_of_geojson_leaves_no_store(tmp_path, case):
    text, extra, named = _GEOJSON_FAILURES[case]
    path = tmp_path / "in.geojson"
    path.write_text(text)
    _bin_leaves_nothing(tmp_path, ["in.geojson"], [str(path), *extra], named)


@pytest.mark.parametrize("suffix", [".gpkg", ".fgb", ".shp"])
@pytest.mark.parametrize("case", ["--value", "--layer", "--crs", "lines"])
def test_a_failed_bin_of_a_vector_file_leaves_no_store(tmp_path, suffix, case):
    gpd = pytest.importorskip("geopandas")
    pytest.importorskip("pyogrio")
    from shapely.geometry import LineString, Point

    geometry = [LineString([(1, 2), (3, 4)])] if case == "lines" else [Point(2, 1)]
    path = tmp_path / f"in{suffix}"
    gpd.GeoDataFrame({"a": [1]}, geometry=geometry, crs="EPSG:4326").to_file(path)
    before = sorted(p.name for p in tmp_path.iterdir())  # a shapefile's .dbf, .shx, .prj too
    extra, named = {
        "--value": (["--value", "nope"], "no column(s) 'nope'"),
        "--layer": (["--layer", "nope"], "cannot read layer 'nope'"),
        "--crs": (["--crs", "EPSG:99999"], "unknown CRS 'EPSG:99999'"),
        "lines": ([], "row 1: geometry is not a Point"),
    }[case]
    _bin_leaves_nothing(tmp_path, before, [str(path), "--level", "5", *extra], named)


# -- boundary work is bounded before it starts --------------------------------------------


@pytest.mark.parametrize("suffix", [".geojson", ".parquet"])
def test_export_with_a_huge_densify_refuses_before_building_boundaries(tmp_path, suffix):
    """1,013 level-3 cells of 300,004 points each: over MAX_POINTS (index/_checks.py), so refused, nothing written."""
    import numpy as np

    from dggs.storage import CellStore

    rng = np.random.default_rng(5)
    db = tmp_path / "s.db"
    with CellStore(db) as store:
        store.ingest_points(np.degrees(np.arcsin(rng.uniform(-1, 1, 3000))), rng.uniform(-180, 180, 3000), 8)
    out = tmp_path / f"x{suffix}"
    res = run("export", str(db), "--level", "3", "--densify", "100000", "-o", str(out))
    assert res.exit_code == 1 and "Traceback" not in res.output, res.output
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and "boundary points" in lines[0] and "over the limit of 50,000,000" in lines[0], lines
    assert [p.name for p in tmp_path.iterdir() if not p.name.startswith("s.db")] == []  # no output, no temp file
