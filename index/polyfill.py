"""Polygon fill: the cells whose centres lie in, that lie wholly in, or that touch a (Multi)Polygon."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box

from dggs.errors import DggsValueError

from ._checks import check_level, check_size
from ._convert import ids_array
from ._kernel import hierarchy as kh
from ._kernel import points as kp
from ._kernel import polygon as kpoly
from ._shapes import boundaries, geometries
from .hierarchy import get_base_cells

__all__ = ["polygon_to_cells", "FILL_MODES"]

#: The fill modes of :func:`polygon_to_cells`.
FILL_MODES = ("center", "contains", "overlaps")

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


#: Levels whose cells are too large for the circle test: always descended.
_COARSE = 3
#: Levels above the target whose boundary cells go straight to centre tests (9 cheap
#: point-in-polygon tests cost less than classifying 1 + 3 cells).
_DIRECT = 2
#: Footprint radius over the largest centre-corner distance (curved edges bulge a little).
_BULGE = 1.5


#: Cells whose centre is this far from the equator (degrees) are tested in a polar azimuthal
#: equidistant plane instead of lng/lat, where a footprint near a pole spans many longitudes.
_POLAR_LAT = 60.0
#: The polar planes hold the target above this latitude (degrees).
_POLAR_CLIP = 40.0
#: Segment length (degrees) of the target before it is mapped to a polar plane, and the slack
#: per degree from the pole that covers the chords (a 1-degree chord at colatitude c is 3.8e-5 c off).
_POLAR_SEGMENT = 1.0
_POLAR_SLACK = 1e-4


def _polar_xy(lat: np.ndarray, lng: np.ndarray, hemi: float) -> tuple[np.ndarray, np.ndarray]:
    """Polar azimuthal equidistant coordinates (degrees from the pole) around the pole ``hemi`` (+-1)."""
    rho = 90.0 - hemi * lat
    t = np.radians(lng)
    return rho * np.cos(t), hemi * rho * np.sin(t)


def _polar_target(target: Any, hemi: float, buffers: dict[Any, Any]) -> Any:
    """The part of the target above :data:`_POLAR_CLIP` in the polar plane of ``hemi``."""
    key = ("polar", hemi)
    if key not in buffers:
        lo, hi = (_POLAR_CLIP, 90.0) if hemi > 0 else (-90.0, -_POLAR_CLIP)
        part = shapely.segmentize(target.intersection(box(-180.0, lo, 180.0, hi)), _POLAR_SEGMENT)

        def to_plane(xy: np.ndarray) -> np.ndarray:
            x, y = _polar_xy(xy[:, 1], xy[:, 0], hemi)
            return np.column_stack([x, y])

        plane = shapely.make_valid(shapely.transform(part, to_plane))
        # the two sides of a target split at +-180 meet again on the plane
        buffers[key] = shapely.buffer(plane, 1e-12, quad_segs=2)
    return buffers[key]


def _classify(target: Any, cells: np.ndarray, level: int, buffers: dict[Any, Any]) -> tuple[np.ndarray, np.ndarray]:
    """Which cells may hold a centre in ``target`` (hit), and which lie wholly inside it.

    Each cell's lng/lat footprint lies in a circle around its centre whose
    radius is 1.5x its largest centre-to-corner distance.  A cell whose centre
    is inside the target, or within that radius of its boundary, is a hit; one
    whose centre is inside and farther than the radius from the boundary lies
    wholly inside.  Both are decided against a compiled bucket grid of the
    target's edges (:func:`_near`): O(edges near the circle) a cell, however
    jagged the target.  A circle across the antimeridian is also tested 360
    degrees over.  Cells more than :data:`_POLAR_LAT` from the equator (a pole
    on a corner among them) take the same test in a polar azimuthal
    equidistant plane, where their footprints are not stretched over the
    longitudes; coarse levels are hits, never inside.
    """
    n = cells.shape[0]
    if level < _COARSE:
        return np.ones(n, dtype=bool), np.zeros(n, dtype=bool)
    lat, lng = np.empty(n), np.empty(n)
    kp.centres(cells.shape[0], cells, lat, lng)
    corners = boundaries(cells, 0)  # (N, 3, 2) lat, lng
    dlat = corners[..., 0] - lat[:, None]
    dlng = (corners[..., 1] - lng[:, None] + 180.0) % 360.0 - 180.0
    radius = _BULGE * np.sqrt((dlat * dlat + dlng * dlng).max(axis=1))
    hit = np.zeros(n, dtype=bool)
    inside = np.zeros(n, dtype=bool)
    polar_plane = np.abs(lat) >= _POLAR_LAT
    for hemi in (1.0, -1.0):
        sel = np.flatnonzero(polar_plane & (np.sign(lat) == hemi))
        if sel.size == 0:
            continue
        x, y = _polar_xy(lat[sel], lng[sel], hemi)
        cx, cy = _polar_xy(corners[sel, :, 0], corners[sel, :, 1], hemi)
        r = _BULGE * np.sqrt(((cx - x[:, None]) ** 2 + (cy - y[:, None]) ** 2).max(axis=1))
        r += _POLAR_SLACK * (90.0 - np.abs(lat[sel]) + 2.0 * r)
        if (90.0 - np.abs(lat[sel]) + r).max() >= 90.0 - _POLAR_CLIP:  # too coarse for the plane
            polar_plane[sel] = False
            continue
        plane = _polar_target(target, hemi, buffers)
        hit[sel], inside[sel] = _near(plane, x, y, r, buffers, ("polar", hemi))
    flat = ~polar_plane
    polar = flat & (np.abs(lat) + radius >= 90.0)
    across = flat & ~polar & (np.abs(lng) + radius > 180.0)
    sel = np.flatnonzero(flat & ~polar)
    if sel.size:
        hit[sel], inside[sel] = _near(target, lng[sel], lat[sel], radius[sel], buffers, "flat")
        inside[sel] &= ~across[sel]
        over = sel[across[sel]]
        if over.size:
            shifted = lng[over] - np.copysign(360.0, lng[over])
            hit[over] |= _near(target, shifted, lat[over], radius[over], buffers, "flat")[0]
    if polar.any():
        _, miny, _, maxy = target.bounds
        hit[polar] = np.where(lat[polar] > 0, maxy >= lat[polar] - radius[polar], miny <= lat[polar] + radius[polar])
    return hit, inside


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


def _edge_index(target: Any) -> tuple[np.ndarray, ...] | None:
    """The target's edges (x0, y0, x1, y1) and their bucket grid (:func:`dggs.index._kernel.polygon.build`)."""
    ends = []
    for ring in shapely.get_rings(shapely.get_parts(target)):
        xy = shapely.get_coordinates(ring)
        if xy.shape[0] >= 2:
            ends.append(np.concatenate([xy[:-1], xy[1:]], axis=1))
    if not ends:
        return None
    seg = np.ascontiguousarray(np.concatenate(ends))
    x0, y0, x1, y1 = (np.ascontiguousarray(seg[:, i]) for i in range(4))
    side = int(min(1024, max(1, math.sqrt(seg.shape[0]))))
    frame, start, items = kpoly.build(x0, y0, x1, y1, side)
    return x0, y0, x1, y1, frame, start, items


