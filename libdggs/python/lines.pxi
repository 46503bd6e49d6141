# The line tracer (libdggs/src/line_trace.c, chord.c, line_layout.c): the numba functions of
# dggs.index._kernel.line_trace, chord and line_layout under their own names, and the IVEA tracer of
# ivea_lines as ivea_trace / ivea_cells_at (one C function each, the projection its first argument). The shims
# index/_kernel/line_trace.py, chord.py, line_layout.py and ivea_lines.py re-export them under the old names.

import numpy as np

# dggs_projection's values (dggs.h), passed as int (the C prototypes take the enum; the other parts declare it)
cdef enum:
    _LINES_ISEA = 0
    _LINES_IVEA = 1

cdef extern from "chord.h" nogil:
    double dggs_dist_to_segment(double px, double py, double x0, double y0, double x1, double y1)
    void dggs_corners6(uint64_t cell, double t[6])
    bint dggs_crosses(const double ta[6], const double tb[6], double xa, double ya, double xb, double yb)
    bint dggs_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb)
    bint dggs_corner_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb)

cdef extern from "line_layout.h" nogil:
    int64_t dggs_clean(const double *xy, size_t n, double *out, size_t *count)
    void dggs_layout_size(const double *dist, size_t nseg, double max_span, size_t *size, size_t *inner)
    void dggs_layout(const double *xy, const double *az12, const double *az21, const double *dist, size_t nseg,
                     double max_span, double *lat, double *lng, double *az_out, double *az_in, double *span,
                     int64_t *at, int64_t *seg, double *s)

cdef extern from "line_trace.h" nogil:
    void dggs_ecef(double lat_deg, double lng_deg, double *x, double *y, double *z)
    void dggs_tangent(double lat_deg, double lng_deg, double az_deg, double *x, double *y, double *z)
    void dggs_geodetic(double x, double y, double z, double *lat, double *lng)
    void dggs_line_trace_span(const double *lat, const double *lng, const double *az_out, const double *az_in,
                              const double *span, size_t k, double c[12])
    void dggs_at(const double c[12], double t, double *lat, double *lng)
    uint64_t dggs_cell_at(int proj, double x, double y, double z, int level, int hint, int *face)
    int64_t dggs_trace(int proj, const double *lat, const double *lng, const double *az_out,
                       const double *az_in, const double *span, size_t n, int level, double step, double corner,
                       uint64_t *out, size_t cap, int64_t *fix, size_t fixcap, bint shortcut, int64_t *nfix)


# ---- chord.py ----

def dist_to_segment(double px, double py, double x0, double y0, double x1, double y1):
    """The distance from point (px, py) to the segment (x0, y0) - (x1, y1) in the plane (chord.dist_to_segment)."""
    return dggs_dist_to_segment(px, py, x0, y0, x1, y1)


def corners6(uint64_t cell):
    """The planar corners of a cell as six numbers (chord.corners6: points.triangle's, without the face)."""
    cdef double t[6]
    dggs_corners6(cell, t)
    return t[0], t[1], t[2], t[3], t[4], t[5]


cdef int _lines_six(object src, double *dst) except -1:
    cdef Py_ssize_t i
    if len(src) != 6:
        raise ValueError(f"corners must be 6 numbers, not {len(src)}")
    for i in range(6):
        dst[i] = src[i]
    return 0


def crosses(ta, tb, double xa, double ya, double xb, double yb):
    """chord.crosses: clear's test on the corners ``ta``, ``tb`` (:func:`corners6`) of two cells on one face."""
    cdef double a[6]
    cdef double b[6]
    _lines_six(ta, a)
    _lines_six(tb, b)
    return bool(dggs_crosses(a, b, xa, ya, xb, yb))


def clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb):
    """Whether the line from a sample in ``a`` to one in ``b`` (edge neighbours) crosses only their shared edge.

    chord.clear.
    """
    return bool(dggs_clear(a, b, fa, xa, ya, fb, xb, yb))


def corner_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb):
    """Whether the line from a sample in ``a`` to one in ``b`` (cells meeting at one corner) stays clear of it.

    chord.corner_clear.
    """
    return bool(dggs_corner_clear(a, b, fa, xa, ya, fb, xb, yb))


# ---- line_layout.py ----

