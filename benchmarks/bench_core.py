"""Benchmark the compiled C core (issue 31): a fresh install's first calls, single calls and point location.

Three tables, every case against its peer in the same run, cases interleaved round by round:

1. **Fresh install.**  A wheel of this tree (``pip wheel .``) is installed into a new venv with h3-py beside it;
   then, in new processes (nothing cached but the bytecode pip writes), ``import dggs`` and the first call of
   ``latlng_to_cell``, ``grid_disk``, ``polygon_to_cells``, ``cell_to_polygon``, ``cells_to_polygons`` and
   ``line_to_cells``, each timed alone (CPU seconds of the process, and wall), against ``import h3`` and h3-py's
   nearest calls (``latlng_to_cell``, ``grid_disk``, ``h3shape_to_cells``, ``cell_to_boundary``,
   ``cells_to_h3shape``, ``grid_path_cells``).  Median of ``--fresh-runs`` processes.
2. **Single calls** (one id or point a call, a Python loop): dggs against h3-py, str and int ids, CPU time per
   call on one thread.
3. **Point to cell** over ``--points`` points, in worker processes on one thread and on the default threads:
   dggs (level 17, 0.1 km2, int ids) against h3ronpy (res 9, 0.1 km2) and healpix-geo (depth 14, WGS84).

Prints markdown; ``--json PATH`` keeps the numbers.  Run::

    .venv-bench/bin/python benchmarks/bench_core.py            # ~5 minutes on 2 cores (the venv install most)
    .venv-bench/bin/python benchmarks/bench_core.py --quick    # smoke test
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

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from _common import ONE_THREAD, code_state, describe_code, loadavg, machine, points, thread_env  # noqa: E402

HERE = Path(__file__).resolve()
ROOT = HERE.parent.parent

# --------------------------------------------------------------------------- 1. fresh install

FIRST_DGGS = """
import json, time, sys
def t(f):
    w, c = time.perf_counter(), time.process_time(); r = f(); return (time.process_time() - c, time.perf_counter() - w), r
out = {}
out["import"], dggs = t(lambda: __import__("dggs"))
from shapely.geometry import box, LineString
out["latlng_to_cell"], cell = t(lambda: dggs.latlng_to_cell(51.05, -114.07, 9))
out["grid_disk"], _ = t(lambda: dggs.grid_disk(cell, 2))
out["polygon_to_cells"], _ = t(lambda: dggs.polygon_to_cells(box(-114.5, 50.8, -113.5, 51.3), 9))
out["cell_to_polygon"], _ = t(lambda: dggs.cell_to_polygon(cell))
out["cells_to_polygons"], _ = t(lambda: dggs.cells_to_polygons(dggs.grid_disk(cell, 2)))
out["line_to_cells"], _ = t(lambda: dggs.line_to_cells(LineString([(-114.07, 51.05), (-113.49, 53.55)]), 9))
print(json.dumps(out))
"""

FIRST_H3 = """
import json, time
def t(f):
    w, c = time.perf_counter(), time.process_time(); r = f(); return (time.process_time() - c, time.perf_counter() - w), r
