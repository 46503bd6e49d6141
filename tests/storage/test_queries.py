"""Every query against a brute-force computation over the same rows (unit + hypothesis)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon, box

import dggs
from dggs.storage import CellStore, rollup_query

from .helpers import brute_aggregate, clustered_points, expected_rows, under


def _fill(store: CellStore, seed: int, n: int, level: int, batch_size: int = 50):
    rng = np.random.default_rng(seed)
    lat, lng = clustered_points(rng, n, centres=4, spread=rng.choice([0.05, 1.0, 10.0]))
    v = [None if rng.random() < 0.1 else int(x) for x in rng.integers(-50, 1000, n)]
    w = rng.normal(0, 10, n)
    store.ingest_points(lat, lng, level, {"v": np.array(v, dtype=object), "w": w}, batch_size=batch_size,
                        types={"v": int})
    return expected_rows(lat, lng, level, {"v": v, "w": w.tolist()})


def _same_rows(got: list[dict], want: list[dict]) -> None:
    assert sorted((r["cell"], r["row"]) for r in got) == sorted((r["cell"], r["row"]) for r in want)
    by_row = {r["row"]: r for r in want}
    for r in got:
        w = by_row[r["row"]]
        assert r["lat"] == w["lat"] and r["lng"] == w["lng"]
        assert r["v"] == w["v"]
        assert r["w"] == pytest.approx(w["w"])


def _close(a, b):
    if a is None or b is None:
        return a is None and b is None
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9)


store_cases = st.tuples(
    st.integers(0, 2**32 - 1),  # seed
    st.integers(0, 120),  # points
    st.integers(2, 9),  # stored level
    st.sampled_from([7, 50, 10_000]),  # batch size
    st.sampled_from([1, 60, 10**9]),  # merge threshold: rows split between merged and pending
)


@settings(max_examples=25, deadline=None)
@given(store_cases, st.data())
def test_queries_match_brute_force(case, data):
    seed, n, level, batch_size, merge_rows = case
    with CellStore(":memory:", merge_rows=merge_rows) as store:
        rows = _fill(store, seed, n, level, batch_size)
        if merge_rows == 1 and n:  # leave a tail pending, as an interrupted ingest would
            extra_lat, extra_lng = np.array([10.0, -20.0]), np.array([20.0, 170.0])
            store.conn.execute("BEGIN")
            for i, (a, b) in enumerate(zip(extra_lat, extra_lng, strict=True), start=n + 1):
                cell = dggs.latlng_to_cell(a, b, level)
                store.conn.execute(
                    "INSERT INTO points_pending (cell, lat, lng, source_id, row, v, w) VALUES (?, ?, ?, 1, ?, 7, 1.5)",
                    (cell, a, b, i),
                )
                rows.append({"cell": cell, "lat": a, "lng": b, "row": i, "v": 7, "w": 1.5})
            store.conn.execute("COMMIT")

        # count and descendants at random prefixes of stored cells, and random cells
        assert store.count() == len(rows)
        probes = {r["cell"][: data.draw(st.integers(1, level + 1))] for r in rows[:5]}
        probes |= {"A", "T5", "C" + "0" * min(level, 3)}
        for cell in probes:
            cell_level = len(cell) - 1
            want = [r for r in rows if r["cell"].startswith(cell)]
            assert store.count(cell) == len(want)
            got = store.descendants(cell)
            _same_rows(got, want)
            assert [r["cell"] for r in got] == sorted(r["cell"] for r in got)
            if cell_level == level:
                _same_rows(store.get(cell), want)

        # roll-up at every level up to the stored one, by either plan: one range query per cell
        # (forced here; chosen for many rows a cell) or one GROUP BY
        ranged = data.draw(st.booleans())
        saved = rollup_query.RANGE_ROWS_PER_CELL
        rollup_query.RANGE_ROWS_PER_CELL = 0 if ranged else 10**12
        try:
            for agg_level in sorted({0, level, data.draw(st.integers(0, level))}):
                for column in ("v", "w"):
                    got = store.aggregate(agg_level, column)
                    want = brute_aggregate(rows, agg_level, column)
                    assert [g["cell"] for g in got] == sorted(want)
                    for g in got:
                        w = want[g["cell"]]
                        assert g["count"] == w["count"]
                        for stat in ("sum", "mean", "min", "max"):
                            assert _close(g[stat], w[stat]), (stat, g, w)
                    # no count asked, under some cells, a limit
                    parents = sorted({c[: data.draw(st.integers(1, agg_level + 1))] for c in list(want)[:3]})
                    inside = {c: w for c, w in want.items() if any(c.startswith(p) for p in parents)}
                    part = store.aggregate(agg_level, column, ("max", "min"), cell=parents or None)
                    if parents:
                        assert [g["cell"] for g in part] == sorted(inside)
                        assert all(_close(g["max"], inside[g["cell"]]["max"]) for g in part)
                    limit = data.draw(st.integers(0, 4))
                    assert store.aggregate(agg_level, column, limit=limit) == got[:limit]
        finally:
            rollup_query.RANGE_ROWS_PER_CELL = saved

        # within: rows under the cells of a polygon
        lat0, lng0 = data.draw(st.floats(-60, 60)), data.draw(st.floats(-170, 150))
        size = data.draw(st.sampled_from([1.0, 15.0]))
        poly = box(lng0, lat0, lng0 + size, lat0 + size)
        poly_level = data.draw(st.integers(0, min(level, 5)))
        _same_rows(store.within(poly, poly_level), under(rows, dggs.polygon_to_cells(poly, poly_level), poly_level))

        # disk around a stored cell
        if rows:
            centre = rows[0]["cell"][: data.draw(st.integers(1, level + 1))]
            k = data.draw(st.integers(0, 2))
            disk_level = len(centre) - 1
            _same_rows(store.disk(centre, k), under(rows, dggs.grid_disk(centre, k), disk_level))


def test_aggregate_orders_limits_and_filters(store):
    rows = _fill(store, 7, 300, 6)
    want = brute_aggregate(rows, 2, "w")
    top = store.aggregate(2, "w", ("count", "sum"), order_by="count", limit=3)
    assert [t["count"] for t in top] == sorted((w["count"] for w in want.values()), reverse=True)[:3]
    low = store.aggregate(2, "w", ("min",), order_by="min", descending=False, limit=1)
    assert low[0]["min"] == pytest.approx(min(w["min"] for w in want.values()))
    parent = top[0]["cell"][:2]
    inside = store.aggregate(2, "w", ("count",), cell=parent)
    assert {r["cell"] for r in inside} == {c for c in want if c.startswith(parent)}
    assert store.aggregate(2, stats=("count",))[0].keys() == {"cell", "count"}


def test_aggregate_is_a_prefix_group_by_in_sql(store):
    _fill(store, 1, 10, 5)
    plan = " ".join(
        str(r) for r in store.conn.execute(
            "EXPLAIN QUERY PLAN SELECT count(*) FROM all_points WHERE cell >= ?1 AND cell < ?1 || '~'", ("A1",)
        )
    )
    assert "SEARCH points USING PRIMARY KEY (cell>? AND cell<?)" in plan


def test_to_geojson_matches_aggregate(store, tmp_path):
    _fill(store, 3, 80, 5)
    path = tmp_path / "out.geojson"
    fc = store.to_geojson(3, "v", path)
    agg = store.aggregate(3, "v")
    assert [f["properties"]["cell"] for f in fc["features"]] == [a["cell"] for a in agg]
    assert [f["properties"]["count"] for f in fc["features"]] == [a["count"] for a in agg]
    import json

    assert json.loads(path.read_text()) == json.loads(json.dumps(fc))
    assert fc["features"][0]["geometry"]["type"] in ("Polygon", "MultiPolygon")


def test_empty_store_queries(store):
    assert store.count() == 0
    assert store.count("A") == 0
    assert store.descendants("B1") == []
    assert store.get("C12") == []
    assert store.aggregate(3) == []
    assert store.within(box(-1, -1, 1, 1), 2) == []
    assert store.to_geojson(2)["features"] == []


@pytest.mark.parametrize(
    "call, error",
    [
        (lambda s: s.count("X1"), dggs.InvalidCellError),
        (lambda s: s.count("A1'; DROP TABLE points; --"), dggs.InvalidCellError),
        (lambda s: s.descendants("A12222"), dggs.LevelMismatchError),  # finer than stored level 3
        (lambda s: s.get("A1"), dggs.LevelMismatchError),
        (lambda s: s.aggregate(4, "v"), dggs.LevelMismatchError),
        (lambda s: s.aggregate(-1, "v"), dggs.LevelError),
        (lambda s: s.aggregate(2, "nope"), dggs.DggsValueError),
        (lambda s: s.aggregate(2, 'v" FROM points; --'), dggs.DggsValueError),
        (lambda s: s.aggregate(2, "v", ("median",)), dggs.DggsValueError),
        (lambda s: s.aggregate(2, None, ("sum",)), dggs.DggsValueError),
        (lambda s: s.aggregate(2, "name", ("sum",)), dggs.DggsValueError),
        (lambda s: s.aggregate(2, "v", ("sum",), order_by="count"), dggs.DggsValueError),
        (lambda s: s.aggregate(1, "v", cell="A12"), dggs.LevelMismatchError),
        (lambda s: s.within(box(0, 0, 1, 1), 5), dggs.LevelMismatchError),
    ],
)
def test_invalid_queries(store, call, error):
    store.ingest_points([1.0, 2.0], [3.0, 4.0], 3, {"v": [1, 2], "name": ["a", "b"]})
    with pytest.raises(error):
        call(store)
    assert store.count() == 2  # nothing was dropped by an injection attempt


def test_within_a_country_outline(store):
    # A rough outline of Italy's boot, built by hand.
    italy = Polygon([(7.0, 44.0), (13.7, 45.8), (12.3, 44.2), (18.5, 40.1), (15.6, 38.0), (16.0, 39.6),
                     (12.0, 42.0), (10.2, 43.9), (7.0, 44.0)])
    store.ingest_records(
        [{"lat": 41.9, "lng": 12.5, "name": "Rome"}, {"lat": 48.85, "lng": 2.35, "name": "Paris"},
         {"lat": 40.85, "lng": 14.27, "name": "Naples"}],
        values=["name"], level=9,
    )
    names = {r["name"] for r in store.within(italy, 6)}
    assert names == {"Rome", "Naples"}


def test_to_arrow_and_export_match_aggregate(tmp_path):
    pa = pytest.importorskip("pyarrow")
    pq = pytest.importorskip("pyarrow.parquet")
    with CellStore() as store:
        _fill(store, 11, 400, 8)
        rows = store.aggregate(4, "w", ("count", "sum", "max"))
        table = store.to_arrow(4, "w", ("count", "sum", "max"), densify=2)
        assert table.column_names == ["cell", "cell_id", "count", "sum", "max", "bbox", "geometry"]
        assert table.column("cell").to_pylist() == [r["cell"] for r in rows]
        for stat in ("count", "sum", "max"):
            assert table.column(stat).to_pylist() == [r[stat] for r in rows]
        assert table.column("cell_id").type == pa.int64()
        assert store.export(tmp_path / "a.parquet", 4, "w", ("count", "sum", "max"), densify=2) == len(rows)
        assert pq.read_table(tmp_path / "a.parquet").equals(table)
        assert store.export(tmp_path / "a.geojson", 4) == len(rows)
        with pytest.raises(dggs.DggsValueError, match="format"):
            store.export(tmp_path / "a.parquet", 4, format="shp")
        with pytest.raises(dggs.DggsValueError, match="extension"):
            store.export(tmp_path / "a", 4)
        assert store.to_arrow(2, "w").num_rows == len(store.aggregate(2))


@pytest.mark.parametrize("pending", [False, True])
def test_range_plan_equals_the_group_by_plan(tmp_path, monkeypatch, pending):
    """Enough rows a cell for the range plan on its own; the same answers as one GROUP BY, pending rows or not."""
    rng = np.random.default_rng(5)
    n = 20_000
    lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, n))), rng.uniform(-180, 180, n)
    ints = np.where(rng.random(n) < 0.1, None, rng.integers(-50, 50, n)).astype(object)
    names = np.array([f"n{i % 97}" for i in range(n)], dtype=object)
    with CellStore(tmp_path / "s.db", merge_rows=10**9 if pending else 1000) as store:
        store.ingest_points(lat, lng, 6, {"i": ints, "x": rng.normal(0, 1, n), "t": names}, types={"i": int},
                            batch_size=4000)
        if pending:  # an interrupted ingest's tail: rows left in points_pending
            store.conn.execute("INSERT INTO points_pending SELECT * FROM points WHERE row % 3 = 0")
            store.conn.execute("DELETE FROM points WHERE row % 3 = 0")
        assert store.conn.execute("SELECT count(*) FROM points_pending").fetchone()[0] > 0 or not pending
        for level in (0, 1, 3):
            for column, stats in ((None, ("count",)), ("i", ("count", "sum", "mean", "min", "max")),
                                  ("x", ("mean", "max")), ("t", ("min", "max", "count"))):
                for cell in (None, ["C", "D4"]):
                    if cell is not None and level == 0:
                        continue
                    monkeypatch.setattr(rollup_query, "RANGE_CELLS", 40_000)
                    ranged = store.aggregate(level, column, stats, cell=cell)
                    monkeypatch.setattr(rollup_query, "RANGE_CELLS", -1)
                    grouped = store.aggregate(level, column, stats, cell=cell)
                    assert [r["cell"] for r in ranged] == [r["cell"] for r in grouped]
                    for a, b in zip(ranged, grouped, strict=True):
                        for s in stats:
                            assert a[s] == pytest.approx(b[s], rel=1e-12) if isinstance(b[s], float) else a[s] == b[s]
