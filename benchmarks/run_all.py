"""Run every benchmark and write BENCHMARKS.md at the repository root.

Runs ``bench_grid.py``, ``bench_snyder.py`` and ``bench_storage.py`` (each
skipped with a note if it is missing) as subprocesses with this interpreter,
collects the markdown each prints, and writes BENCHMARKS.md: the machine, the
command, the date, each benchmark's tables, and the targets of issues 3 and 6
checked against bench_grid's numbers (met / missed).

Run::

    make bench                                    # the real run (1,000,000 points; ~5-10 minutes)
    .venv-bench/bin/python benchmarks/run_all.py --quick --output /tmp/BENCHMARKS.md   # smoke test
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TIMEOUT = 900  # seconds per benchmark script


def run_script(name: str, args: list[str]) -> tuple[str, str | None, float]:
    """Run one benchmark script; return (markdown, problem or None, seconds)."""
    path = HERE / name
    if not path.exists():
        print(f"note: {name} is missing; skipped", file=sys.stderr)
        return "", f"`benchmarks/{name}` is not there yet; skipped.", 0.0
    print(f"running {name} {' '.join(args)}", file=sys.stderr, flush=True)
    t0 = time.perf_counter()
    try:
        proc = subprocess.run(
            [sys.executable, str(path), *args],
            cwd=ROOT,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            timeout=TIMEOUT,
        )
    except subprocess.TimeoutExpired:
        return "", f"`benchmarks/{name}` did not finish in {TIMEOUT} s; skipped.", time.perf_counter() - t0
    secs = time.perf_counter() - t0
    if proc.stderr:
        sys.stderr.write(proc.stderr[-4000:])
    if proc.returncode != 0:
        tail = "\n".join(proc.stderr.strip().splitlines()[-5:])
        return proc.stdout, f"`benchmarks/{name}` failed (exit {proc.returncode}):\n\n```\n{tail}\n```", secs
    print(f"  {name}: {secs:.0f} s", file=sys.stderr, flush=True)
    return proc.stdout, None, secs


def code_state() -> str:
    """The commit measured, and any uncommitted changes to the library code (the venv is editable)."""
    def git(*a: str) -> str:
        try:
            return subprocess.run(["git", *a], cwd=ROOT, capture_output=True, text=True, timeout=30).stdout.rstrip()
        except (OSError, subprocess.SubprocessError):
            return ""

    head = git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = [ln[3:] for ln in git("status", "--porcelain", "--", "dggs", "index", "storage").splitlines()]
    if not dirty:
        return f"commit {head}, library code clean"
    return f"commit {head} plus uncommitted work in progress in {', '.join(f'`{d}`' for d in dirty)}"


def machine() -> dict[str, Any]:
    cpu = platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            cpu = next((ln.split(":", 1)[1].strip() for ln in fh if ln.startswith("model name")), cpu)
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as fh:
            kb = int(next(ln.split()[1] for ln in fh if ln.startswith("MemTotal")))
            mem = f"{kb / 2**20:.0f} GiB"
    except (OSError, StopIteration):
        pass
    try:
        nproc = len(os.sched_getaffinity(0))
    except AttributeError:
        nproc = os.cpu_count()
    import numpy

    return {"cpu": cpu, "nproc": nproc, "mem": mem, "python": platform.python_version(),
            "numpy": numpy.__version__, "platform": platform.platform()}


# --------------------------------------------------------------------------- targets


def _verdict(ok: bool | None) -> str:
    return "n/a" if ok is None else ("**met**" if ok else "**missed**")


def targets(g: dict[str, Any]) -> list[tuple[str, str, str, str]]:
    """(issue, target, measured, verdict) rows from bench_grid's JSON."""
    rows: list[tuple[str, str, str, str]] = []
    pt = g["point_to_cell"]

    def rate(impl_prefix: str, level: int) -> float | None:
        r = next((x for x in pt if x["impl"].startswith(impl_prefix) and x["level"] == level), None)
        return r["rate"] if r else None

    levels = sorted({x["level"] for x in pt})
    # issue 3: as fast as h3's fastest Python path
    for lv in levels:
        ours = rate("dggs", lv)
        peers = {k: rate(k, lv) for k in ("h3-py string", "h3-py integer", "h3ronpy")}
        peers = {k: v for k, v in peers.items() if v}
        if not peers:
            rows.append(("3", f"point to cell >= h3's fastest Python path (level {lv})", "no h3 peer", "n/a"))
            continue
        best = max(peers, key=peers.get)
        ratio = ours / peers[best]
        h3py = {k: v for k, v in peers.items() if k.startswith("h3-py")}
        also = ""
        if best not in h3py and h3py:
            b2 = max(h3py, key=h3py.get)
            also = f" (vs h3-py alone, its {b2.split()[-1]} API loop: {ours / h3py[b2]:.2f}x)"
        rows.append(("3", f"point to cell >= h3's fastest Python path (h3-py or h3ronpy), level {lv}",
                     f"{ours / 1e6:.2f} M/s vs {best} {peers[best] / 1e6:.2f} M/s = {ratio:.2f}x{also}",
                     _verdict(ratio >= 1)))
    # issue 3: linear in points
    for lv, s in g["scaling_points"].items():
        r = s["ns_large"] / s["ns_small"]
        rows.append(("3", f"cost linear in points, level {lv} (per-point time flat, within the +-25% noise)",
                     f"{s['ns_small']:.0f} ns/pt at {s['n_small']:,}, {s['ns_large']:.0f} ns/pt at {s['n_large']:,} "
                     f"(x{r:.2f})", _verdict(r <= 1.25)))
    # issue 3: at most linear in level: t(L) / t(L0) <= L / L0 for every level L (true of any
    # a + b L with a, b >= 0; a quadratic or worse term breaks it at the deep levels)
    sweep = sorted(((int(k), v["ns_per_point"]) for k, v in g["level_sweep"].items()))
    (l0, t0) = sweep[0]
    growth = max((t / t0) / (lv / l0) for lv, t in sweep[1:])
    worst_step = max((t2 / t1) / (l2 / l1) for (l1, t1), (l2, t2) in zip(sweep, sweep[1:]))
    ls = [lv for lv, _ in sweep]
    ts = [t for _, t in sweep]
    mean_l, mean_t = sum(ls) / len(ls), sum(ts) / len(ts)
    slope = sum((a - mean_l) * (b - mean_t) for a, b in zip(ls, ts)) / sum((a - mean_l) ** 2 for a in ls)
    ln, tn = sweep[-1]
    rows.append(("3", f"cost at most linear in level: time(L) / time({l0}) <= L / {l0} for L in "
                      f"{', '.join(str(lv) for lv in ls[1:])}",
                 f"{t0:.0f} ns/pt at level {l0} to {tn:.0f} at level {ln} (x{tn / t0:.2f} for x{ln / l0:.0f} levels); "
                 f"largest (time ratio / level ratio) {growth:.2f}; least-squares slope ~{slope:.0f} ns per level; "
                 f"worst single step {worst_step:.2f} (noise-prone)",
                 _verdict(growth <= 1.0)))
    # issue 6: point to cell vs h3-py string API and h3ronpy
    for lv in levels:
        ours = rate("dggs", lv)
        for peer, need in (("h3-py string", 2.0), ("h3ronpy", 1.0)):
            p = rate(peer, lv)
            if p is None:
                rows.append(("6", f"latlng_to_cell >= {need:g}x {peer}, level {lv}", "peer missing", "n/a"))
                continue
            rows.append(("6", f"latlng_to_cell >= {need:g}x {peer}, level {lv}",
                         f"{ours / p:.2f}x", _verdict(ours / p >= need)))
    # issue 6: cell operations
    ops = g["cell_ops"]
    ours = ops.get("dggs (array call)", {})
    loop = ops.get("dggs `grid_disk(c, 1)` (Python loop)", {})
    for impl in ("h3-py string API (loop)", "h3-py integer API (loop)"):
        if impl not in ops:
            rows.append(("6", f"boundaries and disks >= 2x {impl}", "peer missing", "n/a"))
            continue
        p = ops[impl]
        rows.append(("6", f"boundaries >= 2x {impl}", f"{ours['boundary'] / p['boundary']:.2f}x",
                     _verdict(ours["boundary"] / p["boundary"] >= 2)))
        rows.append(("6", f"disks k=1 >= 2x {impl}, `grid_disk(cells, 1)` array call",
                     f"{ours['disk'] / p['disk']:.2f}x", _verdict(ours["disk"] / p["disk"] >= 2)))
        if "disk" in loop:
            rows.append(("6", f"disks k=1 >= 2x {impl}, `grid_disk(c, 1)` per cell",
                         f"{loop['disk'] / p['disk']:.3g}x", _verdict(loop["disk"] / p["disk"] >= 2)))
    h = ops.get("h3ronpy (vectorized)")
    for op in ("parent", "children"):
        if h is None:
            rows.append(("6", f"{op} >= 1x h3ronpy", "peer missing", "n/a"))
            continue
        rows.append(("6", f"{op} >= 1x h3ronpy", f"{ours[op] / h[op]:.3g}x", _verdict(ours[op] / h[op] >= 1)))
    return rows


