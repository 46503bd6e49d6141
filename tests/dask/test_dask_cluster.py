"""dggs.dask on real worker processes: a LocalCluster of two processes gives the single-process answers.

One cluster (two worker processes, one thread each) serves the module. Every answer is checked against
plain Python over the same rows: ids from the Python API, roll-ups as counts of id prefixes (a level-k
parent is the id's first k + 1 characters, docs/grid.md), GeoParquet files against the rows written.
Marked slow: starting the workers takes seconds on shared cores (`make test-all` runs it).
"""

from __future__ import annotations

import collections
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

dd = pytest.importorskip("dask.dataframe", reason="the 'dask' extra is not installed")
pd = pytest.importorskip("pandas")
distributed = pytest.importorskip("distributed")
pq = pytest.importorskip("pyarrow.parquet")

import dggs  # noqa: E402
from dggs.dask import add_cells, aggregate, read_parquet, to_parquet  # noqa: E402
from tests.strategies import special_points  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


@pytest.fixture(scope="module")
def points():
    """Random points on the sphere plus the poles, the antimeridian, the icosahedron's vertices and edges."""
    rng = np.random.default_rng(22)
    n = 40_000
    special = np.array(special_points())
    lat = np.concatenate([special[:, 0], np.degrees(np.arcsin(rng.uniform(-1, 1, n)))])
    lng = np.concatenate([special[:, 1], rng.uniform(-180, 180, n)])
    value = rng.integers(0, 1000, lat.size).astype(float)  # integer-valued: sums are exact in any order
    return pd.DataFrame({"lat": lat, "lng": lng, "value": value})


def test_the_workers_are_separate_processes(client):
    pids = client.run(os.getpid)
    assert len(pids) == 2 and len(set(pids.values())) == 2 and os.getpid() not in pids.values()


def test_add_cells_equals_the_python_api(client, points):
    got = add_cells(dd.from_pandas(points, npartitions=8), level=11).compute()
    expected = dggs.latlng_to_cell(points["lat"].to_numpy(), points["lng"].to_numpy(), 11)
    assert got.index.equals(points.index)
    assert got["cell"].tolist() == expected.tolist()
    assert got[["lat", "lng", "value"]].equals(points)


def test_rollup_equals_id_prefix_counts(client, points):
    ddf = add_cells(dd.from_pandas(points, npartitions=8), level=11)
    agg = aggregate(ddf, 3, "value", stats=("count", "sum", "max")).compute()
    cells = dggs.latlng_to_cell(points["lat"].to_numpy(), points["lng"].to_numpy(), 11).tolist()
    counts = collections.Counter(c[:4] for c in cells)
    sums: dict[str, float] = collections.defaultdict(float)
    tops: dict[str, float] = collections.defaultdict(lambda: -1.0)
    for c, v in zip(cells, points["value"].tolist(), strict=True):
        sums[c[:4]] += v
        tops[c[:4]] = max(tops[c[:4]], v)
    assert agg["count"].to_dict() == dict(counts)
    assert agg["sum"].to_dict() == dict(sums)
    assert agg["max"].to_dict() == dict(tops)
    only_counts = aggregate(ddf, 0).compute()
    assert only_counts["count"].to_dict() == dict(collections.Counter(c[0] for c in cells))


def test_partitioned_geoparquet_equals_single_process(client, points, tmp_path):
    """The files the workers write hold the same rows as those one process writes, face by face."""
    import dask

    ddf = add_cells(dd.from_pandas(points.iloc[:8000], npartitions=4), level=7)
    to_parquet(ddf, str(tmp_path / "cluster"), densify=4)
    with dask.config.set(scheduler="synchronous"):
        to_parquet(ddf, str(tmp_path / "single"), densify=4)
    faces = sorted(p.name for p in (tmp_path / "cluster").glob("face=*"))
    assert faces == sorted(p.name for p in (tmp_path / "single").glob("face=*"))
    for face in faces:
        tables = [pq.read_table(tmp_path / kind / face).sort_by([("cell", "ascending"), ("value", "ascending")])
                  for kind in ("cluster", "single")]
        assert tables[0].equals(tables[1]), face
        assert b"geo" in pq.read_schema(next((tmp_path / "cluster" / face).glob("*.parquet"))).metadata
    back = read_parquet(str(tmp_path / "cluster"), faces=["A", "T"]).compute()
    cells = dggs.latlng_to_cell(points["lat"].to_numpy()[:8000], points["lng"].to_numpy()[:8000], 7).tolist()
    assert sorted(back["cell"]) == sorted(c for c in cells if c[0] in "AT")


def test_bad_coordinates_raise_the_typed_error_from_a_worker(client):
    pdf = pd.DataFrame({"lat": [10.0, 95.0], "lng": [0.0, 0.0]})
    with pytest.raises(dggs.CoordinateError, match="95"):
        add_cells(dd.from_pandas(pdf, npartitions=1), level=5).compute()


def test_example_runs(tmp_path):
    proc = subprocess.run([sys.executable, str(ROOT / "examples" / "dask_cluster.py"), "--out", str(tmp_path / "o"),
                           "--partitions", "3", "--size", "20000"], capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "equal to one process" in proc.stdout
    assert list((tmp_path / "o").glob("face=*/*.parquet"))
