"""CSV ingest now against the hand-written parser it replaced, in one run, cases interleaved.

Issue 11 replaced dggs's own CSV parser with pyarrow's streaming reader and
asked that ingesting 1M CSV rows get faster, measured against the code of the
day in one run.  This script rebuilds that code from git (commit ``d399663^``,
the last one with the hand-written parser) as a package in a temporary
directory, writes one CSV of random points, and runs ``CellStore.ingest_csv``
of the same file with both versions, alternating (old, new, old, new, ...),
each in a fresh process that first ingests a 1,000-row file so that imports
and first calls are not timed.  Prints a markdown table of medians
(wall and CPU time) and the ratio old / new (above 1: the new code is faster).

Run::

    .venv-bench/bin/python benchmarks/bench_ingest.py                 # 1,000,000 rows, 3 rounds
    .venv-bench/bin/python benchmarks/bench_ingest.py --rows 100000 --rounds 1
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_storage import make_csv  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
BASELINE = "d399663^"

#: One ingest in a fresh process: warm up on a small file, then time the big one.
CHILD = r"""
import json, os, sys, time
if sys.argv[1]:
    sys.path.insert(0, sys.argv[1])
from dggs.storage import CellStore
values = json.loads(sys.argv[5])
values = {k: {"str": str, "int": int, "float": float}[v] for k, v in values.items()}
with CellStore(sys.argv[4] + ".warm") as store:
    store.ingest_csv(sys.argv[3], values=values, level=12)
t0, c0 = time.perf_counter(), time.process_time()
with CellStore(sys.argv[4]) as store:
    result = store.ingest_csv(sys.argv[2], values=values, level=12)
print(json.dumps({"wall": time.perf_counter() - t0, "cpu": time.process_time() - c0,
                  "rows": result.rows_inserted}))
"""


def build_baseline(rev: str, into: Path) -> Path:
    """Lay out the package of commit ``rev`` as setuptools would install it; return its parent."""
    src = into / "src"
    src.mkdir()
    archive = subprocess.run(["git", "archive", rev], cwd=ROOT, check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(src)], input=archive, check=True)
    lib = into / "lib"
    shutil.copytree(src / "dggs", lib / "dggs")
    shutil.copytree(src / "index", lib / "dggs" / "index")  # package-dir mapping of pyproject.toml
    shutil.copytree(src / "storage", lib / "dggs" / "storage")
    return lib


def ingest(lib: str, csv: Path, warm: Path, db: Path, values: dict[str, str]) -> dict:
    """Run one timed ingest in a fresh process (``lib`` empty: the installed dggs)."""
    for path in (db, Path(f"{db}.warm")):
        for suffix in ("", "-wal", "-shm"):
            Path(f"{path}{suffix}").unlink(missing_ok=True)
    out = subprocess.run(
        [sys.executable, "-c", CHILD, lib, str(csv), str(warm), str(db), json.dumps(values)],
        check=True, capture_output=True, text=True, cwd=db.parent,
    ).stdout
    return json.loads(out.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline", default=BASELINE, help="git revision of the old code")
    args = ap.parse_args()

    cases = {
        "numbers (count:int, value:float)": {"count": "int", "value": "float"},
        "with a text column (id:str, count, value)": {"id": "str", "count": "int", "value": "float"},
    }
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        old_lib = str(build_baseline(args.baseline, work))
        csv, warm = work / "points.csv", work / "warm.csv"
        make_csv(csv, args.rows)
        make_csv(warm, 1_000, seed=1)
        times: dict[tuple[str, str], list[dict]] = {}
        for _ in range(args.rounds):
            for case, values in cases.items():
                for side, lib in (("old", old_lib), ("new", "")):
                    run = ingest(lib, csv, warm, work / "store.db", values)
                    assert run["rows"] == args.rows, run
                    times.setdefault((case, side), []).append(run)
                    print(f"  {case} {side}: {run['wall']:.2f} s", file=sys.stderr, flush=True)

    print(f"### CSV ingest against the hand-written parser ({args.rows:,} rows, level 12, batch 10,000)\n")
    print(f"Old: commit `{args.baseline}` (the last with dggs's own CSV parser), rebuilt from git; new: this tree. "
          f"Each ingest in a fresh process after a 1,000-row warm-up, {args.rounds} rounds, old and new "
          f"alternating; medians. Load average at the end: {os.getloadavg()[0]:.2f}.\n")
    print("| case | old wall | new wall | old CPU | new CPU | **old / new (wall)** | old / new (CPU) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for case in cases:
        old = times[(case, "old")]
        new = times[(case, "new")]
        ow, nw = (statistics.median(r["wall"] for r in s) for s in (old, new))
        oc, nc = (statistics.median(r["cpu"] for r in s) for s in (old, new))
        print(f"| {case} | {ow:.2f} s | {nw:.2f} s | {oc:.2f} s | {nc:.2f} s | **{ow / nw:.2f}x** | {oc / nc:.2f}x |")
    print()


if __name__ == "__main__":
    main()
