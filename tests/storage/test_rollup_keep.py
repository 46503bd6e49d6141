"""Kept roll-ups (``CellStore.keep_rollups``) give what SQL's GROUP BY over the rows gives (issue 18).

Oracle: the plain ``GROUP BY substr(cell, 1, level + 1)`` over ``all_points``
on a separate sqlite3 connection, compared value for value and type for type
(an int sum is an int, a mean the double ``avg`` gives; a REAL sum the
correctly rounded one, ``fsum``, and its mean that over the count), after ingests of
every kind (ordered arrays, a streamed CSV through the pending table,
records), deletions and bad batches.
"""

from __future__ import annotations

import csv
import os
import signal
import sqlite3
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from dggs.errors import DggsError, LevelError, LevelMismatchError, StorageError
from dggs.storage import CellStore
from dggs.storage.errors import BadRowError

from .helpers import FSum, stat_sql

STATS = ("count", "sum", "mean", "min", "max")


@pytest.fixture(autouse=True)
def _always_read_kept(monkeypatch):
    """Read the kept partials even where the rows, as columns, would be cheaper (small test stores)."""
    from dggs.storage import rollup_serve

    monkeypatch.setattr(rollup_serve, "KEPT_GAIN", 0)


def oracle(path, level, column, stats, cell=None, order_by=None, descending=True, limit=None):
    """The roll-up as plain SQL computes it from the rows."""
    con = sqlite3.connect(path)
    con.create_aggregate("fsum", 1, FSum)
    try:
        exprs = ", ".join(f'{stat_sql(s, column, TYPES.get(column))} AS "{s}"' for s in stats)
        where, params = "", [level + 1]
        if cell is not None:
            where, params = "WHERE cell >= ? AND cell < ? || '~'", [level + 1, cell, cell]
        order = "1" if order_by is None else f'"{order_by}" {"DESC" if descending else "ASC"}, 1'
        sql = f"SELECT substr(cell, 1, ?), {exprs} FROM all_points {where} GROUP BY 1 ORDER BY {order}"
        if limit is not None:
            sql += f" LIMIT {limit}"
        return [dict(zip(("cell", *stats), row, strict=True)) for row in con.execute(sql, params)]
    finally:
        con.close()


def same(a, b):
    """Equal values of equal types (an int sum must not come back as a float)."""
    return a == b and [[type(v) for v in r.values()] for r in a] == [[type(v) for v in r.values()] for r in b]


def points(seed, n=300, big=False):
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    lat[:60], lng[:60] = rng.normal(48.0, 0.05, 60), rng.normal(2.0, 0.05, 60)  # a cluster
    lat[60:64], lng[60:64] = [90.0, -90.0, 10.0, -10.0], [0.0, 45.0, 180.0, -180.0]  # poles, antimeridian
    ints = rng.integers(2**53, 2**54, n) if big else rng.integers(-1000, 1000, n)
    reals = rng.normal(size=n) * 10.0 ** rng.integers(-5, 15, n)
    values = {"i": ints.astype(object), "r": reals.astype(object)}
    for col in values.values():
        col[rng.random(n) < 0.1] = None
    values["r"][rng.random(n) < 0.05] = -0.0
    return lat, lng, values


TYPES = {"i": "INTEGER", "r": "REAL"}


