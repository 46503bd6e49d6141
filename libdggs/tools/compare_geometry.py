"""Compare the C geometry floor (dggs._core, libdggs/src/geometry.c and ivea.c) with the numba kernel, bit for bit.

Runs each function of dggs/geometry/kernel.py and the compiled part of ivea.py (the numba reference: the
installed package) and its binding in dggs._core (this worktree's build, loaded by path) on the same inputs:
over a million uniform points on the sphere plus the poles, the antimeridian (+-180, offsets 1e-12 and 1e-9,
wrapped longitudes), the icosahedron's vertex latitudes and vertices, its face edges and points 1e-12 / 1e-9 rad
off them, face centres, level-1 dividing rays, planar points near and at the face centre (subnormal, 2**-500),
face corners and edges; both projections; the batch loops forward_rad / inverse_deg of both projections in
the ISEA and the POLE orientations, on one thread and on several; descend / descend4 / child_corners along
chains of 28 levels. Floats are compared as their bits (``.view(np.uint64)``). Exit code 0 only if all equal.

Run from anywhere but the repository root (the numba reference must be the installed package)::

    cd /tmp && nice /work/main/.venv/bin/python /path/to/libdggs/tools/compare_geometry.py [--points 1000000]
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import math
import os
import sys
import time

import numpy as np
from numba import njit

from dggs.geometry import ivea as V
from dggs.geometry import kernel as K
from dggs.geometry.icosahedron import ISEA, POLE

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FAILURES: list[str] = []
COUNTS: dict[str, int] = {}


def load_core(path: str | None):
    """Load this worktree's dggs._core by path, under its real name."""
    so = path or glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    sys.modules["dggs._core"] = core
    return core


def bits(a: np.ndarray) -> np.ndarray:
    """Floats as their bits, ints as int64."""
    a = np.ascontiguousarray(a)
    return a.view(np.uint64) if a.dtype == np.float64 else a.astype(np.int64)


def same(name: str, ref, got) -> None:
    """Record a comparison of arrays (or tuples of arrays), bit for bit."""
    ref = ref if isinstance(ref, tuple) else (ref,)
    got = got if isinstance(got, tuple) else (got,)
    n = 0
    for j, (r, g) in enumerate(zip(ref, got, strict=True)):
        r, g = np.asarray(r), np.asarray(g)
        if r.dtype != np.float64:
            r, g = r.astype(np.int64), g.astype(np.int64)
        else:
            g = g.astype(np.float64)
        n = r.shape[0]
        if r.shape != g.shape:
            FAILURES.append(f"{name}[{j}]: shapes {r.shape} != {g.shape}")
            continue
        bad = np.flatnonzero(bits(r) != bits(g))
        if bad.size:
            i = int(bad[0])
            FAILURES.append(f"{name}[{j}]: {bad.size} of {r.shape[0]} differ; first at {i}: "
                            f"{r.ravel()[i]!r} != {g.ravel()[i]!r}")
    COUNTS[name] = COUNTS.get(name, 0) + n


# ---- the numba reference, batch loops over the kernel's per-point functions ----

@njit(cache=False)
def ref_geodetic_to_unit(lat, lng, out):
    """The numba kernel's geodetic_to_unit, looped over rows."""
    for i in range(lat.shape[0]):
        out[i, 0], out[i, 1], out[i, 2] = K.geodetic_to_unit(lat[i], lng[i])


@njit(cache=False)
def ref_forward(ivea, centres, frames, p, face, x, y):
    """The numba kernel's forward, looped over rows."""
    for i in range(p.shape[0]):
        if ivea:
            face[i], x[i], y[i] = V.forward_unit(centres, frames, p[i, 0], p[i, 1], p[i, 2])
        else:
            face[i], x[i], y[i] = K.forward_unit(centres, frames, p[i, 0], p[i, 1], p[i, 2])


