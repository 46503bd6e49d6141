"""Compiled compaction over ``uint64`` id arrays: compact and uncompact cell sets.

Same conventions as :mod:`.hierarchy` (valid ids in, ``bad`` as the last
return value for a violated level relation).  Compaction is one stack pass
after a radix sort; uncompaction writes id ranges in order, with no re-sort.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .bits import level_of, parent_at, range_end, shift_of
from .hierarchy import children, finer_than, n_desc

_U0 = np.uint64(0)
_U1 = np.uint64(1)
_INT64_MAX = np.iinfo(np.int64).max
#: Radix sort: bits per pass, and the smallest input it is used for (np.sort below).
_RADIX_BITS = 12
_RADIX_MIN = 4096


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
        if finer_than(ids[i], level):
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
        c = n_desc(lv, level)
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
