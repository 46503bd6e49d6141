"""Points per edge from a bound on each edge's bulge, no geodesic call per edge: compiled C, libdggs/src/edge_bound.c.

``edge_bounds(proj, ids, bulge, length)`` writes bounds (metres on WGS84) of each
edge's bulge and length; ``edge_point_counts(proj, ids, tolerance_m, area_tolerance, out)``
the points per edge a tolerance needs; ``ragged_rings(proj, ids, counts, offsets, out)``
closed (lng, lat) rings of varying counts into one flat buffer (shapely's ragged
arrays); ``edge_rings_count(proj, ids, tolerance_m, area_tolerance, counts, scratch)`` and
``edge_rings_write(proj, ids, counts, scratch, offsets, out, special)`` the same rings with
the count in one pass (each ring from the count's own points where they suffice, 0, 1 or 3
an edge; ``EDGE_RING_ROWS`` scratch rows a cell) and the flags of those at a pole or across
the antimeridian.  ``proj`` is 0 (ISEA) or 1 (IVEA); ids are assumed valid.
"""

from __future__ import annotations

from dggs._core import (
    EDGE_RING_ROWS,
    edge_bounds,
    edge_point_counts,
    edge_rings_count,
    edge_rings_write,
    ragged_rings,
)

__all__ = ["EDGE_RING_ROWS", "edge_bounds", "edge_point_counts", "edge_rings_count", "edge_rings_write", "ragged_rings"]
