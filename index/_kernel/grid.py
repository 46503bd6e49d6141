"""The grid as a graph over 64-bit ids (compiled): edge neighbours, disks, rings, distances.

Every level is a reflection tiling (docs/grid.md, "Neighbours"; thesis
§6.1.7), so the cell across an edge is the cell's mirror image there, and
mirror images carry the same edge labels.  Walking up from the last digit,
the first digit whose edge is shared with a sibling changes and the digits
after it stay: a neighbour is the id with one field replaced.  At the edge of
the level-1 triangle a table gives the (face, level-1 digit) across.  The
tables come from the geometry (:mod:`dggs.index._kernel.grid_tables`).

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
* Distances are exact: a count of mirror lines in a planar chart where that is
  provably the distance on the sphere, else a bidirectional breadth-first search.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange, types
from numba.extending import intrinsic

from dggs.geometry._parallel import loops

from . import grid_tables as _t
from .bits import DIGIT_LOW_BITS, MARKER, MAX_LEVEL, level_of
from .bits import is_valid as _bits_is_valid
from .grid_tables import disk_size_bound, ring_size_bound

__all__ = ["are_neighbours", "disk", "disk_of", "disk_size_bound", "disk_sizes", "disk_width", "level_cells",
           "neighbours", "next_ring", "ring", "ring_size_bound", "ring_width"]

# The orientation parity below counts digits 0 and 2 (codes 1 and 3: the low bit): it needs these mirror children.
assert _t.CHILD_FLIP.tolist() == [True, False, True]
_STEP = _t.STEP.astype(np.int64)
_BLOCK = _t.BLOCK.copy()
_L1_TABLE = _t.L1_TABLE.astype(np.int64)
_L1_CCW = _t.L1_CCW.astype(np.int64)
_BASE_ADJ = _t.BASE_ADJ.astype(np.int64)
_COLUMN_LABEL = _t.COLUMN_LABEL.astype(np.int64)
_U3 = np.uint64(3)
_LOW54 = np.uint64((1 << 54) - 1)
_U0 = np.uint64(0)
_U63 = np.uint64(63)


@intrinsic
def _popcount(typingctx, x):
    sig = types.uint64(types.uint64)

    def codegen(context, builder, signature, args):
        return builder.ctpop(args[0])

    return sig, codegen


# ---------------------------------------------------------------------------
# Edge neighbours: the digit walk on bits
# ---------------------------------------------------------------------------
@njit(cache=True, nogil=True, inline="always")
def _across(cell: np.uint64, level: int, label: int) -> np.uint64:
    """The cell across the edge of ``label`` (a = 0, b = 1, c = 2) of a cell at ``level`` >= 1."""
    edge = label
    lv = level
    while lv >= 4:  # three levels per lookup while the block stays below level 2
        s = np.uint64(2 * (MAX_LEVEL - lv))
        r = _BLOCK[edge, np.int64((cell >> s) & _U63)]
        if r >= 64:
            return (cell & ~(_U63 << s)) | (np.uint64(r - 64) << s)
        edge = r
        lv -= 3
    for pos in range(lv, 1, -1):  # then one level at a time
        s = np.uint64(2 * (MAX_LEVEL - pos))
        step = _STEP[np.int64((cell >> s) & _U3) - 1, edge]
        if step < 3:  # a sibling shares the edge: replace this digit, keep the later ones
            return (cell & ~(_U3 << s)) | (np.uint64(step + 1) << s)
        edge = step - 3  # the edge lies on the parent's edge of this label
    face = np.int64((cell >> np.uint64(57)) & np.uint64(31))
    d1 = np.int64((cell >> np.uint64(54)) & np.uint64(7)) - 1
    nf = _L1_TABLE[face, d1, edge, 0]
    nd = _L1_TABLE[face, d1, edge, 1]
    return (cell & _LOW54) | MARKER | (np.uint64(nf) << np.uint64(57)) | (np.uint64(nd + 1) << np.uint64(54))


@njit(cache=True, nogil=True, inline="always")
def _is_ccw(cell: np.uint64) -> int:
    """1 if the cell's corners A, B, C run counter-clockwise: level-1 orientation XOR parity of digits 0 and 2."""
    d1 = np.int64((cell >> np.uint64(54)) & np.uint64(7)) - 1
    return int(_L1_CCW[d1] ^ np.int64(_popcount(cell & DIGIT_LOW_BITS) & np.uint64(1)))  # type: ignore[call-arg]


