"""Freeze outputs of the numba point kernels (index/_kernel/points.py, ivea_points.py) into libdggs/tests/test_points.c.

Rewrites the block between ``BEGIN FROZEN`` and ``END FROZEN`` of the test with C tables (floats as C99
hex-float literals): point location at the poles, on the antimeridian, at icosahedron vertices, face-edge
midpoints and face centres and at random points, every level 0..28, both projections; centres; triangles and
corners; plain boundaries; the exact pole and antimeridian rings. ``--poles`` prints points.c's pole table.
Run with the numba package installed (the reference), from anywhere but this checkout's root::

    cd /tmp && python /path/to/libdggs/tools/freeze_points.py
"""

from __future__ import annotations

import argparse
import math
import os
import re

import numpy as np

from dggs.geometry import kernel as gk
from dggs.index._kernel import ivea_points as ki
from dggs.index._kernel import points as kp

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.join(os.path.dirname(HERE), "tests", "test_points.c")
PROJS = (("DGGS_ISEA", kp), ("DGGS_IVEA", ki))


def h(x: float) -> str:
    """A double as a C99 hex-float literal (NAN / INFINITY spelled out)."""
    x = float(x)
    if math.isnan(x):
        return "NAN"
    if math.isinf(x):
        return "INFINITY" if x > 0 else "-INFINITY"
    return x.hex()


def u(c) -> str:
    """A uint64 as a C literal."""
    return f"0x{int(c):016x}ULL"


def special_points() -> list[tuple[float, float, str]]:
    """(lat, lng, what): poles, the antimeridian, vertices, edge midpoints, face centres, off the globe."""
    pts = [(90.0, 0.0, "north pole"), (-90.0, 0.0, "south pole"), (90.0, 123.0, "north pole, any longitude"),
           (0.0, 180.0, "antimeridian"), (0.0, -180.0, "antimeridian, -180"), (45.0, 180.0, "antimeridian 45N"),
           (-60.0, -180.0, "antimeridian 60S"), (10.0, 540.0, "longitude 540"), (-33.0, -179.999999999, "near -180")]
    fc = np.asarray(gk.FACE_CORNERS_CCW)
    for face in (0, 4, 9, 16, 19):
        for k in range(3):
            x, y = fc[k]
            lat, lng = gk.unit_to_geodetic(*gk.inverse_unit(gk.ISEA_FRAMES, face, x, y))
            pts.append((lat, lng, f"vertex {k} of face {face}"))
            mx, my = 0.5 * (fc[k] + fc[(k + 1) % 3])
            lat, lng = gk.unit_to_geodetic(*gk.inverse_unit(gk.ISEA_FRAMES, face, mx, my))
            pts.append((lat, lng, f"edge midpoint {k} of face {face}"))
        lat, lng = gk.unit_to_geodetic(*gk.ISEA_CENTRES[face])
        pts.append((lat, lng, f"centre of face {face}"))
    rng = np.random.default_rng(7)
    for _ in range(10):
        pts.append((math.degrees(math.asin(rng.uniform(-1, 1))), rng.uniform(-180, 180), "random"))
    pts += [(math.nan, 0.0, "NaN latitude"), (91.0, 0.0, "latitude 91"), (0.0, math.inf, "infinite longitude")]
    return pts


