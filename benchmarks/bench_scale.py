"""Points binned at scale: Spark local[2] through dggs's Arrow UDF, Dask on two worker processes, H3 alike.

The job: read N points (lat, lng, value) from a folder of 8 Parquet files, give each its cell id (int64),
and reduce the ids to one number (their maximum), so every id is computed and nothing but the answer
comes back.  Timed once each, in this order (wall seconds, the engine started and warmed up first):

- dggs's own call: ``dggs.latlng_to_cell(lat, lng, level, as_int=True)`` on the arrays in memory, on two
  threads (``DGGS_THREADS=2``; no Parquet read) -- the yardstick;
- Spark ``local[2]``: an Arrow UDF that returns its input (Spark's own cost: read, batches to Python and
  back), dggs's Arrow UDF (``dggs.spark.latlng_to_cell``), H3 through h3ronpy in the same kind of Arrow
  UDF, and H3 the way h3-pyspark calls it (a row-at-a-time ``udf`` of ``h3.latlng_to_cell``, timed on
  fewer points: h3-pyspark 1.2.6 itself calls the h3 3.x names, which h3 4 has not, so it cannot run);
- Dask, a LocalCluster of two worker processes: ``dggs.dask.add_cells`` (string ids, its API), the same
  with int64 ids through ``map_partitions``, and h3ronpy through ``map_partitions``;
- the first tasks' cost: a new Spark session's first and second job on 2,000 points (its Python workers
  start and import dggs), then a second new session.

H3 runs at resolution 9 and dggs at the level nearest it in mean cell area.  Run::

    .venv-bench/bin/python benchmarks/bench_scale.py            # 10M points, a few minutes on 2 cores
    .venv-bench/bin/python benchmarks/bench_scale.py --quick    # 1M points
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import loadavg, points  # noqa: E402

H3_RES = 9


def nearest_level(res: int) -> int:
    import h3

    import dggs

    target = h3.average_hexagon_area(res, unit="m^2")
    table = dggs.level_table(dggs.MAX_LEVEL)
    return min(range(dggs.MAX_LEVEL + 1), key=lambda lv: abs(math.log(table[lv]["area_m2"] / target)))


def write_points(folder: Path, n: int) -> tuple[np.ndarray, np.ndarray]:
    import pyarrow as pa
    import pyarrow.parquet as pq

    lat, lng = points(n)
    value = np.random.default_rng(1).exponential(1.0, n)
    folder.mkdir(parents=True)
    for k, rows in enumerate(np.array_split(np.arange(n), 8)):
        pq.write_table(pa.table({"lat": lat[rows], "lng": lng[rows], "value": value[rows]}), folder / f"part-{k}.parquet")
    return lat, lng


def timed(f: Any) -> tuple[float, Any]:
    t0 = time.perf_counter()
    out = f()
    return time.perf_counter() - t0, out


# ---------------------------------------------------------------------------------------------- Spark


# Arrow UDFs without type hints: Spark takes a hinted function for another kind of UDF
def _identity(lat, lng):  # type: ignore[no-untyped-def]
    import pyarrow.compute as pc

    return pc.cast(lat, "int64", safe=False)


def _h3ronpy(lat, lng):  # type: ignore[no-untyped-def]
    import h3ronpy.vector as hv
    import pyarrow as pa

    return hv.coordinates_to_cells(lat, lng, H3_RES).cast(pa.int64())


def _h3_row(lat: float, lng: float) -> int:
    import h3

    return h3.str_to_int(h3.latlng_to_cell(lat, lng, H3_RES))


def spark_session() -> Any:
    import dggs.spark

    conf = {"spark.ui.enabled": "false", "spark.ui.showConsoleProgress": "false", "spark.driver.memory": "2g",
            "spark.sql.shuffle.partitions": "4"}
    spark = dggs.spark.local_session("local[2]", **conf)
    spark.sparkContext.setLogLevel("ERROR")
    return spark


def spark_rows(folder: Path, row_folder: Path, level: int, expected_max: int) -> list[tuple[str, float, int]]:
    from pyspark.sql import functions as F

    import dggs.spark as ds

    spark = spark_session()
    try:
        df = spark.read.parquet(str(folder))
        n = df.count()
        warm = spark.read.parquet(str(row_folder))
        warm.select(ds.latlng_to_cell("lat", "lng", level).alias("c")).agg(F.max("c")).collect()  # workers up
        identity = F.arrow_udf(_identity, "bigint")
        h3r = F.arrow_udf(_h3ronpy, "bigint")
        h3row = F.udf(_h3_row, "bigint")
        out = []
        t, _ = timed(lambda: df.select(identity("lat", "lng").alias("c")).agg(F.max("c")).collect())
        out.append(("Spark local[2]: Arrow UDF returning its input (Spark's own cost)", t, n))
        t, got = timed(lambda: df.select(ds.latlng_to_cell("lat", "lng", level).alias("c")).agg(F.max("c")).first()[0])
        assert got == expected_max, (got, expected_max)
        out.append((f"Spark local[2]: dggs Arrow UDF, level {level}", t, n))
        t, _ = timed(lambda: df.select(h3r("lat", "lng").alias("c")).agg(F.max("c")).collect())
        out.append((f"Spark local[2]: h3ronpy in an Arrow UDF, res {H3_RES}", t, n))
        m = warm.count()
        t, _ = timed(lambda: warm.select(h3row("lat", "lng").alias("c")).agg(F.max("c")).collect())
        out.append((f"Spark local[2]: h3 row-at-a-time udf (h3-pyspark's way), res {H3_RES}", t, m))
        return out
    finally:
        spark.stop()


def first_task(level: int) -> list[tuple[str, float]]:
    """The first jobs' wall time in a new session, then in a second new session."""
    from pyspark.sql import functions as F

    import dggs.spark as ds

    out = []
    for label in ("first new session", "second new session"):
        spark = spark_session()
        try:
            df = spark.range(2000, numPartitions=2).select((F.col("id") % 170 - 85).cast("double").alias("lat"),
                                                            (F.col("id") % 350 - 175).cast("double").alias("lng"))
            identity = F.arrow_udf(_identity, "bigint")
            t0, _ = timed(lambda d=df, u=identity: d.select(u("lat", "lng").alias("c")).agg(F.max("c")).collect())
            job = lambda d=df: d.select(ds.latlng_to_cell("lat", "lng", level).alias("c")).agg(F.max("c")).collect()  # noqa: E731
            t1, _ = timed(job)
            t2, _ = timed(job)
            out.append((f"{label}: first job, an Arrow UDF returning its input (the Python workers start)", t0))
            out.append((f"{label}: first dggs job (each worker imports dggs)", t1))
            out.append((f"{label}: second dggs job", t2))
        finally:
            spark.stop()
    return out


