"""Several named datasets in one store file (issue 38, item 5): each with its own level, projection, columns.

The referees: pandas groupby over the raw points (cells from ``dggs.latlng_to_cell``), ``raster_to_cells`` for the
raster's rows (tested against independent oracles in tests/raster), and, for a store written before datasets, the
outputs main's code gave for it (tests/storage/fixtures/single_dataset_v1.json, written with the fixture file by
main at 50f668d).
"""

from __future__ import annotations

import json
import math
import shutil
import sqlite3
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.cli import main
from dggs.errors import DggsValueError
from dggs.storage import BadRowError, CellStore, DatasetError, list_datasets
from dggs.storage.scoped import scoped

FIXTURES = Path(__file__).parent / "fixtures"


def _tables(path) -> set[str]:
    with sqlite3.connect(path) as conn:
        return {name for (name,) in conn.execute("SELECT name FROM sqlite_master")}


def _rows(path, dataset: str | None) -> list[tuple]:
    """Every stored row of one dataset, read by its full table names (no dggs code in between)."""
    prefix = "" if dataset is None else f"{dataset}/"
    with sqlite3.connect(path) as conn:
        return sorted(conn.execute(f'SELECT * FROM "{prefix}points" UNION ALL SELECT * FROM "{prefix}points_pending"'))


def _same(got, frozen) -> bool:
    return json.loads(json.dumps(got, default=str)) == frozen


# -- a store written before datasets ---------------------------------------------------------------------------


def test_a_store_written_before_datasets_opens_queries_and_ingests_as_before(tmp_path):
    frozen = json.loads((FIXTURES / "single_dataset_v1.json").read_text())
    db = tmp_path / "old.db"
    shutil.copy(FIXTURES / "single_dataset_v1.db", db)
    before = _tables(db)
    with CellStore(db, readonly=True) as store:
        assert store.dataset is None
        assert store.count() == frozen["count"] and store.level == frozen["level"]
        assert store.projection == frozen["projection"] and store.columns == frozen["columns"]
        assert list(store.rollup_levels) == frozen["rollup_levels"]
        assert _same(store.aggregate(2, "pop", ("count", "sum", "min", "max")), frozen["aggregate_2_pop"])
        assert _same(store.aggregate(3, "w", ("count", "sum")), frozen["aggregate_3_w"])
        assert _same(store.descendants("C"), frozen["descendants_C"])
        assert [(d["name"], d["level"], d["rows"]) for d in store.datasets()] == [(None, 9, 8)]
    with CellStore(db) as store:
        store.ingest_points([10.0, -10.0], [20.0, -20.0], 9, {"pop": [100, 200], "w": [9.5, 8.5]}, source="more")
        after = frozen["after_ingest"]
        assert store.count() == after["count"]
        assert _same(store.aggregate(1, "pop", ("count", "sum")), after["aggregate_1_pop"])
        assert _same(store.aggregate(3, "w", ("count", "sum")), after["rollup_3_w"])
    assert _tables(db) == before  # no table added: an older dggs reads it as before


# -- the case: points at level 17 and a raster at level 10 -----------------------------------------------


def _points(n=3000, seed=7):
    rng = np.random.default_rng(seed)
    lat, lng = rng.uniform(44.0, 52.0, n), rng.uniform(4.0, 14.0, n)
    return lat, lng, rng.integers(0, 1000, n), np.round(rng.uniform(0, 100, n), 3)


def _oracle(lat, lng, n, spend, level):
    """count, sum of n (exact) and fsum of spend per level-``level`` cell, by pandas over the raw points."""
    cells = dggs.latlng_to_cell(lat, lng, 17)
    frame = pd.DataFrame({"cell": [c[: level + 1] for c in cells], "n": n, "spend": spend})
    grouped = frame.groupby("cell")
    return {cell: (len(g), int(g["n"].sum()), math.fsum(g["spend"])) for cell, g in grouped}


