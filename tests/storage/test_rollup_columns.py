"""Roll-ups over columns (issue 35, item 1) against a pandas oracle at every level 0-28.

The store holds points at level 28 (so every level is a roll-up), clustered
and repeated so that groups of one row and of thousands occur at fine and
coarse levels alike, with an INTEGER and a REAL column holding NULLs,
negatives and values 10**-5..10**15 apart.  The oracle reads the rows with
plain SQL once, then per level groups the integer ids' parents
(``dggs.cell_to_parent``) with pandas: counts, integer sums, min and max
exactly; integer means ``float(sum) / n`` (SQLite's ``avg`` below 2**53);
REAL sums the exact sum of the values (as integers over a common power of
two, with Python's correctly rounded integer division: no ``math.fsum``,
which the store uses) and REAL means that over n.
"""

from __future__ import annotations

import itertools
import sqlite3

import numpy as np
import pandas as pd
import pytest

import dggs
from dggs.errors import DggsError
from dggs.storage import CellStore

STATS = ("count", "sum", "mean", "min", "max")


def _points(n: int, seed: int):
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    k = n // 4  # a quarter in a few tight clusters: many rows in fine cells
    lat[:k] = rng.normal(48.0, 0.001, k)
    lng[:k] = rng.normal(2.0, 0.001, k)
    same = n // 20  # repeated points: groups of several rows at the stored level too
    lat[k : k + same] = np.repeat(lat[:same:10], 10)[:same]
    lng[k : k + same] = np.repeat(lng[:same:10], 10)[:same]
    ints = rng.integers(-(2**31), 2**31, n).astype(object)
    reals = (rng.normal(size=n) * 10.0 ** rng.integers(-5, 15, n)).astype(object)
    reals[rng.random(n) < 0.05] = 0.1  # non-dyadic repeats: sums that round
    ints[rng.random(n) < 0.1] = None
    reals[rng.random(n) < 0.1] = None
    return lat, lng, {"i": ints, "r": reals}