out = {}
out["import"], h3 = t(lambda: __import__("h3"))
out["latlng_to_cell"], cell = t(lambda: h3.latlng_to_cell(51.05, -114.07, 8))
out["grid_disk"], _ = t(lambda: h3.grid_disk(cell, 2))
poly = h3.LatLngPoly([(50.8, -114.5), (50.8, -113.5), (51.3, -113.5), (51.3, -114.5)])
out["polygon_to_cells"], _ = t(lambda: h3.h3shape_to_cells(poly, 8))
out["cell_to_polygon"], _ = t(lambda: h3.cell_to_boundary(cell))
out["cells_to_polygons"], _ = t(lambda: h3.cells_to_h3shape(h3.grid_disk(cell, 2)))
out["line_to_cells"], _ = t(lambda: h3.grid_path_cells(cell, h3.latlng_to_cell(53.55, -113.49, 8)))
print(json.dumps(out))
"""

CALLS = ("import", "latlng_to_cell", "grid_disk", "polygon_to_cells", "cell_to_polygon", "cells_to_polygons",
         "line_to_cells")


def fresh_install(runs: int) -> dict[str, Any]:
    """Install a wheel of this tree and h3 into a new venv; time the first calls in ``runs`` new processes each."""
    with tempfile.TemporaryDirectory(prefix="dggs-fresh-") as tmp:
        wheels, venv = Path(tmp) / "wheels", Path(tmp) / "venv"
        subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "-w", str(wheels), str(ROOT)],
                       check=True, capture_output=True)
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
        py = str(venv / "bin" / "python")
        wheel = next(wheels.glob("dggs-*.whl"))
        subprocess.run([py, "-m", "pip", "install", "--quiet", str(wheel), "h3"], check=True, capture_output=True)
        env = {k: v for k, v in os.environ.items() if not k.startswith(("DGGS_", "NUMBA_"))}
        found: dict[str, list[dict[str, list[float]]]] = {"dggs": [], "h3": []}
        for _ in range(runs):  # interleaved: dggs, h3, dggs, h3, ...
            for name, code in (("dggs", FIRST_DGGS), ("h3", FIRST_H3)):
                proc = subprocess.run([py, "-c", code], env=env, capture_output=True, text=True, timeout=600,
                                      cwd=tmp)
                if proc.returncode != 0:
                    raise RuntimeError(f"{name} first calls failed: {proc.stderr[-2000:]}")
                found[name].append(json.loads(proc.stdout))
    med: dict[str, Any] = {}
    for name, rows in found.items():
        med[name] = {c: [statistics.median(r[c][0] for r in rows), statistics.median(r[c][1] for r in rows)]
                     for c in CALLS}
        med[name]["total"] = [sum(med[name][c][i] for c in CALLS) for i in (0, 1)]
    med["runs"] = runs
    return med


# --------------------------------------------------------------------------- 2. single calls


def single_calls(n: int, rounds: int) -> dict[str, Any]:
    import h3

    import dggs

    rng = np.random.default_rng(7)
    lat = rng.uniform(-80, 80, n).tolist()
    lng = rng.uniform(-180, 180, n).tolist()
    pts = list(zip(lat, lng, strict=True))
    d_str = [dggs.latlng_to_cell(a, b, 9) for a, b in pts]
    d_int = [dggs.str_to_int(c) for c in d_str]
    h_str = [h3.latlng_to_cell(a, b, 8) for a, b in pts]
    h_int = [h3.str_to_int(c) for c in h_str]
    hi = h3.api.basic_int
    cases: dict[str, tuple[Any, Any]] = {
        "latlng_to_cell (str)": (lambda: [dggs.latlng_to_cell(a, b, 9) for a, b in pts],
                                 lambda: [h3.latlng_to_cell(a, b, 8) for a, b in pts]),
        "latlng_to_cell (int)": (lambda: [dggs.latlng_to_cell(a, b, 9, as_int=True) for a, b in pts],
                                 lambda: [hi.latlng_to_cell(a, b, 8) for a, b in pts]),
        "cell_to_latlng (str)": (lambda: [dggs.cell_to_latlng(c) for c in d_str],
                                 lambda: [h3.cell_to_latlng(c) for c in h_str]),
        "cell_to_latlng (int)": (lambda: [dggs.cell_to_latlng(c) for c in d_int],
                                 lambda: [hi.cell_to_latlng(c) for c in h_int]),
        "cell_to_parent (str)": (lambda: [dggs.cell_to_parent(c, 5) for c in d_str],
                                 lambda: [h3.cell_to_parent(c, 5) for c in h_str]),
        "cell_to_parent (int)": (lambda: [dggs.cell_to_parent(c, 5) for c in d_int],
                                 lambda: [hi.cell_to_parent(c, 5) for c in h_int]),
        "grid_disk k=1 (str)": (lambda: [dggs.grid_disk(c, 1) for c in d_str],
                                lambda: [h3.grid_disk(c, 1) for c in h_str]),
        "grid_disk k=1 (int)": (lambda: [dggs.grid_disk(c, 1) for c in d_int],
                                lambda: [hi.grid_disk(c, 1) for c in h_int]),
        "str_to_int": (lambda: [dggs.str_to_int(c) for c in d_str], lambda: [h3.str_to_int(c) for c in h_str]),
        "int_to_str": (lambda: [dggs.int_to_str(c) for c in d_int], lambda: [h3.int_to_str(c) for c in h_int]),
    }
    found: dict[str, dict[str, list[float]]] = {k: {"dggs": [], "h3": []} for k in cases}
    for f_d, f_h in cases.values():  # warm both once
        f_d(), f_h()
    for _ in range(rounds):
        for key, (f_d, f_h) in cases.items():
            for name, f in (("dggs", f_d), ("h3", f_h)):
                c = time.process_time()
                f()
                found[key][name].append((time.process_time() - c) / n)
    return {k: {name: statistics.median(v) for name, v in row.items()} for k, row in found.items()}


# --------------------------------------------------------------------------- 3. point to cell


def worker_points(n: int, rounds: int) -> dict[str, Any]:
    """Point to cell over n points, every peer interleaved; seconds per point (CPU, wall)."""
    import dggs

    lat, lng = points(n)
    cases: dict[str, Any] = {"dggs level 17 (int)": lambda: dggs.latlng_to_cell(lat, lng, 17, as_int=True)}
    try:
        from h3ronpy.vector import coordinates_to_cells

        cases["h3ronpy res 9"] = lambda: coordinates_to_cells(lat, lng, 9)
    except ImportError:
        pass
    try:
        from healpix_geo.nested import lonlat_to_healpix

        cases["healpix-geo depth 14 (WGS84)"] = lambda: lonlat_to_healpix(lng, lat, 14, ellipsoid="WGS84")
    except ImportError:
        pass
    for f in cases.values():
        f()
    found: dict[str, list[list[float]]] = {k: [] for k in cases}
    for _ in range(rounds):
        for k, f in cases.items():
            w, c = time.perf_counter(), time.process_time()
            f()
            found[k].append([(time.process_time() - c) / n, (time.perf_counter() - w) / n])
    return {k: [statistics.median(r[0] for r in v), statistics.median(r[1] for r in v)] for k, v in found.items()}


def spawn_points(n: int, rounds: int, one_thread: bool) -> dict[str, Any]:
    env = thread_env(one_thread)
    proc = subprocess.run([sys.executable, str(HERE), "--worker-points", str(n), "--rounds", str(rounds)], env=env,
                          capture_output=True, text=True, timeout=900)
    if proc.returncode != 0:
        raise RuntimeError(proc.stderr[-2000:])
    return json.loads(proc.stdout)


# --------------------------------------------------------------------------- report


def ms(s: float) -> str:
    return f"{s * 1e3:.1f}"


def report(res: dict[str, Any]) -> str:
    w: list[str] = []
    m, state = res["machine"], res["code"]
    w.append("### The compiled core (issue 31): `benchmarks/bench_core.py`\n")
    w.append(f"{m['cpu']}, {m['nproc']} cores; {describe_code(state)}; load average "
             f"{' / '.join(f'{x:.2f}' for x in res['load'][0])} at the start, "
             f"{' / '.join(f'{x:.2f}' for x in res['load'][1])} at the end.\n")
    if "fresh" in res:
        f = res["fresh"]
        w.append(f"#### Fresh install: first calls in a new process (median of {f['runs']} processes each)\n")
        w.append("A wheel of this tree and h3-py installed into a new venv; each call timed alone, in milliseconds "
                 "(CPU of the process / wall). dggs at level 9, h3-py at res 8; h3-py's line is `grid_path_cells`.\n")
        w.append("| call | dggs CPU ms | dggs wall ms | h3-py CPU ms | h3-py wall ms |")
        w.append("|---|---:|---:|---:|---:|")
        for c in (*CALLS, "total"):
            d, h = f["dggs"][c], f["h3"][c]
            w.append(f"| {c} | {ms(d[0])} | {ms(d[1])} | {ms(h[0])} | {ms(h[1])} |")
        w.append("")
    if "single" in res:
        w.append("#### Single calls, one thread (CPU ns a call; ratio = h3-py's time / dggs's: >= 1 means dggs is "
                 "faster)\n")
        w.append("| call | dggs ns | h3-py ns | ratio |")
        w.append("|---|---:|---:|---:|")
        for k, row in res["single"].items():
            w.append(f"| {k} | {row['dggs'] * 1e9:.0f} | {row['h3'] * 1e9:.0f} | {row['h3'] / row['dggs']:.2f}x |")
        w.append("")
    for mode in ("one", "default"):
        key = f"points_{mode}"
        if key not in res:
            continue
        rows = res[key]
        base = rows.get("dggs level 17 (int)")
        threads = "one thread (every thread variable 1)" if mode == "one" else "the default threads (dggs: "\
            f"{m['nproc']} OpenMP threads; h3ronpy and healpix-geo: their own defaults, rayon's {m['nproc']})"
        w.append(f"#### Point to cell, {res['n_points']:,} points, {threads}\n")
        w.append("ns a point; ratio = the peer's time / dggs's (>= 1: dggs is faster), CPU and wall.\n")
        w.append("| implementation | CPU ns | wall ns | CPU ratio | wall ratio |")
        w.append("|---|---:|---:|---:|---:|")
        for k, (cpu, wall) in rows.items():
            w.append(f"| {k} | {cpu * 1e9:.1f} | {wall * 1e9:.1f} | {cpu / base[0]:.2f}x | {wall / base[1]:.2f}x |")
        w.append("")
    return "\n".join(w)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--json", metavar="PATH")
    ap.add_argument("--fresh-runs", type=int, default=5)
    ap.add_argument("--no-fresh", action="store_true", help="skip the fresh install table")
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--worker-points", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.worker_points:
        print(json.dumps(worker_points(args.worker_points, args.rounds)))
        return
    if args.quick:
        args.fresh_runs, args.points, args.rounds = 1, 100_000, 1
    res: dict[str, Any] = {"machine": machine(), "code": code_state(), "n_points": args.points}
    load0 = loadavg()
    if not args.no_fresh:
        res["fresh"] = fresh_install(args.fresh_runs)
    os.environ.update(ONE_THREAD)
    res["single"] = single_calls(2_000 if args.quick else 20_000, args.rounds)
    res["points_one"] = spawn_points(args.points, args.rounds, one_thread=True)
    res["points_default"] = spawn_points(args.points, args.rounds, one_thread=False)
    res["load"] = [load0, loadavg()]
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=1))
    print(report(res))


if __name__ == "__main__":
    main()
