"""Ingest from CSV, GeoJSON, dicts, arrays and DataFrames; bad rows; resume; CRS."""

from __future__ import annotations

import csv
import json
import math
import warnings

import numpy as np
import pytest

import dggs
from dggs.storage import BadRowError, CellStore, RejectedRowsWarning

from .helpers import clustered_points, write_csv


def _rows_by_number(store):
    return {r["row"]: r for r in store.db.query("SELECT * FROM all_points")}


def test_csv_types_nulls_and_values(store, tmp_path):
    path = write_csv(
        tmp_path / "a.csv",
        ["name", "lat", "lng", "pop", "temp"],
        [["Paris", "48.85", "2.35", "2100000", "11.5"], ["Nowhere", "10", "20", "", ""], ["Oslo", "59.9", "10.75", "700000", "5"]],
    )
    result = store.ingest_csv(path, values=["name", "pop", "temp"], level=6)
    assert (result.rows_read, result.rows_inserted, result.rows_rejected) == (3, 3, 0)
    assert store.columns == {"name": "TEXT", "pop": "INTEGER", "temp": "REAL"}
    rows = _rows_by_number(store)
    assert rows[1]["name"] == "Paris" and rows[1]["pop"] == 2100000 and rows[1]["temp"] == 11.5
    assert rows[2]["pop"] is None and rows[2]["temp"] is None
    assert rows[1]["cell"] == dggs.latlng_to_cell(48.85, 2.35, 6)
    assert store.level == 6 and store.meta["crs"] == "EPSG:4326"


def test_csv_declared_types_and_delimiter(store, tmp_path):
    path = tmp_path / "a.tsv"
    path.write_text("y\tx\tcode\n1.5\t2.5\t007\n")
    store.ingest_csv(path, lat="y", lng="x", values={"code": str}, level=4, delimiter="\t")
    assert store.descendants(dggs.latlng_to_cell(1.5, 2.5, 0))[0]["code"] == "007"


def test_csv_quoted_multiline_fields_keep_line_numbers(store, tmp_path):
    path = tmp_path / "q.csv"
    path.write_text('lat,lng,note\n1,2,"a, b"\n3,4,"two\nlines"\n5,6,plain\n7,x,bad\n')
    with pytest.raises(BadRowError) as info:
        store.ingest_csv(path, values=["note"], level=5)
    err = info.value
    assert (err.line, err.row, err.column, err.value) == (6, 4, "lng", "x")
    assert "line 6" in str(err) and "'lng'" in str(err) and "'x'" in str(err)
    with pytest.warns(RejectedRowsWarning, match="line 6"):
        store.ingest_csv(path, values=["note"], level=5, on_error="skip", replace=True)
    notes = {r["row"]: r["note"] for r in store.db.query("SELECT row, note FROM all_points")}
    assert notes == {1: "a, b", 2: "two\nlines", 3: "plain"}


def test_fast_numeric_path_equals_csv_module(store, tmp_path, rng):
    # Several batches: the first goes through the csv module, later ones through numpy.
    n = 2_500
    lat, lng = clustered_points(rng, n)
    rows = [[f"{a:.6f}", f"{b:.6f}", str(int(c)), f"{d:.3f}"] for a, b, c, d in
            zip(lat, lng, rng.integers(0, 100, n), rng.normal(0, 1, n), strict=True)]
    rows[1_234][3] = "oops"  # a bad value deep in a numpy-parsed batch
    rows[2_001][0] = ""  # a missing latitude
    path = write_csv(tmp_path / "n.csv", ["lat", "lng", "n", "x"], rows)
    with pytest.warns(RejectedRowsWarning, match="skipped 2 bad row"):
        result = store.ingest_csv(path, values=["n", "x"], level=9, batch_size=300, on_error="skip")
    assert result.rows_inserted == n - 2
    rejects = store.rejects()
    assert [(r["row"], r["line"], r["column"], r["value"]) for r in rejects] == [
        (1_235, 1_236, "x", "oops"), (2_002, 2_003, "lat", "")]
    assert rejects[0]["record"] == {"lat": rows[1_234][0], "lng": rows[1_234][1], "n": rows[1_234][2], "x": "oops"}
    # brute force: parse the file with the csv module
    stored = _rows_by_number(store)
    with open(path, newline="") as fh:
        for i, rec in enumerate(csv.DictReader(fh), start=1):
            if i in (1_235, 2_002):
                assert i not in stored
                continue
            got = stored[i]
            assert got["lat"] == float(rec["lat"]) and got["lng"] == float(rec["lng"])
            assert got["n"] == int(rec["n"]) and got["x"] == float(rec["x"])
            assert got["cell"] == dggs.latlng_to_cell(float(rec["lat"]), float(rec["lng"]), 9)


