"""Compiled polygon fill: the whole descent through the levels for one polygon, depth first, in id order.

:func:`descend` walks the hierarchy from the 20 base cells, carrying each
cell's planar corners down (one :func:`dggs.geometry.kernel.child_corners`
a level).  A cell is classified by its footprint: every point of a level-l
cell lies within the arc :data:`RHO` [l] of its footprint centre (below),
which bounds its latitudes and longitudes by an ellipse round that centre in
the lng/lat plane.  The polygon's edges sit in the bucket grid of
:mod:`.polygon`: an ellipse that meets no edge lies wholly inside the polygon
(its centre inside) or wholly outside.  Cells wholly inside are emitted
whole, cells outside dropped, the others descended.  In ``"center"`` mode
every descendant at the target level of a cell ``direct`` levels above it
is tested by its centre, computed exactly as :func:`.points.centres` does,
with the exact crossing parity of :func:`.polygon.parity` (the few centres
within rounding of an edge are flagged for GEOS); in the other modes the
boundary cells at the target level are flagged for the caller's test of
their polygons.  Depth first, children in digit order: the output comes out
sorted.

The footprint bound.  A level-l cell is the image under Snyder's inverse of
a planar triangle that lies within ``d_l`` of its footprint centre (for a
base cell its centroid, for a finer one the middle of its hypotenuse,
:func:`_rho_table`).  The inverse stretches no planar length by more than
its largest scale factor, 1.1633 (Snyder 1992: the icosahedral projection's
largest angular deformation is 17.27 degrees; for an equal-area map the
larger scale is ``sqrt((1 + s) / (1 - s))`` with ``s = sin(17.27 / 2)``), so
the arc from that centre to any point of the cell is at most ``rho_l = 1.17
d_l`` (tests/index/kernel/test_kfill.py measures 0.990 of it at worst).
Within that cap the authalic latitude moves at most ``rho_l`` and the
geodetic one at most :data:`K_LAT` times that (WGS84's largest
d(phi)/d(beta) is 1.00449); by the haversine formula, with ``c*`` the cosine
of the cap's largest latitude, ``sin^2(dbeta/2) + c*^2 sin^2(dlng/2) <=
sin^2(rho/2)``, and since ``sin(x/2)`` is concave this gives the ellipse of
semi-axes ``K_LAT rho`` (latitude) and ``2 asin(sin(rho/2) / c*)``
(longitude).  A cap holding a pole (``c* <= sin(rho/2)``) is bounded by its
latitudes only, and never wholly inside.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from dggs.geometry import kernel as gk

from . import bits
from .hierarchy import n_desc
from .polygon import LEAN, near, parity

__all__ = [
    "descend", "first_over", "centre", "footprint", "ellipse", "RHO", "OK", "TOO_MANY", "SURE", "CENTRE", "EDGE",
]

_FRAMES = gk.ISEA_FRAMES
_FACE = gk.FACE_CORNERS_CCW
_L1 = gk.LEVEL1_CORNERS

#: The largest scale factor of Snyder's inverse on a face, rounded up (1.1633: module docstring).
K_INV = 1.17
#: The largest ratio of geodetic to authalic latitude change on WGS84 (1.00449), rounded up.
K_LAT = 1.005


def _rho_table() -> np.ndarray:
    """RHO[l]: the largest arc (radians) from a level-l cell's footprint centre (:func:`footprint`) to its points.

    A base cell's farthest point from its centre is a corner; a finer cell is a
    30-60-90 triangle whose smallest enclosing circle is centred on the
    middle of its hypotenuse AB (the first two corners, as the level-1
    triangles and :func:`dggs.geometry.kernel.child_corners` order them), half
    the hypotenuse across.
    """
    d = np.empty(bits.MAX_LEVEL + 1)
    d[0] = np.hypot(*(_FACE - _FACE.mean(axis=0)).T).max()
    d[1:] = 0.5 * np.hypot(*(_L1[:, 0] - _L1[:, 1]).T).max() / np.sqrt(3.0) ** np.arange(bits.MAX_LEVEL)
    return K_INV * d * (1.0 + 1e-9)


RHO = _rho_table()
_SIN_HALF = np.sin(0.5 * RHO)
_COS = np.cos(RHO)
_SIN = np.sin(RHO)
_RHO_DEG = np.degrees(RHO)
#: Semi-axis in latitude (geodetic degrees) of a level's footprint ellipse.
_A_LAT = K_LAT * _RHO_DEG

#: Room for the depth-first stack: at most 5 + 2 a level siblings wait beside the 20 base cells.
_STACK = 128

#: Status of :func:`descend`: done, or stopped by a count over the limit.
OK, TOO_MANY = 0, 1
#: Flags of the cells found: certain, centre on an edge (left to GEOS), boundary cell at the level (left to the caller).
SURE, CENTRE, EDGE = 0, 1, 2


@njit(cache=True, nogil=True)
def _on_globe(face: int, x: float, y: float):
    ux, uy, uz = gk.inverse_unit(_FRAMES, face, x, y)
    lat, lng = gk.unit_to_geodetic(ux, uy, uz)
    return lat, lng, ux, uy, uz


@njit(cache=True, nogil=True)
def centre(face: int, lv: int, ax: float, ay: float, bx: float, by: float, cx: float, cy: float):
    """(lat, lng, unit vector) of the cell with these planar corners, exactly as ``points._one_centre``."""
    if lv > 0 and not ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0.0):
        bx, by, cx, cy = cx, cy, bx, by  # counter-clockwise first, as points.corners orders them
    return _on_globe(face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0)


@njit(cache=True, nogil=True)
def footprint(face: int, lv: int, ax: float, ay: float, bx: float, by: float, cx: float, cy: float):
    """(lat, lng, unit vector) of the centre of a cell's footprint: the middle of AB, the face's centre at level 0."""
    if lv == 0:
        return _on_globe(face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0)
    return _on_globe(face, 0.5 * (ax + bx), 0.5 * (ay + by))


@njit(**LEAN)
def _in_grid(px: float, py: float, r: float, sx: float, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
             y1: np.ndarray, frame: np.ndarray, start: np.ndarray, items: np.ndarray,
             empty: np.ndarray) -> tuple[bool, bool]:
    """(hit, inside) of the ellipse round (px, py): it meets the polygon, it lies wholly in it."""
    if near(px, py, r, sx, x0, y0, x1, y1, frame, start, items):
        return True, False
    p = parity(px, py, x0, y0, x1, y1, frame, start, items, empty)
    return p != 0, p == 1  # -1 (on an edge) cannot happen off the edges; a hit if it did


@njit(cache=True, nogil=True)
def ellipse(lv: int, ux: float, uy: float, uz: float) -> tuple[float, float]:
    """Semi-axes (latitude, longitude; degrees) of the footprint ellipse of a level-``lv`` cell centred on u.

    The longitude axis is -1 where the cap holds a pole, or comes too near
    one to bound its longitudes (module docstring).
    """
    h = math.hypot(ux, uy)
    norm = math.sqrt(h * h + uz * uz)
    cstar = (h * _COS[lv] - abs(uz) * _SIN[lv]) / norm  # cos(|beta| + rho): the cap's smallest cosine of latitude
    if cstar <= _SIN_HALF[lv]:
        return _A_LAT[lv], -1.0
    return _A_LAT[lv], math.degrees(2.0 * math.asin(_SIN_HALF[lv] / cstar))


@njit(**LEAN)
def _classify(lv, lat, lng, ux, uy, uz, x0, y0, x1, y1, frame, start, items, empty, miny, maxy):
    """(hit, inside) of a cell by its footprint ellipse (module docstring)."""
    a, lam = ellipse(lv, ux, uy, uz)
    if lam < 0.0:  # a pole's cap: its latitudes only
        return not (lat + a < miny or lat - a > maxy), False
    hit, inside = _in_grid(lng, lat, a, a / lam, x0, y0, x1, y1, frame, start, items, empty)
    if abs(lng) + lam > 180.0:  # across the antimeridian: the other side too
        # never wholly inside (already so: the target ends at 180 by an edge, or has one nearer the centre)
        inside = False
        if not hit:
            hit = _in_grid(lng - math.copysign(360.0, lng), lat, a, a / lam, x0, y0, x1, y1, frame, start, items,
                           empty)[0]
    return hit, inside


@njit(cache=True, nogil=True, inline="always")
def _push(stack_id, stack_xy, top, cell, ax, ay, bx, by, cx, cy) -> int:
    stack_id[top] = cell
    stack_xy[top, 0], stack_xy[top, 1], stack_xy[top, 2] = ax, ay, bx
    stack_xy[top, 3], stack_xy[top, 4], stack_xy[top, 5] = by, cx, cy
    return top + 1


@njit(cache=True, nogil=True)
def descend(level, center, direct, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit):
    """The cells of one polygon at ``level``, as (ids, flags, n, status, cand, insides, tested, classified).

    ``ids[:n]`` are sorted cells of mixed levels: a cell coarser than ``level``
    stands for all its descendants.  ``flags`` are :data:`SURE`, :data:`CENTRE`
    (a centre within rounding of an edge: test it exactly) or :data:`EDGE` (a
    boundary cell in the modes other than ``center``).  ``cand[l]``: cells
    looked at on level l (those whose descendants are all tested counted at
    the first such level); ``insides[l]``: descendants at ``level`` of the cells
    emitted whole on level l; ``tested``: centres tested, or EDGE cells;
    ``classified``: cells classified by footprint.  The status is
    :data:`TOO_MANY` when a count passed ``limit`` (the descent stops there).
    The grid is :func:`.polygon.build`'s over the edges (x0, y0) - (x1, y1);
    ``miny``, ``maxy`` are the polygon's latitude bounds.
    """
    ids = np.empty(1024, dtype=np.uint64)
    flags = np.empty(1024, dtype=np.uint8)
    cand = np.zeros(bits.MAX_LEVEL + 2, dtype=np.int64)
    insides = np.zeros(bits.MAX_LEVEL + 2, dtype=np.int64)
    counts = np.zeros(4, dtype=np.int64)  # found, whole, tested, classified
    stack_id = np.empty(_STACK, dtype=np.uint64)
    stack_xy = np.empty((_STACK, 6))
    top = 0
    for face in range(19, -1, -1):
        top = _push(stack_id, stack_xy, top, bits.base_cell(face),
                    _FACE[0, 0], _FACE[0, 1], _FACE[1, 0], _FACE[1, 1], _FACE[2, 0], _FACE[2, 1])
    test_from = max(level - direct, 0) if center else level + 1
    while True:
        status, top = _walk(level, test_from, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit,
                            stack_id, stack_xy, top, ids, flags, cand, insides, counts)
        if status != _FULL:
            return ids, flags, counts[0], status, cand, insides, counts[2], counts[3]
        more_ids = np.empty(2 * ids.shape[0], dtype=np.uint64)  # the output is full: twice the room, and on
        more_flags = np.empty(2 * ids.shape[0], dtype=np.uint8)
        more_ids[: ids.shape[0]] = ids
        more_flags[: ids.shape[0]] = flags
        ids, flags = more_ids, more_flags


_FULL = -1


@njit(cache=True, nogil=True)
def _walk(level, test_from, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit,
          stack_id, stack_xy, top, ids, flags, cand, insides, counts):
    """Run :func:`descend`'s stack until it is empty (OK), a count passes ``limit`` or ``ids`` is full (_FULL).

    Its own function, whose arrays are never replaced, so that numba counts no references in the loop.
    """
    n, whole, tested, classified = counts[0], counts[1], counts[2], counts[3]
    status = OK
    while top > 0:
        if n == ids.shape[0]:
            status = _FULL
            break
        top -= 1
        cell = stack_id[top]
        ax, ay, bx, by = stack_xy[top, 0], stack_xy[top, 1], stack_xy[top, 2], stack_xy[top, 3]
        cx, cy = stack_xy[top, 4], stack_xy[top, 5]
        lv = bits.level_of(cell)
        face = bits.face_of(cell)
        keep = -1
        if lv <= test_from:
            cand[lv] += 1
            if lv >= 1 and cand[lv] > limit:
                status = TOO_MANY
                break
        if lv >= test_from:  # every descendant's centre is tested
            if lv == level:
                tested += 1
                lat, lng, _, _, _ = centre(face, lv, ax, ay, bx, by, cx, cy)
                p = parity(lng, lat, x0, y0, x1, y1, frame, start, items, empty)
                if p == 1:
                    keep = SURE
                elif p == -1:
                    keep = CENTRE
                if whole + tested > limit:
                    status = TOO_MANY
                    break
        else:
            classified += 1
            lat, lng, ux, uy, uz = footprint(face, lv, ax, ay, bx, by, cx, cy)
            hit, inside = _classify(lv, lat, lng, ux, uy, uz, x0, y0, x1, y1, frame, start, items, empty, miny, maxy)
            if not hit:
                continue
            if inside:
                keep = SURE
                if lv < level:
                    count = n_desc(lv, level)
                    insides[lv] += count
                    whole += count
                    if whole > limit:
                        status = TOO_MANY
                        break
            elif lv == level:
                tested += 1
                keep = EDGE
        if keep >= 0:
            ids[n] = cell
            flags[n] = keep
            n += 1
            continue
        if lv >= level:
            continue
        # the children, pushed last first so that they come off the stack in id order
        if lv == 0:
            for d in range(5, -1, -1):
                top = _push(stack_id, stack_xy, top, cell | (np.uint64(d + 1) << np.uint64(bits.L1_SHIFT)),
                            _L1[d, 0, 0], _L1[d, 0, 1], _L1[d, 1, 0], _L1[d, 1, 1], _L1[d, 2, 0], _L1[d, 2, 1])
        else:
            shift = bits.shift_of(lv + 1)
            for d in range(2, -1, -1):
                qx, qy, rx, ry, tx, ty = gk.child_corners(ax, ay, bx, by, cx, cy, d)
                top = _push(stack_id, stack_xy, top, cell | (np.uint64(d + 1) << shift), qx, qy, rx, ry, tx, ty)
    counts[0], counts[1], counts[2], counts[3] = n, whole, tested, classified
    return status, top


@njit(cache=True, nogil=True)
def first_over(cand: np.ndarray, insides: np.ndarray, tested: int, last: int, center: bool, limit: int) -> int:
    """The first count a level-by-level search would have found over ``limit``, or -1.

    On each level ``0 .. last - 1`` classified: the cells found whole so far,
    then those plus the next level's candidates; then (``center``) those plus
    the centres tested.  ``cand``, ``insides``, ``tested`` are :func:`descend`'s.
    """
    total = 0
    for lv in range(last):
        total += insides[lv]
        if total > limit:
            return total
        if total + cand[lv + 1] > limit:
            return total + cand[lv + 1]
    if center and total + tested > limit:
        return total + tested
    return -1
