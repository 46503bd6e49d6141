"""Compiled hierarchy kernels over ``uint64`` id arrays (levels, parents, children, compaction).

Every kernel takes a 1-d ``uint64`` array of VALID ids (the caller validates,
e.g. with :func:`valid_mask`) and plain int levels already range-checked to
``0 .. MAX_LEVEL``.  The layout is in :mod:`dggs.index._kernel.bits` (docs/grid.md,
"Integer ids"): marker bit 62, face in bits 61..57, the level-1 code in bits
56..54, the level-k code (k >= 2) in bits ``2(28-k)+1 .. 2(28-k)``; a code of
0 means "no digit", so the descendants of ``c`` at level ``l`` are the ints
``[c, c + 2**shift_of(l))`` and int order is the depth-first string order.

Error convention
----------------
A kernel that can meet a violated level relation returns an ``int`` named
``bad`` as its LAST return value (or as its only one): ``-1`` when every cell
is fine, else the position in the INPUT array (input order, before any
sorting) of the first offending cell.  Outputs returned next to ``bad >= 0``
are meaningless.  The Python caller raises the typed error naming
``ids[bad]``.  Violations: a cell finer than the requested level
(:func:`parents` below it, :func:`count_children`, :func:`children`,
:func:`uncompact_prepare`, :func:`uncompact`) and a base cell passed to
:func:`parents_up`.  A too-small ``out`` buffer is a programming error and
raises ``ValueError`` instead.

Counts are exact ``int64`` and saturate at ``2**63 - 1`` (the caller compares
them with its ``max_cells`` limit before allocating).

Kernels: :func:`levels`, :func:`valid_mask`, :func:`level_bounds`,
:func:`parents`, :func:`parents_up`, :func:`count_children`, :func:`children`,
:func:`parent_of`; compaction is in :mod:`.compact`.
Children and uncompaction are serial: they run at memory speed (a few ns per
output cell), and the kernels release the GIL (``nogil``) so callers may run
chunks on threads.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .bits import (
    DIGIT_LOW_BITS,
    L1_SHIFT,
    is_valid,
    level_of,
    parent_at,
    shift_of,
)

_U0 = np.uint64(0)
_U1 = np.uint64(1)
_INT64_MAX = np.iinfo(np.int64).max
#: 3**k for k = 0..28 (3**28 < 2**45, exact in int64).
_POW3 = np.array([3**k for k in range(29)], dtype=np.int64)
_POW3.setflags(write=False)
#: Levels enumerated by the precomputed offset table in :func:`children` (3**6 = 729 entries, 5.8 kB).
_TABLE_LEVELS = 6


# --------------------------------------------------------------------------- helpers


@njit(cache=True, nogil=True, inline="always")
def n_desc(cell_level: int, level: int) -> int:
    """Descendants at ``level`` of one cell at ``cell_level`` <= ``level`` (6 children under a base cell)."""
    if cell_level == level:
        return 1
    if cell_level == 0:
        return 6 * _POW3[level - 1]
    return _POW3[level - cell_level]


@njit(cache=True, nogil=True, inline="always")
def finer_than(cell: np.uint64, level: int) -> bool:
    """Whether ``cell`` is finer than ``level``: some field below level ``level``'s is filled."""
    return (cell & ((_U1 << shift_of(level)) - _U1)) != _U0


@njit(cache=True, nogil=True, inline="always")
def _ones(first: int, last: int) -> np.uint64:
    """Code 1 (digit 0) in every 2-bit field of levels ``first .. last`` (2 <= first; empty if first > last)."""
    if first > last:
        return _U0
    hi = (_U1 << (shift_of(first) + np.uint64(2))) - _U1  # bits up to the top of level `first`
    lo = (_U1 << shift_of(last)) - _U1  # bits below level `last`
    return DIGIT_LOW_BITS & hi & ~lo


@njit(cache=True, nogil=True)
def _offset_table(level: int) -> np.ndarray:
    """Offsets of the descendants at ``level`` under a cell ``m`` levels up, for every m <= the table size.

    Entry ``n`` spreads the base-3 digits of ``n`` into consecutive 2-bit fields
    ending at level ``level``: added to a cell whose fields down to ``level``
    hold code 1 (digit 0) it gives its ``n``-th descendant in id order (codes
    1..3 never carry).  The first ``3**m`` entries serve any ``m``.
    """
    m = min(_TABLE_LEVELS, max(level - 1, 0))  # only 2-bit fields (levels >= 2)
    table = np.empty(_POW3[m], dtype=np.uint64)
    s = shift_of(level)
    for n in range(table.size):
        v = _U0
        x = n
        k = np.uint64(0)
        while x:
            v |= np.uint64(x % 3) << k
            x //= 3
            k += np.uint64(2)
        table[n] = v << s
    return table


# --------------------------------------------------------------------------- kernels


@njit(cache=True, nogil=True)
def levels(ids: np.ndarray) -> np.ndarray:
    """Level of every (valid) id, as a ``uint8`` array."""
    out = np.empty(ids.size, dtype=np.uint8)
    for i in range(ids.size):
        out[i] = level_of(ids[i])
    return out


@njit(cache=True, nogil=True)
def valid_mask(ids: np.ndarray) -> np.ndarray:
    """Whether each integer (any ``uint64``) is a well-formed id, as a ``bool`` array; never raises.

    :func:`dggs.index._kernel.bits.is_valid`: rejects 0, bit 63 set, a clear marker
    bit, faces 20..31, level-1 code 7, and an empty field above a filled one.
    """
    out = np.empty(ids.size, dtype=np.bool_)
    for i in range(ids.size):
        out[i] = is_valid(ids[i])
    return out


