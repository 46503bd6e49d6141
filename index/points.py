"""Points and cells: point-to-cell, centres, boundaries, polygons, GeoJSON."""

from __future__ import annotations

import math
from typing import Any, Iterable

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box, mapping

from dggs.geometry._parallel import run_chunks
from dggs.geometry._validate import as_latlng
from dggs.geometry import snyder
from dggs.geometry.split26 import locate

from . import _geo, _scalar
from .cellid import as_id_array, check_level, decode, encode

__all__ = [
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
]


def latlng_to_cell(lat, lng, level: int):
    """The cell at ``level`` holding each point (geodetic WGS84 degrees).

    Parameters
    ----------
    lat, lng : float or array_like
        Latitude and longitude in degrees (WGS84).  Longitudes wrap.
    level : int
        Subdivision level, 0..MAX_LEVEL.

    Returns
    -------
    str or ndarray of str
        A cell id for a scalar point; a ``U`` array shaped like the input
        for arrays.

    Raises
    ------
    CoordinateError
        NaN, infinite or out-of-range coordinates (the message names the
        first bad value and its index).
    LevelError
        ``level`` outside 0..MAX_LEVEL.

    Notes
    -----
    A point on a shared edge or corner goes to one cell by fixed rules
    (the lowest-numbered face, then fixed comparisons at each level), so the
    same point always gets the same cell.

    Examples
    --------
    >>> latlng_to_cell(51.05, -114.07, 9)
    'F200021102'
    >>> latlng_to_cell([0.0, 90.0], [0.0, 0.0], 2).tolist()
    ['C32', 'A50']
    """
    level = check_level(level)
    if (
        isinstance(lat, (float, int))
        and isinstance(lng, (float, int))
        and not isinstance(lat, bool)
        and math.isfinite(lat)
        and math.isfinite(lng)
        and -90.0 <= lat <= 90.0
    ):
        found = _scalar.latlng_to_cell(float(lat), float(lng), level)
        if found is not None:
            return found
    lat_a, lng_a, scalar = as_latlng(lat, lng)
    n = lat_a.shape[0]
    out = np.empty(n, dtype=f"<U{level + 1}")
    codes = out.view(np.uint32).reshape(n, level + 1)  # write the characters in place

    def kernel(sl: slice) -> None:
        xyz = _geo.geodetic_to_xyz(lat_a[sl], lng_a[sl])
        face, x, y = snyder.forward_xyz(xyz, _geo.ORIENTATION)
        encode(face, locate(x, y, level), out=codes[sl])

    run_chunks(kernel, n)
    if scalar:
        return str(out[0])
    return out.reshape(np.broadcast(np.asarray(lat), np.asarray(lng)).shape)


def _planar_centres(dec) -> np.ndarray:
    return _geo.corners(dec).mean(axis=1)


def cell_to_latlng(cell):
    """Centre (geodetic lat, lng in degrees) of a cell or an array of cells.

    The centre is the image of the planar triangle's centroid; it lies in
    the cell, and ``latlng_to_cell(*cell_to_latlng(c), get_level(c)) == c``.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> lat, lng = cell_to_latlng("C")
    >>> round(lat, 6), round(lng, 6)
    (20.990853, 11.25)
    """
    if isinstance(cell, str) and _scalar.is_valid(cell):
        return _scalar.cell_to_latlng(cell)
    ids, scalar = as_id_array(cell)
    dec = decode(ids)
    c = _planar_centres(dec)
    lat, lng = _geo.planar_to_geodetic(dec.face, c[:, 0], c[:, 1])
    if scalar:
        return float(lat[0]), float(lng[0])
    return lat, lng


def _boundary_points(ids: np.ndarray, densify: int) -> tuple[np.ndarray, np.ndarray]:
    """(lat, lng) arrays of shape (N, 3 * (densify + 1)): corners then edge points."""
    if not isinstance(densify, (int, np.integer)) or isinstance(densify, bool) or densify < 0:
        from dggs.errors import DggsValueError

        raise DggsValueError(f"densify {densify!r} must be a non-negative integer")
    dec = decode(ids)
    pts = _geo.corners(dec)  # (N, 3, 2)
    t = np.arange(densify + 1) / (densify + 1)
    start = pts
    end = np.roll(pts, -1, axis=1)
    ring = start[:, :, None, :] + t[None, None, :, None] * (end - start)[:, :, None, :]
    ring = ring.reshape(len(ids), -1, 2)
    m = ring.shape[1]
    face = np.repeat(dec.face, m)
    lat, lng = _geo.planar_to_geodetic(face, ring[..., 0].ravel(), ring[..., 1].ravel())
    return lat.reshape(-1, m), lng.reshape(-1, m)


def cell_to_boundary(cell, densify: int = 0):
    """Corners of a cell as (lat, lng) pairs, counter-clockwise seen from outside.

    Parameters
    ----------
    cell : str or array_like of str
        Cell id(s).
    densify : int
        Points to add along each (curved) edge; 0 gives the 3 corners.

    Returns
    -------
    tuple of (lat, lng) or ndarray
        For one cell, a tuple of ``3 * (densify + 1)`` (lat, lng) tuples, not
        closed.  For an array, an ndarray of shape (N, 3 * (densify + 1), 2).

    Examples
    --------
    >>> len(cell_to_boundary("C401")), len(cell_to_boundary("C401", densify=2))
    (3, 9)
    """
    if (
        isinstance(cell, str)
        and _scalar.is_valid(cell)
        and isinstance(densify, (int, np.integer))
        and not isinstance(densify, bool)
        and 0 <= densify <= 64
    ):
        return _scalar.cell_to_boundary(cell, int(densify))
    ids, scalar = as_id_array(cell)
    lat, lng = _boundary_points(ids, densify)
    if scalar:
        return tuple((float(a), float(b)) for a, b in zip(lat[0], lng[0]))
    return np.stack([lat, lng], axis=-1)


