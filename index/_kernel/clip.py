"""Compiled clipping of polygons by the cells of the hierarchy, in one face plane (for :mod:`.pixels`).

A polygon inside a cell is cut into its parts in the cell's children, depth
first, down to a target level (:func:`descend`): a face's six children by
Sutherland-Hodgman clips against each triangle, a finer cell's three by two
cuts along the lines that part them (:func:`dggs.geometry.kernel.child_corners`).
Each part's planar area is a piece; a child the polygon covers wholly gives
all its descendants at the target level an equal share (cells are congruent
in the plane).  Areas are shoelace sums about a vertex of the polygon, for
precision at fine levels.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from dggs.geometry import kernel as gk

from . import bits

__all__ = ["area", "clip", "descend", "grow"]

_L1 = gk.LEVEL1_CORNERS
#: A triangle whose clipped part is within this fraction of its area is covered wholly.
_WHOLE = 1.0 - 1e-12


@njit(cache=True, nogil=True)
def area(x: np.ndarray, y: np.ndarray, n: int) -> float:
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
def clip(x, y, n, ax, ay, bx, by, cx, cy, ox, oy, tx, ty) -> int:
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
def grow(p, c, a, n, need):
    if n + need <= p.shape[0]:
        return p, c, a
    size = max(2 * p.shape[0], n + need)
    p2, c2, a2 = np.empty(size, np.int64), np.empty(size, np.uint64), np.empty(size, np.float64)
    p2[:n], c2[:n], a2[:n] = p[:n], c[:n], a[:n]
    return p2, c2, a2


@njit(cache=True, nogil=True)
def _whole(cell, level, target, total, pixel, p, c, a, n):
    """Every descendant of ``cell`` at ``target``, ``area`` shared equally."""
    count = 3 ** (target - level)
    p, c, a = grow(p, c, a, n, count)
    share = total / count
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
            kn[j] = clip(x, y, n, _L1[j, 0, 0], _L1[j, 0, 1], _L1[j, 1, 0], _L1[j, 1, 1], _L1[j, 2, 0],
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
def descend(root, root_level, corners, target, px, py, nv, pixel, p, c, a, n, kx, ky, kn, tx, ty, tri, ids, nxt):
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
        got = abs(area(kx[d, digit], ky[d, digit], m))
        if got <= 0.0:
            continue
        cell = _child(ids[d], level, digit)
        if level + 1 == target:
            p, c, a = grow(p, c, a, n, 1)
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
