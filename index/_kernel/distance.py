"""Grid distances between ids of one level (compiled C, libdggs/src/distance.c): exact, in O(level) time at any range.

Within one face pair and away from the icosahedron vertices the distance is
the count of separating mirror lines in a planar chart, which proves it
(:func:`dggs.index._kernel.grid_tables.chart_distance`); elsewhere the fewest
mirror lines over the straight face strips between the cells
(:func:`dggs.index._kernel.strips.strip_distance`).  Level 0 (20 cells) reads
the faces' distances (:data:`grid_tables.FACE_DISTANCE`); any pair no strip
serves (none in the checks) takes a bidirectional breadth-first search over
the rings of :func:`dggs.index._kernel.grid.next_ring`, within
:data:`SEARCH_LIMIT` steps (:func:`search`, called by the verb for the pairs
:func:`distance` marks :data:`NEEDS_SEARCH`).  Results of :func:`distance`:
the distance; -1 for "more than ``max_steps`` apart"; :data:`NEEDS_SEARCH`.
``distances(n, a, b, max_steps, out)`` is the batch loop (``n``: the amount of work).
"""

from __future__ import annotations

from dggs._core import NEEDS_SEARCH, SEARCH_LIMIT, distance, distances, search

__all__ = ["NEEDS_SEARCH", "SEARCH_LIMIT", "distance", "distances", "search"]
