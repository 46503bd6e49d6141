"""The standing adversarial suite: broken files, full disks, read-only media, locks.

The only acceptable outcomes are a correct result (exact row count,
``PRAGMA integrity_check`` ok) or a :class:`dggs.DggsError` subclass naming
the file or value; on the command line, one line and a non-zero exit.

Full disks and read-only media are real: a small tmpfs is mounted by the
test (the tests run as root) and unmounted in teardown.  Where mounting is
impossible those tests say so in their skip reason; the read-only path is
then still tested through the immutable URI directly.
"""

from __future__ import annotations

import json
import os
import shutil
import sqlite3
import subprocess
import uuid
import warnings
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dggs.cli import main
from dggs.errors import DggsError, DggsValueError, StorageError
from dggs.storage import BadRowError, CellStore, RejectedRowsWarning
from dggs.storage.atomic import atomic_write
from dggs.storage.connection import connect_immutable

from .helpers import write_csv

N = 3_000


def _points(n: int = N, seed: int = 1):
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    return lat, lng, np.arange(n)


@pytest.fixture(scope="module")
def good_db(tmp_path_factory) -> Path:
    """A closed store of N rows (WAL checkpointed into the file)."""
    path = tmp_path_factory.mktemp("faults") / "good.db"
    lat, lng, k = _points()
    with CellStore(path) as store:
        store.ingest_points(lat, lng, 8, {"k": k}, batch_size=500)
        store.merge()
    return path


def _mount_tmpfs(where: Path, size: str) -> bool:
    where.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0 or shutil.which("mount") is None:
        return False
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)],
                          capture_output=True, text=True)
    return proc.returncode == 0


@pytest.fixture
def tmpfs(tmp_path):
    """Mount a small tmpfs; yield (path, remount) or skip with the reason."""
    where = tmp_path / f"mnt-{uuid.uuid4().hex[:6]}"
    if not _mount_tmpfs(where, "1m"):
        pytest.skip("cannot mount a tmpfs here (not root, or no CAP_SYS_ADMIN)")

    def remount(options: str) -> None:
        subprocess.run(["mount", "-o", f"remount,{options}", str(where)], check=True)

    try:
        yield where, remount
    finally:
        subprocess.run(["umount", "-l", str(where)], capture_output=True)


def _integrity_ok(path: Path) -> bool:
    con = sqlite3.connect(path)
    try:
        return con.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    finally:
        con.close()


# -- corrupt files ------------------------------------------------------------


def _outcome(path: Path) -> str:
    """Open, count, check: 'exact' or 'error'; anything else fails the test."""
    try:
        with CellStore(path, readonly=True) as store:
            n = store.count()
            store.aggregate(0)
            store.check()
            assert n == N, f"wrong count {n} without an error"
            return "exact"
    except StorageError as exc:
        assert str(path) in str(exc)
        return "error"


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1))
def test_bit_flipped_store_gives_exact_count_or_storage_error(good_db, tmp_path, seed):
    rng = np.random.default_rng(seed)
    data = bytearray(good_db.read_bytes())
    for pos in rng.integers(0, len(data), 200):
        data[pos] ^= 1 << int(rng.integers(0, 8))
    bad = tmp_path / f"flip-{seed}.db"
    bad.write_bytes(bytes(data))
    _outcome(bad)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(fraction=st.floats(0.0, 1.0))
def test_truncated_store_gives_exact_count_or_storage_error(good_db, tmp_path, fraction):
    data = good_db.read_bytes()
    bad = tmp_path / f"cut-{uuid.uuid4().hex[:6]}.db"
    bad.write_bytes(data[: int(len(data) * fraction)])
    if bad.stat().st_size == 0:
        with pytest.raises(StorageError):
            CellStore(bad, readonly=True)
        return
    _outcome(bad)


