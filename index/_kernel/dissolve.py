"""Dissolve a set of cells into its outline: outline edges by id, rings, ring points.

Compiled C, libdggs/src/dissolve.c (through ``dggs._core``).

Everything here is integer work on ids, but the last step (the ring's points):

* the set is sorted, without duplicates and without cells inside other cells
  of the set (:func:`drop_covered`), so its cells' id ranges are disjoint and a
  cell is covered by the set exactly when the greatest set id at or below it
  is itself or an ancestor (one binary search);
* a cell coarser than the finest level of the set stands for its *boundary
  descendants* at that level, the descendants with an edge on its outline
  (:func:`boundary_descendants`): the edge neighbour of a descendant is
  outside the cell exactly when its id is outside the cell's range;
* an edge of a fine cell is on the outline when the cell across it (same
  level) is not covered (:func:`outline_mask`): edges shared by two cells of
  the set cancel by identity, never by coordinates;
* the outline edges are chained into rings (:func:`chain`): an edge runs from
  corner ``i`` to corner ``i + 1`` of its cell, counter-clockwise, so the set
  lies on its left; at its end corner the walk turns through the covered
  cells around the corner until the cell across is not covered: that edge is
  the next one.  Corners where the set touches itself are passed once per
  covered sector.

:func:`ring_points` then writes each ring's (lat, lng) points as
:func:`dggs.index._kernel.points.special_ring` writes a cell's: each edge's
points straight on its face plane, a pole on the ring as two points at
latitude +-90 (the directions the ring arrives and leaves), and the
antimeridian crossing between two points bisected to longitude +-180.
"""

from __future__ import annotations

from dggs._core import dissolve_boundary_descendants as boundary_descendants
from dggs._core import dissolve_chain as chain
from dggs._core import dissolve_drop_covered as drop_covered
from dggs._core import dissolve_multi_polygon as multi_polygon
from dggs._core import dissolve_outline_mask as outline_mask
from dggs._core import dissolve_ring_point_bound as ring_point_bound
from dggs._core import dissolve_ring_points as ring_points

__all__ = ["boundary_descendants", "chain", "drop_covered", "multi_polygon", "outline_mask", "ring_points", "ring_point_bound"]
