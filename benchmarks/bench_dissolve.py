"""Benchmark cells_to_polygons (dissolve) against shapely.union_all and h3's cells_to_h3shape (issue 21).

- **100k contiguous cells**: the level-12 cells of a 20 x 15 degree box
  (``polygon_to_cells``, about 100,000 cells).  dggs.cells_to_polygons against
  ``shapely.union_all`` of the cells' ``cell_to_polygon`` (the union alone, the
  polygons built beforehand, and both), at the same points per edge.  Target:
  dissolve at least 3x faster than the union.
- **per cell against h3**: an H3 disk (``grid_disk``) at resolutions 5 and 7,
  and the dggs cells filling the same shape at the level nearest H3's
  resolution by cell area.  h3-py's ``cells_to_h3shape`` (``basic_int`` and
  ``basic_str``) and h3ronpy's ``cells_to_wkb_polygons(..., link_cells=True)``
  against ``cells_to_polygons`` (uint64 ids and strings; one point an edge, as
  H3's straight-edged hexagons, and by default, each edge with the points its
  cell's polygon gets).  The ratio is the peer's time per input cell over
  dggs's: **>= 1x means dggs is at least as fast**.

Medians of ``--repeat`` calls, one after the other, one process.  Run::

    .venv-bench/bin/python benchmarks/bench_dissolve.py            # markdown on stdout
    .venv-bench/bin/python benchmarks/bench_dissolve.py --quick
"""

from __future__ import annotations

import argparse
import statistics
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import shapely
from shapely.geometry import box

sys.path.insert(0, str(Path(__file__).resolve().parent))

import dggs  # noqa: E402

from _common import fmt_ns, fmt_ratio, loadavg, nearest_level, print_report, run_once, try_import  # noqa: E402


def median_time(fn: Callable[[], Any], repeat: int) -> float:
    """Median wall seconds of ``repeat`` calls (after one warm-up call)."""
    fn()
    return statistics.median(run_once(fn)[0] for _ in range(repeat))


def union_table(level: int, shape: Any, repeat: int) -> list[str]:
    cells = np.asarray(dggs.polygon_to_cells(shape, level, mode="center", as_int=True), dtype=np.uint64)
    strs = dggs.int_to_str(cells)
    d = 2
    polys = dggs.cell_to_polygon(cells, densify=d)
    t_dissolve = median_time(lambda: dggs.cells_to_polygons(cells, densify=d), repeat)
    t_dissolve_str = median_time(lambda: dggs.cells_to_polygons(strs, densify=d), repeat)
    t_default = median_time(lambda: dggs.cells_to_polygons(cells), repeat)
    t_union = median_time(lambda: shapely.union_all(polys), repeat)
    t_both = median_time(lambda: shapely.union_all(dggs.cell_to_polygon(cells, densify=d)), repeat)
    n = cells.size
    rows = [
        f"### {n:,} contiguous cells at level {level} (a {shape.bounds} box)\n",
        "| case | time | per cell | union's time over this |",
        "|---|---:|---:|---:|",
        f"| `cells_to_polygons(uint64 ids, densify={d})` | {t_dissolve * 1e3:.0f} ms | {fmt_ns(t_dissolve / n)} | "
        f"{fmt_ratio(t_union / t_dissolve)} (with the polygons: {fmt_ratio(t_both / t_dissolve)}) |",
        f"| `cells_to_polygons(str ids, densify={d})` | {t_dissolve_str * 1e3:.0f} ms | {fmt_ns(t_dissolve_str / n)} | "
        f"{fmt_ratio(t_union / t_dissolve_str)} |",
        f"| `cells_to_polygons(uint64 ids)` (default points per edge) | {t_default * 1e3:.0f} ms | {fmt_ns(t_default / n)} | - |",
        f"| `shapely.union_all` of the polygons (built before, densify={d}) | {t_union * 1e3:.0f} ms | {fmt_ns(t_union / n)} | 1x |",
        f"| `cell_to_polygon` then `shapely.union_all` | {t_both * 1e3:.0f} ms | {fmt_ns(t_both / n)} | - |",
        "",
        f"Target: dissolve at least 3x faster than the union: **{'met' if t_union / t_dissolve >= 3 else 'missed'}** "
        f"({fmt_ratio(t_union / t_dissolve)}).",
    ]
    return rows


def h3_table(h3: Any, h3v: Any, res: int, k: int, repeat: int) -> list[str]:
    import pyarrow as pa

    centre = h3.latlng_to_cell(45.0, 10.0, res)
    hex_str = h3.grid_disk(centre, k)
    hex_int = np.array([h3.str_to_int(c) for c in hex_str], dtype=np.uint64)
    outline = shapely.geometry.shape(h3.cells_to_geo(hex_str))
    level = nearest_level(res, h3)
    cells = np.asarray(dggs.polygon_to_cells(outline, level, mode="center", as_int=True), dtype=np.uint64)
    strs = dggs.int_to_str(cells)
    hint = [int(c) for c in hex_int]
    t = {
        "h3 basic_int": median_time(lambda: h3.api.basic_int.cells_to_h3shape(hint), repeat) / len(hex_str),
        "h3 basic_str": median_time(lambda: h3.cells_to_h3shape(hex_str), repeat) / len(hex_str),
    }
    if h3v is not None:
        arr = pa.array(hex_int)
        t["h3ronpy"] = median_time(lambda: h3v.cells_to_wkb_polygons(arr, link_cells=True), repeat) / len(hex_str)
    d = {
        "uint64, densify=0": median_time(lambda: dggs.cells_to_polygons(cells, densify=0), repeat) / cells.size,
        "str, densify=0": median_time(lambda: dggs.cells_to_polygons(strs, densify=0), repeat) / cells.size,
        "uint64, default points": median_time(lambda: dggs.cells_to_polygons(cells), repeat) / cells.size,
    }
    rows = [f"### H3 resolution {res} ({len(hex_str):,} cells, disk k={k}) against dggs level {level} "
            f"({cells.size:,} cells, the same shape)\n",
            "| dggs case | per cell | " + " | ".join(f"{p} per cell (ratio)" for p in t) + " |",
            "|---|---:|" + "---:|" * len(t)]
    for name, td in d.items():
        rows.append(f"| `cells_to_polygons` {name} | {fmt_ns(td)} | "
                    + " | ".join(f"{fmt_ns(tp)} ({fmt_ratio(tp / td)})" for tp in t.values()) + " |")
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    repeat = 1 if args.quick else args.repeat
    load0 = loadavg()
    out = ["## cells_to_polygons (issue 21)\n",
           "`" + " ".join(["benchmarks/bench_dissolve.py", *sys.argv[1:]]) + "`, medians of "
           f"{repeat} calls after a warm-up, one process.\n"]
    shape = box(0.0, 40.0, 5.0, 45.0) if args.quick else box(0.0, 40.0, 20.0, 55.0)
    out += union_table(12, shape, repeat) + [""]
    h3 = try_import("h3")
    if h3 is not None:
        h3v = try_import("h3ronpy.vector")
        for res, k in ((5, 30 if args.quick else 100), (7, 30 if args.quick else 100)):
            out += h3_table(h3, h3v, res, k, repeat) + [""]
    print_report(out, load0)


if __name__ == "__main__":
    main()