def test_points_at_level_17_and_a_raster_at_level_10_share_a_store(tmp_path):
    pytest.importorskip("rasterio")
    from dggs.raster import raster_to_cells
    from tests.raster.helpers import field, same_rows, write

    raster = write(tmp_path / "land.tif", field(30, 40))
    db = tmp_path / "work.db"
    lat, lng, n, spend = _points()
    with CellStore(db) as points:
        points.ingest_points(lat, lng, 17, {"n": n, "spend": spend}, source="shops")
    with CellStore(db, dataset="land") as land:
        land.ingest_raster(raster, 10, mode="mean")
    with pytest.raises(dggs.LevelMismatchError, match="level 17"):  # the default dataset keeps its level
        CellStore(db).ingest_raster(raster, 10)

    assert [(d["name"], d["level"], d["projection"], d["rows"]) for d in list_datasets(db)] == [
        (None, 17, "ISEA", len(lat)), ("land", 10, "ISEA", len(raster_to_cells(raster, 10)))]

    want = raster_to_cells(raster, 10, mode="mean")
    value = [c for c in want.columns if c not in ("cell_id", "cell")][0]
    pixels = pd.DataFrame({"cell": [dggs.int_to_str(int(i)) for i in want["cell_id"]], "v": want[value]})
    for keep in (False, True):
        with CellStore(db) as points, CellStore(db, dataset="land") as land:
            if keep:  # rolled up each on its own: the kept partials give the same answers
                points.keep_rollups([12, 8])
                land.keep_rollups([8])
                assert points.rollup_levels == (12, 8) and land.rollup_levels == (8,)
            assert same_rows(land.conn, want)  # the raster's rows, to the last bit
            for level in (12, 8):
                got = {r["cell"]: (r["count"], r["sum"]) for r in points.aggregate(level, "n", ("count", "sum"))}
                oracle = _oracle(lat, lng, n, spend, level)
                assert got == {c: (k, s) for c, (k, s, _) in oracle.items()}
                spent = {r["cell"]: r["sum"] for r in points.aggregate(level, "spend", ("sum",))}
                assert spent.keys() == oracle.keys()
                assert all(spent[c] == pytest.approx(oracle[c][2], rel=1e-12) for c in oracle)
            for level in (8, 6):
                groups = pixels.groupby(pixels["cell"].str[: level + 1])["v"]
                got = {r["cell"]: (r["count"], r["sum"]) for r in land.aggregate(level, value, ("count", "sum"))}
                assert got.keys() == set(groups.groups)
                for cell, g in groups:
                    assert got[cell][0] == len(g) and got[cell][1] == pytest.approx(math.fsum(g), rel=1e-12)

    # exported each on its own
    with CellStore(db, readonly=True) as points, CellStore(db, dataset="land", readonly=True) as land:
        assert points.export(tmp_path / "points.geojson", 12, "n") == len(_oracle(lat, lng, n, spend, 12))
        land.export(tmp_path / "land.geojson", 8, value)
    shops = json.loads((tmp_path / "points.geojson").read_text())["features"]
    oracle = _oracle(lat, lng, n, spend, 12)
    assert {f["properties"]["cell"]: (f["properties"]["count"], f["properties"]["sum"]) for f in shops} == {
        c: (k, s) for c, (k, s, _) in oracle.items()}
    cover = json.loads((tmp_path / "land.geojson").read_text())["features"]
    groups = pixels.groupby(pixels["cell"].str[:9])["v"]
    assert {f["properties"]["cell"]: f["properties"]["count"] for f in cover} == {c: len(g) for c, g in groups}

    # dggs info lists both, one line each
    out = CliRunner().invoke(main, ["info", str(db)])
    assert out.exit_code == 0, out.output
    lines = out.output.splitlines()
    head = lines.index(next(line for line in lines if line.startswith("datasets")))
    assert lines[head].startswith("datasets    2")
    default, named = lines[head + 1].split(), lines[head + 2].split()
    assert default[:5] == ["(default)", "level", "17", "ISEA", f"{len(lat):,}"]
    assert default[6:] == ["n", "INTEGER,", "spend", "REAL"]
    assert named[:5] == ["land", "level", "10", "ISEA", f"{len(want):,}"] 
    assert " ".join(named[6:]) == "value REAL, coverage REAL" == ", ".join(f"{c} REAL" for c in want.columns[1:])