@pytest.mark.parametrize(
    "lat, lng, value, column, reason",
    [
        ("91", "0", "1", "lat", "out of range"),
        ("nan", "0", "1", "lat", "not finite"),
        ("0", "181", "1", "lng", "out of range"),
        ("0", "inf", "1", "lng", "not finite"),
        ("abc", "0", "1", "lat", "not a number"),
        ("0", "0", "1.5e", "v", "not a number"),
        ("0", "0", "inf", "v", "not finite"),
    ],
)
def test_bad_rows_fail_with_line_column_and_value(store, tmp_path, lat, lng, value, column, reason):
    good = [["1", "1", "1"]] * 25
    path = write_csv(tmp_path / "b.csv", ["lat", "lng", "v"], good + [[lat, lng, value]] + good)
    with pytest.raises(BadRowError, match=reason) as info:
        store.ingest_csv(path, values={"v": float}, level=4, batch_size=10)
    assert (info.value.line, info.value.column) == (27, column)
    assert isinstance(info.value, ValueError) and isinstance(info.value, dggs.StorageError)
    # the two whole batches before the bad one are kept
    assert store.count() == 20
    assert store.sources()[0]["rows_done"] == 20 and not store.sources()[0]["complete"]
    # skipping resumes after them and stores the rest, recording the bad row
    with pytest.warns(RejectedRowsWarning):
        result = store.ingest_csv(path, values={"v": float}, level=4, batch_size=10, on_error="skip")
    assert result.rows_resumed == 20 and result.rows_rejected == 1
    assert store.count() == 50
    assert [(r["line"], r["column"]) for r in store.rejects()] == [(27, column)]


def test_short_and_blank_rows(store, tmp_path):
    path = tmp_path / "s.csv"
    path.write_text("lat,lng,v\n1,2,3\n\n4\n5,6,7\n")
    with pytest.warns(RejectedRowsWarning):
        result = store.ingest_csv(path, values=["v"], level=3, on_error="skip")
    assert result.rows_inserted == 2 and result.rows_rejected == 1
    assert "fields" in store.rejects()[0]["reason"] and store.rejects()[0]["line"] == 4


def test_missing_column_names_the_header(store, tmp_path):
    path = write_csv(tmp_path / "m.csv", ["y", "x"], [["1", "2"]])
    with pytest.raises(dggs.DggsValueError, match="no column.*'lat'.*header is 'y', 'x'"):
        store.ingest_csv(path, level=3)


@pytest.mark.parametrize("name", ["cell", "lat", "2x", "a b", 'x"; DROP TABLE points; --', ""])
def test_bad_value_column_names(store, name):
    with pytest.raises(dggs.DggsValueError):
        store.ingest_points([1.0], [2.0], 3, {name: [1]})


def test_level_errors(store):
    with pytest.raises(dggs.LevelError):
        store.ingest_points([1.0], [2.0], 99)
    store.ingest_points([1.0], [2.0], 5)
    with pytest.raises(dggs.LevelMismatchError, match="level 5"):
        store.ingest_points([1.0], [2.0], 6)
    store.ingest_points([1.0], [2.0])  # default: the store's level
    assert store.count() == 2


