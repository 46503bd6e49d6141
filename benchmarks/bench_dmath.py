"""The core's own sin, cos, atan2, hypot and asin (issue 34): alone against glibc's, and point location before/after.

Two tables, CPU time on one thread, gcc -O3 -ffp-contract=off as setup.py builds the core:

- the five functions alone (``benchmarks/c/dmath_bench.c``): ns a call over 1M arguments in the ranges point
  location gives them, libm and dmath alternating, the fastest of 5 rounds;
- point location (``benchmarks/c/point_stages.c``: ``dggs_one_point`` on ISEA at levels 0-28 and on IVEA at 0 and
  28, and its stages) built from this checkout's ``libdggs/src`` and from ``--before DIR``'s (a checkout whose core
  calls the platform's libm, e.g. the main branch), the two programs run alternately ``--rounds`` times over the
  same 1M uniform points, the fastest round of each kept.

Run::

    python benchmarks/bench_dmath.py --before /work/main
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FLAGS = ["-std=c11", "-O3", "-ffp-contract=off", "-fno-fast-math", "-D_POSIX_C_SOURCE=199309L"]


def _build(cc: str, main: Path, root: Path, exe: Path, *extra: str) -> None:
    sources = sorted(glob.glob(str(root / "libdggs" / "src" / "*.c")))
    subprocess.run([cc, *FLAGS, f"-I{root / 'libdggs' / 'include'}", f"-I{root / 'libdggs' / 'src'}", str(main),
                    *sources, *extra, "-lm", "-o", str(exe)], check=True)


def _run(exe: Path, *args: str) -> dict[str, float]:
    return json.loads(subprocess.run([str(exe), *args], check=True, capture_output=True, text=True).stdout)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--before", type=Path, help="a checkout whose libdggs/src is the 'before' core")
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    cc = os.environ.get("CC") or shutil.which("cc") or "gcc"
    with tempfile.TemporaryDirectory() as tmp:
        t = Path(tmp)
        alone = t / "dmath_bench"
        subprocess.run([cc, *FLAGS, f"-I{ROOT / 'libdggs' / 'src'}", str(ROOT / "benchmarks" / "c" / "dmath_bench.c"),
                        str(ROOT / "libdggs" / "src" / "dmath.c"), "-lm", "-o", str(alone)], check=True)
        r = _run(alone, str(args.points), str(args.rounds))
        print(f"### The core's own libm functions alone (`benchmarks/bench_dmath.py`)\n\nCPU ns a call, {args.points:,} "
              f"arguments, one thread, fastest of {args.rounds} alternating rounds.\n")
        print("| function | glibc | dmath | ratio |\n|---|---:|---:|---:|")
        for name in ("sin", "cos", "atan2", "hypot", "asin"):
            a, b = r[f"libm_{name}"], r[f"dmath_{name}"]
            print(f"| {name} | {a:.1f} | {b:.1f} | {b / a:.2f} |")
        if not args.before:
            return
        stages = ROOT / "benchmarks" / "c" / "point_stages.c"
        _build(cc, stages, args.before, t / "before")
        _build(cc, stages, ROOT, t / "after")
        best: dict[str, dict[str, float]] = {"before": {}, "after": {}}
        for _ in range(args.rounds):
            for side in ("before", "after"):
                for k, v in _run(t / side, str(args.points)).items():
                    if k not in ("points", "checksum"):
                        best[side][k] = min(best[side].get(k, float("inf")), v)
        print(f"\n### Point location before/after (`benchmarks/bench_dmath.py --before {args.before}`)\n\nCPU ns a "
              f"point, {args.points:,} uniform points, one thread, fastest of {args.rounds} alternating rounds.\n")
        print("| stage | before (platform libm) | after (dmath) | ratio |\n|---|---:|---:|---:|")
        for k, a in best["before"].items():
            b = best["after"].get(k)
            if b is not None:
                print(f"| {k} | {a:.1f} | {b:.1f} | {b / a:.2f} |")


if __name__ == "__main__":
    sys.exit(main())
