"""The grid as a graph: edge neighbours, disks, rings, distances.

Each level is a reflection tiling (thesis §6.1.7, docs/grid.md), so the cell
across an edge is the mirror image of the cell in that edge; its id is the
cell's with one digit replaced (a digit walk on the integer id, in
:mod:`dggs.index._kernel.grid`).  Disks and rings grow breadth-first, each ring
deduplicated against the two before it.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError, TooManyCellsError

from ._checks import K_LIMIT, check_k, check_max_cells, check_radius, check_size
from ._convert import ROWS, VALUE, Op, apply, apply_pair, id_name
from ._kernel import distance as kd
from ._kernel import grid as kg
from ._kernel import hierarchy as kh

__all__ = ["edge_neighbors", "are_neighbor_cells", "grid_disk", "grid_ring", "grid_distance"]

def _neighbours(ids: np.ndarray) -> np.ndarray:
    out = np.empty((ids.shape[0], 3), dtype=np.uint64)
    kg.neighbours(ids, out)
    return out


def _are_neighbours(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    out = np.empty(a.shape[0], dtype=bool)
    kg.are_neighbours(a, b, out)
    return out


def _rows(loop: Any, width: Callable[[int, int], int], what: str, count: Callable[..., int] | None = None) -> Any:
    """A kernel's rows per id, padded with 0 to the largest real row, checked against ``max_cells`` before allocating.

    ``width(k, level)`` bounds a row at the finest level present.  Where that
    bound is over the limit, ``count`` (if any) counts the real rows first, with
    the memory of two rings and work bounded by the limit.
    """

    def rows(ids: np.ndarray, k: int, max_cells: int) -> np.ndarray:
        n = ids.shape[0]
        w = width(k, max(kh.level_bounds(ids)[1], 0))
        if n * w > max_cells:
            if count is None:
                check_size(n * w, max_cells, f"{what} with k={k}")
            else:
                w = _counted(count, ids, k, max_cells, what)
        out = np.empty((n, w), dtype=np.uint64)
        counts = np.empty(n, dtype=np.int64)
        loop(n * w, ids, k, out, counts)
        m = int(counts.max()) if n else w
        return out if m == w else np.ascontiguousarray(out[:, :m])

    return rows


def _counted(count: Callable[..., int], ids: np.ndarray, k: int, max_cells: int, what: str) -> int:
    """The largest real row, or :class:`TooManyCellsError` naming the first id whose row does not fit."""
    n = ids.shape[0]
    counts = np.zeros(n, dtype=np.int64)
    bad = count(ids, k, max_cells // n, counts)
    if bad >= 0:
        cell, size = id_name(ids[bad]), int(counts[bad])
        rows = f"at least {size:,} cells" if n == 1 else f"{n:,} rows, one of at least {size:,} cells ({n * size:,} with the padding)"
        raise TooManyCellsError(
            f"{what} of {cell!r} with k={k} would return {rows}, over the limit of {max_cells:,} (raise max_cells to allow it)"
        )
    return int(counts.max())


def _distances(a: np.ndarray, b: np.ndarray, max_steps: int) -> np.ndarray:
    la, lb = kh.levels(a), kh.levels(b)
    if (la != lb).any():
        i = int(np.flatnonzero(la != lb)[0])
        raise LevelMismatchError(
            f"cells {id_name(a[i])!r} (level {la[i]}) and {id_name(b[i])!r} (level {lb[i]}) are at different levels"
        )
    dist = np.empty(a.shape[0], dtype=np.int64)
    kd.distances(a.shape[0], a, b, max_steps, dist)
    for j in np.flatnonzero(dist == kd.NEEDS_SEARCH):  # no straight face strip serves the pair (none known)
        dist[j] = kd.search(a[j], b[j], max_steps)
        if dist[j] < 0 and max_steps > kd.SEARCH_LIMIT:
            raise DggsValueError(
                f"cells {id_name(a[j])!r} and {id_name(b[j])!r}: no exact distance found within "
                f"{kd.SEARCH_LIMIT} steps of search"
            )
    if (dist < 0).any():
        i = int(np.flatnonzero(dist < 0)[0])
        raise DggsValueError(f"cells {id_name(a[i])!r} and {id_name(b[i])!r} are more than {max_steps} steps apart")
    return dist


_NEIGHBOURS = Op(many=_neighbours, out=ROWS)
_ARE_NEIGHBOURS = Op(many=_are_neighbours, out=VALUE)
_DISK = Op(many=_rows(kg.disk, kg.disk_width, "grid_disk", kg.disk_sizes), out=ROWS, one=kg.disk_of)
_RING = Op(many=_rows(kg.ring, kg.ring_width, "grid_ring"), out=ROWS)
_DISTANCE = Op(many=_distances, out=VALUE)


def edge_neighbors(cell: Any) -> Any:
    """The three cells that share an edge with ``cell``, across face edges too.

    Column ``i`` is the cell across the edge from corner ``i`` to corner
    ``i + 1`` of :func:`cell_to_boundary`.  A single id gives a list of 3;
    an array gives shape ``input shape + (3,)``, of the same kind.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> edge_neighbors("C401")
    ['C411', 'C402', 'C400']
    """
    return apply(_NEIGHBOURS, cell)


def are_neighbor_cells(a: Any, b: Any) -> Any:
    """Whether cells ``a`` and ``b`` share an edge (element-wise; shapes broadcast as in numpy).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        The two shapes do not broadcast (the message names both sizes and shapes).

    Examples
    --------
    >>> are_neighbor_cells("C401", "C402"), are_neighbor_cells("C401", "C401")
    (True, False)
    """
    return apply_pair(_ARE_NEIGHBOURS, a, b)


def grid_disk(cell: Any, k: int = 1, max_cells: int | None = None) -> Any:
    """All cells within ``k`` edge steps of ``cell`` (including it), sorted.

    A single id gives a sorted list.  An array of N cells gives shape
    ``input shape + (M,)``: row i is the disk of cell i, sorted, padded
    with ``""`` (or 0 for integer ids) where a disk near an icosahedron
    vertex is smaller than the others.

    Parameters
    ----------
    max_cells : int, optional
        Refuse outputs larger than this (default
        :data:`dggs.index.hierarchy.MAX_CELLS`); checked before allocating.
        The output counts N rows of the largest real disk (no disk is larger
        than its level); where the planar bound is over the limit, the disks
        are counted first, with work bounded by the limit.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``k`` is not a non-negative integer, or ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The output would exceed ``max_cells``, or ``k`` is past :data:`dggs.index._checks.K_LIMIT`.

    Examples
    --------
    >>> len(grid_disk("C401", 1)), len(grid_disk("C401", 2))
    (4, 9)
    >>> grid_disk(np.array(["C401", "C402"]), 1).shape
    (2, 4)
    """
    return apply(_DISK, cell, check_radius(k, "grid_disk"), check_max_cells(max_cells))


def grid_ring(cell: Any, k: int = 1, max_cells: int | None = None) -> Any:
    """The cells exactly ``k`` edge steps from ``cell``, sorted.

    Same shapes and padding as :func:`grid_disk`.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``k`` is not a non-negative integer, or ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The output would exceed ``max_cells``, or ``k`` is past :data:`dggs.index._checks.K_LIMIT`.

    Examples
    --------
    >>> grid_ring("C401", 1)
    ['C400', 'C402', 'C411']
    """
    return apply(_RING, cell, check_radius(k, "grid_ring"), check_max_cells(max_cells))


def grid_distance(a: Any, b: Any, max_steps: int | None = None) -> Any:
    """Number of edge steps on the shortest path between cells of one level.

    Element-wise for arrays of the same shape, or shapes that broadcast as in
    numpy (one cell against many).  Exact at every distance, around the
    icosahedron vertices too, in O(level) time a pair: the number of mirror
    lines of the level's planar arrangement that separate the cells, over the
    straight strips of faces between them (docs/grid.md, "Distances").

    Parameters
    ----------
    a, b : cell ids
        Any container of string or integer ids, or one id.
    max_steps : int, optional
        Refuse pairs farther apart than this (no limit by default).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelMismatchError
        The cells are at different levels.
    DggsValueError
        The distance exceeds ``max_steps``, ``max_steps`` is not a non-negative integer,
        or the shapes do not broadcast.

    Examples
    --------
    >>> grid_distance("C401", "C402"), grid_distance("C401", "C401")
    (1, 0)
    """
    limit = K_LIMIT if max_steps is None else min(check_k(max_steps, "max_steps"), K_LIMIT)
    return apply_pair(_DISTANCE, a, b, limit)
