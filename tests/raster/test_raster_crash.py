"""Kill a raster ingest with SIGKILL at arbitrary moments; it must resume to exactly once (issue 19).

The house pattern of tests/storage/test_crash.py, with blocks for batches.
After each kill: ``PRAGMA integrity_check`` is ok, no row is in ``points``
yet, and the partials table holds exactly the partials of the first
``rows_done`` blocks added up (computed here, in this process, the way
``raster_to_cells`` adds them): whole blocks only, none twice.  The last run
ends with ``raster_to_cells``' rows to the last bit and the kept roll-ups
matching the rows.
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

pytest.importorskip("rasterio")

from dggs.raster import block_results, open_checked, raster_to_cells  # noqa: E402
from dggs.raster.stats import combine  # noqa: E402
from dggs.storage import CellStore  # noqa: E402

from .helpers import field, same_rows, write  # noqa: E402

LEVEL, BLOCK, MODE = 11, 12, "mean"

WRITER = textwrap.dedent(
    """
    import sys
    import time
    from dggs.storage import CellStore

    def tick(n):
        print("block", n, flush=True)
        time.sleep(0.02)  # blocks of 12 x 12 pixels take microseconds: let the kill land before the end

    with CellStore(sys.argv[1]) as store:
        store.ingest_raster(sys.argv[2], int(sys.argv[3]), mode=sys.argv[4], block_size=int(sys.argv[5]),
                            progress=tick)
    print("done", flush=True)
    """
)


def _start(tmp_path, db, raster):
    script = tmp_path / "writer.py"
    script.write_text(WRITER)
    args = [sys.executable, str(script), str(db), str(raster), str(LEVEL), MODE, str(BLOCK)]
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _check_whole(db, prefixes):
    """Integrity, and partials that are exactly those of the first rows_done blocks; return rows_done."""
    con = sqlite3.connect(db)
    try:
        assert con.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        source = con.execute("SELECT rows_done, complete FROM sources").fetchall()
        if not source:
            return 0
        done, complete = source[0]
        if complete:
            return done
        assert con.execute("SELECT count(*) FROM points").fetchone()[0] == 0
        tables = {r[0] for r in con.execute("SELECT name FROM sqlite_master")}
        rows = con.execute("SELECT cell, covered, count, total FROM raster_partials ORDER BY cell").fetchall() \
            if "raster_partials" in tables else []
    finally:
        con.close()
    want = prefixes(done)
    assert [r[0] for r in rows] == want.cells.astype(np.int64).tolist()
    assert [r[1] for r in rows] == want.covered.tolist()  # the same float sums, added in the same order
    assert [r[2] for r in rows] == want.count.tolist() and [r[3] for r in rows] == want.sums[0].tolist()
    return done


@pytest.mark.slow  # about 15 s here: five child processes, four of them killed mid-ingest
def test_sigkill_during_a_raster_ingest_then_resume_exactly_once(tmp_path):
    raster = write(tmp_path / "dem.tif", field(96, 120, seed=4), nodata=-9999.0)
    level, src = open_checked(str(raster), LEVEL, MODE, None, None, None, BLOCK)
    parts = list(block_results(src, level, MODE, False, BLOCK))
    assert len(parts) == 80

    def prefixes(done):
        return combine([p for p in parts[:done] if p is not None], 1)

    db = tmp_path / "crash.db"
    with CellStore(db) as store:
        store.keep_rollups([7])
    rng = np.random.default_rng(19)
    kills, seen_done = 0, []
    for _attempt in range(4):
        proc = _start(tmp_path, db, raster)
        wait_for, seen = int(rng.integers(3, 16)), 0
        for line in proc.stdout:
            seen += line.startswith("block")
            if seen >= wait_for or line.startswith("done"):
                break
        time.sleep(float(rng.uniform(0, 0.05)))  # land anywhere: inside a block, a commit
        if proc.poll() is None:
            os.kill(proc.pid, signal.SIGKILL)
            kills += 1
        proc.wait(timeout=60)
        seen_done.append(_check_whole(db, prefixes))
    assert kills >= 3 and seen_done == sorted(seen_done) and 0 < seen_done[-1] < 80
    proc = _start(tmp_path, db, raster)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    with CellStore(db) as store:
        assert store.sources()[0]["complete"] and store.sources()[0]["rows_done"] == 80
        assert same_rows(store.conn, raster_to_cells(raster, LEVEL, mode=MODE, block_size=BLOCK))
        assert store.conn.execute("SELECT count(*) FROM raster_partials").fetchone()[0] == 0
        store.check()  # integrity, and the kept roll-ups equal the rows'
        assert store.ingest_raster(raster, LEVEL, mode=MODE, block_size=BLOCK).already_complete
