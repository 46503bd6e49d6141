# cython: language_level=3
"""dggs._core: the Python binding of libdggs (libdggs/include/dggs.h), and nothing else.

It only converts: numpy arrays (typed memoryviews) and Python numbers in, the C core's functions called per
item, arrays and numbers out. A batch loop releases the GIL and runs on ``THREADS`` OpenMP threads once it has
``PARALLEL_MIN`` items of work (``set_threads``, called by dggs.geometry._parallel from ``DGGS_THREADS``).
Each part of the grid is one ``.pxi`` file beside this one, included here; the modules of
``dggs.index._kernel`` re-export these functions under the names the verbs call.
"""

from cython.parallel cimport prange
from libc.stdint cimport int32_t, int64_t, uint8_t, uint32_t, uint64_t

#: Smallest amount of work (items) that runs on several threads.
cdef Py_ssize_t PARALLEL_MIN_C = 8192
PARALLEL_MIN = PARALLEL_MIN_C
cdef int _THREADS = 1


def set_threads(int n):
    """Use ``n`` threads (>= 1) for large batches."""
    global _THREADS
    if n < 1:
        raise ValueError(f"threads must be >= 1, not {n}")
    _THREADS = n


def get_threads():
    """The threads large batches use."""
    return _THREADS


cdef inline int _nthreads(Py_ssize_t work) noexcept nogil:
    """Threads for a loop over ``work`` items: all of them from PARALLEL_MIN items on, else one."""
    return _THREADS if (_THREADS > 1 and work >= PARALLEL_MIN_C) else 1


cdef extern from *:
    """
    #ifdef _OPENMP
    #include <omp.h>
    static int dggs_binding_thread(void) { return omp_get_thread_num(); }
    #else
    static int dggs_binding_thread(void) { return 0; }
    #endif
    """
    int dggs_binding_thread() noexcept nogil


def thread_of_item(Py_ssize_t n, int[:] out):
    """Write the OpenMP thread number of each item of ``out``, looped as every batch is (the threads' test probe)."""
    cdef Py_ssize_t i
    for i in prange(out.shape[0], nogil=True, num_threads=_nthreads(n), schedule='static'):
        out[i] = dggs_binding_thread()


include "errors.pxi"
include "geometry.pxi"
include "points.pxi"
include "codec.pxi"
include "hierarchy.pxi"
include "grid.pxi"
include "fill.pxi"
include "lines.pxi"
include "local.pxi"
include "edges.pxi"
include "pixels.pxi"
include "plane.pxi"
include "vertex.pxi"
include "lone.pxi"
include "edge_bound.pxi"