def _children(ids: np.ndarray, level: int) -> np.ndarray:
    total, _ = kh.count_children(ids, level)
    out = np.empty(total, dtype=np.uint64)
    kh.children(ids, level, out)
    return out


def _centres_inside(target: Any, ids: np.ndarray) -> np.ndarray:
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    kp.centres(ids.shape[0], ids, lat, lng)
    inside: np.ndarray = shapely.contains_xy(target, lng, lat)
    return inside


def polygon_to_cells(
    polygon: Any, level: int, mode: str = "center", as_int: bool = False, max_cells: int | None = None
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

    Cells have curved edges.  ``"contains"`` and ``"overlaps"`` judge each
    boundary cell by its densified polygon, exactly the one
    :func:`dggs.cell_to_polygon` gives (points per edge chosen cell by cell,
    see docs/grid.md), with shapely's planar predicates in lng/lat
    (``contains`` and ``intersects``), the same plane in which the polygon's
    own edges are straight: a cell with an edge on the polygon's boundary is
    contained, a cell that meets it at one point overlaps.  Cells far from the
    polygon's boundary are decided by footprint circles 1.5x their
    centre-to-corner distance, never by an edge test.

    Parameters
    ----------
    polygon : shapely.Polygon or shapely.MultiPolygon
        Coordinates as (lng, lat) degrees.
    level : int
        Level of the cells to return.
    mode : {"center", "contains", "overlaps"}
        Which cells to return (above).
    as_int : bool
        Return 64-bit integer ids (uint64) instead of strings.
    max_cells : int, optional
        Refuse to return more cells than this (default ``dggs.index.hierarchy.MAX_CELLS``);
        checked level by level before anything large is allocated.

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
    if mode not in FILL_MODES:
        raise DggsValueError(f"mode {mode!r} must be one of {', '.join(map(repr, FILL_MODES))}")
    if not isinstance(polygon, (Polygon, MultiPolygon)):
        raise DggsValueError(f"polygon must be a shapely Polygon or MultiPolygon, not {type(polygon).__name__}")
    found = _fill(polygon, level, max_cells, mode=mode) if not polygon.is_empty else np.zeros(0, dtype=np.uint64)
    return ids_array(found, as_int)


def _cell_geometries(ids: np.ndarray, level: int) -> np.ndarray:
    """The cells' polygons as :func:`dggs.cell_to_polygon` draws them (default densification, cell by cell)."""
    return geometries(ids, None)


def _edge_test(target: Any, ids: np.ndarray, level: int, mode: str) -> np.ndarray:
    """Which cells lie wholly in (``"contains"``) or touch (``"overlaps"``) the target."""
    if ids.size == 0:
        return np.zeros(0, dtype=bool)
    geoms = _cell_geometries(ids, level)
    test: np.ndarray = shapely.contains(target, geoms) if mode == "contains" else shapely.intersects(target, geoms)
    return test


def _fill(
    polygon: Any, level: int, max_cells: int | None, work: dict[str, int] | None = None, mode: str = "center"
) -> np.ndarray:
    """Sorted uint64 ids of the cells at ``level`` in ``polygon`` by ``mode`` (see :func:`polygon_to_cells`).

    ``work``, if given, counts the cells classified (``"classified"``) and the
    centres tested at the target level (``"tested"``): the work, independent of
    the machine's speed.
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
    target = _wrap_polygon(polygon)
    shapely.prepare(target)
    buffers: dict[Any, Any] = {}
    candidates = get_base_cells(as_int=True)
    accepted: list[np.ndarray] = []
    total = 0
    for current in range(level + 1):
        if mode != "center" and current == level:
            # the target level: footprints decide the cells far from the boundary, the
            # cells' own (densified) polygons the others
            hit, inside = _classify(target, candidates, current, buffers)
            if work is not None:
                work["classified"] += int(candidates.shape[0])
            edge = candidates[hit & ~inside]
            if work is not None:
                work["tested"] += int(edge.shape[0])
            accepted.append(candidates[inside])
            accepted.append(edge[_edge_test(target, edge, level, mode)])
            break
        if mode == "center" and (current >= level - _DIRECT and current >= _COARSE or current == level):
            # the last levels: every descendant's centre is tested, no classification
            count, _ = kh.count_children(candidates, level)
            check_size(total + count, max_cells, "polygon_to_cells")
            finest = _children(candidates, level)
            if work is not None:
                work["tested"] += int(finest.shape[0])
            accepted.append(finest[_centres_inside(target, finest)])
            break
        hit, inside = _classify(target, candidates, current, buffers)
        if work is not None:
            work["classified"] += int(candidates.shape[0])
        if inside.any():
            whole = candidates[inside]
            count, _ = kh.count_children(whole, level)
            total += count
            check_size(total, max_cells, "polygon_to_cells")
            accepted.append(_children(whole, level))
        rest = candidates[hit & ~inside]
        if rest.size == 0:
            break
        count, _ = kh.count_children(rest, current + 1)
        check_size(total + count, max_cells, "polygon_to_cells")
        candidates = _children(rest, current + 1)
    if not accepted:
        return np.zeros(0, dtype=np.uint64)
    return np.sort(np.concatenate(accepted))
