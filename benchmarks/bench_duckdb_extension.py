"""The native DuckDB extension against the Python package's numpy call and the Python UDFs (issue 33's targets).

10M random points (uniform on the sphere) to level-17 ids:
- numpy: ``dggs.latlng_to_cell(lat, lng, 17, as_int=True)`` with DGGS_THREADS=1 (set before dggs is imported);
- SQL, extension: ``SELECT sum(dggs_latlng_to_cell(lat, lng, 17)) FROM pts`` over a DuckDB table, 1 and 2 threads;
- SQL, Python UDF (``dggs.duckdb.register``) on 1M points, for scale;
- a roll-up ``GROUP BY dggs_cell_to_parent(id, 8)`` over the 10M ids, extension, 1 and 2 threads;
- polygon fill (a 20x20 degree box at level 12: a constant, which DuckDB folds into a LIST value at plan time; the
  polygon read from a table; the table function's rows), the corners and the WKB polygons of 1M cells, against the Python
  API, one thread.
Best of ``--repeat`` rounds, the cases interleaved in each round. Needs the extension built (``make duckdb-extension``).

Usage: ``DGGS_THREADS=1 python benchmarks/bench_duckdb_extension.py [--n 10000000] [--repeat 3]``.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import time
from collections.abc import Callable
from typing import Any

os.environ.setdefault("DGGS_THREADS", "1")

import duckdb  # noqa: E402
import numpy as np  # noqa: E402
import pyarrow as pa  # noqa: E402
import shapely  # noqa: E402

import dggs  # noqa: E402
import dggs.duckdb  # noqa: E402


def interleaved(cases: dict[str, Callable[[], Any]], repeat: int) -> dict[str, float]:
    """Best wall time of each case over ``repeat`` rounds, the cases taking turns in every round (a shared
    machine's load then weighs on all of them alike)."""
    out = dict.fromkeys(cases, float("inf"))
    for _ in range(repeat):
        for name, fn in cases.items():
            t = time.perf_counter()
            fn()
            out[name] = min(out[name], time.perf_counter() - t)
    return out


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--n", type=int, default=10_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, args.n)))
    lng = rng.uniform(-180, 180, args.n)
    ids = np.asarray(dggs.latlng_to_cell(lat, lng, 17, as_int=True), np.uint64)

    con = duckdb.connect(config={"allow_unsigned_extensions": "true"})
    if not dggs.duckdb.load(con):
        raise SystemExit("build the extension first: make duckdb-extension")
    con.register("pts_view", con.from_arrow(pa.table({"lat": lat, "lng": lng})))
    con.execute("CREATE TABLE pts AS SELECT * FROM pts_view")
    con.execute("CREATE TABLE cells AS SELECT dggs_latlng_to_cell(lat, lng, 17) AS id FROM pts")
    total = con.sql("SELECT sum(id::HUGEINT) FROM cells").fetchall()[0][0]
    assert int(total) == int(ids.astype(object).sum()), "the extension's ids differ from the numpy call's"

    def sql(query: str, threads: int) -> Callable[[], Any]:
        return lambda: (con.execute(f"SET threads = {threads}"), con.sql(query).fetchall())

    points = "SELECT sum(dggs_latlng_to_cell(lat, lng, 17)) FROM pts"
    rollup = "SELECT count(*) FROM (SELECT dggs_cell_to_parent(id, 8) AS p, count(*) FROM cells GROUP BY 1)"
    box = shapely.box(-10, -10, 10, 10)
    m = min(args.n, 1_000_000)
    some = ids[:m]
    con.execute(f"CREATE TABLE some_cells AS SELECT id FROM cells LIMIT {m}")
    con.execute(f"CREATE TABLE boxes AS SELECT '{box.wkt}' AS w")  # the polygon as data, not a constant
    t = interleaved({
        "numpy": lambda: dggs.latlng_to_cell(lat, lng, 17, as_int=True),
        "sql1": sql(points, 1), "sql2": sql(points, 2), "roll1": sql(rollup, 1), "roll2": sql(rollup, 2),
        "fill_py": lambda: dggs.polygon_to_cells(box, 12, as_int=True),
        "fill_sql": sql(f"SELECT len(dggs_polygon_wkt_to_cells('{box.wkt}', 12, 'center'))", 1),
        "fill_tab": sql("SELECT len(dggs_polygon_wkt_to_cells(w, 12, 'center')) FROM boxes", 1),
        "fill_rows": sql(f"SELECT count(*) FROM dggs_polygon_wkt_to_cells('{box.wkt}', 12, 'center')", 1),
        "bnd_py": lambda: dggs.cell_to_boundary(some),
        "bnd_sql": sql("SELECT sum(len(dggs_cell_to_boundary(id))) FROM some_cells", 1),
        "wkb_py": lambda: shapely.to_wkb(dggs.cell_to_polygon(some, densify=0)),
        "wkb_sql": sql("SELECT sum(octet_length(dggs_cell_to_boundary_wkb(id, 0))) FROM some_cells", 1),
        "wkbd_py": lambda: shapely.to_wkb(dggs.cell_to_polygon(some)),
        "wkbd_sql": sql("SELECT sum(octet_length(dggs_cell_to_boundary_wkb(id))) FROM some_cells", 1),
    }, args.repeat)  # fmt: skip
    n_fill = len(dggs.polygon_to_cells(box, 12, as_int=True))

    n_udf = min(args.n, 1_000_000)
    udf = dggs.duckdb.register(duckdb.connect())
    udf.register("pts_view", con.sql(f"SELECT * FROM pts LIMIT {n_udf}").arrow())
    udf.execute("CREATE TABLE pts AS SELECT * FROM pts_view")
    udf.execute("SET threads = 1")
    udf_s = interleaved({"udf": lambda: udf.sql(points).fetchall()}, args.repeat)["udf"]

    n = args.n
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    print(f"{n:,} points to level-17 ids (best of {args.repeat}, cases interleaved); DuckDB {duckdb.__version__}, "
          f"commit {commit}, load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")  # fmt: skip
    print(f"  numpy dggs.latlng_to_cell, DGGS_THREADS=1: {t['numpy']:.3f} s  ({t['numpy'] / n * 1e9:.0f} ns a point)")
    for threads in (1, 2):
        s_ = t[f"sql{threads}"]
        print(f"  SQL extension, {threads} thread(s):        {s_:.3f} s  ({s_ / n * 1e9:.0f} ns a point; "
              f"{t['numpy'] / s_:.2f}x the numpy call)")  # fmt: skip
        print(f"  roll-up GROUP BY dggs_cell_to_parent(id, 8), {threads} thread(s): {t[f'roll{threads}']:.3f} s")
    print(f"  extension 2 threads / 1 thread: {t['sql1'] / t['sql2']:.2f}x (roll-up {t['roll1'] / t['roll2']:.2f}x)")
    print(f"  SQL Python UDF, 1 thread, {n_udf:,} points: {udf_s:.3f} s ({udf_s / n_udf * 1e9:.0f} ns a point)")
    print(f"  polygon fill, 20x20 degree box at level 12 ({n_fill:,} cells), 1 thread: dggs.polygon_to_cells "
          f"{t['fill_py']:.3f} s, SQL dggs_polygon_wkt_to_cells {t['fill_sql']:.3f} s ({t['fill_py'] / t['fill_sql']:.2f}x) on a "
          f"constant (folded by DuckDB into a LIST value), {t['fill_tab']:.3f} s ({t['fill_py'] / t['fill_tab']:.2f}x) on a "
          f"table's polygon, as rows {t['fill_rows']:.3f} s ({t['fill_py'] / t['fill_rows']:.2f}x)")
    print(f"  corners of {m:,} cells, 1 thread: dggs.cell_to_boundary {t['bnd_py']:.3f} s, SQL dggs_cell_to_boundary "
          f"{t['bnd_sql']:.3f} s ({t['bnd_py'] / t['bnd_sql']:.2f}x)")
    print(f"  WKB polygons of {m:,} cells, 1 thread: shapely.to_wkb(dggs.cell_to_polygon(ids, densify=0)) "
          f"{t['wkb_py']:.3f} s, SQL dggs_cell_to_boundary_wkb(id, 0) {t['wkb_sql']:.3f} s ({t['wkb_py'] / t['wkb_sql']:.2f}x)")
    print(f"  default (area-exact) WKB polygons, 1 thread: shapely.to_wkb(dggs.cell_to_polygon(ids)) {t['wkbd_py']:.3f} s, "
          f"SQL dggs_cell_to_boundary_wkb(id) {t['wkbd_sql']:.3f} s ({t['wkbd_py'] / t['wkbd_sql']:.2f}x)")


if __name__ == "__main__":
    main()
