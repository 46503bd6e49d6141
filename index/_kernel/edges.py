"""Directed edges between edge neighbours, as 64-bit ids (compiled).

Layout (docs/grid.md, "Directed edges"): the edge from a cell at level
``l < 28`` across its side ``d`` (0-2: corner ``d`` to corner ``d + 1``, the
column of :func:`dggs.edge_neighbors`) is ::

    (1 << 63) | cell | (d + 1) << shift(l + 1)

the sign bit marks an edge and the direction fills the cell's first empty
field.  With the sign bit cleared an edge is a valid cell id one level finer
(its "shadow"), so edges sort by origin then direction, and the origin is the
shadow's parent.  Level-28 cells have no empty field: their edges have no id
(the kernels answer the null id 0 and the caller refuses them).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from dggs.geometry import kernel as gk
from dggs.geometry._parallel import loops

from . import bits
from .grid import _neighbour
from .points import corners

__all__ = ["EDGE_BIT", "edge_of", "origin_edges", "pair_edges", "ends", "reverse", "lengths", "boundaries", "one_origin",
           "one_destination", "one_ends", "one_reverse", "one_length"]

EDGE_BIT = np.uint64(1 << 63)
_NOT_EDGE = ~EDGE_BIT
# WGS84 (the ellipsoid the geodetic latitudes of dggs.geometry.kernel are on)
_A = 6378137.0
_F = 1.0 / 298.257223563
_E2 = _F * (2.0 - _F)


@njit(cache=True, nogil=True, inline="always")
def edge_of(cell: np.uint64, direction: int) -> np.uint64:
    """The edge id from ``cell`` across side ``direction``; 0 at level 28."""
    level = bits.level_of(cell)
    if level >= bits.MAX_LEVEL:
        return np.uint64(0)
    return EDGE_BIT | cell | (np.uint64(direction + 1) << bits.shift_of(level + 1))


@njit(cache=True, nogil=True, inline="always")
def split(edge: np.uint64):
    """(origin, level of the origin, direction) of a valid edge id."""
    shadow = edge & _NOT_EDGE
    level = bits.level_of(shadow)
    return bits.parent_at(shadow, level - 1), level - 1, bits.digit_of(shadow, level)


def _origin_edges(ids, out):
    """``out[i, d]``: the edge from ``ids[i]`` across side d (0 at level 28)."""
    for i in prange(ids.shape[0]):
        for d in range(3):
            out[i, d] = edge_of(ids[i], d)


origin_edges = loops(_origin_edges)


def _pair_edges(a, b, out):
    """``out[i]``: the edge from ``a[i]`` to its neighbour ``b[i]``; 0 if they are no neighbours or at level 28."""
    for i in prange(a.shape[0]):
        out[i] = 0
        level = bits.level_of(a[i])
        for d in range(3):
            if _neighbour(a[i], level, d) == b[i] and a[i] != b[i]:
                out[i] = edge_of(a[i], d)
                break


pair_edges = loops(_pair_edges)


def _ends(edges, origin, destination):
    """The origin and destination of each valid edge."""
    for i in prange(edges.shape[0]):
        o, level, d = split(edges[i])
        origin[i] = o
        destination[i] = _neighbour(o, level, d)


ends = loops(_ends)


@njit(cache=True, nogil=True)
def one_origin(edge: np.uint64) -> np.uint64:
    """The origin of one valid edge."""
    return split(edge)[0]


@njit(cache=True, nogil=True)
def one_destination(edge: np.uint64) -> np.uint64:
    """The destination of one valid edge."""
    o, level, d = split(edge)
    return _neighbour(o, level, d)


def _reverse(edges, out):
    """``out[i]``: the edge back from the destination of ``edges[i]`` to its origin."""
    for i in prange(edges.shape[0]):
        o, level, d = split(edges[i])
        dest = _neighbour(o, level, d)
        out[i] = 0
        for k in range(3):
            if _neighbour(dest, level, k) == o:
                out[i] = edge_of(dest, k)
                break


reverse = loops(_reverse)


@njit(cache=True, nogil=True)
def one_ends(edge: np.uint64):
    """(origin, destination) of one valid edge."""
    o, level, d = split(edge)
    return o, _neighbour(o, level, d)


@njit(cache=True, nogil=True)
def one_reverse(edge: np.uint64) -> np.uint64:
    """The edge back, of one valid edge."""
    o, level, d = split(edge)
    dest = _neighbour(o, level, d)
    for k in range(3):
        if _neighbour(dest, level, k) == o:
            return edge_of(dest, k)
    return np.uint64(0)


@njit(cache=True, nogil=True)
def _one_length(edge: np.uint64, pieces: int):
    """Length of a valid edge's curve on WGS84 (m) and on the unit authalic sphere (rad).

    One walk of ``2 pieces + 1`` points along the straight edge on its face,
    each through Snyder's inverse: the chords between consecutive points and
    between every other point, extrapolated (Richardson: chord sums err by
    ~1/n^2).
    """
    o, _, d = split(edge)
    face, ax, ay, bx, by, cx, cy = corners(o)
    xs = (ax, bx, cx)
    ys = (ay, by, cy)
    x0, y0, x1, y1 = xs[d], ys[d], xs[(d + 1) % 3], ys[(d + 1) % 3]
    n = 2 * pieces
    fine_m, fine_r, coarse_m, coarse_r = 0.0, 0.0, 0.0, 0.0
    qx, qy, qz, ux, uy, uz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0  # the previous point (ellipsoid, sphere)
    sx, sy, sz, vx, vy, vz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0  # the previous even point
    for k in range(n + 1):
        t = k / n
        px, py, pz = gk.inverse_unit(gk.ISEA_FRAMES, face, (1.0 - t) * x0 + t * x1, (1.0 - t) * y0 + t * y1)
        lat, lng = gk.unit_to_geodetic(px, py, pz)
        phi, lam = math.radians(lat), math.radians(lng)
        sp, cp = math.sin(phi), math.cos(phi)
        nu = _A / math.sqrt(1.0 - _E2 * sp * sp)  # the prime vertical radius of curvature
        ex, ey, ez = nu * cp * math.cos(lam), nu * cp * math.sin(lam), nu * (1.0 - _E2) * sp
        if k:
            fine_m += math.sqrt((ex - qx) ** 2 + (ey - qy) ** 2 + (ez - qz) ** 2)
            fine_r += math.sqrt((px - ux) ** 2 + (py - uy) ** 2 + (pz - uz) ** 2)
        if k % 2 == 0:
            if k:
                coarse_m += math.sqrt((ex - sx) ** 2 + (ey - sy) ** 2 + (ez - sz) ** 2)
                coarse_r += math.sqrt((px - vx) ** 2 + (py - vy) ** 2 + (pz - vz) ** 2)
            sx, sy, sz, vx, vy, vz = ex, ey, ez, px, py, pz
        qx, qy, qz, ux, uy, uz = ex, ey, ez, px, py, pz
    return (4.0 * fine_m - coarse_m) / 3.0, (4.0 * fine_r - coarse_r) / 3.0


def _lengths(edges, pieces, metres, rads):
    for i in prange(edges.shape[0]):
        metres[i], rads[i] = _one_length(edges[i], pieces)


lengths = loops(_lengths)
one_length = _one_length


@njit(cache=True, nogil=True)
def _one_boundary(edge: np.uint64, densify: int, out, i: int) -> None:
    o, _, d = split(edge)
    face, ax, ay, bx, by, cx, cy = corners(o)
    xs = (ax, bx, cx)
    ys = (ay, by, cy)
    x0, y0, x1, y1 = xs[d], ys[d], xs[(d + 1) % 3], ys[(d + 1) % 3]
    step = densify + 1
    for k in range(step + 1):
        t = k / step
        px, py, pz = gk.inverse_unit(gk.ISEA_FRAMES, face, (1.0 - t) * x0 + t * x1, (1.0 - t) * y0 + t * y1)
        out[i, k, 0], out[i, k, 1] = gk.unit_to_geodetic(px, py, pz)


def _boundaries(edges, densify, out):
    """``out[i]``: the (lat, lng) points of edge ``i`` from its first corner to its second, ``densify`` between."""
    for i in prange(edges.shape[0]):
        _one_boundary(edges[i], densify, out, i)


boundaries = loops(_boundaries)
