# points: points <-> ids, corners, centres, boundaries, exact pole/antimeridian rings (libdggs/src/points.c).
# The ISEA functions under index/_kernel/points.py's names; IVEA's (index/_kernel/ivea_points.py) prefixed
# ``ivea_`` (the shim re-exports them under the plain names).

import numpy as np

# The projection argument as an int (C converts it to dggs_projection), so that this file does not declare
# dggs.h's enum a second time beside the other parts' files.
cdef enum:
    POINTS_ISEA = 0
    POINTS_IVEA = 1

cdef extern from "points.h" nogil:
    double DGGS_POLE_LEAD
    double DGGS_ON_EDGE
    int DGGS_SPECIAL_EXTRA
    uint64_t dggs_encode_point(int face, double x, double y, int level)
    uint64_t dggs_one_point(int proj, double lat, double lng, int level)
    int dggs_triangle(uint64_t cell, double t[6])
    int dggs_corners(uint64_t cell, double t[6])
    void dggs_one_centre(int proj, uint64_t cell, double *lat, double *lng)
    void dggs_centre_of(int proj, int64_t cell, double *lat, double *lng)
    void dggs_one_boundary(int proj, uint64_t cell, int densify, double *out, int lnglat)
    int dggs_boundary_rows(int densify, int lnglat)
    uint64_t dggs_one_center_child(uint64_t cell, int level)
    const double *dggs_pole_table()
    void dggs_lat_lng_at(int proj, int face, double x0, double y0, double x1, double y1, double t,
                         double *lat, double *lng)
    double dggs_pole_on(int face, double x0, double y0, double x1, double y1)
    int dggs_edge_params(double *ts, int step, double tp)
    double dggs_crossing(int proj, int face, double x0, double y0, double x1, double y1, double lo,
                         double hi, double lng_lo)
    int dggs_special_ring(int proj, uint64_t cell, int densify, double *out, int rows)
    int dggs_special_ring_rows(int densify)


#: Extra rows of a special ring: two per pole corner, one per antimeridian crossing.
SPECIAL_EXTRA = DGGS_SPECIAL_EXTRA
#: The direction in which an edge leaves a pole: the point this fraction of a densify step away.
POLE_LEAD = DGGS_POLE_LEAD
#: A pole this close (relative to the edge, planar) to a cell's edge lies on it.
ON_EDGE = DGGS_ON_EDGE


