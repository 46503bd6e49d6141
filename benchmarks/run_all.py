"""Run every benchmark and write BENCHMARKS.md at the repository root.

Runs every ``bench_*.py`` listed in ``runs`` below but the DuckDB extension's (it needs
the extension built: ``benchmarks/bench_duckdb_extension.py``) and the small ad hoc ones (each
skipped with a note if it is missing or fails) as subprocesses with this
interpreter, collects the markdown each prints, and writes BENCHMARKS.md: the
machine, the command, the date, the code state (commit, dirty or clean), the
load average at the start and the end, each benchmark's tables, and the
"Targets (issue 18)" table checked against bench_kernel's numbers (met / missed).

Run::

    make bench                                    # the real run (about an hour on 2 cores, longer under load)
    .venv-bench/bin/python benchmarks/run_all.py --quick --output /tmp/BENCHMARKS.md   # smoke test (~1 minute)
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import ONE_THREAD, code_state, describe_code, loadavg, machine, thread_env  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TIMEOUT = {"bench_core.py": 1200, "bench_point_stages.py": 300, "bench_kernel.py": 900, "bench_snyder.py": 300, "bench_storage.py": 300, "bench_rollups.py": 600, "bench_serve.py": 300,
           "bench_workflow.py": 900, "bench_polygons.py": 600, "bench_raster.py": 6 * 3600, "bench_profile.py": 600,
           "bench_handwritten.py": 900, "bench_edges.py": 600, "bench_paths.py": 600, "bench_vertex.py": 300,
           "bench_dissolve.py": 900, "bench_scale.py": 2400,
           "bench_ivea.py": 600, "bench_projection_verbs.py": 600, "bench_handwritten_server.py": 600}  # seconds (bench_raster: the 1.8 GB globe's memory run)


def run_script(name: str, args: list[str], env: dict[str, str]) -> tuple[str, str | None, float]:
    """Run one benchmark script; return (markdown, problem or None, seconds)."""
    path = HERE / name
    if not path.exists():
        print(f"note: {name} is missing; skipped", file=sys.stderr)
        return "", f"`benchmarks/{name}` is not there; skipped.", 0.0
    print(f"running {name} {' '.join(args)}", file=sys.stderr, flush=True)
    t0 = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, str(path), *args], cwd=ROOT, env=env, capture_output=True,
                              text=True, timeout=TIMEOUT[name])
    except subprocess.TimeoutExpired:
        return "", f"`benchmarks/{name}` did not finish in {TIMEOUT[name]} s; skipped.", time.perf_counter() - t0
    secs = time.perf_counter() - t0
    if proc.stderr:
        sys.stderr.write(proc.stderr[-4000:])
    if proc.returncode != 0:
        tail = "\n".join(proc.stderr.strip().splitlines()[-5:])
        return proc.stdout, f"`benchmarks/{name}` failed (exit {proc.returncode}):\n\n```\n{tail}\n```", secs
    print(f"  {name}: {secs:.0f} s", file=sys.stderr, flush=True)
    return proc.stdout, None, secs


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes (a smoke test, not for BENCHMARKS.md)")
    ap.add_argument("--output", default=str(ROOT / "BENCHMARKS.md"))
    ap.add_argument("--skip", default="", help="comma-separated scripts to skip, e.g. bench_storage.py")
    args = ap.parse_args()

    from _kernel_report import render_targets

    started = dt.datetime.now(dt.timezone.utc)
    code = code_state()
    load0 = loadavg()
    t0 = time.perf_counter()
    skip = set(filter(None, args.skip.split(",")))
    with tempfile.TemporaryDirectory() as tmp:
        kjson = Path(tmp) / "kernel.json"
        runs = [
            # the compiled core's targets (issue 31): a fresh install's first calls, single calls, point location
            ("bench_core.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_point_stages.py", ["--quick"] if args.quick else [], thread_env(True)),
            # bench_kernel sets the thread variables itself, per worker
            ("bench_kernel.py", ["--json", str(kjson)] + (["--quick"] if args.quick else []), thread_env(False)),
            # one core for both sides (bench_snyder's own thread options are off here)
            ("bench_snyder.py", ["--points", "100000"] if args.quick else [], thread_env(True)),
            ("bench_storage.py", ["--rows", "100000"] if args.quick else [], thread_env(False)),
            ("bench_rollups.py", ["--rows", "100000", "--rounds", "1"] if args.quick else [], thread_env(True)),
            ("bench_serve.py", ["--clients", "4", "--seconds", "5"] if args.quick else [], thread_env(False)),
            ("bench_workflow.py", ["--points", "100000", "--rounds", "1"] if args.quick else [], thread_env(False)),
            ("bench_polygons.py", ["4000"] if args.quick else ["40000"], thread_env(True)),  # issue 35's polygon target
            ("bench_raster.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_profile.py", ["--quick"] if args.quick else [], thread_env(True)),
            ("bench_paths.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_handwritten.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_edges.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_vertex.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_dissolve.py", ["--quick"] if args.quick else [], thread_env(False)),
            ("bench_scale.py", ["--quick"] if args.quick else [], thread_env(False)),  # Spark local[2], Dask
            # IVEA against ISEA (no peer has IVEA on triangles): one core, as bench_snyder
            ("bench_ivea.py", ["--points", "100000", "--repeats", "1"] if args.quick else [], thread_env(True)),
            ("bench_projection_verbs.py", ["--points", "20000", "--repeats", "1"] if args.quick else [], thread_env(True)),
            ("bench_handwritten_server.py", ["--n", "10000", "--rounds", "1"] if args.quick else [], thread_env(True)),
        ]
        results = [(name, *run_script(name, a, env)) for name, a, env in runs if name not in skip]
        kernel = json.loads(kjson.read_text()) if kjson.exists() else None
    total = time.perf_counter() - t0
    load1 = loadavg()
    m = machine()
    v = m["versions"]

    out: list[str] = []
    w = out.append
    w("# Benchmarks\n")
    w(f"- **Machine:** {m['nproc']} cores ({m['cpu']}), {m['mem']} memory, {m['platform']}; "
      f"Python {m['python']}, numpy {m['numpy']}.")
    w(f"- **Libraries:** dggs {v['dggs']}; peers h3 {v['h3']}, h3ronpy {v['h3ronpy']}, "
      f"healpy {v['healpy']}, pya5 {v['pya5']}, shapely {v['shapely']}, pyproj {v['pyproj']}, pyarrow {v['pyarrow']}.")
    w("- **Command:** `make bench` (that is `.venv-bench/bin/python benchmarks/run_all.py"
      + (" --quick" if args.quick else "") + "`; the venv has dggs editable plus `benchmarks/requirements.txt`).")
    w(f"- **Code measured:** {describe_code(code)} (`git rev-parse --short HEAD` and `git status --porcelain` "
      "of the library folders; the bench venv installs dggs editable, so it runs the working tree).")
    w(f"- **Date:** {started:%Y-%m-%d %H:%M} UTC; the whole run took {total / 60:.1f} minutes.")
    w(f"- **Load average (1, 5, 15 min):** {', '.join(f'{x:.2f}' for x in load0)} at the start, "
      f"{', '.join(f'{x:.2f}' for x in load1)} at the end. Other work on this 2-core machine slows "
      "multi-threaded code most; each table gives its own load average.")
    w("- **Noise:** runs vary by +-25% from one run to the next; every number in a table comes from one run "
      "(medians of 3 timed repeats, the cases of a table interleaved), so compare within a table, not across "
      "runs or machines.")
    w(f"- **Threads:** bench_kernel.py measures every table twice, on one thread ({', '.join(ONE_THREAD)} = 1) "
      "and on the default threads; bench_snyder.py runs with all of those set to 1.")
    if args.quick:
        w("- **Quick run:** small sizes and 1 repeat (`--quick`), a smoke test only.")
    w("")
    for name, text, problem, secs in results:
        if text.strip():
            w(text.strip() + "\n")
            w(f"_({name}: {secs:.0f} s)_\n")
        if problem:
            w(f"### {name}\n\n{problem}\n")

    w("## Targets (issue 18)\n")
    if kernel is None:
        w("bench_kernel.py produced no numbers, so the targets could not be checked.\n")
    else:
        w("Each target against the peer at the nearest cell size, from the bench_kernel.py tables above (same run). "
          "A ratio is the peer's time per unit / dggs's, so **>= 1x means dggs is at least as fast** (the memory "
          "row: h3ronpy's extra peak RSS / dggs's; the threads row: 1-thread time / default-threads time). "
          "The targets use the int (uint64) ids; where that API is not there yet the string-id rows stand in, "
          f"marked as such. Code: {describe_code(kernel['code'])}.\n")
        w(render_targets(kernel["targets"]))
    Path(args.output).write_text("\n".join(out))
    print(f"wrote {args.output} ({total:.0f} s)", file=sys.stderr)


if __name__ == "__main__":
    main()