def test_records_resume_exactly_once(store):
    records = [{"lat": float(i % 80), "lng": float(i % 170), "i": i} for i in range(95)]

    def crashing():
        for n, r in enumerate(records):
            if n == 47:
                raise RuntimeError("connection lost")
            yield r

    with pytest.raises(RuntimeError, match="connection lost"):
        store.ingest_records(crashing(), values=["i"], level=4, batch_size=10, source="feed")
    assert store.count() == 40  # four whole batches
    result = store.ingest_records(records, values=["i"], level=4, batch_size=10, source="feed")
    assert result.rows_resumed == 40 and result.rows_read == 55
    got = sorted(r["i"] for r in store.db.query("SELECT i FROM all_points"))
    assert got == list(range(95))
    again = store.ingest_records(records, values=["i"], level=4, source="feed")
    assert again.already_complete and store.count() == 95
    # other settings for the same source are refused, replace starts afresh
    with pytest.raises(dggs.StorageError, match="other settings"):
        store.ingest_records(records, values=[], level=4, source="feed")
    store.ingest_records(records[:5], values=["i"], level=4, source="feed", replace=True)
    assert store.count() == 5


def test_csv_resume_after_interrupt_and_rerun_is_noop(db_path, tmp_path, rng):
    lat, lng = clustered_points(rng, 1_000)
    rows = [[a, b, i] for i, (a, b) in enumerate(zip(lat, lng, strict=True))]
    path = write_csv(tmp_path / "p.csv", ["lat", "lng", "k"], rows)
    seen = []

    def interrupt(n):
        seen.append(n)
        if len(seen) == 3:
            raise KeyboardInterrupt

    with CellStore(db_path) as store, pytest.raises(KeyboardInterrupt):
        store.ingest_csv(path, values=["k"], level=8, batch_size=100, progress=interrupt)
    with CellStore(db_path) as store:
        assert store.count() == 300
        result = store.ingest_csv(path, values=["k"], level=8, batch_size=64)  # batch size may change
        assert result.rows_resumed == 300 and result.rows_read == 700
        ks = [r["k"] for r in store.db.query("SELECT k FROM all_points ORDER BY k")]
        assert ks == list(range(1_000))
        assert store.ingest_csv(path, values=["k"], level=8).already_complete
        copy = tmp_path / "copy.csv"
        copy.write_bytes(path.read_bytes())
        assert store.ingest_csv(copy, values=["k"], level=8).already_complete  # same content
        assert store.count() == 1_000


def test_points_arrays_dtypes_and_length_check(store):
    store.ingest_points(np.array([1.0, 2.0]), np.array([3.0, 4.0]), 5,
                        {"i": np.array([1, 2]), "f": np.array([0.5, np.nan]), "s": np.array(["a", "b"]),
                         "b": np.array([True, False])})
    assert store.columns == {"i": "INTEGER", "f": "REAL", "s": "TEXT", "b": "INTEGER"}
    rows = _rows_by_number(store)
    assert rows[2]["f"] is None and rows[1]["b"] == 1
    with pytest.raises(dggs.DggsValueError, match="has 1 values"):
        store.ingest_points([1.0, 2.0], [3.0], 5)


def test_dataframe(store):
    pd = pytest.importorskip("pandas")
    df = pd.DataFrame({"lat": [10.0, 20.0, None], "lng": [5.0, 6.0, 7.0], "v": [1, 2, 3], "name": ["a", None, "c"]})
    with pytest.warns(RejectedRowsWarning):
        result = store.ingest(df, level=4, on_error="skip")
    assert result.rows_inserted == 2 and store.rejects()[0]["column"] == "lat"
    assert store.columns == {"v": "INTEGER", "name": "TEXT"}
    assert _rows_by_number(store)[2]["name"] is None


