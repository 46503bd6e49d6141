"""One loop body, two compilations (dggs.geometry._parallel.loops): the threaded one must really use threads.

numba's on-disk cache keys a function by its qualified name and signature, not by the ``parallel`` flag, so
two dispatchers of one function would share a cache entry and the first compiled would serve both: the
"threaded" loops of every kernel ran on one thread.  The body here reports the numba thread of every item;
it is written to a new module file for each test, so it is cached like the kernels (the serial version is
saved first) but its threaded version is never loaded back from a cache (numba crashes loading a cached
parallel function that calls ``get_thread_id``).
"""

from __future__ import annotations

import importlib.util
import textwrap

import numpy as np
import pytest

from dggs.geometry._parallel import THREADS

BODY = """
import numba
from numba import prange

from dggs.geometry._parallel import loops


def _thread_of_item(out):
    for i in prange(out.shape[0]):
        out[i] = numba.get_thread_id()


THREAD_OF_ITEM = loops(_thread_of_item)
"""


@pytest.fixture
def thread_of_item(tmp_path):
    path = tmp_path / "thread_body.py"
    path.write_text(textwrap.dedent(BODY))
    spec = importlib.util.spec_from_file_location("thread_body", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.THREAD_OF_ITEM


@pytest.mark.skipif(THREADS < 2, reason="one thread here (DGGS_THREADS=1 or one core): nothing to spread over")
def test_threaded_loop_runs_on_several_threads_and_serial_loop_on_one(thread_of_item):
    out = np.full(200_000, -1, dtype=np.int64)
    thread_of_item.serial(out)  # compiled and saved first: under a shared cache entry it served both
    assert set(out.tolist()) == {0}
    thread_of_item.threaded(out)
    assert len(set(out.tolist())) >= 2, "the parallel compilation ran every item on one thread"
    thread_of_item.serial(out)
    assert set(out.tolist()) == {0}


def test_the_call_picks_by_the_amount_of_work(thread_of_item):
    out = np.full(16, -1, dtype=np.int64)
    thread_of_item(16, out)  # below PARALLEL_MIN: the serial loop
    assert set(out.tolist()) == {0}


def test_the_two_compilations_of_a_kernel_have_their_own_cache_names():
    from dggs.index._kernel import points

    assert points.locate.serial.py_func.__qualname__ != points.locate.threaded.py_func.__qualname__