@njit(cache=False)
def ref_face_forward(ivea, frames, face, p, x, y):
    """The numba kernel's face_forward, looped over rows."""
    for i in range(p.shape[0]):
        if ivea:
            x[i], y[i] = V.face_forward(frames, face[i], p[i, 0], p[i, 1], p[i, 2])
        else:
            x[i], y[i] = K.face_forward(frames, face[i], p[i, 0], p[i, 1], p[i, 2])


@njit(cache=False)
def ref_inverse(ivea, frames, face, x, y, out):
    """The numba kernel's inverse, looped over rows."""
    for i in range(face.shape[0]):
        if ivea:
            out[i, 0], out[i, 1], out[i, 2] = V.face_inverse(frames, face[i], x[i], y[i])
        else:
            out[i, 0], out[i, 1], out[i, 2] = K.inverse_unit(frames, face[i], x[i], y[i])


@njit(cache=False)
def ref_unit_to_geodetic(p, lat, lng):
    """The numba kernel's unit_to_geodetic, looped over rows."""
    for i in range(p.shape[0]):
        lat[i], lng[i] = K.unit_to_geodetic(p[i, 0], p[i, 1], p[i, 2])


@njit(cache=False)
def ref_small(lat, lng, x, y, out_f, out_i):
    """The numba kernel's small, looped over rows."""
    for i in range(lat.shape[0]):
        phi = math.radians(lat[i])
        out_f[i, 0], out_f[i, 1] = K.authalic_sincos(math.sin(phi), math.cos(phi))
        out_f[i, 2] = K.wrap_degrees(lng[i])
        out_i[i, 0] = K.sector_of(x[i], y[i])
        out_i[i, 1] = K.level1_digit(x[i], y[i])


@njit(cache=False)
def ref_nearest(centres, p, out):
    """The numba kernel's nearest, looped over rows."""
    for i in range(p.shape[0]):
        out[i] = K.nearest_face(centres, p[i, 0], p[i, 1], p[i, 2])


@njit(cache=False)
def ref_natural(c, n, e, x, y, out_xy, out_p):
    """The numba kernel's natural, looped over rows."""
    for i in range(c.shape[0]):
        out_xy[i, 0], out_xy[i, 1] = V.natural_forward(c[i], n[i], e[i])
        out_p[i, 0], out_p[i, 1], out_p[i, 2] = V.natural_inverse(x[i], y[i])


@njit(cache=False)
def ref_level1(x, y, d, px, py):
    """The numba kernel's level1, looped over rows."""
    for i in range(x.shape[0]):
        d[i], px[i], py[i] = K.level1_start(x[i], y[i])


@njit(cache=False)
def ref_descend(px, py, c, ox, oy):
    """The numba kernel's descend, looped over rows."""
    for i in range(px.shape[0]):
        c[i], ox[i], oy[i] = K.descend(px[i], py[i])


@njit(cache=False)
def ref_descend4(px, py, c, ox, oy):
    """The numba kernel's descend4, looped over rows."""
    for i in range(px.shape[0]):
        c[i], ox[i], oy[i] = K.descend4(px[i], py[i])


@njit(cache=False)
def ref_child_corners(t, digit, out):
    """The numba kernel's child_corners, looped over rows."""
    for i in range(t.shape[0]):
        r = K.child_corners(t[i, 0], t[i, 1], t[i, 2], t[i, 3], t[i, 4], t[i, 5], digit[i])
        for k in range(6):
            out[i, k] = r[k]


# ---- inputs ----