def clean(xy):
    """The (N, 2) points without consecutive repeats, checked: ``(-1, points)``, or ``(i, empty)`` (line_layout.clean).

    ``i`` is the index of the first point that is not a finite latitude in -90..90 and a finite longitude.
    """
    cdef const double[:, ::1] src = np.ascontiguousarray(xy, dtype=np.float64)
    if src.shape[1] != 2:
        raise ValueError(f"xy must have shape (N, 2), not {tuple(src.shape)[:2]}")
    cdef Py_ssize_t n = src.shape[0]
    out = np.empty((n, 2), dtype=np.float64)
    cdef double[:, ::1] dst = out
    cdef size_t count = 0
    cdef int64_t bad
    with nogil:
        bad = dggs_clean(&src[0, 0] if n else NULL, <size_t>n, &dst[0, 0] if n else NULL, &count)
    if bad >= 0:
        return int(bad), np.empty((0, 2), dtype=np.float64)
    return -1, (out if <Py_ssize_t>count == n else out[:count].copy())


def layout(xy, az12, az21, dist, double max_span):
    """Anchor arrays for a polyline's segments cut into spans of at most ``max_span`` metres (line_layout.layout).

    Returns ``(lat, lng, az_out, az_in, span, at, seg, s)``.
    """
    cdef const double[:, ::1] p = np.ascontiguousarray(xy, dtype=np.float64)
    cdef const double[::1] a12 = np.ascontiguousarray(az12, dtype=np.float64)
    cdef const double[::1] a21 = np.ascontiguousarray(az21, dtype=np.float64)
    cdef const double[::1] d = np.ascontiguousarray(dist, dtype=np.float64)
    cdef size_t nseg = <size_t>d.shape[0]
    if p.shape[1] != 2 or <size_t>p.shape[0] < nseg + 1 or <size_t>a12.shape[0] < nseg or <size_t>a21.shape[0] < nseg:
        raise ValueError("layout needs len(dist) + 1 points (N, 2) and len(dist) azimuths each way")
    cdef size_t size, inner
    dggs_layout_size(&d[0] if nseg else NULL, nseg, max_span, &size, &inner)
    lat, lng = np.empty(size), np.empty(size)
    az_out, az_in, span = np.empty(size), np.empty(size), np.empty(size - 1)
    at = np.empty(inner, dtype=np.int64)
    seg = np.empty(inner, dtype=np.int64)
    s = np.empty(inner)
    cdef double[::1] vlat = lat, vlng = lng, vout = az_out, vin = az_in, vspan = span, vs = s
    cdef int64_t[::1] vat = at, vseg = seg
    with nogil:
        dggs_layout(&p[0, 0], &a12[0] if nseg else NULL, &a21[0] if nseg else NULL, &d[0] if nseg else NULL, nseg,
                    max_span, &vlat[0], &vlng[0], &vout[0], &vin[0], &vspan[0] if size > 1 else NULL,
                    &vat[0] if inner else NULL, &vseg[0] if inner else NULL, &vs[0] if inner else NULL)
    return lat, lng, az_out, az_in, span, at, seg, s


# ---- line_trace.py and ivea_lines.py ----

def ecef(double lat_deg, double lng_deg):
    """Geodetic WGS84 (lat, lng) degrees on the surface -> ECEF metres (line_trace.ecef)."""
    cdef double x, y, z
    dggs_ecef(lat_deg, lng_deg, &x, &y, &z)
    return x, y, z


def tangent(double lat_deg, double lng_deg, double az_deg):
    """The unit vector (ECEF) at a point heading at azimuth ``az_deg`` (line_trace.tangent)."""
    cdef double x, y, z
    dggs_tangent(lat_deg, lng_deg, az_deg, &x, &y, &z)
    return x, y, z


def geodetic(double x, double y, double z):
    """ECEF metres -> geodetic WGS84 (lat, lng) degrees of the foot of the normal (line_trace.geodetic)."""
    cdef double lat, lng
    dggs_geodetic(x, y, z, &lat, &lng)
    return lat, lng


cdef int _lines_anchors_ok(const double[::1] lat, const double[::1] lng, const double[::1] az_out,
                           const double[::1] az_in, const double[::1] span) except -1:
    cdef Py_ssize_t n = lat.shape[0]
    if lng.shape[0] < n or az_out.shape[0] < n or az_in.shape[0] < n or span.shape[0] < n - 1:
        raise ValueError("the anchors' lat, lng, az_out, az_in need one entry each per anchor, span one per span")
    return 0


