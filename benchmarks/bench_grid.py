"""Benchmark the dggs grid against h3-py, h3ronpy and A5 (pya5).

Point to cell on 1,000,000 random points uniform on the sphere (one fixed
seed, the same points for every library), then cell operations (boundary,
parent, children, disk k=1) on 100,000 cells of those points.  Every number is
the median of 3 runs.  Prints markdown tables on stdout; ``--json PATH`` also
writes the raw numbers (``run_all.py`` reads them to check the targets).

A peer that is not installed is skipped with a note, never an error.

Run::

    make bench                                              # everything, writes BENCHMARKS.md
    .venv-bench/bin/python benchmarks/bench_grid.py         # this file only
    .venv-bench/bin/python benchmarks/bench_grid.py --points 100000 --cells 10000   # quick look
"""

from __future__ import annotations

import argparse
import importlib
import importlib.metadata
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from typing import Any, Callable

import numpy as np

SEED = 20_240_601
REPEAT = 3
# Our levels and the peers' resolutions closest in mean cell area.
OUR_LEVELS = (10, 17)
H3_RES = {10: 5, 17: 9}  # h3 res 5 ~253 km^2, res 9 ~0.105 km^2
SCALING_LEVELS = (5, 10, 17, 25, 40)
DISK_LOOP_CELLS = 2_000  # dggs.grid_disk is per cell and slow; timed on a subset
A5_CELL_OPS_RES_FALLBACK = 14

NOTES: list[str] = []


# --------------------------------------------------------------------------- helpers


def points(n: int, seed: int = SEED) -> tuple[np.ndarray, np.ndarray]:
    """``n`` points uniform on the sphere: (lat, lng) in degrees."""
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1.0, 1.0, n)))
    lng = rng.uniform(-180.0, 180.0, n)
    return lat, lng


def timed(fn: Callable[[], Any], repeat: int = REPEAT) -> tuple[float, Any]:
    """Median wall time of ``fn()`` over ``repeat`` runs, and the last result."""
    times = []
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def fmt_rate(r: float | None) -> str:
    if r is None:
        return "-"
    for scale, unit in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if r >= scale:
            v = r / scale
            return f"{v:.3g} {unit}" if v < 100 else f"{v:.0f} {unit}"
    return f"{r:.0f}"


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "-"
    if r < 0.1:
        return f"{r:.2g}x"
    return f"{r:.2f}x" if r < 10 else f"{r:.0f}x"


def try_import(name: str, pip_name: str):
    try:
        return importlib.import_module(name)
    except Exception as exc:  # ImportError, or a broken wheel
        NOTES.append(f"{pip_name} is not available ({type(exc).__name__}: {exc}); its rows are skipped.")
        print(f"note: skipping {pip_name}: {exc}", file=sys.stderr)
        return None


def version(dist: str) -> str:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return "not installed"


def machine_info() -> dict[str, Any]:
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    import dggs
    from dggs import _parallel

    return {
        "nproc": usable,
        "cpu": cpu,
        "platform": platform.platform(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "dggs": dggs.__version__,
        "dggs_threads": _parallel.default_threads(),
        "DGGS_THREADS": os.environ.get("DGGS_THREADS", "(unset)"),
        "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS", "(unset)"),
        "h3": version("h3"),
        "h3ronpy": version("h3ronpy"),
        "pya5": version("pya5"),
        "pyarrow": version("pyarrow"),
        "loadavg_start": os.getloadavg(),
    }


# --------------------------------------------------------------------------- point to cell


def a5_res_for(area_km2: float, a5) -> int:
    """The A5 resolution whose mean cell area is closest to ``area_km2`` (in log)."""
    best, best_d = 0, float("inf")
    for res in range(0, 30):
        try:
            area = a5.cell_area(res) / 1e6
        except Exception:
            break
        d = abs(np.log(area / area_km2))
        if d < best_d:
            best, best_d = res, d
    return best


