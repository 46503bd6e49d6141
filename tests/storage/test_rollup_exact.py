"""Kept roll-ups of REAL columns (issue 38, item 4): exact sums, read instead of the rows.

A REAL column's kept partials hold the exact sum of its values
(``dggs.storage.rollup_exact``: an expansion of doubles, added exactly batch
by batch), and the kept sum is its correctly rounded value: the very sum the
rows give (``dggs.storage.rollup_columns``), bit for bit, whatever order the
batches came in.  Stores that kept roll-ups before (schema version 2, REAL
sums added inexactly) open unchanged: their REAL sums are read from the rows
until the first write rebuilds the partials.
"""

from __future__ import annotations

import math
import random
import sqlite3

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dggs.storage import CellStore, rollup_serve
from dggs.storage import rollup_exact as rx

STATS = ("count", "sum", "mean", "min", "max")


@pytest.fixture(autouse=True)
def _always_read_kept(monkeypatch):
    """Read the kept partials even where the rows, as columns, would be cheaper (small test stores)."""
    monkeypatch.setattr(rollup_serve, "KEPT_GAIN", 0)


def _values(seed: int, n: int):
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    lat[: n // 3], lng[: n // 3] = rng.normal(48.0, 0.05, n // 3), rng.normal(2.0, 0.05, n // 3)
    r = (rng.normal(size=n) * 10.0 ** rng.integers(-8, 16, n)).astype(object)
    r[rng.random(n) < 0.1] = None
    r[rng.random(n) < 0.05] = 0.1
    r[rng.random(n) < 0.02] = -0.0
    return lat, lng, r


def _unkept(path, level, stats=STATS, **kw):
    """The roll-up from the rows (the kept partials not asked)."""
    import dggs.storage.rollup_query as rq

    real, rq.from_kept = rq.from_kept, lambda *a, **k: None
    try:
        with CellStore(path, readonly=True) as store:
            return store.aggregate(level, "r", stats, **kw)
    finally:
        rq.from_kept = real


def _kept_reads(store, level, stats=STATS, **kw):
    """The roll-up, asserting that it came from the kept partials."""
    import dggs.storage.rollup_query as rq

    calls = []
    real = rq.from_kept

    def spy(*a, **k):
        got = real(*a, **k)
        calls.append(got is not None)
        return got

    rq.from_kept = spy
    try:
        out = store.aggregate(level, "r", stats, **kw)
    finally:
        rq.from_kept = real
    assert calls == [True], "the kept partials did not answer"
    return out


@pytest.mark.parametrize("ordered", [True, False])
def test_kept_real_sums_are_the_rows_sums_bit_for_bit(tmp_path, ordered):
    lat, lng, r = _values(1, 6_000)
    path = tmp_path / "k.db"
    with CellStore(path) as store:
        store.keep_rollups([9, 4])
        order = np.arange(lat.shape[0]) if ordered else np.random.default_rng(2).permutation(lat.shape[0])
        for chunk in np.array_split(order, 7):  # batches in another order than the rows'
            store.ingest_points(lat[chunk], lng[chunk], 12, {"r": r[chunk]}, types={"r": "REAL"}, batch_size=500)
        store.check()  # verify: kept sums equal the rows' correctly rounded sums
        for level in (9, 6, 4, 2, 0):
            kept = _kept_reads(store, level)
            assert kept == _unkept(path, level), level
            assert [math.copysign(1, x["sum"]) for x in kept if x["sum"] is not None] == \
                   [math.copysign(1, x["sum"]) for x in _unkept(path, level) if x["sum"] is not None]
            for by in ("sum", "mean"):
                assert _kept_reads(store, level, order_by=by, limit=5) == _unkept(path, level, order_by=by, limit=5)
            some = [kept[0]["cell"][:1]]
            assert _kept_reads(store, level, cell=some) == _unkept(path, level, cell=some)
        table = store.aggregate(6, "r", STATS, as_table=True)
        assert table.to_pylist() == _unkept(path, 6)
        # deleting a source rebuilds from the rows: still exact
        store.delete_source(store.sources()[0]["id"])
        store.check()
        assert _kept_reads(store, 4) == _unkept(path, 4)


def test_expansions_add_exactly():
    rng = random.Random(5)
    for _ in range(200):
        values = [rng.choice([1.0, -1.0]) * rng.random() * 10.0 ** rng.randint(-20, 20) for _ in range(rng.randint(1, 30))]
        cut = rng.randint(0, len(values))
        a, b = rx.of_values(values[:cut]), rx.of_values(values[cut:])
        total = rx.add(a, b)
        assert rx.rounded(total) == math.fsum(values)
        assert rx.rounded(rx.of_values(values)) == math.fsum(values)
    assert rx.of_values([]) is None and rx.add(None, None) is None
    assert rx.of_values([1e308, 1e308]) == rx.INEXACT and rx.rounded(rx.INEXACT) is None
    assert rx.add(rx.INEXACT, rx.of_values([1.0])) == rx.INEXACT
    assert math.copysign(1, rx.rounded(rx.of_values([-0.0]))) == 1.0  # -0.0 is stored as 0.0


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300), min_size=1,
                max_size=40), st.randoms())
