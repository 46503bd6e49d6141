"""Compare the C child positions and local (i, j) kernels (dggs._core, libdggs/src/local.c) with the numba ones.

Runs index/_kernel/local.py (the installed numba package) and the binding built in this worktree, bit for bit:
child_pos and child_pos_cells at every parent level and level (positions in and out of range), their single-id
entries (invalid ids too), local_ij on pairs of one level 0..28 (the anchor's face, the faces across its edges,
the other 16 faces; anchors and cells at face corners and along face edges), local_cells on the (i, j) of those
pairs, off by small and large steps and at int64's extremes, and the single-id entries; the batch loops on 1 and
2 threads. Local (i, j) is planar: no projection enters. Exit code 0 only if everything is equal.

    nice /work/main/.venv/bin/python libdggs/tools/compare_local.py [--n 1000000] [--seed 3]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from compare_hierarchy import Checker, edge_ids, invalid_ints, load_core, random_ids

I64_MIN, I64_MAX = np.iinfo(np.int64).min, np.iinfo(np.int64).max


def near(rng: np.random.Generator, anchors: np.ndarray, levels: np.ndarray, face_mode: str) -> np.ndarray:
    """Cells of each anchor's level: the anchor with its last few digits redrawn, on the same face or another."""
    out = anchors.copy()
    n = anchors.size
    keep = rng.integers(1, 6, n)  # redraw the digits of the last `keep` levels
    for k in range(1, 29):
        redo = (levels >= k) & (levels - k < keep)
        if k == 1:
            d = rng.integers(1, 7, n).astype(np.uint64) << np.uint64(54)
            out = np.where(redo, (out & ~(np.uint64(7) << np.uint64(54))) | d, out)
        else:
            sh = np.uint64(2 * (28 - k))
            d = rng.integers(1, 4, n).astype(np.uint64) << sh
            out = np.where(redo, (out & ~(np.uint64(3) << sh)) | d, out)
    if face_mode != "same":
        faces = rng.integers(0, 20, n).astype(np.uint64)
        out = (out & ~(np.uint64(31) << np.uint64(57))) | (faces << np.uint64(57))
    return out