@njit(cache=True, nogil=True, inline="always")
def _neighbour(cell: np.uint64, level: int, col: int) -> np.uint64:
    """Column ``col`` of the cell's neighbours (corner ``col`` to ``col + 1``)."""
    if level == 0:
        face = np.int64((cell >> np.uint64(57)) & np.uint64(31))
        return MARKER | (np.uint64(_BASE_ADJ[face, col]) << np.uint64(57))
    return _across(cell, level, _COLUMN_LABEL[_is_ccw(cell), col])


@njit(cache=True, nogil=True)
def neighbours(ids: np.ndarray, out: np.ndarray) -> None:
    """Edge neighbours of ids of any mix of levels (level 0 too).

    Parameters
    ----------
    ids : (N,) uint64
        Valid ids.
    out : (N, 3) uint64
        Receives column ``i`` = the cell across the edge from corner ``i`` to
        corner ``i + 1`` (counter-clockwise corners; the string ids' order).
    """
    for i in range(ids.shape[0]):
        cell = ids[i]
        level = level_of(cell)
        if level == 0:
            for j in range(3):
                out[i, j] = _neighbour(cell, 0, j)
        else:
            ccw = _is_ccw(cell)
            for j in range(3):
                out[i, j] = _across(cell, level, _COLUMN_LABEL[ccw, j])


@njit(cache=True, nogil=True)
def are_neighbours(a: np.ndarray, b: np.ndarray, out: np.ndarray) -> None:
    """``out[i]`` (bool) = whether ``a[i]`` and ``b[i]`` (uint64, same shape) share an edge.

    False for cells of different levels and for a cell and itself.
    """
    for i in range(a.shape[0]):
        level = level_of(a[i])
        hit = False
        if level == level_of(b[i]):
            for j in range(3):
                if _neighbour(a[i], level, j) == b[i]:
                    hit = True
        out[i] = hit


# ---------------------------------------------------------------------------
# Disks and rings (sizes: disk_size_bound, ring_size_bound in grid_tables)
# ---------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def _sort_small(a: np.ndarray, n: int) -> None:
    """Sort ``a[:n]`` in place (insertion sort for short runs)."""
    if n > 48:
        a[:n] = np.sort(a[:n])
        return
    for i in range(1, n):
        x = a[i]
        j = i - 1
        while j >= 0 and a[j] > x:
            a[j + 1] = a[j]
            j -= 1
        a[j + 1] = x


@njit(cache=True, nogil=True)
def next_ring(cur: np.ndarray, prev: np.ndarray, dest: np.ndarray, cand: np.ndarray) -> int:
    """Ring j + 1 from rings j and j - 1 (sorted): write it sorted into ``dest``, return its size.

    In a graph the neighbours of ring j lie in rings j - 1, j and j + 1, so the
    fresh neighbours are those in neither of the last two rings.  ``cand``
    needs room for ``3 * len(cur)`` ids.
    """
    m = 0
    for x in cur:
        level = level_of(x)
        for j in range(3):
            cand[m] = _neighbour(x, level, j)
            m += 1
    _sort_small(cand, m)
    n = 0
    ip = 0
    ir = 0
    last = _U0
    for i in range(m):
        c = cand[i]
        if c == last:
            continue
        last = c
        while ip < prev.shape[0] and prev[ip] < c:
            ip += 1
        while ir < cur.shape[0] and cur[ir] < c:
            ir += 1
        if (ip < prev.shape[0] and prev[ip] == c) or (ir < cur.shape[0] and cur[ir] == c):
            continue
        if n == dest.shape[0]:
            return -1  # no room: a size bound is wrong
        dest[n] = c
        n += 1
    return n


