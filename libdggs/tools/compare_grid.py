"""Compare the C grid graph (dggs._core, libdggs/src/grid.c, grid_tables.c) with the numba kernel, bit for bit.

Runs index/_kernel/grid.py's functions (the installed numba package) and this worktree's binding on random
ids of every level and on edge ids (poles, antimeridian, icosahedron vertices, face corners and edges, both
projections), and asserts equal outputs. Exit code 0 only if every output is equal.

    nice python libdggs/tools/compare_grid.py [--scale 1.0] [--threads 2]
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _grid_inputs import edge_ids, level_of, load_core, random_ids, walk_pairs  # noqa: E402

from dggs.index._kernel import grid as K  # noqa: E402

FAIL = []
COUNTS = {}


def check(name: str, same: bool, items: int) -> None:
    """Count ``items`` under ``name``; remember a mismatch."""
    COUNTS[name] = COUNTS.get(name, 0) + items
    if not same:
        FAIL.append(name)
        print(f"MISMATCH {name}", flush=True)


def rows(fn, ids, k, width, n_work=None):
    """Run a disk or ring loop into fresh rows (filled with 99 first): (out, counts)."""
    out = np.full((ids.shape[0], width), 99, dtype=np.uint64)
    counts = np.full(ids.shape[0], 99, dtype=np.int64)
    fn(ids.shape[0] * width if n_work is None else n_work, ids, k, out, counts)
    return out, counts


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=20240531)
    ap.add_argument("--threads", type=int, default=2, help="the binding's threads (its batch loops' OpenMP path)")
    args = ap.parse_args()
    core = load_core()
    core.set_threads(args.threads)
    rng = np.random.default_rng(args.seed)
    t0 = time.time()
    edges = edge_ids()
    n = int(1_000_000 * args.scale)
    ids = np.concatenate([random_ids(rng, n), edges])
    coarse = np.concatenate([random_ids(rng, int(20_000 * args.scale), levels=range(0, 5)),
                             edges[level_of(edges) <= 4]])

    # neighbours, _neighbour
    a, b = np.empty((ids.shape[0], 3), np.uint64), np.zeros((ids.shape[0], 3), np.uint64)
    K.neighbours(ids, a)
    core.neighbours(ids, b)
    check("neighbours", np.array_equal(a, b), ids.shape[0])
    sub = ids[:: max(1, ids.shape[0] // 20000)]
    lv = level_of(sub)
    same = all(core._neighbour(int(c), int(level), col) == int(a_row[col])
               for c, level, a_row in zip(sub, lv, a[:: max(1, ids.shape[0] // 20000)], strict=True) for col in range(3))
    check("_neighbour", same, 3 * sub.shape[0])

    # are_neighbours: true neighbours, the cell itself, other levels, random cells of a level
    other = np.concatenate([a[:, 0], a[:, 1], ids, random_ids(rng, ids.shape[0])])
    first = np.concatenate([ids, ids, ids[::-1], ids])
    for cols in (first, other):
        assert cols.shape == first.shape
    x, y = np.empty(first.shape[0], bool), np.ones(first.shape[0], bool)
    K.are_neighbours(first, other, x)
    core.are_neighbours(first, other, y)
    check("are_neighbours", np.array_equal(x, y), first.shape[0])

    # bounds and widths
    ks = np.concatenate([np.arange(0, 20001), rng.integers(0, 1 << 31, 2000), [1 << 31, (1 << 31) - 1]])
    same = all(K.disk_size_bound(int(k)) == core.disk_size_bound(int(k)) and
               K.ring_size_bound(int(k)) == core.ring_size_bound(int(k)) for k in ks)
    check("disk_size_bound/ring_size_bound", same, 2 * ks.shape[0])
    same = all(K.disk_width(int(k), level) == core.disk_width(int(k), level) and
               K.ring_width(int(k), level) == core.ring_width(int(k), level)
               for k in ks[::20] for level in range(29))
    same = same and all(K.level_cells(level) == core.level_cells(level) for level in range(29))
    check("disk_width/ring_width/level_cells", same, 2 * 29 * ks[::20].shape[0])

    # disk and ring rows, all levels, k 0..6; coarse levels to k 40 (disks covering the level)
    per_k = int(150_000 * args.scale)
    for k in range(0, 7):
        sel = ids[rng.integers(0, ids.shape[0], per_k)]
        w = K.disk_width(k, 28)
        for name, kf, cf, width in (("disk", K.disk, core.disk, w), ("ring", K.ring, core.ring, K.ring_width(k, 28))):
            ra, rb = rows(kf, sel, k, width), rows(cf, sel, k, width)
            check(name, np.array_equal(ra[0], rb[0]) and np.array_equal(ra[1], rb[1]), sel.shape[0])
    for k in (7, 8, 10, 13, 17, 25, 40):
        sel = np.concatenate([coarse, ids[rng.integers(0, ids.shape[0], int(3000 * args.scale))]])
        w = K.disk_width(k, 28)
        for name, kf, cf, width in (("disk", K.disk, core.disk, w), ("ring", K.ring, core.ring, K.ring_width(k, 28))):
            ra, rb = rows(kf, sel, k, width), rows(cf, sel, k, width)
            check(name, np.array_equal(ra[0], rb[0]) and np.array_equal(ra[1], rb[1]), sel.shape[0])
    # rows too narrow: both raise
    for name, kf, cf in (("disk", K.disk, core.disk), ("ring", K.ring, core.ring)):
        sel = ids[:50]
        errs = []
        for fn in (kf, cf):
            try:
                rows(fn, sel, 5, 3)
                errs.append(None)
            except ValueError as e:
                errs.append(str(e))
        check(name + " (too narrow)", errs[0] == errs[1] and errs[0] is not None, sel.shape[0])

    # disk_sizes: caps that stop early and caps that do not
    for k, cap in ((3, 5), (5, 40), (10, 10**6), (30, 500), (200, 3000), (2000, 10**5), (1 << 31, 2000)):
        m = int((2000 if cap <= 10**4 else 100) * args.scale) + 1
        sel = np.concatenate([coarse[:m], ids[rng.integers(0, ids.shape[0], m)]])
        for chunk in np.array_split(sel, 8):
            ca, cb = np.zeros(chunk.shape[0], np.int64), np.zeros(chunk.shape[0], np.int64)
            ia = K.disk_sizes(chunk, k, cap, ca)
            ib = core.disk_sizes(chunk, k, cap, cb)
            check("disk_sizes", ia == ib and np.array_equal(ca, cb), chunk.shape[0])

    # disk_of: the single-id entry (misses too)
    sel = np.concatenate([edges[:: max(1, edges.shape[0] // 3000)], ids[rng.integers(0, ids.shape[0], 3000)]])
    same = True
    cnt = 0
    for c in sel.tolist():
        for k, mx in ((0, 100), (1, 100), (3, 10**6), (9, 10**6), (64, 10**7), (65, 10**7), (5, 20)):
            ra, rb = K.disk_of(c, k, mx), core.disk_of(c, k, mx)
            same = same and ra.dtype == rb.dtype and np.array_equal(ra, rb)
            cnt += 1
    for c in (0, 5, (1 << 62) | (20 << 57), (1 << 63) - 1):
        ra, rb = K.disk_of(c, 2, 100), core.disk_of(c, 2, 100)
        same = same and ra.size == 0 and rb.size == 0
    check("disk_of", same, cnt)

    # next_ring directly (rings of a few cells)
    same = True
    for c in sel[:2000]:
        prev, cur = np.empty(0, np.uint64), np.array([c], np.uint64)
        for _ in range(6):
            da, db = np.empty(3 * cur.shape[0], np.uint64), np.empty(3 * cur.shape[0], np.uint64)
            ma = K.next_ring(cur, prev, da, np.empty(3 * cur.shape[0], np.uint64))
            mb = core.next_ring(cur, prev, db, np.empty(3 * cur.shape[0], np.uint64))
            same = same and ma == mb and np.array_equal(da[:ma], db[:mb])
            short = np.empty(max(ma - 1, 0), np.uint64)
            same = same and K.next_ring(cur, prev, short.copy(), np.empty(3 * cur.shape[0], np.uint64)) == \
                core.next_ring(cur, prev, short.copy(), np.empty(3 * cur.shape[0], np.uint64))
            prev, cur = cur, da[:ma].copy()
    check("next_ring", same, 2000 * 6)

    # random walks make neighbour chains of many levels: their neighbours again
    far = walk_pairs(rng, ids[:20000], np.full(20000, 30))
    a2, b2 = np.empty((far.shape[0], 3), np.uint64), np.empty((far.shape[0], 3), np.uint64)
    K.neighbours(far, a2)
    core.neighbours(far, b2)
    check("neighbours", np.array_equal(a2, b2), far.shape[0])

    for name in COUNTS:
        print(f"{name}: {COUNTS[name]:,} items {'DIFFER' if name in FAIL else 'equal'}")
    print(f"{'FAILED: ' + ', '.join(sorted(set(FAIL))) if FAIL else 'all equal'} ({time.time() - t0:.0f} s)")
    return 1 if FAIL else 0


if __name__ == "__main__":
    sys.exit(main())