# ---------------------------------------------------------------------------------------------- Dask


def _dggs_int(pdf: Any, level: int) -> Any:
    import pandas as pd

    import dggs

    ids = dggs.latlng_to_cell(pdf["lat"].to_numpy(), pdf["lng"].to_numpy(), level, as_int=True)
    return pd.Series(np.asarray(ids, np.uint64).view(np.int64), index=pdf.index)


def _h3_int(pdf: Any) -> Any:
    import h3ronpy.vector as hv
    import pandas as pd

    ids = hv.coordinates_to_cells(pdf["lat"].to_numpy(), pdf["lng"].to_numpy(), H3_RES)
    return pd.Series(np.asarray(ids).view(np.int64), index=pdf.index)


def dask_rows(folder: Path, level: int, n: int, expected_max: int) -> list[tuple[str, float, int]]:
    import dask.dataframe as dd
    from distributed import Client, LocalCluster

    from dggs.dask import add_cells

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster):
        ddf = dd.read_parquet(str(folder))
        ddf.map_partitions(_dggs_int, level, meta=("c", "int64")).max().compute()  # workers up and compiled
        out = []
        t, _ = timed(lambda: add_cells(ddf, level)["cell"].max().compute())
        out.append((f"Dask, 2 worker processes: dggs.dask.add_cells (string ids), level {level}", t, n))
        t, got = timed(lambda: ddf.map_partitions(_dggs_int, level, meta=("c", "int64")).max().compute())
        assert int(got) == expected_max, (got, expected_max)
        out.append((f"Dask, 2 worker processes: dggs int64 ids by map_partitions, level {level}", t, n))
        t, _ = timed(lambda: ddf.map_partitions(_h3_int, meta=("c", "int64")).max().compute())
        out.append((f"Dask, 2 worker processes: h3ronpy by map_partitions, res {H3_RES}", t, n))
    return out


