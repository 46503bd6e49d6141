"""Compiled exact weights of polygons in cells: each polygon cut along cell edges in Snyder's face planes.

Snyder's projection is equal-area and maps every cell to a planar triangle
with straight edges (thesis §6.1.7): the area of a polygon's part inside a
cell is the planar area, in the cell's face plane, of the polygon clipped by
the cell's triangle, times one constant.  So :func:`pieces` finds, for each
polygon (a raster pixel, its edges densified by the caller), every cell of a
level it meets and the planar area they share, by descending the hierarchy:

* a polygon whose vertices all lie in one cell of the level lies wholly in it
  (cells are convex): one piece, its whole area;
* otherwise it is clipped (Sutherland-Hodgman against each child triangle, a
  convex window) from the smallest cell holding all its vertices down to the
  level; a triangle the polygon covers wholly gives all its descendants at the
  level, an equal share each (cells are congruent in the plane);
* a polygon across face edges is projected onto each face near it (Snyder's
  forward on that face: the sector formulas hold past the face's edges) and
  clipped by that face's triangle first, so each face keeps its own part.

Areas are planar, in the unit-sphere face frame; the caller scales them to
m² (:data:`FACE_AREA` is one face's planar area, 1/20 of the sphere).  The
polygons' edges are chords in the face plane: the caller densifies them.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from dggs.geometry import kernel as gk

from . import bits
from .points import encode_point, triangle

_FRAMES = gk.ISEA_FRAMES
_CENTRES = gk.ISEA_CENTRES
_FACE = gk.FACE_CORNERS_CCW
_L1 = gk.LEVEL1_CORNERS


def _face_area() -> float:
    x, y = _FACE[:, 0], _FACE[:, 1]
    return float(0.5 * abs(x[0] * (y[1] - y[2]) + x[1] * (y[2] - y[0]) + x[2] * (y[0] - y[1])))


#: Planar area of a face triangle in the unit-sphere face frame (a twentieth of the sphere's 4 pi).
FACE_AREA = _face_area()
#: Faces whose triangle may meet a polygon within this angle (radians) of one of its vertices: the face's
#: circumradius (37.38 degrees) and the largest polygon :func:`pieces` takes (:data:`MAX_RADIUS`).
MAX_RADIUS = math.radians(10.0)
_REACH = math.cos(math.radians(37.3774) + MAX_RADIUS + 1e-6)
#: A triangle whose clipped part is within this fraction of its area is covered wholly.
_WHOLE = 1.0 - 1e-12


@njit(cache=True, nogil=True)
def _area(x: np.ndarray, y: np.ndarray, n: int) -> float:
    """Signed shoelace area of the first ``n`` vertices, about the first one (for precision at fine levels)."""
    if n < 3:
        return 0.0
    x0, y0 = x[0], y[0]
    s = 0.0
    for i in range(1, n - 1):
        s += (x[i] - x0) * (y[i + 1] - y0) - (x[i + 1] - x0) * (y[i] - y0)
    return 0.5 * s


@njit(cache=True, nogil=True)
def _clip_edge(x, y, n, ax, ay, bx, by, ox, oy) -> int:
    """The vertices of polygon (x, y)[:n] left of the directed line a -> b, into (ox, oy); their count."""
    m = 0
    if n == 0:
        return 0
    px, py = x[n - 1], y[n - 1]
    pin = (bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0.0
    for i in range(n):
        qx, qy = x[i], y[i]
        qin = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax) >= 0.0
        if qin != pin:  # the edge p -> q crosses the line: its crossing point
            dpx, dpy = qx - px, qy - py
            den = (bx - ax) * dpy - (by - ay) * dpx
            t = ((ax - px) * (by - ay) - (ay - py) * (bx - ax)) / den if den != 0.0 else 0.0
            t = min(max(-t, 0.0), 1.0)
            ox[m] = px + t * dpx
            oy[m] = py + t * dpy
            m += 1
        if qin:
            ox[m] = qx
            oy[m] = qy
            m += 1
        px, py, pin = qx, qy, qin
    return m


@njit(cache=True, nogil=True)
def _clip(x, y, n, ax, ay, bx, by, cx, cy, ox, oy, tx, ty) -> int:
    """Polygon (x, y)[:n] clipped by the triangle (a, b, c) (any orientation) into (ox, oy); the count."""
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0.0:  # make it counter-clockwise
        bx, by, cx, cy = cx, cy, bx, by
    m = _clip_edge(x, y, n, ax, ay, bx, by, tx, ty)
    m = _clip_edge(tx, ty, m, bx, by, cx, cy, ox, oy)
    return _clip_edge(ox, oy, m, cx, cy, ax, ay, tx, ty) if m else 0


@njit(cache=True, nogil=True)
def _child(cell: np.uint64, level: int, digit: int) -> np.uint64:
    """Child ``digit`` of a cell at ``level`` (6 children of a face, 3 below)."""
    return cell | (np.uint64(digit + 1) << bits.SHIFTS[level + 1])


@njit(cache=True, nogil=True)
def _grow(p, c, a, n, need):
    if n + need <= p.shape[0]:
        return p, c, a
    size = max(2 * p.shape[0], n + need)
    p2, c2, a2 = np.empty(size, np.int64), np.empty(size, np.uint64), np.empty(size, np.float64)
    p2[:n], c2[:n], a2[:n] = p[:n], c[:n], a[:n]
    return p2, c2, a2


@njit(cache=True, nogil=True)
def _whole(cell, level, target, area, pixel, p, c, a, n):
    """Every descendant of ``cell`` at ``target``, ``area`` shared equally."""
    count = 3 ** (target - level)
    p, c, a = _grow(p, c, a, n, count)
    share = area / count
    for k in range(count):
        cid = cell
        rest = k
        for lv in range(target, level, -1):  # base-3 digits, the finest last
            cid |= np.uint64(rest % 3 + 1) << bits.SHIFTS[lv]
            rest //= 3
        p[n], c[n], a[n] = pixel, cid, share
        n += 1
    return p, c, a, n


@njit(cache=True, nogil=True)
def _split(x, y, n, ax, ay, bx, by, lx, ly, rx, ry):
    """Polygon (x, y)[:n] cut by the line a -> b: its part left of the line into (lx, ly), right into (rx, ry).

    One pass for two clips (Sutherland-Hodgman against both half-planes); returns both counts.
    """
    nl = 0
    nr = 0
    if n == 0:
        return 0, 0
    px, py = x[n - 1], y[n - 1]
    ps = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
    for i in range(n):
        qx, qy = x[i], y[i]
        qs = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax)
        if (ps > 0.0 and qs < 0.0) or (ps < 0.0 and qs > 0.0):  # the edge crosses the line: both sides get it
            t = ps / (ps - qs)
            ix, iy = px + t * (qx - px), py + t * (qy - py)
            lx[nl], ly[nl] = ix, iy
            rx[nr], ry[nr] = ix, iy
            nl += 1
            nr += 1
        if qs >= 0.0:
            lx[nl], ly[nl] = qx, qy
            nl += 1
        if qs <= 0.0:
            rx[nr], ry[nr] = qx, qy
            nr += 1
        px, py, ps = qx, qy, qs
    return nl, nr


@njit(cache=True, nogil=True)
def _children(level, t, x, y, n, kx, ky, kn, tx, ty):
    """The parts of polygon (x, y)[:n] in each child of triangle ``t`` (ax, ay, bx, by, cx, cy) into kx, ky, kn.

    A face (level 0) has 6 children, each clipped; a finer cell's 3 are cut apart by two lines: child 0
    (B, D, C) lies on C's side of BD, child 2 (A, D, E) on A's side of DE, child 1 between
    (:func:`dggs.geometry.kernel.child_corners`: D a third of the way from C to A, E the midpoint of AB).
    """
    if level == 0:
        for j in range(6):
            kn[j] = _clip(x, y, n, _L1[j, 0, 0], _L1[j, 0, 1], _L1[j, 1, 0], _L1[j, 1, 1], _L1[j, 2, 0],
                          _L1[j, 2, 1], kx[j], ky[j], tx, ty)
            kx[j, :kn[j]], ky[j, :kn[j]] = tx[:kn[j]], ty[:kn[j]]
        return
    ax, ay, bx, by, cx, cy = t[0], t[1], t[2], t[3], t[4], t[5]
    dx, dy = cx + (ax - cx) / 3.0, cy + (ay - cy) / 3.0
    ex, ey = 0.5 * (ax + bx), 0.5 * (ay + by)
    left, right = _split(x, y, n, bx, by, dx, dy, kx[0], ky[0], tx, ty)  # left into child 0's place
    if (dx - bx) * (cy - by) - (dy - by) * (cx - bx) >= 0.0:  # C lies left of B -> D: child 0 is the left part
        kn[0] = left
        kx[1, :right], ky[1, :right] = tx[:right], ty[:right]  # the rest, in child 1's place for now
        rest = right
    else:
        kx[1, :left], ky[1, :left] = kx[0, :left], ky[0, :left]
        kx[0, :right], ky[0, :right] = tx[:right], ty[:right]
        kn[0] = right
        rest = left
    left, right = _split(kx[1], ky[1], rest, dx, dy, ex, ey, kx[2], ky[2], tx, ty)  # left into child 2's place
    if (ex - dx) * (ay - dy) - (ey - dy) * (ax - dx) >= 0.0:  # A lies left of D -> E: child 2 is the left part
        kn[2] = left
        kx[1, :right], ky[1, :right] = tx[:right], ty[:right]
        kn[1] = right
    else:
        kx[1, :left], ky[1, :left] = kx[2, :left], ky[2, :left]
        kn[1] = left
        kx[2, :right], ky[2, :right] = tx[:right], ty[:right]
        kn[2] = right


@njit(cache=True, nogil=True)
def _descend(root, root_level, corners, target, px, py, nv, pixel, p, c, a, n, kx, ky, kn, tx, ty, tri, ids, nxt):
    """Pieces of polygon (px, py)[:nv] inside cell ``root`` (corners ax, ay, bx, by, cx, cy) down to ``target``.

    Depth first, each node's children cut at once (:func:`_children`).  The rest is scratch:
    ``kx``, ``ky`` (levels + 2, 6, width), ``kn`` (levels + 2, 6), ``tx``, ``ty`` (width), width >=
    nv + 3 (levels + 2); ``tri`` (levels + 2, 6), ``ids``, ``nxt`` (levels + 2).
    """
    tri[0, :6] = corners
    ids[0] = root
    _children(root_level, tri[0], px, py, nv, kx[0], ky[0], kn[0], tx, ty)
    nxt[0] = 0
    d = 0
    while d >= 0:
        level = root_level + d
        if nxt[d] == (6 if level == 0 else 3):
            d -= 1
            continue
        digit = nxt[d]
        nxt[d] += 1
        m = kn[d, digit]
        got = abs(_area(kx[d, digit], ky[d, digit], m))
        if got <= 0.0:
            continue
        cell = _child(ids[d], level, digit)
        if level + 1 == target:
            p, c, a = _grow(p, c, a, n, 1)
            p[n], c[n], a[n] = pixel, cell, got
            n += 1
            continue
        if level == 0:
            ax, ay, bx, by, cx, cy = (_L1[digit, 0, 0], _L1[digit, 0, 1], _L1[digit, 1, 0], _L1[digit, 1, 1],
                                      _L1[digit, 2, 0], _L1[digit, 2, 1])
        else:
            t = tri[d]
            ax, ay, bx, by, cx, cy = gk.child_corners(t[0], t[1], t[2], t[3], t[4], t[5], digit)
        if got >= _WHOLE * 0.5 * abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)):
            p, c, a, n = _whole(cell, level + 1, target, got, pixel, p, c, a, n)
            continue
        tri[d + 1, 0], tri[d + 1, 1], tri[d + 1, 2], tri[d + 1, 3], tri[d + 1, 4], tri[d + 1, 5] = (
            ax, ay, bx, by, cx, cy)
        ids[d + 1] = cell
        _children(level + 1, tri[d + 1], kx[d, digit], ky[d, digit], m, kx[d + 1], ky[d + 1], kn[d + 1], tx, ty)
        nxt[d + 1] = 0
        d += 1
    return p, c, a, n


@njit(cache=True, nogil=True)
def chord_errors(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    """Per pixel, the fraction of its area its edges' chords leave out (one point an edge).

    ``lat``, ``lng`` (N, 8): a pixel's corners and edge midpoints in turn, round it.  An edge
    whose midpoint lies ``s`` off its chord leaves out ``2/3 s L`` (a parabola's segment); the
    largest in the face planes of the faces its points lie on (each draws it with its own curvature).
    """
    out = np.zeros(lat.shape[0])
    ux, uy, uz = np.empty(8), np.empty(8), np.empty(8)
    faces = np.empty(8, np.int64)
    x, y = np.empty(8), np.empty(8)
    for i in range(lat.shape[0]):
        for j in range(8):
            ux[j], uy[j], uz[j] = gk.geodetic_to_unit(lat[i, j], lng[i, j])
            faces[j] = gk.nearest_face(_CENTRES, ux[j], uy[j], uz[j])
        for j in range(8):
            f = faces[j]
            if j > 0 and f in faces[:j]:
                continue
            for q in range(8):
                x[q], y[q] = gk.face_forward(_FRAMES, f, ux[q], uy[q], uz[q])
            area = 0.0
            lost = 0.0
            for e in range(4):
                a, m, b = 2 * e, 2 * e + 1, (2 * e + 2) % 8
                area += x[a] * y[b] - x[b] * y[a]
                lost += 2.0 / 3.0 * math.hypot(x[m] - 0.5 * (x[a] + x[b]), y[m] - 0.5 * (y[a] + y[b])) * math.hypot(
                    x[b] - x[a], y[b] - y[a])
            if area != 0.0:
                out[i] = max(out[i], lost / abs(0.5 * area))
    return out


@njit(cache=True, nogil=True)
def _common(cells: np.ndarray, count: int, target: int) -> int:
    """The finest level at which the cells share an ancestor (they are on one face)."""
    for lv in range(1, target + 1):
        first = bits.parent_at(cells[0], lv)
        for i in range(1, count):
            if bits.parent_at(cells[i], lv) != first:
                return lv - 1
    return target


@njit(cache=True, nogil=True)
def _ring(r, col, k, hu, vu, ring):
    """Indices into the flattened point arrays of pixel (r, col)'s ring: top, right, bottom, left edges."""
    hw = hu.shape[1]
    vw = vu.shape[1]
    m = 0
    for j in range(k):  # top edge, left to right
        ring[m] = r * hw + col * k + j
        m += 1
    for j in range(k):  # right edge, top to bottom (vertical points follow the horizontal ones)
        ring[m] = hu.size + (r * k + j) * vw + col + 1
        m += 1
    for j in range(k):  # bottom edge, right to left
        ring[m] = (r + 1) * hw + (col + 1) * k - j
        m += 1
    for j in range(k):  # left edge, bottom to top
        ring[m] = hu.size + ((r + 1) * k - j) * vw + col
        m += 1
    return m


@njit(cache=True, nogil=True)
def grid_pieces(hlat, hlng, vlat, vlng, k: int, valid: np.ndarray, target: int):
    """Cells at level ``target`` met by each pixel of a grid, and the planar area they share.

    The pixels' edges, densified with ``k`` points each: ``hlat``, ``hlng``
    (R + 1, C k + 1) along the R + 1 grid lines of constant row, ``vlat``,
    ``vlng`` (R k + 1, C + 1) along the C + 1 of constant column (degrees,
    WGS84; each corner in both).  Pixel (r, c) is number ``r C + c``; pixels
    where ``valid`` (R, C) is False are left out.  Returns ``(pixel, cell,
    area)``, each pixel's pieces together in pixel order, areas in the
    unit-sphere face plane (:data:`FACE_AREA` a face).  A pixel must lie within
    :data:`MAX_RADIUS` of its corners.
    """
    rows, cols = valid.shape
    npts = hlat.size + vlat.size
    ux, uy, uz = np.empty(npts), np.empty(npts), np.empty(npts)
    fx, fy = np.empty(npts), np.empty(npts)
    faces = np.empty(npts, np.int64)
    cells = np.empty(npts, np.uint64)
    hl, hg, vl, vg = hlat.ravel(), hlng.ravel(), vlat.ravel(), vlng.ravel()
    for i in range(npts):  # every point once: shared by the pixels on both sides
        la, lo = (hl[i], hg[i]) if i < hl.size else (vl[i - hl.size], vg[i - hl.size])
        ux[i], uy[i], uz[i] = gk.geodetic_to_unit(la, lo)
        faces[i] = gk.nearest_face(_CENTRES, ux[i], uy[i], uz[i])
        fx[i], fy[i] = gk.face_forward(_FRAMES, faces[i], ux[i], uy[i], uz[i])
        cells[i] = encode_point(faces[i], fx[i], fy[i], target)
    m = 4 * k
    width = m + 3 * (target + 4) + 8
    ring = np.empty(m, np.int64)
    px, py = np.empty(width), np.empty(width)
    rc = np.empty(m, np.uint64)
    kx, ky = np.empty((target + 3, 6, width)), np.empty((target + 3, 6, width))
    kn = np.zeros((target + 3, 6), np.int64)
    tx, ty = np.empty(width), np.empty(width)
    qx, qy = np.empty(width), np.empty(width)
    tri6 = np.empty((target + 3, 6))
    ids = np.empty(target + 3, np.uint64)
    nxt = np.zeros(target + 3, np.int64)
    near = np.zeros(_CENTRES.shape[0], np.bool_)
    face_tri = np.array([_FACE[0, 0], _FACE[0, 1], _FACE[1, 0], _FACE[1, 1], _FACE[2, 0], _FACE[2, 1]])
    p = np.empty(max(16, 2 * rows * cols), np.int64)
    c = np.empty(p.shape[0], np.uint64)
    a = np.empty(p.shape[0], np.float64)
    n = 0
    for r in range(rows):
        for col in range(cols):
            if not valid[r, col]:
                continue
            pixel = r * cols + col
            _ring(r, col, k, hlat, vlat, ring)
            f = faces[ring[0]]
            one_face = True
            one_cell = True
            for j in range(m):
                q = ring[j]
                px[j], py[j], rc[j] = fx[q], fy[q], cells[q]
                if faces[q] != f:
                    one_face = False
                if cells[q] != rc[0]:
                    one_cell = False
            if one_face:
                if one_cell:  # every vertex in one cell: the pixel lies in it (cells are convex)
                    got = abs(_area(px, py, m))
                    if got > 0.0:
                        p, c, a = _grow(p, c, a, n, 1)
                        p[n], c[n], a[n] = pixel, rc[0], got
                        n += 1
                    continue
                level = _common(rc, m, target)
                root = bits.parent_at(rc[0], level)
                tri = face_tri if level == 0 else np.array(triangle(root)[1:])
                p, c, a, n = _descend(root, level, tri, target, px, py, m, pixel, p, c, a, n, kx, ky, kn, tx, ty, tri6,
                                      ids, nxt)
                continue
            for g in range(_CENTRES.shape[0]):  # across face edges: every face near a vertex
                near[g] = False
                for j in range(m):
                    q = ring[j]
                    if ux[q] * _CENTRES[g, 0] + uy[q] * _CENTRES[g, 1] + uz[q] * _CENTRES[g, 2] >= _REACH:
                        near[g] = True
                        break
            for g in range(_CENTRES.shape[0]):
                if not near[g]:
                    continue
                for j in range(m):
                    q = ring[j]
                    px[j], py[j] = gk.face_forward(_FRAMES, g, ux[q], uy[q], uz[q])
                got_n = _clip(px, py, m, face_tri[0], face_tri[1], face_tri[2], face_tri[3], face_tri[4],
                              face_tri[5], qx, qy, tx, ty)
                got = abs(_area(tx, ty, got_n))
                if got <= 0.0:
                    continue
                if target == 0:
                    p, c, a = _grow(p, c, a, n, 1)
                    p[n], c[n], a[n] = pixel, bits.base_cell(g), got
                    n += 1
                    continue
                px[:got_n], py[:got_n] = tx[:got_n], ty[:got_n]
                p, c, a, n = _descend(bits.base_cell(g), 0, face_tri, target, px, py, got_n, pixel, p, c, a, n,
                                      kx, ky, kn, tx, ty, tri6, ids, nxt)
    return p[:n], c[:n], a[:n]