# --------------------------------------------------------------------------- main


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes (a smoke test, not for BENCHMARKS.md)")
    ap.add_argument("--output", default=str(ROOT / "BENCHMARKS.md"))
    args = ap.parse_args()

    started = dt.datetime.now(dt.timezone.utc)
    code = code_state()
    load0 = os.getloadavg()
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        grid_json = Path(tmp) / "grid.json"
        grid_args = ["--json", str(grid_json)] + (["--points", "100000", "--cells", "10000"] if args.quick else [])
        runs = [
            ("bench_grid.py", grid_args),
            ("bench_snyder.py", ["--points", "100000"] if args.quick else []),
            ("bench_storage.py", ["--rows", "100000"] if args.quick else []),
        ]
        results = [(name, *run_script(name, a)) for name, a in runs]
        grid = json.loads(grid_json.read_text()) if grid_json.exists() else None
    total = time.perf_counter() - t0
    load1 = os.getloadavg()
    m = machine()

    out: list[str] = []
    w = out.append
    w("# Benchmarks\n")
    w(f"- **Machine:** {m['nproc']} cores ({m['cpu']}), {m['mem']} memory, {m['platform']}; "
      f"Python {m['python']}, numpy {m['numpy']}.")
    if grid:
        gm = grid["machine"]
        w(f"- **Libraries:** dggs {gm['dggs']} (point to cell on {gm['dggs_threads']} threads by default), "
          f"h3 {gm['h3']}, h3ronpy {gm['h3ronpy']}, pya5 {gm['pya5']}, pyarrow {gm['pyarrow']}.")
    w("- **Command:** `make bench` (that is `.venv-bench/bin/python benchmarks/run_all.py"
      + (" --quick" if args.quick else "") + "`; the venv has dggs editable plus `benchmarks/requirements.txt`).")
    w(f"- **Code measured:** {code} (the bench venv installs dggs editable, so it runs the working tree).")
    w(f"- **Date:** {started:%Y-%m-%d %H:%M} UTC; the whole run took {total / 60:.1f} minutes.")
    w("- **Noise:** runs vary by +-25% from one run to the next; every number in a table comes from one run "
      "(medians of 3 timed repeats), so compare within a table, not across runs or machines.")
    w(f"- **Shared CPU:** other engineers were using this 2-core machine during the run (load average "
      f"{load0[0]:.2f} at the start, {load1[0]:.2f} at the end), which slows multi-threaded code most.")
    if args.quick:
        w("- **Quick run:** small sizes (`--quick`), a smoke test only.")
    w("")
    for name, text, problem, secs in results:
        if text.strip():
            w(text.strip() + "\n")
            w(f"_({name}: {secs:.0f} s)_\n")
        if problem:
            w(f"### {name}\n\n{problem}\n")

    w("## Targets (issues 3 and 6)\n")
    if grid is None:
        w("bench_grid.py produced no numbers, so the targets could not be checked.\n")
    else:
        rows = targets(grid)
        w("| issue | target | measured (this run) | verdict |")
        w("|---|---|---|---|")
        for r in rows:
            w("| " + " | ".join(r) + " |")
        blas = grid.get("threads", {}).get("OPENBLAS_NUM_THREADS=1 (dggs threads default)")
        if blas:
            n = grid["n_points"]
            best = {lv: max((x["rate"] for x in grid["point_to_cell"]
                             if x["level"] == lv and not x["impl"].startswith("dggs")
                             and not x["impl"].startswith("A5")), default=None) for lv in (10, 17)}
            parts = [f"level {lv}: {n / blas[str(lv)] / 1e6:.2f} M points/s = "
                     f"{n / blas[str(lv)] / best[lv]:.2f}x h3's fastest path" for lv in (10, 17)
                     if str(lv) in blas and best.get(lv)]
            if parts:
                w("| 3, 6 | (for information, not a verdict) point to cell with `OPENBLAS_NUM_THREADS=1` | "
                  + "; ".join(parts) + " | - |")
        met = sum(r[3] == "**met**" for r in rows)
        missed = sum(r[3] == "**missed**" for r in rows)
        w(f"\n{met} met, {missed} missed. Ratios are dggs / peer from the tables above (same run, same points).\n")
    Path(args.output).write_text("\n".join(out))
    print(f"wrote {args.output} ({total:.0f} s)", file=sys.stderr)


if __name__ == "__main__":
    main()
