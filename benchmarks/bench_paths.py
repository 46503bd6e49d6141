"""Benchmark grid_path_cells and line_to_cells per output cell against h3-py and h3ronpy (issue 21).

- **grid_path_cells**: pairs of cells about ``--km`` apart (random starts
  uniform on the sphere, random directions, ``pyproj.Geod``), dggs at the level
  nearest H3's resolution by cell area.  dggs takes all pairs in one call
  (uint64 arrays, or lists of strings); h3-py takes one pair a call
  (``h3.api.basic_int`` and ``basic_str``), as its API does.  Pairs h3 cannot
  join ("Couldn't find line") are left out of both.
- **line_to_cells**: random polylines of ``--vertices`` points ``--km`` apart.
  dggs follows each segment's WGS84 geodesic; h3ronpy's
  ``geometry_to_cells`` traces the LineString (h3o), and h3-py's
  ``grid_path_cells`` between the cells of consecutive vertices stands in for
  a line function h3-py does not have.

The time is per output cell (each side's own count); the ratio is the peer's
time per cell over dggs's, so **>= 1x means dggs is at least as fast**.

Run::

    .venv-bench/bin/python benchmarks/bench_paths.py            # markdown on stdout
    .venv-bench/bin/python benchmarks/bench_paths.py --quick
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import dggs  # noqa: E402

from _common import SEED, fmt_ns, fmt_ratio, interleaved, loadavg, nearest_level, points, print_report, try_import  # noqa: E402

H3_RES = (7, 9)


def pairs(n: int, km: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``n`` random starts on the sphere and ends ``km`` away in random directions."""
    import pyproj

    lat, lng = points(n)
    az = np.random.default_rng(SEED + 1).uniform(-180.0, 180.0, n)
    lng2, lat2, _ = pyproj.Geod(ellps="WGS84").fwd(lng, lat, az, np.full(n, km * 1000.0))
    return lat, lng, np.asarray(lat2), np.asarray(lng2)


def polylines(count: int, vertices: int, km: float) -> list[np.ndarray]:
    """Random walks of ``vertices`` (lat, lng) points, ``km`` between consecutive ones."""
    import pyproj

    geod = pyproj.Geod(ellps="WGS84")
    lat, lng = points(count, SEED + 2)
    rng = np.random.default_rng(SEED + 3)
    out = []
    for la, lo in zip(lat, lng, strict=True):
        pts = [(float(la), float(lo))]
        heading = rng.uniform(-180, 180)
        for _ in range(vertices - 1):
            heading += rng.uniform(-30, 30)
            lo2, la2, _ = geod.fwd(pts[-1][1], pts[-1][0], heading, km * 1000.0)
            pts.append((float(la2), float(lo2)))
        out.append(np.array(pts))
    return out


def path_table(h3: Any, res: int, n: int, km: float, repeat: int) -> list[str]:
    level = nearest_level(res, h3)
    lat, lng, lat2, lng2 = pairs(n, km)
    hb = h3.api.basic_int
    ha = [hb.latlng_to_cell(float(y), float(x), res) for y, x in zip(lat, lng, strict=True)]
    hz = [hb.latlng_to_cell(float(y), float(x), res) for y, x in zip(lat2, lng2, strict=True)]
    ok = []
    for i, (x, y) in enumerate(zip(ha, hz, strict=True)):
        try:
            hb.grid_path_cells(x, y)
            ok.append(i)
        except Exception:  # h3 cannot join some pairs (across icosahedron faces)
            pass
    keep = np.array(ok, dtype=np.int64)
    ha, hz = [ha[i] for i in ok], [hz[i] for i in ok]
    hs, hzs = [h3.int_to_str(x) for x in ha], [h3.int_to_str(x) for x in hz]
    da = dggs.latlng_to_cell(lat[keep], lng[keep], level, as_int=True)
    dz = dggs.latlng_to_cell(lat2[keep], lng2[keep], level, as_int=True)
    sa, sz = dggs.int_to_str(da).tolist(), dggs.int_to_str(dz).tolist()

    def count(paths: list[Any]) -> int:
        return sum(len(p) for p in paths)

    cases = {
        "dggs int (uint64 arrays)": (lambda: dggs.grid_path_cells(da, dz), count),
        "dggs str (lists)": (lambda: dggs.grid_path_cells(sa, sz), count),
        "h3-py int (a pair a call)": (lambda: [hb.grid_path_cells(x, y) for x, y in zip(ha, hz, strict=True)], count),
        "h3-py str (a pair a call)": (lambda: [h3.grid_path_cells(x, y) for x, y in zip(hs, hzs, strict=True)], count),
    }
    res_ = interleaved(cases, repeat, budget=60.0)
    base = res_.get("dggs int (uint64 arrays)")
    rows = [f"### grid_path_cells: H3 res {res} vs dggs level {level}, {len(ok):,} pairs ~{km:g} km apart "
            f"({n - len(ok)} pairs h3 could not join left out)\n",
            "| implementation | output cells | per cell | dggs int faster by |", "|---|---:|---:|---:|"]
    for key, r in res_.items():
        per = r["wall"] / max(r["units"], 1)
        ratio = per / (base["wall"] / base["units"]) if base else None
        rows.append(f"| {key} | {r['units']:,} | {fmt_ns(per)} | {fmt_ratio(ratio)} |")
    sres = res_.get("dggs str (lists)")
    if sres and "h3-py str (a pair a call)" in res_:
        hsr = res_["h3-py str (a pair a call)"]
        rows.append(f"\nString ids against string ids: dggs is {fmt_ratio((hsr['wall'] / hsr['units']) / (sres['wall'] / sres['units']))} "
                    "as fast per cell.")
    return rows


