"""The readers built on pyarrow (CSV) and pyogrio (GeoPackage, Shapefile, FlatGeobuf, GeoParquet)."""

from __future__ import annotations

import warnings

import pytest
from click.testing import CliRunner

import dggs
from dggs.cli import main
from dggs.storage import BadRowError, CellStore, RejectedRowsWarning
from dggs.storage.readers_csv import csv_batches

from .helpers import write_csv

BIG = 2**53 + 1


# -- CSV through pyarrow ---------------------------------------------------------------


def test_batches_are_exact_record_counts_across_arrow_blocks(tmp_path, monkeypatch):
    from dggs.storage import readers_csv

    monkeypatch.setattr(readers_csv, "BLOCK_SIZE", 64)  # many small arrow blocks
    rows = [[i % 80, i % 170, i] for i in range(101)]
    path = write_csv(tmp_path / "b.csv", ["lat", "lng", "k"], rows)
    batches = list(csv_batches(path, "lat", "lng", ["k"], 10))
    assert [b.consumed for b in batches] == [10] * 10 + [1]
    assert [list(b.rows)[0] for b in batches] == list(range(1, 102, 10))
    assert list(batches[3].lines) == list(range(32, 42))  # line = row + 1 (the header)
    resumed = list(csv_batches(path, "lat", "lng", ["k"], 7, skip=95))
    assert [list(b.rows) for b in resumed] == [[96, 97, 98, 99, 100, 101]]


def test_lines_count_quoted_newlines_blank_lines_and_bad_records(tmp_path, monkeypatch):
    from dggs.storage import readers_csv

    monkeypatch.setattr(readers_csv, "BLOCK_SIZE", 32)
    path = tmp_path / "l.csv"
    path.write_text('lat,lng,s\n1,1,"a\nb\nc"\n\n2,2,x\n,,\n3\n4,4,y,extra\n5,5,"q"\n')
    batches = list(csv_batches(path, "lat", "lng", ["s"], 3))
    rows = [r for b in batches for r in b.rows]
    lines = [n for b in batches for n in b.lines]
    # record 2 is the blank line (consumed, no entry); ",," is an entry (a bad one later)
    assert rows == [1, 3, 4, 5, 6, 7] and lines == [2, 6, 7, 8, 9, 10]
    assert sum(b.consumed for b in batches) == 7
    short = [b.bad for b in batches if b.bad]
    assert any("has 1 fields" in reason for bad in short for _, _, reason in bad.values())
    with CellStore() as store, warnings.catch_warnings():
        warnings.simplefilter("ignore", RejectedRowsWarning)
        result = store.ingest_csv(path, values={"s": str}, level=3, on_error="skip")
        assert (result.rows_inserted, result.rows_rejected) == (4, 2)
        assert sorted(r["line"] for r in store.rejects()) == [7, 8]
        got = [r[0] for r in store.conn.execute("SELECT s FROM all_points ORDER BY row")]
        assert got == ["a\nb\nc", "x", "y", "q"]  # too many fields: the leading ones are kept


def test_numbers_are_exact_and_bad_values_name_line_and_column(tmp_path):
    good = [[1, 1, 5, 0.5]] * 30
    path = write_csv(tmp_path / "n.csv", ["lat", "lng", "n", "x"], good + [[1, 1, BIG, 2.5], [1, 1, 7, "oops"]])
    with CellStore() as store:
        with pytest.raises(BadRowError) as info:
            store.ingest_csv(path, values=["n", "x"], level=4, batch_size=8)
        assert (info.value.line, info.value.column, info.value.value) == (33, "x", "oops")
        assert store.count() == 24  # three whole batches
        with pytest.warns(RejectedRowsWarning):
            store.ingest_csv(path, values=["n", "x"], level=4, batch_size=8, on_error="skip")
        assert store.conn.execute("SELECT n FROM all_points WHERE row = 31").fetchone()[0] == BIG


