"""Corners of cells (compiled C, libdggs/src/vertex.c): the cells round a corner (its fan) and corner-sharing disks.

A walk round a corner crosses the edge that starts at it, and in each new cell the next edge that starts there
(both cells' corners run counter-clockwise, so the corner is the far end of the edge back): the grid's edge
adjacency alone, no projection, no tolerance.

* ``fans(ids, corner, fan, corners, size)``: ``fan`` and ``corners`` (N, :data:`MAX_FAN`); returns the index of a
  walk that did not close, or -1.
* ``disk_width(k, level)``: the proven bound of a disk (the edge disk of radius 6k, or the level).
* ``disk_row(cell, k, width)``: one disk, sorted, or None if it outgrows ``width``.
"""

from __future__ import annotations

from dggs._core import vertex_disk_row as disk_row
from dggs._core import vertex_disk_width as disk_width
from dggs._core import vertex_fans as fans
from dggs._core import vertex_MAX_FAN as MAX_FAN

__all__ = ["MAX_FAN", "disk_row", "disk_width", "fans"]
