"""Issue 17, round three: races, self-overwrites, file modes, CSV rules, messages.

Each test reproduces one finding of the adversarial run; the only acceptable
outcomes are a correct result or a :class:`dggs.DggsError` naming the bad
value (on the command line: one line, a non-zero exit).
"""

from __future__ import annotations

import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dggs.cli import main
from dggs.errors import DggsError, LevelMismatchError, StorageError
from dggs.storage import CellStore

from .helpers import write_csv


def _racing(path: Path, level: int, values: list[str], row: dict):
    """Records whose first read lets a second writer create the store (at ``level``, with ``row``)."""

    def records():
        with CellStore(path) as other:
            other.ingest_records([row], values=values, level=level)
        yield {"lat": 10.0, "lng": 20.0, "v": 7}

    return records()


# -- item 1: two writers creating one new store ------------------------------


def test_second_creator_at_another_level_loses(tmp_path):
    path = tmp_path / "r.db"
    with CellStore(path) as store, pytest.raises(LevelMismatchError, match="level 8"):
        store.ingest_records(_racing(path, 8, [], {"lat": 1.0, "lng": 2.0}), level=10)
    with CellStore(path, readonly=True) as store:
        assert store.level == 8
        assert {len(r["cell"]) for r in store.descendants(["A", "B", "C", "D", "E", "F", "G", "H", "I", "J"])} <= {9}
        store.check()


def test_second_creator_with_another_column_type_loses(tmp_path):
    path = tmp_path / "t.db"
    with CellStore(path) as store, pytest.raises(DggsError, match="'v'"):
        store.ingest_records(_racing(path, 5, ["v"], {"lat": 1.0, "lng": 2.0, "v": "word"}), values=["v"], level=5)
    with CellStore(path, readonly=True) as store:
        assert store.columns == {"v": "TEXT"}
        assert store.count() == 1


def test_check_finds_mixed_levels(tmp_path):
    path = tmp_path / "m.db"
    with CellStore(path) as store:
        store.ingest_records([{"lat": 1.0, "lng": 2.0}], level=6)
        store.check()
    conn = sqlite3.connect(path)
    with conn:
        conn.execute("UPDATE points SET cell = substr(cell, 1, 5)")
    conn.close()
    with CellStore(path, readonly=True) as store, pytest.raises(StorageError, match="level"):
        store.check()


def test_two_cli_writers_at_two_levels(tmp_path):
    """Whatever the interleaving, exactly one `dggs bin` wins and the store holds one level."""
    rows = [[i * 0.01, i * 0.02] for i in range(3000)]
    a = write_csv(tmp_path / "a.csv", ["lat", "lng"], rows)
    b = write_csv(tmp_path / "b.csv", ["lat", "lng"], rows[::-1])
    db = tmp_path / "r.db"
    cmd = [sys.executable, "-m", "dggs.cli", "bin"]
    procs = [
        subprocess.Popen([*cmd, str(f), "--db", str(db), "--level", str(n), "--no-progress", "--batch-size", "100"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        for f, n in ((a, 10), (b, 8))
    ]
    outs = [(p.wait(), p.communicate()) for p in procs]
    assert sorted(code for code, _ in outs) == [0, 1], outs
    _, (_, err) = next(o for o in outs if o[0] == 1)
    assert "level" in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
    with CellStore(db, readonly=True) as store:
        store.check()
        assert store.count() == 3000


# -- item 2: an export never overwrites the store it reads ------------------


@pytest.fixture
def small_store(tmp_path):
    path = tmp_path / "s.gpkg"  # a store with another format's extension
    with CellStore(path) as store:
        store.ingest_records([{"lat": 1.0, "lng": 2.0}, {"lat": 40.0, "lng": -3.0}], level=5)
    return path


def _alias(store: Path, how: str, tmp_path: Path) -> Path:
    if how == "same":
        return store
    if how in ("-wal", "-shm"):
        return Path(str(store) + how)
    if how == "relative":
        return Path("..") / store.parent.name / store.name
    link = tmp_path / f"link-{how}.geojson"
    if how == "symlink":
        link.symlink_to(store)
    else:
        link.hardlink_to(store)
    return link


@pytest.mark.parametrize("how", ["same", "-wal", "-shm", "relative", "symlink", "hardlink"])
@pytest.mark.parametrize("fmt", ["geojson", "geoparquet", "gpkg"])
def test_export_refuses_its_own_store(small_store, tmp_path, how, fmt, monkeypatch):
    monkeypatch.chdir(tmp_path)
    before = small_store.read_bytes()
    out = _alias(small_store, how, tmp_path)
    result = CliRunner().invoke(main, ["export", str(small_store), "--level", "2", "-o", str(out), "--format", fmt])
    assert result.exit_code == 1, result.output
    assert "is the store" in result.output and len(result.output.strip().splitlines()) == 1
    assert small_store.read_bytes() == before
    with CellStore(small_store, readonly=True) as store:
        store.check()
        assert store.count() == 2
    with CellStore(small_store) as store, pytest.raises(StorageError, match="is the store"):
        store.to_geojson(2, path=out)


def test_plot_refuses_its_own_store(small_store):
    before = small_store.read_bytes()
    result = CliRunner().invoke(main, ["plot", str(small_store), "--level", "2", "--png", str(small_store)])
    assert result.exit_code == 1 and "is the store" in result.output, result.output
    assert small_store.read_bytes() == before