def test_cli_on_a_corrupt_store_prints_one_line(good_db, tmp_path):
    rng = np.random.default_rng(7)
    data = bytearray(good_db.read_bytes())
    for pos in rng.integers(len(data) // 2, len(data), 200):  # the schema pages stay: open succeeds, reads fail
        data[pos] ^= 1 << int(rng.integers(0, 8))
    bad = tmp_path / "flipped.db"
    bad.write_bytes(bytes(data))
    runner = CliRunner()
    failed = 0
    for args in (["query", str(bad), "--level", "2"], ["info", str(bad)],
                 ["export", str(bad), "--level", "1", "--geojson", str(tmp_path / "o.geojson")]):
        result = runner.invoke(main, args)
        if result.exit_code == 0:
            continue  # the flips missed everything this command reads
        failed += 1
        assert result.exit_code == 1, result.output
        assert not isinstance(result.exception, (sqlite3.Error, OSError)), result.exception
        assert "Traceback" not in result.output and result.output.count("\n") == 1, result.output
        assert "corrupt" in result.output
    assert failed


def test_tampered_meta_level_is_a_storage_error(good_db, tmp_path):
    bad = tmp_path / "meta.db"
    shutil.copy(good_db, bad)
    con = sqlite3.connect(bad)
    con.execute("UPDATE meta SET value = 'x9' WHERE key = 'level'")
    con.commit()
    con.close()
    with pytest.raises(StorageError, match="meta.level is 'x9'"):
        CellStore(bad)
    result = CliRunner().invoke(main, ["info", str(bad)])
    assert result.exit_code == 1 and "meta.level" in result.output and result.output.count("\n") == 1


# -- a full disk --------------------------------------------------------------


def test_full_disk_during_ingest_then_resume_exactly_once(tmp_path, tmpfs):
    where, remount = tmpfs
    lat, lng, k = _points(40_000, seed=3)
    csv_path = write_csv(tmp_path / "big.csv", ["lat", "lng", "k"],
                         [[f"{a:.5f}", f"{b:.5f}", i] for a, b, i in zip(lat, lng, k, strict=True)])
    db = where / "full.db"
    with CellStore(db) as store, pytest.raises(StorageError, match="disk is full"):
        store.ingest_csv(csv_path, values=["k"], level=10, batch_size=2_000)
    assert _integrity_ok(db)
    remount("size=64m")
    with CellStore(db) as store:
        result = store.ingest_csv(csv_path, values=["k"], level=10, batch_size=2_000)
        assert result.rows_resumed % 2_000 == 0
        assert store.count() == 40_000
        ks = [r[0] for r in store.conn.execute("SELECT k FROM all_points ORDER BY k")]
        assert ks == list(range(40_000))
        store.check()


def test_full_disk_export_leaves_the_old_file_whole(good_db, tmp_path, tmpfs):
    where, _ = tmpfs
    out = where / "cells.geojson"
    out.write_text('{"old": true}')
    (where / "filler").write_bytes(b"\0" * (1024 * 1024 - 64 * 1024))
    runner = CliRunner()
    result = runner.invoke(main, ["export", str(good_db), "--level", "4", "--geojson", str(out)])
    assert result.exit_code == 1 and "cannot write" in result.output and result.output.count("\n") == 1
    assert json.loads(out.read_text()) == {"old": True}
    assert sorted(p.name for p in where.iterdir()) == ["cells.geojson", "filler"]  # no temp file left
    pytest.importorskip("matplotlib")
    result = runner.invoke(main, ["plot", str(good_db), "--level", "4", "--png", str(where / "m.png")])
    assert result.exit_code == 1 and "cannot write" in result.output
    assert not (where / "m.png").exists()


@pytest.mark.parametrize("fmt", ["gpkg", "fgb"])
def test_full_disk_gdal_export_is_one_line_and_leaves_the_old_file(good_db, tmpfs, fmt):
    """GDAL's own messages ("no such table: gpkg_contents", "Unexpected I/O failure") do not say the disk is full."""
    pytest.importorskip("pyogrio")
    where, _ = tmpfs
    out = where / f"cells.{fmt}"
    out.write_bytes(b"old")
    (where / "filler").write_bytes(b"\0" * (1024 * 1024 - 64 * 1024))
    result = CliRunner().invoke(main, ["export", str(good_db), "--level", "4", "-o", str(out)])
    assert result.exit_code == 1 and result.output.count("\n") == 1, result.output
    assert "Traceback" not in result.output and f"cannot write {out}: no space left" in result.output.lower()
    with CellStore(good_db, readonly=True) as store, pytest.raises(StorageError, match=f"(?i){out}: no space left"):
        store.export(out, 4)
    assert out.read_bytes() == b"old"
    assert sorted(p.name for p in where.iterdir()) == [out.name, "filler"]  # no temp file or folder left


def test_other_gdal_write_failures_name_the_target_not_the_temp_file(good_db, tmp_path, monkeypatch):
    errors = pytest.importorskip("pyogrio.errors")
    geopandas = pytest.importorskip("geopandas")

    pyogrio = pytest.importorskip("pyogrio")

    def broken(self, filename, **kwargs):
        raise errors.DataSourceError(f"Failed to write features to dataset {filename}; simulated")

    monkeypatch.setattr(geopandas.GeoDataFrame, "to_file", broken)
    # polygons only go to GDAL as an arrow table (dggs.arrow.write_cells): that path fails alike
    monkeypatch.setattr(pyogrio, "write_arrow", lambda table, filename, **kwargs: broken(table, filename))
    out = tmp_path / "cells.gpkg"
    with CellStore(good_db, readonly=True) as store, pytest.raises(StorageError) as info:
        store.export(out, 2)
    assert f"cannot write {out}: Failed to write features to dataset {out}; simulated" in str(info.value)
    assert "space" not in str(info.value).split(";")[0] and not out.exists()


def test_atomic_write_never_leaves_a_truncated_file(tmp_path):
    out = tmp_path / "x.json"
    out.write_text("old")
    with pytest.raises(RuntimeError), atomic_write(out) as fh:
        fh.write("half")
        raise RuntimeError("interrupted")
    assert out.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["x.json"]


# -- read-only media ------------------------------------------------------------


def test_readonly_store_on_a_readonly_mount(good_db, tmpfs):
    where, remount = tmpfs
    db = where / "ro.db"
    shutil.copy(good_db, db)
    with CellStore(db) as store:  # WAL mode, closed cleanly: no -wal/-shm left
        assert store.count() == N
    remount("ro")
    assert not os.access(where, os.W_OK)
    with CellStore(db, readonly=True) as store:
        assert store.count() == N and sum(r["count"] for r in store.aggregate(0)) == N
    with pytest.raises(StorageError, match=str(db)):
        with CellStore(db) as store:
            store.ingest_points([1.0], [1.0], 8)
    result = CliRunner().invoke(main, ["query", str(db), "--level", "0"])
    assert result.exit_code == 0, result.output


def test_readonly_folder_copy_and_immutable_uri(good_db, tmp_path):
    folder = tmp_path / "locked"
    folder.mkdir()
    db = folder / "copy.db"
    shutil.copy(good_db, db)
    db.chmod(0o444)
    folder.chmod(0o555)
    try:
        with CellStore(db, readonly=True) as store:
            assert store.count() == N
        con = connect_immutable(db)  # the path taken on read-only media
        assert con.execute("SELECT count(*) FROM points").fetchone()[0] == N
        con.close()
    finally:
        folder.chmod(0o755)
    Path(str(db) + "-wal").write_bytes(b"x" * 100)  # unmerged log: immutable would miss rows
    with pytest.raises(StorageError, match="write-ahead log"):
        connect_immutable(db)


# -- locks, encodings, odd input ---------------------------------------------------


def test_locked_store_with_a_short_timeout(good_db, tmp_path):
    db = tmp_path / "locked.db"
    shutil.copy(good_db, db)
    holder = sqlite3.connect(db, isolation_level=None)
    holder.execute("BEGIN IMMEDIATE")
    try:
        with CellStore(db, timeout=0.05) as store:
            with pytest.raises(StorageError, match="locked by another process"):
                store.ingest_points([1.0], [1.0], 8)
            assert store.count() == N  # readers still work
    finally:
        holder.execute("ROLLBACK")
        holder.close()


def test_bogus_encoding_is_one_line(tmp_path):
    path = write_csv(tmp_path / "p.csv", ["lat", "lng"], [[1, 1]])
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(tmp_path / "e.db"), "--encoding", "bogus"])
    assert result.exit_code == 1 and "unknown text encoding 'bogus'" in result.output
    assert result.output.count("\n") == 1