def sphere_points(n: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Geodetic (lat, lng) degrees: uniform points and the edge cases."""
    lat = [np.degrees(np.arcsin(rng.uniform(-1, 1, n)))]
    lng = [rng.uniform(-180, 180, n)]
    offs = np.array([0.0, 1e-12, -1e-12, 1e-9, -1e-9])
    # poles, with any longitude
    m = 2000
    lat.append(np.repeat([90.0, -90.0, 90.0 - 1e-12, -90.0 + 1e-9], m // 4))
    lng.append(rng.uniform(-540, 540, m))
    # the antimeridian and wrapped longitudes
    for base in (180.0, -180.0, 540.0, -540.0, 360.0, 0.0, -0.0, 1e6 + 0.5):
        for o in offs:
            lat.append(np.degrees(np.arcsin(rng.uniform(-1, 1, 1000))))
            lng.append(np.full(1000, base + o))
    # icosahedron vertices and face centres (authalic lat/lng as geodetic degrees, both kinds), with offsets
    geo = ISEA.geometry
    for pts in (geo.vertices, geo.centres):
        vl = np.degrees(np.arctan2(pts[:, 2], np.hypot(pts[:, 0], pts[:, 1])))
        vg = np.degrees(np.arctan2(pts[:, 1], pts[:, 0]))
        a, b = np.meshgrid(offs, offs)
        lat.append((vl[:, None] + a.ravel()[None, :]).ravel())
        lng.append((vg[:, None] + b.ravel()[None, :]).ravel())
        # their latitudes (and the geodetic latitudes whose authalic latitude they are) with any longitude
        for v in np.unique(np.round(vl, 12)):
            lat.append(np.full(500, v) + rng.choice(offs, 500))
            lng.append(rng.uniform(-180, 180, 500))
    return np.concatenate(lat), np.concatenate(lng)


def edge_vectors(rng: np.random.Generator, per_edge: int) -> np.ndarray:
    """Unit vectors on and 1e-12 / 1e-9 rad off every face edge (great-circle arcs between adjacent vertices)."""
    geo = ISEA.geometry
    edges = {tuple(sorted((int(f[k]), int(f[(k + 1) % 3])))) for f in geo.face_vertices for k in range(3)}
    out = []
    for a, b in sorted(edges):
        va, vb = geo.vertices[a], geo.vertices[b]
        t = np.concatenate([rng.uniform(0, 1, per_edge), [0.0, 0.5, 1.0]])
        p = (1 - t)[:, None] * va + t[:, None] * vb
        p /= np.linalg.norm(p, axis=1)[:, None]
        normal = np.cross(va, vb)
        normal /= np.linalg.norm(normal)
        for o in (0.0, 1e-12, -1e-12, 1e-9, -1e-9):
            q = p + o * normal
            out.append(q / np.linalg.norm(q, axis=1)[:, None])
    return np.concatenate(out)


def planar_points(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(face, x, y) on the faces: uniform in the triangle, near and at the centre, corners, edges, dividing rays."""
    r = K.FACE_CORNERS_CCW
    u, v = rng.uniform(0, 1, n), rng.uniform(0, 1, n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    xy = [r[0] + u[:, None] * (r[1] - r[0]) + v[:, None] * (r[2] - r[0])]
    tiny = np.array([0.0, -0.0, 5e-324, -5e-324, 1e-310, 2.0**-500, np.nextafter(2.0**-500, 1), 2.0**-501, 1e-200,
                     1e-17, 1e-12])
    for a in tiny:
        for b in tiny:
            xy.append(np.array([[a, b], [-a, b], [a, -b], [-a, -b]]))
    # corners, edges (and slightly inside / outside), dividing rays at azimuth 60 k and 30 + 60 k
    for k in range(3):
        a, b = r[k], r[(k + 1) % 3]
        t = np.concatenate([np.linspace(0, 1, 2001), rng.uniform(0, 1, 2000)])
        e = (1 - t)[:, None] * a + t[:, None] * b
        for s in (1.0, 1 - 1e-12, 1 + 1e-12, 1 - 1e-9, 1 + 1e-10):
            xy.append(e * s)
    for az in np.radians(np.arange(0, 360, 30)):
        rho = np.concatenate([np.linspace(0, 0.8, 3001), 10.0 ** rng.uniform(-300, 0, 1000)])
        xy.append(np.stack([rho * math.sin(az), rho * math.cos(az)], axis=1))
        xy.append(np.stack([rho * math.sin(az + 1e-12), rho * math.cos(az + 1e-12)], axis=1))
    xy = np.concatenate(xy)
    face = rng.integers(0, 20, xy.shape[0]).astype(np.int64)
    return face, np.ascontiguousarray(xy[:, 0]), np.ascontiguousarray(xy[:, 1])


# ---- the C side, per point through the binding ----

def c_rows(fn, *cols) -> tuple[np.ndarray, ...]:
    """Call a per-point binding entry on each row; its tuple results as columns."""
    out = list(map(fn, *(c.tolist() if isinstance(c, np.ndarray) else c for c in cols)))
    arr = np.array(out, dtype=object)
    if arr.ndim == 1:
        return (np.array(out),)
    return tuple(np.array(arr[:, j].tolist()) for j in range(arr.shape[1]))


def main() -> int:
    """Run every comparison; 0 if all are bit-identical."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--points", type=int, default=1_000_000, help="uniform points on the sphere")
    ap.add_argument("--so", default=None, help="the dggs._core extension to test (default: this worktree's)")
    args = ap.parse_args()
    core = load_core(args.so)
    rng = np.random.default_rng(31)
    t0 = time.time()
    centres, frames = np.ascontiguousarray(K.ISEA_CENTRES), np.ascontiguousarray(K.ISEA_FRAMES)

    lat, lng = sphere_points(args.points, rng)
    n = lat.shape[0]
    print(f"{n} sphere points", flush=True)
    ref_p = np.empty((n, 3))
    ref_geodetic_to_unit(lat, lng, ref_p)
    same("geodetic_to_unit", tuple(ref_p.T), c_rows(core.geodetic_to_unit, lat, lng))
    p = np.concatenate([ref_p, edge_vectors(rng, 2000), ISEA.geometry.vertices, ISEA.geometry.centres,
                        -ISEA.geometry.vertices])
    m = p.shape[0]
    print(f"{m} unit vectors (+ face edges, vertices, centres)", flush=True)

    nf = np.empty(m, dtype=np.int64)
    ref_nearest(centres, p, nf)
    same("nearest_face", nf, c_rows(core.nearest_face, [centres] * m, p[:, 0], p[:, 1], p[:, 2]))
    planes = {}
    for ivea, name, fwd, ffwd, inv in ((0, "snyder", core.snyder_forward_unit, core.snyder_face_forward,
                                        core.snyder_inverse_unit),
                                       (1, "ivea", core.ivea_forward_unit, core.ivea_face_forward,
                                        core.ivea_face_inverse)):
        face, x, y = np.empty(m, dtype=np.int64), np.empty(m), np.empty(m)
        ref_forward(ivea, centres, frames, p, face, x, y)
        same(f"{name}.forward_unit", (face, x, y), c_rows(fwd, [centres] * m, [frames] * m, p[:, 0], p[:, 1], p[:, 2]))
        planes[name] = (face, x, y)
        # face_forward on a neighbouring face (the formulas hold past the face's edges)
        k = min(m, 300_000)
        other = np.argsort(-(p[:k] @ centres.T), axis=1)[:, 1].astype(np.int64)
        ox, oy = np.empty(k), np.empty(k)
        ref_face_forward(ivea, frames, other, p[:k], ox, oy)
        same(f"{name}.face_forward(neighbour face)", (ox, oy),
             c_rows(ffwd, [frames] * k, other, p[:k, 0], p[:k, 1], p[:k, 2]))
        # inverse of the forward's points and of planar test points
        pf, px_, py_ = planar_points(rng, 200_000)
        fi = np.concatenate([face, pf])
        xi, yi = np.concatenate([x, px_]), np.concatenate([y, py_])
        q = np.empty((fi.shape[0], 3))
        ref_inverse(ivea, frames, fi, xi, yi, q)
        same(f"{name}.inverse_unit", tuple(q.T), c_rows(inv, [frames] * fi.shape[0], fi, xi, yi))
        # unit_to_geodetic of the inverse's vectors, and of scaled copies (any norm)
        g_lat, g_lng = np.empty(fi.shape[0]), np.empty(fi.shape[0])
        ref_unit_to_geodetic(q, g_lat, g_lng)
        same("unit_to_geodetic", (g_lat, g_lng), c_rows(core.unit_to_geodetic, q[:, 0], q[:, 1], q[:, 2]))
        s = q[:100_000] * rng.uniform(0.5, 3.0, (min(100_000, q.shape[0]), 1))
        g_lat, g_lng = np.empty(s.shape[0]), np.empty(s.shape[0])
        ref_unit_to_geodetic(s, g_lat, g_lng)
        same("unit_to_geodetic(any norm)", (g_lat, g_lng), c_rows(core.unit_to_geodetic, s[:, 0], s[:, 1], s[:, 2]))
        planes[name + "_planar"] = (pf, px_, py_)

    # the batch loops of the checked API, ISEA and POLE orientations, one thread and several
    for orient_name, orient in (("ISEA", ISEA), ("POLE", POLE)):
        cen, fra = np.ascontiguousarray(orient.geometry.centres), np.ascontiguousarray(orient.geometry.frames)
        rlat, rlng = np.radians(lat), np.radians(lng)
        for name, ref_loops, c_fwd, c_inv in (("snyder", K, core.snyder_forward_rad, core.snyder_inverse_deg),
                                              ("ivea", V, core.ivea_forward_rad, core.ivea_inverse_deg)):
            outs = []
            for threads in (1, 2):
                core.set_threads(threads)
                f, x, y = np.empty(n, dtype=np.intp), np.empty(n), np.empty(n)
                c_fwd(n, rlat, rlng, cen, fra, f, x, y)
                outs.append((f, x, y))
            f, x, y = np.empty(n, dtype=np.intp), np.empty(n), np.empty(n)
            ref_loops.forward_rad(n, rlat, rlng, cen, fra, f, x, y)
            same(f"{name}.forward_rad[{orient_name}, 1 thread]", (f, x, y), outs[0])
            same(f"{name}.forward_rad[{orient_name}, 2 threads]", (f, x, y), outs[1])
            pf, px_, py_ = planes[name + "_planar"]
            fi = np.concatenate([f, pf]).astype(np.int64)
            xi, yi = np.concatenate([x, px_]), np.concatenate([y, py_])
            k = fi.shape[0]
            ref_lat, ref_lng = np.empty(k), np.empty(k)
            ref_loops.inverse_deg(k, fi, xi, yi, fra, ref_lat, ref_lng)
            for threads in (1, 2):
                core.set_threads(threads)
                c_lat, c_lng = np.empty(k), np.empty(k)
                c_inv(k, fi, xi, yi, fra, c_lat, c_lng)
                same(f"{name}.inverse_deg[{orient_name}, {threads} thread(s)]", (ref_lat, ref_lng), (c_lat, c_lng))
    core.set_threads(1)

    # authalic_sincos, wrap_degrees, sector_of, level1_digit
    pf, px_, py_ = planes["snyder_planar"]
    xs = np.concatenate([planes["snyder"][1], px_])[:n]
    ys = np.concatenate([planes["snyder"][2], py_])[:n]
    k = xs.shape[0]
    wl = np.concatenate([[1e300, -1e300, 180.0, -180.0, 540.0, -540.0, -0.0, 0.0, np.nextafter(180.0, 200),
                          np.nextafter(-180, -200), 720.0, -720.0, 900.0, 1e16 + 180.0],
                         rng.uniform(-1e4, 1e4, 10000), lng])[:k]
    la = lat[:k]
    out_f, out_i = np.empty((k, 3)), np.empty((k, 2), dtype=np.int64)
    ref_small(la, wl, xs, ys, out_f, out_i)
    phi = np.radians(la)
    same("authalic_sincos", (out_f[:, 0], out_f[:, 1]), c_rows(core.authalic_sincos, np.sin(phi), np.cos(phi)))
    same("wrap_degrees", out_f[:, 2], c_rows(core.wrap_degrees, wl))
    same("sector_of", out_i[:, 0], c_rows(core.sector_of, xs, ys))
    same("level1_digit", out_i[:, 1], c_rows(core.level1_digit, xs, ys))

    # IVEA's natural triangle maps
    q = p[: min(m, k, 500_000)]
    nx, ny = np.empty((q.shape[0], 2)), np.empty((q.shape[0], 3))
    ref_natural(q[:, 0], q[:, 1], q[:, 2], xs[: q.shape[0]], ys[: q.shape[0]], nx, ny)
    same("ivea.natural_forward", tuple(nx.T), c_rows(core.ivea_natural_forward, q[:, 0], q[:, 1], q[:, 2]))
    same("ivea.natural_inverse", tuple(ny.T), c_rows(core.ivea_natural_inverse, xs[: q.shape[0]], ys[: q.shape[0]]))

    # Split (2:6): level1_start, then chains of descend4 and descend to level 28
    d, cx, cy = np.empty(k, dtype=np.int64), np.empty(k), np.empty(k)
    ref_level1(xs, ys, d, cx, cy)
    same("level1_start", (d, cx, cy), c_rows(core.level1_start, xs, ys))
    c4 = min(k, 300_000)
    ax, ay = cx[:c4].copy(), cy[:c4].copy()
    for step in range(6):
        c, ox, oy = np.empty(c4, dtype=np.uint64), np.empty(c4), np.empty(c4)
        ref_descend4(ax, ay, c, ox, oy)
        same(f"descend4(step {step + 1})", (c, ox, oy), c_rows(core.descend4, ax, ay))
        ax, ay = ox, oy
    c1 = min(k, 100_000)
    ax, ay = cx[:c1].copy(), cy[:c1].copy()
    for _ in range(27):
        c, ox, oy = np.empty(c1, dtype=np.int64), np.empty(c1), np.empty(c1)
        ref_descend(ax, ay, c, ox, oy)
        same("descend(27 steps)", (c, ox, oy), c_rows(core.descend, ax, ay))
        ax, ay = ox, oy
    # descend / descend4 on grid-cell corners of the jump table and on the canonical triangle's edges
    gx = np.repeat(np.arange(1025) * (K.SQRT3 / 1024), 593)
    gy = np.tile(np.arange(593) * (1.0 / 592), 1025)
    eps = rng.choice([0.0, 1e-12, -1e-12, 1e-9, -1e-9, 5e-324], gx.shape[0])
    gx, gy = gx + eps, gy + rng.permutation(eps)
    c, ox, oy = np.empty(gx.shape[0], dtype=np.uint64), np.empty(gx.shape[0]), np.empty(gx.shape[0])
    ref_descend4(gx, gy, c, ox, oy)
    same("descend4(jump grid nodes)", (c, ox, oy), c_rows(core.descend4, gx, gy))
    c, ox, oy = np.empty(gx.shape[0], dtype=np.int64), np.empty(gx.shape[0]), np.empty(gx.shape[0])
    ref_descend(gx, gy, c, ox, oy)
    same("descend(jump grid nodes)", (c, ox, oy), c_rows(core.descend, gx, gy))
    # child_corners along random digit paths from every level-1 triangle
    chains = 40_000
    t = np.ascontiguousarray(K.LEVEL1_CORNERS[rng.integers(0, 6, chains)].reshape(chains, 6))
    for _ in range(2, 29):
        digit = rng.integers(0, 3, chains).astype(np.int64)
        out = np.empty((chains, 6))
        ref_child_corners(t, digit, out)
        same("child_corners(levels 2-28)", tuple(out.T), c_rows(core.child_corners, *t.T, digit))
        t = out

    print(f"\n{sum(COUNTS.values())} comparisons in {time.time() - t0:.0f} s:")
    for name, count in COUNTS.items():
        bad = any(f.startswith(name + "[") for f in FAILURES)
        print(f"  {name:48s} {count:>10d}  {'DIFFER' if bad else 'bit-identical'}")
    if FAILURES:
        print("\nDIFFERENCES:")
        for f in FAILURES:
            print("  " + f)
        return 1
    print("ALL BIT-IDENTICAL")
    return 0


if __name__ == "__main__":
    sys.exit(main())
