"""Bin points with Apache Spark, roll them up by equal-area cell, and write GeoParquet by parent cell.

Run locally (Spark local[2], Java 17):

    python examples/spark_job.py

or over your own Parquet points (columns lat, lng, value) and on a cluster (the same code under spark-submit):

    spark-submit examples/spark_job.py --input 'hdfs:///points'

Needs the optional extra: pip install 'dggs[spark]'.  Spark's Python workers run $PYSPARK_PYTHON;
dggs.spark.local_session sets it to this interpreter when it is unset.
"""

from __future__ import annotations

import argparse
import os
import tempfile

import numpy as np


def main() -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    import dggs.spark as ds

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--input", help="Parquet folder with lat, lng, value columns (default: generated)")
    parser.add_argument("--points", type=int, default=200_000, help="points to generate without --input")
    parser.add_argument("--level", type=int, default=12, help="level to bin at (default 12)")
    parser.add_argument("--rollup", type=int, default=5, help="coarser level to summarise at (default 5)")
    parser.add_argument("--out", default=None, help="GeoParquet output folder (default: a temp dir)")
    args = parser.parse_args()

    work = tempfile.mkdtemp(prefix="dggs-spark-")
    source = args.input
    if source is None:  # random points on the sphere, in 4 Parquet files
        rng = np.random.default_rng(0)
        source = os.path.join(work, "points")
        os.makedirs(source)
        for k in range(4):
            n = args.points // 4
            pq.write_table(pa.table({"lat": np.degrees(np.arcsin(rng.uniform(-1, 1, n))),
                                     "lng": rng.uniform(-180, 180, n), "value": rng.exponential(10.0, n)}),
                           os.path.join(source, f"part-{k}.parquet"))

    spark = ds.local_session("local[2]", **{"spark.ui.enabled": "false", "spark.ui.showConsoleProgress": "false",
                                           "spark.sql.shuffle.partitions": "8"})
    spark.sparkContext.setLogLevel("ERROR")
    try:
        points = spark.read.parquet(source)
        binned = points.select(ds.latlng_to_cell("lat", "lng", args.level).alias("cell"), "value")
        binned.createOrReplaceTempView("binned")
        with ds.spark_errors():  # a bad row raises dggs's own error, naming it
            top = spark.sql(f"SELECT dggs_cell_to_parent_str(cell, {args.rollup}) AS parent, count(*) AS n, "
                            "sum(value) AS total FROM binned GROUP BY parent ORDER BY total DESC LIMIT 5").collect()
            rolled = ds.rollup(binned, args.rollup, values=["value"], stats=["sum", "mean"])
            cells = rolled.count()
            out = args.out or os.path.join(work, "geoparquet")
            rows = ds.write_geoparquet(binned, out, level=1)
        print(f"rolled up {points.count()} points to {cells} cells at level {args.rollup}; the 5 largest totals:")
        for row in top:
            print(f"  {row.parent}  {row.n:6d} points  total {row.total:12.1f}")
        print(f"wrote {rows} rows of GeoParquet partitioned by level-1 parent to {out}")
    finally:
        spark.stop()


if __name__ == "__main__":
    main()
