"""Whether a line between samples in two edge-neighbouring cells crosses only their shared edge (the tracer's test).

:func:`dggs.index._kernel.line_trace.trace` samples each geodesic every half
short edge.  Two consecutive samples in cells that share an edge do not prove
that the line went straight across it: passing near an end of that edge it
can clip the cells on the other side of the corner (at a corner of 4 cells,
A -> C -> D -> B).  :func:`clear` decides, in the face plane where the
samples were located, whether the line cannot have done so; where it is
not sure the tracer bisects the span, which costs one located point.

The bound on the line's bend: in the face plane the image of a geodesic is
not straight.  Within one of Snyder's six sectors of a face it curves
gently (its curvature scaled by the step length, vanishing for short steps),
but where it crosses a sector boundary the projection's derivative jumps and
the image has a kink, whose offset from the chord scales with the chord's
length L.  Measured over 1.2 million great-circle arcs of 1e-4 to 0.3 rad
(16 interior points each, random places and directions, on one face), the
largest distance from the chord was 0.137 L on ISEA and 0.068 L on IVEA,
the same from 1e-4 to 0.01 rad (the kink), less at 0.3 rad.  :data:`BEND` is
0.25: a false alarm only costs a bisection.  The floor covers the
interpolation's 0.1 mm and rounding.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import bits
from .points import triangle

__all__ = ["BEND", "clear", "corner_clear", "corners6", "crosses", "dist_to_segment"]

#: Bound on how far the face-plane image of a geodesic strays from its chord, as a fraction of the
#: chord's length (the module's measurement: at most 0.137 on ISEA, 0.068 on IVEA).
BEND = 0.25
#: Absolute floor of the bend bound (plane units of the unit sphere: 0.6 mm, over the interpolation's 0.1 mm).
_BEND_FLOOR = 1e-10


@njit(cache=True, nogil=True)
def dist_to_segment(px: float, py: float, x0: float, y0: float, x1: float, y1: float) -> float:
    """The distance from point (px, py) to the segment (x0, y0) - (x1, y1) in the plane."""
    dx, dy = x1 - x0, y1 - y0
    ll = dx * dx + dy * dy
    t = 0.0 if ll == 0.0 else max(0.0, min(1.0, ((px - x0) * dx + (py - y0) * dy) / ll))
    ex, ey = x0 + t * dx - px, y0 + t * dy - py
    return math.sqrt(ex * ex + ey * ey)


@njit(cache=True, nogil=True)
def clear(a: np.uint64, b: np.uint64, fa: int, xa: float, ya: float, fb: int, xb: float, yb: float) -> bool:
    """Whether the line from a sample in ``a`` to one in ``b`` (edge neighbours) crosses only their shared edge.

    In the face plane the samples (xa, ya) and (xb, yb) join by a chord of
    length L; the line's image strays at most ``eps = BEND * L`` from it
    (plus a floor).  With P, Q the shared edge's ends, the chord must cross
    PQ at X, P and Q must be more than eps from the chord (so the line
    cannot pass round either end into the cells beyond), and X more than
    ``2 eps`` from both (the cells' angles at P and Q are 30, 60 or 90
    degrees, so X is then more than eps from the lines of ``a``'s and
    ``b``'s other edges: the line, near X, cannot clip them).  False where the
    samples are on different faces, or anything is in doubt: the caller
    then bisects, which only costs a point.
    """
    if fa < 0 or fa != fb or bits.face_of(a) != fa or bits.face_of(b) != fb:
        return False
    return crosses(corners6(a), corners6(b), xa, ya, xb, yb)


@njit(cache=True, nogil=True)
def corners6(cell: np.uint64):
    """The planar corners of a cell as six numbers (:func:`dggs.index._kernel.points.triangle`'s, without the face)."""
    _, a0x, a0y, a1x, a1y, a2x, a2y = triangle(cell)
    return a0x, a0y, a1x, a1y, a2x, a2y


@njit(cache=True, nogil=True)
def crosses(ta, tb, xa: float, ya: float, xb: float, yb: float) -> bool:
    """:func:`clear`'s test on the corners ``ta`` and ``tb`` (:func:`corners6`) of two cells on the samples' face."""
    a0x, a0y, a1x, a1y, a2x, a2y = ta
    b0x, b0y, b1x, b1y, b2x, b2y = tb
    # a's corner that is not b's is the one farthest from all of b's corners
    far = -1.0
    rx, ry = 0.0, 0.0
    px, py, qx, qy = 0.0, 0.0, 0.0, 0.0
    for i in range(3):
        cx, cy = (a0x, a0y) if i == 0 else ((a1x, a1y) if i == 1 else (a2x, a2y))
        d = min((cx - b0x) ** 2 + (cy - b0y) ** 2, (cx - b1x) ** 2 + (cy - b1y) ** 2, (cx - b2x) ** 2 + (cy - b2y) ** 2)
        if d > far:
            far = d
            rx, ry = cx, cy
    first = True
    for i in range(3):
        cx, cy = (a0x, a0y) if i == 0 else ((a1x, a1y) if i == 1 else (a2x, a2y))
        if cx == rx and cy == ry:
            continue
        if first:
            px, py = cx, cy
            first = False
        else:
            qx, qy = cx, cy
    ex, ey = qx - px, qy - py
    d0 = ex * (ya - py) - ey * (xa - px)
    d1 = ex * (yb - py) - ey * (xb - px)
    if d0 * d1 > 0.0 or d0 == d1:  # the chord does not cross PQ's line
        return False
    t = d0 / (d0 - d1)
    cx, cy = xa + t * (xb - xa), ya + t * (yb - ya)  # X
    ln = math.sqrt((xb - xa) ** 2 + (yb - ya) ** 2)
    eps = BEND * ln + _BEND_FLOOR
    if math.sqrt((cx - px) ** 2 + (cy - py) ** 2) <= 2.0 * eps or math.sqrt((cx - qx) ** 2 + (cy - qy) ** 2) <= 2.0 * eps:
        return False
    if (cx - px) * ex + (cy - py) * ey <= 0.0 or (cx - qx) * ex + (cy - qy) * ey >= 0.0:  # X beyond P or Q
        return False
    return dist_to_segment(px, py, xa, ya, xb, yb) > eps and dist_to_segment(qx, qy, xa, ya, xb, yb) > eps


@njit(cache=True, nogil=True)
def corner_clear(a: np.uint64, b: np.uint64, fa: int, xa: float, ya: float, fb: int, xb: float, yb: float) -> bool:
    """Whether the line from a sample in ``a`` to one in ``b`` (cells meeting at one corner V) stays clear of V.

    The tracer joins such cells through their one common edge neighbour
    (the shortcut) when they are at most a step apart; the line could go
    round V the other way only by passing V closer than its bend, ``BEND``
    times the chord (the cells the other way span 180 degrees or more).
    False where the samples are on different faces or the chord passes
    within that of V: the caller then bisects.
    """
    if fa < 0 or fa != fb or bits.face_of(a) != fa or bits.face_of(b) != fb:
        return False
    _, a0x, a0y, a1x, a1y, a2x, a2y = triangle(a)
    _, b0x, b0y, b1x, b1y, b2x, b2y = triangle(b)
    best = -1.0
    vx, vy = 0.0, 0.0
    for i in range(3):
        cx, cy = (a0x, a0y) if i == 0 else ((a1x, a1y) if i == 1 else (a2x, a2y))
        d = min((cx - b0x) ** 2 + (cy - b0y) ** 2, (cx - b1x) ** 2 + (cy - b1y) ** 2, (cx - b2x) ** 2 + (cy - b2y) ** 2)
        if best < 0.0 or d < best:
            best = d
            vx, vy = cx, cy
    eps = BEND * math.sqrt((xb - xa) ** 2 + (yb - ya) ** 2) + _BEND_FLOOR
    return dist_to_segment(vx, vy, xa, ya, xb, yb) > eps
