# Hierarchy and compaction (libdggs/src/hierarchy.c, compact.c): the kernels of index/_kernel/hierarchy.py and
# compact.py under their names, with their arguments and returns. Ids are 1-d uint64 arrays of any strides
# (copied once when not contiguous); the kernels are serial, as the numba ones, and release the GIL.

import numpy as np

cdef extern from "hierarchy.h" nogil:
    int64_t dggs_n_desc(int cell_level, int level)
    bint dggs_finer_than(uint64_t cell, int level)
    void dggs_levels(const uint64_t *ids, int64_t n, uint8_t *out)
    void dggs_valid_mask(const uint64_t *ids, int64_t n, uint8_t *out)
    void dggs_level_bounds(const uint64_t *ids, int64_t n, int *lo, int *hi)
    int64_t dggs_parents(const uint64_t *ids, int64_t n, int level, uint64_t *out)
    int64_t dggs_parents_up(const uint64_t *ids, int64_t n, uint64_t *out)
    int64_t dggs_count_children(const uint64_t *ids, int64_t n, int level, int64_t *total)
    int dggs_children(const uint64_t *ids, int64_t n, int level, uint64_t *out, int64_t out_size, int64_t *bad)
    int64_t dggs_parent_of(int64_t cell, int level)

cdef extern from "compact.h" nogil:
    int DGGS_RADIX_HIST
    int64_t dggs_sort_scratch_size(int64_t n)
    void dggs_radix_sort(const uint64_t *a, int64_t n, uint64_t *out, uint64_t *scratch)
    void dggs_sorted(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch)
    int64_t dggs_compact(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch)
    int64_t dggs_uncompact_prepare(const uint64_t *ids, int64_t n, int level, uint64_t *cells, uint64_t *scratch,
                                   int64_t *n_cells, int64_t *total)

cdef extern from "dggs.h" nogil:
    int _HIER_E_BUFFER "DGGS_E_BUFFER"


cdef const uint64_t[::1] _hier_ids(ids):
    """The ids as a C-contiguous uint64 view (a copy only when ``ids`` has gaps)."""
    return np.ascontiguousarray(ids)


cdef inline const uint64_t *_hier_ptr(const uint64_t[::1] a) noexcept nogil:
    return &a[0] if a.shape[0] else NULL


cdef inline uint64_t *_hier_wptr(uint64_t[::1] a) noexcept nogil:
    return &a[0] if a.shape[0] else NULL


def n_desc(int cell_level, int level):
    """Descendants at ``level`` of one cell at ``cell_level`` <= ``level`` (6 children under a base cell)."""
    if cell_level > level or cell_level < 0 or level > 28:
        raise ValueError(f"n_desc: levels {cell_level}, {level} out of order or range")
    return dggs_n_desc(cell_level, level)


def finer_than(uint64_t cell, int level):
    """Whether ``cell`` is finer than ``level``: some field below level ``level``'s is filled."""
    return dggs_finer_than(cell, level)


def levels(ids):
    """Level of every (valid) id, as a ``uint8`` array."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    cdef Py_ssize_t n = a.shape[0]
    out = np.empty(n, dtype=np.uint8)
    cdef uint8_t[::1] o = out
    with nogil:
        if n:
            dggs_levels(&a[0], n, &o[0])
    return out


def valid_mask(ids):
    """Whether each integer (any ``uint64``) is a well-formed id, as a ``bool`` array; never raises."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    cdef Py_ssize_t n = a.shape[0]
    out = np.empty(n, dtype=np.uint8)
    cdef uint8_t[::1] o = out
    with nogil:
        if n:
            dggs_valid_mask(&a[0], n, &o[0])
    return out.view(np.bool_)


def level_bounds(ids):
    """``(lowest, highest)`` level among ``ids``; ``(-1, -1)`` when empty."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    cdef int lo, hi
    with nogil:
        dggs_level_bounds(_hier_ptr(a), a.shape[0], &lo, &hi)
    return lo, hi


def parents(ids, int level):
    """Ancestor of every id at ``level``: ``(out, bad)``, bad -1 or the first cell coarser than ``level``."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    out = np.empty(a.shape[0], dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef int64_t bad
    with nogil:
        bad = dggs_parents(_hier_ptr(a), a.shape[0], level, _hier_wptr(o))
    return out, bad


