"""Issue 10, storage half: nothing lost, no wrong answer.

One test (or a few) per item; each failed before its fix.
"""

from __future__ import annotations

import json
import sqlite3
import warnings

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import dggs
from dggs.cli import main
from dggs.errors import DggsValueError, InvalidCellError, StorageError
from dggs.storage import BadRowError, CellStore, IngestOptions

from .helpers import write_csv

BIG = 2**53 + 1  # 9007199254740993: the first integer a float64 cannot hold


# -- 7. batch sizes -----------------------------------------------------------


@pytest.mark.parametrize("size", [0, -1, 2.5, True, "10"])
def test_bad_batch_size_is_refused_before_touching_the_store(tmp_path, size):
    path = write_csv(tmp_path / "p.csv", ["lat", "lng"], [[1, 1], [2, 2]])
    with CellStore(tmp_path / "s.db") as store:
        for call in (
            lambda: store.ingest_csv(path, level=5, batch_size=size),
            lambda: store.ingest_records([{"lat": 1, "lng": 1}], level=5, batch_size=size),
            lambda: store.ingest_points([1.0], [1.0], 5, batch_size=size),
        ):
            with pytest.raises(DggsValueError, match="batch_size"):
                call()
        assert store.sources() == [] and store.count() == 0
        assert store.ingest_csv(path, level=5).rows_inserted == 2  # the corrected run stores them


def test_cli_batch_size_zero_exits_non_zero_and_stores_nothing(tmp_path):
    path = write_csv(tmp_path / "p.csv", ["lat", "lng"], [[1, 1], [2, 2]])
    db = tmp_path / "x.db"
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db), "--batch-size", "0"])
    assert result.exit_code != 0 and "batch-size" in result.output
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db)])
    assert result.exit_code == 0 and "stored 2" in result.output


def test_options_object_is_frozen_and_checked():
    options = IngestOptions(batch_size=5, on_error="skip")
    with pytest.raises(AttributeError):
        options.batch_size = 0  # type: ignore[misc]
    with pytest.raises(DggsValueError, match="on_error"):
        IngestOptions(on_error="ignore")


# -- 8. an unclosed quote -------------------------------------------------------


def test_unclosed_quote_fails_naming_the_line(tmp_path):
    path = tmp_path / "q.csv"
    path.write_text('lat,lng,name\n1,1,a\n2,2,"b\n3,3,c\n4,4,d\n')
    with CellStore() as store:
        for on_error in ("fail", "skip"):
            with pytest.raises(BadRowError, match="line 3.*closing quote"):
                store.ingest_csv(path, values=["name"], level=5, on_error=on_error)
        assert store.sources()[0]["complete"] == 0
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(tmp_path / "q.db"), "--value", "name"])
    assert result.exit_code == 1 and "line 3" in result.output


def test_unclosed_quote_in_a_later_batch_and_over_the_line_limit(tmp_path, monkeypatch):
    from dggs.storage import readers

    rows = "".join(f"{i % 80},{i % 170},x{i}\n" for i in range(50))
    path = tmp_path / "q.csv"
    path.write_text("lat,lng,name\n" + rows + '1,1,"open\n' + rows)
    with CellStore() as store, pytest.raises(BadRowError, match="line 52"):
        store.ingest_csv(path, values=["name"], level=5, batch_size=7)
    monkeypatch.setattr(readers, "MAX_FIELD_LINES", 5)
    with CellStore() as store, pytest.raises(BadRowError, match="line 52.*more than 5 lines"):
        store.ingest_csv(path, values=["name"], level=5, batch_size=7)


def test_quoted_newlines_and_literal_quotes_still_parse(tmp_path):
    path = tmp_path / "ok.csv"
    path.write_text('lat,lng,name\n1,1,"two\nlines"\n2,2,5" pipe\n3,3,"say ""hi"""\n')
    with CellStore() as store:
        store.ingest_csv(path, values=["name"], level=5, batch_size=1)
        names = sorted(r[0] for r in store.conn.execute("SELECT name FROM all_points"))
    assert names == ['5" pipe', 'say "hi"', "two\nlines"]


# -- 9. integers above 2**53 -----------------------------------------------------


