"""Shortest paths in the edge graph (compiled C, libdggs/src/paths.c): one greedy walk per pair, a step per cell.

Every step of a shortest path lowers the exact grid distance to the target by
one, and the cells of a level form a bipartite graph (a step across an edge
mirrors the cell, flipping its orientation), so each neighbour is one step
nearer or one step farther (from level 1: the level-0 graph, the
dodecahedron's, has odd cycles).  The walk takes, at each cell, the first
neighbour (in column order of :func:`dggs.index._kernel.grid.neighbours`)
that is one step nearer: deterministic, and one distance evaluation (O(level),
:func:`dggs.index._kernel.distance.distance`) a cell.

``paths(n, a, b, offsets, out, status)`` writes path ``i`` (``grid_distance(a[i], b[i]) + 1``
cells) into ``out[offsets[i]:offsets[i + 1]]``; ``status[i]`` is 0, or -1 where the
walk found no nearer neighbour (a wrong distance: never seen).
"""

from __future__ import annotations

from dggs._core import paths

__all__ = ["paths"]
