"""Kept roll-ups read as columns (issue 35 item 1): counts and INTEGER stats with no tuple per cell.

The kept partials of a count or an INTEGER column are read as one concatenated
string per column (``rollup_serve._as_columns``); this checks them at every
level 0-28 against the pandas oracle of ``test_rollup_columns`` (``cell_to_parent``
of the integer ids and a ``groupby``), as dicts and as tables, and that the
tuple path is not taken for them (it is the one left for REAL columns).
"""

from __future__ import annotations

import pytest

from dggs.storage import CellStore, rollup_serve
from dggs.storage.rollup_columns import Rolled

from .test_rollup_columns import STATS, _oracle, _points, _rows


@pytest.fixture(autouse=True)
def _always_read_kept(monkeypatch):
    """Read the kept partials even where the rows, as columns, would be cheaper (a small store)."""
    monkeypatch.setattr(rollup_serve, "KEPT_GAIN", 0)


@pytest.fixture(scope="module")
def kept_store(tmp_path_factory):
    path = tmp_path_factory.mktemp("kept") / "k.db"
    lat, lng, values = _points(20_000, 5)
    with CellStore(path) as store:
        store.keep_rollups([27, 20, 12, 6, 0])
        store.ingest_points(lat, lng, 28, values, types={"i": "INTEGER", "r": "REAL"}, batch_size=7_000)
    return path


def test_kept_integer_and_count_roll_ups_match_pandas_at_every_level_without_tuples(kept_store, monkeypatch):
    ids, ints, reals = _rows(kept_store)

    def refuse(*args, **kwargs):
        raise AssertionError("a count or INTEGER roll-up of kept partials went through tuples")

    monkeypatch.setattr(Rolled, "from_tuples", classmethod(refuse))
    with CellStore(kept_store, readonly=True) as store:
        for level in range(29):
            want = _oracle(ids, ints, reals, level)["i"]
            rows = store.aggregate(level, "i", STATS)
            for k in ("cell", *STATS):
                got = [r[k] for r in rows]
                assert got == want[k], (level, k)
                assert [type(v) for v in got] == [type(v) for v in want[k]], (level, k)
            assert store.aggregate(level, "i", STATS, as_table=True).to_pydict() == want, level
            counted = store.aggregate(level, None, ("count",), as_table=True).to_pydict()
            assert counted == {"cell": want["cell"], "count": want["count"]}, level


@pytest.mark.parametrize("level", [0, 6, 9, 20, 27])
def test_ordered_and_limited_kept_roll_ups_match_pandas(kept_store, level):
    ids, ints, reals = _rows(kept_store)
    want = _oracle(ids, ints, reals, level)["i"]
    with CellStore(kept_store, readonly=True) as store:
        for by in ("count", "sum", "min", "max", "mean"):
            got = store.aggregate(level, "i", STATS, order_by=by, descending=True, limit=5)
            # SQL's ORDER BY stat DESC, cell: NULLs last; ties by cell id
            ranked = sorted(range(len(want["cell"])),
                            key=lambda i: (want[by][i] is None, -(want[by][i] or 0), want["cell"][i]))[:5]
            assert [r["cell"] for r in got] == [want["cell"][i] for i in ranked], (level, by)
            assert [r[by] for r in got] == [want[by][i] for i in ranked], (level, by)


def test_reals_still_come_exactly_from_kept_partials(kept_store):
    ids, ints, reals = _rows(kept_store)
    with CellStore(kept_store, readonly=True) as store:
        for level in (0, 6, 12, 20):
            want = _oracle(ids, ints, reals, level)["r"]
            assert store.aggregate(level, "r", STATS, as_table=True).to_pydict() == want, level