def interleaved(cases: dict[Any, Callable[[], Any]], repeat: int = REPEAT,
                extra: Callable[[], dict[Any, float]] | None = None) -> dict[Any, float]:
    """Median seconds per case, the cases run in turn in each of ``repeat`` rounds.

    Round-robin rather than case after case, so that a burst of load from other
    processes hits every row of a table alike.  ``extra`` (optional) is called
    once per round and returns more {case: seconds} (the DGGS_THREADS=1 worker).
    """
    times: dict[Any, list[float]] = {k: [] for k in cases}
    for _ in range(repeat):
        for key, fn in cases.items():
            t0 = time.perf_counter()
            fn()
            times[key].append(time.perf_counter() - t0)
        if extra is not None:
            for key, secs in extra().items():
                times.setdefault(key, []).append(secs)
    return {k: statistics.median(v) for k, v in times.items()}


def dggs_latlng(lat: np.ndarray, lng: np.ndarray, levels, repeat: int = REPEAT) -> dict[int, float]:
    """Median seconds of ``dggs.latlng_to_cell`` per level (the DGGS_THREADS=1 worker)."""
    import dggs

    dggs.latlng_to_cell(lat[:1000], lng[:1000], 10)  # warm-up: imports, thread pool
    return interleaved({lv: (lambda lv=lv: dggs.latlng_to_cell(lat, lng, lv)) for lv in levels}, repeat)


#: Environments of the threading table, each timed in a fresh interpreter.  numpy's
#: OpenBLAS starts its own threads inside matmul (the (N, 3) @ (3, 20) face test), on
#: top of dggs's thread pool: OPENBLAS_NUM_THREADS=1 shows what that costs.
THREAD_VARIANTS = {
    "DGGS_THREADS=1": {"DGGS_THREADS": "1"},
    "OPENBLAS_NUM_THREADS=1 (dggs threads default)": {"OPENBLAS_NUM_THREADS": "1"},
    "DGGS_THREADS=1 OPENBLAS_NUM_THREADS=1": {"DGGS_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"},
}


def thread_worker_round(n: int) -> dict[Any, float]:
    """One timed run per level per THREAD_VARIANTS environment, each in a fresh interpreter."""
    out: dict[Any, float] = {}
    for name, extra_env in THREAD_VARIANTS.items():
        env = {k: v for k, v in os.environ.items() if k not in ("DGGS_THREADS", "OPENBLAS_NUM_THREADS")}
        env.update(extra_env)
        cmd = [sys.executable, os.path.abspath(__file__), "--thread-worker", "--points", str(n)]
        proc = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True, timeout=600)
        one = json.loads(proc.stdout.strip().splitlines()[-1])
        out.update({(name, int(k)): v for k, v in one.items()})
    return out


