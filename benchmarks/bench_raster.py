"""Raster to cells (issue 19): dggs.raster against h3ronpy, raster2dggs and exactextract, and the peak RSS.

Data: uint8 EPSG:4326 GeoTIFFs (deflate, tiled 512x512), a smooth field plus Gaussian noise made with numpy,
written a tile at a time with rasterio into a temporary folder (no download, no raster whole in memory).
1. In process, one raster (``--rows`` x ``--cols`` pixels of 0.01 deg from 50N 5E, ~0.87 km2 each) at level
   ``--fine`` (15, 0.89 km2: cells the size of the pixels) and ``--coarse`` (11, 72 km2: ~80 pixels a cell), h3
   at the nearest cell area (res 8, 6): ``raster_to_cells`` ``"center"`` and ``"mean"`` from the file, h3ronpy's
   ``raster_to_dataframe(..., compact=False)`` on the band read with rasterio (the read timed with it and
   alone), exactextract's ``mean`` of the same cells as ``dggs.cell_to_polygon`` polygons (made untimed).  A
   fresh process a thread mode: one thread (DGGS_THREADS, NUMBA_NUM_THREADS, RAYON_NUM_THREADS, OMP_NUM_THREADS
   = 1; CPU time, ``time.process_time``) and the default threads (wall).  Each function runs first on a small
   input (compilation), each case once untimed, then the cases in turn over ``--rounds``, medians kept
   (``_common.interleaved``); a call over ``--budget`` s is timed once, on a sample if one says so (marked *).
2. Whole processes writing Parquet: ``dggs bin-raster --mode center`` (and ``mean`` at the coarse level; it
   always writes polygons) against ``raster2dggs h3 --sample nn`` (the pixel under each cell's centre) with
   ``-g polygon`` and ``-g none``, and ``--overlay weighted`` (area-weighted mean) at the coarse level; a
   warm-up run each, then rounds alternating the thread modes; CPU from ``RUSAGE_CHILDREN``.
3. Memory: ``--rss-rows`` x ``--rss-cols`` pixels of ``--rss-deg`` round 0N 0E (30,000 x 60,000 of 0.006 deg:
   the globe, 1.8 GB; ``--quick`` 2,048 x 2,048), ``mode="mean"`` at ``--rss-level`` (8) in a fresh process on
   the default threads after a 256x256 warm-up: ``ru_maxrss`` (whole process) against issue 19's 600 MB, and
   the time.  The parent reads the worker's VmRSS / VmHWM every 2 s and kills it past ``--rss-cap`` MB (the
   machine is shared) or ``--rss-timeout`` s, reporting the peak so far.  The globe takes an hour or more.
4. A projected raster (issue 35): ``--rows`` x ``--cols`` uint8 pixels of 1 km in UTM 32N (EPSG:32632) from 300 km
   E 5,600 km N (~50.5N 6E), at the same two levels (~0.9 and ~72 pixels a cell), one thread (CPU):
   ``"center"``, exact ``"mean"`` (cut cell by cell in the raster's plane where it pays, dggs.raster.plane), the
   same ``"mean"`` cut pixel by pixel (the path before), and binning every pixel's centre (pyproj to lat/lng,
   ``latlng_to_cell``, a groupby), interleaved as in 1.
Prints one Markdown section: tables, targets (met / missed), load average, commit.  ``--quick``: small sizes,
1 round (run_all's smoke test)."""

from __future__ import annotations

import argparse
import json
import math
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402
import pyarrow.parquet as pq  # noqa: E402

import _common as c  # noqa: E402
from _common import NOTES, fmt_ns, loadavg, note, thread_env  # noqa: E402

HERE = Path(__file__).resolve()
BIN = Path(sys.executable).parent
FULL = dict(rows=1000, cols=1500, fine=15, coarse=11, rounds=3, budget=60.0, table_budget=400.0,
            rss_deg=0.006, rss_rows=30_000, rss_cols=60_000, rss_level=8, rss_timeout=2 * 3600.0, rss_cap=12_000,
            cli_timeout=900.0)
QUICK = dict(rows=200, cols=300, fine=15, coarse=11, rounds=1, budget=5.0, table_budget=30.0,
             rss_deg=0.006, rss_rows=2048, rss_cols=2048, rss_level=8, rss_timeout=900.0, rss_cap=12_000,
             cli_timeout=300.0)
