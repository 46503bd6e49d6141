"""Threads for the compiled kernel: ``DGGS_THREADS`` and when a loop runs in parallel.

Every batch operation has a serial loop and a ``prange`` loop over the same
per-item function.  Inputs below :data:`PARALLEL_MIN` items take the serial
loop (starting threads costs more than it saves); larger ones use numba's
thread pool, whose size is ``DGGS_THREADS`` (or ``NUMBA_NUM_THREADS``, or the
number of cores).
"""

from __future__ import annotations

import os

import numba

from dggs.errors import DggsValueError

#: Smallest input that runs on several threads.
PARALLEL_MIN = 8192


def _configure() -> int:
    env = os.environ.get("DGGS_THREADS")
    if not env:
        return int(getattr(numba.config, "NUMBA_NUM_THREADS"))
    try:
        wanted = int(env)
    except ValueError:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer") from None
    if wanted < 1:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer")
    n = min(wanted, int(getattr(numba.config, "NUMBA_NUM_THREADS")))
    if n > 1:  # one thread never starts the pool: every loop takes its serial version
        numba.set_num_threads(n)
    return n


THREADS = _configure()


def default_threads() -> int:
    """Threads used for large inputs."""
    return THREADS


def parallel(n: int) -> bool:
    """Whether a loop over ``n`` items should run on several threads."""
    return THREADS > 1 and n >= PARALLEL_MIN

