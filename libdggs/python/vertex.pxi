# vertex: corners of cells (libdggs/src/vertex.c), under the names of dggs.index._kernel.vertex, prefixed here
# ("vertex_") so that they do not clash with the other parts; the shim re-exports them.

cdef extern from "vertex.h" nogil:
    int DGGS_VERTEX_MAX_FAN
    int dggs_fan(uint64_t cell, int corner, uint64_t *fan, int *corners)
    int64_t dggs_disk_vertex_width(int64_t k, int level)
    int64_t dggs_disk_vertex_table_size(int64_t width)
    int64_t dggs_disk_vertex_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table,
                                 int64_t table_size)


#: vertex.h DGGS_VERTEX_MAX_FAN: most cells around one corner.
vertex_MAX_FAN = DGGS_VERTEX_MAX_FAN


def vertex_fans(const uint64_t[:] ids, const int64_t[:] corner, uint64_t[:, ::1] fan, int64_t[:, ::1] corners,
                int64_t[:] size):
    """The cells round corner ``corner[i]`` of valid ``ids[i]``, in walking order: ``fan[i, :size[i]]`` (the rest 0)
    and the corner's index in each ``corners[i, :size[i]]``. Returns the index of a walk that did not close, or -1."""
    cdef Py_ssize_t i, j, m = ids.shape[0]
    cdef int c[12]
    cdef int n
    if m and (fan.shape[1] < DGGS_VERTEX_MAX_FAN or corners.shape[1] < DGGS_VERTEX_MAX_FAN):
        raise ValueError("fan and corners need MAX_FAN columns")
    for i in range(m):
        n = dggs_fan(ids[i], <int>corner[i], &fan[i, 0], c)
        if n < 0:
            return i
        size[i] = n
        for j in range(DGGS_VERTEX_MAX_FAN):
            corners[i, j] = c[j] if j < n else 0
            if j >= n:
                fan[i, j] = 0
    return -1


def vertex_disk_width(int64_t k, int level):
    """Most cells within ``k`` corner-sharing steps of a cell at ``level`` (the edge disk of radius 6k, or the level)."""
    return dggs_disk_vertex_width(k, level)


def vertex_disk_row(uint64_t cell, int64_t k, int64_t width):
    """The cells within ``k`` corner-sharing steps of ``cell``, sorted (uint64 array); None if they outgrow ``width``.

    Raises RuntimeError if a walk round a corner does not close (a broken grid).
    """
    cdef int64_t tsize = dggs_disk_vertex_table_size(width), n
    row_arr = np.empty(max(width, 1), dtype=np.uint64)
    table_arr = np.zeros(tsize, dtype=np.uint64)
    cdef uint64_t[::1] row = row_arr
    cdef uint64_t[::1] table = table_arr
    with nogil:
        n = dggs_disk_vertex_row(cell, k, &row[0], width, &table[0], tsize)
    if n == -2:
        raise RuntimeError(f"a walk round a corner near cell {cell} did not close")
    return None if n < 0 else row_arr[:n].copy()