def test_any_split_and_order_gives_fsum(values, rnd):
    shuffled = values[:]
    rnd.shuffle(shuffled)
    blob = None
    for k in range(0, len(shuffled), 3):
        blob = rx.add(blob, rx.of_values(shuffled[k : k + 3]))
    assert rx.rounded(blob) == math.fsum(v + 0.0 for v in values)


def _old_layout(path):
    """Turn a store keeping roll-ups into one written before exact sums: inexact REAL sums, schema version 2."""
    con = sqlite3.connect(path)
    with con:
        con.execute('UPDATE rollups SET "r:sum" = "r:sum" * (1 + 2e-16)')  # as an inexact running sum may be
        con.execute('ALTER TABLE rollups DROP COLUMN "r:x"')
        con.execute("DELETE FROM meta WHERE key = 'rollup_exact_sums'")
        con.execute("UPDATE meta SET value = '2' WHERE key = 'schema_version'")
    con.close()


def test_a_store_kept_before_exact_sums_opens_unchanged_and_migrates_on_its_first_write(tmp_path):
    lat, lng, r = _values(3, 3_000)
    path = tmp_path / "old.db"
    with CellStore(path) as store:
        store.keep_rollups([8])
        store.ingest_points(lat[:2000], lng[:2000], 11, {"r": r[:2000]}, types={"r": "REAL"})
    _old_layout(path)
    with CellStore(path, readonly=True) as reader:  # read as it is: REAL sums from the rows
        assert reader.meta["schema_version"] == "2"
        assert reader.aggregate(8, "r", STATS) == _unkept(path, 8)
        assert reader.aggregate(5, "r", ("count", "min", "max")) == _unkept(path, 5, ("count", "min", "max"))
        reader.check()  # the old layout's REAL sums are not compared
    with CellStore(path) as store:  # opening to write changes nothing yet
        assert store.meta["schema_version"] == "2"
        store.ingest_points(lat[2000:], lng[2000:], 11, {"r": r[2000:]}, types={"r": "REAL"})
        assert store.meta["schema_version"] == "3" and store.meta["rollup_exact_sums"] == "1"
        store.check()
        for level in (8, 3):
            assert _kept_reads(store, level) == _unkept(path, level)


def test_partials_of_about_a_cell_a_row_are_not_read(tmp_path, monkeypatch):
    """Where a kept level has about a cell a row, the rows read as columns are cheaper: same answer."""

    monkeypatch.setattr(rollup_serve, "KEPT_GAIN", 2)
    lat, lng, r = _values(4, 2_000)
    with CellStore(tmp_path / "g.db") as store:
        store.keep_rollups([11, 2])
        store.ingest_points(lat, lng, 12, {"r": r}, types={"r": "REAL"})
        import dggs.storage.rollup_query as rq

        answered = []
        real = rq.from_kept
        monkeypatch.setattr(rq, "from_kept", lambda *a, **k: answered.append(real(*a, **k) is not None) or real(*a, **k))
        fine, coarse = store.aggregate(11, "r"), store.aggregate(2, "r")
        assert answered == [False, True]
        monkeypatch.setattr(rollup_serve, "KEPT_GAIN", 0)
        assert store.aggregate(11, "r") == fine and store.aggregate(2, "r") == coarse


def test_groups_of_one_two_and_more_are_exact():
    rng = np.random.default_rng(7)
    counts = rng.integers(0, 6, 400)
    values = rng.normal(size=int(counts.sum())) * 10.0 ** rng.integers(-20, 20, int(counts.sum()))
    values[::17] = -0.0
    blobs, sums = rx.of_groups(values, counts)
    at = 0
    for k, c in enumerate(counts.tolist()):
        group = values[at : at + c].tolist()
        at += c
        if c == 0:
            assert blobs[k] is None and sums[k] is None
            continue
        assert sums[k] == math.fsum(group) and rx.rounded(blobs[k]) == sums[k]
        assert math.copysign(1, sums[k]) == math.copysign(1, math.fsum(v + 0.0 for v in group))
        other = rx.of_values(group[::-1])  # any other expansion of the same sum adds up the same
        assert rx.rounded(rx.add(blobs[k], other)) == math.fsum(group + group)
    big, _ = rx.of_groups(np.array([1.7e308, 1.7e308, 1.0]), np.array([2, 1]))
    assert big[0] == rx.INEXACT and rx.rounded(big[1]) == 1.0
