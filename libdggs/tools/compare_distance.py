"""Compare the C grid distances (dggs._core: distance.c, strips.c, grid_tables.c) with the numba kernel.

distance, distances (batch), search (the fallback breadth-first search), strip_distance and chart_distance on
pairs of one level: neighbours reached by random walks of 1..200 steps, uniformly random pairs (most of them
far apart), pairs among the edge ids (poles, antimeridian, icosahedron vertices, face corners and edges, both
projections), every level 0..28. Exit code 0 only if every output is equal.

    nice python libdggs/tools/compare_distance.py [--scale 1.0] [--threads 2]
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
from dggs.index._kernel.grid_tables import chart_distance  # noqa: E402
from dggs.index._kernel.strips import strip_distance  # noqa: E402

FAIL = []
COUNTS = {}


def check(name: str, same: bool, items: int) -> None:
    """Count ``items`` under ``name``; remember a mismatch."""
    COUNTS[name] = COUNTS.get(name, 0) + items
    if not same:
        FAIL.append(name)
        print(f"MISMATCH {name}", flush=True)


def same_level_random(rng, ids):
    """Random partners at each id's level (another random id with the same level)."""
    lv = level_of(ids)
    out = np.empty_like(ids)
    for level in range(29):
        on = lv == level
        out[on] = random_ids(rng, int(on.sum()), levels=[level])
    return out


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--threads", type=int, default=2, help="the binding's threads (its batch loops' OpenMP path)")
    args = ap.parse_args()
    core = load_core()
    core.set_threads(args.threads)
    rng = np.random.default_rng(args.seed)
    t0 = time.time()
    edges = edge_ids()
    n = int(400_000 * args.scale)
    starts = np.concatenate([random_ids(rng, n), edges])
    near = walk_pairs(rng, starts, rng.integers(1, 40, starts.shape[0]))
    mid_starts = np.concatenate([random_ids(rng, n // 4), edges[:: 4]])
    mid = walk_pairs(rng, mid_starts, rng.integers(40, 200, mid_starts.shape[0]))
    far_a = np.concatenate([random_ids(rng, n), edges])
    far_b = same_level_random(rng, far_a)
    # the edge ids against each other, level by level
    lv = level_of(edges)
    ea, eb = [], []
    for level in range(29):
        e = edges[lv == level]
        if e.size:
            ea.append(e)
            eb.append(e[rng.permutation(e.size)])
    a = np.concatenate([starts, mid_starts, far_a, *ea, starts])
    b = np.concatenate([near, mid, far_b, *eb, starts])  # the last block: a cell and itself

    # distances (batch) and distance (per item) at several max_steps
    for max_steps in (1 << 40, 25, 0):
        x, y = np.empty(a.shape[0], np.int64), np.full(a.shape[0], 7, np.int64)
        KD.distances(a.shape[0], a, b, max_steps, x)
        core.distances(a.shape[0], a, b, max_steps, y)
        check("distances", np.array_equal(x, y), a.shape[0])
        if max_steps == 1 << 40:
            print(f"distances: {np.count_nonzero(x == KD.NEEDS_SEARCH)} pairs need the search; "
                  f"max {x.max()}", flush=True)
    pick = rng.integers(0, a.shape[0], int(100_000 * args.scale))
    same = all(KD.distance(a[i], b[i], 1 << 40) == core.distance(a[i], b[i], 1 << 40) for i in pick)
    check("distance", same, pick.shape[0])

    # chart_distance and strip_distance (levels >= 1), both orders
    on = level_of(a) >= 1
    pa, pb = a[on], b[on]
    pick = rng.integers(0, pa.shape[0], int(150_000 * args.scale))
    same = True
    for i in pick:
        level = int(level_of(pa[i:i + 1])[0])
        same = same and chart_distance(pa[i], pb[i], level) == core.chart_distance(pa[i], pb[i], level)
        same = same and chart_distance(pb[i], pa[i], level) == core.chart_distance(pb[i], pa[i], level)
    check("chart_distance", same, 2 * pick.shape[0])
    pick = rng.integers(0, pa.shape[0], int(150_000 * args.scale))
    same = True
    for i in pick:
        level = int(level_of(pa[i:i + 1])[0])
        same = same and strip_distance(pa[i], pb[i], level) == core.strip_distance(pa[i], pb[i], level)
    check("strip_distance", same, pick.shape[0])

    # search: the breadth-first fallback on near pairs, limits below and above the distance
    k = int(3000 * args.scale)
    sa = np.concatenate([starts[:k], edges[:: max(1, edges.shape[0] // k)]])
    sb = walk_pairs(rng, sa, rng.integers(0, 25, sa.shape[0]))
    same = True
    cnt = 0
    for i in range(sa.shape[0]):
        for m in (1 << 40, 10, 3, 0):
            same = same and KD.search(sa[i], sb[i], m) == core.search(sa[i], sb[i], m)
            cnt += 1
    check("search", same, cnt)
    # search at the coarse levels, where rings run out (far side of the level)
    lv_s = level_of(sa)
    for level in (0, 1, 2):
        e = edges[level_of(edges) == level][:60]
        same = all(KD.search(x, y, 1 << 40) == core.search(x, y, 1 << 40) for x in e for y in e[:20])
        check("search", same, e.shape[0] * min(20, e.shape[0]))
    del lv_s

    for name in COUNTS:
        print(f"{name}: {COUNTS[name]:,} items {'DIFFER' if name in FAIL else 'equal'}")
    print(f"{'FAILED: ' + ', '.join(sorted(set(FAIL))) if FAIL else 'all equal'} ({time.time() - t0:.0f} s)")
    return 1 if FAIL else 0


if __name__ == "__main__":
    sys.exit(main())
