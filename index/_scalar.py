"""Pure-Python paths for one cell id at a time (no floating point, so exact).

numpy costs about a microsecond per call whatever the array size, so a
single-id call through the array code pays for dozens of tiny passes.  The
operations that only rewrite digits (validity, level, parent, children,
neighbours, disks) have these string versions; they are tested to agree
with the array versions on every input.
"""

from __future__ import annotations

import re

from .cellid import FACE_LETTERS, MAX_LEVEL

_VALID = re.compile(r"[A-T](?:[0-5][0-2]{0,%d})?\Z" % (MAX_LEVEL - 1))


def is_valid(cell: str) -> bool:
    """Whether a str is a well-formed id."""
    return _VALID.match(cell) is not None


_tables = None


def _load_tables():
    """Plain-list copies of the neighbour tables in :mod:`index.grid`."""
    global _tables
    if _tables is None:
        from dggs.geometry.split26 import face_adjacency

        from . import _geo
        from .grid import _OUTER, _SIBLING, _level1_tables

        ccw, table = _level1_tables()
        adj = face_adjacency(_geo.ORIENTATION.geometry.face_vertices)
        _tables = (
            _SIBLING.tolist(),
            _OUTER.tolist(),
            [bool(v) for v in ccw],
            table.tolist(),
            [[FACE_LETTERS[adj[f][k]] for k in (1, 0, 2)] for f in range(20)],
        )
    return _tables


def neighbours(cell: str) -> list[str]:
    """The 3 edge neighbours of a valid id, in the array code's column order.

    Walking up from the last digit, the first digit whose edge is shared
    with a sibling changes; the digits after it stay (mirror images keep
    their labels), so each neighbour is the id with one character replaced.
    """
    sibling, outer, l1_ccw, l1_table, base = _load_tables()
    if len(cell) == 1:
        return list(base[ord(cell) - 65])
    tail = cell[2:]
    flips = tail.count("0") + tail.count("2")
    ccw = l1_ccw[ord(cell[1]) - 48] ^ (flips % 2 == 1)
    found = ["", "", ""]
    for label in (0, 1, 2):  # a, b, c
        edge = label
        pos = len(cell) - 1
        while pos >= 2:
            c = ord(cell[pos]) - 48
            sib = sibling[c][edge]
            if sib >= 0:
                found[label] = cell[:pos] + chr(48 + sib) + cell[pos + 1 :]
                break
            edge = outer[c][edge]
            pos -= 1
        else:  # reached the level-1 triangle's edge
            f, d1 = l1_table[ord(cell[0]) - 65][ord(cell[1]) - 48][edge]
            found[label] = FACE_LETTERS[f] + chr(48 + d1) + tail
    order = (2, 0, 1) if ccw else (1, 0, 2)  # corner-order columns: c, a, b or b, a, c
    return [found[i] for i in order]


def disk(cell: str, k: int) -> list[str]:
    """Sorted ids within k edge steps of a valid id (breadth-first on sets)."""
    seen = {cell}
    ring = [cell]
    for _ in range(k):
        nxt = []
        for c in ring:
            for n in neighbours(c):
                if n not in seen:
                    seen.add(n)
                    nxt.append(n)
        ring = nxt
    return sorted(seen)


def children(cell: str, level: int) -> list[str]:
    """Descendants of a valid id at ``level`` in id order."""
    out = [cell]
    for lv in range(len(cell), level + 1):
        digits = "012345" if lv == 1 else "012"
        out = [c + d for c in out for d in digits]
    return out


# ----------------------------------------------------------------------------
# One point to one cell, in floats (pure Python)
# ----------------------------------------------------------------------------
# Python's math and numpy's vector loops may round the last bit differently,
# so wherever a decision (face, sector, level-1 triangle, child) is closer to
# a tie than the rounding could move it, this path gives up (returns None)
# and the caller uses the array path: both paths always agree.
_TIE = 1e-13  # decision margin at level 1, ~1000x the paths' rounding gap (grows by sqrt 3 per level)
_point_tables = None