DEG, WEST, NORTH = 0.01, 5.0, 50.0
MODES = ("one", "default")
CASES = ("dggs center", "dggs mean", "pixel centres", "h3ronpy", "rasterio read", "exactextract mean")


def h3_res(level: int) -> int:
    """The h3 resolution whose hexagon area is nearest (in log) to the dggs level's cell area."""
    import h3

    import dggs

    a = dggs.cell_area(level) / 1e6
    return min(range(16), key=lambda r: abs(math.log(h3.average_hexagon_area(r, "km^2") / a)))


def write_raster(path: Path, west: float, north: float, deg: float, height: int, width: int) -> float:
    """A uint8 EPSG:4326 GeoTIFF (deflate, 512x512 tiles) written a tile at a time; the seconds it took."""
    import rasterio
    from rasterio.transform import from_origin
    from rasterio.windows import Window

    t0 = time.perf_counter()
    profile = dict(driver="GTiff", height=height, width=width, count=1, dtype="uint8", crs="EPSG:4326", nodata=0,
                   transform=from_origin(west, north, deg, deg), tiled=True, blockxsize=512, blockysize=512,
                   compress="deflate", BIGTIFF="IF_SAFER")
    with rasterio.open(path, "w", **profile) as ds:
        for r in range(0, height, 512):
            lat = north - (np.arange(r, min(r + 512, height)) + 0.5) * deg
            for col in range(0, width, 512):
                lng = np.radians(west + (np.arange(col, min(col + 512, width)) + 0.5) * deg)
                phi = np.radians(lat)[:, None]
                f = 120 + 60 * np.sin(7 * lng) * np.cos(5 * phi) + 30 * np.sin(3 * lng + 11 * phi)
                f = f + np.random.default_rng((r, col)).normal(0.0, 8.0, f.shape)  # a tile's noise, seeded by place
                ds.write(np.clip(f, 1, 254).astype(np.uint8), 1, window=Window(col, r, len(lng), len(lat)))
    return time.perf_counter() - t0



def read_band(path: str) -> Any:
    import rasterio

    with rasterio.open(path) as ds:
        return ds.read(1), ds.transform


def pixel_centres(path: str, level: int) -> Any:
    """Binning every pixel's centre (issue 35's yardstick: what raster2dggs and h3ronpy do): the band read,
    ``latlng_to_cell`` of each centre, a pandas groupby mean."""
    import pandas as pd

    import dggs

    band, t = read_band(path)
    rows, cols = band.shape
    lat = t.f + t.e * (np.arange(rows) + 0.5)
    lng = t.c + t.a * (np.arange(cols) + 0.5)
    cells = dggs.latlng_to_cell(np.repeat(lat, cols), np.tile(lng, rows), level, as_int=True)
    return pd.Series(band.ravel(), dtype=np.float64).groupby(np.asarray(cells)).mean()


PROJ_CRS, PROJ_PIXEL, PROJ_WEST, PROJ_NORTH = "EPSG:32632", 1000.0, 300_000.0, 5_600_000.0
PROJ_CASES = ("dggs center", "dggs mean", "dggs mean, pixel by pixel", "pixel centres")


def write_projected(path: Path, height: int, width: int) -> None:
    """A uint8 UTM 32N GeoTIFF of 1 km pixels (deflate, 512x512 tiles): a smooth field plus noise in its pixels."""
    import rasterio
    from rasterio.transform import from_origin

    profile = dict(driver="GTiff", height=height, width=width, count=1, dtype="uint8", crs=PROJ_CRS, nodata=0,
                   transform=from_origin(PROJ_WEST, PROJ_NORTH, PROJ_PIXEL, PROJ_PIXEL), tiled=True,
                   blockxsize=512, blockysize=512, compress="deflate")
    r, col = np.mgrid[0:height, 0:width]
    f = 120 + 60 * np.sin(col / 41.0) * np.cos(r / 53.0) + np.random.default_rng(35).normal(0.0, 8.0, (height, width))
    with rasterio.open(path, "w", **profile) as ds:
        ds.write(np.clip(f, 1, 254).astype(np.uint8), 1)