def pole_table():
    """A new (20, 3) array: per face the face-frame (x, y) of a pole on its boundary and its sign (0: none)."""
    out = np.empty((20, 3))
    cdef double[:, ::1] o = out
    cdef const double *p = dggs_pole_table()
    cdef int i
    for i in range(60):
        o[i // 3, i % 3] = p[i]
    return out


def encode_point(int face, double x, double y, int level):
    """The id of the level-``level`` cell holding face-frame point (x, y) on ``face``."""
    return dggs_encode_point(face, x, y, level)


def triangle(uint64_t cell):
    """Face and face-frame corners of a cell as Split (2:6) labels them: ``(face, ax, ay, bx, by, cx, cy)``."""
    cdef double t[6]
    cdef int face = dggs_triangle(cell, t)
    return face, t[0], t[1], t[2], t[3], t[4], t[5]


def corners(uint64_t cell):
    """Face and face-frame corners of a cell, counter-clockwise seen from outside: ``(face, ax, ..., cy)``."""
    cdef double t[6]
    cdef int face = dggs_corners(cell, t)
    return face, t[0], t[1], t[2], t[3], t[4], t[5]


def pole_on(int face, double x0, double y0, double x1, double y1):
    """Parameter t in [0, 1) at which the face's pole lies on the planar segment, or -1."""
    return dggs_pole_on(face, x0, y0, x1, y1)


def edge_params(double[::1] ts, int step, double tp):
    """Fill ``ts`` (at least ``step + 2`` long) with a densified edge's parameters; return how many."""
    if step < 0 or ts.shape[0] < step + 2:
        raise ValueError(f"ts needs {step + 2} entries, has {ts.shape[0]}")
    return dggs_edge_params(&ts[0], step, tp)


cdef inline object _points_check_ring(double[:, ::1] out, int need):
    if out.shape[1] != 2 or out.shape[0] < need:
        raise ValueError(f"out must be ({need}, 2) or longer, not ({out.shape[0]}, {out.shape[1]})")


cdef object _points_boundaries(int proj, Py_ssize_t n, const uint64_t[:] ids, int densify,
                               double[:, :, ::1] out, bint lnglat):
    cdef Py_ssize_t m = ids.shape[0], i
    if densify < 0:
        raise ValueError(f"densify must be >= 0, not {densify}")
    if out.shape[0] < m or out.shape[2] != 2 or out.shape[1] < dggs_boundary_rows(densify, lnglat):
        raise ValueError(f"out must be ({m}, {dggs_boundary_rows(densify, lnglat)}, 2), not ({out.shape[0]}, {out.shape[1]}, {out.shape[2]})")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        dggs_one_boundary(proj, ids[i], densify, &out[i, 0, 0], lnglat)


cdef object _points_locate(int proj, Py_ssize_t n, const double[:] lat, const double[:] lng, int level,
                           uint64_t[:] out):
    cdef Py_ssize_t m = lat.shape[0], i
    if lng.shape[0] < m or out.shape[0] < m:
        raise ValueError("lat, lng and out must have the same length")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_one_point(proj, lat[i], lng[i], level)


cdef object _points_centres(int proj, Py_ssize_t n, const uint64_t[:] ids, double[:] lat, double[:] lng):
    cdef Py_ssize_t m = ids.shape[0], i
    if lat.shape[0] < m or lng.shape[0] < m:
        raise ValueError("ids, lat and lng must have the same length")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        dggs_one_centre(proj, ids[i], &lat[i], &lng[i])


cdef object _points_special_ring(int proj, uint64_t cell, int densify, double[:, ::1] out):
    if densify < 0:
        raise ValueError(f"densify must be >= 0, not {densify}")
    _points_check_ring(out, dggs_special_ring_rows(densify))
    return dggs_special_ring(proj, cell, densify, &out[0, 0], <int>out.shape[0])


def one_point(double lat, double lng, int level):
    """The id of the cell holding one point; the null id 0 for a point that is not on the globe."""
    return dggs_one_point(POINTS_ISEA, lat, lng, level)


def ivea_one_point(double lat, double lng, int level):
    """IVEA's :func:`one_point`."""
    return dggs_one_point(POINTS_IVEA, lat, lng, level)


def locate(Py_ssize_t n, const double[:] lat, const double[:] lng, int level, uint64_t[:] out):
    """``out[i]``: the id of the cell holding point ``i`` (0 where the point is not on the globe)."""
    _points_locate(POINTS_ISEA, n, lat, lng, level, out)


def ivea_locate(Py_ssize_t n, const double[:] lat, const double[:] lng, int level, uint64_t[:] out):
    """IVEA's :func:`locate`."""
    _points_locate(POINTS_IVEA, n, lat, lng, level, out)


def centres(Py_ssize_t n, const uint64_t[:] ids, double[:] lat, double[:] lng):
    """``lat[i], lng[i]``: the centre of valid id ``i``."""
    _points_centres(POINTS_ISEA, n, ids, lat, lng)


def ivea_centres(Py_ssize_t n, const uint64_t[:] ids, double[:] lat, double[:] lng):
    """IVEA's :func:`centres`."""
    _points_centres(POINTS_IVEA, n, ids, lat, lng)


def boundaries(Py_ssize_t n, const uint64_t[:] ids, int densify, double[:, :, ::1] out, bint lnglat):
    """``out[i]``: the boundary of valid id ``i``: 3 (densify + 1) (lat, lng), or closed (lng, lat) with ``lnglat``."""
    _points_boundaries(POINTS_ISEA, n, ids, densify, out, lnglat)


def ivea_boundaries(Py_ssize_t n, const uint64_t[:] ids, int densify, double[:, :, ::1] out, bint lnglat):
    """IVEA's :func:`boundaries`."""
    _points_boundaries(POINTS_IVEA, n, ids, densify, out, lnglat)


def center_children(Py_ssize_t n, const uint64_t[:] ids, int level, uint64_t[:] out):
    """``out[i]``: the descendant at ``level`` of valid id ``i`` holding its centre."""
    cdef Py_ssize_t m = ids.shape[0], i
    if out.shape[0] < m:
        raise ValueError("ids and out must have the same length")
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_one_center_child(ids[i], level)


def centre_of(int64_t cell):
    """Centre of one id given as an int64 (the single-id entry); NaNs if it is no id."""
    cdef double lat, lng
    dggs_centre_of(POINTS_ISEA, cell, &lat, &lng)
    return lat, lng


def ivea_centre_of(int64_t cell):
    """IVEA's :func:`centre_of`."""
    cdef double lat, lng
    dggs_centre_of(POINTS_IVEA, cell, &lat, &lng)
    return lat, lng


def lat_lng_at(int face, double x0, double y0, double x1, double y1, double t):
    """(lat, lng) of the planar point at parameter ``t`` from (x0, y0) to (x1, y1) on ``face``."""
    cdef double lat, lng
    dggs_lat_lng_at(POINTS_ISEA, face, x0, y0, x1, y1, t, &lat, &lng)
    return lat, lng


def ivea_lat_lng_at(int face, double x0, double y0, double x1, double y1, double t):
    """IVEA's :func:`lat_lng_at`."""
    cdef double lat, lng
    dggs_lat_lng_at(POINTS_IVEA, face, x0, y0, x1, y1, t, &lat, &lng)
    return lat, lng


def crossing(int face, double x0, double y0, double x1, double y1, double lo, double hi, double lng_lo):
    """Latitude where the curve from parameter lo (longitude ``lng_lo``) to hi reaches +-180 (bisection)."""
    return dggs_crossing(POINTS_ISEA, face, x0, y0, x1, y1, lo, hi, lng_lo)


def ivea_crossing(int face, double x0, double y0, double x1, double y1, double lo, double hi, double lng_lo):
    """IVEA's :func:`crossing`."""
    return dggs_crossing(POINTS_IVEA, face, x0, y0, x1, y1, lo, hi, lng_lo)


def special_ring(uint64_t cell, int densify, double[:, ::1] out):
    """Write the (lat, lng) boundary of a cell with its exact pole and antimeridian points; return the count.

    ``out`` needs ``3 (densify + 1) + SPECIAL_EXTRA`` rows of 2.
    """
    return _points_special_ring(POINTS_ISEA, cell, densify, out)


def ivea_special_ring(uint64_t cell, int densify, double[:, ::1] out):
    """IVEA's :func:`special_ring`."""
    return _points_special_ring(POINTS_IVEA, cell, densify, out)
