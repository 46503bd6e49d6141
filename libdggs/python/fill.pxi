# fill: polygon fill's edge bucket grid (libdggs/src/polygon.c) and its descent through the levels (fill.c), the
# entries of dggs.index._kernel.polygon, .fill and .ivea_fill under the names those numba modules had.

import numpy as np

cdef extern from "<stdbool.h>" nogil:
    ctypedef bint fill_cbool "bool"

cdef extern from "polygon.h" nogil:
    ctypedef struct dggs_edge_grid:
        const double *x0
        const double *y0
        const double *x1
        const double *y1
        const double *frame
        const int64_t *start
        const int64_t *items
        const int64_t *empty
    void dggs_ring_edges(const double *xy, int64_t n, double *x0, double *y0, double *x1, double *y1, int64_t *m,
                         fill_cbool *closed)
    int dggs_polygon_build_count(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                                 int64_t side, double *frame, int64_t *start)
    void dggs_polygon_build_fill(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                                 const double *frame, const int64_t *start, int64_t *items, int64_t *empty,
                                 double *scratch)
    fill_cbool dggs_near(double px, double py, double r, double sx, const dggs_edge_grid *g)
    int dggs_parity(double px, double py, const dggs_edge_grid *g)
    void dggs_polygon_classify(double px, double py, double r, const dggs_edge_grid *g, fill_cbool *hit,
                               fill_cbool *inside)

cdef extern from "fill.h" nogil:
    int DGGS_FILL_OK, DGGS_FILL_TOO_MANY, DGGS_FILL_FULL, DGGS_FILL_FAILED
    int DGGS_FILL_SURE, DGGS_FILL_CENTRE, DGGS_FILL_EDGE, DGGS_FILL_LEVELS, DGGS_FILL_FIRST_ROOM
    const double dggs_fill_rho[29]
    ctypedef struct dggs_fill_state:
        int64_t cand[30]
        int64_t insides[30]
        int64_t n, whole, tested, classified
    void dggs_fill_centre(int proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                          double cy, double *lat, double *lng, double *u)
    void dggs_footprint(int proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                        double cy, double *lat, double *lng, double *u)
    void dggs_ellipse(int lv, double ux, double uy, double uz, double *a, double *lam)
    void dggs_fill_start(dggs_fill_state *s, int level, fill_cbool center, int direct, double miny, double maxy,
                         int64_t limit)
    int dggs_fill_walk(int proj, dggs_fill_state *s, const dggs_edge_grid *g, uint64_t *ids, uint8_t *flags,
                       int64_t room)
    int64_t dggs_first_over(const int64_t *cand, const int64_t *insides, int64_t tested, int last, fill_cbool center,
                            int64_t limit)

cdef extern from "tables.h" nogil:
    const double dggs_face_corners_ccw[3][2]
    const double dggs_level1_corners[6][3][2]


cdef dggs_edge_grid _fill_grid(const double[::1] x0, const double[::1] y0, const double[::1] x1,
                               const double[::1] y1, const double[::1] frame, const int64_t[::1] start,
                               const int64_t[::1] items, const int64_t[::1] empty, bint with_empty) except *:
    """The C view of a grid (polygon.build's arrays), after checking that its arrays are as long as it says."""
    cdef dggs_edge_grid g
    cdef Py_ssize_t m = x0.shape[0]
    cdef int64_t side
    if y0.shape[0] != m or x1.shape[0] != m or y1.shape[0] != m:
        raise ValueError("the edge arrays x0, y0, x1, y1 must have one length")
    if frame.shape[0] < 7:
        raise ValueError("frame must have 7 entries")
    side = <int64_t>frame[4]
    if side < 1 or side > 65536 or start.shape[0] < side * side + 1 or (with_empty and empty.shape[0] < side * side):
        raise ValueError("start and empty must have side * side + 1 and side * side entries")
    if start[side * side] > items.shape[0]:
        raise ValueError("items is shorter than start says")
    g.x0 = &x0[0] if m else NULL
    g.y0 = &y0[0] if m else NULL
    g.x1 = &x1[0] if m else NULL
    g.y1 = &y1[0] if m else NULL
    g.frame = &frame[0]
    g.start = &start[0]
    g.items = &items[0] if items.shape[0] else NULL
    g.empty = &empty[0] if with_empty else NULL
    return g


def polygon_ring_edges(xy):
    """The edges (x0, y0, x1, y1) of closed rings laid end to end in ``xy`` (n, 2), and whether every ring closed.

    A ring ends at the next repeat of its first point (polygon.py ``ring_edges``).
    """
    cdef const double[:, ::1] p = np.ascontiguousarray(np.asarray(xy)[:, :2], dtype=np.float64)
    cdef Py_ssize_t n = p.shape[0]
    x0, y0, x1, y1 = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    cdef double[::1] a = x0, b = y0, c = x1, d = y1
    cdef int64_t m = 0
    cdef fill_cbool closed = True
    if n:
        dggs_ring_edges(&p[0, 0], n, &a[0], &b[0], &c[0], &d[0], &m, &closed)
    return x0[:m], y0[:m], x1[:m], y1[:m], bool(closed)


