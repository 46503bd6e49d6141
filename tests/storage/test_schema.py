"""Opening stores: schema, metadata, pragmas, and clear errors for broken files."""

from __future__ import annotations

import sqlite3

import pytest

import dggs
from dggs.storage import SCHEMA_VERSION, CellStore


def test_new_store_schema_and_metadata(db_path):
    with CellStore(db_path) as store:
        meta = store.meta
        assert meta["schema_version"] == "1"  # a new store: readable by a dggs that knows version 1 only
        assert SCHEMA_VERSION == 3  # what this dggs reads: 2 is a store keeping roll-ups, 3 with exact REAL sums
        assert meta["crs"] == "EPSG:4326"
        assert meta["created"] and meta["updated"] and meta["dggs_version"]
        assert store.level is None
        assert store.conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
        assert store.conn.execute("PRAGMA foreign_keys").fetchone()[0] == 1
        tables = set(store.db.table_names()) | set(store.db.view_names())
        assert {"meta", "sources", "points", "points_pending", "rejects", "all_points"} <= tables
        store.ingest_points([1.0], [2.0], 7, {"v": [1.5]})
        assert store.meta["level"] == "7"
        assert store.meta["updated"] >= meta["updated"]
    with CellStore(db_path) as again:  # reopening keeps everything
        assert again.level == 7 and again.count() == 1 and again.columns == {"v": "REAL"}


def test_points_are_clustered_on_the_cell_id(db_path):
    with CellStore(db_path) as store:
        sql = store.conn.execute("SELECT sql FROM sqlite_master WHERE name = 'points'").fetchone()[0]
        assert "WITHOUT ROWID" in sql and "PRIMARY KEY (cell, source_id, row, part)" in sql
        plan = " ".join(str(r) for r in store.conn.execute(
            "EXPLAIN QUERY PLAN SELECT * FROM points WHERE cell >= ?1 AND cell < ?1 || '~'", ("B2",)))
        assert "SEARCH points USING PRIMARY KEY (cell>? AND cell<?)" in plan


def test_foreign_keys_are_enforced(store):
    with pytest.raises(sqlite3.IntegrityError):
        store.conn.execute("INSERT INTO points (cell, lat, lng, source_id, row) VALUES ('A1', 0, 0, 999, 1)")


def test_not_a_database(tmp_path):
    path = tmp_path / "data.db"
    path.write_text("lat,lng\n1,2\n" * 100)
    with pytest.raises(dggs.StorageError, match=f"{path} is not a SQLite database"):
        CellStore(path)


def test_truncated_database(tmp_path, db_path):
    with CellStore(db_path) as store:
        store.ingest_points([1.0] * 500, [2.0] * 500, 5)
        store.conn.execute("PRAGMA wal_checkpoint(TRUNCATE)")
    damaged = tmp_path / "damaged.db"
    damaged.write_bytes(db_path.read_bytes()[:100] + b"\x00" * 3000)
    with pytest.raises(dggs.StorageError, match="damaged.db"):
        with CellStore(damaged) as store:
            store.count()


def test_other_sqlite_database(tmp_path):
    path = tmp_path / "other.db"
    con = sqlite3.connect(path)
    con.execute("CREATE TABLE people (name TEXT)")
    con.commit()
    con.close()
    with pytest.raises(dggs.StorageError, match="other.db is a SQLite database but not a dggs cell store"):
        CellStore(path)


def test_wrong_columns_and_newer_schema(tmp_path, db_path):
    with CellStore(db_path):
        pass
    con = sqlite3.connect(db_path)
    con.execute("UPDATE meta SET value = '99' WHERE key = 'schema_version'")
    con.commit()
    con.close()
    with pytest.raises(dggs.StorageError, match="schema version 99"):
        CellStore(db_path)


def test_missing_file_directory_and_readonly(tmp_path):
    with pytest.raises(dggs.StorageError, match="no cell store at"):
        CellStore(tmp_path / "missing.db", create=False)
    with pytest.raises(dggs.StorageError, match="is a directory"):
        CellStore(tmp_path)
    path = tmp_path / "ro.db"
    with CellStore(path) as store:
        store.ingest_points([1.0], [2.0], 3)
    with CellStore(path, readonly=True) as store:
        assert store.count() == 1
        with pytest.raises(dggs.StorageError, match="read-only"):
            store.ingest_points([1.0], [2.0], 3)


def test_empty_sqlite_file_becomes_a_store(tmp_path):
    path = tmp_path / "empty.db"
    path.touch()
    with CellStore(path) as store:
        assert store.count() == 0


def test_delete_source(store):
    store.ingest_points([1.0, 2.0], [3.0, 4.0], 4, source="a")
    store.ingest_points([5.0], [6.0], 4, source="b")
    assert store.delete_source("a") == 2
    assert store.count() == 1 and [s["name"] for s in store.sources()] == ["b"]
    with pytest.raises(dggs.StorageError, match="no source"):
        store.delete_source("a")


@pytest.mark.slow  # 6 s here: starts many processes
def test_many_processes_create_one_store_at_once(tmp_path):
    import subprocess
    import sys

    db = tmp_path / "race.db"
    code = "import sys; from dggs.storage import CellStore; CellStore(sys.argv[1]).close()"
    procs = [subprocess.Popen([sys.executable, "-c", code, str(db)], stderr=subprocess.PIPE, text=True)
             for _ in range(4)]
    for proc in procs:
        assert proc.wait(timeout=60) == 0, proc.stderr.read()
    with CellStore(db) as store:
        assert store.meta["schema_version"] == "1"
