# Child positions and local (i, j) coordinates (libdggs/src/local.c): the kernels of index/_kernel/local.py under
# their names. The batch loops are called as the numba Loops were, ``name(n, *args)`` with n the amount of work.

import numpy as np

cdef extern from "local.h" nogil:
    int64_t dggs_child_count(int parent_level, int level)
    int64_t dggs_child_pos(uint64_t cell, int parent_level)
    int64_t dggs_one_child_pos(int64_t cell, int parent_level)
    uint64_t dggs_child_pos_cell(int64_t pos, uint64_t parent, int level)
    uint64_t dggs_one_child_cell(int64_t parent, int64_t pos, int level)
    bint dggs_one_ij(uint64_t anchor, uint64_t cell, int64_t *i, int64_t *j)
    bint dggs_one_local_ij(int64_t anchor, int64_t cell, int64_t *i, int64_t *j)
    uint64_t dggs_one_cell(uint64_t anchor, int64_t i, int64_t j)
    uint64_t dggs_one_local_cell(int64_t anchor, int64_t i, int64_t j)
    const signed char *dggs_unfold_face_table()


def child_count(int parent_level, int level):
    """Descendants at ``level`` of one cell at ``parent_level`` (<= level)."""
    return dggs_child_count(parent_level, level)


def child_pos(Py_ssize_t n, const uint64_t[:] ids, int parent_level, int64_t[:] out):
    """``out[i]``: the position of ``ids[i]`` below its ancestor at ``parent_level``; -1 if that is finer."""
    cdef Py_ssize_t i
    for i in prange(ids.shape[0], nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_child_pos(ids[i], parent_level)


def one_child_pos(int64_t cell, int parent_level):
    """The single-id entry of :func:`child_pos`: -1 for an invalid id or a cell coarser than ``parent_level``."""
    return dggs_one_child_pos(cell, parent_level)


def child_pos_cells(Py_ssize_t n, const int64_t[:] pos, const uint64_t[:] parents, int level, uint64_t[:] out):
    """``out[i]``: the descendant of ``parents[i]`` at ``level`` at position ``pos[i]``; 0 if out of range."""
    cdef Py_ssize_t i
    for i in prange(parents.shape[0], nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_child_pos_cell(pos[i], parents[i], level)


def one_child_cell(int64_t parent, int64_t pos, int level):
    """The single-id entry of :func:`child_pos_cells`: the null id for an invalid parent or position."""
    return dggs_one_child_cell(parent, pos, level)


def local_ij(Py_ssize_t n, const uint64_t[:] anchors, const uint64_t[:] ids, int64_t[:] i_out, int64_t[:] j_out):
    """``(i_out[k], j_out[k])``: the (i, j) of ``ids[k]`` around ``anchors[k]`` (same level); OUT_OF_RANGE in i."""
    cdef Py_ssize_t k
    cdef int64_t i, j
    for k in prange(ids.shape[0], nogil=True, num_threads=_nthreads(n), schedule='static'):
        i = 0  # assigned in the loop: private to each thread
        j = 0
        dggs_one_ij(anchors[k], ids[k], &i, &j)
        i_out[k] = i
        j_out[k] = j


def one_local_ij(int64_t anchor, int64_t cell):
    """The single-pair entry of :func:`local_ij`: ``(i, j, ok)``, not ok for invalid ids, two levels or no pair."""
    cdef int64_t i, j
    cdef bint ok = dggs_one_local_ij(anchor, cell, &i, &j)
    return i, j, ok


def local_cells(Py_ssize_t n, const uint64_t[:] anchors, const int64_t[:] i_in, const int64_t[:] j_in,
                uint64_t[:] out):
    """``out[k]``: the cell at ``(i_in[k], j_in[k])`` around ``anchors[k]``, or the null id."""
    cdef Py_ssize_t k
    for k in prange(anchors.shape[0], nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[k] = dggs_one_cell(anchors[k], i_in[k], j_in[k])


def one_local_cell(int64_t anchor, int64_t i, int64_t j):
    """The single-id entry of :func:`local_cells`: the null id for an invalid anchor or a pair naming no cell."""
    return dggs_one_local_cell(anchor, i, j)


def local_unfold_face():
    """local.py ``UNFOLD_FACE``: the face across edge k (corner k to k + 1) of face f, a new (20, 3) int64 array."""
    cdef const signed char *t = dggs_unfold_face_table()
    return np.array([[t[3 * f + k] for k in range(3)] for f in range(20)], dtype=np.int64)