def test_served_by_a_real_dggs_serve_each_dataset_a_collection(tmp_path):
    from tests.server.serving import serving

    db = tmp_path / "work.db"
    lat, lng, n, spend = _points(400)
    with CellStore(db) as points, CellStore(db, dataset="coarse") as coarse:
        points.ingest_points(lat, lng, 17, {"n": n})
        coarse.ingest_points(lat[:50], lng[:50], 10, {"spend": spend[:50]})

    def get(url):
        import urllib.request

        with urllib.request.urlopen(url, timeout=30) as response:
            return json.loads(response.read())

    with serving(db) as base:
        listed = get(base + "/collections")
        assert [c["id"] for c in listed["collections"]] == ["work", "coarse"] and listed["numberMatched"] == 2
        for cid, count, level in (("work", 400, 17), ("coarse", 50, 10)):
            assert get(f"{base}/collections/{cid}")["description"].startswith(f"{count} points binned into level-{level}")
            zones = get(f"{base}/collections/{cid}/dggs/DGGS-Split26-ISEA/zones?zone-level=2&compact-zones=false")
            want = sorted({c[:3] for c in dggs.latlng_to_cell(lat[:count], lng[:count], 17)})
            assert sorted(zones["zones"]) == want
            items = get(f"{base}/collections/{cid}/items?zone-level=1")
            want1 = pd.Series([c[:2] for c in dggs.latlng_to_cell(lat[:count], lng[:count], 17)]).value_counts()
            assert {f["properties"]["zoneID"]: f["properties"]["count"] for f in items["features"]} == want1.to_dict()
            layers = get(f"{base}/map/layers?collection={cid}")
            assert layers["collection"] == cid and layers["stored_level"] == level
            assert layers["collections"] == ["work", "coarse"]
        assert get(base + "/map/layers")["collection"] == "work"  # today's URLs: the default dataset
        import urllib.error

        with pytest.raises(urllib.error.HTTPError) as missing:
            get(base + "/collections/nope")
        assert missing.value.code == 404


# -- names, errors, nothing half made ------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["a/b", "", "1x", "x y", "x" * 65, 5, "räin", 'q"'])
def test_a_bad_dataset_name_is_a_typed_error_naming_it(tmp_path, name):
    with pytest.raises(DatasetError, match="dataset name") as caught:
        CellStore(tmp_path / "s.db", dataset=name)
    assert isinstance(caught.value, DggsValueError) and repr(name) in str(caught.value)
    assert not (tmp_path / "s.db").exists()


def test_a_missing_dataset_read_only_is_a_typed_error_naming_it(tmp_path):
    db = tmp_path / "s.db"
    with CellStore(db, dataset="land") as land:
        land.ingest_points([1.0], [2.0], 5)
    for kwargs in ({"readonly": True}, {"create": False}):
        with pytest.raises(DatasetError, match="no dataset 'sea'.*land"):
            CellStore(db, dataset="sea", **kwargs)
    with CellStore(db, dataset="LAND") as again:  # names ignore case, as SQLite's table names do
        assert again.dataset == "land" and again.count() == 1


def test_a_failed_first_ingest_leaves_no_half_made_dataset(tmp_path):
    db = tmp_path / "s.db"
    with CellStore(db) as store:
        store.ingest_points([1.0], [2.0], 5)
    before = _tables(db)
    with pytest.raises(BadRowError, match="91.0"), CellStore(db, dataset="new") as new:
        new.ingest_points([1.0, 91.0], [2.0, 0.0], 5)
    assert _tables(db) == before and [d["name"] for d in list_datasets(db)] == [None]
    assert _rows(db, None) and len(_rows(db, None)) == 1
    with pytest.raises(BadRowError), CellStore(tmp_path / "new.db", dataset="new") as new:  # a new file too
        new.ingest_points([91.0], [2.0], 5)
    assert not (tmp_path / "new.db").exists()


def test_the_cli_bins_exports_and_refuses_per_dataset(tmp_path):
    csv = tmp_path / "p.csv"
    csv.write_text("lat,lng,pop\n48.85,2.35,10\n51.5,-0.12,20\n40.7,-74.0,30\n")
    db = tmp_path / "c.db"
    runner = CliRunner()
    assert runner.invoke(main, ["bin", str(csv), "--db", str(db), "--level", "7", "--value", "pop"]).exit_code == 0
    out = runner.invoke(main, ["bin", str(csv), "--db", str(db), "--level", "3", "--value", "pop", "--dataset", "coarse"])
    assert out.exit_code == 0 and "dataset coarse" in out.output and "(level 3" in out.output
    out = runner.invoke(main, ["export", str(db), "--level", "2", "--dataset", "coarse", "--column", "pop",
                               "-o", str(tmp_path / "c.geojson")])
    assert out.exit_code == 0, out.output
    cells = {f["properties"]["cell"] for f in json.loads((tmp_path / "c.geojson").read_text())["features"]}
    assert cells == {c[:3] for c in dggs.latlng_to_cell([48.85, 51.5, 40.7], [2.35, -0.12, -74.0], 7)}
    info = runner.invoke(main, ["info", str(db), "--dataset", "coarse"])
    assert info.exit_code == 0 and "dataset     coarse" in info.output and "level       3" in info.output
    for args in (["info", str(db), "--dataset", "nope"], ["query", str(db), "--level", "1", "--dataset", "a/b"],
                 ["bin", str(csv), "--db", str(db), "--level", "3", "--dataset", "bad name"]):
        out = runner.invoke(main, args)
        assert out.exit_code == 1 and len(out.output.strip().splitlines()) == 1, out.output
        assert "nope" in out.output or "a/b" in out.output or "bad name" in out.output
    assert [d["name"] for d in list_datasets(db)] == [None, "coarse"]


