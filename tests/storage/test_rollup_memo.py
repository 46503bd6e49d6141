"""Roll-ups streamed by group starts and remembered per file state give what SQL's GROUP BY gives (issue 18).

Oracle: the plain ``GROUP BY substr(cell, 1, level + 1)`` query on a separate
sqlite3 connection (REAL sums correctly rounded: ``fsum``), compared value for value (floats exactly), whatever
roll-ups came before on the store's own connection.
"""

from __future__ import annotations

import sqlite3

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from dggs.errors import DggsError
from dggs.storage import CellStore

from .helpers import FSum, stat_sql

STATS = ("count", "sum", "mean", "min", "max")


def _oracle(path, level, column, stats):
    con = sqlite3.connect(path)
    con.create_aggregate("fsum", 1, FSum)
    try:
        exprs = ", ".join(stat_sql(s, column, "REAL" if column == "r" else None) for s in stats)
        sql = f"SELECT substr(cell, 1, ?), {exprs} FROM all_points GROUP BY 1 ORDER BY 1"
        return [dict(zip(("cell", *stats), row, strict=True)) for row in con.execute(sql, (level + 1,))]
    finally:
        con.close()


def _store(tmp_path, seed, n=400, big=False):
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lat[:50] = rng.normal(48.0, 0.01, 50)  # a cluster: many rows a coarse cell
    lng = rng.uniform(-180, 180, n)
    lng[:50] = rng.normal(2.0, 0.01, 50)
    ints = rng.integers(2**53, 2**54, n) if big else rng.integers(-1000, 1000, n)  # big: sums past 2**53
    reals = rng.normal(size=n) * 10.0 ** rng.integers(-5, 15, n)
    words = np.array(["ant", "bee", "cat", "dog"])[rng.integers(0, 4, n)]
    values = {"i": ints.astype(object), "r": reals.astype(object), "t": words.astype(object)}
    for col in values.values():  # some NULLs
        col[rng.random(n) < 0.1] = None
    path = tmp_path / f"m{seed}{big}.db"
    store = CellStore(path)
    store.ingest_points(lat, lng, 12, values, types={"i": "INTEGER", "r": "REAL", "t": "TEXT"})
    return store, path


def _stats(column):
    return ("count", "min", "max") if column == "t" else STATS if column else ("count",)


@settings(max_examples=15)
@given(
    st.integers(0, 2**16),
    st.lists(st.tuples(st.sampled_from([None, "i", "r", "t"]), st.integers(0, 12)), min_size=1, max_size=6),
)
@example(1, [("r", 11), ("r", 4), ("i", 11), ("i", 4), ("i", 4), (None, 0)])
@example(2, [("i", 12), ("i", 0), ("t", 9), ("t", 3)])
def test_any_sequence_of_roll_ups_matches_sql(tmp_path_factory, seed, calls):
    store, path = _store(tmp_path_factory.mktemp("memo"), seed)
    with store:
        for column, level in calls:
            stats = _stats(column)
            assert store.aggregate(level, column, stats) == _oracle(path, level, column, stats), (column, level)


def test_large_integers_whose_mean_doubles_cannot_hold_go_back_to_sql(tmp_path):
    store, path = _store(tmp_path, 7, big=True)
    with store:
        first = store.aggregate(10, "i", STATS)
        assert first == _oracle(path, 10, "i", STATS)
        assert store.aggregate(3, "i", STATS) == _oracle(path, 3, "i", STATS)


def test_a_write_through_any_connection_is_seen(tmp_path):
    store, path = _store(tmp_path, 8)
    with store:
        assert store.aggregate(5, "i", STATS) == _oracle(path, 5, "i", STATS)
        store.conn.execute("UPDATE points SET i = 5 WHERE i IS NOT NULL")  # this connection, raw SQL
        store.conn.commit()
        assert store.aggregate(5, "i", STATS) == _oracle(path, 5, "i", STATS)
        assert store.aggregate(2, "i", STATS) == _oracle(path, 2, "i", STATS)
        with CellStore(path) as other:  # another connection
            other.ingest_points([48.0], [2.0], 12, {"i": [10**6]})
        after = store.aggregate(2, "i", STATS)
        assert after == _oracle(path, 2, "i", STATS)
        assert sum(r["count"] for r in after) == 401
        store.ingest_points([-10.0], [20.0], 12, {"i": [1]})  # this store's own ingest
        assert sum(r["count"] for r in store.aggregate(2, "i", STATS)) == 402
        assert store.aggregate(5, "i", STATS) == _oracle(path, 5, "i", STATS)


