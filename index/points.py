"""Points and cells: point-to-cell, centres, boundaries, polygons, GeoJSON.

Every function runs the compiled kernel (:mod:`dggs.index._kpoints`) over
64-bit ids; ids come in and go out through :mod:`dggs.index._convert`, so a
str gives a str, an int an int, and any array or column the same kind back.
"""

from __future__ import annotations

from typing import Any
from collections.abc import Iterable

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, mapping

from dggs.errors import CoordinateError, DggsValueError
from dggs.geometry._parallel import parallel

from . import _codec, _kpoints
from ._bits import MAX_LEVEL
from ._convert_in import cells_in, scalar_id
from ._coords import as_coordinates, as_float_scalar, check_densify, check_points, ids_out, raise_bad_point
from ._polygons import default_densify, rings_to_geometries
from .cellid import check_level

__all__ = [
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
    "default_densify",
]

_SCALARS = (float, int)


def latlng_to_cell(lat, lng, level: int, as_int: bool = False):
    """The cell at ``level`` holding each point (geodetic WGS84 degrees).

    Parameters
    ----------
    lat, lng : float or array_like
        Latitude and longitude in degrees (WGS84).  Longitudes wrap (reduced
        exactly modulo 360).  Arrays of any shape broadcast together; a
        pandas Series gives a Series with its index.
    level : int
        Subdivision level, 0..MAX_LEVEL.
    as_int : bool
        Return 64-bit integer ids (a Python int for one point, a uint64
        array otherwise) instead of strings.

    Returns
    -------
    str, int or ndarray
        One id for a scalar point; an array shaped like the input otherwise.

    Raises
    ------
    CoordinateError
        Non-numeric, NaN, infinite or out-of-range coordinates (the message
        names the first bad value and its index), or shapes that do not match.
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
    >>> latlng_to_cell(51.05, -114.07, 9, as_int=True)
    5392473139689029632
    >>> latlng_to_cell([0.0, 90.0], [0.0, 0.0], 2).tolist()
    ['C32', 'A50']
    """
    if type(lat) in _SCALARS and type(lng) in _SCALARS and type(level) is int and 0 <= level <= MAX_LEVEL:
        try:
            a, b = float(lat), float(lng)
        except OverflowError:
            raise CoordinateError(f"coordinates ({lat!r}, {lng!r}) are too large to be numbers of degrees") from None
        found = int(_kpoints.one_point(a, b, level))  # the single-point path: no numpy
        if found:
            return found if as_int else _codec.format_int(found)
    level = check_level(level)
    try:
        scalar = np.ndim(lat) == 0 and np.ndim(lng) == 0
    except ValueError:  # a ragged nested list
        raise CoordinateError("coordinates must be numbers or equal-length arrays of numbers, not ragged lists") from None
    if scalar:
        a, b = as_float_scalar(lat, "latitude"), as_float_scalar(lng, "longitude")
        cell = int(_kpoints.one_point(a, b, level))
        if cell == 0:
            raise_bad_point(np.array([a]), np.array([b]), 0)
        return cell if as_int else _codec.format_int(cell)
    lat_a, lng_a, shape, index = as_coordinates(lat, lng)
    ids = np.empty(lat_a.shape[0], dtype=np.uint64)
    if parallel(ids.shape[0]):
        _kpoints.points_parallel(lat_a, lng_a, level, ids)
    else:
        _kpoints.points_serial(lat_a, lng_a, level, ids)
    check_points(lat_a, lng_a, ids)
    return ids_out(ids, shape, index, as_int)


