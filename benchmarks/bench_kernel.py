"""Benchmark the dggs kernel (64-bit ids) against h3ronpy, healpy, h3-py and A5 (issue 9).

Every table runs twice, each time in a fresh worker process: on one thread
(DGGS_THREADS=1 NUMBA_NUM_THREADS=1 RAYON_NUM_THREADS=1 OMP_NUM_THREADS=1
OPENBLAS_NUM_THREADS=1) and on the default threads (those variables unset).
Then, each in fresh processes: the threads speed-up of point to cell (1-thread
and default processes alternating), the peak RSS of point to cell on 10M
points, and the first call after ``import dggs`` in two fresh processes.  Prints markdown on stdout; ``--json PATH`` writes the raw numbers and
the issue-18 targets (``run_all.py`` reads them).  Wall and CPU time, load
average and the git commit are reported with the numbers.

A peer that is not installed, or a dggs function of the new API that is not
there yet, is skipped with a note: the script never crashes on it.

Run::

    make bench                                                  # everything, writes BENCHMARKS.md
    .venv-bench/bin/python benchmarks/bench_kernel.py           # this file only (~3-5 minutes)
    .venv-bench/bin/python benchmarks/bench_kernel.py --quick   # smoke test, under a minute
"""

from __future__ import annotations

import argparse
import inspect
import json
import os
import resource
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from _common import (  # noqa: E402
    NOTES,
    code_state,
    loadavg,
    machine,
    note,
    points,
    run_json,
    run_once,
    thread_env,
    thread_info,
    try_import,
)

HERE = Path(__file__).resolve()
FULL = dict(points=1_000_000, loop_points=200_000, cells=100_000, compact_cells=1_000_000, box_deg=20.0,
            circle_km=500.0, single_calls=20_000, rss_points=10_000_000, repeat=3, rounds=3, budget=5.0,
            table_budget=90.0)
QUICK = dict(points=100_000, loop_points=20_000, cells=10_000, compact_cells=50_000, box_deg=20.0,
             circle_km=100.0, single_calls=2_000, rss_points=1_000_000, repeat=1, rounds=1, budget=5.0,
             table_budget=30.0)
WORKER_TIMEOUT = 600
RSS_IMPLS = ("dggs-int", "dggs-str", "h3ronpy", "healpy")
WARM_POINTS = 200_000  # the RSS workers' warm-up: large enough for any parallel path


def peers() -> dict[str, Any]:
    mods = {"h3": try_import("h3"), "h3ronpy": try_import("h3ronpy"), "healpy": try_import("healpy"),
            "a5": try_import("a5", "pya5")}
    mods["h3ronpy.vector"] = try_import("h3ronpy.vector") if mods["h3ronpy"] else None
    return mods


def int_signature() -> bool:
    """Whether latlng_to_cell takes ``as_int`` (without calling it: no compilation triggered)."""
    import dggs

    try:
        return "as_int" in inspect.signature(dggs.latlng_to_cell).parameters
    except (TypeError, ValueError):
        return False


def maxrss() -> int:
    """Peak resident set size of this process so far, bytes (Linux reports KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


# --------------------------------------------------------------------------- workers (fresh processes)


def worker_tables(mode: str, sizes: dict[str, Any]) -> dict[str, Any]:
    import _common
    from _kernel_cases import run_all_tables

    _common.TABLE_BUDGET[0] = sizes["table_budget"]
    load0 = loadavg()
    mods = peers()
    out = run_all_tables(mods, sizes, sizes["repeat"], sizes["budget"])
    out.update(mode=mode, threads=thread_info(), load=[load0, loadavg()], notes=NOTES,
               dggs_path=str(Path(sys.modules["dggs"].__file__).parent))
    return out


def worker_threads(n: int) -> dict[str, Any]:
    """One timed point-to-cell call each for dggs and h3ronpy (after a warm-up), level 17 / res 9."""
    import dggs

    lat, lng = points(n)
    kw = {"as_int": True} if int_signature() else {}
    out: dict[str, Any] = {"threads": thread_info()}
    cases = {"dggs": lambda: dggs.latlng_to_cell(lat, lng, 17, **kw)}
    hv = try_import("h3ronpy.vector")
    if hv is not None:
        cases["h3ronpy"] = lambda: hv.coordinates_to_cells(lat, lng, 9)
    for name, fn in cases.items():
        fn()  # warm-up
        wall, cpu, _ = run_once(fn)
        out[name] = {"wall": wall, "cpu": cpu}
    return out


def points_in_place(n: int) -> tuple[np.ndarray, np.ndarray]:
    """``points(n)``'s distribution made in place, so that no temporary raises the peak RSS before the call."""
    rng = np.random.default_rng(20_240_601)
    lat = rng.random(n)
    lat *= 2.0
    lat -= 1.0
    np.arcsin(lat, out=lat)
    np.degrees(lat, out=lat)
    lng = rng.random(n)
    lng *= 360.0
    lng -= 180.0
    return lat, lng


