"""Where point location's time goes in the C core, stage by stage (issue 31's profile of its missed targets).

Compiles ``benchmarks/c/point_stages.c`` with the core's sources (``cc -O3 -ffp-contract=off``, one thread) and
prints, in ns a point over 1M uniform points (CPU time): the authalic unit vector (``geodetic_to_unit``: a sine
and cosine pair and the authalic series), the nearest face (a 20-way dot product scan), Snyder's forward on
that face (an arctangent and square roots), and the descent through the levels (``encode_point``), beside the
whole ``dggs_one_point`` at levels 0-28.  Run::

    .venv-bench/bin/python benchmarks/bench_point_stages.py
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


def run(points: int) -> dict[str, float]:
    cc = os.environ.get("CC") or shutil.which("cc") or "gcc"
    with tempfile.TemporaryDirectory() as tmp:
        exe = str(Path(tmp) / "point_stages")
        sources = sorted(glob.glob(str(ROOT / "libdggs" / "src" / "*.c")))
        subprocess.run([cc, "-std=c11", "-O3", "-ffp-contract=off", "-D_POSIX_C_SOURCE=199309L",
                        f"-I{ROOT / 'libdggs' / 'include'}", f"-I{ROOT / 'libdggs' / 'src'}",
                        str(ROOT / "benchmarks" / "c" / "point_stages.c"), *sources, "-lm", "-o", exe], check=True)
        out = subprocess.run([exe, str(points)], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def report(r: dict[str, float]) -> str:
    w = ["### Point location in the C core, stage by stage (`benchmarks/bench_point_stages.py`)\n",
         f"CPU ns a point over {int(r['points']):,} uniform points, one thread, gcc -O3 (the stages timed one by one "
         "over the same points; the whole `dggs_one_point` beside them).\n",
         "| stage | ns a point |", "|---|---:|",
         f"| authalic unit vector (`geodetic_to_unit`: sin, cos, the authalic series) | {r['geodetic_to_unit']:.1f} |",
         f"| nearest face (20 dot products) | {r['nearest_face']:.1f} |",
         f"| Snyder's forward on that face (atan2, square roots) | {r['face_forward']:.1f} |"]
    for lv in (0, 1, 5, 9, 13, 17, 21, 28):
        w.append(f"| descent to level {lv} (`encode_point`) / whole `dggs_one_point` | {r[f'encode_{lv}']:.1f} / "
                 f"{r[f'one_point_{lv}']:.1f} |")
    return "\n".join(w) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    print(report(run(100_000 if args.quick else args.points)))


if __name__ == "__main__":
    sys.exit(main())
