# edges and dissolve: directed edges (libdggs/src/edges.c) and the outlines of cell sets (dissolve.c), under the
# names of dggs.index._kernel.edges, .ivea_edges and .dissolve, prefixed here ("edges_", "ivea_edges_",
# "dissolve_", "ivea_dissolve_") so that they do not clash with the other parts; the shims re-export them.

import numpy as np


cdef extern from "edges.h" nogil:
    uint64_t dggs_edge_of(uint64_t cell, int direction)
    void dggs_edges_split(uint64_t edge, uint64_t *origin, int *level, int *direction)
    uint64_t dggs_pair_edges(uint64_t a, uint64_t b)
    void dggs_edges_ends(uint64_t edge, uint64_t *origin, uint64_t *destination)
    uint64_t dggs_edges_reverse(uint64_t edge)
    uint64_t dggs_one_origin(uint64_t edge)
    uint64_t dggs_one_destination(uint64_t edge)
    void dggs_one_length(int proj, uint64_t edge, int64_t pieces, double *metres, double *rads)
    void dggs_edges_one_boundary(int proj, uint64_t edge, int64_t densify, double *out)

cdef extern from "dissolve.h" nogil:
    void dggs_drop_covered(const uint64_t *ids, int64_t n, uint8_t *keep)
    int64_t dggs_dissolve_descend(uint64_t cell, int level, uint64_t *out, int64_t cap)
    void dggs_outline_mask(uint64_t cell, const uint64_t *cells, int64_t n, uint8_t *mask)
    int64_t dggs_chain(const uint64_t *ecell, const int64_t *ecol, int64_t m, const uint64_t *cells, int64_t n,
                       uint8_t *visited, int64_t *order, int64_t *starts, int64_t *nstarts)
    int64_t dggs_ring_point_bound(const int64_t *steps, int64_t m)
    int dggs_ring_points(int proj, const uint64_t *cell, const int64_t *col, const int64_t *steps,
                         const int64_t *starts, int64_t nstarts, double *out, int64_t rows, uint8_t *corner,
                         int64_t *ends, double *ts, int64_t ts_len)

cdef extern from "dggs.h" nogil:
    int dggs_cells_to_multi_polygon(const uint64_t *cells, size_t n, int densify, int proj, double *lng_lat,
                                    int64_t points, int64_t *ring_sizes, int64_t rings, int64_t *polygon_rings,
                                    int64_t polygons, int64_t *num_points, int64_t *num_rings, int64_t *num_polygons)


# ---- edges (index/_kernel/edges.py; ivea_edges.py for the IVEA curves) ---------------------------------------

def edges_edge_of(uint64_t cell, int direction):
    """The edge id from ``cell`` across side ``direction``; 0 at level 28."""
    return dggs_edge_of(cell, direction)


def edges_split(uint64_t edge):
    """(origin, level of the origin, direction) of a valid edge id."""
    cdef uint64_t o
    cdef int level, d
    dggs_edges_split(edge, &o, &level, &d)
    return o, level, d


def edges_origin_edges(Py_ssize_t n, const uint64_t[:] ids, uint64_t[:, :] out):
    """``out[i, d]``: the edge from ``ids[i]`` across side d (0 at level 28)."""
    cdef Py_ssize_t i, m = ids.shape[0]
    if m and out.shape[1] < 3:
        raise ValueError("out needs 3 columns")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i, 0] = dggs_edge_of(ids[i], 0)  # dggs_origin_edges, column by column (any strides)
        out[i, 1] = dggs_edge_of(ids[i], 1)
        out[i, 2] = dggs_edge_of(ids[i], 2)


def edges_pair_edges(Py_ssize_t n, const uint64_t[:] a, const uint64_t[:] b, uint64_t[:] out):
    """``out[i]``: the edge from ``a[i]`` to its neighbour ``b[i]``; 0 if they are no neighbours or at level 28."""
    cdef Py_ssize_t i, m = a.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_pair_edges(a[i], b[i])


