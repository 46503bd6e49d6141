"""The native core's point location per point, beside js/tools/bench.mjs's (the same 100,000 points).

    DGGS_THREADS=1 python js/tools/bench_native.py [FIXTURES_DIR]

dggs.latlng_to_cell(lat, lng, 17, as_int=True) on the arrays (one C loop), and on one point at a time: the process's CPU
time (DGGS_THREADS=1: one thread), best of 7 runs after a warm-up.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

import dggs


def best(fn: object, n: int, runs: int = 7) -> float:
    """Best CPU time per point in ns."""
    fn()  # type: ignore[operator]
    times = []
    for _ in range(runs):
        t0 = time.process_time_ns()
        fn()  # type: ignore[operator]
        times.append(time.process_time_ns() - t0)
    return min(times) / n


def main(folder: Path) -> None:
    """Print ns per point."""
    raw = np.fromfile(folder / "bulk.bin", dtype="<f8").reshape(6, -1)
    lat, lng = raw[0].copy(), raw[1].copy()
    n = len(lat)
    batch = best(lambda: dggs.latlng_to_cell(lat, lng, 17, as_int=True), n)
    la, ln = lat.tolist(), lng.tolist()
    one = best(lambda: [dggs.latlng_to_cell(a, b, 17, as_int=True) for a, b in zip(la, ln, strict=True)], n, 3)
    print(f"native core (dggs._core), {n} points, level 17, ns per point:")
    print(f"  latlng_to_cell on arrays         {batch:.0f}")
    print(f"  latlng_to_cell per point         {one:.0f}")


if __name__ == "__main__":
    main(Path(sys.argv[1] if len(sys.argv) > 1 else "build/js-fixtures"))
