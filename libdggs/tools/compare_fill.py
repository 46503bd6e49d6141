"""Compare libdggs's fill.c (through a build of ``dggs._core``) with the numba kernels fill.py and ivea_fill.py.

Bit for bit: polygon_to_cells' kernel outputs, ``descend``'s (ids, flags, n, status, cand, insides, tested,
classified), on random polygons (small and large, with holes, in several parts, across the antimeridian, round
and near the poles, slivers), in both descent modes (``center``, and the boundary-cell mode of ``contains`` /
``overlaps``), at levels 0-15, ``direct`` 0-2, limits large and small (TOO_MANY), on ISEA and IVEA, each polygon
prepared exactly as polyfill._fill does (_wrap_polygon, _edge_index); ``first_over`` on each result; and
``centre``, ``footprint``, ``ellipse`` on random cells' planar corners at levels 0-28 (and on poles, face
vertices and the antimeridian), both projections.

Run with the numba package importable (the reference) and the path of the built extension::

    nice .venv/bin/python libdggs/tools/compare_fill.py --core dggs/_core.cpython-311-x86_64-linux-gnu.so

Exit code 0 only if every output is equal.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import numpy as np
import shapely

import dggs
from dggs.index._kernel import fill as kfill  # the numba reference
from dggs.index._kernel import ivea_fill
from dggs.index._kernel import points as kp
from dggs.index.polyfill import _DIRECT, _NO_GRID, _edge_index, _wrap_polygon

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from compare_polygon import load_core, same  # noqa: E402 - this folder's helper

if not hasattr(kfill, "_walk"):  # pragma: no cover - the shim is installed: nothing to compare against
    sys.exit("dggs.index._kernel.fill is not the numba kernel")

#: km^2 of the globe (authalic sphere) and of a level-l cell.
_GLOBE = 510_065_621.7


def cell_km2(level: int) -> float:
    """Area of one level-``level`` cell (20 faces, 6 level-1 triangles each, then 3 children a level)."""
    return _GLOBE / 20 if level == 0 else _GLOBE / (120 * 3 ** (level - 1))


def polygons(rng: np.random.Generator, count: int) -> list:
    """Random (Multi)Polygons in lng/lat, some with longitudes past 180 (the verb wraps them)."""
    out = []
    for k in range(count):
        kind = k % 8
        if kind == 0:  # a star of any size
            n = int(rng.integers(3, 300))
            cx, cy = rng.uniform(-180, 180), rng.uniform(-70, 70)
            size = 10.0 ** rng.uniform(-2.5, 1.6)
            t = np.sort(rng.uniform(0, 2 * np.pi, n))
            rad = size * rng.uniform(0.3, 1.0, n)
            geom = shapely.Polygon(np.c_[cx + rad * np.cos(t), np.clip(cy + rad * np.sin(t), -90, 90)])
        elif kind == 1:  # a disc with a hole
            c = (rng.uniform(-170, 170), rng.uniform(-60, 60))
            r = 10.0 ** rng.uniform(-1.5, 1.3)
            geom = shapely.Point(*c).buffer(r).difference(shapely.Point(c[0] + 0.2 * r, c[1]).buffer(0.4 * r))
        elif kind == 2:  # across the antimeridian, given past 180
            x = rng.uniform(170, 179.9)
            w = 10.0 ** rng.uniform(-1, 1.3)
            y = rng.uniform(-60, 50)
            geom = shapely.box(x, y, x + w, y + rng.uniform(0.5, 15))
        elif kind == 3:  # across the antimeridian, split at 180 in two parts
            y = rng.uniform(-70, 60)
            h = rng.uniform(0.2, 10)
            geom = shapely.MultiPolygon([shapely.box(rng.uniform(160, 179.5), y, 180, y + h),
                                         shapely.box(-180, y, rng.uniform(-179.5, -160), y + h)])
        elif kind == 4:  # round a pole
            lat = rng.uniform(60, 89.5)
            geom = shapely.box(-180, lat, 180, 90) if rng.random() < 0.5 else shapely.box(-180, -90, 180, -lat)
        elif kind == 5:  # near a pole, not round it
            c = (rng.uniform(-180, 180), rng.uniform(80, 88) * (1 if rng.random() < 0.5 else -1))
            geom = shapely.Point(*c).buffer(rng.uniform(0.5, 2.0))
        elif kind == 6:  # several parts
            parts = [shapely.Point(rng.uniform(-170, 170), rng.uniform(-70, 70)).buffer(10.0 ** rng.uniform(-1.5, 1))
                     for _ in range(int(rng.integers(2, 5)))]
            geom = shapely.union_all(parts)
        else:  # a sliver along a meridian
            x = rng.uniform(-179, 179)
            geom = shapely.Polygon([(x, -50), (x + 1e-3, -50), (x + 2e-3, 60), (x, 60)])
        geom = shapely.make_valid(geom)
        if geom.geom_type in ("Polygon", "MultiPolygon") and not geom.is_empty:
            out.append(geom)
    return out


def pick_level(poly, rng: np.random.Generator, most: int) -> int:
    """A random level at which the polygon holds at most about ``most`` cells."""
    minx, miny, maxx, maxy = poly.bounds
    km2 = poly.area * 12_364.0 * max(0.05, math.cos(math.radians(0.5 * (miny + maxy))))
    top = 0
    while top < 15 and km2 / cell_km2(top + 1) < most:
        top += 1
    return int(rng.integers(max(0, top - 4), top + 1))


def prepared(poly):
    """polyfill._fill's preparation: the wrapped target and its edge grid."""
    target = _wrap_polygon(poly)
    return (_edge_index(target) or _NO_GRID), poly.bounds[1], poly.bounds[3]