def test_scoped_renames_bare_table_names_only():
    sql = ("SELECT p.points, 'points', \"points\", q.meta FROM points AS p JOIN all_points ON points.cell = 1 "
           "-- points\nWHERE x IN (SELECT * FROM points_pending) /* meta */")
    assert scoped(sql, "land") == (
        "SELECT p.points, 'points', \"points\", q.meta FROM \"land/points\" AS p JOIN \"land/all_points\" "
        "ON \"land/points\".cell = 1 -- points\nWHERE x IN (SELECT * FROM \"land/points_pending\") /* meta */")
    assert scoped(sql, None) is sql


# -- the invariant: ingesting into one dataset never changes another's rows ----------------------------------------

_COORDS = st.tuples(st.floats(-90, 90), st.floats(-180, 180))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(target=st.sampled_from([None, "a", "b"]), level=st.integers(0, 18),
       points=st.lists(_COORDS, min_size=1, max_size=20))
@example(target="a", level=18, points=[(90.0, 0.0), (-90.0, 180.0), (0.0, -180.0), (0.0, 180.0)])  # poles, 180
@example(target=None, level=0, points=[(58.2825256, -180.0 + 11.25), (31.7174744, 36.0)])  # near vertices
def test_ingesting_into_one_dataset_never_changes_anothers_rows(target, level, points):
    with tempfile.TemporaryDirectory() as folder:
        db = Path(folder) / "s.db"
        with CellStore(db) as default, CellStore(db, dataset="a") as a, CellStore(db, dataset="b") as b:
            default.ingest_points([10.0, 20.0], [30.0, 40.0], 12, {"v": [1, 2]})
            a.ingest_points([-10.0], [-30.0], 5, {"w": ["x"]})
            b.keep_rollups([0])
        before = {name: _rows(db, name) for name in (None, "a", "b")}
        lat, lng = zip(*points, strict=True)
        store = CellStore(db, dataset=target)
        try:
            if store.level is not None and store.level != level:
                with pytest.raises(dggs.LevelMismatchError):
                    store.ingest_points(list(lat), list(lng), level)
            else:
                store.ingest_points(list(lat), list(lng), level, {"k": list(range(len(lat)))})
                assert store.count() == len(_rows(db, target)) == len(before[target]) + len(points)
        finally:
            store.close()
        for name in (None, "a", "b"):
            if name != target:
                assert _rows(db, name) == before[name]


_WRITER = """
import sys
from dggs.storage import CellStore
with CellStore(sys.argv[1], dataset="b", merge_rows=5_000) as store:
    store.ingest_csv(sys.argv[2], values=["k"], level=10, batch_size=500, progress=lambda n: print("batch", flush=True))
"""


def test_sigkill_during_an_ingest_into_one_dataset_leaves_the_others_whole_and_it_resumes_once(tmp_path):
    import os
    import signal
    import subprocess
    import sys

    rng = np.random.default_rng(5)
    n = 30_000
    lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, n))), rng.uniform(-180, 180, n)
    csv = tmp_path / "p.csv"
    pd.DataFrame({"lat": lat, "lng": lng, "k": np.arange(n)}).to_csv(csv, index=False)
    db = tmp_path / "s.db"
    with CellStore(db) as default, CellStore(db, dataset="a") as a:
        default.ingest_points(lat[:500], lng[:500], 12, {"v": np.arange(500)})
        a.ingest_points(lat[:50], lng[:50], 4)
    before = {name: _rows(db, name) for name in (None, "a")}
    script = tmp_path / "writer.py"
    script.write_text(_WRITER)
    proc = subprocess.Popen([sys.executable, str(script), str(db), str(csv)], stdout=subprocess.PIPE, text=True)
    try:
        for _ in range(8):  # eight batches committed, then killed wherever it is
            assert proc.stdout is not None and proc.stdout.readline()
        os.kill(proc.pid, signal.SIGKILL)
    finally:
        proc.wait(30)
    with sqlite3.connect(db) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        done = conn.execute('SELECT rows_done FROM "b/sources"').fetchone()[0]
    assert 0 < done < n and done % 500 == 0 and len(_rows(db, "b")) == done
    assert {name: _rows(db, name) for name in (None, "a")} == before
    with CellStore(db, dataset="b") as b:
        b.ingest_csv(csv, values=["k"], level=10, batch_size=500)
        stored = sorted(k for (k,) in b.conn.execute("SELECT k FROM all_points"))
    assert stored == list(range(n))  # every row exactly once
    assert {name: _rows(db, name) for name in (None, "a")} == before