def line_table(h3: Any, h3v: Any, res: int, count: int, vertices: int, km: float, repeat: int) -> list[str]:
    import shapely

    level = nearest_level(res, h3)
    lines = polylines(count, vertices, km)
    shapes = [shapely.LineString(p[:, ::-1]) for p in lines]
    hb = h3.api.basic_int

    def h3_paths() -> list[int]:
        out: list[int] = []
        for p in lines:
            cells = [hb.latlng_to_cell(float(y), float(x), res) for y, x in p]
            for a, b in zip(cells[:-1], cells[1:], strict=True):
                try:
                    out.extend(hb.grid_path_cells(a, b)[1:])
                except Exception:
                    pass
        return out

    cases: dict[str, tuple[Any, ...]] = {
        "dggs line_to_cells (uint64)": (lambda: [dggs.line_to_cells(p, level, as_int=True) for p in lines], lambda r: sum(len(x) for x in r)),
        "h3-py grid_path_cells between vertices": (h3_paths, len),
    }
    if h3v is not None:
        cases["h3ronpy geometry_to_cells (LineString)"] = (lambda: [h3v.geometry_to_cells(s, res) for s in shapes],
                                                            lambda r: sum(len(x) for x in r))
    res_ = interleaved(cases, repeat, budget=60.0)
    base = res_.get("dggs line_to_cells (uint64)")
    rows = [f"### line_to_cells: H3 res {res} vs dggs level {level}, {count} polylines of {vertices} points ~{km:g} km apart\n",
            "| implementation | output cells | per cell | dggs faster by |", "|---|---:|---:|---:|"]
    for key, r in res_.items():
        per = r["wall"] / max(r["units"], 1)
        ratio = per / (base["wall"] / base["units"]) if base else None
        rows.append(f"| {key} | {r['units']:,} | {fmt_ns(per)} | {fmt_ratio(ratio)} |")
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--pairs", type=int, default=5000)
    ap.add_argument("--km", type=float, default=20.0)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    n, repeat = (500, 1) if args.quick else (args.pairs, args.repeat)
    h3 = try_import("h3")
    if h3 is None:
        print("## grid_path_cells and line_to_cells (issue 21)\n\nh3 is not installed: nothing to compare.")
        return
    h3v = try_import("h3ronpy.vector")
    load0 = loadavg()
    out = ["## grid_path_cells and line_to_cells (issue 21)\n",
           "Time per output cell, one process; the last column is the peer's time per cell over dggs's "
           "(**>= 1x: dggs at least as fast**). `" + " ".join(["benchmarks/bench_paths.py", *sys.argv[1:]]) + "`.\n"]
    for res in H3_RES:
        km = args.km * (3.0 if res == 7 else 1.0)
        out += path_table(h3, res, n, km, repeat) + [""]
    for res in H3_RES:
        km = args.km * (3.0 if res == 7 else 1.0)
        out += line_table(h3, h3v, res, 20 if args.quick else 100, 20, km, repeat) + [""]
    print_report(out, load0)


if __name__ == "__main__":
    main()