def parents_up(ids):
    """Parent of every id, one level up each: ``(out, bad)``, bad -1 or the first base cell."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    out = np.empty(a.shape[0], dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef int64_t bad
    with nogil:
        bad = dggs_parents_up(_hier_ptr(a), a.shape[0], _hier_wptr(o))
    return out, bad


def count_children(ids, int level):
    """``(total, bad)``: descendants at ``level`` over all ids (saturated at 2**63 - 1), bad as hierarchy.py's."""
    cdef const uint64_t[::1] a = _hier_ids(ids)
    cdef int64_t total, bad
    with nogil:
        bad = dggs_count_children(_hier_ptr(a), a.shape[0], level, &total)
    return total, bad


def children(ids, int level, out):
    """Write the descendants at ``level`` of every id into ``out``; return bad (-1 or the first finer cell).

    Raises ValueError when ``out`` is too short (the blocks before are written).
    """
    cdef const uint64_t[::1] a = _hier_ids(ids)
    cdef uint64_t[:] o_any = out
    target = out if o_any.shape[0] == 0 or o_any.strides[0] == 8 else np.empty(o_any.shape[0], dtype=np.uint64)
    cdef uint64_t[::1] o = target
    cdef int64_t bad
    cdef int err
    with nogil:
        err = dggs_children(_hier_ptr(a), a.shape[0], level, _hier_wptr(o), o.shape[0], &bad)
    if target is not out:
        out[:] = target
    if err == _HIER_E_BUFFER:
        raise ValueError("children: output buffer too short")
    return bad


def parent_of(int64_t cell, int64_t level):
    """Ancestor of one id (int64) at ``level`` (-1: one level up); 0 where there is none or ``cell`` is no id."""
    if level < -1:
        level = -1
    elif level > 29:
        level = 29
    return dggs_parent_of(cell, <int>level)


def _compact_radix_sort(a):
    """Sorted copy of ``a`` (compact.py ``_radix_sort``: LSD radix sort over the bits that differ)."""
    cdef const uint64_t[::1] v = _hier_ids(a)
    cdef Py_ssize_t n = v.shape[0]
    out = np.empty(n, dtype=np.uint64)
    scratch = np.empty(n + DGGS_RADIX_HIST, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef uint64_t[::1] s = scratch
    with nogil:
        dggs_radix_sort(_hier_ptr(v), n, _hier_wptr(o), &s[0])
    return out


def _compact_sorted(ids):
    """``ids`` if already non-decreasing, else a sorted copy (compact.py ``_sorted``)."""
    cdef const uint64_t[::1] v = _hier_ids(ids)
    cdef Py_ssize_t n = v.shape[0]
    cdef Py_ssize_t i
    with nogil:
        for i in range(1, n):
            if v[i] < v[i - 1]:
                break
        else:
            i = n
    if i >= n:
        return ids
    out = np.empty(n, dtype=np.uint64)
    scratch = np.empty(dggs_sort_scratch_size(n) + 1, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef uint64_t[::1] s = scratch
    with nogil:
        dggs_sorted(&v[0], n, &o[0], &s[0])
    return out


def compact(ids):
    """Fewest cells covering the same area as ``ids`` (valid, any order, any levels, duplicates allowed), sorted."""
    cdef const uint64_t[::1] v = _hier_ids(ids)
    cdef Py_ssize_t n = v.shape[0]
    out = np.empty(n, dtype=np.uint64)
    scratch = np.empty(dggs_sort_scratch_size(n) + 1, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef uint64_t[::1] s = scratch
    cdef int64_t top
    with nogil:
        top = dggs_compact(_hier_ptr(v), n, _hier_wptr(o), &s[0])
    return out[:top].copy()


def uncompact_prepare(ids, int level):
    """``(cells, total, bad)``: the sorted, non-overlapping cover of ``ids``, its size at ``level``, bad."""
    cdef const uint64_t[::1] v = _hier_ids(ids)
    cdef Py_ssize_t n = v.shape[0]
    cells = np.empty(n, dtype=np.uint64)
    scratch = np.empty(dggs_sort_scratch_size(n) + 1, dtype=np.uint64)
    cdef uint64_t[::1] c = cells
    cdef uint64_t[::1] s = scratch
    cdef int64_t m, total, bad
    with nogil:
        bad = dggs_uncompact_prepare(_hier_ptr(v), n, level, _hier_wptr(c), &s[0], &m, &total)
    if bad >= 0:
        return np.empty(0, dtype=np.uint64), 0, bad
    return cells[:m].copy(), total, bad


def uncompact(ids, int level):
    """``(out, bad)``: all descendants at ``level`` of the area ``ids`` cover, sorted and unique (no size limit)."""
    cells, total, bad = uncompact_prepare(ids, level)
    out = np.empty(total if bad < 0 else 0, dtype=np.uint64)
    if bad >= 0:
        return out, bad
    children(cells, level, out)
    return out, -1