def test_other_encodings_are_transcoded_by_pyarrow(tmp_path):
    path = tmp_path / "w.csv"
    path.write_bytes("lat;lng;name\n1;2;Z\u00fcrich\n3;4;\u0141\u00f3d\u017a\n".encode("cp1250"))
    with CellStore() as store:
        store.ingest_csv(path, values=["name"], level=3, delimiter=";", encoding="cp1250")
        names = [r[0] for r in store.conn.execute("SELECT name FROM all_points ORDER BY row")]
    assert names == ["Z\u00fcrich", "\u0141\u00f3d\u017a"]


def test_bad_utf8_in_a_later_block_names_a_line(tmp_path, monkeypatch):
    from dggs.storage import readers_csv

    monkeypatch.setattr(readers_csv, "BLOCK_SIZE", 64)
    path = tmp_path / "u.csv"
    path.write_bytes(b"lat,lng,s\n" + b"1,1,a\n" * 40 + b"1,1,\xff\n")
    with CellStore() as store, pytest.raises(dggs.DggsValueError, match=r"not utf-8 text \(after line \d+: invalid UTF8"):
        store.ingest_csv(path, values=["s"], level=3)


# -- vector files through pyogrio ------------------------------------------------------------


@pytest.fixture
def frame():
    gpd = pytest.importorskip("geopandas")
    from shapely.geometry import Point, box

    return gpd.GeoDataFrame(
        {"name": ["paris", "london", "box"], "n": [BIG, 2, 3]},
        geometry=[Point(2.35, 48.85), Point(-0.12, 51.5), box(10, 10, 30, 30)],
        crs="EPSG:4326",
    )


@pytest.mark.parametrize("suffix", [".gpkg", ".fgb", ".parquet"])
def test_vector_files_points_and_polygons(tmp_path, frame, suffix):
    pytest.importorskip("pyogrio")
    path = tmp_path / f"v{suffix}"
    if suffix == ".parquet":
        frame.to_parquet(path)
    else:
        frame.to_file(path)
    with CellStore() as store:
        result = store.ingest(path, level=5, batch_size=2)
        assert result.rows_read == 3 and store.columns == {"name": "TEXT", "n": "INTEGER"}
        cell = dggs.latlng_to_cell(48.85, 2.35, 5)
        assert [(r["name"], r["n"]) for r in store.get(cell)] == [("paris", BIG)]
        polygon = store.conn.execute("SELECT count(*) FROM all_points WHERE name = 'box'").fetchone()[0]
        assert polygon == result.rows_inserted - 2 > 1
        assert store.ingest(path, level=5).already_complete


def test_shapefile_in_another_crs_and_resume(tmp_path, frame):
    pytest.importorskip("pyogrio")
    path = tmp_path / "pts.shp"
    frame.iloc[:2].to_crs("EPSG:3857").to_file(path)
    with CellStore() as store:
        seen = []

        def stop(n):
            seen.append(n)
            raise KeyboardInterrupt

        with pytest.raises(KeyboardInterrupt):
            store.ingest_vector(path, values=["name"], level=6, batch_size=1, progress=stop)
        assert store.count() == 1
        result = store.ingest_vector(path, values=["name"], level=6, batch_size=1)
        assert (result.rows_resumed, result.rows_read) == (1, 1)
        rows = {r[0]: (r[1], r[2]) for r in store.conn.execute("SELECT name, lat, lng FROM all_points")}
    assert rows["paris"] == pytest.approx((48.85, 2.35)) and rows["london"] == pytest.approx((51.5, -0.12))


def test_geopackage_layers_and_the_cli(tmp_path, frame):
    pytest.importorskip("pyogrio")
    path = tmp_path / "two.gpkg"
    frame.iloc[:1].to_file(path, layer="one")
    frame.iloc[1:2].to_file(path, layer="other")
    db = tmp_path / "v.db"
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db), "--layer", "other", "--level", "5"])
    assert result.exit_code == 0, result.output
    with CellStore(db) as store:
        assert [r["name"] for r in store.get(dggs.latlng_to_cell(51.5, -0.12, 5))] == ["london"]
        with pytest.raises(dggs.DggsValueError, match="no column.*'nope'"):
            store.ingest_vector(path, layer="one", values=["nope"])
        with pytest.raises(dggs.DggsValueError, match="layer 'missing'"):
            store.ingest_vector(path, layer="missing")
        assert len(store.sources()) == 1