def rss_now() -> int:
    """Current resident set size, bytes."""
    with open("/proc/self/statm") as fh:
        return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def reset_peak() -> bool:
    """Reset the kernel's peak-RSS mark to the current RSS (Linux >= 4.0: "5" into /proc/self/clear_refs).

    Without it the high-water mark after the imports (transients of pyproj,
    the thread pools) sits above the resident size, and a call could use that
    gap unseen.  ``ru_maxrss`` follows the reset.
    """
    try:
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        return True
    except OSError:
        return False


def worker_rss(impl: str, n: int) -> dict[str, Any]:
    """Extra peak RSS of one point-to-cell call on ``n`` points (level 17, h3 res 9, healpy nside 16384)."""
    lat, lng = points_in_place(n)
    if impl.startswith("dggs"):
        import dggs

        if impl == "dggs-int" and not int_signature():
            return {"skipped": "no `as_int` in dggs.latlng_to_cell yet"}
        kw = {"as_int": True} if impl == "dggs-int" else {}
        fn = lambda a, b: dggs.latlng_to_cell(a, b, 17, **kw)  # noqa: E731
    elif impl == "h3ronpy":
        import h3ronpy.vector as hv

        fn = lambda a, b: hv.coordinates_to_cells(a, b, 9)  # noqa: E731
    else:
        import healpy

        np.subtract(90.0, lat, out=lat)  # theta, phi (radians), in place: part of the inputs
        np.radians(lat, out=lat)
        np.radians(lng, out=lng)
        fn = lambda a, b: healpy.ang2pix(16384, a, b, nest=True)  # noqa: E731
    fn(lat[:WARM_POINTS], lng[:WARM_POINTS])  # warm-up: the parallel path, thread pools
    reset = reset_peak()
    base, now = maxrss(), rss_now()
    wall, cpu, res = run_once(lambda: fn(lat, lng))
    peak = maxrss()
    if isinstance(res, np.ndarray):
        nbytes, itemsize = res.nbytes, res.dtype.itemsize
    else:  # an arrow array (h3ronpy)
        import pyarrow as pa

        nbytes = pa.array(res).nbytes
        itemsize = nbytes // max(len(res), 1)
    # gap: how far the high-water mark already was above the resident size at the baseline; a call
    # whose extra memory fits in the gap is under-reported by up to that much.
    out = {"baseline": base, "peak": peak, "delta": peak - base, "gap": base - now, "reset": reset,
           "out_bytes": int(nbytes),
           "itemsize": int(itemsize), "wall": wall, "cpu": cpu}
    if impl == "dggs-str":
        out["string_widths"] = {lv: int(dggs.latlng_to_cell(lat[:2], lng[:2], lv).dtype.itemsize)
                                for lv in (10, 17, 28)}
    return out


def worker_compile() -> dict[str, Any]:
    """Seconds (wall, CPU) of ``import dggs`` and of the first and second calls in this fresh process."""
    out: dict[str, Any] = {}
    w, c, dggs = run_once(lambda: __import__("dggs"))
    out["import"] = (w, c)
    lat, lng = points(1000)
    kind = "int" if int_signature() else "str"
    out["kind"] = {"int": "int (uint64)", "str": "string (no int API yet)"}[kind]
    kw = {"as_int": True} if kind == "int" else {}
    for tag in ("first", "second"):
        w, c, ids = run_once(lambda: dggs.latlng_to_cell(lat, lng, 17, **kw))
        out[f"latlng_{tag}"] = (w, c)
    for tag in ("first", "second"):
        w, c, _ = run_once(lambda: dggs.grid_disk(ids[:100], 1))
        out[f"disk_{tag}"] = (w, c)
    return out


# --------------------------------------------------------------------------- orchestration


def spawn(args: list[str], env: dict[str, str], timeout: float = WORKER_TIMEOUT) -> dict[str, Any] | None:
    try:
        return run_json([str(HERE), *args], env, timeout)
    except Exception as exc:
        note(f"`bench_kernel.py {' '.join(args[:2])}` failed ({type(exc).__name__}: {str(exc)[:300]}); skipped.")
        return None