def corner_cells(levels: range) -> np.ndarray:
    """Cells at a face's three corners and along its edges (digit runs 0/1/2 under each level-1 digit)."""
    out = []
    for face in (0, 3, 7, 10, 16, 19):
        for level in levels:
            for d1 in range(6):
                for d in (0, 1, 2):
                    c = (1 << 62) | (face << 57)
                    if level >= 1:
                        c |= (d1 + 1) << 54
                    for k in range(2, level + 1):
                        c |= (d + 1) << (2 * (28 - k))
                    out.append(c)
    return np.array(sorted(set(out)), dtype=np.uint64)


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=3)
    args = ap.parse_args()
    from dggs.index._kernel import hierarchy as nh
    from dggs.index._kernel import local as nl

    core = load_core()
    rng = np.random.default_rng(args.seed)
    chk = Checker()
    n = args.n
    ids = np.concatenate([edge_ids(), corner_cells(range(29)), random_ids(rng, n)])
    lv = nh.levels(ids).astype(np.int64)

    for threads in (1, 2):
        core.set_threads(threads)
        # child positions at every parent level (a parent finer than the cell gives -1)
        for p in range(29):
            sub = ids[:: 7 if p % 4 else 1]
            a, b = np.empty(sub.size, np.int64), np.empty(sub.size, np.int64)
            nl.child_pos(sub.size, sub, p, a)
            core.child_pos(sub.size, sub, p, b)
            chk.same(f"child_pos t{threads}", a, b, sub.size)
        # child_pos_cells: positions in range, at its ends, past them, negative, and huge
        for level in range(29):
            sub = ids[(lv <= level)][: n // 20]
            count = np.array([nl.child_count(int(p), level) for p in range(29)], dtype=np.int64)
            c = count[nh.levels(sub).astype(np.int64)]
            pos = (rng.random(sub.size) * c).astype(np.int64)
            pick = rng.integers(0, 6, sub.size)
            pos = np.where(pick == 1, c - 1, pos)
            pos = np.where(pick == 2, c, pos)
            pos = np.where(pick == 3, -1 - rng.integers(0, 5, sub.size), pos)
            pos = np.where(pick == 4, I64_MAX - rng.integers(0, 5, sub.size), pos)
            pos = np.where(pick == 5, 0, pos)
            for parents, positions in ((sub, pos), (ids[:2000], pos[:2000])):  # finer parents give 0 too
                m = min(parents.size, positions.size)
                a, b = np.empty(m, np.uint64), np.empty(m, np.uint64)
                nl.child_pos_cells(m, positions[:m], parents[:m], level, a)
                core.child_pos_cells(m, positions[:m], parents[:m], level, b)
                chk.same(f"child_pos_cells t{threads}", a, b, m)
            # strided and broadcast inputs, as numba takes any strides
            a, b = np.empty(sub.size // 2, np.uint64), np.empty(sub.size // 2, np.uint64)
            nl.child_pos_cells(a.size, pos[::2][: a.size], sub[::2][: a.size], level, a)
            core.child_pos_cells(b.size, pos[::2][: b.size], sub[::2][: b.size], level, b)
            chk.same(f"child_pos_cells strided t{threads}", a, b, a.size)

        # local (i, j): pairs on the same face, on any face, and corner / edge cells against each other
        for level in range(29):
            anchors = np.concatenate([ids[lv == level][: n // 29], corner_cells(range(level, level + 1))])
            levels = np.full(anchors.size, level)
            cells = np.concatenate(
                [near(rng, anchors, levels, "same"), near(rng, anchors, levels, "any"), anchors[::-1]]
            )
            anc = np.concatenate([anchors, anchors, anchors])
            ia, ja = np.empty(anc.size, np.int64), np.empty(anc.size, np.int64)
            ib, jb = np.empty(anc.size, np.int64), np.empty(anc.size, np.int64)
            nl.local_ij(anc.size, anc, cells, ia, ja)
            core.local_ij(anc.size, anc, cells, ib, jb)
            chk.same(f"local_ij t{threads}", (ia, ja), (ib, jb), anc.size)
            # local_cells on those pairs' (i, j), off by steps, far away, and at int64's ends
            ok = ia != nl.OUT_OF_RANGE
            ii, jj, aa = ia[ok], ja[ok], anc[ok]
            step = rng.integers(-2, 3, (2, ii.size))
            far = rng.integers(-(3 ** min(level, 38) // 1), 3 ** min(level, 38) // 1 + 1, (2, ii.size))
            extreme = rng.choice(np.array([I64_MIN, I64_MIN + 1, -1, 0, 1, I64_MAX - 1, I64_MAX]), (2, ii.size))
            for di, dj in ((0, 0), (step[0], step[1]), (far[0], far[1])):
                qi, qj = ii + di, jj + dj
                a, b = np.empty(aa.size, np.uint64), np.empty(aa.size, np.uint64)
                nl.local_cells(aa.size, aa, qi, qj, a)
                core.local_cells(aa.size, aa, qi, qj, b)
                chk.same(f"local_cells t{threads}", a, b, aa.size)
            m = min(aa.size, 2000)
            a, b = np.empty(m, np.uint64), np.empty(m, np.uint64)
            nl.local_cells(m, aa[:m], extreme[0][:m], extreme[1][:m], a)
            core.local_cells(m, aa[:m], extreme[0][:m], extreme[1][:m], b)
            chk.same(f"local_cells extreme t{threads}", a, b, m)
    core.set_threads(1)

    # the single-id entries, on valid and invalid ints
    junk = invalid_ints(rng, 20_000) & np.uint64(I64_MAX)
    sample = np.concatenate([ids[:: max(1, ids.size // 30_000)], junk]).view(np.int64).tolist()
    plv = rng.integers(0, 29, len(sample)).tolist()
    chk.same(
        "one_child_pos",
        [nl.one_child_pos(c, p) for c, p in zip(sample, plv, strict=True)],
        [core.one_child_pos(c, p) for c, p in zip(sample, plv, strict=True)],
        len(sample),
    )
    pos = rng.integers(-3, 50, len(sample)).tolist()
    chk.same(
        "one_child_cell",
        [nl.one_child_cell(c, q, p) for c, q, p in zip(sample, pos, plv, strict=True)],
        [core.one_child_cell(c, q, p) for c, q, p in zip(sample, pos, plv, strict=True)],
        len(sample),
    )
    others = (
        np.concatenate([near(rng, ids[:: max(1, ids.size // 30_000)], lv[:: max(1, ids.size // 30_000)], "any"), junk])
        .view(np.int64)
        .tolist()
    )
    chk.same(
        "one_local_ij",
        [nl.one_local_ij(a, c) for a, c in zip(sample, others, strict=True)],
        [core.one_local_ij(a, c) for a, c in zip(sample, others, strict=True)],
        len(sample),
    )
    ijs = rng.integers(-40, 41, (2, len(sample))).tolist()
    chk.same(
        "one_local_cell",
        [nl.one_local_cell(a, i, j) for a, i, j in zip(sample, ijs[0], ijs[1], strict=True)],
        [core.one_local_cell(a, i, j) for a, i, j in zip(sample, ijs[0], ijs[1], strict=True)],
        len(sample),
    )
    for p in range(29):
        for level in range(29):
            chk.same("child_count", nl.child_count(p, level), core.child_count(p, level))
    chk.same("UNFOLD_FACE", nl.UNFOLD_FACE, core.local_unfold_face(), 60)
    return chk.report()


if __name__ == "__main__":
    sys.exit(main())