def fill(path, seed, kept, big=False, csv_dir=None, delete=False):
    """A store keeping ``kept`` built by three kinds of ingest (arrays, CSV, records), with a deletion if asked."""
    lat, lng, values = points(seed, big=big)
    store = CellStore(path)
    store.keep_rollups(kept)
    store.ingest_points(lat[:150], lng[:150], 12, {k: v[:150] for k, v in values.items()}, types=TYPES,
                        batch_size=40)
    if csv_dir is not None:
        file = csv_dir / f"p{seed}.csv"
        with open(file, "w", newline="") as fh:
            out = csv.writer(fh)
            out.writerow(["lat", "lng", "i", "r"])
            for k in range(150, 250):
                out.writerow([lat[k], lng[k], "" if values["i"][k] is None else values["i"][k],
                              "" if values["r"][k] is None else repr(values["r"][k])])
        store.ingest_csv(file, values={"i": int, "r": float}, batch_size=30)
    records = [{"lat": lat[k], "lng": lng[k], "i": values["i"][k], "r": values["r"][k]} for k in range(250, 300)]
    store.ingest_records(records, values=["i", "r"], source="late", batch_size=20)
    if delete:  # rebuilds the partials from the rows
        store.ingest_points(lat[:20] + 0.001, lng[:20], 12, {"i": values["i"][:20]}, source="gone")
        store.delete_source("gone")
    return store


@pytest.mark.parametrize("delete", [False, True])
def test_keeping_roll_ups_gives_sql_at_every_level_stat_and_column(tmp_path, delete):
    store = fill(tmp_path / "k.db", 1, [9, 5, 2], csv_dir=tmp_path, delete=delete)
    with store:
        assert store.rollup_levels == (9, 5, 2)
        for level in range(13):
            for column, stats in ((None, ("count",)), ("i", STATS), ("r", ("count", "min", "max")), ("r", STATS)):
                got = store.aggregate(level, column, stats)
                assert same(got, oracle(store.path, level, column, stats)), (level, column, stats)
        store.check()


@settings(max_examples=15, deadline=None)
@given(
    st.integers(0, 2**16),
    st.lists(st.integers(0, 12), min_size=1, max_size=3),
    st.sampled_from(["i", "r", None]),
    st.integers(0, 12),
    st.sampled_from([None, "count", "sum", "mean", "min", "max"]),
    st.booleans(),
    st.sampled_from([None, 0, 1, 7]),
)
@example(3, [12, 0], "i", 0, None, True, None)
@example(4, [6], "i", 3, "sum", False, 1)
@example(5, [11], "r", 11, "min", True, 7)
def test_any_kept_levels_and_query_match_sql(tmp_path_factory, seed, kept, column, level, order_by, descending, limit):
    folder = tmp_path_factory.mktemp("keep")
    stats = ("count",) if column is None else STATS
    if order_by is not None and order_by not in stats:
        order_by = None
    with fill(folder / "k.db", seed, kept) as store:
        got = store.aggregate(level, column, stats, order_by=order_by, descending=descending, limit=limit)
        assert same(got, oracle(store.path, level, column, stats, None, order_by, descending, limit))
        cell = str(got[0]["cell"])[: max(1, level)] if got else None
        if cell is not None:  # under one cell (a prefix range)
            under = store.aggregate(level, column, stats, cell=cell)
            assert same(under, oracle(store.path, level, column, stats, cell))


def test_fractions_in_an_integer_column_give_sql_sums(tmp_path):
    """An INTEGER column keeps fractional numbers as REAL: their sums depend on the order, so come from the rows."""
    rng = np.random.default_rng(3)
    lat, lng, _ = points(3)
    mixed = rng.integers(-50, 50, lat.shape[0]).astype(object)
    some = rng.random(lat.shape[0]) < 0.3
    mixed[some] = rng.normal(size=int(some.sum())) * 10.0 ** rng.integers(-3, 7, int(some.sum()))
    with CellStore(tmp_path / "mixed.db") as store:
        store.keep_rollups([9, 4])
        for part in np.array_split(np.arange(lat.shape[0]), 3):  # three sources interleave in every cell
            store.ingest_points(lat[part], lng[part], 12, {"i": mixed[part]}, types={"i": "INTEGER"}, batch_size=25)
        for level in (12, 9, 6, 4, 1):
            assert same(store.aggregate(level, "i", STATS), oracle(store.path, level, "i", STATS)), level


