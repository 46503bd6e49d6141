"""Points per edge, cell by cell: as few as keep a polygon's area true to the cell's.

A cell's edges are straight in the face plane of Snyder's projection and
curved on the ellipsoid; a polygon through ``d`` points per edge joins them
by geodesics (what :class:`pyproj.Geod` measures).  Between two points the
true edge departs from the geodesic by a bulge that shrinks as ``1 / (d + 1)**2``
(the edge is smooth: halving a segment quarters its sagitta).  So one
measurement per edge, the distance ``b`` from the true midpoint to the
geodesic midpoint of its ends (``d = 0``), gives what any ``d`` needs: each
edge's lune between curve and geodesic is at most ``2/3 b L`` (``L`` its
length; the parabola's segment), summed over the three edges without letting
opposite bulges cancel, within ``area_tolerance`` of the cell's exact area.

The count is rounded up to a power of two (at most 256), so a million cells
make a handful of groups, each built in one vectorized call.  Checked
against pyproj.Geod on random cells and on cells at icosahedron vertices,
where the projection bends most (tests/index/test_area.py).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._kernel import hierarchy as kh
from ._kernel import points as kp

__all__ = [
    "AREA_TOLERANCE", "DRAW_TOLERANCE", "EXACT", "STEPS", "check_tolerance", "edge_points", "edge_points_metadata",
    "needed_densify",
]  # fmt: skip

#: The relative area error :func:`dggs.cell_to_polygon`'s default keeps within.
AREA_TOLERANCE = 1e-6

#: The exports' default ``tolerance``: metres between a drawn edge and the true one (docs/storage.md,
#: "Files sized to need"); under a pixel of any web map that shows a cell's edges, and level-10 files near H3's size.
DRAW_TOLERANCE = 10.0

#: The ``tolerance`` that asks for :func:`dggs.cell_to_polygon`'s area-exact default instead of a distance.
EXACT = "exact"

#: The point counts used: each a power of two (and 0), the largest the cap.
STEPS = np.array([0, 1, 2, 4, 8, 16, 32, 64, 128, 256])


#: Metres per degree of latitude, the largest on WGS84 (at the poles): the flat metric errs long.
_M_PER_DEG_LAT = 111_694.0

#: Headroom for the flat metric's error in longitude (the ellipsoid's radius of curvature across).
_SAFETY = 1.01


def _geod() -> object:
    from pyproj import Geod

    return Geod(ellps="WGS84")


def needed_densify(ids: np.ndarray, area_tolerance: float = AREA_TOLERANCE, rings: Any = None) -> np.ndarray:
    """Points per edge each cell of ``ids`` (valid uint64 ids) needs, from :data:`STEPS`.

    ``area_tolerance`` is relative to the cell's area.  ``rings`` is the boundary kernel loop
    (default ISEA's ``points.boundaries``; ``dggs.Grid("IVEA")`` passes its own).
    """
    n = ids.shape[0]
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    ring = np.empty((n, 6, 2))
    (kp.boundaries if rings is None else rings)(n * 2, ids, 1, ring, False)  # (lat, lng): corner, midpoint, corner, midpoint, ...
    lat0, lng0 = ring[:, 0::2, 0].ravel(), ring[:, 0::2, 1].ravel()
    lat1, lng1 = np.roll(ring[:, 0::2, 0], -1, axis=1).ravel(), np.roll(ring[:, 0::2, 1], -1, axis=1).ravel()
    geod = _geod()
    azimuth, _, length = geod.inv(lng0, lat0, lng1, lat1)  # type: ignore[attr-defined]
    mid_lng, mid_lat, _ = geod.fwd(lng0, lat0, azimuth, length / 2)  # type: ignore[attr-defined]
    # The bulge is short (under 1 % of the edge): a local flat metric measures it to well under 1 %.
    true_lat, true_lng = ring[:, 1::2, 0].ravel(), ring[:, 1::2, 1].ravel()
    north = (true_lat - mid_lat) * _M_PER_DEG_LAT
    east = ((true_lng - mid_lng + 180.0) % 360.0 - 180.0) * _M_PER_DEG_LAT * np.cos(np.radians(true_lat))
    bulge = np.hypot(north, east) * _SAFETY
    bulge, length = bulge.reshape(n, 3), length.reshape(n, 3)
    from .measure import cell_area

    levels = kh.levels(ids)
    area = np.empty(n)
    for level in np.unique(levels).tolist():  # every cell of a level has the same area
        area[levels == level] = cell_area(int(level))
    need = (2.0 / 3.0) * (bulge * length).sum(axis=1) / (area * area_tolerance)  # (d + 1)**2 needed
    exact = np.ceil(np.sqrt(need)) - 1.0
    return STEPS[np.minimum(np.searchsorted(STEPS, exact), STEPS.size - 1)]


def check_tolerance(tolerance: Any) -> tuple[float, float]:
    """(metres, relative area) of a ``tolerance``: a positive number of metres, or ``"exact"``.

    Raises
    ------
    DggsValueError
        Anything else, named.

    Examples
    --------
    >>> check_tolerance(10), check_tolerance("exact")
    ((10.0, 0.0), (0.0, 1e-06))
    """
    from dggs.errors import DggsValueError

    if isinstance(tolerance, str) and tolerance == EXACT:
        return 0.0, AREA_TOLERANCE
    if isinstance(tolerance, (int, float, np.integer, np.floating)) and not isinstance(tolerance, bool):
        value = float(tolerance)
        if np.isfinite(value) and value > 0.0:
            return value, 0.0
    raise DggsValueError(f"tolerance must be a positive number of metres or {EXACT!r}, not {tolerance!r}")


def edge_points(ids: np.ndarray, tolerance: Any = EXACT, ivea: bool = False) -> np.ndarray:
    """Points per edge each cell of ``ids`` (valid uint64 ids) needs for ``tolerance``, computed in the core.

    ``tolerance`` is metres between each drawn edge (geodesics between its points) and the true edge, or
    ``"exact"``: each polygon's geodesic area within :data:`AREA_TOLERANCE` of the cell's.  From a bound
    on each edge's bulge (libdggs/src/edge_bound.c): no geodesic is computed; at most 256.

    Examples
    --------
    >>> import dggs
    >>> ids = np.asarray(dggs.latlng_to_cell([10.0], [20.0], 10, as_int=True), dtype=np.uint64)
    >>> int(edge_points(ids, 1000.0)[0]), bool(edge_points(ids)[0] > 1)
    (0, True)
    """
    from ._kernel import edge_bound

    metres, area = check_tolerance(tolerance)
    out = np.empty(ids.shape[0], dtype=np.int32)
    if ids.shape[0]:
        edge_bound.edge_point_counts(1 if ivea else 0, np.ascontiguousarray(ids, dtype=np.uint64), metres, area, out)
    return out.astype(np.int64)


def edge_points_metadata(densify: int | None, tolerance: Any) -> dict[str, Any]:
    """How a file's polygons were drawn, for its metadata: a fixed count, a distance, or area-exact.

    Examples
    --------
    >>> edge_points_metadata(None, 10.0)
    {'edge_points': 'tolerance', 'tolerance_m': 10.0}
    >>> edge_points_metadata(None, "exact")
    {'edge_points': 'exact', 'area_tolerance': 1e-06}
    >>> edge_points_metadata(4, 10.0)
    {'edge_points': 'densify', 'densify': 4}
    """
    if densify is not None:
        return {"edge_points": "densify", "densify": int(densify)}
    metres, area = check_tolerance(tolerance)
    if area:
        return {"edge_points": EXACT, "area_tolerance": area}
    return {"edge_points": "tolerance", "tolerance_m": metres}
