# grid: the grid graph (libdggs/src/grid.c, grid_tables.c, strips.c, distance.c, paths.c), under the names of
# dggs.index._kernel.grid, .grid_tables, .strips, .distance and .paths.

from cython.parallel cimport threadid

import numpy as np


cdef extern from "grid.h" nogil:
    uint64_t dggs_neighbour(uint64_t cell, int level, int col)
    void dggs_neighbours(uint64_t cell, uint64_t *out)
    bint dggs_are_neighbours(uint64_t a, uint64_t b)
    int64_t dggs_next_ring(const uint64_t *cur, int64_t ncur, const uint64_t *prev, int64_t nprev, uint64_t *dest,
                           int64_t dest_len, uint64_t *cand)
    int64_t dggs_disk_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table,
                          int64_t table_size)
    int64_t dggs_disk_table_size(int64_t width)
    int64_t dggs_ring_row(uint64_t cell, int64_t k, uint64_t *out, int64_t out_width, uint64_t *work)
    int64_t dggs_ring_work_size(int64_t out_width)
    int64_t dggs_disk_of_width(uint64_t cell, int64_t k, int64_t max_cells)
    int64_t dggs_level_cells(int level)
    int64_t dggs_disk_width(int64_t k, int level)
    int64_t dggs_ring_width(int64_t k, int level)
    int64_t dggs_disk_size_count(uint64_t cell, int64_t k, int64_t cap, uint64_t *work, int64_t work_len)
    int64_t dggs_disk_sizes_work_size(int64_t r)

cdef extern from "grid_tables.h" nogil:
    int64_t dggs_ring_size_bound(int64_t k)
    int64_t dggs_disk_size_bound(int64_t k)
    int64_t dggs_chart_distance(uint64_t a, uint64_t b, int level)

cdef extern from "strips.h" nogil:
    int DGGS_MAX_STRIP
    int64_t dggs_strip_distance(uint64_t a, uint64_t b, int level)

cdef extern from "distance.h" nogil:
    int64_t DGGS_NEEDS_SEARCH
    int64_t DGGS_SEARCH_LIMIT
    int64_t DGGS_SEARCH_NO_ROOM
    int64_t dggs_distance(uint64_t a, uint64_t b, int64_t max_steps)
    int64_t dggs_search_work_size(int64_t max_steps)
    int64_t dggs_search(uint64_t a, uint64_t b, int64_t max_steps, uint64_t *work, int64_t work_len)

cdef extern from "paths.h" nogil:
    int DGGS_WALK_NEEDS_WORK
    int dggs_paths_walk(uint64_t a, uint64_t b, uint64_t *out, int64_t start, int64_t stop, uint64_t *work,
                        int64_t work_len)


#: strips.MAX_STRIP: most face edges a searched strip crosses.
MAX_STRIP = DGGS_MAX_STRIP
#: distance.NEEDS_SEARCH: what :func:`distance` returns for a pair only a search can settle.
NEEDS_SEARCH = DGGS_NEEDS_SEARCH
#: distance.SEARCH_LIMIT: most steps the fallback search takes.
SEARCH_LIMIT = DGGS_SEARCH_LIMIT


# ---- grid (index/_kernel/grid.py) ---------------------------------------------------------------------------

def _neighbour(uint64_t cell, int level, int col):
    """Column ``col`` of the cell's neighbours (corner ``col`` to ``col + 1``)."""
    return dggs_neighbour(cell, level, col)


def neighbours(const uint64_t[:] ids, uint64_t[:, ::1] out):
    """Edge neighbours of ids of any mix of levels (level 0 too): ``out`` (N, 3), column i = corner i to i + 1."""
    cdef Py_ssize_t i, m = ids.shape[0]
    if out.shape[1] < 3 and m:
        raise ValueError("out needs 3 columns")
    for i in prange(m, nogil=True, num_threads=_nthreads(m), schedule='static'):
        dggs_neighbours(ids[i], &out[i, 0])


def are_neighbours(const uint64_t[:] a, const uint64_t[:] b, out):
    """``out[i]`` (bool) = whether ``a[i]`` and ``b[i]`` share an edge (False for different levels, and a cell and itself)."""
    cdef uint8_t[:] o = out.view(np.uint8)
    cdef Py_ssize_t i, m = a.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(m), schedule='static'):
        o[i] = dggs_are_neighbours(a[i], b[i])