def test_a_float_sum_added_in_another_order_is_not_served(tmp_path):
    """0.1 then 0.2 + 0.3 from a second source: SQL sums the rows in key order, (0.1 + 0.2) + 0.3."""
    with CellStore(tmp_path / "order.db") as store:
        store.keep_rollups([6])
        store.ingest_points([10.0], [20.0], 9, {"i": [0.1]}, types={"i": "INTEGER"})
        store.ingest_points([10.0, 10.0], [20.0, 20.0], 9, {"i": [0.2, 0.3]}, types={"i": "INTEGER"})
        got = store.aggregate(6, "i", ("sum", "mean"))
        assert got[0]["sum"] == (0.1 + 0.2) + 0.3 != 0.1 + (0.2 + 0.3)  # the order of the rows, not of the partials
        assert same(got, oracle(store.path, 6, "i", ("sum", "mean")))
    with CellStore(tmp_path / "inner.db") as store:  # integer min and max, fractions between them
        store.keep_rollups([6])
        for values in ([-10], [-5.1, -0.7], [10]):
            store.ingest_points([10.0] * len(values), [20.0] * len(values), 9, {"i": values}, types={"i": "INTEGER"})
        got = store.aggregate(6, "i", ("sum", "min", "max"))
        assert got[0]["sum"] == ((-10 + -5.1) + -0.7) + 10 != (-10 + (-5.1 + -0.7)) + 10
        assert same(got, oracle(store.path, 6, "i", ("sum", "min", "max")))


def test_sums_reaching_two_to_the_53_come_from_the_rows(tmp_path):
    with fill(tmp_path / "big.db", 7, [10, 3], big=True) as store:
        for level in (10, 3, 1):
            assert same(store.aggregate(level, "i", STATS), oracle(store.path, level, "i", STATS))


def test_an_overflowing_sum_raises_as_without_kept_roll_ups_and_counts_still_come(tmp_path):
    with CellStore(tmp_path / "o.db") as store:
        store.keep_rollups([4])
        store.ingest_points([1.0, 1.0], [2.0, 2.0], 9, {"i": [2**62, 2**62]})
        store.ingest_points([1.0], [2.0], 9, {"i": [2**62]})  # the kept sum passes int64: stored as REAL
        with pytest.raises((DggsError, sqlite3.Error), match="overflow"):
            store.aggregate(4, "i", ("sum",))
        assert same(store.aggregate(4, "i", ("count", "max")), oracle(store.path, 4, "i", ("count", "max")))
        store.check()


def test_a_failed_batch_leaves_no_partials_behind(tmp_path):
    with CellStore(tmp_path / "f.db") as store:
        store.keep_rollups([6])
        records = [{"lat": 10.0 + k / 100, "lng": 20.0, "v": k} for k in range(50)]
        records[45]["lat"] = 95.0  # a bad row in the third batch
        with pytest.raises(BadRowError):
            store.ingest_records(records, values=["v"], source="s", batch_size=20)
        assert store.count() == 40
        assert same(store.aggregate(6, "v", STATS), oracle(store.path, 6, "v", STATS))
        store.check()


def test_writes_with_raw_sql_are_found_by_check_and_mended_by_keeping_again(tmp_path):
    with fill(tmp_path / "raw.db", 11, [8]) as store:
        store.conn.execute("UPDATE points SET i = i + 1 WHERE i IS NOT NULL")
        store.conn.commit()
        with pytest.raises(StorageError, match="kept roll-up of level 8"):
            store.check()
        store.keep_rollups([8])
        store.check()
        assert same(store.aggregate(8, "i", STATS), oracle(store.path, 8, "i", STATS))


