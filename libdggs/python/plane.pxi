# plane: pixels of a raster cut by cells' rings in the raster's own plane (libdggs/src/pixels_plane.c), under the
# name dggs.index._kernel.pixels.plane_pieces (prefixed here "pixels_").

cdef extern from "dggs.h" nogil:
    ctypedef struct dggs_plane_pieces_out:
        int64_t *pixel
        uint64_t *cell
        double *area
        double *cu
        double *cv
        int64_t cap
        int64_t n
    int64_t dggs_plane_pieces_work_words(int64_t rows, int64_t cols)
    int dggs_plane_pieces(const double *x, const double *y, const int64_t *ring_start, const uint64_t *cells,
                          int64_t n_rings, int64_t rows, int64_t cols, const uint8_t *valid,
                          dggs_plane_pieces_out *out, void *work, int64_t work_words, int64_t *resume, int64_t *need)


def pixels_plane_pieces(x, y, ring_start, cells, valid):
    """Pixels of the grid ``valid`` (R, C) each ring meets: ``(pixel, cell, area, cu, cv)``, a ring's together.

    Ring ``k`` (its cell ``cells[k]``) is ``x``, ``y`` ``[ring_start[k]:ring_start[k + 1]]`` in pixel coordinates
    (x the column, y the row); areas in pixel units, ``cu``, ``cv`` each piece's centroid in its pixel's own
    coordinates (``dggs_plane_pieces``).
    """
    ok = np.ascontiguousarray(valid, dtype=np.bool_)
    xs = np.ascontiguousarray(x, dtype=np.float64)
    ys = np.ascontiguousarray(y, dtype=np.float64)
    st = np.ascontiguousarray(ring_start, dtype=np.int64)
    ids = np.ascontiguousarray(cells, dtype=np.uint64)
    if ok.ndim != 2 or xs.ndim != 1 or ys.shape != xs.shape or st.ndim != 1 or ids.ndim != 1:
        raise ValueError("valid must be (R, C), x and y alike and 1-d, ring_start and cells 1-d")
    if st.shape[0] != ids.shape[0] + 1 or st[0] < 0 or st[st.shape[0] - 1] > xs.shape[0]:
        raise ValueError("ring_start needs one more entry than cells, within x")
    cdef int64_t rows = ok.shape[0], cols = ok.shape[1], n_rings = ids.shape[0]
    work = np.empty(max(dggs_plane_pieces_work_words(rows, cols), 1), dtype=np.float64)
    cdef int64_t cap = max(64, 2 * rows * cols)
    arrays = [np.empty(cap, np.int64), np.empty(cap, np.uint64)] + [np.empty(cap, np.float64) for _ in range(3)]
    cdef const double[::1] mx = xs if xs.shape[0] else np.zeros(1), my = ys if ys.shape[0] else np.zeros(1)
    cdef const int64_t[::1] mst = st
    cdef const uint64_t[::1] mids = ids if n_rings else np.zeros(1, np.uint64)
    cdef const uint8_t[::1] mok = ok.reshape(-1).view(np.uint8)
    cdef double[::1] mw = work
    cdef int64_t[::1] mp
    cdef uint64_t[::1] mc
    cdef double[::1] ma, mu, mv
    cdef dggs_plane_pieces_out out
    cdef int64_t resume = 0, need = 0
    cdef int err
    cdef uint8_t db = 0
    out.n = 0
    while True:
        mp, mc, ma, mu, mv = arrays
        out.pixel, out.cell, out.area, out.cu, out.cv, out.cap = &mp[0], &mc[0], &ma[0], &mu[0], &mv[0], cap
        with nogil:
            err = dggs_plane_pieces(&mx[0], &my[0], &mst[0], &mids[0], n_rings, rows, cols,
                                    &mok[0] if mok.shape[0] else &db, &out, &mw[0], mw.shape[0], &resume, &need)
        if err != 5:  # DGGS_E_BUFFER: grow (doubling, or to what is needed) and go on from the ring it stopped at
            break
        cap = max(2 * cap, need)
        grown = [np.empty(cap, a.dtype) for a in arrays]
        for g, a in zip(grown, arrays):
            g[:out.n] = a[:out.n]
        arrays = grown
    if err:
        raise ValueError("plane_pieces needs rows, cols >= 1, ring_start increasing and finite points within 1e15")
    return tuple(a[:out.n] for a in arrays)
