"""Compare the C hierarchy kernels (dggs._core, libdggs/src/hierarchy.c) with the numba ones, bit for bit.

Runs index/_kernel/hierarchy.py (the installed numba package) and the binding built in this worktree on random and
edge ids of every level and face (and on invalid integers where a kernel takes any), and asserts equal outputs:
levels, valid_mask, level_bounds, parents (every level), parents_up, count_children, children (every level, and
the too-short buffer), parent_of, n_desc, finer_than. Exit code 0 only if everything is equal.

    nice /work/main/.venv/bin/python libdggs/tools/compare_hierarchy.py [--n 1000000] [--seed 1]
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


def load_core():
    """Load the worktree's dggs._core by path, under its real name."""
    so = glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


def random_ids(rng: np.random.Generator, n: int, lo: int = 0, hi: int = 28) -> np.ndarray:
    """``n`` valid ids of levels lo..hi, every face, uniform digits."""
    lv = rng.integers(lo, hi + 1, n)
    v = (np.uint64(1) << np.uint64(62)) | (rng.integers(0, 20, n).astype(np.uint64) << np.uint64(57))
    v |= np.where(lv >= 1, rng.integers(1, 7, n), 0).astype(np.uint64) << np.uint64(54)
    for k in range(2, 29):
        v |= np.where(lv >= k, rng.integers(1, 4, n), 0).astype(np.uint64) << np.uint64(2 * (28 - k))
    return v


def edge_ids() -> np.ndarray:
    """Base cells, first and last cells of every level on faces 0 and 19, the deepest all-0 and all-2 cells."""
    out = []
    for face in (0, 1, 9, 10, 19):
        base = (1 << 62) | (face << 57)
        out.append(base)
        for level in range(1, 29):
            for d1, d in ((1, 1), (6, 3), (3, 2)):
                c = base | (d1 << 54)
                for k in range(2, level + 1):
                    c |= d << (2 * (28 - k))
                out.append(c)
    return np.array(out, dtype=np.uint64)


