"""Dissolve a set of cells into its outline (compiled): outline edges by id, rings, ring points.

Everything here is integer work on ids, but the last step (the ring's points):

* the set is sorted, without duplicates and without cells inside other cells
  of the set (:func:`drop_covered`), so its cells' id ranges are disjoint and a
  cell is covered by the set exactly when the greatest set id at or below it
  is itself or an ancestor (:func:`_covered`, one binary search);
* a cell coarser than the finest level of the set stands for its *boundary
  descendants* at that level, the descendants with an edge on its outline
  (:func:`boundary_descendants`): the edge neighbour of a descendant is
  outside the cell exactly when its id is outside the cell's range;
* an edge of a fine cell is on the outline when the cell across it (same
  level, :mod:`.grid`) is not covered (:func:`outline_mask`): edges shared by
  two cells of the set cancel by identity, never by coordinates;
* the outline edges are chained into rings (:func:`chain`): an edge runs from
  corner ``i`` to corner ``i + 1`` of its cell, counter-clockwise, so the set
  lies on its left; at its end corner the walk turns through the covered
  cells around the corner (entering a cell across its edge ``j``, the corner
  is the cell's corner ``j + 1`` and its next edge there is ``j + 1``) until
  the cell across is not covered: that edge is the next one.  Corners where
  the set touches itself are passed once per covered sector.

:func:`ring_points` then writes each ring's (lat, lng) points as
:func:`dggs.index._kernel.points.special_ring` writes a cell's: each edge's
points straight on its face plane, a pole on the ring as two points at
latitude +-90 (the directions the ring arrives and leaves), and the
antimeridian crossing between two points bisected to longitude +-180.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from dggs.geometry import kernel as gk
from dggs.geometry._parallel import loops

from .bits import level_of, range_end, shift_of
from .grid import _neighbour
from .points import _ISEA_FRAMES, _POLE_LEAD, _crossing, _edge_params, _lat_lng_at, _pole_on, corners

__all__ = ["boundary_descendants", "chain", "drop_covered", "outline_mask", "ring_points", "ring_point_bound"]

_U1 = np.uint64(1)


@njit(cache=True, nogil=True)
def drop_covered(ids: np.ndarray) -> np.ndarray:
    """Mask of the sorted unique ``ids`` not inside an earlier id of the array (an ancestor's range)."""
    keep = np.zeros(ids.shape[0], dtype=np.bool_)
    end = np.uint64(0)
    for i in range(ids.shape[0]):
        c = ids[i]
        if c >= end:
            keep[i] = True
            end = range_end(c, level_of(c))
    return keep


@njit(cache=True, nogil=True, inline="always")
def _covered(cells: np.ndarray, y: np.uint64) -> bool:
    """Whether ``y`` is in the range of a cell of ``cells`` (sorted, disjoint ranges)."""
    i = np.searchsorted(cells, y, side="right") - 1
    if i < 0:
        return False
    x = cells[i]
    return bool(y < range_end(x, level_of(x)))


@njit(cache=True, nogil=True)
def _descend(cell: np.uint64, level: int, out: np.ndarray, write: bool) -> int:
    """Boundary descendants of ``cell`` at ``level`` (depth first), written to ``out`` if ``write``; their count."""
    top = level_of(cell)
    end = range_end(cell, top)
    stack = np.empty(6 * (level - top + 1), dtype=np.uint64)
    stack[0] = cell
    sp = 1
    n = 0
    while sp > 0:
        sp -= 1
        c = stack[sp]
        lv = level_of(c)
        s = shift_of(lv + 1)
        for code in range(6 if lv == 0 else 3, 0, -1):  # pushed in reverse: popped in id order
            ch = c | (np.uint64(code) << s)
            edge = False
            for col in range(3):
                nb = _neighbour(ch, lv + 1, col)
                if nb < cell or nb >= end:
                    edge = True
            if not edge:
                continue
            if lv + 1 == level:
                if write:
                    out[n] = ch
                n += 1
            else:
                stack[sp] = ch
                sp += 1
    return n


@njit(cache=True, nogil=True)
def boundary_descendants(ids: np.ndarray, level: int) -> np.ndarray:
    """The descendants at ``level`` of each of ``ids`` (each coarser than ``level``) with an edge on its outline."""
    counts = np.empty(ids.shape[0], dtype=np.int64)
    dummy = np.empty(0, dtype=np.uint64)
    for i in range(ids.shape[0]):
        counts[i] = _descend(ids[i], level, dummy, False)
    out = np.empty(counts.sum(), dtype=np.uint64)
    at = 0
    for i in range(ids.shape[0]):
        _descend(ids[i], level, out[at : at + counts[i]], True)
        at += counts[i]
    return out


def _outline_mask(fine: np.ndarray, cells: np.ndarray, mask: np.ndarray) -> None:
    """``mask[i, col]``: whether the edge ``col`` of ``fine[i]`` is on the outline of ``cells``."""
    for i in prange(fine.shape[0]):
        c = fine[i]
        lv = level_of(c)
        for col in range(3):
            mask[i, col] = not _covered(cells, _neighbour(c, lv, col))


outline_mask = loops(_outline_mask)


@njit(cache=True, nogil=True, inline="always")
def _find(ecell: np.ndarray, ecol: np.ndarray, cell: np.uint64, col: int) -> int:
    i = int(np.searchsorted(ecell, cell))
    while i < ecell.shape[0] and ecell[i] == cell:
        if ecol[i] == col:
            return i
        i += 1
    return -1


@njit(cache=True, nogil=True)
def chain(ecell: np.ndarray, ecol: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """Chain the outline edges (sorted by cell, then column) into rings.

    Returns ``(order, starts, bad)``: the edges' indices ring after ring,
    the start of each ring in ``order`` (one more entry: the end), and -1, or
    the index of an edge whose successor was not found (a broken grid).
    """
    m = ecell.shape[0]
    visited = np.zeros(m, dtype=np.bool_)
    order = np.empty(m, dtype=np.int64)
    starts = np.empty(m + 1, dtype=np.int64)
    pos = 0
    r = 0
    for s in range(m):
        if visited[s]:
            continue
        starts[r] = pos
        r += 1
        k = s
        while True:
            visited[k] = True
            order[pos] = k
            pos += 1
            cur = ecell[k]
            lv = level_of(cur)
            e = (ecol[k] + 1) % 3
            for _ in range(16):  # at most 12 cells around a corner
                c = _neighbour(cur, lv, e)
                if not _covered(cells, c):
                    break
                j = 0
                while j < 3 and _neighbour(c, lv, j) != cur:
                    j += 1
                e = (j + 1) % 3
                cur = c
            k = _find(ecell, ecol, cur, e)
            if k == s:
                break
            if k < 0 or visited[k]:
                return order, starts[: r + 1], order[pos - 1]
    starts[r] = pos
    return order, starts[: r + 1], -1


@njit(cache=True, nogil=True)
def ring_point_bound(steps: np.ndarray) -> int:
    """Rows :func:`ring_points` may write for edges of ``steps`` segments each."""
    return int(2 * steps.sum() + 4 * steps.shape[0])


@njit(cache=True, nogil=True, inline="always")
def _edge(cell: np.uint64, col: int):
    face, ax, ay, bx, by, cx, cy = corners(cell)
    if col == 0:
        return face, ax, ay, bx, by
    if col == 1:
        return face, bx, by, cx, cy
    return face, cx, cy, ax, ay


@njit(cache=True, nogil=True, inline="always")
def _grid_point(face: int, x0: float, y0: float, x1: float, y1: float, j: int, step: int):
    """Point ``j`` of ``step`` along the edge, computed as :func:`dggs.index._kernel.points.boundaries` does."""
    px, py, pz = gk.inverse_unit(_ISEA_FRAMES, face, x0 + j * ((x1 - x0) / step), y0 + j * ((y1 - y0) / step))
    return gk.unit_to_geodetic(px, py, pz)


@njit(cache=True, nogil=True)
def ring_points(cell: np.ndarray, col: np.ndarray, steps: np.ndarray, starts: np.ndarray, out: np.ndarray,
                corner: np.ndarray, ends: np.ndarray) -> None:
    """Write the rings' (lat, lng) points into ``out``; ``ends[r]`` is one past ring ``r``'s last row.

    ``cell``, ``col`` and ``steps`` (segments per edge: densify + 1) are the
    edges in ring order, ring ``r`` being ``starts[r]:starts[r + 1]``.
    ``corner[row]`` is set where the row is a corner of the outline (not a
    pole, a crossing or a densified point).  ``out`` needs
    :func:`ring_point_bound` rows.
    """
    n = 0
    ts = np.empty(steps.max() + 2 if steps.shape[0] else 2)
    for r in range(starts.shape[0] - 1):
        a, b = starts[r], starts[r + 1]
        for k in range(a, b):
            face, x0, y0, x1, y1 = _edge(cell[k], col[k])
            step = steps[k]
            kn = a if k + 1 == b else k + 1
            fn, nx0, ny0, nx1, ny1 = _edge(cell[kn], col[kn])
            end_at_pole = _pole_on(fn, nx0, ny0, nx1, ny1) == 0.0
            tp = _pole_on(face, x0, y0, x1, y1)
            m = _edge_params(ts, step, tp)
            lead = _POLE_LEAD / step
            for q in range(m - 1):
                ta, tb = ts[q], ts[q + 1]
                if ta == tp:
                    if ta > 0.0:
                        _, lin = _lat_lng_at(face, x0, y0, x1, y1, ta - lead)
                    else:  # the ring arrives at the pole along the previous edge
                        kp_ = b - 1 if k == a else k - 1
                        fp, px0, py0, px1, py1 = _edge(cell[kp_], col[kp_])
                        _, lin = _lat_lng_at(fp, px0, py0, px1, py1, 1.0 - _POLE_LEAD / steps[kp_])
                    _, lout = _lat_lng_at(face, x0, y0, x1, y1, ta + lead)
                    sign = 1.0 if _lat_lng_at(face, x0, y0, x1, y1, ta)[0] > 0.0 else -1.0
                    out[n, 0], out[n, 1] = 90.0 * sign, lin
                    out[n + 1, 0], out[n + 1, 1] = 90.0 * sign, lout
                    corner[n] = False
                    corner[n + 1] = False
                    n += 2
                    continue
                lat, lng = _grid_point(face, x0, y0, x1, y1, int(round(ta * step)), step)
                out[n, 0], out[n, 1] = lat, lng
                corner[n] = q == 0
                n += 1
                if tb == tp or (q == m - 2 and end_at_pole):
                    continue
                _, lng_b = _lat_lng_at(face, x0, y0, x1, y1, tb)
                if abs(lng_b - lng) > 180.0 and abs(lng) < 180.0 and abs(lng_b) < 180.0:
                    out[n, 0] = _crossing(face, x0, y0, x1, y1, ta, tb, lng)
                    out[n, 1] = 180.0 if lng > 0.0 else -180.0
                    corner[n] = False
                    n += 1
        ends[r] = n
