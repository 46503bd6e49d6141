"""Compiled loops between points and 64-bit cell ids: location, centres, corners, boundaries.

Each operation is an inner per-item function (``_one_*``) and two loops over
it: a serial one for small inputs (no thread start-up) and a ``prange`` one
for large inputs.  :func:`run` picks between them.  Inputs are assumed
checked, except coordinates: a point that is not a finite latitude in
-90..90 and a finite longitude gets the null id 0, which the caller turns
into a :class:`~dggs.errors.CoordinateError` naming it.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from dggs.geometry import kernel as gk

from . import _bits

_ISEA_CENTRES = gk.ISEA_CENTRES
_ISEA_FRAMES = gk.ISEA_FRAMES
_FACE_CORNERS = gk.FACE_CORNERS_CCW
_L1 = gk.LEVEL1_CORNERS
_U0 = np.uint64(0)


@njit(cache=True, nogil=True)
def encode_point(face: int, x: float, y: float, level: int) -> np.uint64:
    """The id of the level-``level`` cell holding face-frame point (x, y) on ``face``."""
    cell = _bits.base_cell(face)
    if level == 0:
        return cell
    d, px, py = gk.level1_start(x, y)
    cell |= np.uint64(d + 1) << np.uint64(_bits.L1_SHIFT)
    lv = 2
    while lv + 3 <= level:  # four levels per table look-up
        packed, px, py = gk.descend4(px, py)
        cell |= packed << np.uint64(2 * (_bits.MAX_LEVEL - lv - 3))
        lv += 4
    while lv <= level:
        c, px, py = gk.descend(px, py)
        cell |= np.uint64(c + 1) << np.uint64(2 * (_bits.MAX_LEVEL - lv))
        lv += 1
    return cell


@njit(cache=True, nogil=True)
def _one_point(lat: float, lng: float, level: int) -> np.uint64:
    if not (-90.0 <= lat <= 90.0) or not np.isfinite(lng):
        return _U0
    px, py, pz = gk.geodetic_to_unit_fast(lat, lng)
    face, x, y = gk.forward_unit_fast(_ISEA_CENTRES, _ISEA_FRAMES, px, py, pz)
    return encode_point(face, x, y, level)


@njit(cache=True, nogil=True)
def points_serial(lat, lng, level, out):
    for i in range(lat.shape[0]):
        out[i] = _one_point(lat[i], lng[i], level)


@njit(cache=True, nogil=True, parallel=True)
def points_parallel(lat, lng, level, out):
    for i in prange(lat.shape[0]):
        out[i] = _one_point(lat[i], lng[i], level)


@njit(cache=True, nogil=True)
def one_point(lat: float, lng: float, level: int) -> np.uint64:
    """A single point (the scalar call path)."""
    return _one_point(lat, lng, level)


# ----------------------------------------------------------------------------
# Cells to planar corners
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def corners(cell: np.uint64):
    """Face and face-frame corners of a cell, counter-clockwise seen from outside.

    Returns ``(face, ax, ay, bx, by, cx, cy)``: a base cell's corners are its
    face's vertices; a finer cell's are its 30-60-90 triangle (A, B, C),
    reordered (A, C, B) where that is the counter-clockwise order.
    """
    face = _bits.face_of(cell)
    level = _bits.level_of(cell)
    if level == 0:
        return (face, _FACE_CORNERS[0, 0], _FACE_CORNERS[0, 1], _FACE_CORNERS[1, 0],
                _FACE_CORNERS[1, 1], _FACE_CORNERS[2, 0], _FACE_CORNERS[2, 1])
    d = _bits.digit_of(cell, 1)
    ax, ay = _L1[d, 0, 0], _L1[d, 0, 1]
    bx, by = _L1[d, 1, 0], _L1[d, 1, 1]
    cx, cy = _L1[d, 2, 0], _L1[d, 2, 1]
    for lv in range(2, level + 1):
        ax, ay, bx, by, cx, cy = gk.child_corners(ax, ay, bx, by, cx, cy, _bits.digit_of(cell, lv))
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0.0:
        return face, ax, ay, bx, by, cx, cy
    return face, ax, ay, cx, cy, bx, by


@njit(cache=True, nogil=True)
def _one_centre(cell: np.uint64):
    face, ax, ay, bx, by, cx, cy = corners(cell)
    px, py, pz = gk.inverse_unit(_ISEA_FRAMES, face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0)
    return gk.unit_to_geodetic(px, py, pz)


@njit(cache=True, nogil=True)
def centres_serial(ids, lat, lng):
    for i in range(ids.shape[0]):
        lat[i], lng[i] = _one_centre(ids[i])


@njit(cache=True, nogil=True, parallel=True)
def centres_parallel(ids, lat, lng):
    for i in prange(ids.shape[0]):
        lat[i], lng[i] = _one_centre(ids[i])


@njit(cache=True, nogil=True)
def one_centre(cell: np.uint64):
    return _one_centre(cell)


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


@njit(cache=True, nogil=True)
def boundaries_serial(ids, densify, out, lnglat=False):
    for i in range(ids.shape[0]):
        _one_boundary(ids[i], densify, out, i, lnglat)


@njit(cache=True, nogil=True, parallel=True)
def boundaries_parallel(ids, densify, out, lnglat=False):
    for i in prange(ids.shape[0]):
        _one_boundary(ids[i], densify, out, i, lnglat)


@njit(cache=True, nogil=True)
def _one_center_child(cell: np.uint64, level: int) -> np.uint64:
    face, ax, ay, bx, by, cx, cy = corners(cell)
    return encode_point(face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0, level)


@njit(cache=True, nogil=True)
def center_children(ids, level, out):
    for i in range(ids.shape[0]):
        out[i] = _one_center_child(ids[i], level)


@njit(cache=True, nogil=True)
def centre_of(cell: int):
    """Centre of one id given as an int64 (the scalar call path); NaNs if it is no id."""
    c = np.uint64(cell)
    if not _bits.is_valid(c):
        return np.nan, np.nan
    return _one_centre(c)