def polygon_build(x0, y0, x1, y1, int64_t side):
    """``(frame, start, items, empty)``: the segments bucketed on a ``side`` x ``side`` grid (polygon.py ``build``)."""
    cdef const double[::1] a = np.ascontiguousarray(x0, dtype=np.float64)
    cdef const double[::1] b = np.ascontiguousarray(y0, dtype=np.float64)
    cdef const double[::1] c = np.ascontiguousarray(x1, dtype=np.float64)
    cdef const double[::1] d = np.ascontiguousarray(y1, dtype=np.float64)
    cdef Py_ssize_t n = a.shape[0]
    if b.shape[0] != n or c.shape[0] != n or d.shape[0] != n:
        raise ValueError("the edge arrays x0, y0, x1, y1 must have one length")
    if n == 0:
        raise ValueError("zero-size array to reduction operation minimum which has no identity")
    if side < 1 or side > 65536:
        raise ValueError(f"side {side} must be 1..65536")
    frame = np.empty(7)
    start = np.empty(side * side + 1, dtype=np.int64)
    cdef double[::1] f = frame
    cdef int64_t[::1] s = start
    cdef int err
    with nogil:
        err = dggs_polygon_build_count(&a[0], &b[0], &c[0], &d[0], n, side, &f[0], &s[0])
    if err:
        raise ValueError(error_string(err))
    items = np.empty(start[side * side], dtype=np.int64)
    empty = np.empty(side * side, dtype=np.int64)
    scratch = np.empty(start[side * side])
    cdef int64_t[::1] it = items, em = empty
    cdef double[::1] sc = scratch
    with nogil:
        dggs_polygon_build_fill(&a[0], &b[0], &c[0], &d[0], n, &f[0], &s[0], &it[0] if it.shape[0] else NULL,
                                &em[0], &sc[0] if sc.shape[0] else NULL)
    return frame, start, items, empty


def polygon_near(double px, double py, double r, double sx, const double[::1] x0, const double[::1] y0,
                 const double[::1] x1, const double[::1] y1, const double[::1] frame, const int64_t[::1] start,
                 const int64_t[::1] items):
    """Whether some segment lies within ``r`` of (px, py) once x is multiplied by ``sx`` > 0 (polygon.py ``near``)."""
    cdef dggs_edge_grid g = _fill_grid(x0, y0, x1, y1, frame, start, items, start, False)
    return bool(dggs_near(px, py, r, sx, &g))


def polygon_parity(double px, double py, const double[::1] x0, const double[::1] y0, const double[::1] x1,
                   const double[::1] y1, const double[::1] frame, const int64_t[::1] start, const int64_t[::1] items,
                   const int64_t[::1] empty):
    """1 if (px, py) is inside the polygon, 0 if outside, -1 on or within rounding of an edge (polygon.py ``parity``)."""
    cdef dggs_edge_grid g = _fill_grid(x0, y0, x1, y1, frame, start, items, empty, True)
    return dggs_parity(px, py, &g)


def polygon_classify(Py_ssize_t work, const double[::1] px, const double[::1] py, const double[::1] r,
                     const double[::1] x0, const double[::1] y0, const double[::1] x1, const double[::1] y1,
                     const double[::1] frame, const int64_t[::1] start, const int64_t[::1] items,
                     const int64_t[::1] empty, hit, inside):
    """``hit[i]``: the circle of radius ``r[i]`` round point i meets the polygon; ``inside[i]``: lies wholly in it."""
    cdef dggs_edge_grid g = _fill_grid(x0, y0, x1, y1, frame, start, items, empty, True)
    cdef uint8_t[:] h = np.asarray(hit).view(np.uint8)
    cdef uint8_t[:] ins = np.asarray(inside).view(np.uint8)
    cdef Py_ssize_t m = px.shape[0], i
    if py.shape[0] < m or r.shape[0] < m or h.shape[0] < m or ins.shape[0] < m:
        raise ValueError("py, r, hit and inside must be as long as px")
    cdef fill_cbool a, b
    for i in prange(m, nogil=True, num_threads=_nthreads(work), schedule='static'):
        dggs_polygon_classify(px[i], py[i], r[i], &g, &a, &b)
        h[i] = a
        ins[i] = b


cdef int _fill_check_face_level(int face, int lv) except -1:
    if not 0 <= face < 20:
        raise ValueError(f"face {face} is not 0..19")
    if not 0 <= lv <= 28:
        raise ValueError(f"level {lv} is not 0..28")
    return 0


def _fill_point(int proj, int what, int face, int lv, double ax, double ay, double bx, double by, double cx,
                double cy):
    _fill_check_face_level(face, lv)
    cdef double lat, lng
    cdef double u[3]
    if what == 0:
        dggs_fill_centre(proj, face, lv, ax, ay, bx, by, cx, cy, &lat, &lng, u)
    else:
        dggs_footprint(proj, face, lv, ax, ay, bx, by, cx, cy, &lat, &lng, u)
    return lat, lng, u[0], u[1], u[2]