def test_big_integers_stay_exact_everywhere(tmp_path):
    gj = tmp_path / "p.geojson"
    gj.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 1]}, "properties": {"v": BIG}}]}))
    csv_path = write_csv(tmp_path / "p.csv", ["lat", "lng", "v"], [[1, 1, BIG], [1, 1, ""]])
    with CellStore() as store:
        store.ingest_records([{"lat": 1, "lng": 1, "v": BIG}], values=["v"], level=5)
        store.ingest_geojson(gj, level=5)
        store.ingest_points([1.0], [1.0], 5, {"v": np.array([BIG], dtype=object)})
        store.ingest_points([1.0], [1.0], 5, {"v": [BIG]}, types={"v": int})
        store.ingest_points([1.0], [1.0], 5, {"v": np.array([BIG], dtype=np.int64)})
        store.ingest_points([1.0], [1.0], 5, {"v": np.array([BIG], dtype=np.uint64)})
        store.ingest_csv(csv_path, values={"v": int}, level=5)
        store.ingest_records([{"lat": 1, "lng": 1, "v": str(BIG)}], values={"v": "INTEGER"}, level=5)
        values = [r[0] for r in store.conn.execute("SELECT v FROM all_points WHERE v IS NOT NULL")]
        assert values == [BIG] * 8
        assert store.aggregate(0, "v", ("max",))[0]["max"] == BIG


def test_integers_beyond_int64_are_refused_naming_the_value():
    with CellStore() as store:
        with pytest.raises(BadRowError, match="18446744073709551616.*64-bit"):
            store.ingest_records([{"lat": 1, "lng": 1, "v": 2**64}], values=["v"], level=5)
        with pytest.raises(BadRowError, match="64-bit"):
            store.ingest_points([1.0], [1.0], 5, {"v": np.array([2**64 - 1], dtype=np.uint64)})
        store.ingest_records([{"lat": 1, "lng": 1, "t": 2**64}], values={"t": str}, level=5)
        assert store.conn.execute("SELECT t FROM all_points").fetchone()[0] == str(2**64)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(-(2**63), 2**63 - 1), min_size=1, max_size=20))
def test_any_int64_round_trips(ints):
    with CellStore() as store:
        n = len(ints)
        store.ingest_records([{"lat": 1.0, "lng": 1.0, "v": v} for v in ints], values=["v"], level=4)
        store.ingest_points([1.0] * n, [1.0] * n, 4, {"v": np.array(ints, dtype=object)})
        got = [r[0] for r in store.conn.execute("SELECT v FROM all_points ORDER BY source_id, row")]
    assert got == ints + ints


# -- 10. ids in any container; shapes -------------------------------------------


def test_queries_accept_ids_in_any_container():
    import pandas as pd

    rng = np.random.default_rng(3)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 500)))
    lng = rng.uniform(-180, 180, 500)
    with CellStore() as store:
        store.ingest_points(lat, lng, 4)
        a = "A"
        n = store.count(a)
        assert n > 0
        for form in (np.array([a]), [a], (a,), pd.Series([a]), dggs.str_to_int(a), [dggs.str_to_int(a)],
                     np.array([dggs.str_to_int(a)], dtype=np.uint64)):
            assert store.count(form) == n, form
            assert len(store.descendants(form)) == n
            assert store.aggregate(0, cell=form)[0]["count"] == n
        both = store.count(["A", "B"])
        assert both == store.count("A") + store.count("B")
        assert store.count(["A", "A0", "A"]) == n  # each row once
        assert store.count([]) == 0 and store.descendants([]) == []
        cell = store.aggregate(4)[0]["cell"]
        assert store.get([cell]) == store.get(cell) == store.get(dggs.str_to_int(cell))
        assert store.disk(dggs.str_to_int(cell), 1) == store.disk(cell, 1)
        with pytest.raises(InvalidCellError):
            store.count(["A", "nope"])
        with pytest.raises(InvalidCellError):
            store.count([1.5])


def test_array_shape_mismatch_raises():
    with CellStore() as store:
        with pytest.raises(DggsValueError, match=r"shape \(2, 3\)"):
            store.ingest_points(np.full((2, 3), 10.0), [1.0, 2.0], 5)
        with pytest.raises(DggsValueError, match="3 values but lat has 2"):
            store.ingest_points([1.0, 2.0], [1.0, 2.0], 5, {"v": [1, 2, 3]})
        with pytest.raises(DggsValueError, match="shape"):
            store.ingest_points([1.0, 2.0], [1.0, 2.0], 5, {"v": [[1, 2], [3, 4]]})
        assert store.sources() == [] and store.count() == 0