@njit(cache=True, nogil=True, inline="always")
def _slot(x: np.uint64, mask: int) -> int:
    return int(np.int64((x * np.uint64(0x9E3779B97F4A7C15)) >> np.uint64(40)) & mask)


@njit(cache=True, nogil=True)
def _disk_row(cell: np.uint64, k: int, row: np.ndarray, table: np.ndarray) -> int:
    """Disk of radius ``k`` into ``row`` (ring after ring, then sorted); return its size, -1 if it outgrows ``row``.

    ``table`` (all 0, a power of 2 at least twice ``row``) is an open-addressing
    set of the cells seen so far; it is emptied again before returning.
    """
    mask = table.shape[0] - 1
    row[0] = cell
    table[_slot(cell, mask)] = cell
    head, tail = 0, 1
    for _ in range(k):
        end = tail  # ring j = row[head:end]
        if head == end:
            break  # the disk covers the level: later rings are empty
        while head < end:
            x = row[head]
            head += 1
            level = level_of(x)
            for j in range(3):
                y = _neighbour(x, level, j)
                s = _slot(y, mask)
                while table[s] != _U0 and table[s] != y:
                    s = (s + 1) & mask
                if table[s] == _U0:
                    if tail == row.shape[0]:
                        table[:] = 0
                        return -1
                    table[s] = y
                    row[tail] = y
                    tail += 1
    for t in range(tail):  # empty the set: clear each cell's probe run
        s = _slot(row[t], mask)
        while table[s] != _U0:
            table[s] = 0
            s = (s + 1) & mask
    _sort_small(row, tail)
    return tail