def next_ring(const uint64_t[::1] cur, const uint64_t[::1] prev, uint64_t[::1] dest, uint64_t[::1] cand):
    """Ring j + 1 from rings j and j - 1 (sorted) into ``dest``, sorted; its size, or -1 if ``dest`` is too short.

    ``cand`` needs room for ``3 * len(cur)`` ids.
    """
    if cand.shape[0] < 3 * cur.shape[0]:
        raise ValueError("cand needs room for 3 * len(cur) ids")
    cdef uint64_t dummy = 0
    cdef const uint64_t *pc = &cur[0] if cur.shape[0] else &dummy
    cdef const uint64_t *pp = &prev[0] if prev.shape[0] else &dummy
    cdef uint64_t *pd = &dest[0] if dest.shape[0] else &dummy
    cdef uint64_t *pk = &cand[0] if cand.shape[0] else &dummy
    return dggs_next_ring(pc, cur.shape[0], pp, prev.shape[0], pd, dest.shape[0], pk)


def disk(Py_ssize_t n, const uint64_t[:] ids, int64_t k, uint64_t[:, ::1] out, int64_t[:] counts):
    """Cells within ``k`` steps of each id (origin included): row i of ``out`` sorted, padded with 0; ``counts[i]`` its size.

    ``n`` is the amount of work (threads). Raises ValueError if a disk outgrows ``out``.
    """
    cdef Py_ssize_t i, j, m = ids.shape[0], width = out.shape[1]
    cdef int nt = _nthreads(n)
    cdef int64_t tsize = dggs_disk_table_size(width), c
    cdef uint64_t[:, ::1] tables = np.zeros((nt, tsize), dtype=np.uint64)
    cdef uint64_t dummy = 0
    if m == 0:
        return
    for i in prange(m, nogil=True, num_threads=nt, schedule='static'):
        c = dggs_disk_row(ids[i], k, &out[i, 0] if width else &dummy, width, &tables[threadid(), 0], tsize)
        for j in range(c if c > 0 else 0, width):
            out[i, j] = 0
        counts[i] = c
    if np.asarray(counts[:m]).min() < 0:
        raise ValueError("a disk outgrew disk_size_bound(k)")


def ring(Py_ssize_t n, const uint64_t[:] ids, int64_t k, uint64_t[:, ::1] out, int64_t[:] counts):
    """Cells exactly ``k`` steps from each id, as :func:`disk` (``out`` (N, >= ring_width)).

    Raises ValueError if a ring outgrows ``out``.
    """
    cdef Py_ssize_t i, j, m = ids.shape[0], width = out.shape[1]
    cdef int nt = _nthreads(n)
    cdef int64_t wsize = dggs_ring_work_size(width), c
    cdef uint64_t[:, ::1] work = np.empty((nt, wsize), dtype=np.uint64)
    cdef uint64_t dummy = 0
    if m == 0:
        return
    for i in prange(m, nogil=True, num_threads=nt, schedule='static'):
        c = dggs_ring_row(ids[i], k, &out[i, 0] if width else &dummy, width, &work[threadid(), 0])
        for j in range(c if c > 0 else 0, width):
            out[i, j] = 0
        counts[i] = c
    if np.asarray(counts[:m]).min() < 0:
        raise ValueError("a ring outgrew ring_size_bound(k)")


def level_cells(int level):
    """Cells at ``level``: 20 at level 0, ``120 * 3 ** (level - 1)`` after (docs/grid.md)."""
    return dggs_level_cells(level)


def disk_width(int64_t k, int level):
    """Most cells within ``k`` steps of a cell at ``level``: the planar bound, or the whole level."""
    return dggs_disk_width(k, level)


def ring_width(int64_t k, int level):
    """Most cells exactly ``k`` steps from a cell at ``level``."""
    return dggs_ring_width(k, level)


def disk_sizes(const uint64_t[:] ids, int64_t k, int64_t cap, int64_t[:] counts):
    """``counts[i]`` = the size of the disk of radius ``k`` around ``ids[i]``, without storing the disk.

    Stops at the first id whose disk passes ``cap`` cells and returns its index (its count is then the first
    ring total over ``cap``), else -1. The rings live in a buffer grown as the numba code grows its arrays.
    """
    cdef Py_ssize_t i
    cdef int64_t c, r = 1024
    cdef uint64_t[::1] work = np.empty(dggs_disk_sizes_work_size(r), dtype=np.uint64)
    for i in range(ids.shape[0]):
        while True:
            with nogil:
                c = dggs_disk_size_count(ids[i], k, cap, &work[0], work.shape[0])
            if c != -2:
                break
            r *= 2
            work = np.empty(dggs_disk_sizes_work_size(r), dtype=np.uint64)
        counts[i] = c
        if c > cap:
            return i
    return -1