def test_a_dataset_named_as_the_file_is_served_apart(tmp_path):
    from fastapi.testclient import TestClient

    from dggs.server.app import create_app

    db = tmp_path / "land.db"
    with CellStore(db) as default, CellStore(db, dataset="land") as land:
        default.ingest_points([1.0], [2.0], 6)
        land.ingest_points([3.0, 4.0], [5.0, 6.0], 3)
    with TestClient(create_app(db)) as client:
        assert [c["id"] for c in client.get("/collections").json()["collections"]] == ["land", "land-dataset"]
        assert client.get("/map/layers", params={"collection": "land-dataset"}).json()["count"] == 2
        assert client.get("/map/layers", params={"collection": "land"}).json()["count"] == 1


def test_bin_raster_into_a_dataset_and_a_failed_one_taken_back(tmp_path):
    pytest.importorskip("rasterio")
    from dggs.raster import raster_to_cells
    from tests.raster.helpers import field, same_rows, write

    good = write(tmp_path / "good.tif", field(30, 40))
    data = field(30, 40)
    data[0, 25, 30] = np.inf  # a pixel of a late block: the earlier blocks' partials are committed first
    bad = write(tmp_path / "bad.tif", data)
    db = tmp_path / "s.db"
    with CellStore(db) as store:
        store.ingest_points([1.0], [2.0], 12)
    before = _tables(db)
    out = CliRunner().invoke(main, ["bin-raster", str(bad), "--level", "10", "--db", str(db), "--dataset", "r",
                                    "--block-size", "16"])
    assert out.exit_code == 1 and len(out.output.strip().splitlines()) == 1, out.output
    assert _tables(db) == before and [d["name"] for d in list_datasets(db)] == [None]
    out = CliRunner().invoke(main, ["bin-raster", str(good), "--level", "10", "--db", str(db), "--dataset", "r",
                                    "--block-size", "16"])
    assert out.exit_code == 0 and "dataset r (level 10)" in out.output, out.output
    with CellStore(db, dataset="r", readonly=True) as r:
        assert same_rows(r.conn, raster_to_cells(good, 10, block_size=16))
    assert len(_rows(db, None)) == 1


DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


@pytest.mark.parametrize("kind", ["csv", "geojson", "dataframe", "records", "vector"])
def test_every_ingest_into_a_dataset_stores_what_it_stores_in_a_store_of_its_own(tmp_path, kind):
    """The referee: the same input ingested into the default dataset of a new store (the code path of a store
    without datasets); row for row the same, and the other datasets of the shared store untouched."""
    cities = pd.read_csv(DATA / "cities.csv")
    if kind == "vector":
        gpd = pytest.importorskip("geopandas")
        pytest.importorskip("pyogrio")
        gpkg = tmp_path / "cities.gpkg"
        gpd.GeoDataFrame(cities, geometry=gpd.points_from_xy(cities.lng, cities.lat), crs="EPSG:4326").to_file(gpkg)

    def ingest(store):
        if kind == "csv":
            return store.ingest_csv(DATA / "cities.csv", values=["name", "population"], level=8)
        if kind == "geojson":
            return store.ingest_geojson(DATA / "stations.geojson", level=8)
        if kind == "dataframe":
            return store.ingest_dataframe(cities, values=["name", "population"], level=8, source="cities")
        if kind == "records":
            return store.ingest_records(cities.to_dict("records"), values=["name", "population"], level=8,
                                        source="cities")
        return store.ingest_vector(gpkg, values=["name", "population"], level=8)

    alone, shared = tmp_path / "alone.db", tmp_path / "shared.db"
    with CellStore(alone) as store:
        ingest(store)
    with CellStore(shared) as default, CellStore(shared, dataset="other") as other:
        default.ingest_points([1.0, 2.0], [3.0, 4.0], 15, {"q": [1.5, 2.5]})
        other.ingest_points([5.0], [6.0], 2)
    before = {name: _rows(shared, name) for name in (None, "other")}
    with CellStore(shared, dataset="x") as x:
        ingest(x)
        assert x.count() > 0 and x.level == 8
    assert _rows(shared, "x") == _rows(alone, None)
    assert {name: _rows(shared, name) for name in (None, "other")} == before
