"""Threads for the compiled core: ``DGGS_THREADS``, read once, handed to :mod:`dggs._core`.

Every batch loop of the core's binding (``libdggs/python/*.pxi``) runs on one thread below
:data:`PARALLEL_MIN` items of work (starting threads costs more than it saves) and on :data:`THREADS`
OpenMP threads from there on, with the GIL released. ``THREADS`` is ``DGGS_THREADS``, or else the number of
cores this process may use. This module is the one place that decides it; :mod:`dggs.index._many` and the
raster binning take their thread pools' size from :func:`default_threads` too.

Examples
--------
>>> from dggs import _core
>>> _core.get_threads() == default_threads()
True
>>> parallel(10), parallel(10**6) == (default_threads() > 1)
(False, True)
"""

from __future__ import annotations

import os

from dggs import _core
from dggs.errors import DggsValueError

#: Smallest input (in items of work) that runs on several threads (the binding's own threshold).
PARALLEL_MIN: int = _core.PARALLEL_MIN


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on Linux
        return os.cpu_count() or 1


def _configure() -> int:
    env = os.environ.get("DGGS_THREADS")
    if not env:
        return _cores()
    try:
        wanted = int(env)
    except ValueError:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer") from None
    if wanted < 1:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer")
    return wanted


THREADS = _configure()
_core.set_threads(THREADS)


def default_threads() -> int:
    """Threads used for large inputs.

    Returns
    -------
    int
        ``DGGS_THREADS`` if set, else the number of cores this process may use.
    """
    return THREADS


def parallel(n: int) -> bool:
    """Whether a loop over ``n`` items of work runs on several threads.

    Parameters
    ----------
    n : int
        Items of work (points, cells, or cells times points per cell).

    Returns
    -------
    bool
        True when more than one thread is allowed and ``n >= PARALLEL_MIN``.
    """
    return THREADS > 1 and n >= PARALLEL_MIN