def bench_point_to_cell(n: int, res: dict[str, Any], mods: dict[str, Any]) -> None:
    import dggs

    lat, lng = points(n)
    lat_l, lng_l = lat.tolist(), lng.tolist()  # what a Python-loop user has
    small = min(100_000, n)
    lat_s, lng_s = lat[:small], lng[:small]
    area = {lv: float(dggs.cell_area("A" + "0" * lv, "km^2")) for lv in OUR_LEVELS}
    meta: dict[Any, dict[str, Any]] = {}
    cases: dict[Any, Callable[[], Any]] = {}

    dggs.latlng_to_cell(lat[:1000], lng[:1000], 10)  # warm-up: imports, thread pool
    for lv in SCALING_LEVELS:  # 10 and 17 for the main table; all for the level sweep
        cases[("dggs", lv)] = lambda lv=lv: dggs.latlng_to_cell(lat, lng, lv)
    loop_n = min(100_000, n)  # one point at a time: timed on a subset, rate per point
    lat_loop, lng_loop = lat_l[:loop_n], lng_l[:loop_n]
    for lv in OUR_LEVELS:  # cost per point at 100k points
        cases[("dggs-small", lv)] = lambda lv=lv: dggs.latlng_to_cell(lat_s, lng_s, lv)
        meta[("dggs", lv)] = dict(impl="dggs (numpy, threaded)", how="vectorized", res=f"level {lv}", area=area[lv])
        cases[("dggs-loop", lv)] = lambda lv=lv: [dggs.latlng_to_cell(a_, b_, lv) for a_, b_ in zip(lat_loop, lng_loop)]
        meta[("dggs-loop", lv)] = dict(impl="dggs one point per call", how=f"Python loop ({loop_n:,} points)",
                                       res=f"level {lv}", area=area[lv], n=loop_n)

    h3 = mods.get("h3")
    if h3 is not None:
        from h3.api import basic_int as h3i

        for lv in OUR_LEVELS:
            r = H3_RES[lv]
            a = h3.average_hexagon_area(r, "km^2")
            cases[("h3s", lv)] = lambda r=r: [h3.latlng_to_cell(a_, b_, r) for a_, b_ in zip(lat_l, lng_l)]
            meta[("h3s", lv)] = dict(impl="h3-py string API", how="Python loop", res=f"res {r}", area=a)
            cases[("h3i", lv)] = lambda r=r: [h3i.latlng_to_cell(a_, b_, r) for a_, b_ in zip(lat_l, lng_l)]
            meta[("h3i", lv)] = dict(impl="h3-py integer API", how="Python loop", res=f"res {r}", area=a)
    h3ronpy_vec = mods.get("h3ronpy.vector")
    if h3ronpy_vec is not None:
        for lv in OUR_LEVELS:
            r = H3_RES[lv]
            a = h3.average_hexagon_area(r, "km^2") if h3 is not None else float("nan")
            h3ronpy_vec.coordinates_to_cells(lat[:1000], lng[:1000], r)
            cases[("h3ronpy", lv)] = lambda r=r: h3ronpy_vec.coordinates_to_cells(lat, lng, r)
            meta[("h3ronpy", lv)] = dict(impl="h3ronpy `vector.coordinates_to_cells`", how="vectorized (Rust)",
                                         res=f"res {r}", area=a)
    a5 = mods.get("a5")
    if a5 is not None:
        lnglat = list(zip(lng_l, lat_l))
        res["a5_res"] = {}
        for lv in OUR_LEVELS:
            r = a5_res_for(area[lv], a5)
            res["a5_res"][str(lv)] = r
            cases[("a5", lv)] = lambda r=r: [a5.lonlat_to_cell(p, r) for p in lnglat]
            meta[("a5", lv)] = dict(impl="A5 (pya5) `lonlat_to_cell`", how="Python loop", res=f"res {r}",
                                    area=a5.cell_area(r) / 1e6)

    def threads_round() -> dict[Any, float]:
        try:
            return thread_worker_round(n)
        except Exception as exc:
            msg = f"DGGS_THREADS=1 run failed: {exc}"
            if msg not in NOTES:
                NOTES.append(msg)
            return {}

    secs = interleaved(cases, extra=threads_round)
    res["point_to_cell"] = [dict(meta[k], level=k[1], seconds=secs[k], rate=meta[k].get("n", n) / secs[k]) for k in meta]
    res["level_sweep"] = {str(lv): {"seconds": secs[("dggs", lv)], "ns_per_point": secs[("dggs", lv)] / n * 1e9,
                                    "rate": n / secs[("dggs", lv)]} for lv in SCALING_LEVELS}
    res["scaling_points"] = {
        str(lv): {"n_small": small, "ns_small": secs[("dggs-small", lv)] / small * 1e9, "n_large": n,
                  "ns_large": secs[("dggs", lv)] / n * 1e9}
        for lv in OUR_LEVELS
    }
    res["threads"] = {"default": {str(lv): secs[("dggs", lv)] for lv in OUR_LEVELS}}
    for name in THREAD_VARIANTS:
        if all((name, lv) in secs for lv in OUR_LEVELS):
            res["threads"][name] = {str(lv): secs[(name, lv)] for lv in OUR_LEVELS}


# --------------------------------------------------------------------------- cell operations


