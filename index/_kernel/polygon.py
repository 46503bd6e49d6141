"""Compiled point- and circle-against-polygon tests for polygon fill: a uniform bucket grid over the polygon's edges.

:func:`build` sorts a polygon's edges (segments in one plane, lng/lat for
polygon fill) into the buckets of a uniform grid over their bounding box,
and records for each bucket the nearest bucket right of it that no edge
meets, and that one's side.
:func:`near` says whether some edge lies within ``r`` of a point (the
point-to-segment distance over the buckets the circle's box overlaps), in a
plane whose x axis may be scaled first (an ellipse is then a circle).
:func:`parity` locates a point by the crossing number of the ray to +x (over
the buckets of the point's row up to such an empty one, each edge counted
once), with the sign of every crossing decided by an orientation whose
rounding error is bounded: a point within that error of an edge is reported
as undecided (-1), never guessed.
So an answer of 1 (inside) or 0 (outside) is the exact one, the same as an
exact point-in-polygon test (GEOS's) gives; only points on or within about
1e-16 of an edge are left to one.  :func:`classify` combines the two for
circles (``hit``: meets the polygon; ``inside``: lies wholly in it).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit, prange

from dggs.geometry._parallel import loops

__all__ = ["ring_edges", "build", "near", "parity", "classify"]

#: Relative error bound of a 2x2 orientation determinant in doubles: Shewchuk 1997 ("Adaptive precision
#: floating-point arithmetic and fast robust geometric predicates"), ccwerrboundA = (3 + 16 eps) eps with
#: eps = 2**-53 is 3.3e-16; three times that for margin.
ORIENT_ERR = 1e-15
#: Below this sum of products the bound above could be lost to underflow: undecided.
_TINY = 1e-290
#: Options of the compiled functions that take the grid's arrays and allocate nothing: without numba's
#: runtime (``_nrt``), whose reference counts on each array argument of each call (atomic, in the prologue
#: and epilogue) took 18 % of polygon fill's time (perf; numba 0.68).
LEAN: dict[str, Any] = {"cache": True, "nogil": True, "_nrt": False}


@njit(cache=True, nogil=True)
def ring_edges(xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool]:
    """The edges (x0, y0, x1, y1) of closed rings laid end to end in ``xy``, and whether every ring closed.

    A ring ends at the next repeat of its first point: in a valid polygon a
    ring never passes through its first point again before closing (a ring
    touching itself is invalid), so this finds the rings exactly.
    """
    n = xy.shape[0]
    x0, y0, x1, y1 = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    m = 0
    i = 0
    while i < n:
        j = i + 1
        while j < n and not (xy[j, 0] == xy[i, 0] and xy[j, 1] == xy[i, 1]):
            j += 1
        if j == n:
            return x0[:m], y0[:m], x1[:m], y1[:m], False
        for k in range(i, j):
            x0[m], y0[m], x1[m], y1[m] = xy[k, 0], xy[k, 1], xy[k + 1, 0], xy[k + 1, 1]
            m += 1
        i = j + 1
    return x0[:m], y0[:m], x1[:m], y1[:m], True


@njit(cache=True, nogil=True)
def build(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray, side: int) -> tuple[
    np.ndarray, np.ndarray, np.ndarray, np.ndarray
]:
    """Bucket the segments on a ``side`` x ``side`` grid over their bounding box.

    Returns ``(frame, start, items, empty)``: ``frame`` = (xmin, ymin, width,
    height of a bucket, side, xmax, ymax), ``items[start[b]:start[b + 1]]`` the
    segments overlapping bucket ``b = row * side + column``, and ``empty[b]`` the
    first bucket column at or right of b's, in its row, that holds no segment
    (``side`` if none), plus ``side + 1`` times 1 if that bucket's centre lies
    inside the polygon (:func:`_empty_buckets`).
    """
    n = x0.shape[0]
    xmin = min(x0.min(), x1.min())
    ymin = min(y0.min(), y1.min())
    xmax = max(x0.max(), x1.max())
    ymax = max(y0.max(), y1.max())
    w = max((xmax - xmin) / side, 1e-300)
    h = max((ymax - ymin) / side, 1e-300)
    frame = np.array([xmin, ymin, w, h, float(side), xmax, ymax])
    count = np.zeros(side * side + 1, dtype=np.int64)
    for i in range(n):
        c0, c1 = _span(min(x0[i], x1[i]), max(x0[i], x1[i]), xmin, w, side)
        r0, r1 = _span(min(y0[i], y1[i]), max(y0[i], y1[i]), ymin, h, side)
        for r in range(r0, r1 + 1):
            for c in range(c0, c1 + 1):
                count[r * side + c + 1] += 1
    start = np.cumsum(count)
    fill = start[:-1].copy()
    items = np.empty(start[-1], dtype=np.int64)
    for i in range(n):
        c0, c1 = _span(min(x0[i], x1[i]), max(x0[i], x1[i]), xmin, w, side)
        r0, r1 = _span(min(y0[i], y1[i]), max(y0[i], y1[i]), ymin, h, side)
        for r in range(r0, r1 + 1):
            for c in range(c0, c1 + 1):
                items[fill[r * side + c]] = i
                fill[r * side + c] += 1
    return frame, start, items, _empty_buckets(x0, y0, x1, y1, frame, start, items)


@njit(cache=True, nogil=True)
def _empty_buckets(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray, frame: np.ndarray,
                   start: np.ndarray, items: np.ndarray) -> np.ndarray:
    """Per bucket, the next empty bucket of its row and whether that one's centre is inside (see :func:`build`).

    A row's crossings with the horizontal line through its buckets' centres,
    sorted, give each empty bucket's centre its crossing number.  No segment
    meets an empty bucket, so every crossing lies at least half a bucket from
    its centre, far beyond rounding, and every point of it shares its side.
    """
    side = int(frame[4])
    xmin, ymin, w, h = frame[0], frame[1], frame[2], frame[3]
    out = np.empty(side * side, dtype=np.int64)
    xs = np.empty(start[-1])
    for row in range(side):
        yc = ymin + (row + 0.5) * h
        m = 0
        for col in range(side):
            b = row * side + col
            for k in range(start[b], start[b + 1]):
                i = items[k]
                if (y0[i] > yc) != (y1[i] > yc) and _index(min(x0[i], x1[i]), xmin, w, side) == col:
                    xs[m] = x0[i] + (yc - y0[i]) * (x1[i] - x0[i]) / (y1[i] - y0[i])
                    m += 1
        crossings = np.sort(xs[:m])
        j = m
        nxt = side
        for col in range(side - 1, -1, -1):
            b = row * side + col
            xc = xmin + (col + 0.5) * w
            while j > 0 and crossings[j - 1] > xc:
                j -= 1
            if start[b] == start[b + 1]:
                nxt = col + (side + 1) * ((m - j) & 1)
            out[b] = nxt
    return out


@njit(cache=True, nogil=True, inline="always")
def _index(v: float, origin: float, size: float, side: int) -> int:
    """Bucket of a coordinate along one axis, clipped to the grid (monotone in ``v``)."""
    return min(max(int(math.floor((v - origin) / size)), 0), side - 1)


@njit(cache=True, nogil=True)
def _span(lo: float, hi: float, origin: float, size: float, side: int) -> tuple[int, int]:
    """Buckets (first, last) of an interval along one axis, clipped to the grid."""
    return _index(lo, origin, size, side), _index(hi, origin, size, side)


@njit(**LEAN)
def near(px: float, py: float, r: float, sx: float, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
         y1: np.ndarray, frame: np.ndarray, start: np.ndarray, items: np.ndarray) -> bool:
    """Whether some segment lies within ``r`` of (px, py) once x is multiplied by ``sx`` > 0.

    With ``sx = r / a`` this is the ellipse of semi-axes ``a`` along x and ``r``
    along y; with ``sx = 1`` the circle of radius ``r``.
    """
    if px + r / sx < frame[0] or px - r / sx > frame[5] or py + r < frame[1] or py - r > frame[6]:
        return False  # the ellipse's box misses the edges' box
    side = int(frame[4])
    c0, c1 = _span(px - r / sx, px + r / sx, frame[0], frame[2], side)
    r0, r1 = _span(py - r, py + r, frame[1], frame[3], side)
    rr = r * r
    for row in range(r0, r1 + 1):
        for col in range(c0, c1 + 1):
            b = row * side + col
            for k in range(start[b], start[b + 1]):
                i = items[k]
                ex, ey = (x1[i] - x0[i]) * sx, y1[i] - y0[i]
                wx, wy = (px - x0[i]) * sx, py - y0[i]
                ee = ex * ex + ey * ey
                t = 0.0 if ee == 0.0 else min(1.0, max(0.0, (wx * ex + wy * ey) / ee))
                dx, dy = wx - t * ex, wy - t * ey
                if dx * dx + dy * dy <= rr:
                    return True
    return False


@njit(**LEAN)
def parity(px: float, py: float, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray,
           frame: np.ndarray, start: np.ndarray, items: np.ndarray, empty: np.ndarray) -> int:
    """1 if (px, py) is inside the polygon, 0 if outside, -1 if it lies on or within rounding of an edge.

    The ray from the point to +x, up to the centre of the first bucket of its
    row at or right of its own that holds no segment (whose side is known,
    :func:`build`; without one, to infinity), crosses edge i when ``(y0 > py) !=
    (y1 > py)`` (the half-open rule: a vertex on the ray counts once) and the
    point and the ray's end lie on either side of it: the signs of the
    orientations of (edge start, edge end, point), trusted only when they
    exceed their error bound (:data:`ORIENT_ERR`).  An edge spanning several
    buckets of the row is counted in the first of them at or right of the
    point's.  An edge whose bounding box holds the point, found in the point's
    own bucket, makes the answer undecided when the point may lie on it
    (horizontal edges and vertices included).
    """
    if not (frame[0] <= px <= frame[5] and frame[1] <= py <= frame[6]):
        return 0  # outside the edges' bounding box (exact bounds): outside every ring
    side = int(frame[4])
    xmin, ymin, w, h = frame[0], frame[1], frame[2], frame[3]
    row = _index(py, ymin, h, side)
    first = _index(px, xmin, w, side)
    stop = empty[row * side + first]
    odd = stop > side  # the side of the stop bucket's centre
    stop = stop - (side + 1) if odd else stop
    if stop == first:
        return 1 if odd else 0  # no segment in the point's bucket: the side of its centre
    end = xmin + (stop + 0.5) * w if stop < side else np.inf
    for col in range(first, stop):
        b = row * side + col
        for k in range(start[b], start[b + 1]):
            i = items[k]
            ax, ay, bx, by = x0[i], y0[i], x1[i], y1[i]
            crosses = (ay > py) != (by > py)
            if crosses:
                if max(_index(min(ax, bx), xmin, w, side), first) != col:
                    continue  # counted in an earlier bucket of this row
            elif col != first or not (min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by)):
                continue  # neither crosses the ray nor can hold the point (exact comparisons)
            det = _orient(ax, ay, bx, by, px, py)
            if det == 0.0:
                return -1  # the point may lie on this edge
            # the crossing lies right of the point iff the point is left of an upward edge (right of a downward one)
            if crosses and (det > 0.0) == (by > ay):
                if end < np.inf:
                    beyond = _orient(ax, ay, bx, by, end, py)
                    if beyond == 0.0:
                        return -1  # cannot happen: the end is half a bucket off every edge
                    if (beyond > 0.0) == (by > ay):
                        continue  # the crossing lies beyond the ray's end
                odd = not odd
    return 1 if odd else 0


@njit(cache=True, nogil=True, inline="always")
def _orient(ax: float, ay: float, bx: float, by: float, px: float, py: float) -> float:
    """Orientation of (a, b, p): positive if p lies left of a -> b; 0.0 where rounding could flip its sign."""
    left = (ax - px) * (by - py)
    right = (ay - py) * (bx - px)
    det = left - right
    bound = ORIENT_ERR * (abs(left) + abs(right))
    if abs(det) <= bound or bound < _TINY:
        return 0.0
    return det


def _classify_impl(px: np.ndarray, py: np.ndarray, r: np.ndarray, x0: np.ndarray, y0: np.ndarray,
                   x1: np.ndarray, y1: np.ndarray, frame: np.ndarray, start: np.ndarray, items: np.ndarray,
                   empty: np.ndarray, hit: np.ndarray, inside: np.ndarray) -> None:
    """``hit[i]``: the circle of radius ``r[i]`` round point i meets the polygon; ``inside[i]``: lies wholly in it."""
    for i in prange(px.shape[0]):
        if near(px[i], py[i], r[i], 1.0, x0, y0, x1, y1, frame, start, items):
            hit[i], inside[i] = True, False
        else:
            c = parity(px[i], py[i], x0, y0, x1, y1, frame, start, items, empty) != 0  # -1 only within r of an edge
            hit[i], inside[i] = c, c


classify = loops(_classify_impl)
