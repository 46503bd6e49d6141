"""The native DuckDB extension against the Python package's numpy call and the Python UDFs (issue 33's targets).

10M random points (uniform on the sphere) to level-17 ids:
- numpy: ``dggs.latlng_to_cell(lat, lng, 17, as_int=True)`` with DGGS_THREADS=1 (set before dggs is imported);
- SQL, extension: ``SELECT sum(dggs_latlng_to_cell(lat, lng, 17)) FROM pts`` over a DuckDB table, 1 and 2 threads;
- SQL, Python UDF (``dggs.duckdb.register``) on 1M points, for scale;
- a roll-up ``GROUP BY dggs_cell_to_parent(id, 8)`` over the 10M ids, extension, 1 and 2 threads;
- polygon fill (a 20x20 degree box at level 12) and the corners of 1M cells, against the Python API, one thread.
Best of ``--repeat`` runs each. Needs the extension built (``make duckdb-extension``).

Usage: ``DGGS_THREADS=1 python benchmarks/bench_duckdb_extension.py [--n 10000000] [--repeat 3]``.
"""

from __future__ import annotations

import argparse
import os
import time

os.environ.setdefault("DGGS_THREADS", "1")

import duckdb  # noqa: E402
import numpy as np  # noqa: E402

import dggs  # noqa: E402
import dggs.duckdb  # noqa: E402


def best(fn, repeat: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--n", type=int, default=10_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, args.n)))
    lng = rng.uniform(-180, 180, args.n)

    numpy_s = best(lambda: dggs.latlng_to_cell(lat, lng, 17, as_int=True), args.repeat)
    ids = np.asarray(dggs.latlng_to_cell(lat, lng, 17, as_int=True), np.uint64)

    con = duckdb.connect(config={"allow_unsigned_extensions": "true"})
    if not dggs.duckdb.load(con):
        raise SystemExit("build the extension first: make duckdb-extension")
    pts = con.from_arrow(__import__("pyarrow").table({"lat": lat, "lng": lng}))
    con.register("pts_view", pts)
    con.execute("CREATE TABLE pts AS SELECT * FROM pts_view")
    con.execute("CREATE TABLE cells AS SELECT dggs_latlng_to_cell(lat, lng, 17) AS id FROM pts")
    total = con.sql("SELECT sum(id::HUGEINT) FROM cells").fetchall()[0][0]
    assert int(total) == int(ids.astype(object).sum()), "the extension's ids differ from the numpy call's"

    rows = []
    for threads in (1, 2):
        con.execute(f"SET threads = {threads}")
        sql_s = best(lambda: con.sql("SELECT sum(dggs_latlng_to_cell(lat, lng, 17)) FROM pts").fetchall(), args.repeat)
        roll_s = best(lambda: con.sql("SELECT count(*) FROM (SELECT dggs_cell_to_parent(id, 8) AS p, count(*) "
                                      "FROM cells GROUP BY 1)").fetchall(), args.repeat)  # fmt: skip
        rows.append((threads, sql_s, roll_s))

    # polygon fill and boundaries against the Python API, one thread each
    import shapely

    con.execute("SET threads = 1")
    box = shapely.box(-10, -10, 10, 10)
    fill_py = best(lambda: dggs.polygon_to_cells(box, 12, as_int=True), args.repeat)
    fill_sql = best(lambda: con.sql(f"SELECT len(dggs_polygon_wkt_to_cells('{box.wkt}', 12, 'center'))").fetchall(),
                    args.repeat)  # fmt: skip
    n_fill = len(dggs.polygon_to_cells(box, 12, as_int=True))
    m = min(args.n, 1_000_000)
    some = ids[:m]
    bnd_py = best(lambda: dggs.cell_to_boundary(some), args.repeat)
    con.execute(f"CREATE TABLE some_cells AS SELECT id FROM cells LIMIT {m}")
    bnd_sql = best(lambda: con.sql("SELECT sum(len(dggs_cell_to_boundary(id))) FROM some_cells").fetchall(), args.repeat)
    wkb_sql = best(lambda: con.sql("SELECT sum(octet_length(dggs_cell_to_boundary_wkb(id))) FROM some_cells").fetchall(),
                   args.repeat)  # fmt: skip

    n_udf = min(args.n, 1_000_000)
    udf = dggs.duckdb.register(duckdb.connect())
    udf.register("pts_view", con.sql(f"SELECT * FROM pts LIMIT {n_udf}").arrow())
    udf.execute("CREATE TABLE pts AS SELECT * FROM pts_view")
    udf.execute("SET threads = 1")
    udf_s = best(lambda: udf.sql("SELECT sum(dggs_latlng_to_cell(lat, lng, 17)) FROM pts").fetchall(), args.repeat)

    n = args.n
    print(f"{n:,} points to level-17 ids (best of {args.repeat}); DuckDB {duckdb.__version__}")
    print(f"  numpy dggs.latlng_to_cell, DGGS_THREADS=1: {numpy_s:.3f} s  ({numpy_s / n * 1e9:.0f} ns a point)")
    for threads, sql_s, roll_s in rows:
        print(f"  SQL extension, {threads} thread(s):        {sql_s:.3f} s  ({sql_s / n * 1e9:.0f} ns a point; "
              f"{numpy_s / sql_s:.2f}x the numpy call)")  # fmt: skip
        print(f"  roll-up GROUP BY dggs_cell_to_parent(id, 8), {threads} thread(s): {roll_s:.3f} s")
    one, two = rows[0][1], rows[1][1]
    print(f"  extension 2 threads / 1 thread: {one / two:.2f}x")
    print(f"  SQL Python UDF, 1 thread, {n_udf:,} points: {udf_s:.3f} s ({udf_s / n_udf * 1e9:.0f} ns a point)")
    print(f"  polygon fill, 20x20 degree box at level 12 ({n_fill:,} cells), 1 thread: dggs.polygon_to_cells "
          f"{fill_py:.3f} s, SQL dggs_polygon_wkt_to_cells {fill_sql:.3f} s ({fill_py / fill_sql:.2f}x)")
    print(f"  boundaries of {m:,} cells, 1 thread: dggs.cell_to_boundary {bnd_py:.3f} s, SQL dggs_cell_to_boundary "
          f"{bnd_sql:.3f} s ({bnd_py / bnd_sql:.2f}x), SQL dggs_cell_to_boundary_wkb {wkb_sql:.3f} s")


if __name__ == "__main__":
    main()
