"""Bin points on a Dask cluster and roll them up by equal-area cell.

Run locally (a 2-process LocalCluster):

    python examples/dask_cluster.py

or against a running scheduler (same code, more machines):

    python examples/dask_cluster.py --scheduler tcp://scheduler.example:8786 --input 's3://bucket/points/*.parquet'

Needs the optional extra: pip install 'dggs[dask]'.
"""

from __future__ import annotations

import argparse
import os
import tempfile

import numpy as np


def _random_points(seed: int, n: int = 125_000):
    import pandas as pd

    rng = np.random.default_rng(seed)
    return pd.DataFrame(
        {
            "lat": np.degrees(np.arcsin(rng.uniform(-1, 1, n))),
            "lng": rng.uniform(-180, 180, n),
            "value": rng.exponential(10.0, n),
        }
    )


def main() -> None:
    import dask
    import dask.dataframe as dd
    from distributed import Client, LocalCluster

    from dggs.dask import add_cells, aggregate, to_parquet

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scheduler", help="address of a dask.distributed scheduler (default: a LocalCluster)")
    parser.add_argument("--input", help="Parquet/CSV glob with lat, lng, value columns (default: generated)")
    parser.add_argument("--level", type=int, default=12, help="level to bin at (default 12, ~24 km^2)")
    parser.add_argument("--rollup", type=int, default=6, help="coarser level to summarise at (default 6)")
    parser.add_argument("--out", default=None, help="Parquet output folder (default: a temp dir)")
    parser.add_argument("--partitions", type=int, default=8, help="generated partitions (default 8)")
    parser.add_argument("--size", type=int, default=125_000, help="points in a generated partition (default 125,000)")
    args = parser.parse_args()

    cluster = None if args.scheduler else LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                                          dashboard_address=None)
    with Client(args.scheduler or cluster) as client:
        print("dask dashboard / scheduler:", client.dashboard_link or args.scheduler)
        if args.input:
            reader = dd.read_parquet if args.input.endswith(".parquet") else dd.read_csv
            ddf = reader(args.input)
        else:  # generated on the workers
            ddf = dd.from_map(_random_points, range(args.partitions), n=args.size)
        ddf = add_cells(ddf, args.level)
        print("workers (separate processes):", sorted(client.run(os.getpid).values()))
        summary = aggregate(ddf, args.rollup, "value", stats=("count", "sum")).compute()
        with dask.config.set(scheduler="synchronous"):  # the same roll-up in this one process
            alone = aggregate(ddf, args.rollup, "value", stats=("count", "sum")).compute()
        same = summary.sort_index()["count"].equals(alone.sort_index()["count"]) and np.allclose(
            summary.sort_index()["sum"], alone.sort_index()["sum"], rtol=1e-12)
        print(f"roll-up of {int(summary['count'].sum())} points to {len(summary)} cells at level {args.rollup},",
              "equal to one process" if same else "DIFFERENT from one process")
        print(summary.sort_values("sum", ascending=False).head(10).to_string())
        out = args.out or tempfile.mkdtemp(prefix="dggs-parquet-")
        to_parquet(ddf, out)
        print("wrote GeoParquet partitioned by base cell to", out)
    if cluster is not None:
        cluster.close()
    if not same:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