def interpolate(lat, lng, az_out, az_in, span, k, t, double[:] out_lat, double[:] out_lng):
    """``out_lat[i], out_lng[i]``: the interpolated point at fraction ``t[i]`` of span ``k[i]``.

    line_trace.interpolate (for tests).
    """
    cdef const double[::1] vlat = np.ascontiguousarray(lat, dtype=np.float64)
    cdef const double[::1] vlng = np.ascontiguousarray(lng, dtype=np.float64)
    cdef const double[::1] vout = np.ascontiguousarray(az_out, dtype=np.float64)
    cdef const double[::1] vin = np.ascontiguousarray(az_in, dtype=np.float64)
    cdef const double[::1] vspan = np.ascontiguousarray(span, dtype=np.float64)
    cdef const int64_t[:] vk = np.asarray(k, dtype=np.int64)
    cdef const double[:] vt = np.asarray(t, dtype=np.float64)
    _lines_anchors_ok(vlat, vlng, vout, vin, vspan)
    cdef Py_ssize_t m = vk.shape[0], i
    if vt.shape[0] < m or out_lat.shape[0] < m or out_lng.shape[0] < m:
        raise ValueError("t, out_lat and out_lng need an entry per k")
    for i in range(m):
        if vk[i] < 0 or vk[i] >= vlat.shape[0] - 1:
            raise IndexError(f"span {vk[i]} is out of range 0..{vlat.shape[0] - 2}")
    cdef double c[12]
    with nogil:
        for i in range(m):
            dggs_line_trace_span(&vlat[0], &vlng[0], &vout[0], &vin[0], &vspan[0], <size_t>vk[i], c)
            dggs_at(c, vt[i], &out_lat[i], &out_lng[i])


cdef _lines_cells_at(int proj, lat, lng, int level, uint64_t[:] out, bint chained):
    cdef const double[:] vlat = np.asarray(lat, dtype=np.float64)
    cdef const double[:] vlng = np.asarray(lng, dtype=np.float64)
    cdef Py_ssize_t n = vlat.shape[0], i
    if vlng.shape[0] < n or out.shape[0] < n:
        raise ValueError("lng and out need an entry per point")
    cdef int hint = -1, face
    cdef double x, y, z
    with nogil:
        for i in range(n):
            dggs_ecef(vlat[i], vlng[i], &x, &y, &z)
            out[i] = dggs_cell_at(proj, x, y, z, level, hint, &face)
            if chained:
                hint = face


def cells_at(lat, lng, int level, uint64_t[:] out, bint chained=False):
    """``out[i]``: the cell of point ``i`` located as the tracer locates interpolated points (line_trace.cells_at).

    ``chained``: each point's face search starts from the one before's, as along a line.
    """
    _lines_cells_at(_LINES_ISEA, lat, lng, level, out, chained)


def ivea_cells_at(lat, lng, int level, uint64_t[:] out, bint chained=False):
    """:func:`cells_at` on the IVEA projection (ivea_lines.cells_at)."""
    _lines_cells_at(_LINES_IVEA, lat, lng, level, out, chained)


cdef _lines_trace(int proj, lat, lng, az_out, az_in, span, int level, double step, double corner,
                  uint64_t[::1] out, int64_t[::1] fix, bint shortcut):
    cdef const double[::1] vlat = np.ascontiguousarray(lat, dtype=np.float64)
    cdef const double[::1] vlng = np.ascontiguousarray(lng, dtype=np.float64)
    cdef const double[::1] vout = np.ascontiguousarray(az_out, dtype=np.float64)
    cdef const double[::1] vin = np.ascontiguousarray(az_in, dtype=np.float64)
    cdef const double[::1] vspan = np.ascontiguousarray(span, dtype=np.float64)
    _lines_anchors_ok(vlat, vlng, vout, vin, vspan)
    if vlat.shape[0] == 0:
        raise ValueError("trace needs at least one anchor")
    cdef int64_t n, nfix = 0, no_fix = 0  # a zero-length fix still gets a pointer: NULL would mean "count only"
    with nogil:
        n = dggs_trace(proj, &vlat[0], &vlng[0], &vout[0], &vin[0], &vspan[0] if vspan.shape[0] else NULL,
                       <size_t>vlat.shape[0], level, step, corner, &out[0] if out.shape[0] else NULL,
                       <size_t>out.shape[0], &fix[0] if fix.shape[0] else &no_fix, <size_t>fix.shape[0], shortcut,
                       &nfix)
    return int(n), int(nfix)


def trace(lat, lng, az_out, az_in, span, int level, double step, double corner, uint64_t[::1] out,
          int64_t[::1] fix, bint shortcut=True):
    """The cells along a chain of anchors, into ``out``: ``(cells, corner gaps)``, or ``(-1, 0)`` if ``out`` is full.

    line_trace.trace (its docstring and libdggs/src/line_trace.h say how).
    """
    return _lines_trace(_LINES_ISEA, lat, lng, az_out, az_in, span, level, step, corner, out, fix, shortcut)


def ivea_trace(lat, lng, az_out, az_in, span, int level, double step, double corner, uint64_t[::1] out,
               int64_t[::1] fix, bint shortcut=True):
    """:func:`trace` on the IVEA projection (ivea_lines.trace)."""
    return _lines_trace(_LINES_IVEA, lat, lng, az_out, az_in, span, level, step, corner, out, fix, shortcut)
