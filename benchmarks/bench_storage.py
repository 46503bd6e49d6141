"""Benchmark dggs.storage: CSV ingest throughput and query latency.

Generates a CSV of N random points (uniform on the sphere, with an integer
and a float value column) in a temporary directory, ingests it end to end
with :meth:`CellStore.ingest_csv` (streamed, default batch size), then times
roll-ups and prefix (descendant) queries.  Prints a markdown table.

Run::

    .venv/bin/python benchmarks/bench_storage.py            # 1,000,000 points
    .venv/bin/python benchmarks/bench_storage.py --rows 100000 --level 10

The "CSV reader alone" row times :func:`dggs.storage.readers_csv.csv_batches` without a store
(pyarrow parse, record and line accounting, numeric conversion).
"""

from __future__ import annotations

import argparse
import csv
import os
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

import dggs
from dggs.storage import CellStore


def make_csv(path: Path, rows: int, seed: int = 0) -> None:
    """Write ``rows`` random points (lat, lng, count, value) to ``path`` in chunks."""
    rng = np.random.default_rng(seed)
    with open(path, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["id", "lat", "lng", "count", "value"])
        for start in range(0, rows, 100_000):
            n = min(100_000, rows - start)
            lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
            lng = rng.uniform(-180, 180, n)
            count = rng.integers(0, 1000, n)
            value = rng.normal(20, 5, n)
            writer.writerows(
                zip(
                    range(start, start + n),
                    np.round(lat, 6).tolist(),
                    np.round(lng, 6).tolist(),
                    count.tolist(),
                    np.round(value, 3).tolist(),
                    strict=True,
                )
            )


def read_only(path: Path, batch_size: int) -> int:
    """Run the CSV reader over ``path`` as an ingest would (numeric types known), no store."""
    from dggs.storage.readers_csv import csv_batches

    types = {"count": "INTEGER", "value": "REAL"}
    return sum(b.consumed for b in csv_batches(path, "lat", "lng", ["count", "value"], batch_size, types=types))


def timed(fn, repeat: int = 5) -> float:
    """Median wall time of ``fn()`` in seconds."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    """Generate the CSV, ingest it, time the queries, print a markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--level", type=int, default=12)
    parser.add_argument("--batch-size", type=int, default=10_000)
    parser.add_argument("--dir", default=None, help="work directory (default: a temp dir)")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(dir=args.dir) as tmp:
        csv_path = Path(tmp) / "points.csv"
        db_path = Path(tmp) / "points.db"
        t0 = time.perf_counter()
        make_csv(csv_path, args.rows)
        gen = time.perf_counter() - t0
        size_mb = csv_path.stat().st_size / 1e6

        load_before = os.getloadavg()[0]
        t0, c0 = time.perf_counter(), time.process_time()
        with CellStore(db_path) as store:
            result = store.ingest_csv(
                csv_path, values=["count", "value"], level=args.level, batch_size=args.batch_size
            )
        ingest, cpu = time.perf_counter() - t0, time.process_time() - c0
        assert result.rows_inserted == args.rows, result

        results = [
            ("generate CSV", f"{args.rows:,} rows, {size_mb:.0f} MB", f"{gen:.2f} s"),
            (
                "ingest_csv end to end (open, hash, parse, bin, insert, index)",
                f"level {args.level}, batch {args.batch_size:,}",
                f"{ingest:.2f} s = **{args.rows / ingest:,.0f} rows/s**",
            ),
        ]
        results.append(("  CPU time of the ingest (both threads)", f"load average before: {load_before:.1f}", f"{cpu:.2f} s"))
        t0 = time.perf_counter()
        with CellStore(Path(tmp) / "text.db") as store:
            store.ingest_csv(
                csv_path, values={"id": str, "count": int, "value": float}, level=args.level,
                batch_size=args.batch_size,
            )
        t = time.perf_counter() - t0
        results.append(
            ("ingest_csv with a text column too (id:str)", f"level {args.level}", f"{t:.2f} s = **{args.rows / t:,.0f} rows/s**")
        )
        t = timed(lambda: read_only(csv_path, args.batch_size), repeat=1)
        results.append(
            ("CSV reader alone (pyarrow, no store)", f"batch {args.batch_size:,}", f"{t:.2f} s = {args.rows / t:,.0f} rows/s")
        )
        t0 = time.perf_counter()
        with CellStore(db_path) as store:
            again = store.ingest_csv(csv_path, values=["count", "value"], level=args.level)
        assert again.already_complete
        results.append(("same ingest again (hash, finds it complete)", "", f"{time.perf_counter() - t0:.2f} s"))

        rng = np.random.default_rng(1)
        lat = np.degrees(np.arcsin(rng.uniform(-1, 1, args.rows)))
        lng = rng.uniform(-180, 180, args.rows)
        value = rng.normal(20, 5, args.rows)
        t0 = time.perf_counter()
        with CellStore(Path(tmp) / "arrays.db") as store:
            store.ingest_points(lat, lng, args.level, {"value": value})
        t = time.perf_counter() - t0
        results.append(
            ("ingest_points from numpy arrays", "batch 100,000", f"{t:.2f} s = **{args.rows / t:,.0f} rows/s**")
        )

        db_mb = sum(
            os.path.getsize(str(db_path) + s) for s in ("", "-wal") if os.path.exists(str(db_path) + s)
        ) / 1e6
        results.append(("database size", "", f"{db_mb:.0f} MB"))

        with CellStore(db_path, readonly=True) as store:
            some = store.get(store.descendants("A")[0]["cell"])[0]["cell"] if store.count("A") else None
            for level in (0, 3, 6):
                t = timed(lambda level=level: store.aggregate(level, "value"), repeat=3)
                n = len(store.aggregate(level, "value", ("count",)))
                results.append((f"aggregate to level {level} (count/sum/mean/min/max)", f"{n:,} cells", f"{t * 1000:.0f} ms"))
            t = timed(lambda: store.aggregate(3, "value", cell="A0"), repeat=5)
            results.append(("aggregate under one level-1 cell to level 3", "A0", f"{t * 1000:.1f} ms"))
            for level in (2, 5, 8):
                cell = some[: level + 1] if some else "A" + "0" * level
                n = store.count(cell)
                t = timed(lambda cell=cell: store.count(cell), repeat=20)
                results.append((f"count(cell) prefix range, level {level}", f"{n:,} rows", f"{t * 1000:.2f} ms"))
                t = timed(lambda cell=cell: store.descendants(cell), repeat=5)
                results.append((f"descendants(cell), level {level}", f"{n:,} rows", f"{t * 1000:.2f} ms"))
            if some:
                t = timed(lambda: store.get(some), repeat=20)
                results.append(("get(cell) at the stored level", some, f"{t * 1000:.3f} ms"))
                k_cell = some[:9]
                t = timed(lambda: store.disk(k_cell, 2), repeat=5)
                results.append(("disk(cell, 2) at level 8", f"{len(store.disk(k_cell, 2)):,} rows", f"{t * 1000:.1f} ms"))

    print(f"\n### dggs.storage benchmark ({args.rows:,} points, dggs {dggs.__version__}, {os.cpu_count()} CPUs)\n")
    print("| operation | size | time |")
    print("|---|---|---|")
    for name, size, value in results:
        print(f"| {name} | {size} | {value} |")


if __name__ == "__main__":
    main()