def freeze() -> str:
    """The C tables."""
    out = []
    pts = special_points()
    out.append("/* one_point: lat, lng, level, projection, id (0: not on the globe) */")
    out.append("static const struct { double lat, lng; int level; dggs_projection proj; uint64_t id; } FROZEN_POINTS[] = {")
    rows = 0
    ids = []
    for i, (lat, lng, what) in enumerate(pts):
        for proj, mod in PROJS:
            levels = range(29) if i in (0, 3, 12) else (i % 29, (7 * i + 3) % 29)
            for level in levels:
                c = mod.one_point(lat, lng, level)
                out.append(f"    {{{h(lat)}, {h(lng)}, {level}, {proj}, {u(c)}}}, /* {what} */")
                rows += 1
                if c:
                    ids.append(int(c))
    out.append("};")
    ids = sorted(set(ids))
    rng = np.random.default_rng(11)
    pick = sorted(set(rng.choice(ids, 40, replace=False).tolist()) | {ids[0], ids[-1]})
    out.append("/* centre_of: id, projection, lat, lng */")
    out.append("static const struct { uint64_t id; dggs_projection proj; double lat, lng; } FROZEN_CENTRES[] = {")
    for c in pick:
        for proj, mod in PROJS:
            lat, lng = mod.centre_of(c)
            out.append(f"    {{{u(c)}, {proj}, {h(lat)}, {h(lng)}}},")
    out.append("};")
    out.append("/* triangle and corners: id, face, triangle's ax..cy, corners' ax..cy */")
    out.append("static const struct { uint64_t id; int face; double tri[6], cor[6]; } FROZEN_CORNERS[] = {")
    for c in pick[:30]:
        t = kp.triangle(np.uint64(c))
        k = kp.corners(np.uint64(c))
        out.append(f"    {{{u(c)}, {t[0]}, {{{', '.join(h(v) for v in t[1:])}}}, {{{', '.join(h(v) for v in k[1:])}}}}},")
    out.append("};")
    # plain boundaries, densify 0 and 2
    out.append("/* one_boundary (lat, lng rows): id, projection, densify, the 3 (densify + 1) rows */")
    out.append("static const struct { uint64_t id; dggs_projection proj; int densify; double rows[9][2]; } FROZEN_BOUNDARIES[] = {")
    for c in pick[:8]:
        for proj, mod in PROJS:
            for densify in (0, 2):
                b = np.empty((1, 3 * (densify + 1), 2))
                mod.boundaries(1, np.array([c], dtype=np.uint64), densify, b, False)
                r = ", ".join(f"{{{h(a)}, {h(bb)}}}" for a, bb in b[0])
                out.append(f"    {{{u(c)}, {proj}, {densify}, {{{r}}}}},")
    out.append("};")
    # special rings: cells at the poles and across the antimeridian
    ring_ids = set()
    for lat, lng in ((90.0, 0.0), (-90.0, 0.0), (89.99, 45.0), (-89.99, -100.0), (0.0, 180.0), (50.0, 179.9999),
                     (-20.0, -179.9999), (70.0, 180.0)):
        for level in (0, 1, 2, 5, 13, 28):
            ring_ids.add(int(kp.one_point(lat, lng, level)))
            ring_ids.add(int(ki.one_point(lat, lng, level)))
    ring_ids = sorted(ring_ids)
    rng.shuffle(ring_ids)
    ring_ids = sorted(ring_ids[:24])
    out.append("/* special_ring: id, projection, densify, count, rows (lat, lng) */")
    out.append("static const struct { uint64_t id; dggs_projection proj; int densify, count; double rows["
               + str(3 * 2 + kp.SPECIAL_EXTRA) + "][2]; } FROZEN_RINGS[] = {")
    for c in ring_ids:
        for proj, mod in PROJS:
            for densify in (0, 1):
                buf = np.zeros((3 * (densify + 1) + kp.SPECIAL_EXTRA, 2))
                m = mod.special_ring(np.uint64(c), densify, buf)
                r = ", ".join(f"{{{h(a)}, {h(bb)}}}" for a, bb in buf[:m])
                out.append(f"    {{{u(c)}, {proj}, {densify}, {m}, {{{r}}}}},")
    out.append("};")
    return "\n".join(out)


def poles() -> str:
    """points.c's pole table."""
    return "\n".join(
        "    {%s, %s, %s}, /* face %d */" % (h(r[0]), h(r[1]), h(r[2]), f) for f, r in enumerate(kp.POLES)
    )


def main() -> None:
    """Rewrite the frozen block of test_points.c (or print the pole table)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--poles", action="store_true", help="print points.c's pole table instead")
    args = parser.parse_args()
    if args.poles:
        print(poles())
        return
    with open(TEST) as f:
        text = f.read()
    block = "/* BEGIN FROZEN (tools/freeze_points.py) */\n" + freeze() + "\n/* END FROZEN */"
    text = re.sub(r"/\* BEGIN FROZEN.*?/\* END FROZEN \*/", lambda m: block, text, flags=re.S)
    with open(TEST, "w") as f:
        f.write(text)
    print(f"wrote {TEST}")


if __name__ == "__main__":
    main()
