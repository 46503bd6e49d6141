"""Threads of the compiled core (dggs.geometry._parallel, libdggs/python/core.pyx): a large batch really runs on
several threads, a small one on one, and DGGS_THREADS is what the binding uses.

``_core.thread_of_item(n, out)`` is the binding's own probe: the loop every batch function uses, writing the
OpenMP thread number of each item.
"""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from dggs import _core
from dggs.geometry._parallel import PARALLEL_MIN, THREADS, default_threads


@pytest.mark.skipif(THREADS < 2, reason="one thread here (DGGS_THREADS=1 or one core): nothing to spread over")
def test_a_large_batch_runs_on_several_threads():
    out = np.full(200_000, -1, dtype=np.int32)
    _core.thread_of_item(out.size, out)
    assert (out >= 0).all()
    assert len(set(out.tolist())) >= 2, "the batch loop ran every item on one thread"


def test_a_small_batch_runs_on_one_thread():
    out = np.full(16, -1, dtype=np.int32)
    _core.thread_of_item(out.size, out)
    assert set(out.tolist()) == {0}
    out = np.full(PARALLEL_MIN - 1, -1, dtype=np.int32)
    _core.thread_of_item(out.size, out)
    assert set(out.tolist()) == {0}


def test_the_binding_uses_the_configured_threads():
    assert _core.get_threads() == default_threads() == THREADS


def test_dggs_threads_reaches_the_binding_in_a_fresh_process():
    env = {k: v for k, v in os.environ.items() if not k.startswith("DGGS_")}
    env["DGGS_THREADS"] = "3"
    code = "import dggs.geometry._parallel as p; from dggs import _core; print(p.THREADS, _core.get_threads())"
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.split() == ["3", "3"]
