"""Compiled hierarchy kernels (``dggs.index._kernel.hierarchy``) against a pure-Python string oracle.

The oracle and the str <-> int conversion are written here from the layout in
docs/grid.md ("Integer ids"), independently of the code under test: bit 62
marker, face in bits 61..57, level-1 code (digit + 1) in bits 56..54, the
level-k code (digit + 1) at bit ``2 * (28 - k)`` for k >= 2.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from dggs.index._kernel import compact as KC
from dggs.index._kernel import hierarchy as K

MAX_LEVEL = 28
FACES = "ABCDEFGHIJKLMNOPQRST"


# --------------------------------------------------------------------------- conversion


def s2i(cell: str) -> int:
    """String id -> int id, straight from the layout."""
    v = (1 << 62) | (FACES.index(cell[0]) << 57)
    if len(cell) > 1:
        v |= (int(cell[1]) + 1) << 54
    for k in range(2, len(cell)):
        v |= (int(cell[k]) + 1) << (2 * (MAX_LEVEL - k))
    return v


def i2s(v: int) -> str:
    """Int id -> string id (assumes a well-formed id)."""
    v = int(v)
    out = FACES[(v >> 57) & 31]
    code = (v >> 54) & 7
    if code:
        out += str(code - 1)
        for k in range(2, MAX_LEVEL + 1):
            code = (v >> (2 * (MAX_LEVEL - k))) & 3
            if not code:
                break
            out += str(code - 1)
    return out


def arr(cells: list[str]) -> np.ndarray:
    return np.array([s2i(c) for c in cells], dtype=np.uint64)


def strs(ids: np.ndarray) -> list[str]:
    return [i2s(v) for v in ids.tolist()]


# --------------------------------------------------------------------------- oracle


def o_level(cell: str) -> int:
    return len(cell) - 1


def o_parent(cell: str, level: int) -> str:
    return cell[: level + 1]


def o_children(cell: str, level: int) -> list[str]:
    """Descendants at ``level`` in depth-first (id) order: suffixes over "012345" then "012"."""
    if o_level(cell) == level:
        return [cell]
    digits = "012345" if len(cell) == 1 else "012"
    return [g for d in digits for g in o_children(cell + d, level)]


def o_count(cell: str, level: int) -> int:
    """Number of descendants at ``level``, without listing them."""
    d = level - o_level(cell)
    return 6 * 3 ** (d - 1) if o_level(cell) == 0 and d > 0 else 3**d


def o_compact(cells: list[str]) -> list[str]:
    """Drop covered cells and merge complete sibling sets until nothing changes (by sets)."""
    s = set(cells)
    while True:
        s = {c for c in s if not any(c[:k] in s for k in range(1, len(c)))}
        by_parent: dict[str, set[str]] = defaultdict(set)
        for c in s:
            if len(c) > 1:
                by_parent[c[:-1]].add(c)
        full = [p for p, kids in by_parent.items() if len(kids) == (6 if len(p) == 1 else 3)]
        if not full:
            return sorted(s)
        for p in full:
            s -= by_parent[p]
            s.add(p)


def o_uncompact(cells: list[str], level: int) -> list[str]:
    return sorted({g for c in cells for g in o_children(c, level)})


# --------------------------------------------------------------------------- strategies


@st.composite
def cells(draw, min_level: int = 0, max_level: int = MAX_LEVEL, faces: str = FACES) -> str:
    """A random valid string id, digit by digit."""
    lv = draw(st.integers(min_level, max_level))
    out = draw(st.sampled_from(faces))
    if lv >= 1:
        out += str(draw(st.integers(0, 5)))
    for _ in range(lv - 1):
        out += str(draw(st.integers(0, 2)))
    return out


@st.composite
def cells_with_depth(draw, max_depth: int = 5) -> tuple[list[str], int]:
    """A few cells and a target level at most ``max_depth`` below the finest of them."""
    cs = draw(st.lists(cells(), min_size=1, max_size=4))
    top = max(map(o_level, cs))
    level = draw(st.integers(top, min(MAX_LEVEL, top + max_depth)))
    # keep the output small: no cell goes more than max_depth levels down (the finest never does)
    return [c for c in cs if level - o_level(c) <= max_depth], level


@st.composite
def cell_soups(draw, min_level: int = 0, max_level: int = MAX_LEVEL - 2) -> list[str]:
    """Overlapping cell sets: complete sibling groups, whole subtrees, duplicates, cells with ancestors.

    Seeds lie at levels ``min_level .. max_level`` (<= 26) on faces C and T; the
    soup holds cells up to two levels finer and two levels coarser.
    """
    out: list[str] = []
    for _ in range(draw(st.integers(1, 6))):
        seed = draw(cells(min_level=min_level, max_level=max_level, faces="CT"))
        kind = draw(st.integers(0, 5))
        if kind == 0:
            out.append(seed)
        elif kind == 1:  # a complete sibling group
            out += o_children(seed, o_level(seed) + 1)
        elif kind == 2:  # a whole subtree two levels down, minus maybe one cell
            group = o_children(seed, o_level(seed) + 2)
            if draw(st.booleans()):
                group.pop(draw(st.integers(0, len(group) - 1)))
            out += group
        elif kind == 3:  # a cell together with one of its descendants and an ancestor
            kid = seed + str(draw(st.integers(0, 5 if len(seed) == 1 else 2)))
            out += [seed, kid, seed[: max(1, len(seed) - draw(st.integers(0, 2)))]]
        elif kind == 4:  # duplicates
            out += [seed] * draw(st.integers(2, 3))
        else:  # a sibling group with one member replaced by one of its children
            group = o_children(seed, o_level(seed) + 1)
            j = draw(st.integers(0, len(group) - 1))
            group[j] += str(draw(st.integers(0, 2)))
            out += group
    return draw(st.permutations(out))


# --------------------------------------------------------------------------- conversion sanity


def test_conversion_pinned():
    # docs/grid.md: the level-k code sits at bit 2 * (28 - k), so level 2 at bit 52, level 3 at 50
    assert s2i("C401") == (1 << 62) | (2 << 57) | ((4 + 1) << 54) | ((0 + 1) << 52) | ((1 + 1) << 50)
    assert s2i("C401") == 4996743786567565312
    assert s2i("A") == 1 << 62
    assert s2i("T") == (1 << 62) | (19 << 57)
    assert s2i("A0" + "2" * 27) == (1 << 62) | (1 << 54) | sum(3 << (2 * (28 - k)) for k in range(2, 29))
    assert i2s(s2i("T5" + "1" * 27)) == "T5" + "1" * 27


@given(st.lists(cells(), min_size=2, max_size=20))
def test_int_order_is_string_order(cs):
    assert sorted(cs) == [i2s(v) for v in sorted(s2i(c) for c in cs)]


# --------------------------------------------------------------------------- levels, validity


@given(st.lists(cells(), max_size=20))
def test_levels(cs):
    out = K.levels(arr(cs))
    assert out.dtype in (np.uint8, np.int8)
    assert out.tolist() == [o_level(c) for c in cs]


def test_levels_and_bounds_pinned():
    cs = ["A", "C4", "C401", "T5" + "2" * 27]
    assert K.levels(arr(cs)).tolist() == [0, 1, 3, 28]
    assert tuple(K.level_bounds(arr(cs))) == (0, 28)
    assert tuple(K.level_bounds(arr(["C40", "C4012"]))) == (2, 4)
    assert tuple(K.level_bounds(np.empty(0, dtype=np.uint64))) == (-1, -1)


@given(st.lists(cells(), max_size=20))
def test_valid_mask_accepts_ids(cs):
    assert K.valid_mask(arr(cs)).all()


def test_valid_mask_rejects():
    good = s2i("C401")
    bad = [
        0,
        good | (1 << 63),  # bit 63 set
        good & ~(1 << 62),  # marker clear
        (1 << 63) - 1,  # all ones below bit 63: face 31, level-1 code 7
        *[(1 << 62) | (f << 57) for f in range(20, 32)],  # face 20..31
        (1 << 62) | (7 << 54),  # level-1 code 7
        (1 << 62) | (2 << 57) | (7 << 54) | (1 << 52),
        (1 << 62) | (1 << 52),  # level-2 digit under an empty level-1 field
        s2i("C4") | (1 << 50),  # level 3 filled, level 2 empty
        s2i("C40") | (2 << 0),  # level 28 filled below empty levels 3..27
        s2i("C4" + "0" * 25) | (1 << 0),  # levels 2..26 and 28 filled, level 27 empty
    ]
    ok = [s2i("A"), s2i("T"), s2i("T5"), s2i("C401"), s2i("A0" + "2" * 27)]
    got = K.valid_mask(np.array(bad + ok, dtype=np.uint64)).tolist()
    assert got == [False] * len(bad) + [True] * len(ok)


# --------------------------------------------------------------------------- parents


@given(st.lists(cells(min_level=5), min_size=1, max_size=20), st.integers(0, 5))
def test_parents_are_prefixes(cs, level):
    out, bad = K.parents(arr(cs), level)
    assert bad == -1
    assert strs(out) == [o_parent(c, level) for c in cs]


@given(st.lists(cells(), min_size=1, max_size=20), st.integers(0, MAX_LEVEL))
def test_parents_level_error_is_first_offender(cs, level):
    out, bad = K.parents(arr(cs), level)
    offenders = [i for i, c in enumerate(cs) if o_level(c) < level]
    if offenders:
        assert bad == offenders[0]
    else:
        assert bad == -1
        assert strs(out) == [o_parent(c, level) for c in cs]


def test_parents_pinned():
    deep = "T5" + "2" * 27  # level 28, face T
    out, bad = K.parents(arr(["C401", deep, "A", "T5"]), 0)
    assert bad == -1 and strs(out) == ["C", "T", "A", "T"]
    out, bad = K.parents(arr([deep, "C4"]), 1)
    assert bad == -1 and strs(out) == ["T5", "C4"]
    out, bad = K.parents(arr([deep]), 28)
    assert bad == -1 and strs(out) == [deep]
    out, bad = K.parents(arr([deep]), 27)
    assert bad == -1 and strs(out) == [deep[:-1]]
    assert K.parents(arr(["C401", "C4", "A"]), 2)[1] == 1
    assert K.parents(arr(["C401", "A"]), 1)[1] == 1


@given(st.lists(cells(min_level=1), min_size=1, max_size=20))
def test_parents_up(cs):
    out, bad = K.parents_up(arr(cs))
    assert bad == -1
    assert strs(out) == [c[:-1] for c in cs]


def test_parents_up_pinned():
    out, bad = K.parents_up(arr(["A0", "T5" + "2" * 27, "C401"]))
    assert bad == -1 and strs(out) == ["A", "T5" + "2" * 26, "C40"]
    assert K.parents_up(arr(["C401", "C4", "T", "A"]))[1] == 2


# --------------------------------------------------------------------------- children


def run_children(cs: list[str], level: int) -> list[str]:
    ids = arr(cs)
    total, bad = K.count_children(ids, level)
    assert bad == -1
    out = np.zeros(total, dtype=np.uint64)
    assert K.children(ids, level, out) == -1
    return strs(out)


@given(cells_with_depth())
def test_children_match_oracle(case):
    cs, level = case
    expected = [g for c in cs for g in o_children(c, level)]
    assert K.count_children(arr(cs), level) == (len(expected), -1)
    assert run_children(cs, level) == expected


@pytest.mark.parametrize(
    ("cell", "level"),
    [
        ("A", 0),
        ("A", 1),
        ("A", 2),
        ("T", 3),
        ("A", 8),  # odometer above the 6-level table, under a base cell
        ("C4", 1),
        ("C4", 2),
        ("T5", 12),  # 3**11 cells: odometer carries across 5 fields
        ("C401", 10),
        ("T5" + "2" * 26, 28),
        ("T5" + "2" * 27, 28),
        ("A0" + "1" * 19, 28),  # level 20 -> 28: table + odometer at the bottom of the id
    ],
)
def test_children_pinned(cell, level):
    expected = o_children(cell, level)
    n = o_count(cell, level)
    assert len(expected) == n
    assert K.count_children(arr([cell]), level) == (n, -1)
    assert run_children([cell], level) == expected


def test_children_literal():
    assert run_children(["C401"], 4) == ["C4010", "C4011", "C4012"]
    assert run_children(["T"], 1) == ["T0", "T1", "T2", "T3", "T4", "T5"]
    assert run_children(["C4012", "A"], 1 + 4)[:4] == ["C40120", "C40121", "C40122", "A00000"]


def test_children_level_errors():
    ids = arr(["C4", "A", "C401", "C40", "C4012"])
    assert K.count_children(ids, 2)[1] == 2
    out = np.zeros(100, dtype=np.uint64)
    assert K.children(ids, 2, out) == 2
    assert K.count_children(ids, 3)[1] == 4
    assert K.count_children(arr(["A0" + "0" * 27]), 27)[1] == 0


def test_children_buffer_too_short():
    with pytest.raises(ValueError, match="too short"):
        K.children(arr(["C4"]), 3, np.zeros(8, dtype=np.uint64))


def test_count_children_saturates():
    ids = np.full(300_000, s2i("A"), dtype=np.uint64)  # 300k * 6 * 3**27 > 2**63
    assert K.count_children(ids, 28) == (2**63 - 1, -1)
    assert K.count_children(ids[:2], 28) == (2 * 6 * 3**27, -1)


def test_empty_inputs():
    e = np.empty(0, dtype=np.uint64)
    assert K.levels(e).size == 0 and K.valid_mask(e).size == 0
    assert K.parents(e, 3)[0].size == 0 and K.parents_up(e)[1] == -1
    assert K.count_children(e, 5) == (0, -1)
    assert K.children(e, 5, e) == -1
    assert KC.compact(e).size == 0
    out, bad = KC.uncompact(e, 5)
    assert out.size == 0 and bad == -1


# --------------------------------------------------------------------------- compact


@given(cell_soups())
def test_compact_matches_set_oracle(cs):
    out = KC.compact(arr(cs))
    assert out.dtype == np.uint64
    assert strs(out) == o_compact(cs)
    assert np.all(out[1:] > out[:-1])


@given(st.lists(cells(), max_size=30))
def test_compact_random_cells(cs):
    assert strs(KC.compact(arr(cs))) == o_compact(cs)


def test_compact_pinned():
    assert strs(KC.compact(arr(["C4010", "C4011", "C4012", "C402"]))) == ["C401", "C402"]
    assert strs(KC.compact(arr(["A0", "A1", "A2", "A3", "A4", "A5"]))) == ["A"]
    assert strs(KC.compact(arr(["A0", "A1", "A2", "A3", "A4"]))) == ["A0", "A1", "A2", "A3", "A4"]
    # the first and last siblings present, a middle one only in part: no merge
    assert strs(KC.compact(arr(["C40", "C411", "C42"]))) == ["C40", "C411", "C42"]
    partial = ["A0", "A1", "A2", "A3", "A41", "A5"]
    assert strs(KC.compact(arr(partial))) == partial
    assert strs(KC.compact(arr(["A0", "A1", "A2", "A3", "A40", "A41", "A42", "A5"]))) == ["A"]
    # a merged parent completes its own set, through the level-1 sextet into the base cell
    assert strs(KC.compact(arr(o_children("T", 4)))) == ["T"]
    assert strs(KC.compact(arr(["C40", "C410", "C411", "C412", "C42"]))) == ["C4"]
    all_level1 = [f + d for f in FACES for d in "012345"]
    assert strs(KC.compact(arr(all_level1[::-1]))) == list(FACES)
    deep = "T5" + "2" * 26
    assert strs(KC.compact(arr(o_children(deep, 28)[::-1] + [deep + "1"]))) == [deep]
    assert strs(KC.compact(arr(["C401", "C4", "C4", "C40122", "A"]))) == ["A", "C4"]


def test_compact_large_shuffled():
    """Above the radix-sort threshold: a subtree uncompacted 6 levels plus noise, shuffled."""
    rng = np.random.default_rng(7)
    cs = o_children("C40", 8) + o_children("T51", 7)[:-1] + o_children("A3", 6)
    noise = ["".join([FACES[rng.integers(20)], str(rng.integers(6))] + [str(d) for d in rng.integers(0, 3, 8)])
             for _ in range(500)]
    noise += ["T5" + "".join(str(d) for d in rng.integers(0, 3, 27)) for _ in range(200)]
    cs = cs + noise + cs[:100]
    ids = arr(cs)
    rng.shuffle(ids)
    out = KC.compact(ids)
    assert strs(out) == o_compact(cs)
    cells_, total, bad = KC.uncompact_prepare(ids, 28)
    kept = np.unique(ids)[_not_covered(np.unique(ids))]
    assert bad == -1 and np.array_equal(cells_, kept)
    assert total == sum(o_count(c, 28) for c in strs(kept))


def _not_covered(sorted_ids: np.ndarray) -> np.ndarray:
    """Mask of the sorted ids that no other id in the list is a proper ancestor of (oracle by strings)."""
    s = strs(sorted_ids)
    present = set(s)
    return np.array([not any(c[:k] in present for k in range(1, len(c))) for c in s])


# --------------------------------------------------------------------------- uncompact


@given(st.integers(0, MAX_LEVEL - 2).flatmap(lambda lo: cell_soups(lo, min(lo + 2, MAX_LEVEL - 2))), st.integers(0, 2))
def test_uncompact_matches_oracle(cs, extra):
    level = min(MAX_LEVEL, max(map(o_level, cs)) + extra)
    if sum(o_count(c, level) for c in set(cs)) > 20_000:
        return
    ids = arr(cs)
    out, bad = KC.uncompact(ids, level)
    assert bad == -1
    assert strs(out) == o_uncompact(cs, level)
    assert np.all(out[1:] > out[:-1])
    # the two-step form gives the same, with the count known before allocating
    cells_, total, bad = KC.uncompact_prepare(ids, level)
    assert bad == -1 and total == out.size
    buf = np.zeros(total, dtype=np.uint64)
    assert K.children(cells_, level, buf) == -1
    assert np.array_equal(buf, out)
    # round trip
    assert np.array_equal(KC.compact(out), KC.compact(ids))


def test_uncompact_pinned():
    assert strs(KC.uncompact(arr(["C401", "C4020"]), 4)[0]) == ["C4010", "C4011", "C4012", "C4020"]
    assert KC.uncompact(arr(["T", "T3", "A", "T32"]), 1)[1] == 3  # "T32" is finer than level 1
    out, bad = KC.uncompact(arr(["T", "T3", "A"]), 1)
    assert bad == -1 and strs(out) == ["A" + d for d in "012345"] + ["T" + d for d in "012345"]
    deep = "T5" + "2" * 27
    out, bad = KC.uncompact(arr([deep, deep, deep[:-1]]), 28)
    assert bad == -1 and strs(out) == o_children(deep[:-1], 28)


def test_uncompact_error_is_input_position():
    """The error index refers to the unsorted input, first offender in input order."""
    ids = arr(["T", "C4012", "A", "B01", "C40"])
    assert KC.uncompact(ids, 2)[1] == 1
    assert KC.uncompact_prepare(ids, 2)[2] == 1
    assert KC.uncompact(ids, 3)[1] == 1
    assert KC.uncompact(ids, 4)[1] == -1


def test_sorting_helper_matches_numpy():
    """The internal sort against numpy's: all levels, all faces, many duplicates."""
    rng = np.random.default_rng(3)
    n = 50_000
    lv = rng.integers(0, 29, n)
    v = (1 << 62) | (rng.integers(0, 20, n).astype(np.uint64) << np.uint64(57))
    v = v.astype(np.uint64)
    v |= np.where(lv >= 1, rng.integers(1, 7, n), 0).astype(np.uint64) << np.uint64(54)
    for k in range(2, 29):
        v |= np.where(lv >= k, rng.integers(1, 4, n), 0).astype(np.uint64) << np.uint64(2 * (28 - k))
    assert K.valid_mask(v).all()
    deep = v[lv == 28]
    v = np.concatenate([v, v[:1000]])
    assert np.array_equal(KC._radix_sort(v), np.sort(v))
    assert np.array_equal(KC._sorted(v), np.sort(v))
    assert np.array_equal(KC._radix_sort(deep), np.sort(deep))
    for span in range(1, 65):  # keys differing in `span` bits: every pass count and width
        for low in sorted({0, 64 - span, (64 - span) // 2}):
            keys = rng.integers(0, 2**63, 3000, dtype=np.uint64) << np.uint64(1)
            keys |= rng.integers(0, 2, 3000, dtype=np.uint64)
            keys = (keys >> np.uint64(64 - span)) << np.uint64(low)
            assert np.array_equal(KC._radix_sort(keys), np.sort(keys)), (span, low)
    same = np.full(5000, s2i("C401"), dtype=np.uint64)
    assert np.array_equal(KC._radix_sort(same), same)
