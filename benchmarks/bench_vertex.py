"""Benchmark grid_disk_vertex per output cell against grid_disk and h3-py's grid_disk (issue 32 item 6).

A corner-sharing disk of radius k round a level-28 cell (its ~9 k^2 cells, 812,698 at k = 300) against the
edge disk of about as many cells (radius 3k) from dggs's ``grid_disk``, and h3-py's ``grid_disk`` (which is
H3's vertex-and-edge adjacency: hexagons share both) of about as many cells at resolution 15. One call each,
integer and string ids; the time is CPU time per output cell on one thread; the ratio is grid_disk's time per
cell over grid_disk_vertex's, so **>= 1x means the vertex disk costs no more a cell than the edge disk**.

Run::

    .venv-bench/bin/python benchmarks/bench_vertex.py            # markdown on stdout
    .venv-bench/bin/python benchmarks/bench_vertex.py --quick
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import dggs  # noqa: E402

from _common import fmt_ns, fmt_ratio, interleaved, loadavg, print_report, try_import  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="k up to 60, one round")
    args = ap.parse_args()
    load0 = loadavg()
    h3 = try_import("h3")
    radii = (10, 60) if args.quick else (10, 60, 300)
    cell = dggs.latlng_to_cell(10.0, 20.0, 28)
    as_int = dggs.str_to_int(cell)
    out = ["## grid_disk_vertex (issue 32 item 6)\n",
           "Level 28, one call a row, CPU time per output cell, one thread.\n",
           "| case | cells | per cell (CPU) | grid_disk int per cell / this |", "|---|---:|---:|---:|"]
    for k in radii:
        cases: dict[str, tuple[Callable[[], Any], Any]] = {
            f"grid_disk_vertex(int, {k})": (lambda k=k: dggs.grid_disk_vertex(as_int, k), len),
            f"grid_disk_vertex(str, {k})": (lambda k=k: dggs.grid_disk_vertex(cell, k), len),
            f"grid_disk(int, {3 * k})": (lambda k=k: dggs.grid_disk(as_int, 3 * k), len),
            f"grid_disk(str, {3 * k})": (lambda k=k: dggs.grid_disk(cell, 3 * k), len),
        }
        if h3 is not None:
            hc = h3.latlng_to_cell(10.0, 20.0, 15)
            cases[f"h3-py grid_disk(str, {int(1.73 * k)})"] = (lambda k=k, hc=hc: h3.grid_disk(hc, int(1.73 * k)), len)
        res = interleaved(cases, 1 if args.quick else 5, budget=120.0)
        ref = res.get(f"grid_disk(int, {3 * k})")
        for key, r in res.items():
            per = r["cpu"] / r["units"]
            ratio = ref["cpu"] / ref["units"] / per if ref else None
            out.append(f"| {key} | {r['units']:,} | {fmt_ns(per)} | {fmt_ratio(ratio)} |")
    out.append("")
    print_report(out, load0)


if __name__ == "__main__":
    main()