def _disk_impl(ids: np.ndarray, k: int, out: np.ndarray, counts: np.ndarray) -> None:
    """Cells within ``k`` steps of each id (the disks, origin included).

    Parameters
    ----------
    ids : (N,) uint64
        Valid ids, any mix of levels.
    k : int
        Radius, >= 0.
    out : (N, M) uint64, M >= the largest disk (:func:`disk_width`, or :func:`disk_sizes`)
        Receives row i sorted ascending, padded with 0.
    counts : (N,) int64
        Receives the size of row i.

    Notes
    -----
    Breadth-first, ring after ring; a small hash set per origin holds the
    cells seen (1.5-2x faster here than sorting each ring's candidates against
    the last two rings, as :func:`ring` does).  Origins run in parallel chunks.
    Raises ValueError if a disk outgrows ``out``.
    """
    n = ids.shape[0]
    width = out.shape[1]
    size = 64
    while size < 2 * width:
        size *= 2
    chunk = 1024
    for c in prange((n + chunk - 1) // chunk):
        table = np.zeros(size, dtype=np.uint64)
        for i in range(c * chunk, min(n, (c + 1) * chunk)):
            row = out[i, :width]
            m = _disk_row(ids[i], k, row, table)
            out[i, max(m, 0) :] = 0
            counts[i] = m
    if n and counts[:n].min() < 0:
        raise ValueError("a disk outgrew disk_size_bound(k)")


def _ring_impl(ids: np.ndarray, k: int, out: np.ndarray, counts: np.ndarray) -> None:
    """Cells exactly ``k`` steps from each id, as :func:`disk` with ``out`` (N, >= :func:`ring_width`).

    Breadth-first rings deduplicated against the last two rings only (the
    neighbours of ring j lie in rings j - 1, j and j + 1): O(k) memory per origin.
    """
    n = ids.shape[0]
    width = max(out.shape[1], 6)  # no ring is wider than ring_size_bound(k) or its level (ring_width)
    chunk = 1024
    for c in prange((n + chunk - 1) // chunk):
        cand = np.empty(3 * width, dtype=np.uint64)
        bufs = np.empty((3, width), dtype=np.uint64)
        for i in range(c * chunk, min(n, (c + 1) * chunk)):
            bufs[1, 0] = ids[i]
            a, b, nprev, ncur = 0, 1, 0, 1  # buffers of rings j - 1 and j
            for _ in range(k):
                if ncur == 0:
                    break  # past the far side of the level: every later ring is empty
                d = 3 - a - b
                nn = next_ring(bufs[b, :ncur], bufs[a, :nprev], bufs[d], cand)
                if nn < 0 or nn > out.shape[1]:
                    ncur = -1
                    break
                a, b, nprev, ncur = b, d, ncur, nn
            out[i, : max(ncur, 0)] = bufs[b, : max(ncur, 0)]
            out[i, max(ncur, 0) :] = 0
            counts[i] = ncur
    if n and counts[:n].min() < 0:
        raise ValueError("a ring outgrew ring_size_bound(k)")


# One body, two compilations (serial for small inputs: starting numba's threads
# costs microseconds, more under load); called as loop(n, *args).
disk = loops(_disk_impl)
ring = loops(_ring_impl)
_disk_serial = disk.serial  # for disk_of: compiled code calls a dispatcher, not a Loops


@njit(cache=True, nogil=True)
def level_cells(level: int) -> int:
    """Cells at ``level``: 20 at level 0, ``120 * 3 ** (level - 1)`` after (docs/grid.md)."""
    return 20 if level == 0 else 120 * 3 ** (level - 1)


@njit(cache=True, nogil=True)
def disk_width(k: int, level: int) -> int:
    """Most cells within ``k`` steps of a cell at ``level``: the planar bound, or the whole level."""
    cells = level_cells(level)
    return cells if k >= cells else min(disk_size_bound(k), cells)


@njit(cache=True, nogil=True)
def ring_width(k: int, level: int) -> int:
    """Most cells exactly ``k`` steps from a cell at ``level``."""
    cells = level_cells(level)
    return cells if k >= cells else min(ring_size_bound(k), cells)


@njit(cache=True, nogil=True)
def disk_sizes(ids: np.ndarray, k: int, cap: int, counts: np.ndarray) -> int:
    """``counts[i]`` = the size of the disk of radius ``k`` around ``ids[i]``, without storing the disk.

    Counts ring after ring (:func:`next_ring`: memory of two rings), and stops
    at the first id whose disk passes ``cap`` cells: returns its index (its
    count is then the first ring total over ``cap``), else -1.  The work is at
    most ``cap`` cells per id.
    """
    for i in range(ids.shape[0]):
        prev = np.empty(0, dtype=np.uint64)
        cur = np.full(1, ids[i], dtype=np.uint64)
        size = 1
        for _ in range(k):
            if cur.shape[0] == 0 or size > cap:
                break
            dest = np.empty(3 * cur.shape[0], dtype=np.uint64)  # three neighbours per cell
            m = next_ring(cur, prev, dest, np.empty(3 * cur.shape[0], dtype=np.uint64))
            prev, cur = cur, dest[:m]
            size += m
        counts[i] = size
        if size > cap:
            return i
    return -1


@njit(cache=True, nogil=True)
def disk_of(cell: int, k: int, max_cells: int) -> np.ndarray:
    """The disk of one id (int64), sorted (the single-id entry).

    Empty (a miss, which the caller explains) if it is no id, if ``k`` is over
    64 (the general path takes any k), or if the row the disk may need
    (:func:`disk_width`) is over ``max_cells``: the general path then counts the real disk.
    """
    if k > 64 or not _bits_is_valid(np.uint64(cell)):
        return np.empty(0, dtype=np.uint64)
    width = disk_width(k, level_of(np.uint64(cell)))
    if width > max_cells:
        return np.empty(0, dtype=np.uint64)
    out = np.empty((1, width), dtype=np.uint64)
    counts = np.empty(1, dtype=np.int64)
    ids = np.empty(1, dtype=np.uint64)
    ids[0] = np.uint64(cell)
    _disk_serial(ids, k, out, counts)
    return out[0, : counts[0]]