def edges_ends(Py_ssize_t n, const uint64_t[:] edges, uint64_t[:] origin, uint64_t[:] destination):
    """The origin and destination of each valid edge."""
    cdef Py_ssize_t i, m = edges.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        dggs_edges_ends(edges[i], &origin[i], &destination[i])


def edges_reverse(Py_ssize_t n, const uint64_t[:] edges, uint64_t[:] out):
    """``out[i]``: the edge back from the destination of ``edges[i]`` to its origin."""
    cdef Py_ssize_t i, m = edges.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_edges_reverse(edges[i])


def edges_one_origin(uint64_t edge):
    """The origin of one valid edge."""
    return dggs_one_origin(edge)


def edges_one_destination(uint64_t edge):
    """The destination of one valid edge."""
    return dggs_one_destination(edge)


def edges_one_ends(uint64_t edge):
    """(origin, destination) of one valid edge."""
    cdef uint64_t o, d
    dggs_edges_ends(edge, &o, &d)
    return o, d


def edges_one_reverse(uint64_t edge):
    """The edge back, of one valid edge."""
    return dggs_edges_reverse(edge)


cdef _edges_one_length(int proj, uint64_t edge, int64_t pieces):
    cdef double metres, rads
    dggs_one_length(proj, edge, pieces, &metres, &rads)
    return metres, rads


def edges_one_length(uint64_t edge, int64_t pieces):
    """Length of a valid edge's curve on WGS84 (m) and on the unit authalic sphere (rad): (metres, rads)."""
    return _edges_one_length(0, edge, pieces)


def ivea_edges_one_length(uint64_t edge, int64_t pieces):
    """:func:`edges_one_length` on the IVEA projection."""
    return _edges_one_length(1, edge, pieces)


cdef _edges_lengths(int proj, Py_ssize_t n, const uint64_t[:] edges, int64_t pieces, double[:] metres,
                    double[:] rads):
    cdef Py_ssize_t i, m = edges.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        dggs_one_length(proj, edges[i], pieces, &metres[i], &rads[i])


def edges_lengths(Py_ssize_t n, const uint64_t[:] edges, int64_t pieces, double[:] metres, double[:] rads):
    """``metres[i], rads[i]``: the length of edge ``i`` (:func:`edges_one_length`)."""
    _edges_lengths(0, n, edges, pieces, metres, rads)


def ivea_edges_lengths(Py_ssize_t n, const uint64_t[:] edges, int64_t pieces, double[:] metres, double[:] rads):
    """:func:`edges_lengths` on the IVEA projection."""
    _edges_lengths(1, n, edges, pieces, metres, rads)


cdef _edges_boundaries(int proj, Py_ssize_t n, const uint64_t[:] edges, int64_t densify, double[:, :, ::1] out):
    cdef Py_ssize_t i, m = edges.shape[0]
    if densify < 0:
        raise ValueError("densify must be >= 0")
    if m and (out.shape[0] < m or out.shape[1] < densify + 2 or out.shape[2] != 2 or out.strides[1] != 16):
        raise ValueError("out needs (len(edges), densify + 2, 2) rows of (lat, lng), each row contiguous")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        dggs_edges_one_boundary(proj, edges[i], densify, &out[i, 0, 0])


def edges_boundaries(Py_ssize_t n, const uint64_t[:] edges, int64_t densify, double[:, :, ::1] out):
    """``out[i]``: the (lat, lng) points of edge ``i`` from its first corner to its second, ``densify`` between."""
    _edges_boundaries(0, n, edges, densify, out)


def ivea_edges_boundaries(Py_ssize_t n, const uint64_t[:] edges, int64_t densify, double[:, :, ::1] out):
    """:func:`edges_boundaries` on the IVEA projection."""
    _edges_boundaries(1, n, edges, densify, out)


# ---- dissolve (index/_kernel/dissolve.py; ivea_edges.ring_points for IVEA) ------------------------------------

def dissolve_drop_covered(const uint64_t[::1] ids):
    """Mask of the sorted unique ``ids`` not inside an earlier id of the array (an ancestor's range)."""
    keep = np.zeros(ids.shape[0], dtype=np.bool_)
    cdef uint8_t[::1] k = keep.view(np.uint8)
    if ids.shape[0]:
        with nogil:
            dggs_drop_covered(&ids[0], ids.shape[0], &k[0])
    return keep


