"""Benchmark roll-ups (issue 35 item 1, issue 38 item 4): ``CellStore.aggregate`` against pandas and plain SQLite.

One store of N random points (default 1,000,000, level 12) with an INTEGER
column ``count`` and a REAL column ``value``; roll-ups to levels 10 and 6 of
all five stats, timed as CPU time (``time.process_time``, median of rounds)
with every thread count set to 1:

* ``aggregate(level, column)`` (a dict per cell) and ``as_table=True`` (columns);
* the same with the store keeping roll-ups at 10 and 6 (``keep_rollups``);
* pandas: ``groupby`` on the integer ids' parents (``dggs.cell_to_parent`` included), the rows in memory;
* plain SQLite: ``SELECT substr(cell, 1, level + 1), count(*), sum(c), avg(c), min(c), max(c) ... GROUP BY 1``
  on its own connection, rows fetched.

Run (``--storage`` runs an older ``storage/`` folder instead, e.g. one from ``git archive``)::

    .venv/bin/python benchmarks/bench_rollups.py
    git archive 987afea storage | tar -x -C /tmp/old && .venv/bin/python benchmarks/bench_rollups.py --storage /tmp/old/storage
"""

from __future__ import annotations

import os

for _var in ("DGGS_THREADS", "NUMBA_NUM_THREADS", "RAYON_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS",
             "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import importlib.util  # noqa: E402
import shutil  # noqa: E402
import sqlite3  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402

STATS = ("count", "sum", "mean", "min", "max")


def _load_storage(folder: str | None) -> Any:
    """``dggs.storage``, from ``folder`` if given (an older copy of the package's ``storage/``)."""
    import dggs

    if folder is not None:
        spec = importlib.util.spec_from_file_location(
            "dggs.storage", Path(folder) / "__init__.py", submodule_search_locations=[folder]
        )
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules["dggs.storage"] = module
        spec.loader.exec_module(module)
        dggs.storage = module  # type: ignore[attr-defined]
    import dggs.storage

    return dggs.storage


def cpu(fn: Any, rounds: int, before: Any = None) -> float:
    """Median CPU seconds of ``fn()`` over ``rounds`` calls (``before()`` untimed before each)."""
    times = []
    for _ in range(rounds):
        if before is not None:
            before()
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return statistics.median(times)


def main() -> None:
    """Build the store, time each way of rolling up, print a markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--level", type=int, default=12)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--storage", default=None, help="an older storage/ folder to time instead")
    parser.add_argument("--dir", default=None)
    args = parser.parse_args()
    storage = _load_storage(args.storage)
    import pandas as pd

    import dggs

    rng = np.random.default_rng(1)
    n = args.rows
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    counts = rng.integers(0, 1000, n)
    values = np.round(rng.normal(20, 5, n), 3)
    results: list[tuple[str, str, str, float]] = []
    with tempfile.TemporaryDirectory(dir=args.dir) as tmp:
        path = Path(tmp) / "p.db"
        with storage.CellStore(path) as store:
            store.ingest_points(lat, lng, args.level, {"count": counts, "value": values})
        kept_path = Path(tmp) / "kept.db"
        shutil.copy(path, kept_path)
        with storage.CellStore(kept_path) as store:
            t0 = time.process_time()
            store.keep_rollups([10, 6])
            keep_cpu = time.process_time() - t0
        con = sqlite3.connect(path)
        con.execute("PRAGMA threads = 0")
        cells, ints, reals = zip(*con.execute("SELECT cell, count, value FROM points"), strict=True)
        frame = pd.DataFrame({"id": np.asarray(dggs.str_to_int(np.asarray(cells)), dtype=np.uint64),
                              "count": np.asarray(ints, dtype=np.int64), "value": np.asarray(reals)})
        with storage.CellStore(path, readonly=True) as store, storage.CellStore(kept_path, readonly=True) as kept:
            for level in (10, 6):
                groups = len(store.aggregate(level, None, ("count",)))
                for column in ("value", "count"):
                    label = f"level {level} ({groups:,} cells), {column}"

                    def pandas_way(level: int = level, column: str = column) -> Any:
                        parent = np.asarray(dggs.cell_to_parent(frame["id"].to_numpy(), level))
                        return frame.groupby(parent)[column].agg(["count", "sum", "mean", "min", "max"])

                    def sql_way(level: int = level, column: str = column) -> Any:
                        return con.execute(
                            f"SELECT substr(cell, 1, {level + 1}), count(*), sum({column}), avg({column}), "
                            f"min({column}), max({column}) FROM points GROUP BY 1"
                        ).fetchall()

                    ways = {
                        "pandas groupby (int ids, cell_to_parent)": pandas_way,
                        "SQLite GROUP BY substr": sql_way,
                        "aggregate (dicts)": lambda level=level, column=column: store.aggregate(level, column, STATS),
                        "aggregate kept (dicts)": lambda level=level, column=column: kept.aggregate(level, column, STATS),
                    }
                    try:
                        store.aggregate(0, None, ("count",), as_table=True)
                        ways["aggregate as_table"] = lambda level=level, column=column: store.aggregate(
                            level, column, STATS, as_table=True)
                        ways["aggregate kept as_table"] = lambda level=level, column=column: kept.aggregate(
                            level, column, STATS, as_table=True)
                    except TypeError:
                        pass  # an older storage: no as_table
                    def forget() -> None:  # no partials remembered from the call before (rollup_memo)
                        for s in (store, kept):
                            s._store.memo.__init__()

                    for name, fn in ways.items():
                        fn()  # warm: imports, page cache
                        results.append((label, name, "", cpu(fn, args.rounds, forget)))
        con.close()
    print(f"\n### roll-ups, {n:,} rows at level {args.level}, CPU time (1 thread), median of {args.rounds}; "
          f"storage from {args.storage or 'this tree'}; keep_rollups([10, 6]) {keep_cpu:.2f} s\n")
    print("| roll-up | way | CPU s | x pandas | x SQLite |")
    print("|---|---|---|---|---|")
    base: dict[str, dict[str, float]] = {}
    for label, name, _, t in results:
        base.setdefault(label, {})[name] = t
    for label, name, _, t in results:
        pandas_t = base[label]["pandas groupby (int ids, cell_to_parent)"]
        sql_t = base[label]["SQLite GROUP BY substr"]
        print(f"| {label} | {name} | {t:.3f} | {pandas_t / t:.2f} | {sql_t / t:.2f} |")


if __name__ == "__main__":
    main()
