"""Compiled grid distances between ids of one level: exact, by mirror lines, in O(level) time at any range.

Within one face pair and away from the icosahedron vertices the distance is
the count of separating mirror lines in a planar chart, which proves it
(:func:`dggs.index._kernel.grid_tables.chart_distance`); elsewhere the fewest
mirror lines over the straight face strips between the cells
(:func:`dggs.index._kernel.strips.strip_distance`).  Level 0 (20 cells) reads
the faces' distances (:data:`grid_tables.FACE_DISTANCE`); any pair no strip
serves (none in the checks) takes a bidirectional
breadth-first search over the rings of :func:`dggs.index._kernel.grid.next_ring`,
within :data:`SEARCH_LIMIT` steps, compiled on its own (:func:`search`, called
by the verb for the pairs :func:`distance` marks :data:`NEEDS_SEARCH`) so that
the common path compiles in a third of the time.  Results of :func:`distance`:
the distance; -1 for "more than ``max_steps`` apart"; :data:`NEEDS_SEARCH`.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from dggs.geometry._parallel import loops

from .bits import level_of
from .grid import next_ring
from .grid_tables import FACE_DISTANCE, chart_distance
from .strips import strip_distance

__all__ = ["NEEDS_SEARCH", "SEARCH_LIMIT", "distance", "distances", "search"]

#: What :func:`distance` returns for a pair only a search can settle.
NEEDS_SEARCH = -3
_FACE_DISTANCE = FACE_DISTANCE.copy()

#: Most steps the fallback search takes (O(d**2) cells: 4096 steps is about 20 M cells).
SEARCH_LIMIT = 4096


@njit(cache=True, nogil=True)
def _grow(buf: np.ndarray, need: int) -> np.ndarray:
    if buf.shape[0] >= need:
        return buf
    new = np.empty(max(need, 2 * buf.shape[0]), dtype=np.uint64)
    new[: buf.shape[0]] = buf
    return new


@njit(cache=True, nogil=True)
def _intersects(x: np.ndarray, y: np.ndarray) -> bool:
    i = 0
    j = 0
    while i < x.shape[0] and j < y.shape[0]:
        if x[i] == y[j]:
            return True
        if x[i] < y[j]:
            i += 1
        else:
            j += 1
    return False


@njit(cache=True, nogil=True)
def _bfs_distance(a: np.uint64, b: np.uint64, max_steps: int) -> int:
    """Bidirectional breadth-first search: rings from both ends, the smaller grows (O(d**2) cells).

    Invariant: the distance exceeds ``ra + rb``.  Growing ring ``ra`` to ``ra + 1``,
    a path of length ``ra + 1 + rb`` exists iff the new ring meets ring ``rb``.
    """
    if a == b:
        return 0
    bufs = [np.empty(64, dtype=np.uint64) for _ in range(6)]  # (prev, cur, next) per side
    ns = np.zeros(6, dtype=np.int64)
    radius = np.zeros(2, dtype=np.int64)
    bufs[1][0], bufs[4][0] = a, b
    ns[1] = ns[4] = 1
    cand = np.empty(64, dtype=np.uint64)
    while radius[0] + radius[1] < max_steps:
        side = 0 if ns[1] <= ns[4] else 1
        o = 3 * side
        cand = _grow(cand, 3 * ns[o + 1])
        bufs[o + 2] = _grow(bufs[o + 2], 3 * ns[o + 1])
        n = next_ring(bufs[o + 1][: ns[o + 1]], bufs[o][: ns[o]], bufs[o + 2], cand)
        if n == 0:
            return -1
        bufs[o], bufs[o + 1], bufs[o + 2] = bufs[o + 1], bufs[o + 2], bufs[o]
        ns[o], ns[o + 1] = ns[o + 1], n
        radius[side] += 1
        other = 3 - o
        if _intersects(bufs[o + 1][:n], bufs[other + 1][: ns[other + 1]]):
            return radius[0] + radius[1]
    return -1


@njit(cache=True, nogil=True)
def distance(a: np.uint64, b: np.uint64, max_steps: int) -> int:
    """Edge steps on a shortest path between two valid cells of one level (the caller checks the levels).

    Parameters
    ----------
    a, b : uint64
        The cells.
    max_steps : int
        Give up beyond this distance.

    Returns
    -------
    int
        The distance; -1 if it exceeds ``max_steps``; :data:`NEEDS_SEARCH` if no
        straight strip serves the pair (then :func:`search`).

    Notes
    -----
    Exact.  Where a planar chart proves it (both cells on one face or two
    adjacent faces, and the disk the count spans clear of the icosahedron
    vertices: most pairs at fine levels) it is the number of separating mirror
    lines (:func:`dggs.index._kernel.grid_tables.chart_distance`); otherwise the
    fewest over the straight face strips (:mod:`dggs.index._kernel.strips`).
    Both take O(level) time whatever the distance.
    """
    if a == b:
        return 0
    level = level_of(a)
    if level == 0:
        d = _FACE_DISTANCE[np.int64((a >> np.uint64(57)) & np.uint64(31)), np.int64((b >> np.uint64(57)) & np.uint64(31))]
    else:
        d = chart_distance(a, b, level)
        if d < 0:
            d = chart_distance(b, a, level)
        if d < 0:
            d = strip_distance(a, b, level)
        if d < 0:
            return NEEDS_SEARCH
    return d if d <= max_steps else -1


@njit(cache=True, nogil=True)
def search(a: np.uint64, b: np.uint64, max_steps: int) -> int:
    """The distance by breadth-first search, or -1 beyond ``min(max_steps, SEARCH_LIMIT)`` steps."""
    return _bfs_distance(a, b, min(max_steps, SEARCH_LIMIT))


def _distances_impl(a: np.ndarray, b: np.ndarray, max_steps: int, out: np.ndarray) -> None:
    """``out[i] = distance(a[i], b[i], max_steps)`` (int64), pairs in parallel."""
    for i in prange(a.shape[0]):
        out[i] = distance(a[i], b[i], max_steps)


distances = loops(_distances_impl)