# ---------------------------------------------------------------------------------------------- report


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", type=int, default=10_000_000)
    ap.add_argument("--row-points", type=int, default=500_000, help="points for the row-at-a-time udf")
    ap.add_argument("--quick", action="store_true", help="1M points (row udf: 100,000)")
    args = ap.parse_args()
    if args.quick:
        args.points, args.row_points = 1_000_000, 100_000
    os.environ["DGGS_THREADS"] = "2"
    import dggs

    level = nearest_level(H3_RES)
    load0 = loadavg()
    work = Path(tempfile.mkdtemp(prefix="dggs-bench-scale-"))
    lat, lng = write_points(work / "points", args.points)
    write_points(work / "rows", args.row_points)

    dggs.latlng_to_cell(lat, lng, level, as_int=True)  # compiled (the parallel loop: the size picks it)
    t_np, ids = min((timed(lambda: dggs.latlng_to_cell(lat, lng, level, as_int=True)) for _ in range(3)),
                    key=lambda r: r[0])
    expected_max = int(np.asarray(ids, np.uint64).max())
    rows = [(f"dggs.latlng_to_cell, numpy arrays in memory, 2 threads, level {level}", t_np, args.points)]
    rows += spark_rows(work / "points", work / "rows", level, expected_max)
    rows += dask_rows(work / "points", level, args.points, expected_max)
    firsts = first_task(level)
    load1 = loadavg()

    print("## Points at scale: Spark and Dask (bench_scale.py)\n")
    print(f"{args.points:,} points uniform on the sphere in 8 Parquet files; each job bins them (int64 ids) and "
          f"reduces the ids to their maximum. dggs level {level} is the level nearest H3 res {H3_RES} in mean "
          f"cell area. Load average at the start {load0}, at the end {load1} (2 cores shared with other work: "
          "the ratios are the numbers to read).\n")
    print("| job | points | wall | per point | per point per core | / dggs numpy call |")
    print("|---|---:|---:|---:|---:|---:|")
    base = t_np / args.points
    for name, t, n in rows:
        per = t / n
        print(f"| {name} | {n:,} | {t:.2f} s | {per * 1e9:.0f} ns | {per * 2e9:.0f} ns | {per / base:.2f}x |")
    spark_dggs = next(t for name, t, _ in rows if "dggs Arrow UDF" in name)
    spark_h3 = next(t for name, t, _ in rows if "h3ronpy in an Arrow UDF" in name)
    print(f"\nSpark's dggs Arrow UDF job takes {spark_dggs / t_np:.2f}x the time of the two-thread numpy call "
          f"(target: within 1.5x); h3ronpy in the same kind of UDF takes {spark_h3 / spark_dggs:.2f}x the dggs "
          "job's time (target: above 1).\n")
    print("First tasks (2,000 points, 2 partitions, local[2]), in a new session, then in a second new "
          "session.\n")
    print("| job | wall |")
    print("|---|---:|")
    for name, t in firsts:
        print(f"| {name} | {t:.2f} s |")
    print()


if __name__ == "__main__":
    main()
