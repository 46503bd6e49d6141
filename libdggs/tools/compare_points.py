"""Compare libdggs's points (dggs._core, this checkout's build) with the numba kernels bit for bit.

Runs index/_kernel/points.py and ivea_points.py (the installed package: the numba reference) and this checkout's
dggs._core on random and edge inputs: point location at every level 0..28 (poles, the antimeridian,
icosahedron vertices, face edges, points off the globe), centres, boundaries (densify 0, 1, 4; both row
orders), centre children, triangles and corners, the single-id entries, and the pole/antimeridian helpers and
exact rings, on both projections. Floats are compared as their bits. Exit code 0 only if all are equal.

    cd /tmp && nice python /work/wt/points/libdggs/tools/compare_points.py [--scale 1.0]
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

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def load_core():
    """Load dggs._core of this checkout's build, by path under its real name."""
    so = glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


core = load_core()
from dggs.geometry import kernel as gk  # noqa: E402  (the installed package: the numba reference)
from dggs.index._kernel import ivea_points as ki  # noqa: E402
from dggs.index._kernel import points as kp  # noqa: E402

FAILED: list[str] = []


def same(a, b) -> bool:
    """Whether two results are equal bit for bit (floats by their bits)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a.view(np.uint64), b.view(np.uint64)))
    return bool(np.array_equal(a, b))


def report(name: str, count: int, equal: bool) -> None:
    """Print one comparison's line and remember a failure."""
    print(f"{name:44s} {count:>10,d} items  {'equal' if equal else 'DIFFERENT'}", flush=True)
    if not equal:
        FAILED.append(name)