def projected_centres(path: str, level: int) -> Any:
    """Binning every pixel's centre of a projected raster: pyproj to lat/lng, ``latlng_to_cell``, a groupby mean."""
    import pandas as pd
    import pyproj

    import dggs

    band, t = read_band(path)
    rows, cols = band.shape
    to = pyproj.Transformer.from_crs(PROJ_CRS, "EPSG:4326", always_xy=True)
    lng, lat = to.transform(np.tile(t.c + t.a * (np.arange(cols) + 0.5), rows),
                            np.repeat(t.f + t.e * (np.arange(rows) + 0.5), cols))
    cells = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    return pd.Series(band.ravel(), dtype=np.float64).groupby(np.asarray(cells)).mean()


def worker_projected(path: str, sizes: dict[str, Any]) -> dict[str, Any]:
    import dggs.raster.pieces as pieces
    from dggs.raster import raster_to_cells

    def pixel_by_pixel(lv: int) -> Any:  # the path before issue 35's plane cut: every block cut pixel by pixel
        keep = pieces.plane_block_pieces
        pieces.plane_block_pieces = lambda *a: None
        try:
            return raster_to_cells(path, lv, mode="mean")
        finally:
            pieces.plane_block_pieces = keep

    c.TABLE_BUDGET[0] = sizes["table_budget"]
    load0, out = loadavg(), {}
    for scale in ("fine", "coarse"):
        lv = sizes[scale]
        for mode in ("center", "mean"):  # first calls on a small window
            raster_to_cells(path, lv, mode=mode, window=(0, 0, 64, 64))
        cases = {"dggs center": (lambda lv=lv: raster_to_cells(path, lv, mode="center"), len),
                 "dggs mean": (lambda lv=lv: raster_to_cells(path, lv, mode="mean"), len),
                 "dggs mean, pixel by pixel": (lambda lv=lv: pixel_by_pixel(lv), len),
                 "pixel centres": (lambda lv=lv: projected_centres(path, lv), len)}
        out[scale] = {"level": lv, "times": c.interleaved(cases, sizes["rounds"], sizes["budget"])}
    return {"projected": out, "load": [load0, loadavg()], "notes": NOTES}