def compare_descend(core, rng, n_polygons: int, most: int) -> tuple[dict, dict]:
    """Compare ``descend`` and ``first_over`` on random polygons."""
    counts = {"descend calls": 0, "cells found": 0, "cells tested": 0, "cells classified": 0, "too_many": 0,
              "first_over": 0}
    bad = {"descend": 0, "first_over": 0}
    pairs = ((kfill.descend, core.fill_descend), (ivea_fill.descend, core.ivea_fill_descend))
    for poly in polygons(rng, n_polygons):
        grid, miny, maxy = prepared(poly)
        level = pick_level(poly, rng, most)
        for center in (True, False):
            direct = _DIRECT if rng.random() < 0.7 else int(rng.integers(0, 3))
            for proj, (ref, mine) in enumerate(pairs):
                for limit in (50_000_000, int(rng.integers(0, 400))):
                    want = ref(level, center, direct, *grid, miny, maxy, limit)
                    got = mine(level, center, direct, *grid, miny, maxy, limit)
                    n = int(want[2])
                    ok = (int(got[2]) == n and same(want[0][:n], got[0][:n]) and same(want[1][:n], got[1][:n])
                          and int(want[3]) == int(got[3]) and same(want[4], got[4]) and same(want[5], got[5])
                          and int(want[6]) == int(got[6]) and int(want[7]) == int(got[7]))
                    if not ok:
                        bad["descend"] += 1
                        print(f"DIFFERENT: level {level} center {center} direct {direct} proj {proj} limit {limit} "
                              f"{poly.wkt[:200]}", file=sys.stderr)
                    counts["descend calls"] += 1
                    counts["cells found"] += n
                    counts["cells tested"] += int(want[6])
                    counts["cells classified"] += int(want[7])
                    counts["too_many"] += int(want[3]) == kfill.TOO_MANY
                    last = max(level - direct, 0) if center else level
                    for lim in (limit, 0, int(rng.integers(0, 10_000)), n):
                        counts["first_over"] += 1
                        a = kfill.first_over(want[4], want[5], int(want[6]), last, center, lim)
                        b = core.fill_first_over(want[4], want[5], int(want[6]), last, center, lim)
                        bad["first_over"] += int(a) != int(b)
    return counts, bad


