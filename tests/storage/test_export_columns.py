"""Exports built from the roll-up's columns (issue 35): the files read back give a pandas groupby's numbers.

The store's roll-up reaches the GeoParquet and GeoPackage writers as pyarrow
columns, not a dict per cell; this reads both files back (pyarrow, and GDAL
through pyogrio) and compares them with a groupby of the points' parents
(``dggs.cell_to_parent``), and checks that a second format of the same
roll-up neither rolls up nor draws again.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq
import pyogrio
import pytest

import dggs
from dggs.storage import CellStore, rollup_query

STATS = ("count", "sum", "mean", "min", "max")


@pytest.fixture(scope="module")
def store_and_points(tmp_path_factory):
    rng = np.random.default_rng(7)
    n = 3000
    lat = np.clip(rng.normal(45.0, 2.0, n), -89.0, 89.0)
    lng = rng.normal(10.0, 3.0, n)
    lat[:4], lng[:4] = [89.99, -89.99, 0.0, 0.0], [0.0, 0.0, 179.999, -179.999]  # poles, antimeridian
    pop = rng.integers(-500, 500, n).astype(object)
    pop[rng.random(n) < 0.1] = None
    path = tmp_path_factory.mktemp("export") / "e.db"
    with CellStore(path) as store:
        store.keep_rollups([8])
        store.ingest_points(lat, lng, 12, {"pop": pop, "none": np.full(n, None, dtype=object)},
                            types={"pop": "INTEGER", "none": "INTEGER"})
    return path, lat, lng, pop


def _oracle(lat, lng, pop, level):
    ids = np.asarray(dggs.latlng_to_cell(lat, lng, 12, as_int=True), dtype=np.uint64)
    parents = np.asarray(dggs.cell_to_parent(ids, level), dtype=np.uint64)
    frame = pd.DataFrame({"p": parents, "pop": pd.array(list(pop), dtype="Int64")})
    g = frame.groupby("p", sort=True)["pop"]
    out = pd.DataFrame({"count": g.size(), "sum": g.sum(min_count=1), "min": g.min(), "max": g.max()})
    out["mean"] = out["sum"].astype("Float64") / g.count()
    out.index = dggs.int_to_str(out.index.to_numpy(np.uint64)).tolist()
    return out


@pytest.mark.parametrize("level", [0, 5, 8])
def test_geoparquet_and_geopackage_hold_the_groupby(store_and_points, tmp_path, level):
    path, lat, lng, pop = store_and_points
    want = _oracle(lat, lng, pop, level)
    with CellStore(path) as store:
        assert store.export(tmp_path / "c.parquet", level, "pop") == len(want)
        assert store.export(tmp_path / "c.gpkg", level, "pop") == len(want)
    parquet = pq.read_table(tmp_path / "c.parquet")
    gpkg = pyogrio.read_dataframe(tmp_path / "c.gpkg")
    for frame in (parquet.to_pandas(), gpkg):
        assert frame["cell"].tolist() == want.index.tolist()
        for stat in STATS:
            got = frame[stat].tolist()
            expected = [None if pd.isna(v) else v for v in want[stat].tolist()]
            assert [None if v is None or (isinstance(v, float) and np.isnan(v)) else v for v in got] == expected, stat
    types = {f.name: f.type for f in parquet.schema}
    assert types["count"] == pa.int64() and types["sum"] == pa.int64() and types["mean"] == pa.float64()


def test_a_column_of_nulls_keeps_the_null_type(store_and_points, tmp_path):
    path, *_ = store_and_points
    with CellStore(path) as store:
        store.export(tmp_path / "n.parquet", 6, "none", ("count", "sum", "min"))
    types = {f.name: f.type for f in pq.read_table(tmp_path / "n.parquet").schema}
    assert types["sum"] == pa.null() and types["min"] == pa.null() and types["count"] == pa.int64()


def test_a_second_format_of_the_same_roll_up_does_not_roll_up_again(store_and_points, tmp_path, monkeypatch):
    path, *_ = store_and_points
    calls = []
    real = rollup_query.aggregate

    def counted(*args, **kwargs):
        calls.append(args[1])
        return real(*args, **kwargs)

    monkeypatch.setattr(rollup_query, "aggregate", counted)
    with CellStore(path) as store:
        store.export(tmp_path / "a.parquet", 7, "pop")
        store.export(tmp_path / "a.gpkg", 7, "pop")
        store.export(tmp_path / "a.fgb", 7, "pop")
    assert calls == [7]
