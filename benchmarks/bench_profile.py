"""Where the time goes in issue 18's missed targets: point location, single calls and polygon output, in parts.

One thread (run it with DGGS_THREADS=1; run_all does), CPU
time (``time.process_time``), medians of interleaved rounds after a warm-up
(``_common.interleaved``).  Each table splits one missed operation into parts
that can be timed apart through public entry points and plain baselines:

1. Point to cell on 1M random points: numpy's four trigonometric functions of
   the points alone (the libm floor of any projection), dggs at level 0 (unit
   vector, authalic latitude, face, Snyder's forward: everything but the
   descent), at levels 10 and 17, and healpy's ``ang2pix(nest=True)``.
2. One call from a Python loop: a Python function returning its argument,
   the compiled core's single-id entry (``parent_of``), Python's own bit
   operations, h3-py's and dggs's ``cell_to_parent`` on int ids.
3. Polygons of 100,000 level-17 cells: the compiled boundary alone
   (``cell_to_boundary``), shapely building polygons from it, and
   ``cell_to_polygon`` at ``densify=0`` and at its default.
Prints one Markdown section.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import _common as c  # noqa: E402
from _common import fmt_ns, loadavg  # noqa: E402


def _loop(fn: Any, items: list[Any]) -> Any:
    def run() -> int:
        for x in items:
            fn(x)
        return len(items)

    return run


def point_table(n: int, rounds: int) -> dict[str, Any]:
    import dggs

    lat, lng = c.points(n)
    healpy = c.try_import("healpy")

    def trig() -> None:
        p, lam = np.radians(lat), np.radians(lng)
        np.sin(p), np.cos(p), np.sin(lam), np.cos(lam)

    cases: dict[str, Any] = {"numpy sin, cos of lat and lng (4 ufuncs)": (trig, lambda _: n)}
    for level in (0, 10, 17):
        cases[f"dggs latlng_to_cell, level {level}"] = (
            lambda lv=level: dggs.latlng_to_cell(lat, lng, lv, as_int=True), lambda _: n)
    if healpy is not None:
        nside = 2**13  # 0.0621 km2 a pixel: the nearest power of two to level 17's 0.099 km2
        theta, phi = np.radians(90.0 - lat), np.radians(lng)
        cases["healpy ang2pix(nest=True), nside 8192"] = (lambda: healpy.ang2pix(nside, theta, phi, nest=True),
                                                          lambda _: n)
    for f, _ in cases.values():
        f()
    return c.interleaved(cases, rounds, 300.0)


def call_table(n: int, rounds: int) -> dict[str, Any]:
    import dggs
    from dggs.index._kernel import hierarchy as kh

    h3 = c.try_import("h3")
    cells = [int(x) for x in dggs.latlng_to_cell(*c.points(n), 17, as_int=True)]

    mask = (1 << 64) - 1 - 3

    cases: dict[str, Any] = {
        "Python function returning its argument": (_loop(lambda x: x, cells), n),
        "the core's single-id entry (dggs._core parent_of(int, -1))": (_loop(lambda x: kh.parent_of(x, -1), cells), n),
        "Python bit operations on the int (a mask, an or)": (_loop(lambda x: (x & mask) | 1, cells), n),
        "dggs.cell_to_parent(int)": (_loop(dggs.cell_to_parent, cells), n),
    }
    if h3 is not None:
        h3cells = [h3.str_to_int(h3.latlng_to_cell(la, ln, 9)) for la, ln in zip(*c.points(n), strict=True)]
        cases["h3.cell_to_parent(int) (h3-py's int API)"] = (_loop(h3.api.basic_int.cell_to_parent, h3cells), n)
    for f, _ in cases.values():
        f()
    return c.interleaved(cases, rounds, 120.0)


def polygon_table(n: int, rounds: int) -> dict[str, Any]:
    import shapely

    import dggs

    cells = dggs.latlng_to_cell(*c.points(n), 17, as_int=True)

    def shapely_only(corners: np.ndarray) -> Any:
        ring = np.concatenate([corners, corners[:, :1]], axis=1)[..., ::-1]  # (lat, lng) -> (x, y), closed
        return shapely.polygons(shapely.linearrings(ring))

    corners = dggs.cell_to_boundary(cells)
    cases: dict[str, Any] = {
        "cell_to_boundary (the compiled corners)": (lambda: dggs.cell_to_boundary(cells), lambda _: n),
        "shapely.polygons of those corners": (lambda: shapely_only(corners), lambda _: n),
        "cell_to_polygon(densify=0)": (lambda: dggs.cell_to_polygon(cells, densify=0), lambda _: n),
        "cell_to_polygon (default densify)": (lambda: dggs.cell_to_polygon(cells), lambda _: n),
    }
    for f, _ in cases.values():
        f()
    return c.interleaved(cases, rounds, 120.0)


def render(tables: list[tuple[str, dict[str, Any]]], load: list[list[float]], code: dict[str, Any]) -> str:
    out = ["### Where the time goes: issue 18's misses in parts (bench_profile.py)\n",
           f"One thread, CPU time per point, call or cell; medians of interleaved rounds. {c.describe_code(code)}; "
           f"1-minute load average {load[0][0]:.2f} at the start, {load[1][0]:.2f} at the end.\n"]
    for title, times in tables:
        out.append(f"#### {title}\n\n| part | CPU per unit |\n|---|---:|")
        for name, t in times.items():
            out.append(f"| {name} | {fmt_ns(t['cpu'] / t['units']) if t and t.get('units') else '-'} |")
        out.append("")
    out.append(c.notes_section())
    return "\n".join(out) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes, 1 round (a smoke test)")
    args = ap.parse_args()
    n_points, n_calls, n_cells, rounds = (20_000, 2_000, 5_000, 1) if args.quick else (1_000_000, 20_000, 100_000, 3)
    code, load0 = c.code_state(), loadavg()
    tables = [
        (f"Point to cell, {n_points:,} random points", point_table(n_points, rounds)),
        (f"One call from a Python loop, {n_calls:,} level-17 cells (h3: res 9)", call_table(n_calls, rounds)),
        (f"Polygons of {n_cells:,} level-17 cells", polygon_table(n_cells, rounds)),
    ]
    print(render(tables, [load0, loadavg()], code))


if __name__ == "__main__":
    main()
