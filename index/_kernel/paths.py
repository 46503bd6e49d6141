"""Compiled shortest paths in the edge graph: one greedy walk per pair, a step per output cell.

Every step of a shortest path lowers the exact grid distance to the target by
one, and the cells of a level form a bipartite graph (a step across an edge
mirrors the cell, flipping its orientation), so each neighbour is one step
nearer or one step farther (from level 1: the level-0 graph, the
dodecahedron's, has odd cycles).  The walk takes, at each cell, the first
neighbour (in column order of :func:`dggs.index._kernel.grid.neighbours`)
that is one step nearer: deterministic, and one distance evaluation (O(level),
:func:`dggs.index._kernel.distance.distance`) a cell (:func:`_walk`).
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from dggs.geometry._parallel import loops

from .bits import level_of
from .distance import NEEDS_SEARCH, SEARCH_LIMIT, distance, search
from .grid import _neighbour

__all__ = ["paths"]

_FAR = 1 << 62


@njit(cache=True, nogil=True)
def _steps(x: np.uint64, target: np.uint64) -> int:
    d = distance(x, target, _FAR)
    if d == NEEDS_SEARCH:
        d = search(x, target, SEARCH_LIMIT)
    return d


@njit(cache=True, nogil=True)
def _walk(a: np.uint64, b: np.uint64, out: np.ndarray, start: int, stop: int) -> int:
    """Fill ``out[start:stop]`` with a shortest path from ``a`` to ``b``; 0, or -1 if no nearer neighbour.

    The cell stepped from is one step farther, so it is skipped; of the other
    two, if the first is not nearer the second is (some neighbour is nearer):
    one distance evaluation a step, two at most on the first.  Level 0 (the
    icosahedron's faces, whose graph has 5-cycles, so neighbours can be
    equally far) checks every candidate.
    """
    out[start] = a
    cur = a
    prev = np.uint64(0)
    level = level_of(a)
    d = stop - start - 1
    j = start
    while d > 0:
        nxt = np.uint64(0)
        left = 3 if prev == 0 else 2  # candidates not yet ruled out
        for col in range(3):
            nb = _neighbour(cur, level, col)
            if nb == prev:
                continue
            if d == 1:
                if nb == b:
                    nxt = nb
                    break
            elif (left == 1 and level > 0) or _steps(nb, b) == d - 1:
                nxt = nb
                break
            left -= 1
        if nxt == 0:
            return -1
        j += 1
        out[j] = nxt
        prev = cur
        cur = nxt
        d -= 1
    return 0 if cur == b else -1


def _paths_impl(a: np.ndarray, b: np.ndarray, offsets: np.ndarray, out: np.ndarray, status: np.ndarray) -> None:
    """Path ``i`` (``grid_distance(a[i], b[i]) + 1`` cells) into ``out[offsets[i]:offsets[i + 1]]``.

    ``status[i]`` is 0, or -1 where the walk found no nearer neighbour (a wrong distance: never seen).
    """
    for i in prange(a.shape[0]):
        status[i] = _walk(a[i], b[i], out, offsets[i], offsets[i + 1])


paths = loops(_paths_impl)
