"""Child positions and local (i, j) lattice coordinates over 64-bit ids (compiled).

Child positions (docs/grid.md, "Child positions")
-------------------------------------------------
The position of a cell among the descendants of its ancestor at level ``p``,
at the cell's own level, in digit order: the digits below level ``p`` read
as a number in base 3, except that the level-1 digit (0-5) is a base-6 digit
when ``p`` is 0.

Local coordinates (docs/grid.md, "Local coordinates")
-----------------------------------------------------
Every level >= 1 is the kisrhombille tiling of an equilateral triangle
lattice: a cell's corner A (30 degrees) is a lattice vertex, B (60 degrees) a
lattice triangle's centre, C (90 degrees) an edge midpoint.  With the anchor's
``e1 = 2 (C - A)`` and ``e2`` = ``e1`` turned 60 degrees counter-clockwise, a
cell's centroid relative to the anchor's centroid is ``(u e1 + v e2) / 18``
with integers ``u = v (mod 3)``; ``i = (2u + v) / 3`` and ``j = (u + 2v) / 3``
are the cell's coordinates.  At level 0 (the faces) ``e1`` is a face edge and
the centroid is ``(u e1 + v e2) / 3``.  Cells on the anchor's face and on the
three faces across its edges are unfolded into the anchor's face plane by the
rigid motion that fixes the two shared vertices; other cells are out of range.
A kernel marks what it cannot answer: ``OUT_OF_RANGE`` in ``i``, or the null id.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from dggs.geometry import kernel as gk
from dggs.geometry._parallel import loops

from . import bits
from .points import encode_point, triangle

__all__ = ["OUT_OF_RANGE", "child_pos", "child_pos_cells", "local_ij", "local_cells", "one_child_pos", "one_local_ij",
           "one_child_cell", "one_local_cell",
           "UNFOLD_FACE"]

#: Marks a cell that has no coordinates around its anchor (in ``i``).
OUT_OF_RANGE = np.iinfo(np.int64).min
_SQ3_2 = math.sqrt(3.0) / 2.0
_CORNERS = gk.FACE_CORNERS_CCW
_FRAMES = gk.ISEA_FRAMES


# ----------------------------------------------------------------------------
# Child positions
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def child_count(parent_level: int, level: int) -> np.int64:
    """Descendants at ``level`` of one cell at ``parent_level`` (<= level)."""
    if level == parent_level:
        return np.int64(1)
    n = np.int64(3) ** np.int64(level - max(parent_level, 1))
    return n * 6 if parent_level == 0 else n


def _child_pos(ids, parent_level, out):
    """``out[i]``: the position of ``ids[i]`` below its ancestor at ``parent_level``; -1 if that is finer."""
    for i in prange(ids.shape[0]):
        cell = ids[i]
        level = bits.level_of(cell)
        if level < parent_level:
            out[i] = -1
            continue
        pos = np.int64(0)
        for lv in range(parent_level + 1, level + 1):
            base = 6 if lv == 1 else 3
            pos = pos * base + bits.digit_of(cell, lv)
        out[i] = pos


child_pos = loops(_child_pos)


@njit(cache=True, nogil=True)
def one_child_pos(cell: int, parent_level: int) -> int:
    """The single-id entry of :func:`child_pos`: -1 for an invalid id or a cell coarser than ``parent_level``."""
    c = np.uint64(cell)
    if not bits.is_valid(c):
        return -1
    level = bits.level_of(c)
    if level < parent_level:
        return -1
    pos = 0
    for lv in range(parent_level + 1, level + 1):
        pos = pos * (6 if lv == 1 else 3) + bits.digit_of(c, lv)
    return pos


def _child_pos_cells(pos, parents, level, out):
    """``out[i]``: the descendant of ``parents[i]`` at ``level`` at position ``pos[i]``; 0 if out of range."""
    for i in prange(parents.shape[0]):
        parent = parents[i]
        p = bits.level_of(parent)
        q = pos[i]
        if p > level or q < 0 or q >= child_count(p, level):
            out[i] = 0
            continue
        cell = parent
        for lv in range(level, p, -1):
            base = 6 if lv == 1 else 3
            cell |= np.uint64(q % base + 1) << bits.shift_of(lv)
            q //= base
        out[i] = cell


child_pos_cells = loops(_child_pos_cells)


@njit(cache=True, nogil=True)
def one_child_cell(parent: int, pos: int, level: int) -> np.uint64:
    """The single-id entry of :func:`child_pos_cells`: the null id for an invalid parent or position."""
    p = np.uint64(parent)
    if not bits.is_valid(p):
        return np.uint64(0)
    positions = np.full(1, pos, dtype=np.int64)
    out = np.zeros(1, dtype=np.uint64)
    _child_pos_cells_one(positions, p, level, out)
    return out[0]


@njit(cache=True, nogil=True)
def _child_pos_cells_one(pos, parent, level, out) -> None:
    p = bits.level_of(parent)
    q = pos[0]
    if p > level or q < 0 or q >= child_count(p, level):
        return
    cell = parent
    for lv in range(level, p, -1):
        base = 6 if lv == 1 else 3
        cell |= np.uint64(q % base + 1) << bits.shift_of(lv)
        q //= base
    out[0] = cell


# ----------------------------------------------------------------------------
# Unfolding: the faces across each edge of a face, moved into its plane
# ----------------------------------------------------------------------------
def _unfold_tables() -> tuple[np.ndarray, np.ndarray]:
    """The faces across each face's edges, and the motions that unfold them.

    ``face[f, k]`` is the face across edge k (corner k to k + 1) of face f;
    ``motion[f, k]`` is (cos, sin, tx, ty) taking that face's frame into f's
    unfolded plane (the rigid motion fixing the two shared vertices).
    """
    n = _FRAMES.shape[0]
    unit = np.empty((n, 3, 3))
    for f in range(n):
        for c in range(3):
            unit[f, c] = gk.inverse_unit(_FRAMES, f, _CORNERS[c, 0], _CORNERS[c, 1])
    face = np.full((n, 3), -1, dtype=np.int64)
    motion = np.zeros((n, 3, 4))
    for f in range(n):
        for k in range(3):
            p, q = unit[f, k], unit[f, (k + 1) % 3]
            for g in range(n):
                if g == f:
                    continue
                ip = [c for c in range(3) if np.abs(unit[g, c] - p).max() < 1e-9]
                iq = [c for c in range(3) if np.abs(unit[g, c] - q).max() < 1e-9]
                if ip and iq:
                    a0, a1 = _CORNERS[ip[0]], _CORNERS[iq[0]]  # in g's frame
                    b0, b1 = _CORNERS[k], _CORNERS[(k + 1) % 3]  # in f's frame
                    ang = math.atan2(*(b1 - b0)[::-1]) - math.atan2(*(a1 - a0)[::-1])
                    co, si = math.cos(ang), math.sin(ang)
                    t = b0 - np.array([co * a0[0] - si * a0[1], si * a0[0] + co * a0[1]])
                    face[f, k] = g
                    motion[f, k] = (co, si, t[0], t[1])
    return face, motion


UNFOLD_FACE, _MOTION = _unfold_tables()
UNFOLD_FACE.setflags(write=False)


@njit(cache=True, nogil=True)
def _basis(anchor: np.uint64):
    """The anchor's face, centroid and lattice axes: ``(face, ox, oy, e1x, e1y, e2x, e2y, scale)``."""
    face, ax, ay, bx, by, cx, cy = triangle(anchor)
    if bits.level_of(anchor) == 0:
        e1x, e1y, scale = bx - ax, by - ay, 3.0
    else:
        e1x, e1y, scale = 2.0 * (cx - ax), 2.0 * (cy - ay), 18.0
    e2x = 0.5 * e1x - _SQ3_2 * e1y
    e2y = _SQ3_2 * e1x + 0.5 * e1y
    return face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0, e1x, e1y, e2x, e2y, scale


