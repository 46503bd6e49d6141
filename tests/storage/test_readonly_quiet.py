"""Issue 17 item 15: a read-only store leaves its folder untouched while nobody writes, yet sees every commit.

A quiet store (no ``-wal``/``-shm`` beside it) is read immutable, which makes no
side files; a writer appearing later (its ``-wal`` there now) or a store replaced
on disk is caught up with before the next read, never answered from the old file.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from dggs.errors import StorageError
from dggs.storage import CellStore


def _side_files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(("-wal", "-shm")))


def _store(path: Path, points: list[tuple[float, float]]) -> None:
    with CellStore(path) as store:
        store.ingest_records([{"lat": lat, "lng": lng} for lat, lng in points], level=6)


def test_a_quiet_read_only_store_makes_no_side_files(tmp_path):
    path = tmp_path / "q.db"
    _store(path, [(10.0, 20.0), (-30.0, 40.0)])
    assert _side_files(tmp_path) == []
    before = path.read_bytes()
    with CellStore(path, readonly=True) as store:
        assert store.count() == 2
        assert sum(r["count"] for r in store.aggregate(3)) == 2
        assert _side_files(tmp_path) == []
    assert _side_files(tmp_path) == [] and path.read_bytes() == before


def test_a_reader_sees_a_writer_that_came_after_it(tmp_path):
    path = tmp_path / "w.db"
    _store(path, [(10.0, 20.0)])
    with CellStore(path, readonly=True) as reader:
        assert reader.count() == 1
        with CellStore(path) as writer:  # holds the store open: its -wal is there
            writer.ingest_records([{"lat": 1.0, "lng": 2.0}, {"lat": 3.0, "lng": 4.0}], level=6)
            assert reader.count() == 3  # caught up, as a WAL reader beside the writer
            writer.ingest_records([{"lat": 5.0, "lng": 6.0}], level=6)
            assert reader.count() == 4
        assert reader.count() == 4


def test_a_reader_sees_a_store_replaced_on_disk(tmp_path):
    path, other = tmp_path / "r.db", tmp_path / "other.db"
    _store(path, [(10.0, 20.0)])
    _store(other, [(1.0, 2.0), (3.0, 4.0), (5.0, 6.0)])
    with CellStore(path, readonly=True) as reader:
        assert reader.count() == 1
        os.replace(other, path)
        assert reader.count() == 3
    assert _side_files(tmp_path) == []


def test_a_store_deleted_under_a_reader_is_named(tmp_path):
    path = tmp_path / "d.db"
    _store(path, [(10.0, 20.0)])
    with CellStore(path, readonly=True) as reader:
        assert reader.count() == 1
        path.unlink()
        with pytest.raises(StorageError, match="d.db was deleted"):
            reader.count()


def test_a_store_copied_over_with_a_writer_open_still_reads_the_latest(tmp_path):
    path = tmp_path / "c.db"
    _store(path, [(10.0, 20.0)])
    shutil.copy(path, tmp_path / "copy.db")
    with CellStore(tmp_path / "copy.db", readonly=True) as reader, CellStore(tmp_path / "copy.db") as writer:
        writer.ingest_records([{"lat": 1.0, "lng": 2.0}], level=6)
        assert reader.count() == 2



def test_the_public_connection_follows_the_reader_when_it_opens_the_store_again(tmp_path):
    """``store.conn`` and ``store.db`` were the first connection's: closed once a writer appeared."""
    path = tmp_path / "c.db"
    _store(path, [(10.0, 20.0)])
    with CellStore(path, readonly=True) as reader:
        assert reader.conn.execute("SELECT count(*) FROM points").fetchone()[0] == 1
        with CellStore(path) as writer:
            writer.ingest_records([{"lat": 1.0, "lng": 2.0}], level=6)
            assert reader.conn.execute("SELECT count(*) FROM all_points").fetchone()[0] == 2
            assert reader.db.execute("SELECT count(*) FROM all_points").fetchone()[0] == 2
