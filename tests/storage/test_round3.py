"""Issue 17, round three: races, self-overwrites, file modes, CSV rules, messages.

Each test reproduces one finding of the adversarial run; the only acceptable
outcomes are a correct result or a :class:`dggs.DggsError` naming the bad
value (on the command line: one line, a non-zero exit).
"""

from __future__ import annotations

import os
import sqlite3
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dggs.cli import main
from dggs.errors import DggsError, DggsValueError, LevelMismatchError, StorageError
from dggs.storage import BadRowError, CellStore, RejectedRowsWarning
from dggs.storage.atomic import atomic_write

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
    # the loser: a level mismatch, or, if the winner held the store past its lock timeout, a lock error
    assert ("level" in err or "locked" in err) and "Traceback" not in err and len(err.strip().splitlines()) == 1
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


# -- item 8: outputs respect the umask; stale temporary files are removed ----


@pytest.fixture
def umask():
    def set_(mask: int) -> None:
        os.umask(mask)

    old = os.umask(0o022)
    yield set_
    os.umask(old)


@pytest.mark.parametrize("mask", [0o022, 0o002, 0o077])
@pytest.mark.parametrize("name", ["out.geojson", "out.parquet", "out.gpkg", "map.png"])
def test_outputs_respect_the_umask(small_store, tmp_path, umask, mask, name):
    umask(mask)
    out = tmp_path / name
    args = ["plot", str(small_store), "--level", "2", "--png"] if name.endswith(".png") else [
        "export", str(small_store), "--level", "2", "-o"]
    result = CliRunner().invoke(main, [*args, str(out)])
    assert result.exit_code == 0, result.output
    assert stat.S_IMODE(out.stat().st_mode) == 0o666 & ~mask


def test_atomic_write_keeps_an_existing_files_mode(tmp_path, umask):
    out = tmp_path / "kept.txt"
    out.write_text("old")
    out.chmod(0o640)
    with atomic_write(out) as fh:
        fh.write("new")
    assert out.read_text() == "new" and stat.S_IMODE(out.stat().st_mode) == 0o640


def test_stale_temporary_files_are_removed_on_the_next_export(small_store, tmp_path):
    out = tmp_path / "cells.geojson"
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = [tmp_path / ".cells.geojson.k2j4h5x1.tmp", tmp_path / f".cells.geojson.{dead.pid}-abc.tmp"]
    for path in stale:
        path.write_bytes(b"x" * 1000)
    (tmp_path / ".cells.geojson.q9w8e7r6.tmp").mkdir()  # a killed GPKG export's folder
    (tmp_path / ".cells.geojson.q9w8e7r6.tmp" / "cells.geojson").write_text("half")
    alive = tmp_path / f".cells.geojson.{os.getppid()}-def.tmp"  # a running export's file
    alive.write_bytes(b"y")
    other = tmp_path / ".other.geojson.k2j4h5x1.tmp"  # another output's: not ours to remove
    other.write_bytes(b"z")
    result = CliRunner().invoke(main, ["export", str(small_store), "--level", "2", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == sorted([alive.name, other.name])


# -- item 17: CSV rules -------------------------------------------------------


def _csv(tmp_path: Path, text: str, name: str = "in.csv") -> Path:
    path = tmp_path / name
    path.write_text(text, newline="")
    return path


def _rows(store: CellStore) -> list[dict]:
    return sorted(store.descendants(list("ABCDEFGHIJ")), key=lambda r: r["row"])


def test_nan_is_missing_and_infinity_a_bad_row_in_every_input(tmp_path):
    """The one rule (docs/storage.md): NaN is a missing value (NULL), +-inf a bad row."""
    with CellStore() as store:
        store.ingest_csv(_csv(tmp_path, "lat,lng,v\n1,2,nan\n3,4,NaN\n5,6,1.5\n"), values=["v"], level=5)
        store.ingest_records([{"lat": 1, "lng": 2, "v": float("nan")}], values=["v"], level=5)
        store.ingest_points([1.0], [2.0], 5, {"v": [float("nan")]})
        assert sorted(r["v"] is None for r in _rows(store)) == [False, True, True, True, True]
        for spelling in ("inf", "-inf", "Infinity"):
            with pytest.raises(BadRowError, match="not finite"):
                store.ingest_csv(_csv(tmp_path, f"lat,lng,v\n1,2,{spelling}\n", f"{spelling}.csv"), values=["v"])
        with pytest.raises(BadRowError, match="not finite"):
            store.ingest_records([{"lat": 1, "lng": 2, "v": float("inf")}], values=["v"])
        with pytest.raises(BadRowError, match="not finite"):
            store.ingest_points([1.0], [2.0], 5, {"v": [float("-inf")]})


def test_a_duplicate_header_is_refused(tmp_path):
    with CellStore() as store, pytest.raises(DggsValueError, match="'lat' twice"):
        store.ingest_csv(_csv(tmp_path, "lat,lat,lng\n1,2,3\n"), level=5)
    with CellStore() as store:  # a duplicate column that is not used is harmless
        assert store.ingest_csv(_csv(tmp_path, "lat,lng,x,x\n1,2,3,4\n", "x.csv"), level=5).rows_inserted == 1


@pytest.mark.parametrize("name", ["cell\n", "v\n", "v\r", " v", "v "])
def test_a_value_column_name_with_a_trailing_newline_is_refused(tmp_path, name):
    with CellStore() as store, pytest.raises(DggsValueError, match="not a plain identifier"):
        store.ingest_records([{"lat": 1.0, "lng": 2.0, name: 3}], values=[name], level=5)


@pytest.mark.parametrize("text", ["lat,lng,v", "lat,lng,v\n", "lat,lng,v\r\n"])
def test_a_header_only_file_is_no_rows_not_empty(tmp_path, text):
    with CellStore() as store:
        result = store.ingest_csv(_csv(tmp_path, text), values=["v"], level=5)
        assert (result.rows_read, result.rows_inserted) == (0, 0)
        assert store.columns == {"v": "TEXT"} or "v" not in store.columns


def test_a_field_longer_than_a_block_is_named_by_its_line(tmp_path):
    big = "x" * (5 << 20)
    path = _csv(tmp_path, f"lat,lng,v\n1,2,a\n3,4,b\n1,2,{big}\n3,4,y\n")
    with CellStore() as store, pytest.raises(DggsValueError, match=r"line 4") as info:
        store.ingest_csv(path, values=["v"], level=5)
    assert "straddl" not in str(info.value) and "in.csv" in str(info.value)


def test_projected_coordinates_outside_the_crs_are_bad_rows(tmp_path):
    path = _csv(tmp_path, "lat,lng\n1e20,1e20\n5000,6000\n-2e7,3e7\n")
    with CellStore() as store, pytest.warns(RejectedRowsWarning):
        result = store.ingest_csv(path, level=5, crs="EPSG:3857", on_error="skip")
        assert (result.rows_inserted, result.rows_rejected) == (1, 2)
        (row,) = _rows(store)
        assert row["row"] == 2 and abs(row["lat"]) < 1 and abs(row["lng"]) < 1


# -- item 16: messages that name the right thing ------------------------------


@pytest.mark.parametrize("content", [
    "lat,lng\n1,2\n".encode("utf-16"),
    bytes(range(256)) * 12,
])
def test_a_csv_that_is_not_text_is_named_not_the_store(tmp_path, content):
    path = tmp_path / "u.csv"
    path.write_bytes(content)
    db = tmp_path / "u.db"
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db), "--level", "5", "--no-progress"])
    assert result.exit_code == 1 and "u.csv" in result.output and "corrupt" not in result.output, result.output
    assert len(result.output.strip().splitlines()) == 1


