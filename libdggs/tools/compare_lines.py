"""Compare the C line tracer (dggs._core, and libdggs's public dggs_line_to_cells) with the numba kernel, bit for bit.

Run with the package's Python, from anywhere (the numba reference is the installed package; the C binding is
loaded by path from this worktree's build):
    python libdggs/tools/compare_lines.py [--so dggs/_core....so] [--lib build/libdggs/libdggs.so] [--scale 1.0]

Compared (floats as their bits, ids and their order exactly; both projections throughout):
- cells_at (line_trace._sample, the tracer's point location: ECEF, Bowring's foot, the authalic series, the
  face search from a hint, the face projection, encode_point), lone and chained, on random points and the
  special ones (poles, +-180, icosahedron vertices, face-edge midpoints, 1e-12 off them), levels 0..28;
- interpolate (the Hermite spans and the return to the surface) on the anchors of random lines;
- ecef, tangent, geodetic; chord's dist_to_segment, corners6, crosses, clear, corner_clear on random cells
  and samples near their shared edges and corners; clean and layout on random polylines;
- trace (ISEA and IVEA, with and without the shortcut, and a full output buffer) on random polylines: long
  ones (10,000+ km), lines along cell edges and icosahedron edges, through vertices and over the poles,
  across the antimeridian, levels 0..20: the cells, their number, the corner gaps;
- dggs_line_to_cells (the C library, through ctypes, with PROJ's geod_inverse / geod_direct from pyproj's own
  libproj) against dggs.line_to_cells, with its grow protocol exercised.
Exit code 0 only if everything is equal.
"""

from __future__ import annotations

import argparse
import ctypes
import glob
import importlib.util
import math
import os
import sys
import time

import numpy as np
import pyproj
from numba import njit

from dggs.geometry.icosahedron import ISEA
from dggs.index import paths
from dggs.index._kernel import chord as kchord
from dggs.index._kernel import grid as kgrid
from dggs.index._kernel import ivea_lines as kivea
from dggs.index._kernel import line_layout as klayout
from dggs.index._kernel import line_trace as kline

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
FAILS: list[str] = []
COUNTS: dict[str, int] = {}


def load_core(path: str | None):
    """The worktree's dggs._core, loaded by path under its real name."""
    so = path or glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def same(name: str, a, b, n: int | None = None) -> None:
    """Record a comparison: arrays (floats by their bits) or plain values equal, n items counted."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind == "f":
        a = a.astype(np.float64).view(np.uint64)
    if b.dtype.kind == "f":
        b = b.astype(np.float64).view(np.uint64)
    ok = a.shape == b.shape and np.array_equal(a, b)
    COUNTS[name] = COUNTS.get(name, 0) + (n if n is not None else max(1, a.size))
    if not ok:
        FAILS.append(name)
        if len(FAILS) <= 20:
            bad = "shape" if a.shape != b.shape else int(np.flatnonzero(a.reshape(-1) != b.reshape(-1))[0])
            print(f"MISMATCH {name}: first at {bad}", file=sys.stderr)


# ---- inputs ----


def special_points() -> np.ndarray:
    """Poles, the antimeridian, the icosahedron's vertices and face-edge midpoints (geodetic), and 1e-12 off them."""
    from dggs.geometry.authalic import WGS84

    geo = ISEA.geometry
    pts = [
        (90.0, 0.0),
        (-90.0, 0.0),
        (0.0, 180.0),
        (0.0, -180.0),
        (45.0, 180.0),
        (-45.0, -180.0),
        (89.999999, 37.0),
        (-89.9999999999, -123.0),
        (12.5, 179.9999999999),
        (-33.0, -179.99999999),
    ]
    verts = geo.vertices
    vs = list(verts)
    for f in range(20):
        for k in range(3):
            m = verts[geo.face_vertices[f, k]] + verts[geo.face_vertices[f, (k + 1) % 3]]
            vs.append(m / np.linalg.norm(m))
    for v in vs:
        beta = math.asin(max(-1.0, min(1.0, float(v[2]))))
        lat = float(WGS84.authalic_to_geodetic_deg(math.degrees(beta)))
        pts.append((max(-90.0, min(90.0, lat)), math.degrees(math.atan2(float(v[1]), float(v[0])))))
    base = np.array(pts)
    off = [base]
    for d in (1e-12, -1e-12, 1e-9):
        off.append(np.column_stack([np.clip(base[:, 0] + d, -90, 90), base[:, 1] - d]))
    return np.concatenate(off)


