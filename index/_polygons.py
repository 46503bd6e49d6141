"""Shapely geometry of cells: all ordinary cells in one ``shapely.polygons`` call.

A boundary ring (lat, lng) becomes a lng/lat polygon.  Rings that cross the
antimeridian or touch a pole (a few cells per level) need unwrapping,
closing over the pole and splitting at +-180; they take :func:`ring_to_geometry`
one by one.  Every other ring is already a simple counter-clockwise lng/lat
ring and goes into one vectorized call.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box
from shapely.geometry.polygon import orient

from . import _kpoints

_POLE_TOL = 1e-9  # degrees


def default_densify(level: int) -> int:
    """Edge points that keep a polygon's geodesic area within 1e-6 of the cell's.

    Measured with pyproj.Geod on WGS84 over random cells (tests/test_area.py):
    level-0 and level-1 edges are nearly geodesics; cells touching an
    icosahedron vertex bend the same at every level (the projection is
    self-similar there), which sets the need at levels 2-12.
    """
    if level <= 1:
        return 32
    if level <= 12:
        return 256
    return 64 if level <= 16 else 32


def special_rings(coords: np.ndarray) -> np.ndarray:
    """Rows of closed (lng, lat) rings (N, M, 2) that may cross the antimeridian or touch a pole.

    A step of more than 90 degrees of longitude between consecutive points
    (across +-180, or past a pole between two points), or a point within a
    degree of a pole: the few cells that take the exact per-cell path.
    """
    steps = np.abs(np.diff(coords[..., 0], axis=1))
    return (steps > 90.0).any(axis=1) | (np.abs(coords[..., 1]) > 89.0).any(axis=1)


def rings_to_geometries(coords: np.ndarray, ids: np.ndarray, densify: int) -> np.ndarray:
    """Object array of shapely geometries of the cells ``ids`` from their closed (lng, lat) rings (N, M, 2).

    Ordinary rings go into one ``shapely.polygons`` call; the special ones
    are recomputed by the kernel with their exact pole and antimeridian
    points (:func:`dggs.index._kpoints.special_ring`) and built one by one.
    """
    n = coords.shape[0]
    out = np.empty(n, dtype=object)
    if n == 0:
        return out
    special = special_rings(coords)
    if special.any():
        plain = ~special
        out[plain] = shapely.polygons(coords[plain])
        buf = np.empty((3 * (densify + 1) + _kpoints.SPECIAL_EXTRA, 2))
        for i in np.flatnonzero(special):
            m = _kpoints.special_ring(ids[i], densify, buf)
            out[i] = ring_to_geometry(buf[:m, 0], buf[:m, 1])
    else:
        out[:] = shapely.polygons(coords)
    return out


def _pole_pairs(lat: np.ndarray, lng: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ring with every point at a pole given as two: arriving and leaving longitude.

    The kernel's exact rings already give pole points in pairs; a lone pole
    point (a plain boundary's corner) takes its neighbours' longitudes.
    """
    at_pole = np.abs(np.abs(lat) - 90.0) < _POLE_TOL
    if not at_pole.any():
        return lat, lng
    m = len(lat)
    ys: list[float] = []
    xs: list[float] = []
    i = 0
    while i < m:
        if at_pole[i]:
            pole = math.copysign(90.0, lat[i])
            if i + 1 < m and at_pole[i + 1]:
                xs += [float(lng[i]), float(lng[i + 1])]
                i += 2
            else:
                xs += [float(lng[i - 1]), float(lng[(i + 1) % m])]
                i += 1
            ys += [pole, pole]
        else:
            xs.append(float(lng[i]))
            ys.append(float(lat[i]))
            i += 1
    return np.array(ys), np.array(xs)


def ring_to_geometry(lat: np.ndarray, lng: np.ndarray) -> Polygon | MultiPolygon:
    """A lng/lat ring on the sphere (counter-clockwise seen from outside) -> shapely geometry.

    Longitudes are unwrapped so that consecutive points are under 180
    degrees apart, except along a pole (two consecutive points at latitude
    +-90), where the ring runs west at the North Pole and east at the South
    Pole (the cell lies below, resp. above, that side), over the cell's
    angle at the pole.  The result is split at the antimeridian, and every
    exterior is counter-clockwise (RFC 7946).
    """
    ys, xs = _pole_pairs(np.asarray(lat, dtype=float), np.asarray(lng, dtype=float))
    steps = np.diff(np.concatenate([xs, xs[:1]]))
    steps = (steps + 180.0) % 360.0 - 180.0
    along = (np.abs(ys) == 90.0) & (np.roll(ys, -1) == ys)
    if along.any():
        raw = np.roll(xs, -1)[along] - xs[along]
        steps[along] = np.where(ys[along] > 0, -((-raw) % 360.0), raw % 360.0)
    xs = xs[0] + np.concatenate([[0.0], np.cumsum(steps[:-1])])
    winding = float(np.sum(steps))
    if abs(winding) > 180.0:  # the ring goes round a pole: close it over the pole
        pole = 90.0 if ys.mean() > 0 else -90.0
        xs = np.concatenate([xs, [xs[-1], xs[0] + winding, xs[0] + winding]])
        ys = np.concatenate([ys, [pole, pole, ys[0]]])
    poly = Polygon(np.column_stack([xs, ys]))
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    lo, hi = xs.min(), xs.max()
    if lo >= -180.0 and hi <= 180.0:
        parts = [poly]
    else:
        parts = []
        for k in range(int(math.floor((lo + 180.0) / 360.0)), int(math.floor((hi + 180.0) / 360.0)) + 1):
            window = box(-180.0 + 360.0 * k, -90.0, 180.0 + 360.0 * k, 90.0)
            piece = poly.intersection(window)
            if not piece.is_empty:
                parts.append(shapely.affinity.translate(piece, xoff=-360.0 * k))
    geoms: list = []
    for p in parts:
        geoms.extend(getattr(p, "geoms", [p]))
    geoms = [orient(g, 1.0) for g in geoms if isinstance(g, Polygon) and g.area > 0]
    return geoms[0] if len(geoms) == 1 else MultiPolygon(geoms)