def bench_cell_ops(n_cells: int, res: dict[str, Any], mods: dict[str, Any]) -> None:
    import dggs

    lat, lng = points(n_cells)  # the first n_cells of the same points
    cases: dict[tuple[str, str], Callable[[], Any]] = {}
    count: dict[tuple[str, str], int] = {}

    def add(impl: str, op: str, fn: Callable[[], Any], k: int = n_cells) -> None:
        cases[(impl, op)] = fn
        count[(impl, op)] = k

    cells = dggs.latlng_to_cell(lat, lng, 17)
    dggs.cell_to_boundary(cells[:100]), dggs.edge_neighbors(cells[:100])  # warm-up
    impl = OURS_OPS
    add(impl, "boundary", lambda: dggs.cell_to_boundary(cells))
    add(impl, "parent", lambda: dggs.cell_to_parent(cells))
    add(impl, "children", lambda: dggs.cell_to_children(cells))
    add(impl, "disk", lambda: dggs.grid_disk(cells, 1))  # (N, 4): each cell and its 3 neighbours
    sub = cells[: min(DISK_LOOP_CELLS, n_cells)].tolist()
    add(OURS_DISK_LOOP, "disk", lambda: [dggs.grid_disk(c, 1) for c in sub], len(sub))

    h3 = mods.get("h3")
    if h3 is not None:
        from h3.api import basic_int as h3i

        r = H3_RES[17]
        hs = [h3.latlng_to_cell(a, b, r) for a, b in zip(lat.tolist(), lng.tolist())]
        hi = [h3i.latlng_to_cell(a, b, r) for a, b in zip(lat.tolist(), lng.tolist())]
        for impl, api, cs in (("h3-py string API (loop)", h3, hs), ("h3-py integer API (loop)", h3i, hi)):
            add(impl, "boundary", lambda api=api, cs=cs: [api.cell_to_boundary(c) for c in cs])
            add(impl, "parent", lambda api=api, cs=cs: [api.cell_to_parent(c) for c in cs])
            add(impl, "children", lambda api=api, cs=cs: [api.cell_to_children(c) for c in cs])
            add(impl, "disk", lambda api=api, cs=cs: [api.grid_disk(c, 1) for c in cs])
    h3ronpy = mods.get("h3ronpy")
    h3ronpy_vec = mods.get("h3ronpy.vector")
    if h3ronpy is not None and h3ronpy_vec is not None:
        hr = H3_RES[17]  # (bound now: the lambdas run later)
        arr = np.asarray(h3ronpy_vec.coordinates_to_cells(lat, lng, hr)).astype(np.uint64)
        impl = "h3ronpy (vectorized)"
        add(impl, "boundary", lambda: h3ronpy_vec.cells_to_wkb_polygons(arr))
        add(impl, "parent", lambda: h3ronpy.change_resolution(arr, hr - 1))
        add(impl, "children", lambda: h3ronpy.change_resolution(arr, hr + 1))
        add(impl, "disk", lambda: h3ronpy.grid_disk(arr, 1))
    a5 = mods.get("a5")
    if a5 is not None:
        ar = res.get("a5_res", {}).get("17", A5_CELL_OPS_RES_FALLBACK)
        ac = [a5.lonlat_to_cell(p, ar) for p in zip(lng.tolist(), lat.tolist())]
        impl = "A5 (pya5, loop)"
        add(impl, "boundary", lambda: [a5.cell_to_boundary(c) for c in ac])
        add(impl, "parent", lambda: [a5.cell_to_parent(c) for c in ac])
        add(impl, "children", lambda: [a5.cell_to_children(c) for c in ac])
        add(impl, "disk", lambda: [a5.grid_disk(c, 1) for c in ac])
        res["a5_cell_res"] = ar
    # Sanity checks of what is timed (one call each, untimed).
    assert dggs.cell_to_children(cells[:10]).shape == (30,)
    assert dggs.edge_neighbors(cells[:10]).shape == (10, 3)
    if h3ronpy is not None and h3ronpy_vec is not None:
        assert len(h3ronpy.change_resolution(arr[:10], hr + 1)) == 70
        assert len(h3ronpy.change_resolution(arr[:10], hr - 1)) == 10
    secs = interleaved(cases)
    ops: dict[str, dict[str, float]] = {}
    for (impl, op), t in secs.items():
        ops.setdefault(impl, {})[op] = count[(impl, op)] / t
    res["cell_ops"] = ops
    res["n_cells"] = n_cells


# --------------------------------------------------------------------------- report

OURS_PT = "dggs (numpy, threaded)"
OURS_OPS = "dggs (array call)"
OURS_DISK_LOOP = "dggs `grid_disk(c, 1)` (Python loop)"
OP_NAMES = ("boundary", "parent", "children", "disk")


