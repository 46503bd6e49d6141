"""Kill an ingest with SIGKILL at arbitrary moments; the store must stay whole.

After each kill: ``PRAGMA integrity_check`` is ok, the store holds exactly
the rows of the committed batches (``sources.rows_done`` of them, a whole
number of batches), and re-running the same ingest ends with every input row
stored exactly once.  Also: readers keep working while a writer ingests, and
only ever see whole batches.
"""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import dggs
from dggs.storage import CellStore

from .helpers import write_csv

N_ROWS = 60_000
BATCH = 1_000

WRITER = textwrap.dedent(
    """
    import sys
    from dggs.storage import CellStore

    db, csv_path, batch, merge_rows = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    mode = sys.argv[5] if len(sys.argv) > 5 else "csv"

    def tick(n):
        print("batch", n, flush=True)

    with CellStore(db, merge_rows=merge_rows) as store:
        if mode == "csv":
            store.ingest_csv(csv_path, values=["k", "x"], level=10, batch_size=batch, progress=tick)
        elif mode == "arrays":  # a named DataFrame: its rows go in cell order straight into points
            import pandas as pd
            frame = pd.read_csv(csv_path)
            store.ingest_dataframe(frame, values=["k", "x"], level=10, batch_size=batch, source="frame",
                                   progress=tick)
        else:  # a named stream of dicts: resumable the same way
            import csv
            with open(csv_path, newline="") as fh:
                rows = ({"lat": float(r["lat"]), "lng": float(r["lng"]), "k": int(r["k"]), "x": float(r["x"])}
                        for r in csv.DictReader(fh))
                store.ingest_records(rows, values=["k", "x"], level=10, batch_size=batch, source="stream",
                                     progress=tick)
    print("done", flush=True)
    """
)


@pytest.fixture(scope="module")
def big_csv(tmp_path_factory):
    rng = np.random.default_rng(99)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, N_ROWS)))
    lng = rng.uniform(-180, 180, N_ROWS)
    path = tmp_path_factory.mktemp("crash") / "points.csv"
    return write_csv(
        path,
        ["lat", "lng", "k", "x"],
        [[f"{a:.6f}", f"{b:.6f}", i, f"{i * 0.5:.1f}"] for i, (a, b) in enumerate(zip(lat, lng, strict=True))],
    )


def _start_writer(tmp_path, db, csv_path, merge_rows=7_000, mode="csv"):
    script = tmp_path / "writer.py"
    script.write_text(WRITER)
    return subprocess.Popen(
        [sys.executable, str(script), str(db), str(csv_path), str(BATCH), str(merge_rows), mode],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def _check_whole(db) -> int:
    """Integrity, whole batches only, no duplicates; return rows stored."""
    con = sqlite3.connect(db)
    try:
        assert con.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        sources = con.execute("SELECT rows_done, rows_inserted FROM sources").fetchall()
        stored = con.execute("SELECT count(*) FROM all_points").fetchone()[0]
        distinct = con.execute("SELECT count(DISTINCT k) FROM all_points").fetchone()[0]
    finally:
        con.close()
    done = sources[0][0] if sources else 0
    assert stored == done == (sources[0][1] if sources else 0)
    assert done % BATCH == 0 or done == N_ROWS
    assert distinct == stored
    return stored


@pytest.mark.slow  # 3 x 4.6 s here: a child process killed mid-ingest
@pytest.mark.parametrize("mode", ["csv", "records", "arrays"])
def test_sigkill_during_ingest_then_resume_exactly_once(tmp_path, big_csv, mode):
    db = tmp_path / "crash.db"
    rng = np.random.default_rng(5)
    kills = 0
    for _attempt in range(4):
        proc = _start_writer(tmp_path, db, big_csv, mode=mode)
        wait_for = int(rng.integers(2, 12))
        seen = 0
        for line in proc.stdout:
            if line.startswith("batch"):
                seen += 1
            if seen >= wait_for or line.startswith("done"):
                break
        time.sleep(float(rng.uniform(0, 0.05)))  # land anywhere: inside a batch, a merge, a commit
        if proc.poll() is None:
            os.kill(proc.pid, signal.SIGKILL)
            kills += 1
        proc.wait(timeout=60)
        _check_whole(db)
    assert kills >= 2
    if mode in ("records", "arrays"):  # finish with the same named input
        proc = _start_writer(tmp_path, db, big_csv, mode=mode)
        proc.wait(timeout=120)
        assert proc.returncode == 0, proc.stderr.read()
        with CellStore(db) as store:
            assert store.count() == N_ROWS
            store.check()
            pairs = store.conn.execute("SELECT row, k FROM all_points ORDER BY k").fetchall()
            assert pairs == [(k + 1, k) for k in range(N_ROWS)]  # each input row once, under its own number
        assert _check_whole(db) == N_ROWS
        return
    with CellStore(db) as store:
        result = store.ingest_csv(big_csv, values=["k", "x"], level=10, batch_size=BATCH)
        assert result.rows_resumed + result.rows_read == N_ROWS
        assert store.count() == N_ROWS
        ks = [r[0] for r in store.conn.execute("SELECT k FROM all_points ORDER BY k")]
        assert ks == list(range(N_ROWS))
        assert store.info()["pending"] == 0
        assert store.sources()[0]["complete"]
        store.check()
    assert _check_whole(db) == N_ROWS


def test_readers_work_while_a_writer_ingests(tmp_path, big_csv):
    db = tmp_path / "busy.db"
    with CellStore(db):  # create the schema before the writer starts
        pass
    dggs.uncompact_cells(["A"], 0)  # the roll-up's kernel compiled (a cold cache takes seconds) before the writer runs
    proc = _start_writer(tmp_path, db, big_csv, merge_rows=5_000)
    counts = []
    try:
        with CellStore(db, readonly=True) as reader:
            while proc.poll() is None:
                n = reader.count()
                counts.append(n)
                assert n % BATCH == 0 or n == N_ROWS  # whole batches only
                if reader.level is not None:
                    rolled = reader.aggregate(0, "x", ("count",))
                    assert sum(r["count"] for r in rolled) >= n  # later snapshot, never fewer
                time.sleep(0.01)
    finally:
        proc.wait(timeout=120)
    assert proc.returncode == 0, proc.stderr.read()
    assert counts == sorted(counts)
    assert len(set(counts)) > 2  # the reader saw the store grow
    with CellStore(db, readonly=True) as reader:
        assert reader.count() == N_ROWS


def test_two_writers_on_one_source_never_duplicate(tmp_path, big_csv):
    db = tmp_path / "two.db"
    with CellStore(db):
        pass
    procs = [_start_writer(tmp_path, db, big_csv) for _ in range(2)]
    for proc in procs:
        proc.wait(timeout=180)
    outcomes = sorted(p.returncode for p in procs)
    stderr = " ".join(p.stderr.read() for p in procs)
    assert outcomes[0] == 0  # at least one finished
    if outcomes[1] != 0:
        assert "by another process too" in stderr
    with CellStore(db) as store:
        store.ingest_csv(big_csv, values=["k", "x"], level=10, batch_size=BATCH)  # finish if needed
        assert store.count() == N_ROWS
    assert _check_whole(db) == N_ROWS