def test_to_geojson_has_one_feature_per_cell_with_its_properties(tmp_path):
    with CellStore() as store:
        store.ingest_points([1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 6, {"v": [1, 2, 3]})
        rows = store.aggregate(2, "v")
        fc = store.to_geojson(2, "v", tmp_path / "c.geojson")
    assert len(fc["features"]) == len(rows) == 2
    for feature, row in zip(fc["features"], rows, strict=True):
        assert feature["properties"]["sum"] == row["sum"]
    assert json.loads((tmp_path / "c.geojson").read_text()) == json.loads(json.dumps(fc))


# -- 11. appended files, typos, inference -----------------------------------------


def test_appended_csv_resumes_after_the_old_rows(tmp_path):
    path = tmp_path / "grow.csv"
    rows = [[i % 80, i % 170, i] for i in range(1500)]
    write_csv(path, ["lat", "lng", "k"], rows[:1000])
    with CellStore(tmp_path / "g.db") as store:
        store.ingest_csv(path, values=["k"], level=5, batch_size=300)
        write_csv(path, ["lat", "lng", "k"], rows)  # the same 1,000 rows and 500 more
        result = store.ingest_csv(path, values=["k"], level=5, batch_size=300)
        assert (result.rows_resumed, result.rows_read) == (1000, 500)
        assert store.count() == 1500
        assert sorted(r[0] for r in store.conn.execute("SELECT k FROM all_points")) == list(range(1500))
        assert store.ingest_csv(path, values=["k"], level=5).already_complete
        assert len(store.sources()) == 1


def test_changed_csv_is_an_error_naming_the_change(tmp_path):
    path = write_csv(tmp_path / "c.csv", ["lat", "lng"], [[1, 1], [2, 2]])
    with CellStore() as store:
        store.ingest_csv(path, level=5)
        write_csv(path, ["lat", "lng"], [[3, 3], [2, 2], [5, 5]])
        with pytest.raises(StorageError, match="changed since.*bytes.*replace=True"):
            store.ingest_csv(path, level=5)
        assert store.count() == 2
        store.ingest_csv(path, level=5, replace=True)
        assert store.count() == 3 and len(store.sources()) == 1


def test_typo_in_a_column_does_not_block_the_corrected_command(tmp_path):
    path = write_csv(tmp_path / "t.csv", ["lat", "lng"], [[1, 1], [2, 2]])
    db = tmp_path / "t.db"
    runner = CliRunner()
    bad = runner.invoke(main, ["bin", str(path), "--db", str(db), "--lat", "latt"])
    assert bad.exit_code == 1 and "'latt'" in bad.output
    with CellStore(db) as store:
        assert store.sources() == []
    good = runner.invoke(main, ["bin", str(path), "--db", str(db)])
    assert good.exit_code == 0 and "stored 2" in good.output, good.output


def test_a_source_with_no_committed_rows_takes_new_settings(tmp_path):
    path = write_csv(tmp_path / "t.csv", ["lat", "lng", "v"], [[1, 1, 1], [95, 2, 2]])
    with CellStore() as store:
        with pytest.raises(BadRowError):
            store.ingest_csv(path, values=["v"], level=5)  # fails in the first batch
        with pytest.warns(UserWarning):
            result = store.ingest_csv(path, level=5, on_error="skip")  # other settings: fine
        assert result.rows_inserted == 1


def test_one_word_in_a_numeric_column_is_a_bad_row_not_a_text_column(tmp_path):
    rows = [[1, 1, i] for i in range(20)] + [[1, 1, "n/a"]] + [[1, 1, 7]]
    path = write_csv(tmp_path / "m.csv", ["lat", "lng", "v"], rows)
    with CellStore() as store:
        with pytest.raises(BadRowError, match="line 22.*'n/a'.*declare the column str"):
            store.ingest_csv(path, values=["v"], level=5)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            store.ingest_csv(path, values=["v"], level=5, on_error="skip")
        assert store.columns == {"v": "INTEGER"}
        assert store.count() == 21 and len(store.rejects()) == 1
    with CellStore() as store:  # declared, the same column is text
        store.ingest_csv(path, values={"v": str}, level=5)
        assert store.columns == {"v": "TEXT"} and store.count() == 22
    with CellStore() as store:  # all text: text
        store.ingest_records([{"lat": 1, "lng": 1, "s": "a"}, {"lat": 1, "lng": 1, "s": "b"}], values=["s"], level=5)
        assert store.columns == {"s": "TEXT"}


def test_cli_declares_value_types(tmp_path):
    path = write_csv(tmp_path / "m.csv", ["lat", "lng", "v"], [[1, 1, 1], [1, 1, "x"]])
    db = tmp_path / "m.db"
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db), "--value", "v:str"])
    assert result.exit_code == 0, result.output
    with CellStore(db, readonly=True) as store:
        assert store.columns == {"v": "TEXT"}