def test_an_overflowing_sum_still_raises_and_counts_still_work(tmp_path):
    with CellStore(tmp_path / "o.db") as store:
        store.ingest_points([1.0, 1.0], [2.0, 2.0], 9, {"i": [2**62, 2**62]})
        with pytest.raises((DggsError, sqlite3.Error), match="overflow"):
            store.aggregate(4, "i", ("sum",))
        assert store.aggregate(4, "i", ("count", "max")) == [{"cell": store.aggregate(4)[0]["cell"], "count": 2,
                                                            "max": 2**62}]


def test_limit_takes_the_first_cells_in_id_order(tmp_path):
    store, path = _store(tmp_path, 9)
    with store:
        store.aggregate(8, "r", STATS)
        assert store.aggregate(8, "r", STATS, limit=7) == _oracle(path, 8, "r", STATS)[:7]
        assert store.aggregate(4, "t", ("count", "min"), limit=3) == _oracle(path, 4, "t", ("count", "min"))[:3]


@pytest.mark.parametrize("column", [None, "i", "r", "t"])
def test_streamed_and_sorted_partials_agree_at_every_level(tmp_path, column):
    """The group-start stream (dense stores) and the sorted GROUP BY (sparse ones) give the same partials."""
    from dggs.storage.rollup import partials_by_group_starts

    store, _ = _store(tmp_path, 10)
    with store:
        for level in range(13):
            with store._store.snapshot():
                streamed = partials_by_group_starts(store.conn, level, column, stream=True)
                sorted_ = partials_by_group_starts(store.conn, level, column, stream=False)
            assert streamed is not None and sorted_ is not None
            assert (streamed.cells, streamed.count, streamed.valued) == (sorted_.cells, sorted_.count, sorted_.valued)
            assert (streamed.low, streamed.high) == (sorted_.low, sorted_.high)
            if column == "r":  # REAL sums: the two orders of addition may differ in the last bits
                assert [t is None for t in streamed.total] == [t is None for t in sorted_.total]
                pairs = [(a, b) for a, b in zip(streamed.total, sorted_.total, strict=True) if a is not None]
                assert all(a == pytest.approx(b, rel=1e-12, abs=1e-300) for a, b in pairs)
            elif column != "t":
                assert streamed.total == sorted_.total


def test_the_memory_held_is_bounded(tmp_path, monkeypatch):
    from dggs.storage import rollup_memo

    monkeypatch.setattr(rollup_memo, "MEMO_CELLS", 150)
    store, path = _store(tmp_path, 11)
    with store:
        memo = store._store.memo
        fine = store.aggregate(12, "i", STATS)  # about 350 cells: over the bound, not kept
        assert len(fine) > 150 and not memo._kept
        assert store.aggregate(3, "i", STATS) == _oracle(path, 3, "i", STATS)
        assert store.aggregate(4, "i", STATS) == _oracle(path, 4, "i", STATS)
        assert sum(len(p.cells) for p in memo._kept.values()) <= 150
        assert store.aggregate(2, "i", STATS) == _oracle(path, 2, "i", STATS)


def test_the_last_export_table_is_reused_only_while_the_file_is_unchanged(tmp_path):
    """Two formats of one roll-up build one table; any write in between builds it again."""
    store, path = _store(tmp_path, 12)
    with store:
        first = store.to_arrow(6, "i")
        assert store.to_arrow(6, "i") is first  # remembered
        assert store.to_arrow(6, "i", ("count",)) is not first and store.to_arrow(5, "i") is not first
        first = store.to_arrow(6, "i")
        store.conn.execute("UPDATE points SET i = 7 WHERE i IS NOT NULL")  # raw SQL on this connection
        store.conn.commit()
        after = store.to_arrow(6, "i")
        assert after is not first and after.column("sum").to_pylist() == [
            r["sum"] for r in _oracle(path, 6, "i", ("sum",))
        ]
        with CellStore(path) as other:  # another connection's ingest
            other.ingest_points([48.0], [2.0], 12, {"i": [10**6]})
        again = store.to_arrow(6, "i")
        assert again is not after and sum(again.column("count").to_pylist()) == 401
        store.ingest_points([-10.0], [20.0], 12, {"i": [1]})  # this store's own ingest
        assert sum(store.to_arrow(6, "i").column("count").to_pylist()) == 402