def test_geojson_properties_that_are_not_an_object(tmp_path):
    path = tmp_path / "p.geojson"
    point = {"type": "Point", "coordinates": [1, 1]}
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": point, "properties": {"a": 1}},
        {"type": "Feature", "geometry": point, "properties": [1, 2]}]}))
    with CellStore() as store:
        with pytest.raises(BadRowError, match="row 2.*not a JSON object"):
            store.ingest_geojson(path, level=5)
        with pytest.warns(UserWarning):
            assert store.ingest_geojson(path, level=5, on_error="skip").rows_inserted == 1


def test_column_names_differing_only_in_case(tmp_path):
    with CellStore() as store:
        with pytest.raises(DggsValueError, match="ignore case"):
            store.ingest_records([{"lat": 1, "lng": 1, "Pop": 1, "pop": 2}], values=["Pop", "pop"], level=5)
        store.ingest_records([{"lat": 1, "lng": 1, "pop": 1}], values=["pop"], level=5)
        with pytest.raises(DggsValueError, match="only in case"):
            store.ingest_records([{"lat": 1, "lng": 1, "POP": 1}], values=["POP"], level=5)
        path = tmp_path / "c.geojson"
        path.write_text(json.dumps({"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 1]},
                                    "properties": {"Name": "a", "name": "b"}}))
        with pytest.raises(DggsValueError, match="only in case"):
            store.ingest_geojson(path, level=5)
        assert store.count() == 1