_POLE_TOL = 1e-9  # degrees


def _ring_to_geometry(lat: np.ndarray, lng: np.ndarray) -> Polygon | MultiPolygon:
    """A lng/lat ring on the sphere -> shapely geometry, split at the antimeridian."""
    pts: list[tuple[float, float]] = []
    m = len(lat)
    for i in range(m):
        if abs(abs(lat[i]) - 90.0) < _POLE_TOL:
            # A corner at a pole: walk up the incoming meridian, along the
            # pole, and down the outgoing one.
            pole = math.copysign(90.0, lat[i])
            pts.append((float(lng[i - 1]), pole))
            pts.append((float(lng[(i + 1) % m]), pole))
        else:
            pts.append((float(lng[i]), float(lat[i])))
    xs = np.array([p[0] for p in pts])
    ys = np.array([p[1] for p in pts])
    # Unwrap longitudes so that consecutive points are under 180 degrees apart.
    steps = np.diff(np.concatenate([xs, xs[:1]]))
    steps = (steps + 180.0) % 360.0 - 180.0
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
        return poly
    parts = []
    for k in range(int(math.floor((lo + 180.0) / 360.0)), int(math.floor((hi + 180.0) / 360.0)) + 1):
        window = box(-180.0 + 360.0 * k, -90.0, 180.0 + 360.0 * k, 90.0)
        piece = poly.intersection(window)
        if not piece.is_empty:
            parts.append(shapely.affinity.translate(piece, xoff=-360.0 * k))
    geoms: list = []
    for p in parts:
        geoms.extend(getattr(p, "geoms", [p]))
    geoms = [g for g in geoms if isinstance(g, Polygon) and g.area > 0]
    return geoms[0] if len(geoms) == 1 else MultiPolygon(geoms)


def default_densify(level: int) -> int:
    """Edge points that keep a polygon's geodesic area within 1e-6 of the cell's.

    Measured with pyproj.Geod on WGS84 over random cells (see
    tests/test_area.py): level-0 and level-1 edges are nearly geodesics;
    cells touching an icosahedron vertex bend the same at every level (the
    projection is self-similar there), which sets the need at levels 2-12.
    """
    if level <= 1:
        return 32
    if level <= 12:
        return 256
    return 64 if level <= 16 else 32


def cell_to_polygon(cell, densify: int | None = None):
    """A cell as a shapely Polygon in (lng, lat), split at the antimeridian.

    Parameters
    ----------
    cell : str or array_like of str
        Cell id(s).
    densify : int, optional
        Points added along each curved edge.  By default enough that the
        polygon's geodesic area on WGS84 is within 1e-6 of the cell's area.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon, or an ndarray of them
        A MultiPolygon only where the cell crosses the antimeridian.

    Examples
    --------
    >>> poly = cell_to_polygon("C401")
    >>> poly.geom_type, poly.is_valid
    ('Polygon', True)
    """
    ids, scalar = as_id_array(cell)
    dec = decode(ids)
    out = np.empty(len(ids), dtype=object)
    for level in np.unique(dec.level):
        sel = np.flatnonzero(dec.level == level)
        n = default_densify(int(level)) if densify is None else densify
        lat, lng = _boundary_points(ids[sel], n)
        for j, i in enumerate(sel):
            out[i] = _ring_to_geometry(lat[j], lng[j])
    return out[0] if scalar else out


def cells_to_geojson(cells, properties: Any = None, densify: int | None = 16) -> dict:
    """A GeoJSON FeatureCollection of cells (RFC 7946: lng/lat, CCW rings).

    Parameters
    ----------
    cells : str or array_like of str
        Cell ids.
    properties : list of dict, or dict of columns, optional
        Per-cell properties; each feature also gets ``cell`` and ``level``.
    densify : int or None
        Points added along each curved edge (default 16, light files); None
        gives :func:`cell_to_polygon`'s area-exact default.

    Examples
    --------
    >>> fc = cells_to_geojson(["C401", "C402"], properties={"n": [1, 2]})
    >>> fc["type"], len(fc["features"]), fc["features"][1]["properties"]
    ('FeatureCollection', 2, {'cell': 'C402', 'level': 3, 'n': 2})
    """
    ids, _ = as_id_array(cells)
    polys = cell_to_polygon(ids, densify) if len(ids) else []
    if properties is None:
        rows: Iterable[dict] = ({} for _ in ids)
    elif isinstance(properties, dict):
        keys = list(properties)
        cols = [list(properties[k]) for k in keys]
        for k, col in zip(keys, cols):
            if len(col) != len(ids):
                from dggs.errors import DggsValueError

                raise DggsValueError(f"property {k!r} has {len(col)} values for {len(ids)} cells")
        rows = ({k: _plain(col[i]) for k, col in zip(keys, cols)} for i in range(len(ids)))
    else:
        rows = ({k: _plain(v) for k, v in dict(r).items()} for r in properties)
    features = []
    for cid, poly, props in zip(ids, polys, rows):
        cid = str(cid)
        features.append(
            {
                "type": "Feature",
                "id": cid,
                "geometry": mapping(shapely.geometry.polygon.orient(poly, 1.0))
                if isinstance(poly, Polygon)
                else mapping(MultiPolygon([shapely.geometry.polygon.orient(p, 1.0) for p in poly.geoms])),
                "properties": {"cell": cid, "level": len(cid) - 1, **props},
            }
        )
    return {"type": "FeatureCollection", "features": features}


def _plain(v):
    """numpy scalars -> Python scalars, for JSON."""
    return v.item() if isinstance(v, np.generic) else v
