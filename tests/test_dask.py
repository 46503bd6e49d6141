"""Scale-out on Dask: a LocalCluster gives exactly the single-process result."""

from __future__ import annotations

import numpy as np
import pytest

dd = pytest.importorskip("dask.dataframe", reason="the 'dask' extra is not installed")
pd = pytest.importorskip("pandas")
distributed = pytest.importorskip("distributed")

import dggs  # noqa: E402
from dggs.dask import add_cells, aggregate, read_parquet, to_parquet  # noqa: E402


@pytest.fixture(scope="module")
def data():
    rng = np.random.default_rng(5)
    n = 60_000
    return pd.DataFrame(
        {
            "lat": np.degrees(np.arcsin(rng.uniform(-1, 1, n))),
            "lng": rng.uniform(-180, 180, n),
            "pop": rng.integers(0, 1000, n).astype(float),  # integer-valued: sums are exact
        }
    )


def single_process(pdf, level, fine=9):
    cells = dggs.latlng_to_cell(pdf["lat"].to_numpy(), pdf["lng"].to_numpy(), fine)
    parents = np.array([c[: level + 1] for c in cells.tolist()])
    out = {}
    for p, v in zip(parents.tolist(), pdf["pop"].tolist()):
        s = out.setdefault(p, [0, 0.0, float("inf"), float("-inf")])
        s[0] += 1
        s[1] += v
        s[2] = min(s[2], v)
        s[3] = max(s[3], v)
    return out


def test_local_cluster_equals_single_process(data, tmp_path):
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster):
            ddf = add_cells(dd.from_pandas(data, npartitions=8), level=9)
            agg = aggregate(ddf, 4, "pop", stats=("count", "sum", "min", "max", "mean")).compute()
            to_parquet(ddf, str(tmp_path / "pq"))
    expected = single_process(data, 4)
    assert set(agg.index) == set(expected)
    for cell, (count, total, lo, hi) in expected.items():
        row = agg.loc[cell]
        assert row["count"] == count and row["sum"] == total and row["min"] == lo and row["max"] == hi
        assert row["mean"] == pytest.approx(total / count, rel=1e-15)
    back = read_parquet(str(tmp_path / "pq"), faces=["C"]).compute()
    assert len(back) and set(back["cell"].str[0]) == {"C"}
    assert len(back) == int(sum(v[0] for k, v in expected.items() if k[0] == "C"))


def test_bad_columns(data):
    ddf = dd.from_pandas(data, npartitions=2)
    with pytest.raises(dggs.DggsValueError, match="'latitude'"):
        add_cells(ddf, 5, lat="latitude")
    with pytest.raises(dggs.DggsValueError, match="stat 'median'"):
        aggregate(add_cells(ddf, 5), 3, "pop", stats=("median",))
