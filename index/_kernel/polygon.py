"""Compiled circle-against-polygon tests for polygon fill: a uniform bucket grid over the polygon's edges.

:func:`build` sorts a polygon's edges (segments in one plane: lng/lat, or a
polar plane) into the buckets of a uniform grid over their bounding box.
:func:`classify` then decides, for circles of radius ``r`` around points,
whether each meets the polygon (``hit``) and whether it lies wholly inside
(``inside``): a circle within ``r`` of an edge (point-to-segment distance, the
buckets the circle's box overlaps) is a hit and not inside; any other lies
wholly on one side, decided by the crossing number of the ray to +x (the
buckets of the point's row, each crossing counted in the one bucket holding
it).  Away from the edges the parity is exact, so the boundary conventions of
point-in-polygon tests never matter here.  O(edges near the circle) a point.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from dggs.geometry._parallel import loops

__all__ = ["build", "classify"]


@njit(cache=True, nogil=True)
def build(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray, side: int) -> tuple[
    np.ndarray, np.ndarray, np.ndarray
]:
    """Bucket the segments on a ``side`` x ``side`` grid over their bounding box.

    Returns ``(frame, start, items)``: ``frame`` = (xmin, ymin, width, height of a
    bucket, side), ``items[start[b]:start[b + 1]]`` the segments overlapping bucket
    ``b = row * side + column``.
    """
    n = x0.shape[0]
    xmin = min(x0.min(), x1.min())
    ymin = min(y0.min(), y1.min())
    w = max((max(x0.max(), x1.max()) - xmin) / side, 1e-300)
    h = max((max(y0.max(), y1.max()) - ymin) / side, 1e-300)
    frame = np.array([xmin, ymin, w, h, float(side)])
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
    return frame, start, items


@njit(cache=True, nogil=True)
def _span(lo: float, hi: float, origin: float, size: float, side: int) -> tuple[int, int]:
    """Buckets (first, last) of an interval along one axis, clipped to the grid."""
    a = int(math.floor((lo - origin) / size))
    b = int(math.floor((hi - origin) / size))
    return min(max(a, 0), side - 1), min(max(b, 0), side - 1)


@njit(cache=True, nogil=True)
def _near(px: float, py: float, r: float, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray,
          frame: np.ndarray, start: np.ndarray, items: np.ndarray) -> bool:
    """Whether some segment lies within ``r`` of (px, py)."""
    side = int(frame[4])
    c0, c1 = _span(px - r, px + r, frame[0], frame[2], side)
    r0, r1 = _span(py - r, py + r, frame[1], frame[3], side)
    rr = r * r
    for row in range(r0, r1 + 1):
        for col in range(c0, c1 + 1):
            b = row * side + col
            for k in range(start[b], start[b + 1]):
                i = items[k]
                ex, ey = x1[i] - x0[i], y1[i] - y0[i]
                wx, wy = px - x0[i], py - y0[i]
                ee = ex * ex + ey * ey
                t = 0.0 if ee == 0.0 else min(1.0, max(0.0, (wx * ex + wy * ey) / ee))
                dx, dy = wx - t * ex, wy - t * ey
                if dx * dx + dy * dy <= rr:
                    return True
    return False


@njit(cache=True, nogil=True)
def _inside(px: float, py: float, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray,
            frame: np.ndarray, start: np.ndarray, items: np.ndarray) -> bool:
    """Crossing-number parity of the ray from (px, py) to +x (the point is off the edges)."""
    side = int(frame[4])
    xmin, ymin, w, h = frame[0], frame[1], frame[2], frame[3]
    if py < ymin or py > ymin + h * side or px > xmin + w * side:
        return False
    row = min(max(int(math.floor((py - ymin) / h)), 0), side - 1)
    first = min(max(int(math.floor((px - xmin) / w)), 0), side - 1)
    odd = False
    for col in range(first, side):
        b = row * side + col
        for k in range(start[b], start[b + 1]):
            i = items[k]
            if (y0[i] > py) != (y1[i] > py):
                xc = x0[i] + (py - y0[i]) * (x1[i] - x0[i]) / (y1[i] - y0[i])
                # each crossing counted in the one bucket that holds it (the same rounding as build)
                if xc > px and min(max(int(math.floor((xc - xmin) / w)), 0), side - 1) == col:
                    odd = not odd
    return odd


def _classify_impl(px: np.ndarray, py: np.ndarray, r: np.ndarray, x0: np.ndarray, y0: np.ndarray,
                   x1: np.ndarray, y1: np.ndarray, frame: np.ndarray, start: np.ndarray, items: np.ndarray,
                   hit: np.ndarray, inside: np.ndarray) -> None:
    """``hit[i]``: the circle of radius ``r[i]`` round point i meets the polygon; ``inside[i]``: lies wholly in it."""
    for i in prange(px.shape[0]):
        if _near(px[i], py[i], r[i], x0, y0, x1, y1, frame, start, items):
            hit[i], inside[i] = True, False
        else:
            c = _inside(px[i], py[i], x0, y0, x1, y1, frame, start, items)
            hit[i], inside[i] = c, c


classify = loops(_classify_impl)
