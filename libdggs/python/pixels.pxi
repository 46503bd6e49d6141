# pixels: exact weights of raster pixels in cells (libdggs/src/pixels.c, clip.c), under the names of
# dggs.index._kernel.pixels and .clip, prefixed here ("pixels_", "clip_"); the shims re-export them.

import numpy as np


cdef extern from "dggs.h" nogil:
    ctypedef struct dggs_pieces:
        int64_t *pixel
        uint64_t *cell
        double *area
        int64_t cap
        int64_t n
    const double DGGS_FACE_AREA
    const double DGGS_PIXEL_MAX_RADIUS

cdef extern from "clip.h" nogil:
    double dggs_clip_area(const double *x, const double *y, int64_t n)
    int64_t dggs_clip(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by,
                      double cx, double cy, double *ox, double *oy, double *tx, double *ty, int64_t cap)

cdef extern from "dggs.h" nogil:
    int64_t dggs_latlng_pieces_work_words(int64_t rows, int64_t cols)
    int dggs_latlng_pieces(double west, double dlng, const double *lat_edges, int64_t rows, int64_t cols,
                           const uint8_t *valid, int level, double tol, dggs_pieces *out, void *work,
                           int64_t work_words, int64_t *resume, int64_t *need)

cdef extern from "pixels.h" nogil:
    int64_t dggs_pixels_region(int face, double ux, double uy, double uz)
    double dggs_chord_error(const double *lat, const double *lng)
    int64_t dggs_grid_pieces_work_words(int64_t npts, int64_t k, int target)
    int dggs_grid_pieces_arcs(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols,
                              const double *vlat, const double *vlng, int64_t vrows, int64_t vcols, int64_t k,
                              const uint8_t *valid, int64_t rows, int64_t cols, int target, bint arcs,
                              dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                              int64_t *need)
    int dggs_grid_pieces(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols, const double *vlat,
                         const double *vlng, int64_t vrows, int64_t vcols, int64_t k, const uint8_t *valid,
                         int64_t rows, int64_t cols, int target, dggs_pieces *out, double *coarse, void *work,
                         int64_t work_words, int64_t *resume, int64_t *need)

#: Planar area of a face triangle in the unit-sphere face frame (a twentieth of the sphere's 4 pi).
PIXELS_FACE_AREA = DGGS_FACE_AREA
#: The largest pixel grid_pieces takes: this angle (radians) from its corners.
PIXELS_MAX_RADIUS = DGGS_PIXEL_MAX_RADIUS


# ---- clip (index/_kernel/clip.py) ----------------------------------------------------------------------------

def clip_area(const double[:] x, const double[:] y, int64_t n):
    """Signed shoelace area of the first ``n`` vertices, about the first one (for precision at fine levels)."""
    if n > x.shape[0] or n > y.shape[0]:
        raise ValueError("n is past the vertices")
    if n < 3:
        return 0.0
    xc, yc = np.ascontiguousarray(x[:n]), np.ascontiguousarray(y[:n])
    cdef const double[::1] a = xc, b = yc
    return dggs_clip_area(&a[0], &b[0], n)


def clip_clip(const double[:] x, const double[:] y, int64_t n, double ax, double ay, double bx, double by, double cx,
              double cy, double[::1] ox, double[::1] oy, double[::1] tx, double[::1] ty):
    """Polygon (x, y)[:n] clipped by the triangle (a, b, c) (any orientation) into (tx, ty); the count.

    (``ox``, ``oy`` are scratch; numba's ``clip`` leaves its result in ``tx``, ``ty`` too.) Each of the four
    needs room for the clipped polygon at every stage (n + 3 vertices always suffice for a convex polygon).
    """
    if n > x.shape[0] or n > y.shape[0]:
        raise ValueError("n is past the vertices")
    cdef int64_t cap = min(ox.shape[0], oy.shape[0], tx.shape[0], ty.shape[0])
    xc, yc = np.ascontiguousarray(x[:n]), np.ascontiguousarray(y[:n])
    cdef const double[::1] a = xc, b = yc
    cdef double d = 0.0
    got = dggs_clip(&a[0] if n else &d, &b[0] if n else &d, n, ax, ay, bx, by, cx, cy, &ox[0] if cap else &d,
                    &oy[0] if cap else &d, &tx[0] if cap else &d, &ty[0] if cap else &d, cap)
    if got < 0:
        raise ValueError("the clipped polygon outgrew the scratch arrays")
    return got


# ---- pixels (index/_kernel/pixels.py) ------------------------------------------------------------------------

def pixels_region(int face, double ux, double uy, double uz):
    """``3 face + sector``: the sector (0..2) as Snyder's face_forward picks it."""
    return dggs_pixels_region(face, ux, uy, uz)