def fill_centre(int face, int lv, double ax, double ay, double bx, double by, double cx, double cy):
    """(lat, lng, ux, uy, uz) of the cell with these planar corners, exactly as its centre (fill.py ``centre``)."""
    return _fill_point(0, 0, face, lv, ax, ay, bx, by, cx, cy)


def ivea_fill_centre(int face, int lv, double ax, double ay, double bx, double by, double cx, double cy):
    """:func:`fill_centre` on IVEA."""
    return _fill_point(1, 0, face, lv, ax, ay, bx, by, cx, cy)


def fill_footprint(int face, int lv, double ax, double ay, double bx, double by, double cx, double cy):
    """(lat, lng, ux, uy, uz) of the centre of a cell's footprint (fill.py ``footprint``)."""
    return _fill_point(0, 1, face, lv, ax, ay, bx, by, cx, cy)


def ivea_fill_footprint(int face, int lv, double ax, double ay, double bx, double by, double cx, double cy):
    """:func:`fill_footprint` on IVEA."""
    return _fill_point(1, 1, face, lv, ax, ay, bx, by, cx, cy)


def fill_ellipse(int lv, double ux, double uy, double uz):
    """Semi-axes (latitude, longitude; degrees) of a level-``lv`` footprint ellipse centred on u (fill.py ``ellipse``)."""
    _fill_check_face_level(0, lv)
    cdef double a, lam
    dggs_ellipse(lv, ux, uy, uz, &a, &lam)
    return a, lam


def _fill_descend(int proj, int level, bint center, int direct, const double[::1] x0, const double[::1] y0,
                  const double[::1] x1, const double[::1] y1, const double[::1] frame, const int64_t[::1] start,
                  const int64_t[::1] items, const int64_t[::1] empty, double miny, double maxy, int64_t limit):
    if not 0 <= level <= 28:
        raise ValueError(f"level {level} is not 0..28")
    cdef dggs_edge_grid g = _fill_grid(x0, y0, x1, y1, frame, start, items, empty, True)
    cdef dggs_fill_state st
    cdef int status
    cdef uint64_t[::1] iv
    cdef uint8_t[::1] fv
    dggs_fill_start(&st, level, center, direct, miny, maxy, limit)
    ids = np.empty(DGGS_FILL_FIRST_ROOM, dtype=np.uint64)
    flags = np.empty(DGGS_FILL_FIRST_ROOM, dtype=np.uint8)
    while True:
        iv, fv = ids, flags
        with nogil:
            status = dggs_fill_walk(proj, &st, &g, &iv[0], &fv[0], iv.shape[0])
        if status != DGGS_FILL_FULL:
            break
        more_ids = np.empty(2 * ids.shape[0], dtype=np.uint64)  # the output is full: twice the room, and on
        more_flags = np.empty(2 * ids.shape[0], dtype=np.uint8)
        more_ids[: ids.shape[0]] = ids
        more_flags[: ids.shape[0]] = flags
        ids, flags = more_ids, more_flags
    if status == DGGS_FILL_FAILED:
        raise RuntimeError("polygon fill's stack overflowed")
    cand = np.array(<int64_t[:DGGS_FILL_LEVELS]> &st.cand[0], dtype=np.int64)
    insides = np.array(<int64_t[:DGGS_FILL_LEVELS]> &st.insides[0], dtype=np.int64)
    return ids, flags, st.n, status, cand, insides, st.tested, st.classified


def fill_descend(level, center, direct, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit):
    """The cells of one polygon at ``level``: (ids, flags, n, status, cand, insides, tested, classified) (fill.py ``descend``)."""
    return _fill_descend(0, level, center, direct, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit)


def ivea_fill_descend(level, center, direct, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit):
    """:func:`fill_descend` on IVEA (ivea_fill.py ``descend``)."""
    return _fill_descend(1, level, center, direct, x0, y0, x1, y1, frame, start, items, empty, miny, maxy, limit)


def fill_first_over(const int64_t[::1] cand, const int64_t[::1] insides, int64_t tested, int last, bint center,
                    int64_t limit):
    """The first count a level-by-level search would have found over ``limit``, or -1 (fill.py ``first_over``)."""
    if last > 0 and (last >= cand.shape[0] or last > insides.shape[0]):
        raise ValueError(f"last {last} is out of the counts' range")
    return dggs_first_over(&cand[0] if cand.shape[0] else NULL, &insides[0] if insides.shape[0] else NULL, tested,
                           last, center, limit)


def fill_tables():
    """fill.py's tables from the C core: ``{"rho": RHO (29,), "face": _FACE (3, 2), "l1": _L1 (6, 3, 2)}``."""
    rho = np.array(<double[:29]> <double *> &dggs_fill_rho[0])
    face = np.array(<double[:6]> <double *> &dggs_face_corners_ccw[0][0]).reshape(3, 2)
    l1 = np.array(<double[:36]> <double *> &dggs_level1_corners[0][0][0]).reshape(6, 3, 2)
    return {"rho": rho, "face": face, "l1": l1}