def dissolve_boundary_descendants(const uint64_t[:] ids, int level):
    """The descendants at ``level`` of each of ``ids`` (each coarser than ``level``) with an edge on its outline."""
    cdef Py_ssize_t i, m = ids.shape[0]
    cdef int64_t at = 0, c
    counts = np.empty(m, dtype=np.int64)
    cdef int64_t[::1] cn = counts
    with nogil:
        for i in range(m):
            cn[i] = dggs_dissolve_descend(ids[i], level, NULL, 0)
    if m and counts.min() < 0:
        raise ValueError(f"boundary descendants need a level finer than the cell's and at most 28, not {level}")
    out = np.empty(int(counts.sum()), dtype=np.uint64)
    cdef uint64_t[::1] o = out
    with nogil:
        for i in range(m):
            c = cn[i]
            if c:
                dggs_dissolve_descend(ids[i], level, &o[at], c)
            at += c
    return out


cdef inline void _dissolve_mask_row(uint64_t cell, const uint64_t *cells, Py_ssize_t nc, uint8_t[:, :] mk,
                                    Py_ssize_t i) noexcept nogil:
    cdef uint8_t b[3]
    dggs_outline_mask(cell, cells, nc, b)
    mk[i, 0] = b[0]
    mk[i, 1] = b[1]
    mk[i, 2] = b[2]


def dissolve_outline_mask(Py_ssize_t n, const uint64_t[:] fine, const uint64_t[::1] cells, mask):
    """``mask[i, col]``: whether the edge ``col`` of ``fine[i]`` is on the outline of ``cells``."""
    cdef uint8_t[:, :] mk = mask.view(np.uint8)
    cdef Py_ssize_t i, m = fine.shape[0], nc = cells.shape[0]
    cdef uint64_t dummy = 0
    cdef const uint64_t *pc = &cells[0] if nc else &dummy
    if m and mk.shape[1] < 3:
        raise ValueError("mask needs 3 columns")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        _dissolve_mask_row(fine[i], pc, nc, mk, i)


def dissolve_chain(const uint64_t[::1] ecell, const int64_t[::1] ecol, const uint64_t[::1] cells):
    """Chain the outline edges (sorted by cell, then column) into rings.

    Returns ``(order, starts, bad)``: the edges' indices ring after ring, the start of each ring in ``order``
    (one more entry: the end), and -1, or the index of an edge whose successor was not found (a broken grid).
    """
    cdef Py_ssize_t m = ecell.shape[0], nc = cells.shape[0]
    if ecol.shape[0] != m:
        raise ValueError("ecell and ecol differ in length")
    order = np.empty(m, dtype=np.int64)
    starts = np.empty(m + 1, dtype=np.int64)
    visited = np.empty(m, dtype=np.uint8)
    cdef int64_t[::1] o = order, s = starts
    cdef uint8_t[::1] v = visited
    cdef int64_t nstarts = 0, bad
    cdef uint64_t du = 0
    cdef int64_t di = 0
    cdef uint8_t db = 0
    with nogil:
        bad = dggs_chain(&ecell[0] if m else &du, &ecol[0] if m else &di, m, &cells[0] if nc else &du, nc,
                         &v[0] if m else &db, &o[0] if m else &di, &s[0], &nstarts)
    return order, starts[:nstarts], bad


def dissolve_ring_point_bound(const int64_t[::1] steps):
    """Rows :func:`dissolve_ring_points` may write for edges of ``steps`` segments each."""
    cdef int64_t d = 0
    return dggs_ring_point_bound(&steps[0] if steps.shape[0] else &d, steps.shape[0])


