"""Compare the C compaction kernels (dggs._core, libdggs/src/compact.c) with the numba ones, bit for bit.

Runs index/_kernel/compact.py (the installed numba package) and the binding built in this worktree on cell soups
(complete and incomplete sibling sets at every level, duplicates, cells inside others, sorted and shuffled, below
and above the radix sort's 4096 ids) and asserts equal outputs of compact, uncompact_prepare, uncompact,
_radix_sort and _sorted. Exit code 0 only if everything is equal.

    nice /work/main/.venv/bin/python libdggs/tools/compare_compact.py [--n 1000000] [--seed 2]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from compare_hierarchy import Checker, edge_ids, load_core, random_ids


def soup(rng: np.random.Generator, nh, n: int, level: int) -> np.ndarray:
    """About ``n`` shuffled ids: descendants at ``level`` of random cells, some dropped, and coarser cells.

    Some complete sibling sets are replaced by their parents; a twentieth of the ids are repeated.
    """
    parts = []
    size = 0
    while size < n:
        up = int(rng.integers(1, 6))
        top = random_ids(rng, 1, max(level - up, 0), max(level - up, 0))
        total, _ = nh.count_children(top, level)
        kids = np.empty(total, dtype=np.uint64)
        nh.children(top, level, kids)
        keep = rng.random(kids.size) > rng.choice([0.0, 0.0, 0.02, 0.3])
        kids = kids[keep]
        if rng.random() < 0.3 and kids.size:  # some complete sets replaced by their parents
            lv = max(level - 1, 0)
            kids = np.concatenate([kids, nh.parents(kids[: max(1, kids.size // 4)], lv)[0]])
        parts.append(kids)
        size += kids.size
    s = np.concatenate(parts + [random_ids(rng, max(1, n // 50), 0, level)])
    s = np.concatenate([s, s[rng.integers(0, s.size, s.size // 20)]])
    rng.shuffle(s)
    return s


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=2)
    args = ap.parse_args()
    from dggs.index._kernel import compact as nc
    from dggs.index._kernel import hierarchy as nh

    core = load_core()
    rng = np.random.default_rng(args.seed)
    chk = Checker()
    done = 0
    cases = []
    for level in range(29):
        for n in (1, 2, 7, 50, 700, 5000):
            cases.append((level, n))
    for level in (1, 2, 5, 9, 17, 28):
        cases.append((level, 60_000))
    for level, n in cases:
        s = soup(rng, nh, n, level)
        for arr in (s, np.sort(s), s[::-1].copy(), s[::2]):
            chk.same("compact", nc.compact(arr), core.compact(arr), arr.size)
            for target in sorted({level, min(level + 1, 28), min(level + 2, 28), max(level - 1, 0)}):
                a, b = nc.uncompact_prepare(arr, target), core.uncompact_prepare(arr, target)
                chk.same("uncompact_prepare", a, b, arr.size)
                if a[2] < 0 and a[1] <= 4_000_000:
                    chk.same("uncompact", nc.uncompact(arr, target), core.uncompact(arr, target), int(a[1]))
                elif a[2] >= 0:
                    chk.same("uncompact bad", nc.uncompact(arr, target), core.uncompact(arr, target))
            done += arr.size
    # the full sets of a few cells, compacted back to them (the recursion to a base cell)
    for top in edge_ids()[::7]:
        lv = int(nh.levels(top[None])[0])
        target = min(lv + 4, 28)
        total, _ = nh.count_children(top[None], target)
        kids = np.empty(total, dtype=np.uint64)
        nh.children(top[None], target, kids)
        rng.shuffle(kids)
        chk.same("compact", nc.compact(kids), core.compact(kids), kids.size)
    # all 120 level-1 cells: the 20 faces
    l1 = np.array([(1 << 62) | (f << 57) | (d << 54) for f in range(20) for d in range(1, 7)], dtype=np.uint64)
    chk.same("compact", nc.compact(l1[::-1].copy()), core.compact(l1[::-1].copy()), l1.size)
    e = np.empty(0, dtype=np.uint64)
    chk.same("compact empty", nc.compact(e), core.compact(e))
    chk.same("uncompact empty", nc.uncompact(e, 5), core.uncompact(e, 5))
    chk.same("uncompact_prepare empty", nc.uncompact_prepare(e, 5), core.uncompact_prepare(e, 5))
    # the sort helpers on any keys: every span of differing bits and position, large and small inputs
    big = random_ids(rng, args.n)
    chk.same("_radix_sort", nc._radix_sort(big), core._compact_radix_sort(big), big.size)
    chk.same("_sorted", nc._sorted(big), core._compact_sorted(big), big.size)
    chk.same("_sorted sorted", nc._sorted(np.sort(big)), core._compact_sorted(np.sort(big)), big.size)
    for span in range(1, 65):
        for low in sorted({0, 64 - span, (64 - span) // 2}):
            for n in (3000, 5000):
                keys = rng.integers(0, 2**63, n, dtype=np.uint64) << np.uint64(1)
                keys |= rng.integers(0, 2, n, dtype=np.uint64)
                keys = (keys >> np.uint64(64 - span)) << np.uint64(low)
                chk.same("_radix_sort keys", nc._radix_sort(keys), core._compact_radix_sort(keys), n)
                chk.same("_sorted keys", nc._sorted(keys), core._compact_sorted(keys), n)
    same = np.full(5000, big[0], dtype=np.uint64)
    chk.same("_radix_sort same", nc._radix_sort(same), core._compact_radix_sort(same), same.size)
    # compact on a large shuffled soup of valid ids (the radix path)
    chk.same("compact big", nc.compact(big), core.compact(big), big.size)
    print(f"{done:,d} soup ids")
    return chk.report()


if __name__ == "__main__":
    sys.exit(main())