def test_deeply_nested_json(tmp_path):
    path = tmp_path / "deep.geojson"
    path.write_text('{"type": "Feature", "properties": {"a": ' + "[" * 100_000 + "]" * 100_000 + "}}")
    with CellStore() as store, pytest.raises(DggsValueError, match="nested too deeply"):
        store.ingest_geojson(path, level=5)
    result = CliRunner().invoke(main, ["bin", str(path), "--db", str(tmp_path / "d.db")])
    assert result.exit_code == 1 and result.output.count("\n") == 1


def test_every_failure_above_is_a_dggs_error():
    assert issubclass(StorageError, DggsError) and issubclass(BadRowError, DggsError)


# -- CSV text of any shape ------------------------------------------------------------

_TEXT = st.text(alphabet=st.sampled_from(list('ab ,"\n\r\'é;|\t0')), max_size=12)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(rows=st.lists(st.tuples(st.floats(-89, 89), st.floats(-179, 179), _TEXT), min_size=1, max_size=30),
       batch=st.integers(1, 7))
def test_any_properly_quoted_csv_round_trips_exactly(tmp_path, rows, batch):
    import csv

    path = tmp_path / f"t-{uuid.uuid4().hex[:6]}.csv"
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh)
        writer.writerow(["lat", "lng", "s"])
        writer.writerows(rows)
    with CellStore() as store:
        result = store.ingest_csv(path, values={"s": str}, level=4, batch_size=batch)
        got = [r[0] for r in store.conn.execute("SELECT s FROM all_points ORDER BY row")]
    assert result.rows_inserted == len(rows)
    assert got == [s or None for _, _, s in rows]  # exactly the text written (empty: NULL)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=st.text(alphabet=st.sampled_from(list('1,."\n x')), max_size=80))
def test_any_csv_text_is_stored_whole_or_refused(tmp_path, text):
    """Arbitrary bytes after a header: every record stored or rejected (counted), or a typed error."""
    path = tmp_path / f"g-{uuid.uuid4().hex[:6]}.csv"
    path.write_text("lat,lng,s\n" + text, encoding="utf-8")
    with CellStore() as store:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RejectedRowsWarning)
                result = store.ingest_csv(path, values={"s": str}, level=4, batch_size=3, on_error="skip")
        except DggsError:
            return
        stored = store.count()
        assert stored == result.rows_inserted
        assert result.rows_inserted + result.rows_rejected <= result.rows_read
        source = store.sources()[0]
        assert source["rows_done"] == result.rows_read and source["complete"]