def _load_point_tables():
    global _point_tables
    if _point_tables is None:
        from dggs.geometry import split26, snyder

        from . import _geo

        geo = _geo.ORIENTATION.geometry
        _point_tables = (
            _geo.ELLIPSOID._to_authalic.tolist(),
            geo.centres.tolist(),
            geo.frames.tolist(),
            split26._L1_C.tolist(),
            split26._L1_ROWS.tolist(),
            split26._M.tolist(),
            split26._T.tolist(),
            snyder._ROT_COS.tolist(),
            snyder._ROT_SIN.tolist(),
        )
    return _point_tables


def latlng_to_cell(lat: float, lng: float, level: int) -> str | None:
    """The cell of one valid point, or None where a decision is too close to call."""
    import math

    from dggs.geometry.snyder import MATH_OPS, sector_forward

    coeffs, centres, frames, l1_c, l1_rows, mats, offs, rot_c, rot_s = _load_point_tables()
    phi = math.radians(lat)
    # authalic latitude: Clenshaw sum of Karney's series (dggs.geometry.authalic)
    s2, c2 = math.sin(2 * phi), math.cos(2 * phi)
    b1 = b2 = 0.0
    for c in reversed(coeffs):
        b1, b2 = 2 * c2 * b1 - b2 + c, b1
    beta = phi + b1 * s2
    lam = math.radians(lng)
    cb = math.cos(beta)
    p = (cb * math.cos(lam), cb * math.sin(lam), math.sin(beta))
    # face: the nearest centre, unless another is within the tie margin
    dots = [p[0] * c[0] + p[1] * c[1] + p[2] * c[2] for c in centres]
    face = max(range(20), key=dots.__getitem__)
    best = dots[face]
    if any(best - d < _TIE for i, d in enumerate(dots) if i != face):
        return None
    fr = frames[face]
    c = sum(a * b for a, b in zip(fr[0], p))
    n = sum(a * b for a, b in zip(fr[1], p))
    e = sum(a * b for a, b in zip(fr[2], p))
    # sector (120 degrees, vertex to vertex) and the reduced azimuth
    az = math.atan2(e, n) % (2 * math.pi)
    sin_z = math.hypot(n, e)
    sector = 2 * math.pi / 3
    k = min(int(az / sector), 2)
    edge_gap = min(az - k * sector, (k + 1) * sector - az)
    if sin_z * edge_gap < _TIE:
        return None
    az -= k * sector
    sin_half_z = math.sqrt(0.5 * (n * n + e * e) / (1.0 + c))
    sp, cp = sector_forward(math.sin(az), math.cos(az), sin_half_z, MATH_OPS)
    x = sp * rot_c[k] + cp * rot_s[k]
    y = cp * rot_c[k] - sp * rot_s[k]
    chars = [FACE_LETTERS[face]]
    if level == 0:
        return chars[0]
    # level-1 triangle: planar azimuth // 60 degrees
    paz = math.atan2(x, y) % (2 * math.pi)
    d = min(int(paz * 3 / math.pi), 5)
    gap = min(paz - d * math.pi / 3, (d + 1) * math.pi / 3 - paz)
    if math.hypot(x, y) * gap < _TIE:
        return None
    chars.append(chr(48 + d))
    dx, dy = x - l1_c[d][0], y - l1_c[d][1]
    r = l1_rows[d]
    px, py = r[0][0] * dx + r[0][1] * dy, r[1][0] * dx + r[1][1] * dy
    margin = _TIE
    sqrt3 = math.sqrt(3.0)
    for _ in range(level - 1):
        s1 = sqrt3 * px + py - 1.0
        s2_ = sqrt3 * px - py - 1.0
        margin *= sqrt3
        if abs(s1) < margin or abs(s2_) < margin:
            return None
        child = 0 if s1 < 0 else (2 if s2_ > 0 else 1)
        chars.append(chr(48 + child))
        m, t = mats[child], offs[child]
        px, py = m[0][0] * px + m[0][1] * py + t[0], m[1][0] * px + m[1][1] * py + t[1]
    return "".join(chars)


# ----------------------------------------------------------------------------
# One cell's centre and corners, in floats (pure Python)
# ----------------------------------------------------------------------------
# These agree with the array paths to rounding (about 1e-15 rad, or 1e-7 of a
# cell at level 40); the centre always maps back to its cell.
_cell_tables = None


