"""Exact pieces of raster pixels in cells, in m² (the compiled :mod:`dggs.index._kernel.pixels`, checked and scaled).

A pixel is given by its edges, densified with ``k`` points each (straight
lines in the raster's CRS become curves on the globe).  Snyder's projection
is equal-area and draws every cell as a planar triangle, so the part of a
pixel inside a cell is its clipped planar area in the face plane times one
constant: the ellipsoid's area over the twenty faces' planar area (the WGS84
authalic sphere has the ellipsoid's area).  The kernel cuts each pixel's
chord polygon; for an even ``k`` the area between each pair of chords and
the curved edge (a third of the triangle the pair makes: Archimedes'
parabolic segment, the local form of a Richardson extrapolation from ``k``
and ``k / 2`` points) is then added to the piece of the cell where it lies
(:func:`edge_corrections`).  An edge shared by two pixels gives one of them
what it takes from the other, in the same cell, so a cell wholly under a
raster is covered to its area even where its pixels were drawn with
different ``k`` (issue 32: scaling each pixel's pieces to its extrapolated
area instead moved up to 3e-6 of a cell's area between cells).
"""

from __future__ import annotations

import math

import numpy as np

from dggs.geometry import kernel as gk
from dggs.geometry.authalic import WGS84

from ._checks import check_level
from ._kernel import pixels as kpx
from .points import latlng_to_cell

__all__ = ["pixel_pieces", "edge_corrections", "chord_errors", "edge_points", "MAX_PIXEL_DEGREES", "M2_PER_UNIT"]

#: Orientation of a ring in the face planes against its orientation on the sphere (Snyder's projection keeps it).
_CCW = 1.0
#: Pieces a pixel up to which a correction's piece is looked up one by one (past it: by sorting).
_PROBE = 24
#: Square metres of the ellipsoid per unit of planar area in a face frame.
M2_PER_UNIT = WGS84.area / 20.0 / kpx.FACE_AREA
#: The widest pixel the kernel takes (degrees of arc from a corner); larger ones are split first.
MAX_PIXEL_DEGREES = math.degrees(kpx.MAX_RADIUS)


def edge_points(k: int) -> int:
    """Points per pixel edge for ``k``: always at least 1."""
    return max(1, int(k))


