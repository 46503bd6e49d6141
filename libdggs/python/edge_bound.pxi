# points per edge: bounds of each edge's bulge, the points per edge a tolerance needs, and closed rings of
# varying point counts into one flat buffer (libdggs/src/edge_bound.c). Ids are assumed valid; `proj` is
# 0 (ISEA) or 1 (IVEA). Under the names of dggs.index._kernel.edge_bound.

cdef extern from "edge_bound.h" nogil:
    void dggs_edge_bounds_of(int proj, uint64_t cell, double *bulge_m, double *length_m)
    int dggs_edge_points_of(int proj, uint64_t cell, double tolerance_m, double area_tolerance)


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