def disk_of(int64_t cell, int64_t k, int64_t max_cells):
    """The disk of one id (int), sorted (the single-id entry); empty for a miss (no id, k over 64, or too wide)."""
    cdef int64_t width = dggs_disk_of_width(<uint64_t>cell, k, max_cells), c
    if width < 0:
        return np.empty(0, dtype=np.uint64)
    out = np.empty(width, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef int64_t tsize = dggs_disk_table_size(width)
    cdef uint64_t[::1] table = np.zeros(tsize, dtype=np.uint64)
    with nogil:
        c = dggs_disk_row(<uint64_t>cell, k, &o[0], width, &table[0], tsize)
    if c < 0:
        raise ValueError("a disk outgrew disk_size_bound(k)")
    return out[:c]


# ---- grid_tables (index/_kernel/grid_tables.py) -------------------------------------------------------------

def ring_size_bound(int64_t k):
    """Most cells exactly ``k`` steps from a cell, at any level: ``12 m + (0, 3, 5, 7, 9)[r]`` for ``k = 5 m + r``."""
    return dggs_ring_size_bound(k)


def disk_size_bound(int64_t k):
    """Most cells within ``k`` steps of a cell, at any level: 1, 4, 10, 16, 25, 37, 52, ..."""
    return dggs_disk_size_bound(k)


def chart_distance(uint64_t a, uint64_t b, int level):
    """Exact distance from the planar arrangement if ``a``'s chart proves it, else -1."""
    return dggs_chart_distance(a, b, level)


# ---- strips (index/_kernel/strips.py) -----------------------------------------------------------------------

def strip_distance(uint64_t a, uint64_t b, int level):
    """The fewest separating lines over the straight face strips from ``a`` to ``b`` (level >= 1), or -1 if none."""
    return dggs_strip_distance(a, b, level)


# ---- distance (index/_kernel/distance.py) -------------------------------------------------------------------

def distance(uint64_t a, uint64_t b, int64_t max_steps):
    """Edge steps between two valid cells of one level; -1 beyond ``max_steps``; NEEDS_SEARCH (-3) where only a search settles it."""
    return dggs_distance(a, b, max_steps)


cdef int64_t _grid_search(uint64_t a, uint64_t b, int64_t max_steps):
    """dggs_search in a work buffer of the documented bound, doubled while a ring outgrows it (as numba grows)."""
    cdef int64_t d, size = dggs_search_work_size(max_steps)
    cdef uint64_t[::1] work
    while True:
        work = np.empty(size, dtype=np.uint64)
        with nogil:
            d = dggs_search(a, b, max_steps, &work[0], size)
        if d != DGGS_SEARCH_NO_ROOM:
            return d
        size *= 2


def search(uint64_t a, uint64_t b, int64_t max_steps):
    """The distance by breadth-first search, or -1 beyond ``min(max_steps, SEARCH_LIMIT)`` steps."""
    return _grid_search(a, b, max_steps)


def distances(Py_ssize_t n, const uint64_t[:] a, const uint64_t[:] b, int64_t max_steps, int64_t[:] out):
    """``out[i] = distance(a[i], b[i], max_steps)``, pairs in parallel."""
    cdef Py_ssize_t i, m = a.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_distance(a[i], b[i], max_steps)


# ---- paths (index/_kernel/paths.py) -------------------------------------------------------------------------

def paths(Py_ssize_t n, const uint64_t[:] a, const uint64_t[:] b, const int64_t[:] offsets, uint64_t[::1] out,
          int64_t[:] status):
    """Path ``i`` (``grid_distance(a[i], b[i]) + 1`` cells) into ``out[offsets[i]:offsets[i + 1]]``.

    ``status[i]`` is 0, or -1 where the walk found no nearer neighbour (a wrong distance: never seen). Pairs
    that need the fallback search (none known) run again, one at a time, with its work buffer.
    """
    cdef Py_ssize_t i, m = a.shape[0]
    cdef int64_t size
    cdef uint64_t dummy = 0
    cdef uint64_t *po = &out[0] if out.shape[0] else &dummy
    cdef uint64_t[::1] work
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        status[i] = dggs_paths_walk(a[i], b[i], po, offsets[i], offsets[i + 1], NULL, 0)
    for i in range(m):
        if status[i] != DGGS_WALK_NEEDS_WORK:
            continue
        size = dggs_search_work_size(DGGS_SEARCH_LIMIT)
        while True:
            work = np.empty(size, dtype=np.uint64)
            status[i] = dggs_paths_walk(a[i], b[i], po, offsets[i], offsets[i + 1], &work[0], size)
            if status[i] != DGGS_WALK_NEEDS_WORK:
                break
            size *= 2
