"""Points and cells: point-to-cell, centres, boundaries, polygons, GeoJSON.

Every function runs the compiled kernel (:mod:`dggs.index._kernel.points`) over
64-bit ids; ids come in and go out through :mod:`dggs.index._convert`, so a
str gives a str, an int an int, and any array or column the same kind back.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely
from shapely.geometry import mapping

from ._checks import check_densify, check_level, check_projection, property_rows
from ._convert import CELL as _CELL
from ._convert import VALUE, Entry, Op, apply, apply_points, cells_in, check_points, format_int
from ._densify import DRAW_TOLERANCE, EXACT, check_tolerance, edge_points_metadata
from ._kernel import hierarchy as kh
from ._kernel import points as kp
from ._kernel import scalar as ks
from ._shapes import boundaries, geometries

__all__ = [
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
]


def _locate(lat: np.ndarray, lng: np.ndarray, level: int) -> np.ndarray:
    ids = np.empty(lat.shape[0], dtype=np.uint64)
    kp.locate(ids.shape[0], lat, lng, level, ids)
    check_points(lat, lng, ids)  # raises naming the first point off the globe
    return ids


def _centres(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    kp.centres(ids.shape[0], ids, lat, lng)
    return lat, lng


_LOCATE = Op(many=_locate, out=_CELL, one=kp.one_point, form="str",
             one_str=Entry(ks.point_str))
_LOCATE_INT = Op(many=_locate, out=_CELL, one=kp.one_point, form="int",
                 one_int=Entry(kp.one_point))
_CENTRE = Op(many=_centres, out=VALUE, one_str=Entry(ks.centre_str),
             one_int=Entry(kp.centre_of))
_BOUNDARY = Op(many=boundaries, out=VALUE)
_POLYGON = Op(many=geometries, out=VALUE)


def latlng_to_cell(lat: Any, lng: Any, level: int, as_int: bool = False) -> Any:
    """The cell at ``level`` holding each point (geodetic WGS84 degrees).

    Parameters
    ----------
    lat, lng : float, list, numpy array, pandas Series or pyarrow array
        Latitude and longitude in degrees (WGS84).  Longitudes wrap (reduced
        exactly modulo 360).  Shapes broadcast together.
    level : int
        Subdivision level, 0..MAX_LEVEL.
    as_int : bool
        Return 64-bit integer ids (uint64 in arrays) instead of strings.

    Returns
    -------
    str, int, list, numpy.ndarray, pandas.Series or pyarrow.Array
        One id for a scalar point; otherwise the container of the first
        coordinate that is one, shaped like the broadcast input (a Series
        keeps its index).

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
    >>> latlng_to_cell([0.0, 90.0], [0.0, 0.0], 2)
    ['C32', 'A50']
    """
    return apply_points(_LOCATE_INT if as_int else _LOCATE, lat, lng, check_level(level))


def cell_to_latlng(cell: Any) -> Any:
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
    return apply(_CENTRE, cell)


def cell_to_boundary(cell: Any, densify: int = 0, max_points: int | None = None) -> Any:
    """Corners of a cell as (lat, lng) pairs, counter-clockwise seen from outside.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Cell id(s).
    densify : int
        Points to add along each (curved) edge; 0 gives the 3 corners.
    max_points : int, optional
        Refuse to build more boundary points than this in all (default 50 million).

    Returns
    -------
    tuple of (lat, lng) or ndarray
        For one cell, a tuple of ``3 * (densify + 1)`` (lat, lng) tuples, not
        closed.  For an array, an ndarray of shape ``input shape + (3 * (densify + 1), 2)``.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``densify`` is not a non-negative integer, or is over the limit of points per edge.
    TooManyCellsError
        Cells x boundary points over ``max_points`` (default
        :data:`dggs.index._checks.MAX_POINTS`, 50 million), checked before allocating.

    Examples
    --------
    >>> len(cell_to_boundary("C401")), len(cell_to_boundary("C401", densify=2))
    (3, 9)
    """
    return apply(_BOUNDARY, cell, check_densify(densify), False, max_points)


def cell_to_polygon(cell: Any, densify: int | None = None, max_points: int | None = None, *, tolerance: Any = EXACT) -> Any:
    """A cell as a shapely Polygon in (lng, lat), split at the antimeridian.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Cell id(s).
    densify : int, optional
        Points added along each curved edge.  By default as many as ``tolerance`` needs.
    max_points : int, optional
        Refuse to build more boundary points than this in all (default 50 million).
    tolerance : float or "exact", default "exact"
        Without ``densify``: metres between each drawn edge (geodesics between its points) and the
        true edge, or ``"exact"``: enough points that the polygon's geodesic area on WGS84 is within
        1e-6 of the cell's area.  Points per edge come from a bound on each edge's bulge computed in
        the core (no geodesic per edge).

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon, or an ndarray of them
        A MultiPolygon only where the cell crosses the antimeridian.  All
        ordinary cells are built in one vectorized shapely call.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``densify`` is not None or a non-negative integer, or is over the limit of points per edge;
        ``tolerance`` is not a positive number or ``"exact"``.
    TooManyCellsError
        Cells x boundary points over ``max_points`` (default
        :data:`dggs.index._checks.MAX_POINTS`, 50 million), checked before allocating.

    Examples
    --------
    >>> poly = cell_to_polygon("C401")
    >>> poly.geom_type, poly.is_valid
    ('Polygon', True)
    >>> len(cell_to_polygon("C401", tolerance=1000.0).exterior.coords) < len(poly.exterior.coords)
    True
    """
    check_tolerance(tolerance)
    return apply(_POLYGON, cell, None if densify is None else check_densify(densify), max_points, tolerance)


def cells_to_geojson(
    cells: Any, properties: Any = None, densify: int | None = None, max_points: int | None = None, *,
    projection: str = "ISEA", tolerance: Any = DRAW_TOLERANCE,
) -> dict[str, Any]:
    """A GeoJSON FeatureCollection of cells (RFC 7946: lng/lat, CCW rings).

    Parameters
    ----------
    cells : str, int or array_like of ids
        Cell ids; the features carry them in the form given (str or int).
    properties : list of dict, or dict of columns, optional
        Per-cell properties (as many as cells); each feature also gets
        ``cell`` and ``level``.
    densify : int or None
        Points added along each curved edge; by default as many as ``tolerance`` needs.
    max_points : int, optional
        Refuse to build more boundary points than this in all (default 50 million).
    projection : {"ISEA", "IVEA"}
        The grid whose cells are drawn (``dggs.Grid(projection).cells_to_geojson`` passes it; docs/grid.md).
    tolerance : float or "exact", default 10.0
        Metres between each drawn edge and the true edge (files sized for drawing, near H3's), or
        ``"exact"``: :func:`cell_to_polygon`'s area-exact default (geodesic areas within 1e-6).
        The choice is written into the collection's ``"dggs"`` member.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``properties`` do not give one row per cell, or ``densify`` is not None or a
        non-negative integer within the limit of points per edge.
    TooManyCellsError
        Cells x boundary points over ``max_points`` (default
        :data:`dggs.index._checks.MAX_POINTS`, 50 million), checked before allocating.

    Examples
    --------
    >>> fc = cells_to_geojson(["C401", "C402"], properties={"n": [1, 2]})
    >>> fc["type"], len(fc["features"]), fc["features"][1]["properties"]
    ('FeatureCollection', 2, {'cell': 'C402', 'level': 3, 'n': 2})
    >>> fc["dggs"], cells_to_geojson(["C401"], tolerance="exact")["dggs"]["edge_points"]
    ({'edge_points': 'tolerance', 'tolerance_m': 10.0}, 'exact')
    """
    ids, kind = cells_in(cells)
    draw = geometries
    if check_projection(projection) == "IVEA":  # IVEA's shapes floor (loaded on first use)
        from ._ivea_shapes import geometries as draw
    densify = None if densify is None else check_densify(densify)
    drawn = edge_points_metadata(densify, tolerance)
    polys = draw(ids, densify, max_points, tolerance)
    # RFC 7946's winding in one call (shapely >= 2.1) rather than shapely.geometry.polygon.orient one polygon
    # at a time: the same rings, faster (benchmarks/bench_handwritten.py); mapping() is most of the time
    polys = shapely.orient_polygons(polys, exterior_cw=False)
    n = ids.shape[0]
    rows = property_rows(properties, n)
    lv = kh.levels(ids)
    as_str = kind.form == "str"
    features: list[dict[str, Any]] = []
    for cid, level, poly, props in zip(ids.tolist(), lv.tolist(), polys, rows, strict=True):
        key = format_int(cid) if as_str else cid
        features.append(
            {
                "type": "Feature",
                "id": key,
                "geometry": mapping(poly),
                "properties": {"cell": key, "level": level, **props},
            }
        )
    # a foreign member (RFC 7946, section 6.1): how the polygons were drawn
    return {"type": "FeatureCollection", "dggs": drawn, "features": features}

