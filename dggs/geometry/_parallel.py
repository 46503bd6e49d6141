"""Threads for the compiled kernel: ``DGGS_THREADS``, and one loop body compiled serial and parallel.

Every batch operation is one loop body written once with ``prange`` and
compiled twice by :func:`loops`: a serial version for inputs below
:data:`PARALLEL_MIN` items (starting threads costs more than it saves) and a
parallel one for larger inputs, on numba's thread pool, whose size is
``DGGS_THREADS`` (or ``NUMBA_NUM_THREADS``, or the number of cores).  This
module is the one place that decides which runs.

Examples
--------
>>> import numpy as np
>>> from numba import prange
>>> def _double(x, out):
...     for i in prange(x.shape[0]):
...         out[i] = 2 * x[i]
>>> double = loops(_double, cache=False)  # a module function caches its compiled code
>>> out = np.empty(3)
>>> double(3, np.arange(3.0), out)
>>> out.tolist()
[0.0, 2.0, 4.0]
"""

from __future__ import annotations

import os
import types
from collections.abc import Callable
from typing import Any

from dggs.errors import DggsValueError


def _check_numba_threads() -> None:
    # numba raises a bare ValueError while it is imported when NUMBA_NUM_THREADS < 1 (numba/np/ufunc/parallel.py)
    env = os.environ.get("NUMBA_NUM_THREADS", "").strip()
    try:
        bad = int(env) < 1
    except ValueError:
        return  # not an integer: numba warns and takes the number of cores
    if bad:
        raise DggsValueError(f"NUMBA_NUM_THREADS {env!r} must be a positive integer")


_check_numba_threads()

import numba  # noqa: E402 - after the check above

from ._cache import install  # noqa: E402 - the package's compiled cache, before any kernel is decorated

install()

#: Smallest input (in items of work) that runs on several threads.
PARALLEL_MIN = 8192


def _configure() -> int:
    env = os.environ.get("DGGS_THREADS")
    if not env:
        return int(numba.config.NUMBA_NUM_THREADS)  # type: ignore[attr-defined]
    try:
        wanted = int(env)
    except ValueError:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer") from None
    if wanted < 1:
        raise DggsValueError(f"DGGS_THREADS {env!r} must be a positive integer")
    n = min(wanted, int(numba.config.NUMBA_NUM_THREADS))  # type: ignore[attr-defined]
    if n > 1:  # one thread never starts the pool: every loop takes its serial version
        numba.set_num_threads(n)
    return n


THREADS = _configure()


def default_threads() -> int:
    """Threads used for large inputs.

    Returns
    -------
    int
        ``DGGS_THREADS`` if set, else numba's thread count.
    """
    return THREADS


def parallel(n: int) -> bool:
    """Whether a loop over ``n`` items of work should run on several threads.

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


class Loops:
    """One ``prange`` loop body compiled into a serial and a parallel loop.

    Call it with the amount of work first, then the body's own arguments:
    ``loop(n, *args)`` runs :attr:`threaded` when :func:`parallel` says so,
    else :attr:`serial` (where ``prange`` is a plain ``range``).
    """

    def __init__(self, body: Callable[..., Any], cache: bool = True) -> None:
        self.__doc__ = body.__doc__
        self.__name__ = body.__name__.lstrip("_")
        #: The body compiled without threads (small inputs; the scalar paths).
        self.serial = numba.njit(cache=cache, nogil=True)(body)
        #: The body compiled with ``parallel=True``, from a copy of the function with its own qualified name:
        #: numba's cache key leaves the ``parallel`` flag out, so one name would share one cache entry and
        #: whichever version compiled first would serve both.
        twin = types.FunctionType(body.__code__, body.__globals__, body.__name__, body.__defaults__, body.__closure__)
        twin.__qualname__ = f"{body.__qualname__}__threaded"
        twin.__doc__ = body.__doc__
        self.threaded = numba.njit(cache=cache, nogil=True, parallel=True)(twin)

    def __call__(self, n: int, *args: Any) -> Any:
        """Run the body over ``args``, on several threads if ``n`` items of work warrant it."""
        return (self.threaded if parallel(n) else self.serial)(*args)


def loops(body: Callable[..., Any], cache: bool = True) -> Loops:
    """Compile ``body`` (a loop over ``prange``) twice: see :class:`Loops`.

    Parameters
    ----------
    body : callable
        A numba-compilable function whose outer loop is a ``prange``.
    cache : bool
        Keep the compiled code on disk (needs the body to live in a file).

    Returns
    -------
    Loops
        Called as ``loop(n, *args)``.
    """
    return Loops(body, cache)