def _store(path, n: int, seed: int = 0):
    lat, lng, values = _points(n, seed)
    with CellStore(path) as store:
        store.ingest_points(lat, lng, 28, values, types={"i": "INTEGER", "r": "REAL"}, batch_size=max(n // 3, 1))
    return path


def _rows(path):
    con = sqlite3.connect(path)
    try:
        cells, ints, reals = zip(*con.execute("SELECT cell, i, r FROM all_points ORDER BY cell"), strict=True)
    finally:
        con.close()
    ids = np.asarray(dggs.str_to_int(np.asarray(cells)), dtype=np.uint64)
    return ids, list(ints), list(reals)


def _exact_sums(reals: list, parents: np.ndarray) -> list:
    """Each group's exact REAL sum, correctly rounded (None if no value): integers over 2**K, no fsum."""
    ratios = [(0, 1) if v is None else v.as_integer_ratio() for v in reals]
    big = max(d.bit_length() - 1 for _, d in ratios)
    scaled = [num << (big - (d.bit_length() - 1)) for num, d in ratios]
    prefix = [0, *itertools.accumulate(scaled)]
    present = [0, *itertools.accumulate(v is not None for v in reals)]
    starts = np.flatnonzero(np.concatenate([[True], parents[1:] != parents[:-1]])).tolist()
    ends = [*starts[1:], len(reals)]
    scale = 1 << big
    return [None if present[b] == present[a] else (prefix[b] - prefix[a]) / scale
            for a, b in zip(starts, ends, strict=True)]


def _oracle(ids, ints, reals, level: int) -> dict[str, dict[str, list]]:
    parents = np.asarray(dggs.cell_to_parent(ids, level), dtype=np.uint64)
    frame = pd.DataFrame({"p": parents, "i": pd.array(ints, dtype="Int64"), "r": pd.array(reals, dtype="Float64")})
    grouped = frame.groupby("p", sort=True)
    cells = dggs.int_to_str(grouped.size().index.to_numpy(np.uint64)).tolist()
    count = grouped.size().tolist()
    out = {}
    for column in ("i", "r"):
        g = grouped[column]
        n = g.count().tolist()
        low = [None if pd.isna(v) else v for v in g.min().tolist()]
        high = [None if pd.isna(v) else v for v in g.max().tolist()]
        if column == "i":
            total = [None if k == 0 else int(s) for s, k in zip(g.sum(min_count=1).fillna(0).tolist(), n, strict=True)]
            low, high = [None if v is None else int(v) for v in low], [None if v is None else int(v) for v in high]
        else:
            total = _exact_sums(reals, parents)
            low, high = [None if v is None else float(v) for v in low], [None if v is None else float(v) for v in high]
        mean = [None if k == 0 else float(s) / k for s, k in zip(total, n, strict=True)]
        out[column] = {"cell": cells, "count": count, "sum": total, "mean": mean, "min": low, "max": high}
    return out


def _check_every_level(path):
    ids, ints, reals = _rows(path)
    with CellStore(path, readonly=True) as store:
        for level in range(29):
            want = _oracle(ids, ints, reals, level)
            for column in ("i", "r"):
                rows = store.aggregate(level, column, STATS)
                got = {k: [r[k] for r in rows] for k in ("cell", *STATS)}
                for k in ("cell", *STATS):
                    assert got[k] == want[column][k], (level, column, k)
                    assert [type(v) for v in got[k]] == [type(v) for v in want[column][k]], (level, column, k)
                table = store.aggregate(level, column, STATS, as_table=True)
                assert table.to_pydict() == want[column], (level, column)


def test_every_level_matches_pandas(tmp_path):
    _check_every_level(_store(tmp_path / "q.db", 20_000))


@pytest.mark.slow
def test_every_level_matches_pandas_million(tmp_path):
    _check_every_level(_store(tmp_path / "m.db", 1_000_000))


def test_table_types_and_orders(tmp_path):
    path = _store(tmp_path / "t.db", 3_000, seed=1)
    with CellStore(path, readonly=True) as store:
        for column, kind in (("i", "int64"), ("r", "double")):
            table = store.aggregate(5, column, STATS, as_table=True)
            assert [str(f.type) for f in table.schema] == ["string", "int64", kind, "double", kind, kind]
            for by, descending in itertools.product(STATS, (True, False)):
                rows = store.aggregate(5, column, STATS, order_by=by, descending=descending, limit=40)
                assert store.aggregate(5, column, STATS, order_by=by, descending=descending, limit=40,
                                       as_table=True).to_pylist() == rows
                every = store.aggregate(5, column, STATS)
                nulls = [r for r in every if r[by] is None]
                values = sorted((r for r in every if r[by] is not None),
                                key=lambda r: (-r[by] if descending else r[by], r["cell"]))
                assert rows == ((values + nulls) if descending else (nulls + values))[:40], (column, by)
        empty = store.aggregate(3, "r", ("count", "sum"), cell=[], as_table=True)
        assert empty.num_rows == 0 and empty.column_names == ["cell", "count", "sum"]


def test_values_of_another_type_fall_back_to_sql(tmp_path):
    """A value written by raw SQL in a column of another type: SQL answers, as it always has."""
    path = _store(tmp_path / "f.db", 2_000, seed=2)
    with CellStore(path) as store:
        before = store.aggregate(2, "i", ("count", "min", "max"))
    con = sqlite3.connect(path)
    with con:
        con.execute("UPDATE points SET i = 'text' WHERE cell = (SELECT min(cell) FROM points)")
    con.close()
    with CellStore(path, readonly=True) as store:
        after = store.aggregate(2, "i", ("count", "min", "max"))
        assert [r["count"] for r in after] == [r["count"] for r in before]
        assert "text" in [r["max"] for r in after]  # SQL's max: text sorts after numbers
        with pytest.raises(DggsError, match="'max' holds 'text', not int64"):
            store.aggregate(2, "i", ("count", "min", "max"), as_table=True)
