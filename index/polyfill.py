"""Polygon fill: the cells whose centres lie in a (Multi)Polygon."""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box

from dggs.errors import DggsValueError

from .cellid import check_level
from .hierarchy import cell_to_children, get_base_cells
from .points import _boundary_points, _ring_to_geometry, cell_to_latlng

__all__ = ["polygon_to_cells"]

_SCREEN_DENSIFY = 8


def _wrap_polygon(poly):
    """Fold parts of a lng/lat polygon beyond +-180 back into -180..180."""
    minx, _, maxx, _ = poly.bounds
    if minx >= -180.0 and maxx <= 180.0:
        return poly
    parts = []
    for k in range(int(math.floor((minx + 180) / 360)), int(math.floor((maxx + 180) / 360)) + 1):
        piece = poly.intersection(box(-180.0 + 360 * k, -90.0, 180.0 + 360 * k, 90.0))
        if not piece.is_empty:
            parts.append(shapely.affinity.translate(piece, xoff=-360.0 * k))
    return shapely.union_all(parts)


def _cell_shapes(cells: np.ndarray) -> np.ndarray:
    lat, lng = _boundary_points(cells, _SCREEN_DENSIFY)
    return np.array([_ring_to_geometry(lat[i], lng[i]) for i in range(len(cells))], dtype=object)


def polygon_to_cells(polygon, level: int) -> np.ndarray:
    """Cells at ``level`` whose centres lie inside a polygon (lng/lat, WGS84).

    Holes are respected.  A polygon that crosses the antimeridian may be given
    with longitudes beyond 180 (e.g. 170..190) or as a MultiPolygon split at
    180.  The search descends the hierarchy: cells far outside are dropped
    early, cells well inside are expanded without testing, and only cells on
    the polygon's boundary have their centres tested.

    Parameters
    ----------
    polygon : shapely.Polygon or shapely.MultiPolygon
        Coordinates as (lng, lat) degrees.
    level : int
        Level of the cells to return.

    Returns
    -------
    ndarray of str
        Sorted cell ids.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> cells = polygon_to_cells(box(-10, -10, 10, 10), 6)
    >>> len(cells), str(cells[0])
    (276, 'C300002')
    """
    level = check_level(level)
    if not isinstance(polygon, (Polygon, MultiPolygon)):
        raise DggsValueError(f"polygon must be a shapely Polygon or MultiPolygon, not {type(polygon).__name__}")
    if polygon.is_empty:
        return np.array([], dtype=f"<U{level + 1}")
    if not polygon.is_valid:
        raise DggsValueError(f"polygon is not valid: {shapely.is_valid_reason(polygon)}")
    minx, miny, maxx, maxy = polygon.bounds
    if miny < -90.0 or maxy > 90.0:
        raise DggsValueError(f"polygon latitudes {miny}..{maxy} are out of range -90..90")
    target = _wrap_polygon(polygon)
    shapely.prepare(target)
    candidates = get_base_cells()
    accepted: list[np.ndarray] = []
    current = 0
    while True:
        if current == level:
            lat, lng = cell_to_latlng(candidates)
            inside = shapely.contains_xy(target, lng, lat)
            accepted.append(candidates[inside])
            break
        shapes = _cell_shapes(candidates)
        # A margin for the curved edges between densified points.
        size = np.array([max(s.bounds[2] - s.bounds[0], s.bounds[3] - s.bounds[1]) for s in shapes])
        grown = shapely.buffer(shapes, 0.05 * size)
        shrunk = shapely.buffer(shapes, 0.0)
        hit = shapely.intersects(target, grown)
        inside = hit & shapely.contains(target, shapely.buffer(shrunk, 0.05 * size))
        if inside.any():
            accepted.append(cell_to_children(candidates[inside], level))
        rest = candidates[hit & ~inside]
        if rest.size == 0:
            break
        current += 1
        candidates = cell_to_children(rest, current)
    if not accepted:
        return np.array([], dtype=f"<U{level + 1}")
    return np.sort(np.concatenate(accepted))