def pixels_chord_errors(lat, lng):
    """Per pixel, the fraction of its area its edges' chords leave out (one point an edge).

    ``lat``, ``lng`` (N, 16): a pixel's points round it, four an edge (its first corner, then at a quarter, half
    and three quarters). NaN where no half-edge is smooth.
    """
    la = np.ascontiguousarray(lat, dtype=np.float64)
    lo = np.ascontiguousarray(lng, dtype=np.float64)
    if la.ndim != 2 or la.shape[1] != 16 or lo.shape[0] != la.shape[0] or lo.shape[1] != 16:
        raise ValueError("lat and lng need 16 points per pixel")
    cdef const double[:, ::1] a = la, b = lo
    cdef Py_ssize_t i, m = la.shape[0]
    out = np.zeros(m)
    cdef double[::1] o = out
    for i in prange(m, nogil=True, num_threads=_nthreads(16 * m), schedule='static'):
        o[i] = dggs_chord_error(&a[i, 0], &b[i, 0])
    return out


def pixels_grid_pieces(hlat, hlng, vlat, vlng, int64_t k, valid, int target, bint arcs=False):
    """Cells at level ``target`` met by each pixel of a grid, and the planar area they share.

    The pixels' edges, densified with ``k`` points each: ``hlat``, ``hlng`` (R + 1, C k + 1) along the R + 1 grid
    lines of constant row, ``vlat``, ``vlng`` (R k + 1, C + 1) along the C + 1 of constant column (degrees, WGS84;
    each corner in both). Pixel (r, c) is number ``r C + c``; pixels where ``valid`` (R, C) is False are left out.
    Returns ``(pixel, cell, area, coarse)``, each pixel's pieces together in pixel order, areas in the unit-sphere
    face plane (:data:`PIXELS_FACE_AREA` a face); ``coarse`` (R C) is, for an even ``k``, the planar area of each
    pixel drawn through every other of its points, NaN for pixels across a kink of the plane (and for all with an
    odd ``k``). A pixel must lie within :data:`PIXELS_MAX_RADIUS` of its corners. With ``arcs`` (an even ``k``),
    each piece also gets the area between its pixel's curved edges and their chords where it lies: each pair of
    chords' parabolic segment, in the cell of the pair's middle point (``dggs_raster_pieces_arcs``).
    """
    h1 = np.ascontiguousarray(hlat, dtype=np.float64)
    h2 = np.ascontiguousarray(hlng, dtype=np.float64)
    v1 = np.ascontiguousarray(vlat, dtype=np.float64)
    v2 = np.ascontiguousarray(vlng, dtype=np.float64)
    ok = np.ascontiguousarray(valid, dtype=np.bool_)
    if ok.ndim != 2 or h1.ndim != 2 or v1.ndim != 2 or h2.shape != h1.shape or v2.shape != v1.shape:
        raise ValueError("hlat, hlng, vlat, vlng and valid must be 2-d, hlat and hlng alike, vlat and vlng alike")
    if target < 0 or target > 28:
        raise ValueError(f"level {target} is outside 0..28")
    cdef int64_t rows = ok.shape[0], cols = ok.shape[1]
    cdef int64_t hr = h1.shape[0], hc = h1.shape[1], vr = v1.shape[0], vc = v1.shape[1]
    cdef int64_t npts = h1.size + (v1.size if k > 1 else 0)
    work = np.empty(max(dggs_grid_pieces_work_words(npts, k, target), 1), dtype=np.float64)
    coarse = np.empty(rows * cols, dtype=np.float64)
    cdef int64_t cap = max(16, 2 * rows * cols)
    p = np.empty(cap, np.int64)
    c = np.empty(cap, np.uint64)
    a = np.empty(cap, np.float64)
    cdef const double[::1] mh1 = h1.reshape(-1), mh2 = h2.reshape(-1), mv1 = v1.reshape(-1), mv2 = v2.reshape(-1)
    cdef const uint8_t[::1] mok = ok.reshape(-1).view(np.uint8)
    cdef double[::1] mw = work, mc = coarse
    cdef int64_t[::1] mp
    cdef uint64_t[::1] mcell
    cdef double[::1] ma
    cdef dggs_pieces out
    cdef int64_t resume = 0, need = 0
    cdef int err
    cdef double dd = 0.0
    cdef uint8_t db = 0
    out.n = 0
    while True:
        mp, mcell, ma = p, c, a
        out.pixel, out.cell, out.area, out.cap = &mp[0], &mcell[0], &ma[0], cap
        with nogil:
            err = dggs_grid_pieces_arcs(&mh1[0] if mh1.shape[0] else &dd, &mh2[0] if mh2.shape[0] else &dd,
                                        hr, hc, &mv1[0] if mv1.shape[0] else &dd,
                                        &mv2[0] if mv2.shape[0] else &dd, vr, vc, k,
                                        &mok[0] if mok.shape[0] else &db, rows, cols, target, arcs, &out,
                                   &mc[0] if mc.shape[0] else &dd, &mw[0], mw.shape[0], &resume, &need)
        if err != 5:  # DGGS_E_BUFFER: grow as numba's clip.grow does (doubling, or to what is needed) and go on
            break
        cap = max(2 * cap, need)
        p2, c2, a2 = np.empty(cap, np.int64), np.empty(cap, np.uint64), np.empty(cap, np.float64)
        p2[:out.n], c2[:out.n], a2[:out.n] = p[:out.n], c[:out.n], a[:out.n]
        p, c, a = p2, c2, a2
    if err == 6:
        raise ValueError("grid_pieces needs hlat, hlng (R + 1, C k + 1), vlat, vlng (R k + 1, C + 1), k >= 1")
    if err:
        raise RuntimeError("grid_pieces: a pixel's clipped polygon outgrew its scratch (a pixel too ragged)")
    return p[:out.n], c[:out.n], a[:out.n], coarse



