"""Directed edges' curves and dissolved outlines on the IVEA projection.

Compiled C, libdggs/src/edges.c and dissolve.c (through ``dggs._core``): the same functions as :mod:`.edges`
(an edge's points and its length) and :mod:`.dissolve` (the outline's ring points), called with ``DGGS_IVEA``,
so that planar points map to the globe by IVEA's inverse.  Which edges make an outline is topological and
shared: :mod:`.dissolve`'s other functions serve both projections.
"""

from __future__ import annotations

from dggs._core import ivea_dissolve_ring_points as ring_points
from dggs._core import ivea_edges_boundaries as boundaries
from dggs._core import ivea_edges_lengths as lengths
from dggs._core import ivea_edges_one_length as one_length

__all__ = ["one_length", "lengths", "boundaries", "ring_points"]