def test_a_failed_bin_leaves_no_empty_store(tmp_path):
    path = _csv(tmp_path, "lat,lng\n1,2\n")
    db = tmp_path / "new.db"
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(db), "--lat", "nope", "--no-progress"])
    assert result.exit_code == 1 and "'nope'" in result.output, result.output
    assert not db.exists() and list(tmp_path.iterdir()) == [path]


def test_aggregate_arguments_of_the_wrong_kind_are_named(tmp_path):
    """A dict for the column (as pandas' agg takes) was a raw TypeError; one stat as a string is one stat."""
    path = tmp_path / "a.db"
    with CellStore(path) as store:
        store.ingest_records([{"lat": 1.0, "lng": 2.0, "v": 3}, {"lat": 1.0, "lng": 2.0, "v": 4}], level=6, values=["v"])
        with pytest.raises(DggsValueError, match=r"column must be .* not \{'v': 'sum'\}"):
            store.aggregate(3, {"v": "sum"})
        (row,) = store.aggregate(3, "v", "sum")
        assert row["sum"] == 7 and set(row) == {"cell", "sum"}


def test_progress_true_draws_a_bar_and_false_none(tmp_path, capsys):
    """progress=False was refused ("must be callable"), as tqdm's users would not expect."""
    import pandas as pd

    frame = pd.DataFrame({"lat": [1.0, 2.0, 3.0], "lng": [4.0, 5.0, 6.0]})
    with CellStore(tmp_path / "p.db") as store:
        store.ingest_dataframe(frame, level=5, progress=True, source="a")
        assert "3.00/3.00" in capsys.readouterr().err  # with its total (issue 38)
        store.ingest_dataframe(frame, level=5, progress=False, source="b")
        assert capsys.readouterr().err == ""
        with pytest.raises(DggsValueError, match="progress must be True, False, None or a callable"):
            store.ingest_dataframe(frame, level=5, progress="yes", source="c")
        assert store.count() == 6


def test_a_shapefile_without_its_dbf_says_it_has_no_columns(tmp_path):
    """Its header was printed as nothing: "its header is " and the line ended."""
    import geopandas as gpd
    from shapely.geometry import Point

    shp = tmp_path / "s.shp"
    gpd.GeoDataFrame({"pop": [1, 2]}, geometry=[Point(1, 2), Point(3, 4)], crs=4326).to_file(shp)
    (tmp_path / "s.dbf").unlink()
    result = CliRunner().invoke(main, ["bin", str(shp), "--db", str(tmp_path / "n.db"), "--level", "5", "--value", "pop"])
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert "has no column(s) 'pop'; it has no columns at all" in result.output
    assert not (tmp_path / "n.db").exists()
