"""Directed edges' curves and dissolved outlines on the IVEA projection: the same code, compiled a second time.

As :mod:`.ivea_points` does for the point kernels: the functions of :mod:`.edges` (an edge's points and its
length) and of :mod:`.dissolve` (the outline's ring points) that map planar points to the globe are rebuilt with
``gk`` bound to the geometry kernel whose ``inverse_unit`` is IVEA's.  The outline rebuild also takes IVEA's
``_lat_lng_at`` and ``_crossing`` (the antimeridian and pole cuts) from :mod:`.ivea_points`.  Which edges
make an outline is topological and shared as compiled.
"""

from __future__ import annotations

from dggs.geometry._parallel import loops

from . import dissolve as _dissolve
from . import edges as _edges
from . import ivea_points as _ki
from .ivea_points import rebuilder

_EDGE_GLOBALS, _edge_rebuilt, _edge_compiled = rebuilder(_edges)
one_length = _edge_compiled("_one_length")
_one_boundary = _edge_compiled("_one_boundary")
lengths = loops(_edge_rebuilt("_lengths"))
boundaries = loops(_edge_rebuilt("_boundaries"))

_RING_GLOBALS, _ring_rebuilt, _ring_compiled = rebuilder(_dissolve)
_RING_GLOBALS["_lat_lng_at"] = _ki._lat_lng_at
_RING_GLOBALS["_crossing"] = _ki._crossing
_grid_point = _ring_compiled("_grid_point", cache=True, nogil=True, inline="always")
ring_points = _ring_compiled("ring_points")

__all__ = ["one_length", "lengths", "boundaries", "ring_points"]