def cell_to_latlng(cell):
    """Centre (geodetic lat, lng in degrees) of a cell or of each cell of an array.

    The centre is the image of the planar triangle's centroid; it lies in
    the cell, and ``latlng_to_cell(*cell_to_latlng(c), get_level(c)) == c``.

    Returns
    -------
    (float, float) or (ndarray, ndarray)
        For arrays, two float arrays shaped like the input.

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
    one = scalar_id(cell)
    if one:
        lat, lng = _kpoints.centre_of(one)
        if lat == lat:  # not NaN: a valid id
            return lat, lng
    ids, kind = cells_in(cell)
    if kind.scalar:
        return _kpoints.one_centre(ids[0])
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    if parallel(ids.shape[0]):
        _kpoints.centres_parallel(ids, lat, lng)
    else:
        _kpoints.centres_serial(ids, lat, lng)
    return lat.reshape(kind.shape), lng.reshape(kind.shape)


def _boundaries(ids: np.ndarray, densify: int, lnglat: bool = False) -> np.ndarray:
    """(N, 3 (densify + 1), 2) (lat, lng) points, or closed (lng, lat) rings one point longer."""
    out = np.empty((ids.shape[0], 3 * (densify + 1) + int(lnglat), 2))
    if parallel(ids.shape[0] * (densify + 1)):
        _kpoints.boundaries_parallel(ids, densify, out, lnglat)
    else:
        _kpoints.boundaries_serial(ids, densify, out, lnglat)
    return out


def cell_to_boundary(cell, densify: int = 0):
    """Corners of a cell as (lat, lng) pairs, counter-clockwise seen from outside.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Cell id(s).
    densify : int
        Points to add along each (curved) edge; 0 gives the 3 corners.

    Returns
    -------
    tuple of (lat, lng) or ndarray
        For one cell, a tuple of ``3 * (densify + 1)`` (lat, lng) tuples, not
        closed.  For an array, an ndarray of shape ``input shape + (3 * (densify + 1), 2)``.

    Examples
    --------
    >>> len(cell_to_boundary("C401")), len(cell_to_boundary("C401", densify=2))
    (3, 9)
    """
    densify = check_densify(densify)
    ids, kind = cells_in(cell)
    out = _boundaries(ids, densify)
    if kind.scalar:
        return tuple((float(a), float(b)) for a, b in out[0])
    return out.reshape(kind.shape + out.shape[1:])


def cell_to_polygon(cell, densify: int | None = None):
    """A cell as a shapely Polygon in (lng, lat), split at the antimeridian.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Cell id(s).
    densify : int, optional
        Points added along each curved edge.  By default enough that the
        polygon's geodesic area on WGS84 is within 1e-6 of the cell's area.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon, or an ndarray of them
        A MultiPolygon only where the cell crosses the antimeridian.  All
        ordinary cells are built in one vectorized shapely call.

    Examples
    --------
    >>> poly = cell_to_polygon("C401")
    >>> poly.geom_type, poly.is_valid
    ('Polygon', True)
    """
    if densify is not None:
        densify = check_densify(densify)
    ids, kind = cells_in(cell)
    out = np.empty(ids.shape[0], dtype=object)
    if densify is None:
        from . import _khier

        lv = _khier.levels(ids)
        groups: dict[int, list[np.ndarray]] = {}
        for level in np.unique(lv):
            groups.setdefault(default_densify(int(level)), []).append(np.flatnonzero(lv == level))
        for n, parts in groups.items():
            sel = np.concatenate(parts)
            out[sel] = rings_to_geometries(_boundaries(ids[sel], n, lnglat=True), ids[sel], n)
    else:
        out[:] = rings_to_geometries(_boundaries(ids, densify, lnglat=True), ids, densify)
    return out[0] if kind.scalar else out.reshape(kind.shape)


def cells_to_geojson(cells, properties: Any = None, densify: int | None = 16) -> dict:
    """A GeoJSON FeatureCollection of cells (RFC 7946: lng/lat, CCW rings).

    Parameters
    ----------
    cells : str, int or array_like of ids
        Cell ids; the features carry them in the form given (str or int).
    properties : list of dict, or dict of columns, optional
        Per-cell properties (as many as cells); each feature also gets
        ``cell`` and ``level``.
    densify : int or None
        Points added along each curved edge (default 16, light files); None
        gives :func:`cell_to_polygon`'s area-exact default.

    Raises
    ------
    DggsValueError
        ``properties`` do not give one row per cell.

    Examples
    --------
    >>> fc = cells_to_geojson(["C401", "C402"], properties={"n": [1, 2]})
    >>> fc["type"], len(fc["features"]), fc["features"][1]["properties"]
    ('FeatureCollection', 2, {'cell': 'C402', 'level': 3, 'n': 2})
    """
    ids, kind = cells_in(cells)
    ids = ids.reshape(-1)
    polys = cell_to_polygon(ids, densify).reshape(-1) if ids.size else []
    n = ids.shape[0]
    rows: Iterable[dict]
    if properties is None:
        rows = ({} for _ in range(n))
    elif isinstance(properties, dict):
        bad = [k for k, v in properties.items() if isinstance(v, (str, bytes)) or not hasattr(v, "__len__")]
        if bad:
            raise DggsValueError(f"property {bad[0]!r} must be a column (a sequence of {n} values), not {properties[bad[0]]!r}")
        cols = {k: list(v) for k, v in properties.items()}
        for k, col in cols.items():
            if len(col) != n:
                raise DggsValueError(f"property {k!r} has {len(col)} values for {n} cells")
        rows = ({k: _plain(col[i]) for k, col in cols.items()} for i in range(n))
    else:
        if isinstance(properties, (str, bytes)) or not hasattr(properties, "__iter__"):
            raise DggsValueError(f"properties must be a dict of columns or a list of dicts, not {properties!r}")
        listed = list(properties)
        if len(listed) != n:
            raise DggsValueError(f"properties has {len(listed)} rows for {n} cells")
        odd = next((r for r in listed if not hasattr(r, "keys")), None)
        if odd is not None:
            raise DggsValueError(f"properties rows must be dicts, not {odd!r}")
        rows = ({k: _plain(v) for k, v in dict(r).items()} for r in listed)
    from . import _khier

    lv = _khier.levels(ids)
    as_str = kind.form == "str"
    features = []
    for cid, level, poly, props in zip(ids.tolist(), lv.tolist(), polys, rows):
        key = _codec.format_int(cid) if as_str else cid
        features.append(
            {
                "type": "Feature",
                "id": key,
                "geometry": mapping(_orient(poly)),
                "properties": {"cell": key, "level": level, **props},
            }
        )
    return {"type": "FeatureCollection", "features": features}


def _orient(poly):
    if isinstance(poly, Polygon):
        return shapely.geometry.polygon.orient(poly, 1.0)
    return MultiPolygon([shapely.geometry.polygon.orient(p, 1.0) for p in poly.geoms])


def _plain(v):
    """numpy scalars -> Python scalars, for JSON."""
    return v.item() if isinstance(v, np.generic) else v
