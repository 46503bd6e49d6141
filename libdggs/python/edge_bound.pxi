# points per edge: bounds of each edge's bulge, the points per edge a tolerance needs, and closed rings of
# varying point counts into one flat buffer (libdggs/src/edge_bound.c). Ids are assumed valid; `proj` is
# 0 (ISEA) or 1 (IVEA). Under the names of dggs.index._kernel.edge_bound.

from libc.string cimport memcpy

cdef extern from "<stdbool.h>" nogil:
    ctypedef bint edge_cbool "bool"

cdef extern from "edge_bound.h" nogil:
    int DGGS_EDGE_RING_REUSED
    int DGGS_EDGE_POINTS_MAX
    void dggs_edge_bounds_of(int proj, uint64_t cell, double *bulge_m, double *length_m)
    int dggs_edge_points_of(int proj, uint64_t cell, double tolerance_m, double area_tolerance)
    int dggs_edge_ring_of(int proj, uint64_t cell, double tolerance_m, double area_tolerance, double *ring,
                          edge_cbool *drawn)

cdef extern from "shape.h" nogil:
    edge_cbool dggs_ring_is_special(const double *lng_lat, int64_t rows)

#: Rows a cell takes in edge_rings_count's scratch.
EDGE_RING_ROWS = DGGS_EDGE_RING_REUSED


def edge_bounds(int proj, const uint64_t[:] ids, double[:, ::1] bulge, double[:, ::1] length):
    """Bounds of each edge's bulge and length (metres on WGS84) into ``bulge`` and ``length`` (N, 3)."""
    cdef Py_ssize_t m = ids.shape[0], i
    if bulge.shape[0] < m or length.shape[0] < m or bulge.shape[1] != 3 or length.shape[1] != 3:
        raise ValueError(f"bulge and length must be ({m}, 3)")
    for i in prange(m, nogil=True, num_threads=_nthreads(m), schedule='static'):
        dggs_edge_bounds_of(proj, ids[i], &bulge[i, 0], &length[i, 0])


def edge_point_counts(int proj, const uint64_t[:] ids, double tolerance_m, double area_tolerance, int32_t[:] out):
    """Points per edge each cell needs for ``tolerance_m`` metres and ``area_tolerance`` (0: not asked) into ``out``."""
    cdef Py_ssize_t m = ids.shape[0], i
    if out.shape[0] < m:
        raise ValueError(f"out must hold {m} counts, not {out.shape[0]}")
    if not (tolerance_m >= 0 and area_tolerance >= 0) or tolerance_m == area_tolerance == 0:
        raise ValueError(f"bad tolerances {tolerance_m!r}, {area_tolerance!r}")
    for i in prange(m, nogil=True, num_threads=_nthreads(m), schedule='static'):
        out[i] = dggs_edge_points_of(proj, ids[i], tolerance_m, area_tolerance)


def ragged_rings(int proj, const uint64_t[:] ids, const int32_t[:] counts, const int64_t[:] offsets,
                 double[:, ::1] out):
    """Closed (lng, lat) rings, cell i's with ``counts[i]`` points per edge, at rows ``offsets[i]`` of ``out``."""
    cdef Py_ssize_t m = ids.shape[0], i
    if counts.shape[0] < m or offsets.shape[0] < m + 1 or out.shape[1] != 2:
        raise ValueError("counts must hold one count a cell, offsets one more, out (rows, 2)")
    if offsets[m] > out.shape[0]:
        raise ValueError(f"out must have {offsets[m]} rows, not {out.shape[0]}")
    for i in range(m):
        if counts[i] < 0 or offsets[i + 1] - offsets[i] != 3 * (counts[i] + 1) + 1:
            raise ValueError(f"offsets do not fit counts at row {i}")
    for i in prange(m, nogil=True, num_threads=_nthreads(m * 8), schedule='static'):
        dggs_one_boundary(proj, ids[i], counts[i], &out[offsets[i], 0], 1)


def edge_rings_count(int proj, const uint64_t[:] ids, double tolerance_m, double area_tolerance, int32_t[:] counts,
                     double[:, ::1] scratch):
    """Pass one of ragged rings drawn as a tolerance asks: each cell's points per edge into ``counts`` and, where
    the count's own points make the ring (0, 1 or 3 a edge), the closed (lng, lat) ring at row EDGE_RING_ROWS i of
    ``scratch``; returns the rows all the rings take (edge_rings_write's ``out``)."""
    cdef Py_ssize_t m = ids.shape[0], i
    cdef int64_t rows = 0
    cdef int stride = DGGS_EDGE_RING_REUSED
    if counts.shape[0] < m or scratch.shape[0] < m * stride or scratch.shape[1] != 2:
        raise ValueError(f"counts must hold {m} counts and scratch ({m * stride}, 2) rows")
    if not (tolerance_m >= 0 and area_tolerance >= 0) or tolerance_m == area_tolerance == 0:
        raise ValueError(f"bad tolerances {tolerance_m!r}, {area_tolerance!r}")
    for i in prange(m, nogil=True, num_threads=_nthreads(m), schedule='static'):
        counts[i] = dggs_edge_ring_of(proj, ids[i], tolerance_m, area_tolerance, &scratch[i * stride, 0], NULL)
    for i in range(m):
        rows += 3 * (counts[i] + 1) + 1
    return rows


def edge_rings_write(int proj, const uint64_t[:] ids, const int32_t[:] counts, const double[:, ::1] scratch,
                     int64_t[:] offsets, double[:, ::1] out, uint8_t[:] special):
    """Pass two: ``offsets`` (m + 1) of the rings laid end to end, the rings into ``out`` (copied from edge_rings_count's
    ``scratch``, or drawn where the count needed more points) and ``special[i]`` whether ring i crosses the
    antimeridian or comes within a degree of a pole (it takes the exact path)."""
    cdef Py_ssize_t m = ids.shape[0], i
    cdef int stride = DGGS_EDGE_RING_REUSED
    cdef int d
    if counts.shape[0] < m or offsets.shape[0] < m + 1 or special.shape[0] < m or out.shape[1] != 2:
        raise ValueError("counts and special must hold one entry a cell, offsets one more, out (rows, 2)")
    if scratch.shape[0] < m * stride or scratch.shape[1] != 2:
        raise ValueError(f"scratch must have ({m * stride}, 2) rows")
    offsets[0] = 0
    for i in range(m):
        if counts[i] < 0 or counts[i] > DGGS_EDGE_POINTS_MAX:
            raise ValueError(f"bad count {counts[i]} at row {i}")
        offsets[i + 1] = offsets[i] + 3 * (counts[i] + 1) + 1
    if offsets[m] > out.shape[0]:
        raise ValueError(f"out must have {offsets[m]} rows, not {out.shape[0]}")
    for i in prange(m, nogil=True, num_threads=_nthreads(m * 2), schedule='static'):
        d = counts[i]
        if d == 0 or d == 1 or d == 3:
            memcpy(&out[offsets[i], 0], &scratch[i * stride, 0], (3 * (d + 1) + 1) * 2 * sizeof(double))
        else:
            dggs_one_boundary(proj, ids[i], d, &out[offsets[i], 0], 1)
        special[i] = dggs_ring_is_special(&out[offsets[i], 0], 3 * (d + 1) + 1)
