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
    for p, v in zip(parents.tolist(), pdf["pop"].tolist(), strict=True):
        s = out.setdefault(p, [0, 0.0, float("inf"), float("-inf")])
        s[0] += 1
        s[1] += v
        s[2] = min(s[2], v)
        s[3] = max(s[3], v)
    return out


@pytest.mark.slow  # 12 s here: starts a LocalCluster
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


def test_to_parquet_writes_geoparquet(data, tmp_path):
    """Every file is GeoParquet 1.1; geopandas, DuckDB and read_parquet read the same rows back."""
    import json

    geopandas = pytest.importorskip("geopandas")
    duckdb = pytest.importorskip("duckdb")
    pq = pytest.importorskip("pyarrow.parquet")
    shapely = pytest.importorskip("shapely")
    pdf = data.iloc[:3000]
    ddf = add_cells(dd.from_pandas(pdf, npartitions=3), level=6)
    path = tmp_path / "pq"
    to_parquet(ddf, str(path), densify=4)
    files = sorted(path.glob("face=*/part.*.parquet"))
    assert files and not list(path.rglob("*.tmp"))
    for file in files:
        geo = json.loads(pq.read_schema(file).metadata[b"geo"])
        assert geo["version"] == "1.1.0" and geo["primary_column"] == "geometry"
        assert geo["columns"]["geometry"]["encoding"] == "WKB" and "bbox" in geo["columns"]["geometry"]["covering"]
    cells = dggs.latlng_to_cell(pdf["lat"].to_numpy(), pdf["lng"].to_numpy(), 6)
    want = pdf.assign(cell=cells, cell_id=dggs.str_to_int(cells).astype(np.int64))
    want = want.sort_values(["cell_id", "pop", "lat"], ignore_index=True)

    frame = geopandas.read_parquet(path).sort_values(["cell_id", "pop", "lat"], ignore_index=True)
    assert frame.crs.to_string() == "OGC:CRS84"
    for col in ("cell", "cell_id", "lat", "lng", "pop"):
        assert frame[col].tolist() == want[col].tolist()
    assert (frame["face"].astype(str) == frame["cell"].str[0]).all()
    polys = dggs.cell_to_polygon(want["cell"].to_numpy(), 4)
    assert shapely.equals_exact(frame.geometry.values, polys, 0).all()

    rows = duckdb.sql(
        f"SELECT cell, cell_id, lat, lng, pop, face, ST_AsWKB(geometry) FROM read_parquet('{path}/*/*.parquet', "
        "hive_partitioning = true) ORDER BY cell_id, pop, lat"
    ).fetchall()
    assert [r[0] for r in rows] == want["cell"].tolist() and [r[1] for r in rows] == want["cell_id"].tolist()
    assert [r[4] for r in rows] == want["pop"].tolist() and all(r[5] == r[0][0] for r in rows)
    assert shapely.equals_exact(shapely.from_wkb([bytes(r[6]) for r in rows]), polys, 0).all()

    back = read_parquet(str(path), faces=["C", "D"]).compute()
    assert sorted(back["cell"]) == sorted(c for c in cells if c[0] in "CD")


def test_to_parquet_of_an_aggregate_and_plain(data, tmp_path):
    geopandas = pytest.importorskip("geopandas")
    ddf = add_cells(dd.from_pandas(data.iloc[:2000], npartitions=2), level=7)
    agg = aggregate(ddf, 3, "pop", stats=("count", "sum"))  # indexed by cell
    to_parquet(agg, str(tmp_path / "agg"))
    frame = geopandas.read_parquet(tmp_path / "agg")
    want = agg.compute()
    assert sorted(frame["cell"]) == sorted(want.index) and frame["count"].sum() == 2000
    to_parquet(ddf, str(tmp_path / "plain"), geometry=False)
    plain = read_parquet(str(tmp_path / "plain")).compute()
    assert len(plain) == 2000 and "geometry" not in plain.columns
    with pytest.raises(dggs.DggsValueError, match="'cell_id'"):
        to_parquet(ddf.assign(cell_id=1), str(tmp_path / "x"))