def pixel_pieces(
    hlat: np.ndarray, hlng: np.ndarray, vlat: np.ndarray, vlng: np.ndarray, k: int, valid: np.ndarray, level: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The cells at ``level`` each valid pixel of a grid meets, and the area (m²) they share.

    Parameters
    ----------
    hlat, hlng : (R + 1, C k + 1) arrays
        Points along the grid lines of constant row (WGS84 degrees).
    vlat, vlng : (R k + 1, C + 1) arrays
        Points along the grid lines of constant column (each corner in both).
    k : int
        Points per pixel edge.
    valid : (R, C) bool array
        Pixels to cut (others get no pieces).
    level : int
        The cells' level.

    Returns
    -------
    pixel, cell, area, pixel_area
        ``pixel`` (row-major index ``r C + c``), ``cell`` (uint64 ids) and
        ``area`` (m²) per piece, each pixel's pieces together; ``pixel_area``
        (R C,) each valid pixel's area (m², 0 for the others), the sum of its pieces.

    Examples
    --------
    >>> lat = np.array([[1.0, 1.0], [0.0, 0.0]]); lng = np.array([[0.0, 1.0], [0.0, 1.0]])
    >>> pixel, cell, area, total = pixel_pieces(lat, lng, lat, lng, 1, np.ones((1, 1), bool), 3)
    >>> round(float(total[0]) / 1e6), bool(abs(area.sum() - total[0]) < 1e-6 * total[0])
    (12308, True)
    """
    level = check_level(level)
    k = edge_points(k)
    arrays = [np.ascontiguousarray(x, dtype=np.float64) for x in (hlat, hlng, vlat, vlng)]
    valid = np.ascontiguousarray(valid, dtype=np.bool_)
    pixel, cell, area, _ = kpx.grid_pieces(arrays[0], arrays[1], arrays[2], arrays[3], k, valid, level)
    if k >= 2 and k % 2 == 0 and pixel.size:  # the arcs' area beyond their chords, in the cells where it lies
        hlat, hlng, vlat, vlng = arrays
        area = _with_corrections(pixel, cell, area, *edge_corrections(hlat, hlng, vlat, vlng, k, valid, level))
    total = np.bincount(pixel, weights=area, minlength=valid.size)
    return pixel, cell, area * M2_PER_UNIT, total * M2_PER_UNIT


def chord_errors(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    """Per pixel, the fraction of its area the chords of its edges leave out (NaN where a point is not finite).

    ``lat``, ``lng`` (N, 16) WGS84 degrees: each pixel's points round it, four an edge from its first corner
    (:func:`dggs.index._kernel.pixels.chord_errors`).
    """
    lat = np.ascontiguousarray(lat, dtype=np.float64)
    lng = np.ascontiguousarray(lng, dtype=np.float64)
    ok = np.isfinite(lat).all(axis=1) & np.isfinite(lng).all(axis=1)
    out = np.full(lat.shape[0], np.nan)
    if ok.any():
        out[ok] = kpx.chord_errors(lat[ok], lng[ok])
    return out


def _point_frames(lat: np.ndarray, lng: np.ndarray) -> tuple[np.ndarray, ...]:
    """Per point (WGS84 degrees): its face-plane ``x``, ``y`` on its face and its sector ``3 face + s``.

    As the kernel finds them (``pixels.c``: the nearest face, Snyder's forward on it, ``dggs_pixels_region``).
    """
    beta = WGS84.geodetic_to_authalic(np.radians(lat))
    lam = np.radians(lng)
    n = beta.size
    face, x, y = np.empty(n, np.int64), np.empty(n), np.empty(n)
    gk.forward_rad(n, beta, lam, gk.ISEA_CENTRES, gk.ISEA_FRAMES, face, x, y)
    cb = np.cos(beta)
    u = np.stack([cb * np.cos(lam), cb * np.sin(lam), np.sin(beta)], axis=1)
    frames = gk.ISEA_FRAMES[face]
    north, east = np.einsum("ij,ij->i", frames[:, 1], u), np.einsum("ij,ij->i", frames[:, 2], u)
    half = 0.5 * math.sqrt(3.0)
    first = (east >= 0.0) & (-0.5 * east - half * north < 0.0) & ~((east == 0.0) & (north < 0.0))
    third = (east < 0.0) & (-0.5 * east + half * north >= 0.0)
    sector = 3 * face + np.where(first, 0, np.where(third, 2, 1))
    return x, y, sector


def _segments(x: np.ndarray, y: np.ndarray, sector: np.ndarray) -> np.ndarray:
    """Signed area of each triangle (p[2i], p[2i+1], p[2i+2]) along the last axis; 0 across a kink of the plane.

    Archimedes: a parabolic arc through the three points bounds, with the two chords, a third of that
    triangle's area (the segment under the long chord is 4/3 of it).
    """
    a, m, b = (slice(0, -2, 2), slice(1, -1, 2), slice(2, None, 2))
    twice = (x[..., m] - x[..., a]) * (y[..., b] - y[..., a]) - (x[..., b] - x[..., a]) * (y[..., m] - y[..., a])
    smooth = (sector[..., a] == sector[..., m]) & (sector[..., m] == sector[..., b])
    out: np.ndarray = np.where(smooth, 0.5 * twice, 0.0)
    return out


def edge_corrections(
    hlat: np.ndarray, hlng: np.ndarray, vlat: np.ndarray, vlng: np.ndarray, k: int, valid: np.ndarray, level: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(pixel, cell, area)``: what each pixel's chords leave out, in the cell where they leave it (planar units).

    Each edge of an even ``k`` is taken in pairs of chords; the area between the curved edge and a pair is a
    third of the triangle the pair makes (:func:`_segments`), given to the cell of the pair's middle point.
    An edge between two pixels is one arc: the area one pixel's chords leave out its neighbour's take in, in
    the same cell, so a cell's covered area is its pixels' true area whatever the points either pixel drew
    its edges with.  Pairs across a kink of the plane (the kernel cuts them at the kink) are left as drawn.
    """
    rows, cols = valid.shape
    empty = (np.zeros(0, np.int64), np.zeros(0, np.uint64), np.zeros(0))
    if k < 2 or k % 2 or not valid.any():
        return empty
    hx, hy, hs = (a.reshape(hlat.shape) for a in _point_frames(hlat.ravel(), hlng.ravel()))
    vx, vy, vs = (a.reshape(vlat.shape) for a in _point_frames(vlat.ravel(), vlng.ravel()))
    # orientation of each pixel's ring (top edge left to right, then down its right edge) in the face planes:
    # that of its corners on the sphere (Snyder's projection keeps it), from two triangles (one may be a pole's)
    beta, lam = WGS84.geodetic_to_authalic(np.radians(hlat[:, ::k])), np.radians(hlng[:, ::k])
    u = np.stack([np.cos(beta) * np.cos(lam), np.cos(beta) * np.sin(lam), np.sin(beta)], axis=-1)
    tl, tr, br, bl = u[:-1, :-1], u[:-1, 1:], u[1:, 1:], u[1:, :-1]
    turn = np.einsum("...i,...i->...", np.cross(tr - tl, br - tl) + np.cross(br - tl, bl - tl), tl)
    sign = np.where(turn > 0.0, _CCW, -_CCW).ravel()
    th = _segments(hx, hy, hs)  # (rows + 1, cols k / 2): along each line of constant row, left to right
    tv = _segments(vx.T, vy.T, vs.T)  # (cols + 1, rows k / 2): along each line of constant column, downwards
    mh = np.asarray(latlng_to_cell(hlat[:, 1::2], hlng[:, 1::2], level, as_int=True), np.uint64)  # middle points' cells
    mv = np.asarray(latlng_to_cell(vlat[1::2], vlng[1::2], level, as_int=True), np.uint64).T
    half = k // 2
    col_of = np.arange(cols * half) // half
    row_of = np.arange(rows * half) // half
    parts = []
    for t, mid, line_pixel, gets in (
        (th[:-1], mh[:-1], np.arange(rows)[:, None] * cols + col_of[None, :], 1.0),  # top edges, as drawn
        (th[1:], mh[1:], np.arange(rows)[:, None] * cols + col_of[None, :], -1.0),  # bottom edges, reversed
        (tv[1:].T, mv[1:].T, row_of[:, None] * cols + np.arange(cols)[None, :], 1.0),  # right edges, downwards
        (tv[:-1].T, mv[:-1].T, row_of[:, None] * cols + np.arange(cols)[None, :], -1.0),  # left edges, upwards
    ):
        pixel = line_pixel.ravel()
        area = gets * t.ravel() / 3.0
        keep = (area != 0.0) & valid.ravel()[pixel]
        parts.append((pixel[keep], mid.ravel()[keep], area[keep] * sign[pixel[keep]]))
    pixel, cell, area = (np.concatenate([p[i] for p in parts]) for i in range(3))
    return pixel, cell, area


def _with_corrections(
    pixel: np.ndarray, cell: np.ndarray, area: np.ndarray, cp: np.ndarray, cc: np.ndarray, ca: np.ndarray
) -> np.ndarray:
    """``area`` with each correction (pixel ``cp``, cell ``cc``, area ``ca``) added to that pixel's piece in that cell.

    ``pixel`` comes grouped (each pixel's pieces together, in pixel order, as the kernel gives them).  A
    correction whose cell holds no piece of its pixel (its point on a cell's edge or corner), or that would
    leave a piece below zero, goes to the pixel's largest piece.
    """
    area = area.copy()
    if not cp.size:
        return area
    counts = np.bincount(pixel, minlength=int(max(pixel.max(), cp.max())) + 1)
    start = np.concatenate([[0], np.cumsum(counts)[:-1]])
    where = np.full(cp.size, -1, np.int64)
    one = counts[cp] == 1  # most pixels lie in one cell: their one piece (if the cell is that piece's)
    where[one] = start[cp[one]]
    where[one & (cell[np.minimum(where, area.size - 1)] != cc)] = -1
    rest = np.nonzero(counts[cp] > 1)[0]
    most = int(counts[cp[rest]].max()) if rest.size else 0
    if most <= _PROBE:  # a few pieces a pixel: look at each in turn
        for j in range(most):
            if not rest.size:
                break
            idx = start[cp[rest]] + j
            hit = (j < counts[cp[rest]]) & (cell[np.minimum(idx, area.size - 1)] == cc[rest])
            where[rest[hit]] = idx[hit]
            rest = rest[~hit]
    else:  # many: by sorting (pixel, cell) keys
        cells, inv = np.unique(np.concatenate([cell, cc[rest]]), return_inverse=True)
        n = np.uint64(cells.size)
        key = pixel.astype(np.uint64) * n + inv[: cell.size].astype(np.uint64)
        ckey = cp[rest].astype(np.uint64) * n + inv[cell.size:].astype(np.uint64)
        order = np.argsort(key, kind="stable")
        at = order[np.minimum(np.searchsorted(key, ckey, sorter=order), key.size - 1)]
        where[rest] = np.where(key[at] == ckey, at, -1)
    lost = np.nonzero(where < 0)[0]
    for i in lost:  # rare: onto the pixel's largest piece
        where[i] = _largest_piece(area, int(start[cp[i]]), int(counts[cp[i]]))
    area += np.bincount(where, weights=ca, minlength=area.size)
    low = np.nonzero(area < 0.0)[0]
    for i in low:  # a sliver's correction larger than the sliver: back, and onto the largest piece
        p = int(pixel[i])
        area[_largest_piece(area, int(start[p]), int(counts[p]))] += area[i]
        area[i] = 0.0
    return area


def _largest_piece(area: np.ndarray, start: int, count: int) -> int:
    """The index of the largest of the pieces ``start .. start + count``."""
    return start + int(np.argmax(area[start:start + count]))