# -- 15. integrity_check on this machine's SQLite ------------------------------------


def test_integrity_check_passes_without_value_columns(tmp_path):
    with CellStore(tmp_path / "a.db") as store:
        store.ingest_points([1.0, 2.0], [3.0, 4.0], 5)
        store.check()
        assert store.conn.execute("PRAGMA integrity_check").fetchall() == [("ok",)]
        names = [r[1] for r in store.conn.execute("PRAGMA table_info(points)")]
    assert names[:4] == ["cell", "source_id", "row", "part"]


def test_old_layout_is_rebuilt_on_open(tmp_path):
    from dggs.storage.schema import DDL

    old = DDL.replace(
        "    source_id INTEGER NOT NULL REFERENCES sources(id),\n    row INTEGER NOT NULL,\n"
        "    part INTEGER NOT NULL DEFAULT 0,\n    lat REAL NOT NULL,\n    lng REAL NOT NULL,\n",
        "    lat REAL NOT NULL,\n    lng REAL NOT NULL,\n    source_id INTEGER NOT NULL REFERENCES sources(id),\n"
        "    row INTEGER NOT NULL,\n    part INTEGER NOT NULL DEFAULT 0,\n",
    ).replace(
        "    source_id INTEGER NOT NULL,\n    row INTEGER NOT NULL,\n    part INTEGER NOT NULL DEFAULT 0,\n"
        "    lat REAL NOT NULL,\n    lng REAL NOT NULL\n",
        "    lat REAL NOT NULL,\n    lng REAL NOT NULL,\n    source_id INTEGER NOT NULL,\n"
        "    row INTEGER NOT NULL,\n    part INTEGER NOT NULL DEFAULT 0\n",
    )
    assert old != DDL
    db = tmp_path / "old.db"
    con = sqlite3.connect(db)
    con.executescript(old)
    con.executemany("INSERT INTO meta VALUES (?, ?)", [("schema_version", "1"), ("level", "5"), ("crs", "EPSG:4326"),
                                                       ("created", "x"), ("updated", "x")])
    con.execute("INSERT INTO sources (id, key, kind, name, params, crs, started, updated, rows_done, complete) "
                "VALUES (1, 'k', 'arrays', 'a', '{}', 'EPSG:4326', 'x', 'x', 2, 1)")
    con.execute("ALTER TABLE points ADD COLUMN v INTEGER")
    con.execute("ALTER TABLE points_pending ADD COLUMN v INTEGER")
    cell = dggs.latlng_to_cell(1.0, 2.0, 5)
    con.execute("INSERT INTO points VALUES (?, 1.0, 2.0, 1, 1, 0, 7)", (cell,))
    con.execute("INSERT INTO points_pending VALUES (?, 1.0, 2.0, 1, 2, 0, 8)", (cell,))
    con.commit()
    con.close()
    with CellStore(db) as store:
        store.check()
        assert [r["v"] for r in store.get(cell)] == [7, 8]
        assert [r[1] for r in store.conn.execute("PRAGMA table_info(points)")][:4] == ["cell", "source_id", "row", "part"]


# -- the split: cheap import, thin facade ------------------------------------------


def test_import_stays_cheap():
    import subprocess
    import sys

    code = (
        "import sys, dggs.storage\n"
        "heavy = [m for m in ('pandas', 'matplotlib', 'pyproj', 'sqlite_utils', 'tqdm') if m in sys.modules]\n"
        "print(heavy)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
