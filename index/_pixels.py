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
(``arcs=True`` of :func:`dggs.index._kernel.pixels.grid_pieces`).  An edge shared by two pixels gives one of them
what it takes from the other, in the same cell, so a cell wholly under a
raster is covered to its area even where its pixels were drawn with
different ``k`` (issue 32: scaling each pixel's pieces to its extrapolated
area instead moved up to 3e-6 of a cell's area between cells).
"""

from __future__ import annotations

import math

import numpy as np

from dggs.geometry.authalic import WGS84

from ._checks import check_level
from ._kernel import pixels as kpx

__all__ = ["pixel_pieces", "latlng_pieces", "plane_pieces", "chord_errors", "edge_points", "MAX_PIXEL_DEGREES", "M2_PER_UNIT"]

#: Square metres of the ellipsoid per unit of planar area in a face frame.
M2_PER_UNIT = WGS84.area / 20.0 / kpx.FACE_AREA
#: Square metres of the ellipsoid per unit of area on the unit sphere (the authalic sphere has its area).
M2_PER_STERADIAN = WGS84.area / (4.0 * math.pi)
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
    # with arcs: the area between the curved edges and their chords, in the cells where it lies
    pixel, cell, area, _ = kpx.grid_pieces(arrays[0], arrays[1], arrays[2], arrays[3], k, valid, level, arcs=True)
    total = np.bincount(pixel, weights=area, minlength=valid.size)
    return pixel, cell, area * M2_PER_UNIT, total * M2_PER_UNIT


def latlng_pieces(
    west: float, dlng: float, lat_edges: np.ndarray, valid: np.ndarray, level: int, tol: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cells at ``level`` each valid pixel of a lat/lng (WGS84) grid meets, and the area (m²) they share.

    The other way round from :func:`pixel_pieces` (issue 35): each cell is cut against the grid's rows and
    columns in the cylindrical equal-area map of the authalic sphere, where a lat/lng pixel is an exact
    rectangle (its area in closed form), the cell's edges densified until their chords leave out at most
    ``tol`` of any pixel they cross (libdggs/src/pixels_latlng.c).

    Parameters
    ----------
    west, dlng : float
        Longitude of column 0's western edge and the columns' width (degrees, ``dlng > 0``, 360 at most in all).
    lat_edges : (R + 1,) array
        The rows' latitudes (row ``r`` between ``lat_edges[r]`` and ``lat_edges[r + 1]``), strictly monotonic.
    valid : (R, C) bool array
        Pixels to cut.
    level : int
        The cells' level.
    tol : float
        The error a piece may have, as a fraction of its pixel's area.

    Returns
    -------
    pixel, cell, area
        Per piece, a cell's pieces together (in pixel order).

    Raises
    ------
    RuntimeError
        A cell edge needing more than 4096 chords (cells far coarser than the pixels): cut with
        :func:`pixel_pieces` instead.

    Examples
    --------
    >>> pixel, cell, area = latlng_pieces(0.0, 1.0, np.array([1.0, 0.0]), np.ones((1, 1), bool), 3, 1e-5)
    >>> round(float(area.sum()) / 1e6)
    12308
    """
    level = check_level(level)
    pixel, cell, area = kpx.latlng_pieces(float(west), float(dlng), np.asarray(lat_edges, np.float64),
                                          np.asarray(valid, np.bool_), level, float(tol))
    return pixel, cell, area * M2_PER_STERADIAN


def plane_pieces(
    x: np.ndarray, y: np.ndarray, ring_start: np.ndarray, cells: np.ndarray, valid: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Cells' rings, in a raster's pixel coordinates, cut against its rows and columns (libdggs/src/pixels_plane.c).

    Ring ``i`` of ``cells[i]`` is ``x, y[ring_start[i]:ring_start[i + 1]]`` (column and row, not closed); a
    projected raster's plane path (:mod:`dggs.raster.plane`) takes each cell's densified ring there.

    Returns
    -------
    pixel, cell, area, cu, cv
        Per piece (a cell's pieces together): its pixel (row-major in ``valid``), its cell, its area in pixel
        units and its centroid within the pixel.

    Examples
    --------
    >>> pixel, cell, area, cu, cv = plane_pieces(np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 2.0]),
    ...                                          np.array([0, 3]), np.array([7], np.uint64), np.ones((2, 2), bool))
    >>> pixel.tolist(), area.tolist()
    ([0, 1, 2], [1.0, 0.5, 0.5])
    """
    arrays = [np.ascontiguousarray(a, dtype=np.float64) for a in (x, y)]
    return kpx.plane_pieces(arrays[0], arrays[1], np.ascontiguousarray(ring_start, dtype=np.int64),
                            np.ascontiguousarray(cells, dtype=np.uint64), np.ascontiguousarray(valid, dtype=np.bool_))


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
