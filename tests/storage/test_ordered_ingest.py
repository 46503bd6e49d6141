"""Arrays and DataFrames are ingested in cell order, straight into the clustered table (issue 18).

The order only changes speed: the stored rows must be exactly those of the
input, each under its own row number, and a resumed ingest must skip exactly
the rows it committed.  Oracles: each point binned alone, as a string id, and
Python's own sort.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import dggs
from dggs.storage import CellStore
from dggs.storage.crs import make_transformer
from dggs.storage.readers_arrays import cell_order

# Poles, the antimeridian, an icosahedron vertex (26.565 N, 0 E is one of the 12), NaN and off-range values.
SPECIAL_LAT = [90.0, -90.0, 0.0, 26.565051177077986, -26.565051177077986, 45.0, math.nan, 91.0, -1e300]
SPECIAL_LNG = [180.0, -180.0, 0.0, 36.0, -144.0, 179.999999, math.nan, 181.0, 1e300]

coords = st.lists(
    st.tuples(
        st.one_of(st.sampled_from(SPECIAL_LAT), st.floats(-90, 90)),
        st.one_of(st.sampled_from(SPECIAL_LNG), st.floats(-180, 180)),
    ),
    min_size=2,
    max_size=60,
)


def _oracle(points: list[tuple[float, float]], level: int) -> list[int]:
    """Positions sorted by (can be binned, string id, position), each point binned alone."""

    def key(i: int) -> tuple[bool, str, int]:
        lat, lng = points[i]
        ok = math.isfinite(lat) and math.isfinite(lng) and abs(lat) <= 90 and abs(lng) <= 180
        return (ok, dggs.latlng_to_cell(lat, lng, level) if ok else "", i)

    return sorted(range(len(points)), key=key)


@given(coords, st.sampled_from([0, 1, 9, 17, 27, 28]))
@example([(90.0, 0.0), (90.0, 180.0), (-90.0, -180.0), (math.nan, 0.0)], 28)  # level 28: no spare bits, argsort
@example([(0.0, 180.0), (0.0, -180.0), (0.0, 180.0), (91.0, 0.0)], 0)  # ties keep input order
@example([(26.565051177077986, 36.0), (26.565051177077986, 36.0 - 1e-12), (math.nan, math.nan)], 17)
def test_cell_order_is_the_stable_order_of_the_string_ids(points, level):
    lat = np.array([p[0] for p in points])
    lng = np.array([p[1] for p in points])
    assert cell_order(lat, lng, level, None).tolist() == _oracle(points, level)


def test_cell_order_in_a_projected_crs_sorts_the_transformed_points():
    rng = np.random.default_rng(3)
    x, y = rng.uniform(-2e7, 2e7, 500), rng.uniform(-1.9e7, 1.9e7, 500)
    transformer = make_transformer("EPSG:3857")
    lng, lat = transformer.transform(x, y)
    expected = _oracle(list(zip(lat.tolist(), lng.tolist(), strict=True)), 12)
    assert cell_order(y, x, 12, transformer).tolist() == expected


def _stored(store: CellStore) -> list[tuple]:
    return store.conn.execute("SELECT cell, row, lat, lng, v FROM all_points ORDER BY row").fetchall()


@pytest.mark.parametrize("batch_size", [7, 1000])
def test_an_ordered_ingest_stores_every_row_once_and_never_uses_the_pending_table(tmp_path, batch_size):
    rng = np.random.default_rng(11)
    n = 300
    lat = np.concatenate([[90.0, -90.0, math.nan, 0.0], np.degrees(np.arcsin(rng.uniform(-1, 1, n - 4)))])
    lng = np.concatenate([[0.0, 180.0, 0.0, -180.0], rng.uniform(-180, 180, n - 4)])
    v = rng.integers(-(2**62), 2**62, n)
    statements: list[str] = []
    with CellStore(tmp_path / "s.db") as store:
        store.conn.set_trace_callback(statements.append)
        with pytest.warns(dggs.storage.RejectedRowsWarning):
            store.ingest_points(lat, lng, 10, {"v": v}, batch_size=batch_size, on_error="skip")
        store.conn.set_trace_callback(None)
        got = _stored(store)
        assert store.info()["pending"] == 0
    assert not [s for s in statements if "INSERT INTO points_pending" in s]
    assert [s for s in statements if s.startswith("INSERT INTO points ")]
    expected = [
        (dggs.latlng_to_cell(float(lat[i]), float(lng[i]), 10), i + 1, float(lat[i]), float(lng[i]), int(v[i]))
        for i in range(n)
        if i != 2  # the NaN row is rejected
    ]
    assert got == expected


def test_ordered_and_unordered_inputs_store_the_same_rows(tmp_path):
    rng = np.random.default_rng(12)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 200)))
    lng = rng.uniform(-180, 180, 200)
    v = rng.normal(size=200)
    with CellStore(tmp_path / "a.db") as a, CellStore(tmp_path / "b.db") as b:
        a.ingest_points(lat, lng, 15, {"v": v}, batch_size=16)
        # As Python objects the coordinates are not orderable: the rows take the pending table and a merge.
        b.ingest_points(lat.astype(object), lng.astype(object), 15, {"v": v}, batch_size=16)
        assert _stored(a) == _stored(b)
        assert len(_stored(a)) == 200


def test_a_bad_coordinate_fails_before_any_row_is_stored(tmp_path):
    """Unbinnable points come first: fixing one and ingesting again resumes from the start, not mid-order."""
    lat = np.array([10.0, 20.0, 30.0, math.nan, 40.0] * 10)
    lng = np.array([1.0, 2.0, 3.0, 4.0, 5.0] * 10)
    with CellStore(tmp_path / "f.db") as store:
        with pytest.raises(dggs.storage.BadRowError, match="row 4"):
            store.ingest_points(lat, lng, 8, batch_size=5, source="s")
        assert store.count() == 0
        lat[3::5] = 50.0
        result = store.ingest_points(lat, lng, 8, batch_size=5, source="s")
        assert result.rows_resumed == 0 and store.count() == 50


@given(coords, st.sampled_from([0, 9, 17, 28]), st.sampled_from(["ISEA", "IVEA"]), st.integers(1, 9))
@example([(90.0, 0.0), (-90.0, 180.0), (math.nan, 0.0), (91.0, 1.0), (0.0, -180.0)], 28, "ISEA", 2)
@example([(26.565051177077986, 36.0), (0.0, 180.0), (45.0, 1e300)], 17, "IVEA", 1)
def test_an_ordered_ingest_bins_each_point_once_and_stores_its_own_cell(points, level, projection, batch_size):
    """The ids ``cell_order`` binned are the ones stored (no second binning per batch), bad rows skipped."""
    import warnings

    from dggs.storage import projection as grid_projection

    located: list[int] = []
    real = grid_projection.grid_locate

    def counting(name):
        locate = real(name)

        def counted(lat, lng, lvl, **kwargs):
            located.append(int(np.size(lat)))
            return locate(lat, lng, lvl, **kwargs)

        return counted

    lat = np.array([p[0] for p in points], dtype=float)
    lng = np.array([p[1] for p in points], dtype=float)
    ok = np.isfinite(lat) & np.isfinite(lng) & (np.abs(lat) <= 90) & (np.abs(lng) <= 180)
    grid = dggs.Grid(projection)
    want = sorted((grid.latlng_to_cell(float(y), float(x), level), i + 1)  # each point binned alone
                  for i, (y, x) in enumerate(zip(lat, lng, strict=True)) if ok[i])
    import dggs.storage.ingest as ingest
    import dggs.storage.inputs as inputs

    saved = inputs.grid_locate, ingest.grid_locate
    inputs.grid_locate = ingest.grid_locate = counting  # the order's binning and the batches'
    try:
        with CellStore(":memory:", projection=projection) as store, warnings.catch_warnings():
            warnings.simplefilter("ignore")
            store.ingest_points(lat, lng, level, {"v": np.arange(len(lat))}, on_error="skip", batch_size=batch_size)
            got = sorted(store.conn.execute("SELECT cell, row FROM points").fetchall())
    finally:
        inputs.grid_locate, ingest.grid_locate = saved
    assert got == want
    assert sum(located) == int(ok.sum())  # once each: in cell_order, none again in the batches


@pytest.mark.parametrize("as_int", [False, True])
@pytest.mark.parametrize("n", [1, 500])
def test_cells_binned_before_are_stored_as_binning_again_would_store_them(tmp_path, as_int, n):
    """``ingest_dataframe(cells=...)`` stores the rows an ingest binning the points stores, binning none."""
    import warnings

    import pandas as pd

    import dggs.storage.ingest as ingest
    import dggs.storage.inputs as inputs

    rng = np.random.default_rng(n)
    lat = np.concatenate([[90.0, -90.0, 0.0, math.nan], rng.uniform(-90, 90, n)])[:max(n, 4)]
    lng = np.concatenate([[0.0, 180.0, -180.0, 0.0], rng.uniform(-180, 180, n)])[:max(n, 4)]
    if n == 1:
        lat, lng = lat[:1], lng[:1]
    ok = np.isfinite(lat)
    cells = np.empty(len(lat), dtype=object)
    cells[ok] = dggs.latlng_to_cell(lat[ok], lng[ok], 12, as_int=as_int)
    cells[~ok] = dggs.latlng_to_cell(0.0, 0.0, 12, as_int=as_int)  # a valid id beside a bad point: still bad
    df = pd.DataFrame({"lat": lat, "lng": lng, "v": np.arange(len(lat)), "cell": cells})
    stored = {}
    for name, column in (("binned", None), ("given", "cell")):
        saved = inputs.grid_locate, ingest.grid_locate
        if column is not None:  # binning anything would fail the test
            def refuse(projection):
                def locate(*args, **kwargs):
                    raise AssertionError("a point was binned again")

                return locate

            inputs.grid_locate = ingest.grid_locate = refuse
        try:
            with CellStore(tmp_path / f"{name}.db") as store, warnings.catch_warnings():
                warnings.simplefilter("ignore")
                store.keep_rollups([8])
                store.ingest_dataframe(df, values=["v"], level=12, cells=column, on_error="skip")
                stored[name] = (store.conn.execute("SELECT * FROM points ORDER BY cell, row").fetchall(),
                                store.conn.execute("SELECT * FROM rollups ORDER BY level, cell").fetchall(),
                                store.columns)
        finally:
            inputs.grid_locate, ingest.grid_locate = saved
    assert stored["given"] == stored["binned"]
    assert len(stored["given"][0]) == int(ok.sum())


def test_given_cells_are_checked_before_anything_is_stored(tmp_path):
    import pandas as pd

    df = pd.DataFrame({"lat": [1.0, 2.0], "lng": [3.0, 4.0]})
    with CellStore(tmp_path / "c.db") as store:
        with pytest.raises(dggs.InvalidCellError, match="'Z9'"):
            store.ingest_dataframe(df.assign(cell=["C40", "Z9"]), level=1, cells="cell")
        with pytest.raises(dggs.LevelMismatchError, match=r"'C401' \(row 2\) is at level 3, not the ingest's level 2"):
            store.ingest_dataframe(df.assign(cell=["C40", "C401"]), level=2, cells="cell")
        with pytest.raises(dggs.DggsValueError, match="no column"):
            store.ingest_dataframe(df, level=2, cells="cell")
        with pytest.raises(dggs.DggsValueError, match="cells has 1 values but lat has 2"):
            store.ingest_points(df["lat"], df["lng"], 2, cells=["C40"])
        assert store.count() == 0 and store.sources() == []
