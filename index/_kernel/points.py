"""Compiled loops between points and 64-bit cell ids: location, centres, corners, boundaries.

Each operation is a per-item function and one ``prange`` loop over it,
compiled serial and parallel by :func:`dggs.geometry._parallel.loops`
(called as ``loop(n, *args)``, which picks by the amount of work).  The
per-item functions that validate their input (:func:`one_point`,
:func:`centre_of`) are the single-id entries.  Inputs are assumed checked,
except coordinates: a point that is not a finite latitude in
-90..90 and a finite longitude gets the null id 0, which the caller turns
into a :class:`~dggs.errors.CoordinateError` naming it.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from dggs.geometry import kernel as gk
from dggs.geometry._parallel import loops

from . import bits

_ISEA_CENTRES = gk.ISEA_CENTRES
_ISEA_FRAMES = gk.ISEA_FRAMES
_FACE_CORNERS = gk.FACE_CORNERS_CCW
_L1 = gk.LEVEL1_CORNERS
_U0 = np.uint64(0)


@njit(cache=True, nogil=True)
def encode_point(face: int, x: float, y: float, level: int) -> np.uint64:
    """The id of the level-``level`` cell holding face-frame point (x, y) on ``face``."""
    cell = bits.base_cell(face)
    if level == 0:
        return cell
    d, px, py = gk.level1_start(x, y)
    cell |= np.uint64(d + 1) << np.uint64(bits.L1_SHIFT)
    lv = 2
    while lv + 3 <= level:  # four levels per table look-up
        packed, px, py = gk.descend4(px, py)
        cell |= packed << np.uint64(2 * (bits.MAX_LEVEL - lv - 3))
        lv += 4
    while lv <= level:
        c, px, py = gk.descend(px, py)
        cell |= np.uint64(c + 1) << np.uint64(2 * (bits.MAX_LEVEL - lv))
        lv += 1
    return cell


@njit(cache=True, nogil=True)
def one_point(lat: float, lng: float, level: int) -> np.uint64:
    """The id of the cell holding one point; the null id 0 for a point that is not on the globe."""
    if not (-90.0 <= lat <= 90.0) or not np.isfinite(lng):
        return _U0
    px, py, pz = gk.geodetic_to_unit(lat, lng)
    face, x, y = gk.forward_unit(_ISEA_CENTRES, _ISEA_FRAMES, px, py, pz)
    return encode_point(face, x, y, level)


def _locate(lat, lng, level, out):
    """``out[i]``: the id of the cell holding point ``i`` (0 where the point is not on the globe)."""
    for i in prange(lat.shape[0]):
        out[i] = one_point(lat[i], lng[i], level)


locate = loops(_locate)


# ----------------------------------------------------------------------------
# Cells to planar corners
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def triangle(cell: np.uint64):
    """Face and face-frame corners of a cell as Split (2:6) labels them: ``(face, ax, ay, bx, by, cx, cy)``.

    A base cell's are its face's vertices; a finer cell's its 30-60-90 triangle
    (A, B, C), in the order :func:`dggs.geometry.kernel.child_corners` divides.
    """
    face = bits.face_of(cell)
    level = bits.level_of(cell)
    if level == 0:
        return (face, _FACE_CORNERS[0, 0], _FACE_CORNERS[0, 1], _FACE_CORNERS[1, 0],
                _FACE_CORNERS[1, 1], _FACE_CORNERS[2, 0], _FACE_CORNERS[2, 1])
    d = bits.digit_of(cell, 1)
    ax, ay = _L1[d, 0, 0], _L1[d, 0, 1]
    bx, by = _L1[d, 1, 0], _L1[d, 1, 1]
    cx, cy = _L1[d, 2, 0], _L1[d, 2, 1]
    for lv in range(2, level + 1):
        ax, ay, bx, by, cx, cy = gk.child_corners(ax, ay, bx, by, cx, cy, bits.digit_of(cell, lv))
    return face, ax, ay, bx, by, cx, cy


@njit(cache=True, nogil=True)
def corners(cell: np.uint64):
    """Face and face-frame corners of a cell, counter-clockwise seen from outside.

    Returns ``(face, ax, ay, bx, by, cx, cy)``: :func:`triangle`'s (A, B, C),
    reordered (A, C, B) where that is the counter-clockwise order.
    """
    face, ax, ay, bx, by, cx, cy = triangle(cell)
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0.0:
        return face, ax, ay, bx, by, cx, cy
    return face, ax, ay, cx, cy, bx, by


@njit(cache=True, nogil=True)
def _one_centre(cell: np.uint64):
    face, ax, ay, bx, by, cx, cy = corners(cell)
    px, py, pz = gk.inverse_unit(_ISEA_FRAMES, face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0)
    return gk.unit_to_geodetic(px, py, pz)


def _centres(ids, lat, lng):
    """``lat[i], lng[i]``: the centre of valid id ``i``."""
    for i in prange(ids.shape[0]):
        lat[i], lng[i] = _one_centre(ids[i])


centres = loops(_centres)


@njit(cache=True, nogil=True)
def _edge_points(out, i: int, start: int, face: int, x0, y0, x1, y1, step: int, lnglat: bool) -> None:
    """Write ``step`` points from (x0, y0) towards (x1, y1), straight on the face plane."""
    dx = (x1 - x0) / step
    dy = (y1 - y0) / step
    a, b = (1, 0) if lnglat else (0, 1)
    for j in range(step):
        px, py, pz = gk.inverse_unit(_ISEA_FRAMES, face, x0 + j * dx, y0 + j * dy)
        lat, lng = gk.unit_to_geodetic(px, py, pz)
        out[i, start + j, a] = lat
        out[i, start + j, b] = lng


@njit(cache=True, nogil=True)
def _one_boundary(cell: np.uint64, densify: int, out, i: int, lnglat: bool) -> None:
    """Write the corners and ``densify`` points per edge as (lat, lng), or (lng, lat) closed with ``lnglat``."""
    face, ax, ay, bx, by, cx, cy = corners(cell)
    step = densify + 1
    _edge_points(out, i, 0, face, ax, ay, bx, by, step, lnglat)
    _edge_points(out, i, step, face, bx, by, cx, cy, step, lnglat)
    _edge_points(out, i, 2 * step, face, cx, cy, ax, ay, step, lnglat)
    if lnglat:  # close the ring
        out[i, 3 * step, 0] = out[i, 0, 0]
        out[i, 3 * step, 1] = out[i, 0, 1]


def _boundaries(ids, densify, out, lnglat):
    """``out[i]``: the boundary of valid id ``i`` (see :func:`_one_boundary`)."""
    for i in prange(ids.shape[0]):
        _one_boundary(ids[i], densify, out, i, lnglat)


boundaries = loops(_boundaries)


@njit(cache=True, nogil=True)
def _one_center_child(cell: np.uint64, level: int) -> np.uint64:
    face, ax, ay, bx, by, cx, cy = corners(cell)
    return encode_point(face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0, level)


def _center_children(ids, level, out):
    """``out[i]``: the descendant at ``level`` of valid id ``i`` holding its centre."""
    for i in prange(ids.shape[0]):
        out[i] = _one_center_child(ids[i], level)


center_children = loops(_center_children)


@njit(cache=True, nogil=True)
def centre_of(cell: int):
    """Centre of one id given as an int64 (the single-id entry); NaNs if it is no id."""
    c = np.uint64(cell)
    if not bits.is_valid(c):
        return np.nan, np.nan
    return _one_centre(c)


# ----------------------------------------------------------------------------
# Exact boundaries of the few cells at a pole or across the antimeridian
# ----------------------------------------------------------------------------
def _pole_table() -> np.ndarray:
    """(20, 3): per face the face-frame (x, y) of a pole on its boundary and the pole's sign (0: none).

    Both poles sit on the midpoints of face edges (PROJ's ISEA orientation):
    each lies on two faces' boundaries, at a fixed planar position.
    """
    table = np.zeros((_ISEA_FRAMES.shape[0], 3))
    for face in range(_ISEA_FRAMES.shape[0]):
        for k in range(3):
            mx = 0.5 * (_FACE_CORNERS[k, 0] + _FACE_CORNERS[(k + 1) % 3, 0])
            my = 0.5 * (_FACE_CORNERS[k, 1] + _FACE_CORNERS[(k + 1) % 3, 1])
            # the plain-Python body of the compiled function: 60 calls at import need no compiled code loaded
            px, py, pz = gk.inverse_unit.py_func(_ISEA_FRAMES, face, mx, my)
            if abs(pz) > 1.0 - 1e-12:
                table[face] = mx, my, math.copysign(1.0, pz)
    return table


POLES = _pole_table()
#: A pole this close (relative to the edge, planar) to a cell's edge lies on it.
_ON_EDGE = 1e-9
#: The direction in which an edge leaves a pole: the point this fraction of a densify step away.
_POLE_LEAD = 1e-4
#: Extra rows of a special ring: two per pole corner, one per antimeridian crossing.
SPECIAL_EXTRA = 16


@njit(cache=True, nogil=True)
def _lat_lng_at(face: int, x0, y0, x1, y1, t):
    px, py, pz = gk.inverse_unit(_ISEA_FRAMES, face, x0 + t * (x1 - x0), y0 + t * (y1 - y0))
    return gk.unit_to_geodetic(px, py, pz)


@njit(cache=True, nogil=True)
def _pole_on(face: int, x0, y0, x1, y1) -> float:
    """Parameter t in [0, 1) at which the face's pole lies on the planar segment, or -1."""
    if POLES[face, 2] == 0.0:
        return -1.0
    qx, qy = POLES[face, 0], POLES[face, 1]
    dx, dy = x1 - x0, y1 - y0
    n2 = dx * dx + dy * dy
    t = ((qx - x0) * dx + (qy - y0) * dy) / n2
    cross = (qx - x0) * dy - (qy - y0) * dx
    if abs(cross) > _ON_EDGE * n2 or t < -_ON_EDGE or t > 1.0 - _ON_EDGE:
        return -1.0
    return 0.0 if t <= _ON_EDGE else t  # at the start corner, up to rounding


@njit(cache=True, nogil=True)
def _edge_params(ts, step: int, tp: float) -> int:
    """Fill ``ts`` with a densified edge's parameters ``j / step`` (j = 0..step), sorted; return how many.

    The pole's parameter ``tp`` goes among them when it falls inside a step.  Boundaries and dissolved
    outlines alike.
    """
    m = 0
    for j in range(step + 1):
        t = j / step
        if tp > 0.0 and (j - 1) / step < tp < t:
            ts[m] = tp
            m += 1
        ts[m] = t
        m += 1
    return m


@njit(cache=True, nogil=True)
def _crossing(face: int, x0, y0, x1, y1, lo, hi, lng_lo):
    """Latitude where the curve from parameter lo (longitude ``lng_lo``) to hi reaches +-180 (bisection)."""
    lo_lat = 0.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        mlat, mlng = _lat_lng_at(face, x0, y0, x1, y1, mid)
        if (mlng > 0.0) == (lng_lo > 0.0) and abs(mlng) > 90.0:
            lo, lo_lat = mid, mlat
        else:
            hi = mid
    if lo_lat == 0.0:
        lo_lat, _ = _lat_lng_at(face, x0, y0, x1, y1, lo)
    return lo_lat


@njit(cache=True, nogil=True)
def special_ring(cell: np.uint64, densify: int, out) -> int:
    """Write the (lat, lng) boundary of a cell with its exact pole and antimeridian points; return the count.

    The ring of :func:`_one_boundary` (not closed) with, where an edge passes
    through a pole (at its middle or at a corner), two rows at latitude +-90
    whose longitudes are the directions in which the boundary arrives at and
    leaves the pole; and where the curve between two consecutive points
    crosses the antimeridian, the crossing itself (bisected on the planar
    edge parameter until the longitude flips) at longitude +-180 on the side
    of the point before it.  ``out`` needs ``3 (densify + 1) + SPECIAL_EXTRA`` rows.
    """
    face, ax, ay, bx, by, cx, cy = corners(cell)
    step = densify + 1
    xs = np.empty(4)
    ys = np.empty(4)
    xs[0], ys[0], xs[1], ys[1], xs[2], ys[2] = ax, ay, bx, by, cx, cy
    xs[3], ys[3] = ax, ay
    lead = _POLE_LEAD / step
    sign = POLES[face, 2]
    ts = np.empty(step + 2)
    n = 0
    for e in range(3):
        x0, y0, x1, y1 = xs[e], ys[e], xs[e + 1], ys[e + 1]
        tp = _pole_on(face, x0, y0, x1, y1)
        tn = _pole_on(face, xs[(e + 1) % 3], ys[(e + 1) % 3], xs[(e + 1) % 3 + 1], ys[(e + 1) % 3 + 1])
        end_at_pole = tn == 0.0  # this edge ends at a pole corner
        m = _edge_params(ts, step, tp)
        for k in range(m - 1):
            ta, tb = ts[k], ts[k + 1]
            if ta == tp:
                if ta > 0.0:
                    _, lin = _lat_lng_at(face, x0, y0, x1, y1, ta - lead)
                else:  # a corner: the boundary arrives along the previous edge
                    pe = (e + 2) % 3
                    _, lin = _lat_lng_at(face, xs[pe], ys[pe], xs[pe + 1], ys[pe + 1], 1.0 - lead)
                _, lout = _lat_lng_at(face, x0, y0, x1, y1, ta + lead)
                out[n, 0], out[n, 1] = 90.0 * sign, lin
                out[n + 1, 0], out[n + 1, 1] = 90.0 * sign, lout
                n += 2
                continue
            lat, lng = _lat_lng_at(face, x0, y0, x1, y1, ta)
            out[n, 0], out[n, 1] = lat, lng
            n += 1
            if tb == tp or (k == m - 2 and end_at_pole) or n >= out.shape[0] - 2:
                continue
            _, lng_b = _lat_lng_at(face, x0, y0, x1, y1, tb)
            if abs(lng_b - lng) > 180.0 and abs(lng) < 180.0 and abs(lng_b) < 180.0:
                out[n, 0] = _crossing(face, x0, y0, x1, y1, ta, tb, lng)
                out[n, 1] = math.copysign(180.0, lng)
                n += 1
    return n