cdef _dissolve_ring_points(int proj, const uint64_t[::1] cell, const int64_t[::1] col, const int64_t[::1] steps,
                           const int64_t[::1] starts, double[:, ::1] out, corner, int64_t[::1] ends):
    cdef Py_ssize_t m = cell.shape[0], ns = starts.shape[0]
    if col.shape[0] != m or steps.shape[0] != m:
        raise ValueError("cell, col and steps differ in length")
    if ns < 1 or ends.shape[0] < ns - 1 or out.shape[1] != 2:
        raise ValueError("starts needs the rings' starts and the end; ends one entry per ring; out (rows, 2)")
    cdef uint8_t[::1] cr = corner.view(np.uint8)
    if cr.shape[0] < out.shape[0]:
        raise ValueError("corner needs a row per row of out")
    cdef Py_ssize_t r
    for r in range(ns):
        if starts[r] < 0 or starts[r] > m or (r and starts[r] < starts[r - 1]):
            raise ValueError("starts must increase within 0..len(cell)")
    cdef int64_t most = int(np.asarray(steps).max()) + 2 if m else 2
    ts = np.empty(most, dtype=np.float64)
    cdef double[::1] t = ts
    cdef uint64_t du = 0
    cdef int64_t di = 0
    cdef double dd = 0.0
    cdef uint8_t db = 0
    cdef int err
    with nogil:
        err = dggs_ring_points(proj, &cell[0] if m else &du, &col[0] if m else &di, &steps[0] if m else &di,
                               &starts[0], ns, &out[0, 0] if out.shape[0] else &dd, out.shape[0],
                               &cr[0] if cr.shape[0] else &db, &ends[0] if ends.shape[0] else &di, &t[0], most)
    if err:
        raise ValueError("out needs ring_point_bound(steps) rows (and steps >= 1)")


def dissolve_ring_points(const uint64_t[::1] cell, const int64_t[::1] col, const int64_t[::1] steps,
                         const int64_t[::1] starts, double[:, ::1] out, corner, int64_t[::1] ends):
    """Write the rings' (lat, lng) points into ``out``; ``ends[r]`` is one past ring ``r``'s last row.

    ``cell``, ``col`` and ``steps`` (segments per edge: densify + 1) are the edges in ring order, ring ``r``
    being ``starts[r]:starts[r + 1]``. ``corner[row]`` (bool) is set where the row is a corner of the outline (not
    a pole, a crossing or a densified point). ``out`` needs :func:`dissolve_ring_point_bound` rows.
    """
    _dissolve_ring_points(0, cell, col, steps, starts, out, corner, ends)


def ivea_dissolve_ring_points(const uint64_t[::1] cell, const int64_t[::1] col, const int64_t[::1] steps,
                              const int64_t[::1] starts, double[:, ::1] out, corner, int64_t[::1] ends):
    """:func:`dissolve_ring_points` on the IVEA projection."""
    _dissolve_ring_points(1, cell, col, steps, starts, out, corner, ends)


def dissolve_multi_polygon(const uint64_t[::1] ids, int densify, int proj):
    """The outline of ``ids`` as polygons (dggs_cells_to_multi_polygon): ``(lng_lat, ring_sizes, polygon_rings)``.

    ``lng_lat`` is (points, 2), the rings end to end (not closed); ``densify`` -1 for cell_to_polygon's default.
    Returns the core's error code instead when it fails.
    """
    cdef Py_ssize_t n = ids.shape[0]
    cdef uint64_t du = 0
    cdef int64_t np_ = 1024, nr = 16, npo = 16, gp = 0, gr = 0, gpo = 0
    cdef int err = 5
    cdef double[:, ::1] xy
    cdef int64_t[::1] rs, pr
    while err == 5:
        pts = np.empty((max(np_, 1), 2))
        rings = np.empty(max(nr, 1), dtype=np.int64)
        polys = np.empty(max(npo, 1), dtype=np.int64)
        xy, rs, pr = pts, rings, polys
        with nogil:
            err = dggs_cells_to_multi_polygon(&ids[0] if n else &du, n, densify, proj, &xy[0, 0], xy.shape[0],
                                              &rs[0], rs.shape[0], &pr[0], pr.shape[0], &gp, &gr, &gpo)
        np_, nr, npo = gp, gr, gpo
    if err:
        return err
    return pts[:gp], rings[:gr], polys[:gpo]