def special_cells() -> np.ndarray:
    """Cells at the poles, the antimeridian, face vertices and centres, at every level."""
    lat = [90.0, -90.0, 89.999999, -89.999999, 0.0, 0.0, 58.2825255885, -58.2825255885, 26.565051177, 10.0]
    lng = [0.0, 0.0, 123.0, -45.0, 180.0, -180.0, 11.25, -168.75, 47.25, 179.9999999]
    out = []
    for level in range(29):
        out.append(dggs.latlng_to_cell(np.array(lat), np.array(lng), level, as_int=True))
    return np.unique(np.concatenate(out))


def compare_points(core, rng, n_cells: int) -> tuple[dict, dict]:
    """centre, footprint and ellipse on random cells' planar corners, every level, both projections."""
    counts = {"centre/footprint corners": 0, "ellipse": 0}
    bad = {"centre": 0, "footprint": 0, "ellipse": 0}
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n_cells)))
    lng = rng.uniform(-180, 180, n_cells)
    levels = rng.integers(0, 29, n_cells)
    cells = np.concatenate([dggs.latlng_to_cell(lat[levels == lv], lng[levels == lv], lv, as_int=True)
                            for lv in range(29)] + [special_cells()])
    pairs = ((kfill.centre, core.fill_centre, kfill.footprint, core.fill_footprint),
             (ivea_fill.centre, core.ivea_fill_centre, ivea_fill.footprint, core.ivea_fill_footprint))
    for cell in cells:
        face, ax, ay, bx, by, cx, cy = kp.triangle(cell)
        lv = dggs.get_level(int(cell))
        t = (int(face), lv, ax, ay, bx, by, cx, cy)
        for ref_c, mine_c, ref_f, mine_f in pairs:
            counts["centre/footprint corners"] += 1
            bad["centre"] += not same(tuple(np.float64(v) for v in ref_c(*t)), tuple(np.float64(v) for v in mine_c(*t)))
            f = ref_f(*t)
            bad["footprint"] += not same(tuple(np.float64(v) for v in f), tuple(np.float64(v) for v in mine_f(*t)))
            for u in (f[2:], tuple(rng.normal(size=3)), (0.0, 0.0, 1.0), (1e-300, 0.0, -1.0)):
                counts["ellipse"] += 1
                want = kfill.ellipse(lv, *u)
                bad["ellipse"] += not same(tuple(np.float64(v) for v in want),
                                           tuple(np.float64(v) for v in core.fill_ellipse(lv, *u)))
    return counts, bad


def main() -> int:
    """Run the comparison; print the counts; 0 if every output is equal."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--core", help="path of the built dggs._core extension")
    ap.add_argument("--polygons", type=int, default=400)
    ap.add_argument("--most", type=int, default=100_000, help="about the most cells a polygon's level holds")
    ap.add_argument("--cells", type=int, default=200_000, help="random cells for centre, footprint, ellipse")
    ap.add_argument("--seed", type=int, default=31)
    args = ap.parse_args()
    core = load_core(args.core)
    rng = np.random.default_rng(args.seed)
    t0 = time.time()
    c1, b1 = compare_descend(core, rng, args.polygons, args.most)
    c2, b2 = compare_points(core, rng, args.cells)
    for k, v in {**c1, **c2}.items():
        print(f"{k:>26}: {v:>12,}")
    for k, v in {**b1, **b2}.items():
        print(f"{k + ' different':>26}: {v:>12,}")
    ok = not any({**b1, **b2}.values())
    print(f"fill.c {'IDENTICAL' if ok else 'DIFFERENT'} to the numba kernels ({time.time() - t0:.0f} s)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