def pixels_latlng_pieces(double west, double dlng, lat_edges, valid, int level, double tol):
    """Cells at ``level`` met by each valid pixel of a lat/lng grid, and the area they share (unit sphere).

    ``valid`` (R, C): the pixels; columns ``dlng`` degrees wide from ``west``; ``lat_edges`` (R + 1,) the rows'
    latitudes, strictly monotonic. Each cell is cut against the grid's rows and columns in the cylindrical
    equal-area map (``dggs_latlng_pieces``), its edges' chords within ``tol`` of any pixel's area. Returns
    ``(pixel, cell, area)``, a cell's pieces together; areas on the unit sphere (4 pi in all).
    """
    ok = np.ascontiguousarray(valid, dtype=np.bool_)
    edges = np.ascontiguousarray(lat_edges, dtype=np.float64)
    if ok.ndim != 2 or edges.ndim != 1 or edges.shape[0] != ok.shape[0] + 1:
        raise ValueError("valid must be (R, C) and lat_edges (R + 1,)")
    cdef int64_t rows = ok.shape[0], cols = ok.shape[1]
    work = np.empty(max(dggs_latlng_pieces_work_words(rows, cols), 1), dtype=np.float64)
    # cells the pixels' size: about 5.2 pieces a pixel (finer cells more: grown below); pages never written are
    # never resident, so room to spare costs no memory
    cdef int64_t cap = max(64, 6 * rows * cols)
    p = np.empty(cap, np.int64)
    c = np.empty(cap, np.uint64)
    a = np.empty(cap, np.float64)
    cdef const double[::1] me = edges
    cdef const uint8_t[::1] mok = ok.reshape(-1).view(np.uint8)
    cdef double[::1] mw = work
    cdef int64_t[::1] mp
    cdef uint64_t[::1] mcell
    cdef double[::1] ma
    cdef dggs_pieces out
    cdef int64_t resume = 0, need = 0
    cdef int err
    cdef double dd = 0.0
    cdef uint8_t db = 0
    out.n = 0
    while True:
        mp, mcell, ma = p, c, a
        out.pixel, out.cell, out.area, out.cap = &mp[0], &mcell[0], &ma[0], cap
        with nogil:
            err = dggs_latlng_pieces(west, dlng, &me[0], rows, cols, &mok[0] if mok.shape[0] else &db, level, tol,
                                     &out, &mw[0], mw.shape[0], &resume, &need)
        if err != 5:  # DGGS_E_BUFFER: grow (doubling, or to what is needed) and go on from the cell it stopped at
            break
        cap = max(2 * cap, need)
        p2, c2, a2 = np.empty(cap, np.int64), np.empty(cap, np.uint64), np.empty(cap, np.float64)
        p2[:out.n], c2[:out.n], a2[:out.n] = p[:out.n], c[:out.n], a[:out.n]
        p, c, a = p2, c2, a2
    if err == 2:
        raise ValueError(f"level {level} is outside 0..28")
    if err == 1 or err == 6:
        raise ValueError("latlng_pieces needs rows, cols >= 1, dlng > 0 (360 degrees at most in all), tol > 0 and "
                         "latitudes strictly monotonic within -90..90")
    if err:
        raise RuntimeError("latlng_pieces: a cell edge needs more than 4096 chords (cells far coarser than pixels) or "
                           "passes through a pole")
    return p[:out.n], c[:out.n], a[:out.n]