def test_pandas_na_is_a_missing_value_and_nullable_columns_keep_their_type(store):
    """pd.NA is NULL (as NaN is); an Int64 column stays exact INTEGER, not float64 with NaN; <NA> coordinates are named."""
    pd = pytest.importorskip("pandas")
    big = 2**53 + 1  # a float64 would round it to 2**53
    df = pd.DataFrame({"lat": [10.0, 20.0, 30.0], "lng": [5.0, 6.0, 7.0],
                       "v": pd.array([pd.NA, big, 3], dtype="Int64"), "s": pd.array(["a", pd.NA, "c"], dtype="string"),
                       "f": pd.array([0.5, pd.NA, 1.0], dtype="Float64"), "b": pd.array([True, pd.NA, False], dtype="boolean")})
    store.ingest_dataframe(df, level=4, batch_size=1)  # the first batch holds only <NA> for v: its dtype tells
    assert store.columns == {"v": "INTEGER", "s": "TEXT", "f": "REAL", "b": "INTEGER"}
    rows = _rows_by_number(store)
    assert [(rows[i]["v"], rows[i]["s"], rows[i]["f"], rows[i]["b"]) for i in (1, 2, 3)] == [
        (None, "a", 0.5, 1), (big, None, None, None), (3, "c", 1.0, 0)]
    store.ingest_points([1.0], [2.0], 4, {"v": pd.array([pd.NA], dtype="Int64")}, source="p")
    store.ingest_records([{"lat": 1.0, "lng": 2.0, "s": pd.NA}], values=["s"], source="r")
    assert [r["s"] for r in store.db.query("SELECT s FROM all_points WHERE row = 1 AND s IS NOT 'a'")] == [None, None]
    bad = pd.DataFrame({"lat": pd.array([10.0, pd.NA], dtype="Float64"), "lng": [5.0, 6.0]})
    with pytest.raises(BadRowError, match=r"row 2: column 'lat': <NA> is missing"):
        store.ingest_dataframe(bad, source="bad")


def test_crs_conversion(store):
    from pyproj import Transformer

    to_merc = Transformer.from_crs("EPSG:4326", "EPSG:3857", always_xy=True)
    lng = np.array([-0.1276, 139.69, -74.006])
    lat = np.array([51.5072, 35.6895, 40.7128])
    x, y = to_merc.transform(lng, lat)
    store.ingest_points(y, x, 10, crs="EPSG:3857")
    rows = sorted(store.db.query("SELECT lat, lng, cell, row FROM all_points"), key=lambda r: r["row"])
    np.testing.assert_allclose([r["lat"] for r in rows], lat, atol=1e-9)
    np.testing.assert_allclose([r["lng"] for r in rows], lng, atol=1e-9)
    assert [r["cell"] for r in rows] == dggs.latlng_to_cell(lat, lng, 10).tolist()
    assert store.sources()[0]["crs"] == "EPSG:3857"
    with pytest.raises(dggs.DggsValueError, match="unknown CRS"):
        store.ingest_points([1.0], [2.0], 10, crs="EPSG:999999")


def test_geojson_points_multipoints_and_polygons(store, tmp_path):
    square = [[10.0, 10.0], [14.0, 10.0], [14.0, 14.0], [10.0, 14.0], [10.0, 10.0]]
    fc = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "Point", "coordinates": [2.35, 48.85]}, "properties": {"name": "Paris", "n": 1}},
        {"type": "Feature", "geometry": {"type": "MultiPoint", "coordinates": [[0.0, 0.0], [0.0, 0.0001]]}, "properties": {"name": "twins", "n": 2}},
        {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [square]}, "properties": {"name": "square", "n": 3}},
        {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}, "properties": {"name": "line", "n": 4}},
        {"type": "Feature", "geometry": None, "properties": {"name": "nothing", "n": 5}},
    ]}
    path = tmp_path / "f.geojson"
    path.write_text(json.dumps(fc))
    with pytest.raises(BadRowError, match="row 4"):
        store.ingest_geojson(path, level=5)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = store.ingest_geojson(path, level=5, on_error="skip")
    assert any(issubclass(w.category, RejectedRowsWarning) for w in caught)
    from shapely.geometry import Polygon

    cells = dggs.polygon_to_cells(Polygon(square), 5)
    assert result.rows_inserted == 1 + 2 + len(cells) and result.rows_rejected == 2
    square_rows = [r for r in store.db.query("SELECT cell, name FROM all_points") if r["name"] == "square"]
    assert sorted(r["cell"] for r in square_rows) == sorted(cells.tolist())
    assert store.columns == {"name": "TEXT", "n": "INTEGER"}


