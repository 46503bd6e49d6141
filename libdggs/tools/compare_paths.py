"""Compare the C grid paths (dggs._core: paths.c) with the numba kernel, cell for cell.

Pairs of one level reached by random walks (1..120 steps), random pairs at levels 1..8, from random ids and from the edge ids (poles,
antimeridian, icosahedron vertices, face corners and edges, both projections), and every pair of some level-0
and level-1 cells; offsets from numba's distances as index/paths.py makes them. Exit code 0 only if equal.

    nice python libdggs/tools/compare_paths.py [--scale 1.0] [--threads 2]
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _grid_inputs import edge_ids, level_of, load_core, random_ids, walk_pairs  # noqa: E402

from dggs.index._kernel import distance as KD  # noqa: E402
from dggs.index._kernel import paths as KP  # noqa: E402


def main() -> int:
    """Compare the paths; 0 if equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--threads", type=int, default=2, help="the binding's threads (its batch loops' OpenMP path)")
    args = ap.parse_args()
    core = load_core()
    core.set_threads(args.threads)
    rng = np.random.default_rng(args.seed)
    t0 = time.time()
    edges = edge_ids()
    n = int(60_000 * args.scale)
    a = np.concatenate([random_ids(rng, n), edges[:: max(1, edges.shape[0] // n)]])
    b = walk_pairs(rng, a, rng.integers(0, 120, a.shape[0]))
    m = int(20_000 * args.scale)  # far pairs at levels 1..8 (distances to hundreds)
    fa = random_ids(rng, m, levels=range(1, 9))
    fb = np.empty_like(fa)
    for level in range(1, 9):
        on = level_of(fa) == level
        fb[on] = random_ids(rng, int(on.sum()), levels=[level])
    a, b = np.concatenate([a, fa]), np.concatenate([b, fb])
    coarse = edges[level_of(edges) <= 1]
    ca, cb = np.meshgrid(coarse[:80], coarse[:80])
    a = np.concatenate([a, ca.ravel(), coarse])
    b = np.concatenate([b, cb.ravel(), coarse])
    keep = level_of(a) == level_of(b)
    a, b = a[keep], b[keep]
    dist = np.empty(a.shape[0], np.int64)
    KD.distances(a.shape[0], a, b, 1 << 40, dist)
    assert (dist >= 0).all()
    offsets = np.zeros(a.shape[0] + 1, np.int64)
    np.cumsum(dist + 1, out=offsets[1:])
    total = int(offsets[-1])
    oa, ob = np.empty(total, np.uint64), np.zeros(total, np.uint64)
    sa, sb = np.zeros(a.shape[0], np.int64), np.full(a.shape[0], 5, np.int64)
    KP.paths(total, a, b, offsets, oa, sa)
    core.paths(total, a, b, offsets, ob, sb)
    same = np.array_equal(oa, ob) and np.array_equal(sa, sb)
    # a wrong distance (one short, one long): both report -1 at the same pairs
    pick = slice(0, 2000)
    for delta in (1, -1):
        d2 = np.maximum(dist[pick] + delta, 0)
        off2 = np.zeros(d2.shape[0] + 1, np.int64)
        np.cumsum(d2 + 1, out=off2[1:])
        xa, xb = np.empty(int(off2[-1]), np.uint64), np.empty(int(off2[-1]), np.uint64)
        ta, tb = np.zeros(d2.shape[0], np.int64), np.zeros(d2.shape[0], np.int64)
        KP.paths(int(off2[-1]), a[pick], b[pick], off2, xa, ta)
        core.paths(int(off2[-1]), a[pick], b[pick], off2, xb, tb)
        ok = ta == 0
        same = same and np.array_equal(ta, tb)
        for i in np.flatnonzero(ok):  # the filled paths agree (a failed walk leaves the rest unwritten)
            same = same and np.array_equal(xa[off2[i]:off2[i + 1]], xb[off2[i]:off2[i + 1]])
    print(f"paths: {a.shape[0]:,} pairs, {total:,} cells, distances up to {dist.max()}, "
          f"{'equal' if same else 'DIFFER'}")
    print(f"{'all equal' if same else 'FAILED: paths'} ({time.time() - t0:.0f} s)")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