def measure_threads(sizes: dict[str, Any]) -> dict[str, Any]:
    load0 = loadavg()
    runs: dict[str, dict[str, list[tuple[float, float]]]] = {"one": {}, "default": {}}
    for r in range(sizes["rounds"]):
        order = ("one", "default") if r % 2 == 0 else ("default", "one")
        for mode in order:
            got = spawn(["--threads-worker", "--points", str(sizes["points"])], thread_env(mode == "one"))
            for impl in ("dggs", "h3ronpy"):
                if got and impl in got:
                    runs[mode].setdefault(impl, []).append((got[impl]["wall"], got[impl]["cpu"]))
    out: dict[str, Any] = {"points": sizes["points"], "rounds": sizes["rounds"], "load": [load0, loadavg()]}
    for mode, d in runs.items():
        out[mode] = {impl: {"wall": float(np.median([x[0] for x in v])), "cpu": float(np.median([x[1] for x in v]))}
                     for impl, v in d.items()}
    return out


def measure_rss(sizes: dict[str, Any]) -> dict[str, Any]:
    n = sizes["rss_points"]
    out: dict[str, Any] = {"points": n, "cases": {}}
    for impl in RSS_IMPLS:
        got = spawn(["--rss-worker", impl, "--points", str(n)], thread_env(False))
        if got is None:
            got = {"error": "worker failed (see the notes)"}
        out["cases"][impl] = got
        if "string_widths" in got:
            out["string_widths"] = got.pop("string_widths")
    return out


def measure_compile() -> dict[str, Any]:
    out: dict[str, Any] = {}
    for name in ("cold", "warm"):  # the page cache warm for the second (the compiled core keeps no other cache)
        got = spawn(["--compile-worker"], thread_env(False))
        if got is None:
            out[name] = {"error": "worker failed (see the notes)"}
            continue
        out["kind"] = got.pop("kind", "?")
        out[name] = got
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes, 1 repeat (a smoke test)")
    ap.add_argument("--json", default=None, help="also write the raw numbers and the targets here")
    ap.add_argument("--with-targets", action="store_true", help="also print the issue-18 targets table")
    ap.add_argument("--skip", default="", help="comma-separated parts to skip: one,default,threads,rss,compile")
    for key, val in FULL.items():
        ap.add_argument("--" + key.replace("_", "-"), type=type(val), default=None,
                        help=f"default {val:,} ({QUICK[key]:,} with --quick)")
    # internal: the workers
    ap.add_argument("--worker", choices=("one", "default"), help=argparse.SUPPRESS)
    ap.add_argument("--sizes", help=argparse.SUPPRESS)
    ap.add_argument("--threads-worker", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--rss-worker", choices=RSS_IMPLS, help=argparse.SUPPRESS)
    ap.add_argument("--compile-worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()

    if args.worker:
        print(json.dumps(worker_tables(args.worker, json.loads(args.sizes))))
        return
    if args.threads_worker:
        print(json.dumps(worker_threads(args.points)))
        return
    if args.rss_worker:
        print(json.dumps(worker_rss(args.rss_worker, args.points)))
        return
    if args.compile_worker:
        print(json.dumps(worker_compile()))
        return

    sizes = dict(QUICK if args.quick else FULL)
    sizes.update({k: getattr(args, k) for k in FULL if getattr(args, k) is not None})
    skip = set(filter(None, args.skip.split(",")))
    t0 = time.perf_counter()
    res: dict[str, Any] = {"machine": machine(), "code": code_state(), "load_start": loadavg(), "sizes": sizes,
                           "repeat": sizes["repeat"], "quick": args.quick, "modes": {}}
    for mode in ("one", "default"):
        if mode in skip:
            continue
        print(f"bench_kernel: tables, {mode} thread(s)", file=sys.stderr, flush=True)
        got = spawn(["--worker", mode, "--sizes", json.dumps(sizes)], thread_env(mode == "one"))
        if got:
            NOTES.extend(n for n in got.pop("notes", []) if n not in NOTES)
            res["modes"][mode] = got
    parts = (("threads", measure_threads), ("rss", measure_rss), ("compile", lambda s: measure_compile()))
    for name, fn in parts:
        if name not in skip:
            print(f"bench_kernel: {name}", file=sys.stderr, flush=True)
            res[name] = fn(sizes)
    res["load_end"] = loadavg()
    res["wall_seconds"] = time.perf_counter() - t0
    res["notes"] = NOTES

    from _kernel_report import render, render_targets, targets

    res["targets"] = targets(res)
    text = render(res)
    if args.with_targets:
        text += "\n#### Targets (issue 18)\n\n" + render_targets(res["targets"])
    print(text)
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=1))
    print(f"bench_kernel: {res['wall_seconds']:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