def render_projected(res: dict[str, Any], sizes: dict[str, Any]) -> list[str]:
    import dggs

    px = sizes["rows"] * sizes["cols"]
    (l0, *_), (l1, *_) = res["load"]
    w = [f"#### A projected raster (issue 35): {sizes['rows']:,} x {sizes['cols']:,} pixels of 1 km in UTM 32N "
         f"({PROJ_CRS}), one thread\n",
         f"1-thread CPU per pixel, medians of {sizes['rounds']} interleaved rounds; 1-minute load average {l0:.2f} to "
         f"{l1:.2f}. The yardstick is the slower of `\"center\"` and binning every pixel's centre.\n",
         "| level | pixels a cell | `\"center\"` | pixel centres | exact `\"mean\"` | `\"mean\"` pixel by pixel "
         "(before) | mean / yardstick (<= 3) | speed-up |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for scale in ("fine", "coarse"):
        t = res["projected"].get(scale)
        if not t:
            continue
        ns = {k: per(t["times"].get(k), "cpu", px) for k in PROJ_CASES}
        yard = max(ns["dggs center"] or 0.0, ns["pixel centres"] or 0.0)
        ratio = ns["dggs mean"] / yard if ns["dggs mean"] and yard else None
        before = ns["dggs mean, pixel by pixel"]
        gain = before / ns["dggs mean"] if ns["dggs mean"] and before else None
        verdict = "-" if ratio is None else ("met" if ratio <= 3 else "**missed**")
        w.append(f"| {t['level']} | {dggs.cell_area(t['level']) / PROJ_PIXEL**2:.3g} | {fmt_ns(ns['dggs center'])} | "
                 f"{fmt_ns(ns['pixel centres'])} | {fmt_ns(ns['dggs mean'])} | "
                 f"{fmt_ns(ns['dggs mean, pixel by pixel'])} | {c.fmt_ratio(ratio)}: {verdict} | {c.fmt_ratio(gain)} |")
    return w + [""]


def worker_tables(path: str, sizes: dict[str, Any]) -> dict[str, Any]:
    import geopandas as gpd
    import h3ronpy.raster as hr
    from exactextract import exact_extract

    import dggs
    from dggs.raster import raster_to_cells

    c.TABLE_BUDGET[0] = sizes["table_budget"]
    load0, rows, cols, out = loadavg(), sizes["rows"], sizes["cols"], {}
    for scale in ("fine", "coarse"):
        lv, res = sizes[scale], h3_res(sizes[scale])
        cells = raster_to_cells(path, lv, mode="mean")["cell_id"].to_numpy().astype(np.uint64)
        gdf = gpd.GeoDataFrame({"cell_id": cells}, geometry=dggs.cell_to_polygon(cells, max_points=10**9),
                               crs="EPSG:4326")
        for mode in ("center", "mean"):  # first calls (numba) on a small window, before interleaved's warm-up
            raster_to_cells(path, lv, mode=mode, window=(0, 0, 64, 64))
        hr.raster_to_dataframe(np.ones((64, 64), np.uint8), read_band(path)[1], res, nodata_value=0, compact=False)

        def mean_sample(frac: float, lv: int = lv) -> Any:  # the top rows of the raster
            m = max(1, int(rows * frac))
            return (lambda: raster_to_cells(path, lv, mode="mean", window=(0, 0, m, cols))), rows / m

        def extract_sample(frac: float, frame: Any = gdf) -> Any:  # the first polygons
            part = frame.iloc[:max(1, int(len(frame) * frac))]
            return (lambda: exact_extract(path, part, ["mean"], output="pandas")), len(frame) / len(part)

        extract_sample(1e-4)[0]()  # first call
        cases = {"dggs center": (lambda lv=lv: raster_to_cells(path, lv, mode="center"), len),
                 "dggs mean": (lambda lv=lv: raster_to_cells(path, lv, mode="mean"), len, mean_sample),
                 "pixel centres": (lambda lv=lv: pixel_centres(path, lv), len),
                 "h3ronpy": (lambda r=res: hr.raster_to_dataframe(*read_band(path), r, nodata_value=0,
                                                                  compact=False), len),
                 "rasterio read": (lambda: read_band(path), lambda o: 0),
                 "exactextract mean": (extract_sample(1.0)[0], len, extract_sample)}
        out[scale] = {"level": lv, "res": res, "times": c.interleaved(cases, sizes["rounds"], sizes["budget"])}
    return {"tables": out, "load": [load0, loadavg()], "notes": NOTES}


def worker_rss(path: str, level: int) -> dict[str, Any]:
    import rasterio

    from dggs.raster import raster_to_cells

    with rasterio.open(path) as ds:
        h, w = ds.shape
    raster_to_cells(path, level, mode="mean", window=(h // 3, w // 2, 256, 256))  # warm-up: numba, pools
    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    wall, cpu, table = c.run_once(lambda: raster_to_cells(path, level, mode="mean"))
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    return {"base": base, "peak": peak, "wall": wall, "cpu": cpu, "cells": len(table), "pixels": h * w}



def run_cli(argv: list[str], env: dict[str, str], out: Path, timeout: float) -> dict[str, Any]:
    """Wall and CPU seconds of one whole process (its children's rusage) and the rows it wrote."""
    shutil.rmtree(out, ignore_errors=True)
    r0, w0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    proc = subprocess.run([*argv, str(out)], env=env, capture_output=True, text=True, timeout=timeout)
    wall, r1 = time.perf_counter() - w0, resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"exit {proc.returncode}: {proc.stderr.strip()[-300:]}")
    rows = sum(pq.ParquetFile(f).metadata.num_rows for f in out.rglob("*.parquet"))
    return {"wall": wall, "cpu": r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime, "units": rows}


def cli_table(path: Path, sizes: dict[str, Any], tmp: Path) -> dict[str, Any]:
    if not (BIN / "raster2dggs").exists():
        note(f"raster2dggs is not installed in {BIN.parent} (benchmarks/requirements.txt); its rows are skipped.")
    load0 = loadavg()
    out = {scale: cli_scale(path, scale, sizes, tmp) for scale in ("fine", "coarse")}
    return out | {"load": [load0, loadavg()]}


def cli_scale(path: Path, scale: str, sizes: dict[str, Any], tmp: Path) -> dict[str, Any]:
    level, res, r2d = sizes[scale], h3_res(sizes[scale]), BIN / "raster2dggs"
    dg = [str(BIN / "dggs"), "bin-raster", str(path), "--level", str(level), "--no-progress", "--mode"]
    rd, p = [str(r2d), "h3", "-v", "ERROR", "-r", str(res)], str(path)
    cases = {"dggs bin-raster --mode center": [*dg, "center", "--parquet"]}
    for g in ("polygon", "none") if r2d.exists() else ():
        cases[f"raster2dggs --sample nn -g {g}"] = [*rd, "--sample", "nn", "-g", g, p]
    if scale == "coarse":  # the weighted means: raster2dggs takes many minutes at the fine level
        cases["dggs bin-raster --mode mean"] = [*dg, "mean", "--parquet"]
        if r2d.exists():
            cases["raster2dggs --overlay weighted -g polygon"] = [*rd, "--overlay", "weighted", "-g", "polygon", p]
    got: dict[str, dict[str, list[dict[str, Any]]]] = {"one": {}, "default": {}}

    def timed(name: str, mode: str) -> dict[str, Any] | None:
        try:
            return run_cli(cases[name], thread_env(mode == "one"), tmp / "out", sizes["cli_timeout"])
        except Exception as exc:
            note(f"`{name}` ({scale}) failed: {type(exc).__name__}: {str(exc)[:300]}; skipped.")
            del cases[name]
            got["one"].pop(name, None), got["default"].pop(name, None)
            return None

    for name in list(cases):  # warm-up on one thread; a case over the budget is timed once a mode instead
        t = timed(name, "one")
        if t and t["wall"] > sizes["budget"]:
            note(f"`{name}` ({scale}): one run took {t['wall']:.0f} s: timed once a mode (marked *).")
            t2 = timed(name, "default")
            if t2:
                got["one"][name], got["default"][name] = [t | {"flag": "once"}], [t2 | {"flag": "once"}]
                del cases[name]
    for r in range(sizes["rounds"]):
        for mode in ("one", "default") if r % 2 == 0 else ("default", "one"):
            for name in list(cases):
                t = timed(name, mode)
                if t:
                    got[mode].setdefault(name, []).append(t)
    return {mode: {name: {k: statistics.median(x[k] for x in ts) if k != "flag" else ts[0][k] for k in ts[0]}
                   for name, ts in d.items()} for mode, d in got.items()}


def measure_rss(sizes: dict[str, Any], tmp: Path) -> dict[str, Any]:
    deg, h, w, path = sizes["rss_deg"], sizes["rss_rows"], sizes["rss_cols"], tmp / "rss.tif"
    made = write_raster(path, -w * deg / 2, h * deg / 2, deg, h, w)  # centred on 0N 0E: the globe when full size
    out: dict[str, Any] = {"deg": deg, "shape": [h, w], "write": made, "bytes": path.stat().st_size,
                           "level": sizes["rss_level"], "load": [loadavg()]}
    argv = [sys.executable, str(HERE), "--rss-worker", str(path), "--level", str(sizes["rss_level"])]
    with open(tmp / "rss.err", "w+") as err:
        proc = subprocess.Popen(argv, env=thread_env(False), stdout=subprocess.PIPE, stderr=err, text=True)
        t0, hwm = time.perf_counter(), 0
        while proc.poll() is None:
            time.sleep(2)
            vm, secs = vm_bytes(proc.pid), time.perf_counter() - t0
            hwm = max(hwm, vm.get("VmHWM", 0))
            if vm.get("VmRSS", 0) > sizes["rss_cap"] * 1e6 or secs > sizes["rss_timeout"]:
                proc.kill()
                proc.wait()
                why = (f"RSS {vm['VmRSS'] / 1e6:,.0f} MB passed the cap of {sizes['rss_cap']:,} MB"
                       if secs <= sizes["rss_timeout"] else "out of time")
                return out | {"killed": f"killed after {secs:.0f} s ({why})", "peak": hwm,
                              "load": out["load"] + [loadavg()]}
        out["load"].append(loadavg())
        if proc.returncode != 0:
            err.seek(0)
            return out | {"error": f"exit {proc.returncode}: " + err.read().strip()[-300:]}
    return out | json.loads(proc.stdout.read().strip().splitlines()[-1])


def vm_bytes(pid: int) -> dict[str, int]:
    """VmRSS and VmHWM of a running process, bytes (nothing once it is gone)."""
    try:
        lines = Path(f"/proc/{pid}/status").read_text().splitlines()
    except OSError:
        return {}
    return {k: int(v.split()[0]) * 1024 for k, v in (ln.split(":", 1) for ln in lines) if k in ("VmRSS", "VmHWM")}



def per(t: dict[str, Any] | None, key: str, pixels: int, unit: str = "pixel") -> float | None:
    """Seconds per pixel or per output cell; a sampled run counts the share of the pixels it read."""
    if not t:
        return None
    return t[key] / (pixels / t.get("scale", 1.0)) if unit == "pixel" else t[key] / t["units"] if t["units"] else None


def cost(res: dict[str, Any], part: str, mode: str, scale: str, case: str, px: int) -> float | None:
    """Seconds per pixel of a case: 1-thread CPU or default-threads wall."""
    t = (res.get(part) or {}).get(scale, {}).get(mode, {}).get(case)
    return per(t, "cpu" if mode == "one" else "wall", px)


def render(res: dict[str, Any], sizes: dict[str, Any]) -> str:
    import dggs

    px, rows, cols = sizes["rows"] * sizes["cols"], sizes["rows"], sizes["cols"]
    v = ", ".join(f"{d} {c.version(d)}" for d in ("dggs", "h3ronpy", "raster2dggs", "exactextract", "rasterio"))
    w = ["### Raster to cells: dggs.raster against h3ronpy, raster2dggs and exactextract (bench_raster.py)\n",
         f"- **Code:** {c.describe_code(res['code'])}; {v}.",
         f"- **Raster:** {rows:,} x {cols:,} = {px:,} pixels of {DEG} deg (~0.87 km2), uint8 EPSG:4326, "
         f"{NORTH - rows * DEG:g}-{NORTH:g}N {WEST:g}-{WEST + cols * DEG:g}E, a smooth field plus noise, deflate, "
         "tiled 512x512, no nodata pixels.",
         f"- **Load average (1, 5, 15 min):** {res['load_start']} at the start, {res['load_end']} at the end; the "
         f"whole script took {res['seconds'] / 60:.1f} min.",
         "- **Times:** CPU (`time.process_time`) in a process on one thread (DGGS_THREADS, NUMBA_NUM_THREADS, "
         "RAYON_NUM_THREADS, OMP_NUM_THREADS = 1), wall in one on the default threads; medians of "
         f"{sizes['rounds']} interleaved rounds after warm-ups. * = timed once (a call over the {sizes['budget']:g} "
         "s budget), on a sample where a note says so.\n"]
    star = lambda *ts: "*" if any(t and t.get("flag") for t in ts) else ""  # noqa: E731
    for scale, what in (("fine", "Cells about the size of the pixels"), ("coarse", "Cells ~100x the pixels")):
        t = res["tables"].get(scale, {})
        if t:
            import h3

            lv, r = t["level"], t["res"]
            w.append(f"#### {what}: dggs level {lv} ({dggs.cell_area(lv) / 1e6:.3g} km2), h3 res {r} "
                     f"({h3.average_hexagon_area(r, 'km^2'):.3g} km2)\n\n| case | output cells | 1 thread: CPU per "
                     "pixel | CPU per cell | default: wall per pixel | wall per cell |\n|---|---:|---:|---:|---:|---:|")
        for case in CASES if t else ():
            a, b = t.get("one", {}).get(case), t.get("default", {}).get(case)
            units = (a or b or {}).get("units", 0)
            w.append(f"| {case}{star(a, b)} | {f'{units:,}' if units else '-'} | {fmt_ns(per(a, 'cpu', px))} | "
                     f"{fmt_ns(per(a, 'cpu', px, 'cell'))} | {fmt_ns(per(b, 'wall', px))} | "
                     f"{fmt_ns(per(b, 'wall', px, 'cell'))} |")
        w.append("")
    loads = "; ".join(f"{m} thread(s) {a[0]:.2f} to {b[0]:.2f}" for m, (a, b) in res["tables"].get("load", {}).items())
    w.append(f"1-minute load average over the table workers: {loads or '-'}.\n")
    if res.get("cli"):
        w.append("#### Whole processes writing Parquet (the command lines)\n\n| process | level / res | output rows "
                 "| 1 thread: CPU | per pixel | default: wall | per pixel |\n|---|---|---:|---:|---:|---:|---:|")
        for scale in ("fine", "coarse"):
            modes = res["cli"][scale]
            for name, a in modes["one"].items():
                b = modes["default"].get(name) or {"wall": math.nan}
                w.append(f"| {name}{star(a, b)} | {sizes[scale]} / {h3_res(sizes[scale])} | {a['units']:,} | "
                         f"{a['cpu']:.2f} s | {fmt_ns(a['cpu'] / px)} | {b['wall']:.2f} s | {fmt_ns(b['wall'] / px)} |")
        (l0, *_), (l1, *_) = res["cli"]["load"]
        w.append(f"\n1-minute load average {l0:.2f} to {l1:.2f}. dggs bin-raster always writes polygon geometry (WKB) "
                 "and a bbox; raster2dggs's `-p` is its default (cores - 1).\n")
    rss = res.get("rss")
    if rss:
        h, wd, deg = *rss["shape"], rss["deg"]
        where = "the globe" if h * deg >= 180 else f"{h * deg:g} x {wd * deg:g} deg round 0N 0E"
        w.append(f"#### Memory: {where}, {wd:,} x {h:,} pixels of {deg:g} deg ({h * wd / 1e6:,.0f} MB decoded, "
                 f"{rss['bytes'] / 1e6:,.0f} MB on disk), `mode=\"mean\"` at level {rss['level']}\n")
        if "killed" in rss:
            w.append(f"The worker was {rss['killed']}; peak RSS so far (VmHWM) **{rss['peak'] / 1e6:,.0f} MB**.")
        elif "error" in rss:
            w.append(f"The worker failed: `{rss['error']}`.")
        else:
            w.append(f"Peak RSS (`ru_maxrss`, whole process) **{rss['peak'] / 1e6:,.0f} MB** (after the imports and "
                     f"a 256x256 warm-up: {rss['base'] / 1e6:,.0f} MB); {rss['cells']:,} cells in {rss['wall']:.0f} s "
                     f"wall, {rss['cpu']:.0f} s CPU on the default threads ({fmt_ns(rss['cpu'] / rss['pixels'])} CPU "
                     "a pixel).")
        w.append(f"Writing the raster took {rss['write']:.0f} s; 1-minute load average {rss['load'][0][0]:.2f} to "
                 f"{rss['load'][-1][0]:.2f}.\n")
    if res.get("projected"):
        w.extend(render_projected(res["projected"], sizes))
    w.append("#### Targets (issue 19)\n\nRatios per pixel from the tables above: 1-thread CPU (judged) and "
             "default-threads wall.\n\n| target | scale | ratio (1-thread CPU) | ratio (default wall) | met |")
    w.append("|---|---|---:|---:|---|")
    targets = (('h3ronpy / dggs `"center"` (>= 1)', "tables", "h3ronpy", "dggs center", 1),
               ("raster2dggs `--sample nn -g polygon` / `dggs bin-raster --mode center` (>= 1)", "cli",
                "raster2dggs --sample nn -g polygon", "dggs bin-raster --mode center", 1),
               ('dggs `"mean"` / `"center"` (<= 3)', "tables", "dggs mean", "dggs center", -3),
               ('exactextract mean / dggs `"mean"` (>= 1)', "tables", "exactextract mean", "dggs mean", 1),
               ('dggs `"mean"` / the slower of `"center"` and pixel centres (<= 3, issue 35)', "tables", "dggs mean",
                ("dggs center", "pixel centres"), -3))
    for scale in ("fine", "coarse"):
        for name, part, num, den, bar in targets:
            dens = den if isinstance(den, tuple) else (den,)
            pair = [(cost(res, part, m, scale, num, px),
                     max((cost(res, part, m, scale, d, px) or 0.0 for d in dens), default=0.0)) for m in MODES]
            r = [a / b if a and b else None for a, b in pair]
            met = "-" if r[0] is None else ("met" if (r[0] >= bar if bar > 0 else r[0] <= -bar) else "**missed**")
            w.append(f"| {name} | {scale} | {c.fmt_ratio(r[0])} | {c.fmt_ratio(r[1])} | {met} |")
    if rss and "peak" in rss:
        ok = "killed" not in rss and rss["peak"] <= 600e6  # issue 19's target
        w.append(f"| peak RSS <= 600 MB | level {rss['level']}, {h:,} x {wd:,} px | {rss['peak'] / 1e6:,.0f} MB | | "
                 f"{'met' if ok else '**missed**'} |")
    if NOTES:
        w.append("\n" + c.notes_section())
    return "\n".join(w) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes, 1 round (a smoke test)")
    ap.add_argument("--skip", default="", help="comma-separated parts to skip: tables,projected,cli,rss")
    for key, val in FULL.items():
        ap.add_argument("--" + key.replace("_", "-"), type=type(val), default=None,
                        help=f"default {val} ({QUICK[key]} with --quick)")
    for flag in ("--tables-worker", "--rss-worker", "--projected-worker", "--sizes", "--level"):  # internal
        ap.add_argument(flag, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.projected_worker:
        print(json.dumps(worker_projected(args.projected_worker, json.loads(args.sizes))))
        return
    if args.tables_worker or args.rss_worker:
        w = worker_tables(args.tables_worker, json.loads(args.sizes)) if args.tables_worker else None
        print(json.dumps(w or worker_rss(args.rss_worker, int(args.level))))
        return

    sizes = dict(QUICK if args.quick else FULL)
    sizes.update({k: getattr(args, k) for k in FULL if getattr(args, k) is not None})
    skip, t0 = set(filter(None, args.skip.split(","))), time.perf_counter()
    res: dict[str, Any] = {"code": c.code_state(), "load_start": loadavg(), "tables": {}}
    with tempfile.TemporaryDirectory(prefix="dggs-bench-raster-") as tmp:
        path = Path(tmp) / "europe.tif"
        write_raster(path, WEST, NORTH, DEG, sizes["rows"], sizes["cols"])
        if "tables" not in skip:
            for mode in ("one", "default"):
                print(f"bench_raster: tables, {mode} thread(s)", file=sys.stderr, flush=True)
                try:
                    got = c.run_json([str(HERE), "--tables-worker", str(path), "--sizes", json.dumps(sizes)],
                                   thread_env(mode == "one"), 4 * 3600)
                except Exception as exc:
                    note(f"the {mode}-thread tables worker failed ({type(exc).__name__}: {str(exc)[:300]}).")
                    continue
                NOTES.extend(f"({'1 thread' if mode == 'one' else 'default threads'}) {n}" for n in got["notes"])
                res["tables"].setdefault("load", {})[mode] = got["load"]
                for scale, t in got["tables"].items():
                    res["tables"].setdefault(scale, {"level": t["level"], "res": t["res"]})[mode] = t["times"]
        if "projected" not in skip:
            print("bench_raster: a projected raster, one thread", file=sys.stderr, flush=True)
            projected = Path(tmp) / "utm.tif"
            write_projected(projected, sizes["rows"], sizes["cols"])
            try:
                got = c.run_json([str(HERE), "--projected-worker", str(projected), "--sizes", json.dumps(sizes)],
                               thread_env(True), 4 * 3600)
                NOTES.extend(f"(projected) {n}" for n in got["notes"])
                res["projected"] = got
            except Exception as exc:
                note(f"the projected worker failed ({type(exc).__name__}: {str(exc)[:300]}).")
        if "cli" not in skip:
            print("bench_raster: command lines", file=sys.stderr, flush=True)
            res["cli"] = cli_table(path, sizes, Path(tmp))
        if "rss" not in skip:
            print(f"bench_raster: memory ({sizes['rss_rows']} x {sizes['rss_cols']})", file=sys.stderr, flush=True)
            res["rss"] = measure_rss(sizes, Path(tmp))
    res["load_end"], res["seconds"] = loadavg(), time.perf_counter() - t0
    print(render(res, sizes))
    print(f"bench_raster: {res['seconds']:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