def unit_to_latlng(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Spherical (lat, lng) degrees of unit vectors (for picking test points only)."""
    lat = np.degrees(np.arcsin(np.clip(p[:, 2], -1, 1)))
    lng = np.degrees(np.arctan2(p[:, 1], p[:, 0]))
    return lat, lng


def edge_points(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Points on and near the special places: poles, +-180, vertices, face edges and centres, off the globe."""
    lat: list[float] = [
        90.0,
        -90.0,
        0.0,
        0.0,
        0.0,
        89.999999999,
        -89.999999999,
        90.0 - 1e-15,
        -0.0,
        math.nan,
        91.0,
        -90.5,
        45.0,
        45.0,
        45.0,
        1e-300,
        5e-324,
    ]
    lng: list[float] = [
        0.0,
        180.0,
        180.0,
        -180.0,
        -0.0,
        33.0,
        -147.0,
        180.0,
        540.0,
        0.0,
        0.0,
        0.0,
        math.inf,
        -math.inf,
        math.nan,
        1e308,
        -5e-324,
    ]
    verts = np.asarray(gk.ISEA_CENTRES)  # face centres
    vlat, vlng = unit_to_latlng(verts)
    lat += vlat.tolist()
    lng += vlng.tolist()
    # icosahedron vertices and edge midpoints: Snyder's inverse of the face corners and edge midpoints
    fc = np.asarray(gk.FACE_CORNERS_CCW)
    for face in range(20):
        for k in range(3):
            for t in (0.0, 0.5, 1.0 / 3.0, 1e-9, 1 - 1e-9):
                x = fc[k, 0] + t * (fc[(k + 1) % 3, 0] - fc[k, 0])
                y = fc[k, 1] + t * (fc[(k + 1) % 3, 1] - fc[k, 1])
                p = gk.inverse_unit(gk.ISEA_FRAMES, face, x, y)
                a, b = gk.unit_to_geodetic(*p)
                lat.append(a)
                lng.append(b)
    base_lat, base_lng = np.array(lat), np.array(lng)
    # jitter them by a few ulps to a few metres
    reps = max(1, n // base_lat.size)
    jl = np.repeat(base_lat, reps)
    jg = np.repeat(base_lng, reps)
    scale = 10.0 ** rng.uniform(-15, -4, jl.size)
    jl = jl + rng.standard_normal(jl.size) * scale
    jg = jg + rng.standard_normal(jg.size) * scale
    # near +-180 and the poles
    m = n // 4
    al = rng.uniform(-90, 90, m)
    ag = np.where(rng.random(m) < 0.5, 180.0, -180.0) - np.copysign(
        10.0 ** rng.uniform(-14, -2, m), rng.standard_normal(m)
    )
    pl = np.copysign(90.0 - 10.0 ** rng.uniform(-14, -1, m), rng.standard_normal(m))
    pg = rng.uniform(-180, 180, m)
    return (np.concatenate([base_lat, jl, al, pl]), np.concatenate([base_lng, jg, ag, pg]))


def random_points(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Uniform points on the sphere, some longitudes far outside -180..180."""
    z = rng.uniform(-1, 1, n)
    lat = np.degrees(np.arcsin(z))
    lng = rng.uniform(-180, 180, n)
    wide = rng.random(n) < 0.05  # some longitudes far outside -180..180
    lng[wide] = rng.uniform(-1e4, 1e4, wide.sum())
    return lat, lng


def compare_locate(rng, n_per_level: int) -> np.ndarray:
    """Point location at every level, both projections; returns ids of every level for the next checks."""
    ids_all = []
    for proj, ref, loc in (("ISEA", kp, core.locate), ("IVEA", ki, core.ivea_locate)):
        total, ok = 0, True
        for level in range(29):
            lat, lng = random_points(rng, n_per_level)
            elat, elng = edge_points(rng, n_per_level // 4)
            lat, lng = np.concatenate([lat, elat]), np.concatenate([lng, elng])
            a = np.empty(lat.size, dtype=np.uint64)
            b = np.empty(lat.size, dtype=np.uint64)
            ref.locate(lat.size, lat, lng, level, a)
            loc(lat.size, lat, lng, level, b)
            ok &= same(a, b)
            total += lat.size
            if proj == "ISEA":
                ids_all.append(a[a != 0][:n_per_level])
            # strided inputs (every other point), as numba takes any strides
            if level % 7 == 0:
                a2 = np.empty(lat[::2].size, dtype=np.uint64)
                b2 = np.empty(lat[::2].size, dtype=np.uint64)
                ref.locate(a2.size, lat[::2], lng[::2], level, a2)
                loc(b2.size, lat[::2], lng[::2], level, b2)
                ok &= same(a2, b2)
        report(f"locate/one_point {proj} levels 0..28", total, ok)
        # the single-point entry on a sample
        lat, lng = edge_points(rng, 2000)
        lv = rng.integers(0, 29, lat.size)
        one = core.one_point if proj == "ISEA" else core.ivea_one_point
        a = np.array(
            [ref.one_point(float(x), float(y), int(v)) for x, y, v in zip(lat, lng, lv, strict=True)], dtype=np.uint64
        )
        b = np.array([one(float(x), float(y), int(v)) for x, y, v in zip(lat, lng, lv, strict=True)], dtype=np.uint64)
        report(f"one_point {proj} (single entry)", lat.size, same(a, b))
    return np.concatenate(ids_all)


def compare_cells(rng, ids: np.ndarray, n_boundary: int, n_scalar: int) -> None:
    """Centres, boundaries and the single-id centre on both projections."""
    for proj, ref, cen, bnd, cof in (
        ("ISEA", kp, core.centres, core.boundaries, core.centre_of),
        ("IVEA", ki, core.ivea_centres, core.ivea_boundaries, core.ivea_centre_of),
    ):
        lat_a, lng_a = np.empty(ids.size), np.empty(ids.size)
        lat_b, lng_b = np.empty(ids.size), np.empty(ids.size)
        ref.centres(ids.size, ids, lat_a, lng_a)
        cen(ids.size, ids, lat_b, lng_b)
        report(f"centres {proj}", ids.size, same(lat_a, lat_b) and same(lng_a, lng_b))
        sub = ids[rng.permutation(ids.size)[:n_boundary]]
        for densify in (0, 1, 4):
            for lnglat in (False, True):
                rows = 3 * (densify + 1) + int(lnglat)
                a = np.empty((sub.size, rows, 2))
                b = np.empty((sub.size, rows, 2))
                ref.boundaries(sub.size * (densify + 1), sub, densify, a, lnglat)
                bnd(sub.size * (densify + 1), sub, densify, b, lnglat)
                report(f"boundaries {proj} densify={densify} lnglat={lnglat}", sub.size, same(a, b))
        # the single-id entry, with ints that are no ids
        vals = np.concatenate(
            [
                ids[:n_scalar].view(np.int64),
                rng.integers(-(2**63), 2**63 - 1, n_scalar // 10, dtype=np.int64),
                np.array([0, 1, 1 << 62, (1 << 62) | (20 << 57), (1 << 62) | (7 << 54), 2**63 - 1, -1]),
            ]
        )
        a = np.array([ref.centre_of(int(v)) for v in vals])
        b = np.array([cof(int(v)) for v in vals])
        report(f"centre_of {proj} (single entry)", vals.size, same(a, b))


def compare_planar(rng, ids: np.ndarray, n_scalar: int) -> None:
    """Triangles, corners, centre children and encode_point (no projection)."""
    sub = ids[rng.permutation(ids.size)[:n_scalar]]
    ok_t = ok_c = True
    for c in sub:
        ok_t &= (
            same(np.array(kp.triangle(c)[1:]), np.array(core.triangle(int(c))[1:]))
            and kp.triangle(c)[0] == core.triangle(int(c))[0]
        )
        ok_c &= (
            same(np.array(kp.corners(c)[1:]), np.array(core.corners(int(c))[1:]))
            and kp.corners(c)[0] == core.corners(int(c))[0]
        )
    report("triangle", sub.size, ok_t)
    report("corners", sub.size, ok_c)
    # centre children at every deeper level
    total, ok = 0, True
    lv = np.array([kp_level(c) for c in ids[: min(ids.size, 300_000)]])
    for target in range(29):
        src = ids[: lv.size][lv <= target]
        a = np.empty(src.size, dtype=np.uint64)
        b = np.empty(src.size, dtype=np.uint64)
        kp.center_children(src.size, src, target, a)
        core.center_children(src.size, src, target, b)
        ok &= same(a, b)
        total += src.size
    report("center_children (levels 0..28)", total, ok)
    # encode_point directly on face-frame points, faces' corners and edges included
    fc = np.asarray(gk.FACE_CORNERS_CCW)
    w = rng.dirichlet([1, 1, 1], n_scalar)
    w[: n_scalar // 4, rng.integers(0, 3)] = 0.0  # on an edge
    w /= w.sum(axis=1, keepdims=True)
    xs, ys = w @ fc[:, 0], w @ fc[:, 1]
    faces = rng.integers(0, 20, n_scalar)
    lvls = rng.integers(0, 29, n_scalar)
    a = np.array(
        [kp.encode_point(int(f), float(x), float(y), int(v)) for f, x, y, v in zip(faces, xs, ys, lvls, strict=True)],
        dtype=np.uint64,
    )
    b = np.array(
        [core.encode_point(int(f), float(x), float(y), int(v)) for f, x, y, v in zip(faces, xs, ys, lvls, strict=True)],
        dtype=np.uint64,
    )
    report("encode_point", n_scalar, same(a, b))


def kp_level(c) -> int:
    """Level of a well-formed id (Python ints)."""
    low = int(c) & ((1 << 54) - 1)
    if low:
        return 28 - ((low & -low).bit_length() - 1) // 2
    return 1 if (int(c) >> 54) & 7 else 0


def special_ids(rng, n: int) -> np.ndarray:
    """Cells at the poles and along the antimeridian (and some random ones), every level, densify-ready."""
    out = []
    for level in range(29):
        m = n // 29
        lat = np.concatenate(
            [
                np.copysign(90.0 - 10.0 ** rng.uniform(-12, 1, m // 2), rng.standard_normal(m // 2)),
                rng.uniform(-90, 90, m - m // 2),
            ]
        )
        lng = np.concatenate(
            [
                rng.uniform(-180, 180, m // 2),
                np.where(rng.random(m - m // 2) < 0.5, 180.0, -180.0)
                - rng.uniform(-1, 1, m - m // 2) * 10.0 ** -rng.uniform(0, 8, m - m // 2),
            ]
        )
        lat = np.concatenate([lat, [90.0, -90.0, 0.0, 0.0]])
        lng = np.concatenate([lng, [0.0, 0.0, 180.0, -180.0]])
        a = np.empty(lat.size, dtype=np.uint64)
        kp.locate(lat.size, lat, lng, level, a)
        out.append(a)
        b = np.empty(lat.size, dtype=np.uint64)
        ki.locate(lat.size, lat, lng, level, b)
        out.append(b)
    return np.unique(np.concatenate(out))


def compare_special(rng, n: int) -> None:
    """The exact pole and antimeridian rings, both projections."""
    ids = special_ids(rng, n)
    for proj, ref, ring in (("ISEA", kp, core.special_ring), ("IVEA", ki, core.ivea_special_ring)):
        total, ok, extra = 0, True, 0
        for densify in (0, 1, 3, 10):
            rows = 3 * (densify + 1) + kp.SPECIAL_EXTRA
            for c in ids:
                a = np.full((rows, 2), 7.0)
                b = np.full((rows, 2), 7.0)
                ma = ref.special_ring(c, densify, a)
                mb = ring(int(c), densify, b)
                if ma != mb or not same(a, b):
                    ok = False
                total += 1
                extra += ma != 3 * (densify + 1)
        report(f"special_ring {proj} densify 0,1,3,10 ({extra:,d} with extra rows)", total, ok)


def compare_helpers(rng, n: int) -> None:
    """The pole table and special_ring's helpers, both projections."""
    poles = core.pole_table()
    report("POLES", 60, same(poles, kp.POLES))
    fc = np.asarray(gk.FACE_CORNERS_CCW)
    ok = True
    # segments along the face edges (through the pole midpoints), with jitter, and random ones
    for _ in range(n):
        face = int(rng.integers(0, 20))
        k = int(rng.integers(0, 3))
        t0, t1 = sorted(rng.uniform(-0.2, 1.2, 2))
        if rng.random() < 0.3:
            t0 = 0.5 if rng.random() < 0.5 else t0
        ax, ay, bx, by = fc[k, 0], fc[k, 1], fc[(k + 1) % 3, 0], fc[(k + 1) % 3, 1]
        j = 10.0 ** rng.uniform(-16, -6) * (rng.random() < 0.5)
        x0, y0 = ax + t0 * (bx - ax) + j, ay + t0 * (by - ay)
        x1, y1 = ax + t1 * (bx - ax), ay + t1 * (by - ay) - j
        if rng.random() < 0.2:
            x0, y0, x1, y1 = rng.uniform(-0.7, 0.7, 4)
        ok &= same(kp._pole_on(face, x0, y0, x1, y1), core.pole_on(face, x0, y0, x1, y1))
    report("_pole_on", n, ok)
    ok = True
    for _ in range(n // 10):
        step = int(rng.integers(1, 40))
        tp = float(rng.choice([-1.0, 0.0, rng.random(), int(rng.integers(0, step + 1)) / step, 1.0]))
        a = np.full(step + 2, 9.0)
        b = np.full(step + 2, 9.0)
        ok &= kp._edge_params(a, step, tp) == core.edge_params(b, step, tp) and same(a, b)
    report("_edge_params", n // 10, ok)
    for proj, ref, lla, cro in (
        ("ISEA", kp, core.lat_lng_at, core.crossing),
        ("IVEA", ki, core.ivea_lat_lng_at, core.ivea_crossing),
    ):
        ok_l = ok_c = True
        for _ in range(n // 5):
            face = int(rng.integers(0, 20))
            w = rng.dirichlet([1, 1, 1], 2)
            x0, y0 = w[0] @ fc[:, 0], w[0] @ fc[:, 1]
            x1, y1 = w[1] @ fc[:, 0], w[1] @ fc[:, 1]
            t = float(rng.random())
            ok_l &= same(np.array(ref._lat_lng_at(face, x0, y0, x1, y1, t)), np.array(lla(face, x0, y0, x1, y1, t)))
            lo, hi = sorted(rng.random(2))
            lng_lo = ref._lat_lng_at(face, x0, y0, x1, y1, lo)[1]
            ok_c &= same(ref._crossing(face, x0, y0, x1, y1, lo, hi, lng_lo), cro(face, x0, y0, x1, y1, lo, hi, lng_lo))
        report(f"_lat_lng_at {proj}", n // 5, ok_l)
        report(f"_crossing {proj}", n // 5, ok_c)


def main() -> int:
    """Run every comparison; 0 only if all are equal."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scale", type=float, default=1.0, help="multiply every count by this")
    parser.add_argument("--seed", type=int, default=20261207)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    s = args.scale
    t0 = time.time()
    ids = compare_locate(rng, int(36_000 * s))
    compare_cells(rng, ids, int(200_000 * s), int(30_000 * s))
    compare_planar(rng, ids, int(30_000 * s))
    compare_special(rng, int(3_000 * s))
    compare_helpers(rng, int(20_000 * s))
    print(f"{time.time() - t0:.0f} s; {'ALL EQUAL' if not FAILED else 'DIFFERENT: ' + ', '.join(FAILED)}")
    return 0 if not FAILED else 1


if __name__ == "__main__":
    sys.exit(main())
