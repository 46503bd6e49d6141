"""Polygon fill: the cells whose centres lie in, that lie wholly in, or that touch a (Multi)Polygon."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box

from dggs.errors import DggsValueError, TooManyCellsError

from ._bbox_fill import bbox_fill
from ._checks import check_level, check_max_cells, check_size, is_choice
from ._convert import ids_array
from ._kernel import fill as kfill
from ._kernel import hierarchy as kh
from ._kernel import points as kp
from ._kernel import polygon as kpoly
from ._shapes import geometries

__all__ = ["polygon_to_cells", "FILL_MODES"]

#: The fill modes of :func:`polygon_to_cells`.
FILL_MODES = ("center", "contains", "overlaps", "overlapping_bbox")

def _wrap_polygon(poly: Any) -> Any:
    """Fold parts of a lng/lat polygon beyond +-180 back into -180..180."""
    minx, _, maxx, _ = poly.bounds
    if minx >= -180.0 and maxx <= 180.0:
        return poly
    if maxx - minx > 720.0 or minx < -540.0 or maxx > 540.0:
        raise DggsValueError(
            f"polygon longitudes {minx}..{maxx} are out of range: give them in -180..180, "
            "or up to one turn beyond for polygons across the antimeridian"
        )
    parts = []
    for k in range(int(math.floor((minx + 180) / 360)), int(math.floor((maxx + 180) / 360)) + 1):
        piece = poly.intersection(box(-180.0 + 360 * k, -90.0, 180.0 + 360 * k, 90.0))
        if not piece.is_empty:
            parts.append(shapely.affinity.translate(piece, xoff=-360.0 * k))
    return shapely.union_all(parts)


#: Levels above the target whose boundary cells have every descendant's centre tested instead of being
#: classified further.  Filling the 177 Natural Earth countries at level 10: 0 classifies 284,880 cells and
#: tests 214,119 centres, 1 165,480 and 358,200, 2 100,191 and 587,601; 1 took the least time.
_DIRECT = 1


def _near(
    target: Any, x: np.ndarray, y: np.ndarray, r: np.ndarray, indexes: dict[Any, Any], key: Any
) -> tuple[np.ndarray, np.ndarray]:
    """(hit, inside) for circles of radius ``r`` around (x, y): meeting the target, and wholly in it."""
    if ("edges", key) not in indexes:
        indexes[("edges", key)] = _edge_index(target)
    edges = indexes[("edges", key)]
    hit = np.zeros(x.shape[0], dtype=bool)
    inside = np.zeros(x.shape[0], dtype=bool)
    if edges is not None and x.shape[0]:
        kpoly.classify(x.shape[0], np.ascontiguousarray(x, dtype=np.float64), np.ascontiguousarray(y, dtype=np.float64),
                       np.ascontiguousarray(r, dtype=np.float64), *edges, hit, inside)
    return hit, inside


#: The grid of a target without edges: no bucket holds an edge, every point lies outside its bounds.
_NO_GRID = (*np.zeros((4, 1)), np.array([0.0, 0.0, 1.0, 1.0, 1.0, -1.0, -1.0]), np.zeros(2, dtype=np.int64),
            np.zeros(0, dtype=np.int64), np.zeros(1, dtype=np.int64))


def _edge_index(target: Any) -> tuple[np.ndarray, ...] | None:
    """The target's edges (x0, y0, x1, y1) and their bucket grid (frame, start, items, empty); None without edges.

    Polygons give their rings' edges.  The lines and points a wrapped target
    may hold (``shapely.contains_xy`` holds their points, a polygon split at a
    longitude of 180.00000000000006 leaves one at -180) give their edges twice,
    once each way, and points a zero-length edge: the crossing parity is the
    polygons', and a point on them is left to GEOS (:func:`dggs.index._kernel.polygon.parity`).
    """
    if target.geom_type in ("Polygon", "MultiPolygon"):  # the rings, end to end: one shapely call
        x0, y0, x1, y1, closed = kpoly.ring_edges(shapely.get_coordinates(target))
        if closed:
            return _bucketed(x0, y0, x1, y1)
    parts = shapely.get_parts(shapely.get_parts(target))
    kind = shapely.get_type_id(parts)
    lines = parts[kind != 3]
    xy, index = shapely.get_coordinates(np.concatenate([shapely.get_rings(parts[kind == 3]), lines, lines]),
                                        return_index=True)
    if xy.shape[0] == 0:
        return None
    # consecutive points of one ring or line make an edge (a ring's last point repeats its first)
    n_rings = index.max() + 1 - 2 * lines.shape[0]
    back = index >= n_rings + lines.shape[0]  # the second copy of each line, reversed
    xy[back] = xy[back][::-1]
    index[back] = index[back][::-1]
    same = index[1:] == index[:-1]
    alone = np.flatnonzero(np.bincount(index, minlength=index.max() + 1) == 1)  # points: a zero-length edge
    x0, y0 = np.concatenate([xy[:-1][same], xy[np.isin(index, alone)]]).T.copy()
    x1, y1 = np.concatenate([xy[1:][same], xy[np.isin(index, alone)]]).T.copy()
    return _bucketed(x0, y0, x1, y1)


def _bucketed(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> tuple[np.ndarray, ...] | None:
    """The edges and their bucket grid, about two buckets a row per sqrt(edges) (fewer edges per bucket)."""
    if x0.shape[0] == 0:
        return None
    side = int(min(1024, max(1, 2 * math.sqrt(x0.shape[0]))))
    return (x0, y0, x1, y1, *kpoly.build(x0, y0, x1, y1, side))


def _check_counts(level: int, mode: str, cand: np.ndarray, insides: np.ndarray, tested: int, limit: int) -> None:
    """Refuse as a level-by-level search does, naming the first count over ``max_cells``.

    On each level the cells found whole so far, then those and the next
    level's candidates, then (``"center"``) those and the centres tested.
    """
    last = max(level - _DIRECT, 0) if mode == "center" else level  # the levels classified: 0 .. last - 1
    over = kfill.first_over(cand, insides, tested, last, mode == "center", limit)
    if over >= 0:
        check_size(over, limit, "polygon_to_cells")


def _children(ids: np.ndarray, level: int) -> np.ndarray:
    total, _ = kh.count_children(ids, level)
    out = np.empty(total, dtype=np.uint64)
    kh.children(ids, level, out)
    return out


def polygon_to_cells(
    polygon: Any, level: int, mode: str = "center", as_int: bool = False, max_cells: int | None = None,
    *, projection: str = "ISEA",
) -> np.ndarray:
    """Cells at ``level`` whose centres lie in, that lie wholly in, or that touch a polygon (lng/lat, WGS84).

    Holes are respected.  A polygon that crosses the antimeridian may be given
    with longitudes beyond 180 (e.g. 170..190) or as a MultiPolygon split at
    180.  The search descends the hierarchy: cells far outside are dropped
    early, cells well inside are expanded without testing, and only cells on
    the polygon's boundary are tested.

    ``mode`` chooses the test (h3's containment modes):

    - ``"center"`` (default): cells whose centre lies inside the polygon.
      Each point goes to one cell, so fills of polygons that tile the plane
      tile the cells.
    - ``"contains"``: cells lying wholly inside the polygon (a subset of
      ``"center"``).
    - ``"overlaps"``: every cell that touches the polygon, its boundary
      included; their union covers the polygon (a superset of ``"center"``).
    - ``"overlapping_bbox"``: every cell whose lng/lat bounding box (of each
      part of its :func:`dggs.cell_to_polygon` polygon, split at the
      antimeridian) meets the polygon, boundary included: h3's experimental
      ``CONTAINMENT_OVERLAPPING_BBOX``, a superset of ``"overlaps"``
      (:mod:`dggs.index._bbox_fill`).

    Cells have curved edges.  ``"contains"`` and ``"overlaps"`` judge each
    boundary cell by its densified polygon, exactly the one
    :func:`dggs.cell_to_polygon` gives (points per edge chosen cell by cell,
    see docs/grid.md), with shapely's planar predicates in lng/lat
    (``contains`` and ``intersects``), the same plane in which the polygon's
    own edges are straight: a cell with an edge on the polygon's boundary is
    contained, a cell that meets it at one point overlaps.  Cells far from the
    polygon's boundary are decided by footprints that provably hold them
    (ellipses in lng/lat, :mod:`dggs.index._kernel.fill`), never by an edge
    test.

    Parameters
    ----------
    polygon : shapely.Polygon or shapely.MultiPolygon
        Coordinates as (lng, lat) degrees.
    level : int
        Level of the cells to return.
    mode : {"center", "contains", "overlaps", "overlapping_bbox"}
        Which cells to return (above).
    as_int : bool
        Return 64-bit integer ids (uint64) instead of strings.
    max_cells : int, optional
        Refuse to return more cells than this (default ``dggs.index.hierarchy.MAX_CELLS``);
        checked level by level before anything large is allocated.
    projection : {"ISEA", "IVEA"}
        The grid's projection (``dggs.Grid(projection).polygon_to_cells`` passes it; docs/grid.md).

    Returns
    -------
    ndarray of str or uint64
        Sorted cell ids.

    Raises
    ------
    LevelError
        ``level`` is not an integer 0..MAX_LEVEL.
    DggsValueError
        Not a (valid) shapely polygon, non-finite bounds, latitudes outside -90..90, longitudes
        more than one turn beyond -180..180, an unknown ``mode``, or ``max_cells`` is not None or
        a non-negative integer.
    TooManyCellsError
        The result would exceed ``max_cells``.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> cells = polygon_to_cells(box(-10, -10, 10, 10), 6)
    >>> len(cells), str(cells[0])
    (276, 'C300002')
    >>> [len(polygon_to_cells(box(-10, -10, 10, 10), 6, mode=m)) for m in ("contains", "center", "overlaps")]
    [232, 276, 338]
    """
    level = check_level(level)
    if not is_choice(mode, FILL_MODES):
        raise DggsValueError(f"mode {mode!r} must be one of {', '.join(map(repr, FILL_MODES))}")
    if not isinstance(polygon, (Polygon, MultiPolygon)):
        raise DggsValueError(f"polygon must be a shapely Polygon or MultiPolygon, not {type(polygon).__name__}")
    if not is_choice(projection, ("ISEA", "IVEA")):
        raise DggsValueError(f"projection {projection!r} is not one of ISEA, IVEA")
    found = (_fill(polygon, level, max_cells, mode=mode, projection=projection) if not polygon.is_empty
             else np.zeros(0, dtype=np.uint64))
    return ids_array(found, as_int)


def _cell_geometries(ids: np.ndarray, level: int, projection: str = "ISEA") -> np.ndarray:
    """The cells' polygons as :func:`dggs.cell_to_polygon` draws them (default densification, cell by cell)."""
    if projection == "IVEA":
        from ._ivea_shapes import geometries as ivea_geometries

        return ivea_geometries(ids, None)
    return geometries(ids, None)


def _edge_test(target: Any, ids: np.ndarray, level: int, mode: str, projection: str = "ISEA") -> np.ndarray:
    """Which cells lie wholly in (``"contains"``) or touch (``"overlaps"``) the target."""
    if ids.size == 0:
        return np.zeros(0, dtype=bool)
    geoms = _cell_geometries(ids, level, projection)
    test: np.ndarray = shapely.contains(target, geoms) if mode == "contains" else shapely.intersects(target, geoms)
    return test


def _fill(
    polygon: Any, level: int, max_cells: int | None, work: dict[str, int] | None = None, mode: str = "center",
    projection: str = "ISEA",
) -> np.ndarray:
    """Sorted uint64 ids of the cells at ``level`` in ``polygon`` by ``mode`` (see :func:`polygon_to_cells`).

    The compiled descent (:func:`dggs.index._kernel.fill.descend`) finds the
    cells; the few centres it cannot place exactly (on an edge) go to GEOS,
    and in the modes other than ``"center"`` the boundary cells to
    :func:`_edge_test`.  ``work``, if given, counts the cells classified
    (``"classified"``) and the centres or cells tested at the target level
    (``"tested"``): the work, independent of the machine's speed.
    """
    if work is not None:
        work.setdefault("classified", 0)
        work.setdefault("tested", 0)
    if not polygon.is_valid:
        raise DggsValueError(f"polygon is not valid: {shapely.is_valid_reason(polygon)}")
    minx, miny, maxx, maxy = polygon.bounds
    if not all(math.isfinite(v) for v in polygon.bounds):
        raise DggsValueError(f"polygon bounds {polygon.bounds} are not finite")
    if miny < -90.0 or maxy > 90.0:
        raise DggsValueError(f"polygon latitudes {miny}..{maxy} are out of range -90..90")
    limit = check_max_cells(max_cells)
    target = _wrap_polygon(polygon)
    shapely.prepare(target)
    if mode == "overlapping_bbox":
        return bbox_fill(target, level, limit, None if projection == "ISEA" else lambda ids: _cell_geometries(ids, level, projection))
    x0, y0, x1, y1, frame, start, items, empty = _edge_index(target) or _NO_GRID
    fill: Any = kfill
    points: Any = kp
    if projection == "IVEA":  # the same descent compiled on IVEA's inverse (its footprint bound holds too)
        from ._kernel import ivea_fill, ivea_points

        fill, points = ivea_fill, ivea_points
    ids, flags, n, status, cand, insides, tested, classified = fill.descend(
        level, mode == "center", _DIRECT, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit
    )
    if work is not None:
        work["classified"] += int(classified)
        work["tested"] += int(tested)
    _check_counts(level, mode, cand, insides, int(tested), limit)
    if status == kfill.TOO_MANY:  # pragma: no cover - _check_counts refuses every count the descent stops at
        raise TooManyCellsError(f"polygon_to_cells would return more than {limit:,} cells")
    ids, flags = ids[:n], flags[:n]
    keep = flags == kfill.SURE
    unsure = np.flatnonzero(flags == kfill.CENTRE)
    if unsure.size:
        lat, lng = np.empty(unsure.size), np.empty(unsure.size)
        points.centres(unsure.size, ids[unsure], lat, lng)
        keep[unsure] = shapely.contains_xy(target, lng, lat)
    edge = np.flatnonzero(flags == kfill.EDGE)
    if edge.size:
        keep[edge] = _edge_test(target, ids[edge], level, mode, projection)
    return _children(ids[keep], level)