def report(res: dict[str, Any]) -> str:
    m = res["machine"]
    n = res["n_points"]
    out: list[str] = []
    w = out.append
    w("### Grid: point to cell and cell operations (bench_grid.py)\n")
    w(f"Machine: {m['nproc']} cores ({m['cpu']}), Python {m['python']}, numpy {m['numpy']}, "
      f"dggs {m['dggs']} ({m['dggs_threads']} threads by default), h3 {m['h3']}, h3ronpy {m['h3ronpy']}, "
      f"pya5 {m['pya5']}, pyarrow {m['pyarrow']}; load average at start "
      f"{m['loadavg_start'][0]:.2f}, at end {m['loadavg_end'][0]:.2f}. "
      f"Medians of {REPEAT} runs, the cases of a table run in turn in each round (so load from other "
      f"processes hits them alike); seed {SEED}.\n")

    # point to cell
    w(f"#### Point to cell, {n:,} random points uniform on the sphere (points/s; ratio = dggs / peer)\n")
    rows = res["point_to_cell"]
    ours = {r["level"]: r["rate"] for r in rows if r["impl"] == OURS_PT}
    w("| library | how | ~216 km² (dggs level 10) | points/s | dggs / it | ~0.1 km² (dggs level 17) | points/s | dggs / it |")
    w("|---|---|---|---:|---:|---|---:|---:|")
    impls = list(dict.fromkeys(r["impl"] for r in rows))
    for impl in impls:
        cells = []
        how = ""
        for lv in OUR_LEVELS:
            r = next((x for x in rows if x["impl"] == impl and x["level"] == lv), None)
            if r is None:
                cells += ["-", "-", "-"]
                continue
            how = r["how"]
            ratio = "1 (ours)" if impl == OURS_PT else fmt_ratio(ours[lv] / r["rate"])
            cells += [f"{r['res']} ({r['area']:.3g} km²)", fmt_rate(r["rate"]), ratio]
        w(f"| {impl} | {how} | " + " | ".join(cells) + " |")
    if "a5_res" in res:
        w("\nA5 resolutions are the ones closest in mean area to ours (log scale): "
          + ", ".join(f"res {r} for level {lv}" for lv, r in res["a5_res"].items())
          + ". h3's are res 5 (253 km²) and res 9 (0.105 km²). h3-py has no vectorized point-to-cell; "
          "the loops are what a user writes (`[h3.latlng_to_cell(a, b, r) for a, b in zip(lats, lngs)]`).")

    # threading
    th = res.get("threads", {})
    if len(th) > 1:
        w(f"\n#### dggs threading and OpenBLAS, {n:,} points (points/s; speed-up over the default)\n")
        w(f"Default: DGGS_THREADS={m['DGGS_THREADS']} ({m['dggs_threads']} threads here), "
          f"OPENBLAS_NUM_THREADS={m.get('OPENBLAS_NUM_THREADS', '(unset)')} "
          f"(numpy's OpenBLAS starts its own threads inside the face test's matmul). Each variant runs "
          f"in a fresh interpreter, in turn with the other rows in every round.\n")
        w("| environment | " + " | ".join(f"level {lv}" for lv in OUR_LEVELS) + " |")
        w("|---|" + "---:|" * len(OUR_LEVELS))
        base = th["default"]
        for name, d in th.items():
            cells = [f"{fmt_rate(n / d[str(lv)])}" + ("" if name == "default" else
                     f" ({base[str(lv)] / d[str(lv)]:.2f}x)") for lv in OUR_LEVELS]
            w(f"| {name} | " + " | ".join(cells) + " |")

    # scaling
    w("\n#### dggs point to cell: cost per point against the number of points and the level\n")
    sp = res["scaling_points"]
    first = next(iter(sp.values()))
    w(f"| level | ns/point at {first['n_small']:,} points | ns/point at {first['n_large']:,} points | ratio |")
    w("|---:|---:|---:|---:|")
    for lv, s in sp.items():
        w(f"| {lv} | {s['ns_small']:.0f} | {s['ns_large']:.0f} | {s['ns_large'] / s['ns_small']:.2f} |")
    w("")
    sweep = res["level_sweep"]
    base_lv = min(int(k) for k in sweep)
    base = sweep[str(base_lv)]["ns_per_point"]
    w(f"| level ({n:,} points) | points/s | ns/point | time / time at level {base_lv} | level / {base_lv} |")
    w("|---:|---:|---:|---:|---:|")
    for lv, s in sorted(sweep.items(), key=lambda kv: int(kv[0])):
        w(f"| {lv} | {fmt_rate(s['rate'])} | {s['ns_per_point']:.0f} | {s['ns_per_point'] / base:.2f} | "
          f"{int(lv) / base_lv:.1f} |")

    # cell ops
    ops = res["cell_ops"]
    nc = res["n_cells"]
    w(f"\n#### Cell operations on {nc:,} cells (input cells/s; dggs level 17, h3 res 9"
      + (f", A5 res {res['a5_cell_res']}" if "a5_cell_res" in res else "") + ")\n")
    w("| library | boundary | parent | children | disk k=1 |")
    w("|---|---:|---:|---:|---:|")
    for impl, d in ops.items():
        w(f"| {impl} | " + " | ".join(fmt_rate(d.get(op)) for op in OP_NAMES) + " |")
    w("")
    w("Ratios (dggs / peer; above 1 means dggs is faster). Disk: `grid_disk(cells, 1)` array call "
      "(a per-cell grid_disk loop in brackets).\n")
    w("| peer | boundary | parent | children | disk k=1 |")
    w("|---|---:|---:|---:|---:|")
    us = ops[OURS_OPS]
    loop = ops.get(OURS_DISK_LOOP, {}).get("disk")
    for impl, d in ops.items():
        if impl in (OURS_OPS, OURS_DISK_LOOP):
            continue
        cells = []
        for op in OP_NAMES:
            if op not in d:
                cells.append("-")
                continue
            c = fmt_ratio(us[op] / d[op])
            if op == "disk" and loop:
                c += f" ({fmt_ratio(loop / d[op])})"
            cells.append(c)
        w(f"| {impl} | " + " | ".join(cells) + " |")
    w("")
    w("- What each call returns: boundary: dggs an (N, 3, 2) array of corners (3 per triangle), h3 a tuple of "
      "6 (or 10) corners per cell, h3ronpy WKB polygons (`vector.cells_to_wkb_polygons`), A5 a closed ring of 5 corners. "
      "Parent: one level up (h3ronpy `change_resolution(arr, 8)`). Children: one level down, 3 per cell for "
      "dggs, 7 for h3 (h3ronpy `change_resolution(arr, 10)`, flat), 4 for A5. "
      "Disk k=1: h3 7 cells, h3ronpy `grid_disk(arr, 1)` (a list per cell), A5 `grid_disk(c, 1)`; "
      "dggs `grid_disk(cells, 1)` gives every cell's disk (the cell and its 3 edge neighbours, sorted) in one call; "
      f"the per-cell loop `grid_disk(c, 1)` is timed on the first {min(DISK_LOOP_CELLS, nc):,} cells.")
    if NOTES:
        w("")
        for note in NOTES:
            w(f"- Note: {note}")
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------- main


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--cells", type=int, default=100_000)
    parser.add_argument("--json", default=None, help="also write the raw numbers here")
    parser.add_argument("--thread-worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()

    if args.thread_worker:  # internal: one timed run per level under this process's DGGS_THREADS
        lat, lng = points(args.points)
        print(json.dumps(dggs_latlng(lat, lng, OUR_LEVELS, repeat=1)))
        return

    mods = {
        "h3": try_import("h3", "h3"),
        "h3ronpy": try_import("h3ronpy", "h3ronpy"),
        "a5": try_import("a5", "pya5"),
    }
    mods["h3ronpy.vector"] = try_import("h3ronpy.vector", "h3ronpy.vector") if mods["h3ronpy"] else None
    res: dict[str, Any] = {"machine": machine_info(), "n_points": args.points, "seed": SEED, "repeat": REPEAT}
    t0 = time.perf_counter()
    bench_point_to_cell(args.points, res, mods)
    bench_cell_ops(min(args.cells, args.points), res, mods)
    res["machine"]["loadavg_end"] = os.getloadavg()
    res["wall_seconds"] = time.perf_counter() - t0
    res["notes"] = NOTES
    text = report(res)
    print(text)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(res, fh, indent=1)


if __name__ == "__main__":
    main()
