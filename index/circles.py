"""Cells within a geodesic distance of a point on WGS84: whose centres, whole cells, or any part.

The search descends the hierarchy from the 20 base cells.  Each cell gets a
radius: the farthest of its corners and edge midpoints from its centre
(``pyproj.Geod``), times :data:`_RADIUS_MARGIN`.  By the triangle inequality of
the geodesic distance, a cell whose centre is farther than the circle's radius
plus its own lies wholly outside (dropped with its descendants), and one whose
centre is nearer than the circle's radius minus its own lies wholly inside
(all its descendants kept untested).  Only the cells at the target level that
neither bound decides are tested exactly.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from ._checks import check_level, check_max_cells, check_projection, check_size, is_choice
from ._convert import as_float_scalar, ids_array
from ._kernel import hierarchy as kh
from ._kernel import points as kp
from ._kernel.bits import MARKER
from ._shapes import boundaries, densify_groups

__all__ = ["circle_to_cells", "CIRCLE_MODES", "MAX_RADIUS_M"]

#: The modes of :func:`circle_to_cells`.
CIRCLE_MODES = ("center", "contains", "intersects")
#: Largest radius (metres): a quarter of the way round the globe.  Cells are judged in an azimuthal
#: equidistant plane about the centre, which tears only at the antipode, far from any cell judged.
MAX_RADIUS_M = 10_000_000.0
#: The sampled radius of a cell (corners and edge midpoints) times this bounds the true one:
#: a curved edge bulges from its midpoint by far less than 2 % of the cell's size.
_RADIUS_MARGIN = 1.02


@lru_cache(maxsize=1)
def _geod() -> Any:
    import pyproj

    return pyproj.Geod(ellps="WGS84")


def _shapes(projection: str) -> tuple[Any, Any, Any]:
    """(centres loop, boundaries, densify groups) of a projection's cells; IVEA's loaded on first use."""
    if projection == "ISEA":
        return kp.centres, boundaries, densify_groups
    from . import _ivea_shapes as ivea
    from ._kernel import ivea_points as ki

    def groups(ids: np.ndarray, densify: None) -> list[tuple[np.ndarray, int]]:
        return densify_groups(ids, densify, ivea=True)

    return ki.centres, ivea.boundaries, groups


def _centres(ids: np.ndarray, centres: Any = kp.centres) -> tuple[np.ndarray, np.ndarray]:
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    centres(ids.shape[0], ids, lat, lng)
    return lat, lng


def _bounds(ids: np.ndarray, lat: float, lng: float, shapes: tuple[Any, Any, Any]) -> tuple[np.ndarray, np.ndarray]:
    """(distance from the point to each cell's centre, a bound on the cell's radius), metres."""
    clat, clng = _centres(ids, shapes[0])
    _, _, dc = _geod().inv(np.full(ids.shape[0], lng), np.full(ids.shape[0], lat), clng, clat)
    pts = shapes[1](ids, 1)  # (N, 6, 2): corners and edge midpoints, (lat, lng)
    m = pts.shape[1]
    _, _, dr = _geod().inv(np.repeat(clng, m), np.repeat(clat, m), pts[:, :, 1].ravel(), pts[:, :, 0].ravel())
    rc = np.asarray(dr).reshape(-1, m).max(axis=1) * _RADIUS_MARGIN + 1e-3
    return np.asarray(dc, dtype=np.float64), rc


def _exact(ids: np.ndarray, lat: float, lng: float, radius: float, mode: str, shapes: tuple[Any, Any, Any]) -> np.ndarray:
    """Which cells meet (``"intersects"``) or lie in (``"contains"``) the circle, judged in the AEQD plane."""
    import pyproj
    import shapely

    keep = np.zeros(ids.shape[0], dtype=bool)
    if ids.size == 0:
        return keep
    aeqd = pyproj.Transformer.from_crs(
        "EPSG:4326", pyproj.CRS.from_proj4(f"+proj=aeqd +lat_0={lat!r} +lon_0={lng!r} +ellps=WGS84 +units=m"),
        always_xy=True,
    )
    for rows, d in shapes[2](ids, None):
        pts = shapes[1](ids[rows], d)  # (n, 3 (d + 1), 2) (lat, lng)
        x, y = aeqd.transform(pts[:, :, 1], pts[:, :, 0])
        x, y = np.asarray(x), np.asarray(y)
        if mode == "contains":
            keep[rows] = np.hypot(x, y).max(axis=1) <= radius
        else:
            polys = shapely.polygons(np.stack([x, y], axis=-1))
            keep[rows] = shapely.distance(polys, shapely.Point(0.0, 0.0)) <= radius
    return keep


def _base_cells() -> np.ndarray:
    return MARKER | (np.arange(20, dtype=np.uint64) << np.uint64(57))


def _descendants(ids: np.ndarray, level: int) -> np.ndarray:
    total, _ = kh.count_children(ids, level)
    out = np.empty(total, dtype=np.uint64)
    kh.children(ids, level, out)
    return out


def _check_args(lat: Any, lng: Any, radius_m: Any, mode: Any) -> tuple[float, float, float]:
    lat, lng = as_float_scalar(lat, "latitude"), as_float_scalar(lng, "longitude")
    if not (math.isfinite(lat) and math.isfinite(lng) and abs(lat) <= 90.0):
        raise CoordinateError(f"centre ({lat!r}, {lng!r}) is not a finite latitude in -90..90 and a finite longitude")
    if isinstance(radius_m, (bool, np.bool_)) or not isinstance(radius_m, (int, float, np.integer, np.floating)):
        raise DggsValueError(f"radius_m {radius_m!r} must be a number of metres")
    radius = float(radius_m)
    if not (0.0 <= radius <= MAX_RADIUS_M):
        raise DggsValueError(f"radius_m {radius_m!r} must be a distance in metres from 0 to {MAX_RADIUS_M:,.0f}")
    if not is_choice(mode, CIRCLE_MODES):
        raise DggsValueError(f"mode {mode!r} must be one of {', '.join(map(repr, CIRCLE_MODES))}")
    return lat, ((lng + 180.0) % 360.0) - 180.0, radius


def circle_to_cells(
    lat: Any, lng: Any, radius_m: Any, level: int, mode: str = "center", as_int: bool = False, max_cells: int | None = None,
    *, projection: str = "ISEA",
) -> np.ndarray:
    """Cells at ``level`` within a geodesic distance of a point (WGS84), at the poles and across the antimeridian.

    ``mode`` chooses which cells (as :func:`dggs.polygon_to_cells`'s modes):

    - ``"center"`` (default): cells whose centre (:func:`dggs.cell_to_latlng`)
      is at most ``radius_m`` from the point, by ``pyproj.Geod`` (Karney's
      geodesic, exact to nanometres);
    - ``"contains"``: cells lying wholly within the circle (a subset of ``"center"``);
    - ``"intersects"``: cells that meet the circle's disk, its edge included
      (a superset of ``"center"``; their union covers the disk).

    ``"contains"`` and ``"intersects"`` judge each cell near the circle's edge by its
    boundary as :func:`dggs.cell_to_polygon` densifies it (within 1e-6 of the
    cell's area), mapped to the azimuthal equidistant projection about the
    point (PROJ's ``aeqd`` on WGS84, where the distance from the centre is the
    geodesic distance exactly, so the circle is a circle): wholly in if every
    boundary point is within ``radius_m``, meeting if the polygon comes within
    ``radius_m`` of the centre.  Cells farther inside or outside are decided by
    bounds that provably hold (the module's notes).

    Parameters
    ----------
    lat, lng : float
        The centre, geodetic WGS84 degrees (the order of the name).
    radius_m : float
        Metres, 0 to :data:`MAX_RADIUS_M` (10,000 km).
    level : int
        Level of the cells.
    mode : {"center", "contains", "intersects"}
    as_int : bool
        Return uint64 ids instead of strings.
    max_cells : int, optional
        Refuse to return, or to test, more cells than this (default
        :data:`dggs.index.hierarchy.MAX_CELLS`), checked level by level before allocating.
    projection : {"ISEA", "IVEA"}
        The grid's projection (``dggs.Grid(projection).circle_to_cells`` passes it): its centres and boundaries.

    Returns
    -------
    ndarray of str or uint64
        Sorted ids.

    Raises
    ------
    CoordinateError
        A centre that is not a finite latitude in -90..90 and a finite longitude.
    LevelError
        A bad level.
    DggsValueError
        A radius that is not a number from 0 to :data:`MAX_RADIUS_M`, an unknown
        ``mode``, or ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        More cells than ``max_cells``.

    Examples
    --------
    >>> [len(circle_to_cells(48.85, 2.35, 20_000, 12, mode=m)) for m in ("contains", "center", "intersects")]
    [34, 50, 76]
    >>> circle_to_cells(90.0, 0.0, 300_000, 5).tolist()  # the North Pole, on the edge between faces A and E
    ['A40000', 'A40001', 'A50000', 'A50001', 'E00000', 'E00001', 'E10000', 'E10001']
    """
    level = check_level(level)
    limit = check_max_cells(max_cells)
    shapes = _shapes(check_projection(projection))
    lat, lng, radius = _check_args(lat, lng, radius_m, mode)
    ids = _base_cells()
    whole: list[np.ndarray] = []
    wholes = 0
    for lv in range(level + 1):
        dc, rc = _bounds(ids, lat, lng, shapes)
        near = dc - rc <= radius
        inside = dc + rc <= radius
        whole.append(ids[inside])
        wholes += kh.count_children(ids[inside], level)[0]
        check_size(wholes, limit, "circle_to_cells")
        ids, dc = ids[near & ~inside], dc[near & ~inside]
        if lv < level:
            check_size(wholes + kh.count_children(ids, lv + 1)[0], limit, "circle_to_cells")
            ids = _descendants(ids, lv + 1)
    keep = dc <= radius if mode == "center" else _exact(ids, lat, lng, radius, mode, shapes)
    found = np.concatenate([_descendants(w, level) for w in whole] + [ids[keep]])
    check_size(int(found.shape[0]), limit, "circle_to_cells")
    return ids_array(np.sort(found), as_int)