def random_points(rng, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Uniform points on the sphere, a tenth of them on whole and half degrees."""
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    k = n // 10  # some on whole and half degrees (ties in the planar tests)
    lat[:k] = np.round(lat[:k] * 2) / 2
    lng[:k] = np.round(lng[:k] * 2) / 2
    return lat, lng


def fwd(lat: float, lng: float, az: float, dist: float) -> tuple[float, float]:
    """The direct geodesic (pyproj's): the point ``dist`` metres from (lat, lng) at azimuth ``az``."""
    lo, la, _ = GEOD.fwd(lng, lat, az, dist)
    return float(la), float(lo)


GEOD = pyproj.Geod(ellps="WGS84")


def random_line(rng, long: bool = False) -> np.ndarray:
    """A polyline of 2-4 points from a random or special start, segments of 1 m .. 12,000 km (10,000+ with long)."""
    if rng.random() < 0.3:
        sp = SPECIAL[rng.integers(SPECIAL.shape[0])]
        lat, lng = float(sp[0]), float(sp[1])
    else:
        lat, lng = (float(v[0]) for v in random_points(rng, 1))
    pts = [(lat, lng)]
    for _ in range(int(rng.integers(1, 4))):
        dist = rng.uniform(10_000_000, 15_000_000) if long else 10.0 ** rng.uniform(0, 7.08)
        lat, lng = fwd(lat, lng, rng.uniform(-180, 180), dist)
        pts.append((lat, lng))
    return np.array(pts)


def shaped_lines(rng) -> list[tuple[str, np.ndarray, list[int]]]:
    """Lines along cell edges and icosahedron edges, through vertices, over the poles, across the antimeridian."""
    import dggs

    out: list[tuple[str, np.ndarray, list[int]]] = []
    geo = ISEA.geometry
    sp = SPECIAL[: 10 + 12 + 60]
    verts = sp[10:22]
    for f in range(20):  # along icosahedron edges, vertex to vertex and midpoint to vertex
        a, b = geo.face_vertices[f, 0], geo.face_vertices[f, 1]
        out.append(("icosahedron edge", np.array([verts[a], verts[b]]), [0, 1, 3, 6]))
        out.append(("edge midpoint", np.array([sp[22 + 3 * f], verts[a]]), [2, 5, 9]))
    for _ in range(40):  # along a cell's edges (through its corners), at its level and the ones around
        level = int(rng.integers(1, 19))
        lat, lng = random_points(rng, 1)
        cell = dggs.latlng_to_cell(float(lat[0]), float(lng[0]), level)
        b = np.asarray(dggs.cell_to_boundary(cell), dtype=np.float64).reshape(-1, 2)[:3]
        out.append(("cell edges", np.vstack([b, b[:1]]), [level - 1, level, level + 1]))
    for lng in (0.0, 37.5, -120.0):  # over the poles
        out.append(("over north pole", np.array([(80.0, lng), (80.0, lng + 180.0)]), [2, 7, 12]))
        out.append(("over south pole", np.array([(-85.0, lng), (-70.0, lng - 180.0)]), [3, 9]))
        out.append(("to the pole", np.array([(70.0, lng), (90.0, 0.0), (60.0, lng + 90)]), [4, 11]))
    for lat in (0.0, 45.0, -60.0, 89.0):  # across the antimeridian
        out.append(("antimeridian", np.array([(lat, 179.5), (lat - 0.5, -179.5), (lat, 179.0)]), [3, 8, 14]))
        out.append(("along 180", np.array([(lat, 180.0), (lat + 0.7, -180.0)]), [5, 13, 18]))
    out.append(("equator 12,000 km", np.array([(0.0, -50.0), (0.0, 57.8)]), [5, 10, 13]))
    out.append(("pole to pole", np.array([(90.0, 0.0), (-90.0, 0.0)]), [4, 9]))
    return out


# ---- numba batch loops over the kernel's per-item functions ----


@njit(cache=False)
def nb_scalars(lat, lng, az, x, y, z, out):
    """The ecef, tangent and geodetic of each point (numba)."""
    for i in range(lat.shape[0]):
        out[i, 0], out[i, 1], out[i, 2] = kline.ecef(lat[i], lng[i])
        out[i, 3], out[i, 4], out[i, 5] = kline.tangent(lat[i], lng[i], az[i])
        out[i, 6], out[i, 7] = kline.geodetic(x[i], y[i], z[i])


@njit(cache=False)
def nb_chord(a, b, fa, xa, ya, fb, xb, yb, ok, dist):
    """The chord tests and distances of each pair (numba)."""
    for i in range(a.shape[0]):
        ok[i, 0] = kchord.clear(a[i], b[i], fa[i], xa[i], ya[i], fb[i], xb[i], yb[i])
        ok[i, 1] = kchord.corner_clear(a[i], b[i], fa[i], xa[i], ya[i], fb[i], xb[i], yb[i])
        ok[i, 2] = kchord.crosses(kchord.corners6(a[i]), kchord.corners6(b[i]), xa[i], ya[i], xb[i], yb[i])
        t = kchord.corners6(a[i])
        dist[i, 0] = kchord.dist_to_segment(xa[i], ya[i], t[0], t[1], t[2], t[3])
        dist[i, 1] = kchord.dist_to_segment(xb[i], yb[i], t[4], t[5], t[4], t[5])
        dist[i, 2] = kchord.dist_to_segment(xa[i], ya[i], xb[i], yb[i], t[0], t[1])


@njit(cache=False)
def nb_pairs(cells, level, col1, col2, pa, pb):
    """Edge neighbours of the cells, and a neighbour of those (numba)."""
    for i in range(cells.shape[0]):
        pa[i] = kgrid._neighbour(cells[i], level[i], col1[i])
        pb[i] = kgrid._neighbour(pa[i], level[i], col2[i])


# ---- the comparisons ----


def compare_cells_at(core, rng, scale: float) -> None:
    """Compare cells_at, lone and chained, both projections, levels 0..28."""
    n = int(250_000 * scale)
    lat, lng = random_points(rng, n)
    sp = SPECIAL
    for level in (0, 1, 2, 5, 9, 13, 17, 20, 24, 28):
        la = np.concatenate([lat, sp[:, 0]]) if level in (0, 9, 28) else lat[: n // 4].copy()
        lo = np.concatenate([lng, sp[:, 1]]) if level in (0, 9, 28) else lng[: n // 4].copy()
        for name, nb, c in (("ISEA", kline.cells_at, core.cells_at), ("IVEA", kivea.cells_at, core.ivea_cells_at)):
            for chained in (False, True):
                a = np.empty(la.size, np.uint64)
                b = np.empty(la.size, np.uint64)
                nb(la, lo, level, a, chained)
                c(la, lo, level, b, chained)
                same(f"cells_at {name}", a, b)
    # strided inputs and output, as numba accepts
    big = np.empty(2 * 1000, np.uint64)
    ref = np.empty(1000, np.uint64)
    kline.cells_at(lat[:2000:2], lng[:2000:2], 11, ref, True)
    core.cells_at(lat[:2000:2], lng[:2000:2], 11, big[::2], True)
    same("cells_at strided", ref, big[::2])


def compare_interpolate(core, rng, scale: float) -> None:
    """Compare interpolate on the anchors of random lines."""
    total = 0
    while total < 1_000_000 * scale:
        xy = random_line(rng, long=rng.random() < 0.3)
        level = int(rng.integers(0, 29))
        lat, lng, az_out, az_in, span, _ = paths._anchors(xy, level)
        m = 20_000
        k = rng.integers(0, span.size, m)
        t = rng.uniform(0, 1, m)
        t[:100] = 0.0
        t[100:200] = 1.0
        a_lat, a_lng, b_lat, b_lng = (np.empty(m) for _ in range(4))
        kline.interpolate(lat, lng, az_out, az_in, span, k, t, a_lat, a_lng)
        core.interpolate(lat, lng, az_out, az_in, span, k, t, b_lat, b_lng)
        same("interpolate", np.stack([a_lat, a_lng]), np.stack([b_lat, b_lng]), m)
        total += m


def compare_scalars(core, rng, scale: float) -> None:
    """Compare ecef, tangent, geodetic."""
    n = int(200_000 * scale)
    lat, lng = random_points(rng, n)
    lat[: SPECIAL.shape[0]], lng[: SPECIAL.shape[0]] = SPECIAL[:, 0], SPECIAL[:, 1]
    az = rng.uniform(-360, 360, n)
    r = 6378137.0 * (1 + rng.uniform(-0.01, 0.01, n))
    x, y, z = (
        r * np.cos(np.radians(lat)) * np.cos(np.radians(lng)),
        r * np.cos(np.radians(lat)) * np.sin(np.radians(lng)),
        r * np.sin(np.radians(lat)),
    )
    x[:50], y[:50] = 0.0, 0.0  # on the axis (a pole)
    ref = np.empty((n, 8))
    nb_scalars(lat, lng, az, x, y, z, ref)
    got = np.empty((n, 8))
    for i in range(n):
        got[i, 0:3] = core.ecef(lat[i], lng[i])
        got[i, 3:6] = core.tangent(lat[i], lng[i], az[i])
        got[i, 6:8] = core.geodetic(x[i], y[i], z[i])
    same("ecef/tangent/geodetic", ref, got, n)


def compare_chord(core, rng, scale: float) -> None:
    """Compare the chord functions on cells and samples near their shared edges and corners."""
    import dggs

    n = int(100_000 * scale)
    lat, lng = random_points(rng, n)
    level = rng.integers(1, 21, n)
    cells = np.array(
        [
            dggs.latlng_to_cell(float(a), float(b), int(lv), as_int=True)
            for a, b, lv in zip(lat[: n // 50], lng[: n // 50], level[: n // 50], strict=True)
        ],
        dtype=np.uint64,
    )
    cells = np.resize(cells, n)
    level = np.resize(level[: n // 50], n).astype(np.int64)
    col1, col2 = rng.integers(0, 3, n), rng.integers(0, 3, n)
    a = cells.copy()
    b1, b2 = np.empty(n, np.uint64), np.empty(n, np.uint64)
    nb_pairs(cells, level, col1, col2, b1, b2)
    b = np.where(rng.random(n) < 0.6, b1, b2)  # edge neighbours, and cells two steps away (a corner, or none)
    ta = np.array([kchord.corners6(c) for c in a[: n // 50]])
    ta = np.resize(ta, (n, 6))
    tb = np.array([kchord.corners6(c) for c in b])
    # samples: random barycentric points of each cell, some exactly on corners or edge midpoints
    wa, wb = rng.dirichlet([1, 1, 1], n), rng.dirichlet([1, 1, 1], n)
    wa[: n // 10] = np.eye(3)[rng.integers(0, 3, n // 10)]
    wb[n // 10 : n // 5] = [0.5, 0.5, 0.0]
    xa = wa[:, 0] * ta[:, 0] + wa[:, 1] * ta[:, 2] + wa[:, 2] * ta[:, 4]
    ya = wa[:, 0] * ta[:, 1] + wa[:, 1] * ta[:, 3] + wa[:, 2] * ta[:, 5]
    xb = wb[:, 0] * tb[:, 0] + wb[:, 1] * tb[:, 2] + wb[:, 2] * tb[:, 4]
    yb = wb[:, 0] * tb[:, 1] + wb[:, 1] * tb[:, 3] + wb[:, 2] * tb[:, 5]
    xb[-100:], yb[-100:] = xa[-100:], ya[-100:]  # a zero-length chord
    fa = ((a >> np.uint64(57)) & np.uint64(31)).astype(np.int64)
    fb = ((b >> np.uint64(57)) & np.uint64(31)).astype(np.int64)
    fa[rng.random(n) < 0.05] = -1
    fb[rng.random(n) < 0.05] = 3
    ok = np.empty((n, 3), np.bool_)
    dist = np.empty((n, 3))
    nb_chord(a, b, fa, xa, ya, fb, xb, yb, ok, dist)
    gok = np.empty((n, 3), np.bool_)
    gdist = np.empty((n, 3))
    for i in range(n):
        ai, bi = int(a[i]), int(b[i])
        gok[i, 0] = core.clear(ai, bi, int(fa[i]), xa[i], ya[i], int(fb[i]), xb[i], yb[i])
        gok[i, 1] = core.corner_clear(ai, bi, int(fa[i]), xa[i], ya[i], int(fb[i]), xb[i], yb[i])
        t6 = core.corners6(ai)
        gok[i, 2] = core.crosses(t6, core.corners6(bi), xa[i], ya[i], xb[i], yb[i])
        gdist[i, 0] = core.dist_to_segment(xa[i], ya[i], t6[0], t6[1], t6[2], t6[3])
        gdist[i, 1] = core.dist_to_segment(xb[i], yb[i], t6[4], t6[5], t6[4], t6[5])
        gdist[i, 2] = core.dist_to_segment(xa[i], ya[i], xb[i], yb[i], t6[0], t6[1])
    same("chord clear/corner_clear/crosses", ok, gok, n)
    same("chord dist_to_segment", dist, gdist, n)
    COUNTS["  (clear true)"] = int(ok[:, 0].sum())
    COUNTS["  (corner_clear true)"] = int(ok[:, 1].sum())


def compare_layout(core, rng, scale: float) -> None:
    """Compare clean and layout on random polylines."""
    for it in range(int(20_000 * scale)):
        n = int(rng.integers(0, 8))
        xy = np.round(rng.uniform(-90, 90, (n, 2)), int(rng.integers(0, 3)))
        if n and rng.random() < 0.3:  # repeats
            xy[rng.integers(0, n)] = xy[0]
            xy = np.repeat(xy, rng.integers(1, 3, n), axis=0)
        if n and rng.random() < 0.05:
            xy[rng.integers(0, xy.shape[0]), rng.integers(0, 2)] = [np.nan, np.inf, 91.0, -90.5][rng.integers(0, 4)]
        i1, p1 = klayout.clean(np.ascontiguousarray(xy))
        i2, p2 = core.clean(xy)
        same("clean", np.array([i1]), np.array([i2]), 1)
        same("clean points", p1, p2, 0)
        if i1 < 0 and p1.shape[0] >= 2:
            nseg = p1.shape[0] - 1
            az12, az21 = rng.uniform(-180, 180, nseg), rng.uniform(-180, 180, nseg)
            dist = 10.0 ** rng.uniform(-3, 7.3, nseg)
            if it % 7 == 0:
                dist[0] = 0.0
            ms = float(kline.span_for(paths._tolerance(int(rng.integers(0, 29)))))
            r1 = klayout.layout(p1, az12, az21, dist, ms)
            r2 = core.layout(p1, az12, az21, dist, ms)
            for r in (r1, r2):  # the anchors between the points are left for the caller (np.empty)
                r[0][r[5]] = r[1][r[5]] = 0.0
            for x1, x2 in zip(r1, r2, strict=True):
                same("layout", x1, x2, 0)
            COUNTS["layout"] += 1


def trace_both(core, proj: str, lat, lng, az_out, az_in, span, level, cap: int, shortcut: bool):
    """The numba and the C tracer on the same anchors: results, cells and corner gaps of each."""
    edge = paths._short_edge(level)
    nb = kline.trace if proj == "ISEA" else kivea.trace
    c = core.trace if proj == "ISEA" else core.ivea_trace
    o1, o2 = np.zeros(cap, np.uint64), np.zeros(cap, np.uint64)
    f1, f2 = np.zeros(max(16, cap // 8), np.int64), np.zeros(max(16, cap // 8), np.int64)
    r1 = nb(lat, lng, az_out, az_in, span, level, paths._STEP_EDGES * edge, paths._CORNER_M, o1, f1, shortcut)
    r2 = c(lat, lng, az_out, az_in, span, level, paths._STEP_EDGES * edge, paths._CORNER_M, o2, f2, shortcut)
    return r1, r2, o1, o2, f1, f2


def compare_trace_line(core, xy: np.ndarray, level: int, tag: str) -> None:
    """Compare trace on one polyline, both projections (and without the shortcut, and into a full buffer)."""
    lat, lng, az_out, az_in, span, dist = paths._anchors(xy, level)
    bound = int(np.ceil(paths._CELLS_PER_EDGE * dist / paths._short_edge(level)).sum()) + paths._CELLS_EXTRA * dist.size
    for proj in ("ISEA", "IVEA"):
        for shortcut in (True, False) if level % 3 == 0 else (True,):
            r1, r2, o1, o2, f1, f2 = trace_both(core, proj, lat, lng, az_out, az_in, span, level, bound + 16, shortcut)
            same(f"trace {tag}", np.array(r1), np.array(r2), 0)
            same(f"trace {tag}", o1, o2, 0)
            same(f"trace {tag}", f1, f2, max(r1[0], 0))
            COUNTS["  (traces with corner gaps)"] = COUNTS.get("  (traces with corner gaps)", 0) + (r1[1] > 0)
            if r1[0] > 4 and shortcut:  # a full buffer: both (-1, 0)
                r1, r2, o1, o2, f1, f2 = trace_both(core, proj, lat, lng, az_out, az_in, span, level, r1[0] // 2, True)
                same("trace full buffer", np.array(r1), np.array(r2), 0)
                same("trace full buffer", np.array(r1), np.array([-1, 0]), 1)


def compare_trace(core, rng, scale: float) -> list[tuple[np.ndarray, int, bool]]:
    """Compare trace on the shaped lines and on random ones; returns (points, level, shaped) of each."""
    lines: list[tuple[np.ndarray, int, bool]] = []
    for _tag, xy, levels in shaped_lines(rng):
        for level in levels:
            if 0 <= level <= 28:
                compare_trace_line(core, xy, level, "shaped")
                lines.append((xy, level, True))
    COUNTS["  (shaped lines)"] = len(lines)
    t_end = time.time() + 25 * scale
    nrand = 0
    while time.time() < t_end:
        long = rng.random() < 0.15
        xy = random_line(rng, long)
        seg = np.array([GEOD.inv(xy[i, 1], xy[i, 0], xy[i + 1, 1], xy[i + 1, 0])[2] for i in range(xy.shape[0] - 1)])
        # levels 0..20, capped so a line is at most ~300,000 cells
        top = 20
        while top > 0 and 3 * seg.sum() / paths._short_edge(top) > 300_000:
            top -= 1
        level = int(rng.integers(0, top + 1))
        compare_trace_line(core, xy, level, "random")
        lines.append((xy, level, False))
        nrand += 1
        COUNTS["  (random lines of 10,000+ km)"] = COUNTS.get("  (random lines of 10,000+ km)", 0) + long
    COUNTS["  (random lines)"] = nrand
    return lines


# ---- the public C function through ctypes ----


class Geodesic(ctypes.Structure):
    """dggs.h's dggs_geodesic."""

    _fields_ = [("inverse", ctypes.c_void_p), ("direct", ctypes.c_void_p), ("geod", ctypes.c_void_p)]


def compare_public(lib_path: str, lines: list[tuple[np.ndarray, int, bool]], rng) -> None:
    """Compare dggs_line_to_cells (ctypes, PROJ's geodesics) against dggs.line_to_cells, the grow protocol too."""
    import dggs

    lib = ctypes.CDLL(lib_path)
    projlib = glob.glob(os.path.join(os.path.dirname(pyproj.__file__), "..", "pyproj.libs", "libproj*.so*"))
    proj = ctypes.CDLL(projlib[0])
    g = ctypes.create_string_buffer(8192)  # struct geod_geodesic (about 400 bytes)
    proj.geod_init.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double]
    proj.geod_init(g, GEOD.a, GEOD.f)
    geo = Geodesic(
        ctypes.cast(proj.geod_inverse, ctypes.c_void_p).value,
        ctypes.cast(proj.geod_direct, ctypes.c_void_p).value,
        ctypes.cast(g, ctypes.c_void_p).value,
    )
    size_t = ctypes.c_size_t
    lib.dggs_line_to_cells_size.argtypes = [
        ctypes.c_void_p,
        size_t,
        ctypes.c_int,
        ctypes.POINTER(Geodesic),
        ctypes.POINTER(size_t),
        ctypes.POINTER(size_t),
    ]
    lib.dggs_line_to_cells.argtypes = [
        ctypes.c_void_p,
        size_t,
        ctypes.c_int,
        ctypes.c_int,
        ctypes.POINTER(Geodesic),
        ctypes.c_void_p,
        size_t,
        ctypes.c_void_p,
        size_t,
        ctypes.POINTER(size_t),
    ]
    extra = [
        np.zeros((0, 2)),
        np.array([(10.0, 20.0)]),
        np.array([(10.0, 20.0), (10.0, 20.0)]),
        np.array([(1.0, 1.0), (1.0, 1.0), (1.0, 3.0), (1.0, 1.0)]),
    ]
    shaped = [ln for ln in lines if ln[2]]
    rand = [ln for ln in lines if not ln[2]]
    todo = [(x, lv) for x in extra for lv in (0, 6, 28)]
    todo += [(x, lv) for x, lv, _ in shaped + rand[: max(1, len(rand) // 3)]]
    regrown = 0
    for i, (xy, level) in enumerate(todo):
        pts = np.ascontiguousarray(xy, dtype=np.float64)
        mx, ws = size_t(), size_t()
        err = lib.dggs_line_to_cells_size(
            pts.ctypes.data, pts.shape[0], level, ctypes.byref(geo), ctypes.byref(mx), ctypes.byref(ws)
        )
        if err != 0:
            FAILS.append(f"dggs_line_to_cells_size error {err}")
            continue
        work = np.empty(max(1, ws.value // 8))
        for p, pname in ((0, "ISEA"), (1, "IVEA")):
            ref = np.asarray(dggs.line_to_cells(pts, level, as_int=True, projection=pname), dtype=np.uint64)
            cap = mx.value if i % 5 else max(1, mx.value // 50)  # every fifth: too small, grown by the protocol
            while True:
                out = np.zeros(max(cap, 1), np.uint64)
                cnt = size_t()
                err = lib.dggs_line_to_cells(
                    pts.ctypes.data,
                    pts.shape[0],
                    level,
                    p,
                    ctypes.byref(geo),
                    work.ctypes.data,
                    ws.value,
                    out.ctypes.data,
                    cap,
                    ctypes.byref(cnt),
                )
                if err != 5:  # DGGS_E_BUFFER
                    break
                if cnt.value <= cap:
                    FAILS.append("grow protocol asked for no more room")
                    break
                cap = cnt.value
                regrown += 1
            same("dggs_line_to_cells", np.array([err]), np.array([0]), 0)
            same("dggs_line_to_cells", ref, out[: cnt.value], max(1, ref.size))
    COUNTS["  (public calls regrown)"] = regrown
    COUNTS["  (public lines)"] = len(todo)


def main() -> int:
    """Run every comparison; 0 if all are equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--so", default=None)
    ap.add_argument("--lib", default=os.path.join(ROOT, "build", "libdggs", "libdggs.so"))
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--seed", type=int, default=31)
    args = ap.parse_args()
    core = load_core(args.so)
    rng = np.random.default_rng(args.seed)
    global SPECIAL
    SPECIAL = special_points()
    t0 = time.time()
    for step in (compare_cells_at, compare_interpolate, compare_scalars, compare_chord, compare_layout):
        t = time.time()
        step(core, rng, args.scale)
        print(f"{step.__name__}: {time.time() - t:.1f} s", flush=True)
    t = time.time()
    lines = compare_trace(core, rng, args.scale)
    print(f"compare_trace: {time.time() - t:.1f} s", flush=True)
    t = time.time()
    compare_public(args.lib, lines, rng)
    print(f"compare_public: {time.time() - t:.1f} s", flush=True)
    for name, n in COUNTS.items():
        print(f"{name}: {n:,}")
    print(f"total {time.time() - t0:.0f} s; {'ALL EQUAL' if not FAILS else f'{len(FAILS)} MISMATCHES'}")
    return 0 if not FAILS else 1


SPECIAL = np.zeros((0, 2))

if __name__ == "__main__":
    sys.exit(main())
