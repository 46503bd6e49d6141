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
:func:`compact`, :func:`uncompact_prepare`, :func:`uncompact`.
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
    range_end,
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
#: Radix sort: bits per pass, and the smallest input it is used for (np.sort below).
_RADIX_BITS = 12
_RADIX_MIN = 4096


# --------------------------------------------------------------------------- helpers


@njit(cache=True, nogil=True, inline="always")
def _n_desc(cell_level: int, level: int) -> int:
    """Descendants at ``level`` of one cell at ``cell_level`` <= ``level`` (6 children under a base cell)."""
    if cell_level == level:
        return 1
    if cell_level == 0:
        return 6 * _POW3[level - 1]
    return _POW3[level - cell_level]


@njit(cache=True, nogil=True, inline="always")
def _finer_than(cell: np.uint64, level: int) -> bool:
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


@njit(cache=True, nogil=True)
def _radix_sort(a: np.ndarray) -> np.ndarray:
    """Sorted copy of ``a`` (LSD radix sort, several times faster than numba's ``np.sort``).

    Only the bits that differ between keys are sorted (ids share the marker,
    and ids of one level share their empty low fields), in passes of <= 12 bits.
    """
    all_and = ~_U0
    any_or = _U0
    for i in range(a.size):
        all_and &= a[i]
        any_or |= a[i]
    diff = all_and ^ any_or
    if diff == _U0:
        return a.copy()
    low = 0
    while (diff >> np.uint64(low)) & _U1 == _U0:
        low += 1
    high = 63
    while (diff >> np.uint64(high)) & _U1 == _U0:
        high -= 1
    n_pass = (high - low + _RADIX_BITS) // _RADIX_BITS
    width = (high - low + n_pass) // n_pass  # ceil(span / n_pass)
    mask = np.uint64((1 << width) - 1)
    hist = np.zeros((n_pass, 1 << width), dtype=np.int64)
    for i in range(a.size):
        x = a[i] >> np.uint64(low)
        for p in range(n_pass):
            hist[p, (x >> np.uint64(width * p)) & mask] += 1
    src = a.copy()
    dst = np.empty_like(a)
    for p in range(n_pass):
        off = hist[p]
        total = 0
        for b in range(off.size):  # counts -> start offsets
            c = off[b]
            off[b] = total
            total += c
        sh = np.uint64(low + width * p)
        for i in range(src.size):
            b = (src[i] >> sh) & mask
            dst[off[b]] = src[i]
            off[b] += 1
        src, dst = dst, src
    return src


@njit(cache=True, nogil=True)
def _sorted(ids: np.ndarray) -> np.ndarray:
    """``ids`` if already non-decreasing, else a sorted copy."""
    for i in range(1, ids.size):
        if ids[i] < ids[i - 1]:
            return np.sort(ids) if ids.size < _RADIX_MIN else _radix_sort(ids)
    return ids


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
        n = _n_desc(lv, level)
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
        if pos + _n_desc(lv, level) > out.size:
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
def compact(ids: np.ndarray) -> np.ndarray:
    """Fewest cells covering the same area, sorted.

    Sorts, then one linear pass: a cell inside the last kept cell's range
    (a duplicate or a descendant of a kept cell) is dropped; a kept cell is
    pushed on a stack, and while the top of the stack is a complete sibling
    set (6 under a base cell, 3 elsewhere; siblings are adjacent in id order)
    it is replaced by the parent, which may complete its own set.

    Parameters
    ----------
    ids : ndarray of uint64
        Valid ids, any order, any levels, duplicates allowed.

    Returns
    -------
    ndarray of uint64
    """
    s = _sorted(ids)
    stack = np.empty(s.size, dtype=np.uint64)
    top = 0
    end = _U0  # one past the last kept cell's descendants
    for i in range(s.size):
        cell = s[i]
        if cell < end:
            continue
        lv = level_of(cell)
        end = range_end(cell, lv)
        stack[top] = cell
        top += 1
        while lv > 0:
            k = 6 if lv == 1 else 3
            sh = shift_of(lv)
            parent = parent_at(cell, lv - 1)
            # `cell` must be the last sibling and the k entries below it the earlier ones
            if top < k or cell != parent | (np.uint64(k) << sh):
                break
            complete = True
            for j in range(k - 1):
                if stack[top - k + j] != parent | (np.uint64(j + 1) << sh):
                    complete = False
                    break
            if not complete:
                break
            top -= k
            stack[top] = parent
            top += 1
            cell = parent
            lv -= 1
    return stack[:top].copy()


@njit(cache=True, nogil=True)
def uncompact_prepare(ids: np.ndarray, level: int) -> tuple[np.ndarray, int, int]:
    """Sorted, non-overlapping cover of ``ids`` and its size at ``level``, for :func:`children`.

    Sorts ``ids`` (unless already sorted) and drops every cell inside the
    range of the previous kept one (duplicates, descendants of a kept cell).
    ``children(cells, level, out)`` then writes the uncompacted cells in id
    order without re-sorting.

    Returns
    -------
    cells : ndarray of uint64
    total : int
        Number of cells at ``level`` (int64, saturated at ``2**63 - 1``).
    bad : int
        -1, or the position in ``ids`` of the first cell finer than ``level``.
    """
    for i in range(ids.size):
        if _finer_than(ids[i], level):
            return np.empty(0, dtype=np.uint64), 0, i
    s = _sorted(ids)
    cells = np.empty(s.size, dtype=np.uint64)
    n = 0
    total = 0
    end = _U0
    for i in range(s.size):
        cell = s[i]
        if cell < end:
            continue
        lv = level_of(cell)
        end = range_end(cell, lv)
        cells[n] = cell
        n += 1
        c = _n_desc(lv, level)
        total = _INT64_MAX if total > _INT64_MAX - c else total + c
    return cells[:n].copy(), total, -1


@njit(cache=True, nogil=True)
def uncompact(ids: np.ndarray, level: int) -> tuple[np.ndarray, int]:
    """All descendants at ``level`` of the area covered by ``ids``, sorted and unique (no size limit).

    :func:`uncompact_prepare` then :func:`children` into a fresh array; use
    those two directly to check the size before allocating.

    Returns
    -------
    out : ndarray of uint64
    bad : int
        -1, or the position in ``ids`` of the first cell finer than ``level``.
    """
    cells, total, bad = uncompact_prepare(ids, level)
    out = np.empty(total if bad < 0 else 0, dtype=np.uint64)
    if bad >= 0:
        return out, bad
    children(cells, level, out)
    return out, -1


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