def invalid_ints(rng: np.random.Generator, n: int) -> np.ndarray:
    """Integers that are mostly not ids: random 64-bit words, and valid ids with one bit flipped."""
    a = rng.integers(0, 2**64, n // 2, dtype=np.uint64, endpoint=False)
    b = random_ids(rng, n - n // 2) ^ (np.uint64(1) << rng.integers(0, 64, n - n // 2).astype(np.uint64))
    return np.concatenate([a, b, np.array([0, 1 << 62, 1 << 63, 2**64 - 1], dtype=np.uint64)])


class Checker:
    """Counts of equal items per comparison, and the differences found."""

    def __init__(self) -> None:
        self.failed = 0
        self.counts: dict[str, int] = {}

    @staticmethod
    def equal(a, b) -> bool:
        """Same type, and bitwise the same values (arrays: dtype, shape and bytes; tuples item by item)."""
        if isinstance(a, np.ndarray):
            return (
                isinstance(b, np.ndarray) and a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()
            )
        if isinstance(a, tuple):
            return (
                isinstance(b, tuple)
                and len(a) == len(b)
                and all(Checker.equal(x, y) for x, y in zip(a, b, strict=True))
            )
        return type(a) is type(b) and a == b

    def same(self, name: str, a, b, items: int = 1) -> None:
        """Record whether numba's ``a`` equals C's ``b`` (``items`` items compared)."""
        if not self.equal(a, b):
            self.failed += 1
            if self.failed < 20:
                print(f"DIFF {name}: numba {a!r:.200} != C {b!r:.200}")
        self.counts[name] = self.counts.get(name, 0) + items

    def report(self) -> int:
        """Print the counts; 0 if all equal, else 1."""
        for name, k in self.counts.items():
            print(f"  {name:24s} {k:>12,d} items equal" if not self.failed else f"  {name:24s} {k:>12,d} items")
        print("ALL EQUAL" if not self.failed else f"{self.failed} DIFFERENCES")
        return 0 if not self.failed else 1


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    from dggs.index._kernel import hierarchy as nh

    core = load_core()
    rng = np.random.default_rng(args.seed)
    chk = Checker()
    ids = np.concatenate([edge_ids(), random_ids(rng, args.n)])
    junk = np.concatenate([invalid_ints(rng, args.n), ids[:1000]])
    rng.shuffle(junk)

    chk.same("levels", nh.levels(ids), core.levels(ids), ids.size)
    chk.same("levels[::3]", nh.levels(ids[::3]), core.levels(ids[::3]), ids[::3].size)
    chk.same("valid_mask", nh.valid_mask(junk), core.valid_mask(junk), junk.size)
    chk.same("valid_mask ids", nh.valid_mask(ids), core.valid_mask(ids), ids.size)
    for part in (ids, ids[:0], ids[5:6], ids[ids < ids[7]], random_ids(rng, 1000, 3, 9)):
        chk.same("level_bounds", tuple(nh.level_bounds(part)), tuple(core.level_bounds(part)), part.size)
    lv = nh.levels(ids)
    for level in range(29):
        sub = ids[lv >= level]
        a, b = nh.parents(sub, level), core.parents(sub, level)
        chk.same("parents", a if a[1] < 0 else a[1], b if a[1] < 0 else b[1], sub.size)
        mixed = np.concatenate([sub[:50], ids[:200]])
        chk.same("parents bad", nh.parents(mixed, level)[1], core.parents(mixed, level)[1])
    a, b = nh.parents_up(ids[lv > 0]), core.parents_up(ids[lv > 0])
    chk.same("parents_up", a[0], b[0], int((lv > 0).sum()))
    chk.same("parents_up bad", a[1], b[1])
    chk.same("parents_up bad", nh.parents_up(ids)[1], core.parents_up(ids)[1])
    for level in range(29):
        chk.same(
            "count_children", tuple(nh.count_children(ids, level)), tuple(core.count_children(ids, level)), ids.size
        )
        sub = ids[lv <= level]
        chk.same(
            "count_children", tuple(nh.count_children(sub, level)), tuple(core.count_children(sub, level)), sub.size
        )
    # children: every level, from cells 0..8 levels above it (the table, the one-level and odometer paths)
    for level in range(29):
        for up in range(0, 9):
            src = ids[lv == max(level - up, 0)][: max(1, 3000 // 3**up)]
            if level - up < 0 and up:
                continue
            total, bad = nh.count_children(src, level)
            oa = np.zeros(total + 3, dtype=np.uint64)
            ob = np.zeros(total + 3, dtype=np.uint64)
            chk.same("children bad", nh.children(src, level, oa), core.children(src, level, ob))
            chk.same("children", oa, ob, int(total))
        src = ids[(lv <= level) & (lv >= level - 3)][:2000]
        total, _ = nh.count_children(src, level)
        oa, ob = np.zeros(total, dtype=np.uint64), np.zeros(total, dtype=np.uint64)
        chk.same("children bad", nh.children(src, level, oa), core.children(src, level, ob))
        chk.same("children", oa, ob, int(total))
        # too short: both raise ValueError after the same blocks
        if total > 1:
            oa, ob = np.zeros(total - 1, dtype=np.uint64), np.zeros(total - 1, dtype=np.uint64)
            ea = eb = None
            try:
                nh.children(src, level, oa)
            except ValueError as e:
                ea = str(e)
            try:
                core.children(src, level, ob)
            except ValueError as e:
                eb = str(e)
            chk.same("children too short", ea, eb)
            chk.same("children too short", oa, ob, int(total - 1))
        # a finer cell: bad and the blocks written before it
        mixed = np.concatenate([src[:20], ids[lv > level][:1], src[20:40]])
        total, _ = nh.count_children(src[:40], level)
        oa, ob = np.zeros(total, dtype=np.uint64), np.zeros(total, dtype=np.uint64)
        chk.same("children bad", nh.children(mixed, level, oa), core.children(mixed, level, ob))
        chk.same("children", oa, ob, int(total))
    # parent_of: valid and invalid ints, levels -3..30
    po = nh.parent_of
    cells = np.concatenate([ids[:: max(1, ids.size // 200_000)], junk[:50_000] & np.uint64(2**63 - 1)]).view(np.int64)
    levels = rng.integers(-3, 31, cells.size)
    pairs = list(zip(cells.tolist(), levels.tolist(), strict=True))
    ra = [po(c, lvl) for c, lvl in pairs]
    rb = [core.parent_of(c, lvl) for c, lvl in pairs]
    chk.same("parent_of", np.array(ra, dtype=np.int64), np.array(rb, dtype=np.int64), cells.size)
    chk.same("parent_of type", type(ra[0]), type(rb[0]))
    for cl in range(29):
        for lvl in range(cl, 29):
            chk.same("n_desc", nh.n_desc(cl, lvl), core.n_desc(cl, lvl))
    for c in ids[:2000].tolist():
        for lvl in range(29):
            chk.same("finer_than", bool(nh.finer_than(np.uint64(c), lvl)), bool(core.finer_than(c, lvl)))
    return chk.report()


if __name__ == "__main__":
    sys.exit(main())
