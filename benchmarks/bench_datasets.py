"""Benchmark a named dataset against the default one (issue 38 item 5): what the table-name rewrite costs.

The same N random points (default 500,000, level 12, one REAL column) ingested with ``ingest_points`` into the
default dataset of one store and into a named dataset of another, then ``aggregate`` to level 8 and 4 and
``count`` under 200 cells; CPU time (``time.process_time``), median of rounds, cases interleaved, one thread.

Run::

    .venv/bin/python benchmarks/bench_datasets.py [--n 500000] [--rounds 3]
"""

from __future__ import annotations

import os

for _var in ("DGGS_THREADS", "NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

import dggs  # noqa: E402
from dggs.storage import CellStore  # noqa: E402


def _cpu(fn) -> float:
    start = time.process_time()
    fn()
    return time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=500_000)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, args.n))), rng.uniform(-180, 180, args.n)
    value = rng.normal(size=args.n)
    probes = dggs.latlng_to_cell(lat[:200], lng[:200], 6)
    times: dict[str, dict[str, list[float]]] = {}
    for _ in range(args.rounds):
        for dataset in (None, "named"):  # interleaved
            label = "default" if dataset is None else "named"
            with tempfile.TemporaryDirectory() as folder:
                path = Path(folder) / "b.db"
                with CellStore(path, dataset=dataset) as store:
                    case = times.setdefault(label, {})
                    case.setdefault("ingest_points", []).append(
                        _cpu(lambda s=store: s.ingest_points(lat, lng, 12, {"v": value}, source="b")))
                    case.setdefault("aggregate 8", []).append(_cpu(lambda s=store: s.aggregate(8, "v", as_table=True)))
                    case.setdefault("aggregate 4", []).append(_cpu(lambda s=store: s.aggregate(4, "v")))
                    case.setdefault("count x200", []).append(
                        _cpu(lambda s=store: [s.count(c) for c in probes]))
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                            cwd=Path(__file__).parent).stdout.strip()
    print(f"n={args.n:,} rounds={args.rounds} commit={commit} load={os.getloadavg()[0]:.2f} (CPU s, median)")
    print(f"{'case':<16}{'default':>10}{'named':>10}{'ratio':>8}")
    for case in times["default"]:
        a, b = statistics.median(times["default"][case]), statistics.median(times["named"][case])
        print(f"{case:<16}{a:>10.3f}{b:>10.3f}{b / a:>8.3f}")


if __name__ == "__main__":
    main()
