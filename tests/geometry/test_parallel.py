"""One loop body, two compilations (dggs.geometry._parallel.loops): the threaded one must really use threads.

numba's on-disk cache keys a function by its qualified name and signature, not by the ``parallel`` flag, so
two dispatchers of one function would share a cache entry and the first compiled would serve both: the
"threaded" loops of every kernel ran on one thread.  These bodies are cached like the kernels' (they live in
a file), and each loop reports the numba thread of every item.
"""

from __future__ import annotations

import numba
import numpy as np
import pytest
from numba import prange

from dggs.geometry._parallel import THREADS, loops


def _thread_of_item(out):
    for i in prange(out.shape[0]):
        out[i] = numba.get_thread_id()


THREAD_OF_ITEM = loops(_thread_of_item)


@pytest.mark.skipif(THREADS < 2, reason="one thread here (DGGS_THREADS=1 or one core): nothing to spread over")
def test_threaded_loop_runs_on_several_threads_and_serial_loop_on_one():
    out = np.full(200_000, -1, dtype=np.int64)
    THREAD_OF_ITEM.serial(out)  # compiled (or loaded) first: under the shared cache entry it served both
    assert set(out.tolist()) == {0}
    THREAD_OF_ITEM.threaded(out)
    assert len(set(out.tolist())) >= 2, "the parallel compilation ran every item on one thread"
    THREAD_OF_ITEM.serial(out)
    assert set(out.tolist()) == {0}


def test_the_call_picks_by_the_amount_of_work():
    out = np.full(16, -1, dtype=np.int64)
    THREAD_OF_ITEM(16, out)  # below PARALLEL_MIN: the serial loop
    assert set(out.tolist()) == {0}


def test_the_two_compilations_have_their_own_cache_names():
    from dggs.index._kernel import points

    assert points.locate.serial.py_func.__qualname__ != points.locate.threaded.py_func.__qualname__