@njit(cache=True, nogil=True)
def level_bounds(ids: np.ndarray) -> tuple[int, int]:
    """``(lowest, highest)`` level among ``ids``; ``(-1, -1)`` when empty."""
    if ids.size == 0:
        return -1, -1
    lo, hi = 99, -1
    for i in range(ids.size):
        lv = level_of(ids[i])
        lo, hi = min(lo, lv), max(hi, lv)
    return lo, hi


@njit(cache=True, nogil=True)
def parents(ids: np.ndarray, level: int) -> tuple[np.ndarray, int]:
    """Ancestor of every id at ``level`` (a cell at ``level`` is its own).

    Returns
    -------
    out : ndarray of uint64
        ``ids`` with every field below level ``level`` cleared.
    bad : int
        -1, or the position of the first cell coarser than ``level``.
    """
    out = np.empty(ids.size, dtype=np.uint64)
    keep = ~((_U1 << shift_of(level)) - _U1)
    if level > 0:
        # the cell reaches `level` iff level `level`'s field is filled (bits 56..54 at level 1, 2 bits after)
        field = (np.uint64(7) if level == 1 else np.uint64(3)) << shift_of(level)
        for i in range(ids.size):
            if ids[i] & field == _U0:
                return out, i
    for i in range(ids.size):
        out[i] = ids[i] & keep
    return out, -1


@njit(cache=True, nogil=True)
def parents_up(ids: np.ndarray) -> tuple[np.ndarray, int]:
    """Parent of every id, one level up each (mixed levels allowed).

    Returns
    -------
    out : ndarray of uint64
    bad : int
        -1, or the position of the first base cell (level 0 has no parent).
    """
    out = np.empty(ids.size, dtype=np.uint64)
    for i in range(ids.size):
        lv = level_of(ids[i])
        if lv == 0:
            return out, i
        out[i] = parent_at(ids[i], lv - 1)
    return out, -1


@njit(cache=True, nogil=True)
def count_children(ids: np.ndarray, level: int) -> tuple[int, int]:
    """Exact number of descendants at ``level`` over all ``ids`` (no allocation).

    A base cell has ``6 * 3**(level - 1)``, a cell at level ``k >= 1`` has
    ``3**(level - k)``, a cell at ``level`` counts itself.

    Returns
    -------
    total : int
        int64, saturated at ``2**63 - 1``.
    bad : int
        -1, or the position of the first cell finer than ``level``.
    """
    total = 0
    for i in range(ids.size):
        lv = level_of(ids[i])
        if lv > level:
            return 0, i
        n = n_desc(lv, level)
        total = _INT64_MAX if total > _INT64_MAX - n else total + n
    return total, -1


@njit(cache=True, nogil=True)
def children(ids: np.ndarray, level: int, out: np.ndarray) -> int:
    """Write the descendants at ``level`` of every id into ``out``.

    The block of cell ``i`` is contiguous and in id order; blocks follow the
    input order (so sorted, non-overlapping input gives sorted output).

    Parameters
    ----------
    ids : ndarray of uint64
    level : int
    out : ndarray of uint64
        At least :func:`count_children` long; entries past the total are untouched.

    Returns
    -------
    bad : int
        -1, or the position of the first cell finer than ``level`` (the
        blocks before it are written).

    Raises
    ------
    ValueError
        ``out`` is too short.
    """
    table = _offset_table(level)
    pos = 0
    for i in range(ids.size):
        cell = ids[i]
        lv = level_of(cell)
        if lv > level:
            return i
        if pos + n_desc(lv, level) > out.size:
            raise ValueError("children: output buffer too short")
        if lv == level:
            out[pos] = cell
            pos += 1
            continue
        if lv + 1 == level and lv > 0:  # one level down: the three codes of the next field
            sh = shift_of(level)
            out[pos] = cell | (_U1 << sh)
            out[pos + 1] = cell | (np.uint64(2) << sh)
            out[pos + 2] = cell | (np.uint64(3) << sh)
            pos += 3
            continue
        n_sub = 1  # a base cell goes through its six level-1 children (3-bit codes 1..6, bits 56..54)
        if lv == 0:
            cell |= _U1 << np.uint64(L1_SHIFT)
            lv = 1
            n_sub = 6
        # The lowest m levels come from `table`; the levels lv+1 .. level-m above them are an
        # odometer over the 2-bit code fields: add one at its lowest field, then reset to
        # code 1 every field the carry left at code 0.
        m = min(level - lv, _TABLE_LEVELS)
        nt = _POW3[m]
        n_odo = _POW3[level - lv - m]
        fill = _ones(lv + 1, level)  # digit 0 everywhere below the cell: its first descendant
        odo_step = _U1 << shift_of(level - m)
        odo_mask = _ones(lv + 1, level - m)
        for b in range(n_sub):
            q = (cell + np.uint64(b) * (_U1 << np.uint64(L1_SHIFT))) | fill
            for _ in range(n_odo):
                for j in range(nt):
                    out[pos + j] = q + table[j]
                pos += nt
                y = q + odo_step
                q = y | (~(y | (y >> _U1)) & odo_mask)
    return -1


@njit(cache=True, nogil=True)
def parent_of(cell: int, level: int) -> int:
    """Ancestor of one id (int64) at ``level`` (-1: one level up); 0 where there is none or ``cell`` is no id."""
    c = np.uint64(cell)
    if not is_valid(c):
        return 0
    lv = level_of(c)
    if level < 0:
        level = lv - 1
    if level < 0 or level > lv:
        return 0
    return int(np.int64(parent_at(c, level)))