@njit(cache=True, nogil=True)
def _one_ij(anchor: np.uint64, cell: np.uint64):
    """(i, j) of ``cell`` around ``anchor`` (same level), or (OUT_OF_RANGE, 0)."""
    f, ox, oy, e1x, e1y, e2x, e2y, scale = _basis(anchor)
    g, ax, ay, bx, by, cx, cy = triangle(cell)
    px, py = (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0
    if g != f:
        k = -1
        for e in range(3):
            if UNFOLD_FACE[f, e] == g:
                k = e
        if k < 0:
            return OUT_OF_RANGE, np.int64(0)
        co, si, tx, ty = _MOTION[f, k, 0], _MOTION[f, k, 1], _MOTION[f, k, 2], _MOTION[f, k, 3]
        px, py = co * px - si * py + tx, si * px + co * py + ty
    dx, dy = px - ox, py - oy
    det = e1x * e2y - e1y * e2x
    u = round(scale * (dx * e2y - dy * e2x) / det)
    v = round(scale * (e1x * dy - e1y * dx) / det)
    return np.int64((2 * u + v) // 3), np.int64((u + 2 * v) // 3)


def _local_ij(anchors, ids, i_out, j_out):
    for n in prange(ids.shape[0]):
        i_out[n], j_out[n] = _one_ij(anchors[n], ids[n])


local_ij = loops(_local_ij)


@njit(cache=True, nogil=True)
def one_local_ij(anchor: int, cell: int):
    """The single-pair entry of :func:`local_ij`: ``(i, j, ok)``, not ok for invalid ids, two levels or no pair."""
    a, c = np.uint64(anchor), np.uint64(cell)
    if not bits.is_valid(a) or not bits.is_valid(c) or bits.level_of(a) != bits.level_of(c):
        return np.int64(0), np.int64(0), False
    i, j = _one_ij(a, c)
    return i, j, i != OUT_OF_RANGE


@njit(cache=True, nogil=True)
def _inside(x: float, y: float) -> int:
    """-1 inside the face triangle (edges included), else the first edge k whose outside holds (x, y)."""
    for k in range(3):
        x0, y0 = _CORNERS[k, 0], _CORNERS[k, 1]
        x1, y1 = _CORNERS[(k + 1) % 3, 0], _CORNERS[(k + 1) % 3, 1]
        if (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0) < -1e-15:
            return k
    return -1


@njit(cache=True, nogil=True)
def _one_cell(anchor: np.uint64, i: np.int64, j: np.int64) -> np.uint64:
    """The cell at (i, j) around ``anchor``, or the null id where no cell of the range has those coordinates."""
    f, ox, oy, e1x, e1y, e2x, e2y, scale = _basis(anchor)
    u, v = 2 * i - j, 2 * j - i
    px = ox + (u * e1x + v * e2x) / scale
    py = oy + (u * e1y + v * e2y) / scale
    face, k = f, _inside(px, py)
    if k >= 0:  # across edge k: back into that face's own frame
        face = UNFOLD_FACE[f, k]
        co, si, tx, ty = _MOTION[f, k, 0], _MOTION[f, k, 1], _MOTION[f, k, 2], _MOTION[f, k, 3]
        qx, qy = px - tx, py - ty
        px, py = co * qx + si * qy, -si * qx + co * qy
        if _inside(px, py) >= 0:
            return np.uint64(0)
    cell = encode_point(face, px, py, bits.level_of(anchor))
    ci, cj = _one_ij(anchor, cell)
    return cell if ci == i and cj == j else np.uint64(0)


def _local_cells(anchors, i_in, j_in, out):
    for n in prange(anchors.shape[0]):
        out[n] = _one_cell(anchors[n], i_in[n], j_in[n])


local_cells = loops(_local_cells)


@njit(cache=True, nogil=True)
def one_local_cell(anchor: int, i: int, j: int) -> np.uint64:
    """The single-id entry of :func:`local_cells`: the null id for an invalid anchor or a pair naming no cell."""
    a = np.uint64(anchor)
    if not bits.is_valid(a):
        return np.uint64(0)
    return _one_cell(a, np.int64(i), np.int64(j))
