"""The grid as a graph over 64-bit ids (compiled C, libdggs/src/grid.c): edge neighbours, disks, rings.

Every level is a reflection tiling (docs/grid.md, "Neighbours"; thesis
§6.1.7), so the cell across an edge is the cell's mirror image there, and
mirror images carry the same edge labels.  Walking up from the last digit,
the first digit whose edge is shared with a sibling changes and the digits
after it stay: a neighbour is the id with one field replaced.  At the edge of
the level-1 triangle a table gives the (face, level-1 digit) across.  The
tables come from the geometry (:mod:`dggs.index._kernel.grid_tables`, generated
into libdggs/src/grid_tables.h).

Conventions
-----------
* Ids are ``uint64`` in the layout of :mod:`dggs.index._kernel.bits`; 0 is the null id.
  Every kernel assumes valid ids (the caller validates).
* ``neighbours`` column ``i`` is the cell across the edge from corner ``i`` to
  corner ``i + 1`` of the cell's counter-clockwise corners (as
  ``edge_neighbors`` on string ids).
* Disk and ring rows are sorted ascending and padded with 0; ``counts``
  holds each row's length.  The caller allocates ``(N, disk_width(k, level))``
  (or ``ring_width``), or the largest real disk (``disk_sizes``).
  ``disk(n, ids, k, out, counts)`` and ``ring(...)`` take the amount of work
  ``n`` first (it picks the threads) and raise ValueError if a row outgrows ``out``.
* Distances are in :mod:`dggs.index._kernel.distance`.
"""

from __future__ import annotations

from dggs._core import _neighbour as _neighbour  # column col of a cell's neighbours: _neighbour(cell, level, col)
from dggs._core import (
    are_neighbours,
    disk,
    disk_of,
    disk_sizes,
    disk_width,
    level_cells,
    neighbours,
    next_ring,
    ring,
    ring_width,
)

from .grid_tables import disk_size_bound, ring_size_bound

__all__ = ["are_neighbours", "disk", "disk_of", "disk_size_bound", "disk_sizes", "disk_width", "level_cells",
           "neighbours", "next_ring", "ring", "ring_size_bound", "ring_width"]
