"""Compare libdggs's polygon.c (through a build of ``dggs._core``) with the numba kernel index/_kernel/polygon.py.

Bit for bit, on random polygons (stars with holes, several parts, polygons on a coarse lattice whose vertices
and edges random points hit exactly, thin slivers, boxes at +-180 and at the poles): ``ring_edges`` (closed and
unclosed inputs), ``build`` (frame, start, items, empty at several sides), ``parity`` and ``near`` per point
(random points, vertices, edge midpoints and 1 ulp off them, scaled x axes) and the ``classify`` batch loop.

Run with the numba package importable (the reference) and the path of the built extension::

    nice .venv/bin/python libdggs/tools/compare_polygon.py --core dggs/_core.cpython-311-x86_64-linux-gnu.so

Exit code 0 only if every output is equal.
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import os
import sys
import time

import numpy as np
import shapely

from dggs.index._kernel import polygon as kpoly  # the numba reference
from dggs.index.polyfill import _edge_index

if hasattr(kpoly, "LEAN") is False:  # pragma: no cover - the shim is installed: nothing to compare against
    sys.exit("dggs.index._kernel.polygon is not the numba kernel")


def load_core(path: str | None):
    """The built ``dggs._core`` at ``path`` (default: the one beside this worktree's dggs/), under its own name."""
    if path is None:
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        path = glob.glob(os.path.join(root, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", path)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


def same(a, b) -> bool:
    """Bitwise equality of two arrays (floats by their bits), scalars or tuples of them."""
    if isinstance(a, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return np.array_equal(a.view(np.uint64), b.view(np.uint64))
    return np.array_equal(a, b)


def polygons(rng: np.random.Generator, count: int) -> list:
    """Random valid (Multi)Polygons in lng/lat."""
    out = []
    for k in range(count):
        kind = k % 6
        if kind == 0:  # a star, maybe with a hole
            n = int(rng.integers(3, 600))
            cx, cy = rng.uniform(-150, 150), rng.uniform(-60, 60)
            t = np.sort(rng.uniform(0, 2 * np.pi, n))
            rad = rng.uniform(2, 10, n)
            hole = [np.c_[cx + 0.8 * np.cos(np.linspace(0, 6, 9)), cy + 0.8 * np.sin(np.linspace(0, 6, 9))]]
            geom = shapely.Polygon(np.c_[cx + rad * np.cos(t), cy + rad * np.sin(t)], hole if rng.random() < 0.5 else None)
        elif kind == 1:  # convex hulls on a lattice: exact edges, lattice points on them
            parts = []
            for _ in range(int(rng.integers(1, 4))):
                x0, y0 = rng.integers(-170, 160), rng.integers(-80, 70)
                pts = np.c_[x0 + rng.integers(0, 12, 8), y0 + rng.integers(0, 12, 8)].astype(float)
                parts.append(shapely.convex_hull(shapely.multipoints(pts)))
            geom = shapely.union_all([p for p in parts if p.geom_type == "Polygon"] or [shapely.box(0, 0, 1, 1)])
        elif kind == 2:  # a donut and touching boxes
            c = rng.uniform(-100, 100, 2)
            geom = shapely.union_all([shapely.Point(*c).buffer(rng.uniform(2, 20)).difference(shapely.Point(*c).buffer(1)),
                                      shapely.box(c[0] + 30, 0, c[0] + 31, 1), shapely.box(c[0] + 31, 1, c[0] + 32, 2)])
        elif kind == 3:  # a sliver
            x = rng.uniform(-170, 170)
            geom = shapely.Polygon([(x, -60), (x + 1e-7, -60), (x + 2e-7, 70), (x, 70)])
        elif kind == 4:  # boxes at the antimeridian and the poles
            geom = shapely.union_all([shapely.box(170, -10, 180, 10), shapely.box(-180, -10, -170, 10),
                                      shapely.box(-180, 80, 180, 90), shapely.box(-180, -90, 180, -85)])
        else:  # a large random blob
            geom = shapely.Point(rng.uniform(-120, 120), rng.uniform(-40, 40)).buffer(rng.uniform(20, 60), 64)
        geom = shapely.make_valid(geom)
        if geom.geom_type in ("Polygon", "MultiPolygon") and not geom.is_empty:
            out.append(geom)
    return out


def main() -> int:
    """Run the comparison; print the counts; 0 if every output is equal."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--core", help="path of the built dggs._core extension")
    ap.add_argument("--polygons", type=int, default=120)
    ap.add_argument("--points", type=int, default=9000, help="points per polygon for parity and near")
    ap.add_argument("--seed", type=int, default=20240531)
    args = ap.parse_args()
    core = load_core(args.core)
    rng = np.random.default_rng(args.seed)
    counts = dict.fromkeys(("ring_edges", "build", "parity", "near", "classify"), 0)
    bad = dict.fromkeys(counts, 0)
    t0 = time.time()
    for poly in polygons(rng, args.polygons):
        xy = shapely.get_coordinates(poly)
        for arr in (xy, xy[:-1], xy[: max(1, len(xy) // 2)], np.zeros((0, 2))):  # closed, and not
            counts["ring_edges"] += 1
            bad["ring_edges"] += not same(kpoly.ring_edges(arr), core.polygon_ring_edges(arr))
        grid = _edge_index(poly)
        x0, y0, x1, y1 = grid[:4]
        for side in {1, 2, 7, int(grid[4][4]), 1024}:
            counts["build"] += 1
            bad["build"] += not same(kpoly.build(x0, y0, x1, y1, side), core.polygon_build(x0, y0, x1, y1, side))
        minx, miny, maxx, maxy = poly.bounds
        m = args.points
        mids = np.c_[(x0 + x1) / 2, (y0 + y1) / 2]
        lattice = np.c_[rng.integers(int(np.floor(minx)) - 1, int(np.ceil(maxx)) + 2, m // 6),
                        rng.integers(int(np.floor(miny)) - 1, int(np.ceil(maxy)) + 2, m // 6)].astype(float)
        pts = np.r_[np.c_[rng.uniform(minx - 1, maxx + 1, m), rng.uniform(miny - 1, maxy + 1, m)], lattice, mids,
                    np.nextafter(mids, np.inf), np.nextafter(mids, -np.inf), np.c_[x0, y0]][: 2 * m]
        r = np.where(rng.random(pts.shape[0]) < 0.2, 0.0, 10.0 ** rng.uniform(-6, 1, pts.shape[0]))
        sx = np.where(rng.random(pts.shape[0]) < 0.5, 1.0, 10.0 ** rng.uniform(-1, 1, pts.shape[0]))
        want_p = np.array([kpoly.parity(px, py, *grid) for px, py in pts.tolist()])
        got_p = np.array([core.polygon_parity(px, py, *grid) for px, py in pts.tolist()])
        counts["parity"] += pts.shape[0]
        bad["parity"] += int((want_p != got_p).sum())
        args7 = grid[:7]
        circles = list(zip(pts.tolist(), r.tolist(), sx.tolist(), strict=True))
        want_n = np.array([kpoly.near(px, py, rr, s, *args7) for (px, py), rr, s in circles])
        got_n = np.array([core.polygon_near(px, py, rr, s, *args7) for (px, py), rr, s in circles])
        counts["near"] += pts.shape[0]
        bad["near"] += int((want_n != got_n).sum())
        for rep in range(4):  # the batch loop: small (serial) and large inputs
            k = 200 if rep == 0 else 40_000
            qx = np.ascontiguousarray(rng.uniform(minx - 2, maxx + 2, k))
            qy = np.ascontiguousarray(rng.uniform(miny - 2, maxy + 2, k))
            qr = np.ascontiguousarray(np.where(rng.random(k) < 0.1, 0.0, 10.0 ** rng.uniform(-4, 0.5, k)))
            h1, i1 = np.zeros(k, dtype=bool), np.zeros(k, dtype=bool)
            h2, i2 = np.zeros(k, dtype=bool), np.zeros(k, dtype=bool)
            kpoly.classify(k, qx, qy, qr, *grid, h1, i1)
            core.polygon_classify(k, qx, qy, qr, *grid, h2, i2)
            counts["classify"] += k
            bad["classify"] += int((h1 != h2).sum() + (i1 != i2).sum())
    for k in counts:
        print(f"{k:>10}: {counts[k]:>10,} compared, {bad[k]:,} different")
    ok = not any(bad.values())
    print(f"polygon.c {'IDENTICAL' if ok else 'DIFFERENT'} to the numba kernel ({time.time() - t0:.0f} s)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
