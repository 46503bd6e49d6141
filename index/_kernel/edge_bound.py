"""Points per edge from a bound on each edge's bulge, no geodesic call per edge: compiled C, libdggs/src/edge_bound.c.

``edge_bounds(proj, ids, bulge, length)`` writes bounds (metres on WGS84) of each
edge's bulge and length; ``edge_point_counts(proj, ids, tolerance_m, area_tolerance, out)``
the points per edge a tolerance needs; ``ragged_rings(proj, ids, counts, offsets, out)``
closed (lng, lat) rings of varying counts into one flat buffer (shapely's ragged
arrays).  ``proj`` is 0 (ISEA) or 1 (IVEA); ids are assumed valid.
"""

from __future__ import annotations

from dggs._core import edge_bounds, edge_point_counts, ragged_rings

__all__ = ["edge_bounds", "edge_point_counts", "ragged_rings"]