def test_levels_are_checked_and_dropping_stops_keeping(tmp_path):
    with CellStore(tmp_path / "l.db") as store:
        assert store.keep_rollups(7) == (7,)  # before any ingest: any level
        with pytest.raises(LevelMismatchError, match="roll-up level 7"):
            store.ingest_points([1.0], [2.0], 5)  # coarser than a kept level
        assert store.count() == 0
        store.ingest_points([1.0], [2.0], 9, {"v": [1]})
        for bad, error in ((10, LevelMismatchError), (-1, LevelError), (2.5, LevelError), (True, LevelError),
                           ("3", LevelError)):
            with pytest.raises(error):
                store.keep_rollups([bad])
        assert store.rollup_levels == (7,) and store.meta["schema_version"] == "3"  # 3: exact REAL sums
        assert store.info()["rollup_levels"] == [7]
        assert store.keep_rollups([]) == ()
        assert store.rollup_levels == () and store.meta["schema_version"] == "1"
        assert "rollups" not in store.db.table_names()
    with CellStore(tmp_path / "l.db", readonly=True) as reader, pytest.raises(StorageError, match="read-only"):
        reader.keep_rollups([3])


def test_a_newer_dggs_store_is_refused_by_one_that_would_not_keep_its_roll_ups(tmp_path, monkeypatch):
    from dggs.storage import schema

    with CellStore(tmp_path / "v.db") as store:
        store.keep_rollups([3])
    monkeypatch.setattr(schema, "SCHEMA_VERSION", 1)  # a dggs from before kept roll-ups
    with pytest.raises(StorageError, match="newer than this dggs supports"):
        CellStore(tmp_path / "v.db")
    monkeypatch.setattr(schema, "SCHEMA_VERSION", 2)  # one keeping roll-ups but adding REAL sums inexactly
    with pytest.raises(StorageError, match="newer than this dggs supports"):
        CellStore(tmp_path / "v.db")


def test_another_process_keeping_other_levels_mid_ingest_stops_it_and_a_rerun_resumes(tmp_path):
    path = tmp_path / "race.db"
    with CellStore(path) as store:
        store.keep_rollups([5])
        calls = []

        def change_levels(n):  # the progress callback runs between batches
            calls.append(n)
            if len(calls) == 2:
                with CellStore(path) as other:
                    other.keep_rollups([5, 3])

        lat, lng, values = points(2)
        with pytest.raises(StorageError, match="kept roll-up levels changed"):
            store.ingest_points(lat, lng, 12, {"i": values["i"]}, source="s", batch_size=50, progress=change_levels)
        store.ingest_points(lat, lng, 12, {"i": values["i"]}, source="s", batch_size=50)
        assert store.count() == 300
        for level in (5, 3):
            assert same(store.aggregate(level, "i", STATS), oracle(path, level, "i", STATS))
        store.check()


KILLED = textwrap.dedent(
    """
    import sys, numpy as np
    from dggs.storage import CellStore
    rng = np.random.default_rng(0)
    n = 60_000
    lat, lng = rng.uniform(-80, 80, n), rng.uniform(-180, 180, n)
    with CellStore(sys.argv[1]) as store:
        if not store.rollup_levels:
            store.keep_rollups([9, 4])
        store.ingest_points(lat, lng, 14, {"v": rng.integers(0, 100, n)}, source="pts", batch_size=2_000,
                            progress=lambda n: print(n, flush=True))
    print("done", flush=True)
    """
)


@pytest.mark.slow
def test_killed_ingests_resume_with_partials_equal_to_the_rows(tmp_path):
    path = tmp_path / "kill.db"
    for kill_after in (3, 7, 12):
        proc = subprocess.Popen([sys.executable, "-c", KILLED, str(path)], stdout=subprocess.PIPE, text=True)
        for _ in range(kill_after):
            if not proc.stdout.readline():
                break
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        with CellStore(path) as store:
            store.check()  # the partials equal the rows after every kill
    out = subprocess.run([sys.executable, "-c", KILLED, str(path)], capture_output=True, text=True, check=True)
    assert "done" in out.stdout
    with CellStore(path) as store:
        assert store.count() == 60_000
        store.check()
        for level in (9, 4, 2):
            assert same(store.aggregate(level, "v", STATS), oracle(path, level, "v", STATS))
