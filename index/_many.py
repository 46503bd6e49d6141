"""Many polygon fills at once, on all cores: :func:`each`.

A fill spends most of its time in the compiled descent, which releases the
GIL (``nogil``), and in GEOS, which shapely calls without it, so fills of
different polygons run side by side on Python threads.  The number of
threads is ``DGGS_THREADS`` (:func:`dggs.geometry._parallel.default_threads`);
with one, no thread is started.

Examples
--------
>>> from shapely.geometry import box
>>> from dggs.index.polyfill import polygon_to_cells
>>> [len(c) for c in each(lambda g: polygon_to_cells(g, 6), [box(0, 0, 10, 10), box(0, 0, 20, 20)])]
[68, 280]
"""

from __future__ import annotations

import concurrent.futures
from collections.abc import Callable, Sequence
from typing import Any

import shapely

from dggs.geometry._parallel import default_threads

__all__ = ["each"]


def each(fill: Callable[[Any], Any], polygons: Sequence[Any], tick: Callable[[int], Any] | None = None) -> list[Any]:
    """``fill(polygon)`` for each polygon, in their order, as a loop would give them.

    Parameters
    ----------
    fill : callable
        Called once for each polygon.
    polygons : sequence of shapely geometries
    tick : callable, optional
        Called with 1 as each polygon's result is taken, in their order (a progress bar's ``update``).

    Returns
    -------
    list
        The results in the polygons' order, up to and including the first
        polygon (in that order) whose fill raised: there, the exception
        instead, and no entries after it, as a loop stopping at the error
        would leave them.  The largest polygons (by area in degrees) start
        first, so that no thread is left with a large one at the end.
    """
    threads = default_threads()
    out: list[Any] = []
    if threads == 1 or len(polygons) < 2:
        for polygon in polygons:
            try:
                out.append(fill(polygon))
            except Exception as exc:  # noqa: BLE001 - handed back to the caller, which raises it
                out.append(exc)
                break
            if tick is not None:
                tick(1)
        return out
    order = sorted(range(len(polygons)), key=lambda i: -float(shapely.area(polygons[i])))
    with concurrent.futures.ThreadPoolExecutor(max_workers=threads) as pool:
        futures: dict[int, concurrent.futures.Future[Any]] = {i: pool.submit(fill, polygons[i]) for i in order}
        for i in range(len(polygons)):
            error = futures[i].exception()
            out.append(futures[i].result() if error is None else error)
            if error is not None:
                for rest in futures.values():
                    rest.cancel()  # the polygons not started yet: no one will read them
                break
            if tick is not None:
                tick(1)
    return out