def test_not_geojson(store, tmp_path):
    path = tmp_path / "x.json"
    path.write_text("[1, 2]")
    with pytest.raises(dggs.DggsValueError, match="not GeoJSON"):
        store.ingest(path)
    path.write_text("{nope")
    with pytest.raises(dggs.DggsValueError, match="not valid JSON"):
        store.ingest(path)


def test_on_error_must_be_known(store):
    with pytest.raises(dggs.DggsValueError, match="on_error"):
        store.ingest_points([1.0], [2.0], 3, on_error="ignore")


# -- property: any CSV, either path, agrees with a brute-force parse ----------

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_numbers = st.one_of(
    st.floats(-200, 200, allow_nan=False).map(lambda x: repr(round(x, 5))),
    st.integers(-200, 200).map(str),
)
_cells = st.one_of(_numbers, st.sampled_from(["", "nan", "inf", "-inf", "abc", "1e400", " 7 "]))


def _brute(lat: str, lng: str, v: str):
    """(stored lat, lng, v) or the bad column, by the documented rules."""
    def num(s):
        try:
            return float(s)
        except ValueError:
            return None

    a, b = num(lat), num(lng)
    if a is None or not math.isfinite(a) or abs(a) > 90:
        return "lat"
    if b is None or not math.isfinite(b) or abs(b) > 180:
        return "lng"
    if v.strip() == "":
        return (a, b, None)
    x = num(v)
    if x is None or math.isinf(x):
        return "v"
    return (a, b, None if math.isnan(x) else x)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(_cells, _cells, _cells), min_size=0, max_size=40), st.integers(1, 9))
def test_any_csv_matches_brute_force(tmp_path_factory, rows, batch_size):
    path = write_csv(tmp_path_factory.mktemp("h") / "h.csv", ["lat", "lng", "v"], [list(r) for r in rows])
    with CellStore(":memory:") as store, warnings.catch_warnings():
        warnings.simplefilter("ignore", RejectedRowsWarning)
        result = store.ingest_csv(path, values={"v": float}, level=6, batch_size=batch_size, on_error="skip")
        stored = {r["row"]: r for r in store.db.query("SELECT * FROM all_points")}
        rejected = {r["row"]: r["column"] for r in store.rejects()}
    assert result.rows_read == len(rows)
    assert len(stored) + len(rejected) == len(rows)
    for i, (lat, lng, v) in enumerate(rows, start=1):
        want = _brute(lat, lng, v)
        if isinstance(want, str):
            assert rejected.get(i) == want, (i, lat, lng, v)
        else:
            got = stored[i]
            assert (got["lat"], got["lng"], got["v"]) == want, (i, lat, lng, v)
            assert got["cell"] == dggs.latlng_to_cell(want[0], want[1], 6)


def test_records_from_a_sqlite_cursor_of_this_thread(store):
    import sqlite3

    con = sqlite3.connect(":memory:")
    con.row_factory = sqlite3.Row
    con.execute("CREATE TABLE t (lat REAL, lng REAL, v INTEGER)")
    con.executemany("INSERT INTO t VALUES (?, ?, ?)", [(i / 10, i / 5, i) for i in range(50)])
    result = store.ingest_records(con.execute("SELECT * FROM t"), values=["v"], level=5, batch_size=7)
    assert result.rows_inserted == 50


def test_encodings(store, tmp_path):
    path = tmp_path / "latin.csv"
    path.write_bytes("lat,lng,name\n1,2,S\u00e3o Paulo\n".encode("latin-1"))
    with pytest.raises(dggs.DggsValueError, match="not utf-8 text.*encoding="):
        store.ingest_csv(path, values=["name"], level=3)
    store.ingest_csv(path, values=["name"], level=3, encoding="latin-1")
    assert store.descendants(dggs.latlng_to_cell(1, 2, 0))[0]["name"] == "S\u00e3o Paulo"
    bom = tmp_path / "bom.csv"
    bom.write_bytes(b"\xef\xbb\xbflat,lng\n3,4\n")
    assert store.ingest_csv(bom, level=3).rows_inserted == 1
