"""The blocks of a raster, worked on all cores and handed back in order (part of :mod:`dggs.raster`).

:func:`each_block` is the one loop over a raster's blocks: ``raster_to_cells``
gathers its results in memory, ``CellStore.ingest_raster`` commits them one
block a transaction and resumes after the blocks committed (``skip``), so
the blocks are numbered the same way in both: row by row, ``size`` pixels a
side, as :meth:`RasterSource.blocks <dggs.raster.source.RasterSource.blocks>`
reads them.  :func:`tidy_classes` sums a block's class areas per cell and
class, so that a block's partials are a few numbers a cell, whoever adds them
up afterwards (numpy here, SQLite in the store) and in the same order.
"""

from __future__ import annotations

import concurrent.futures
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np

from dggs.geometry._parallel import default_threads
from dggs.raster.source import Block, RasterSource
from dggs.raster.stats import Partials

__all__ = ["windows", "each_block", "tidy_classes"]


def windows(src: RasterSource, size: int) -> list[tuple[int, int, int, int]]:
    """``(row, col, rows, cols)`` of every block, row by row (the order of ``RasterSource.blocks``).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> windows(SimpleNamespace(height=3, width=5), 2)
    [(0, 0, 2, 2), (0, 2, 2, 2), (0, 4, 2, 1), (2, 0, 1, 2), (2, 2, 1, 2), (2, 4, 1, 1)]
    """
    return [(r, c, min(size, src.height - r), min(size, src.width - c))
            for r in range(0, src.height, size) for c in range(0, src.width, size)]


def _read(src: RasterSource, window: tuple[int, int, int, int]) -> Block:
    r, c, rows, cols = window
    data, mask = src.reader(src.row0 + r, src.col0 + c, rows, cols)
    return Block(r, c, data, mask)


def each_block(src: RasterSource, size: int, work: Callable[[Block], Any], skip: int = 0) -> Iterator[Any]:
    """``work(block)`` of every block from number ``skip`` on, in block order; None for a block without data.

    Blocks are read here, one after the other (GDAL reads one window at a
    time), and worked on by a pool of threads (the kernel releases the GIL),
    a few ahead of the one handed back, so memory stays bounded.
    """
    threads = default_threads()
    with concurrent.futures.ThreadPoolExecutor(max_workers=threads) as pool:
        pending: list[Any] = []
        for window in windows(src, size)[skip:]:
            block = _read(src, window)
            pending.append(pool.submit(work, block) if block.valid.any() else None)
            while len(pending) > 2 * threads:  # read ahead a little: bounded memory
                first = pending.pop(0)
                yield None if first is None else first.result()
        for fut in pending:
            yield None if fut is None else fut.result()


def tidy_classes(parts: Partials | None) -> Partials | None:
    """A block's class pieces summed per (cell, class), pieces in their order; other partials as they are.

    Examples
    --------
    >>> p = Partials(np.array([1, 2], np.uint64), np.ones(2), np.ones((1, 2)), np.ones((1, 2)), np.ones((1, 2)),
    ...              np.ones(2, np.int64), {"cell": np.array([2, 1, 2], np.uint64), "value": np.array([5, 5, 5]),
    ...                                     "area": np.array([0.5, 1.0, 0.25])})
    >>> c = tidy_classes(p).classes
    >>> c["cell"].tolist(), c["value"].tolist(), c["area"].tolist()
    ([1, 2], [5, 5], [1.0, 0.75])
    """
    if parts is None or not parts.classes or parts.classes["cell"].size == 0:
        return parts
    cell, value, area = parts.classes["cell"], parts.classes["value"], parts.classes["area"]
    order = np.lexsort((value, cell))  # stable: a group's pieces keep their order, and are added in it
    cell, value, area = cell[order], value[order], area[order]
    first = np.concatenate([[True], (cell[1:] != cell[:-1]) | (value[1:] != value[:-1])])
    group = np.cumsum(first) - 1
    parts.classes = {"cell": cell[first], "value": value[first], "area": np.bincount(group, weights=area)}
    return parts