def _load_cell_tables():
    global _cell_tables
    if _cell_tables is None:
        from dggs.geometry import snyder, split26

        from . import _geo

        geo = _geo.ORIENTATION.geometry
        _cell_tables = (
            split26.LEVEL1.tolist(),
            split26.FACE_VERTICES[::-1].tolist(),
            geo.frames.tolist(),
            _geo.ELLIPSOID._to_geodetic.tolist(),
            snyder._ROT_COS.tolist(),
            snyder._ROT_SIN.tolist(),
        )
    return _cell_tables


def _corners(cell: str) -> list[tuple[float, float]]:
    """Face-frame corners of a valid id, counter-clockwise (thesis §6.1.7: D and E per level)."""
    level1, base, *_ = _load_cell_tables()
    if len(cell) == 1:
        return [tuple(v) for v in base]
    (ax, ay), (bx, by), (cx, cy) = level1[ord(cell[1]) - 48]
    for ch in cell[2:]:
        dx, dy = cx + (ax - cx) / 3.0, cy + (ay - cy) / 3.0  # D: a third of the way from C to A
        ex, ey = 0.5 * (ax + bx), 0.5 * (ay + by)  # E: the midpoint of AB
        if ch == "0":  # BCD
            ax, ay, bx, by = bx, by, dx, dy
        elif ch == "1":  # BDE
            ax, ay, bx, by, cx, cy = bx, by, dx, dy, ex, ey
        else:  # ADE
            bx, by, cx, cy = dx, dy, ex, ey
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0:
        return [(ax, ay), (bx, by), (cx, cy)]
    return [(ax, ay), (cx, cy), (bx, by)]


def planar_to_geodetic(face: int, x: float, y: float) -> tuple[float, float]:
    """Closed-form inverse Snyder of one face-frame point, then authalic -> geodetic latitude."""
    import math

    from dggs.geometry.snyder import MATH_OPS, _area_from_planar, _az_closed_sincos, sector_distance

    *_, frames, coeffs, rot_c, rot_s = _load_cell_tables()
    rho = math.hypot(x, y)
    ap = math.atan2(x, y) % (2 * math.pi)
    k = min(int(ap / (2 * math.pi / 3)), 2)
    rc, rs = rot_c[k], rot_s[k]
    if rho > 0:
        sin_a, cos_a = (x * rc - y * rs) / rho, (y * rc + x * rs) / rho
    else:
        sin_a, cos_a = 0.0, 1.0
    sin_az, cos_az = _az_closed_sincos(_area_from_planar(sin_a, cos_a), MATH_OPS)
    cos_z, sin_z = sector_distance(sin_az, cos_az, sin_a, cos_a, rho, MATH_OPS)
    ct, st = cos_az * rc - sin_az * rs, sin_az * rc + cos_az * rs
    c, n, e = frames[face]
    a, b, d = cos_z, sin_z * ct, sin_z * st
    px, py, pz = (a * c[i] + b * n[i] + d * e[i] for i in range(3))
    beta = math.atan2(pz, math.hypot(px, py))
    s2, c2 = math.sin(2 * beta), math.cos(2 * beta)
    b1 = b2 = 0.0
    for coef in reversed(coeffs):
        b1, b2 = 2 * c2 * b1 - b2 + coef, b1
    return math.degrees(beta + b1 * s2), math.degrees(math.atan2(py, px))


def cell_to_latlng(cell: str) -> tuple[float, float]:
    """Centre of a valid id: the image of its planar centroid."""
    pts = _corners(cell)
    return planar_to_geodetic(ord(cell[0]) - 65, sum(p[0] for p in pts) / 3.0, sum(p[1] for p in pts) / 3.0)


def cell_to_boundary(cell: str, densify: int) -> tuple[tuple[float, float], ...]:
    """Corners (and ``densify`` points per edge) of a valid id, counter-clockwise."""
    pts = _corners(cell)
    face = ord(cell[0]) - 65
    out = []
    for i in range(3):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % 3]
        for j in range(densify + 1):
            t = j / (densify + 1)
            out.append(planar_to_geodetic(face, x0 + t * (x1 - x0), y0 + t * (y1 - y0)))
    return tuple(out)
